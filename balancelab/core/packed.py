"""A design's loads and springs packed into arrays, for the vectorized energy of :class:`~balancelab.Design`.

A :class:`~balancelab.Design` computes these arrays once (it is immutable) and reads them in
its energy loop; nothing here knows about kinematics. Layer: core.
"""
from __future__ import annotations

from typing import Any, NamedTuple, Sequence

import numpy as np

from .elements import CablePath, Load, Spring

__all__ = ["PackedElements", "pack_elements", "packed_field"]


class PackedElements(NamedTuple):
    """The loads' and springs' numbers as arrays, one row per element (SI units)."""

    lb: np.ndarray  #: load bodies, shape (n_loads,)
    lp: np.ndarray  #: load points in their bodies' frames (m), shape (n_loads, 2)
    lf: np.ndarray  #: load forces in the global frame (N), shape (n_loads, 2)
    sab: np.ndarray  #: body of each spring's end a, shape (n_springs,)
    sap: np.ndarray  #: spring end a in its body's frame (m), shape (n_springs, 2)
    sbb: np.ndarray  #: body of each spring's end b, shape (n_springs,)
    sbp: np.ndarray  #: spring end b in its body's frame (m), shape (n_springs, 2)
    sk: np.ndarray  #: rates (N/m), shape (n_springs,)
    sl0: np.ndarray  #: free lengths (m), shape (n_springs,)
    scable: tuple[CablePath | None, ...]  #: each spring's cable path (None: a straight spring)


def pack_elements(loads: Sequence[Load], springs: Sequence[Spring]) -> PackedElements:
    """Pack ``loads`` and ``springs`` into arrays.

    Parameters
    ----------
    loads : sequence of Load
    springs : sequence of Spring

    Returns
    -------
    PackedElements

    Examples
    --------
    >>> from balancelab.core.elements import Spring, gravity_load
    >>> p = pack_elements([gravity_load(1, (0.5, 0.0), 2.0)], [Spring(100.0, 0.0, (0, (0.0, 0.3)), (1, (0.2, 0.0)))])
    >>> p.lf.tolist(), p.sk.tolist(), p.sbp.tolist()
    ([[0.0, -19.62]], [100.0], [[0.2, 0.0]])
    """
    L, S = loads, springs
    return PackedElements(
        lb=np.array([ld.body for ld in L], dtype=int),
        lp=np.array([ld.point for ld in L], dtype=float).reshape(-1, 2),
        lf=np.array([ld.force for ld in L], dtype=float).reshape(-1, 2),
        sab=np.array([s.a.body for s in S], dtype=int),
        sap=np.array([s.a.point for s in S], dtype=float).reshape(-1, 2),
        sbb=np.array([s.b.body for s in S], dtype=int),
        sbp=np.array([s.b.point for s in S], dtype=float).reshape(-1, 2),
        sk=np.array([s.k for s in S], dtype=float),
        sl0=np.array([s.free_length for s in S], dtype=float),
        scable=tuple(s.cable for s in S))


def packed_field(name: str) -> Any:
    """A read-only property giving ``self._arrays.<name>`` (one :class:`PackedElements` field).

    Parameters
    ----------
    name : str
        A field of :class:`PackedElements`.

    Returns
    -------
    property

    Examples
    --------
    >>> class Holder:
    ...     _arrays = pack_elements([], [])
    ...     _sk = packed_field("sk")
    >>> Holder()._sk.shape
    (0,)
    """
    if name not in PackedElements._fields:
        raise ValueError(f"name must be a field of PackedElements {PackedElements._fields}, got {name!r}")
    return property(lambda self: getattr(self._arrays, name), doc=f"The packed ``{name}`` array.")
