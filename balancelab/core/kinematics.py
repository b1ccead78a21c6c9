"""The `Kinematics` contract: configuration coordinates in, body poses out.

Every mechanism of :mod:`balancelab.mechanisms` implements this abstract base class;
:class:`balancelab.Design` relies on nothing else. The contract lives in ``core``
(not in ``mechanisms``) because the design, which is core, is written against it:
layers only look down.

A subclass sets three attributes and implements one method:

``nbodies``
    Number of bodies, the ground (body 0) included.
``names``
    Names of the configuration coordinates (also the sympy symbol names).
``q_range``
    Array of shape ``(dof, 2)``: the bounds of each coordinate (rad).

Optionally ``descriptions``: what each coordinate measures, in words ("crank angle from
the x-axis"), which every plot prints next to the coordinate's symbol.
``poses(q)``
    Returns ``(poses, ok)``: poses ``(x, y, angle)`` of shape ``(..., nbodies, 3)`` and
    the boolean mask of the configurations the linkage can reach.

:meth:`Kinematics.reachable` and :meth:`Kinematics.joint_error` follow from ``poses``.
A kinematics that can write body points as sympy expressions also implements
:meth:`Kinematics.symbolic_point` (and :meth:`Kinematics.symbols` when its symbols are
not the coordinates themselves); the others raise ``NotImplementedError`` there.
"""
from __future__ import annotations

from abc import ABC, abstractmethod
from typing import Any, Callable, Sequence

import numpy as np
from numpy.typing import ArrayLike

from .frames import body_to_world

__all__ = ["Kinematics", "body_to_world", "central_difference", "joint_gaps", "spread"]


def joint_gaps(poses: np.ndarray, joints: Sequence) -> np.ndarray:
    """Gap (m) between the two sides of each revolute joint, shape ``(..., len(joints))``.

    Parameters
    ----------
    poses : numpy.ndarray, shape (..., nbodies, 3)
    joints : sequence of Joint
        ``(body_i, point_i, body_j, point_j)``.

    Returns
    -------
    numpy.ndarray

    Examples
    --------
    >>> import numpy as np
    >>> from balancelab import Joint
    >>> poses = np.array([[0.0, 0.0, 0.0], [0.0, 0.0, 1.0]])
    >>> joint_gaps(poses, [Joint(0, (0.0, 0.0), 1, (0.0, 0.0))]).tolist()
    [0.0]
    """
    if not joints:
        return np.zeros(poses.shape[:-2] + (0,))
    xi, yi = body_to_world(poses, [j[0] for j in joints], [j[1] for j in joints])
    xj, yj = body_to_world(poses, [j[2] for j in joints], [j[3] for j in joints])
    return np.hypot(xi - xj, yi - yj)


def central_difference(value: Callable[[np.ndarray], np.ndarray], reachable: Callable[[np.ndarray], np.ndarray],
                       q: np.ndarray, h: float | np.ndarray) -> np.ndarray:
    """Derivative of ``value`` with respect to each configuration coordinate, shape ``(..., dof)``.

    The one finite-difference loop of balancelab: central differences ``(v(q + h e_i) -
    v(q - h e_i)) / 2h``; where a neighbour is unreachable, the one-sided difference from ``q``
    itself (``value`` is never called at an unreachable configuration); where both are, zero.

    Parameters
    ----------
    value : callable
        ``value(q)`` for configurations of shape ``(m, dof)`` (or ``q``'s shape): an array whose
        *last* axis runs over the configurations (``(m,)``, ``(k, m)``, ...).
    reachable : callable
        ``reachable(q)``: boolean mask of shape ``(m,)``.
    q : numpy.ndarray, shape (m, dof)
        Configurations (rad for angles, m for slides), all reachable.
    h : float or numpy.ndarray, shape (dof,)
        Step (rad for angles, m for slides), > 0 (the caller checks it): one for every coordinate,
        or one per coordinate.

    Returns
    -------
    numpy.ndarray
        ``value``'s shape plus a last axis of length ``dof``.

    Examples
    --------
    >>> q = np.array([[0.0], [1.0]])
    >>> d = central_difference(lambda q: np.sin(q[..., 0]), lambda q: q[..., 0] <= 1.0, q, 1e-6)
    >>> np.round(d[:, 0], 5).tolist()     # cos 0, and one-sided at the end of the range
    [1.0, 0.5403]
    """
    dof = q.shape[-1]
    steps = np.broadcast_to(np.asarray(h, dtype=float), (dof,))
    out = []
    for i in range(dof):
        e = np.zeros(dof)
        e[i] = steps[i]
        okp, okm = reachable(q + e), reachable(q - e)
        vp = value(np.where(okp[..., None], q + e, q))
        vm = value(np.where(okm[..., None], q - e, q))
        out.append((vp - vm) / (steps[i] * np.maximum(okp.astype(float) + okm.astype(float), 1.0)))
    return np.stack(out, -1)


def spread(q_range: np.ndarray, n: int) -> np.ndarray:
    """``n`` configurations spread over ``q_range``: a fixed low-discrepancy set (Roberts' R_d).

    Deterministic (no seed), so a check made with it gives the same verdict every time.

    Examples
    --------
    >>> q = spread(np.array([[0.0, 1.0], [-1.0, 1.0]]), 5)
    >>> q.shape, bool((q[:, 0] > 0).all() and (q[:, 0] < 1).all())
    ((5, 2), True)
    """
    dof = q_range.shape[0]
    phi = 2.0
    for _ in range(30):  # phi^(dof+1) = phi + 1
        phi = (1 + phi) ** (1 / (dof + 1))
    alpha = phi ** -np.arange(1, dof + 1)
    u = (0.5 + np.arange(1, n + 1)[:, None] * alpha) % 1.0
    lo, hi = q_range[:, 0], q_range[:, 1]
    return lo + (hi - lo) * (0.02 + 0.96 * u)


class Kinematics(ABC):
    """Abstract base class of every mechanism's kinematics (see the module docstring).

    Examples
    --------
    A one-link lever, written from scratch:

    >>> import numpy as np
    >>> class Lever(Kinematics):
    ...     nbodies, names, q_range = 2, ("theta",), np.array([[-np.pi, np.pi]])
    ...     def poses(self, q):
    ...         q = np.asarray(q, dtype=float)
    ...         out = np.zeros(q.shape[:-1] + (2, 3))
    ...         out[..., 1, 2] = q[..., 0]
    ...         return out, np.ones(q.shape[:-1], dtype=bool)
    >>> Lever().reachable([[0.3]]).tolist()
    [True]
    """

    nbodies: int
    names: tuple[str, ...]
    q_range: np.ndarray
    #: bodies whose angles are the symbolic coordinates, when they are not ``q`` itself
    symbol_bodies: tuple | None = None
    #: True when :meth:`symbols` are independent coordinates (an open chain, a relaxed loop),
    #: False when they are tied by loop-closure equations; None: as many symbols as ``dof``
    independent_symbols: bool | None = None
    #: what each coordinate measures, in words (for axis labels); empty when unknown
    descriptions: tuple[str, ...] = ()

    @property
    def dof(self) -> int:
        """Number of configuration coordinates."""
        return len(self.names)

    @abstractmethod
    def poses(self, q: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """Return ``(poses, ok)``: poses of shape ``(..., nbodies, 3)`` and a boolean mask."""

    def poses_with_trig(self, q: np.ndarray) -> tuple[np.ndarray, np.ndarray, dict]:
        """:meth:`poses` plus any ``{body: (cos(angle), sin(angle))}`` already computed."""
        poses, ok = self.poses(q)
        return poses, ok, {}

    def reachable(self, q: np.ndarray) -> np.ndarray:
        """Boolean mask of the configurations ``q`` (shape ``(..., dof)``) the linkage reaches."""
        return self.poses(q)[1]

    def joint_error(self, q: np.ndarray, joints: Sequence) -> np.ndarray:
        """Largest gap (m) of any of ``joints`` at each configuration, shape ``(...)``.

        Unreachable configurations get ``inf``: their poses mean nothing.
        """
        poses, ok = self.poses(q)
        gaps = joint_gaps(poses, joints)
        worst = gaps.max(axis=-1) if gaps.shape[-1] else np.zeros(gaps.shape[:-1])
        return np.where(ok, worst, np.inf)

    def describe(self) -> tuple[str, ...]:
        """What each coordinate measures, in words (``""`` where the kinematics does not say).

        Examples
        --------
        >>> from balancelab.mechanisms import serial_2r_kinematics
        >>> serial_2r_kinematics(1.0).describe()
        ('angle of link 1 from the x-axis', 'angle of link 2 from the x-axis')
        """
        d = tuple(str(x) for x in self.descriptions)
        return d if len(d) == self.dof else ("",) * self.dof

    def symbols(self) -> tuple[Any, ...]:
        """The sympy symbols of the configuration coordinates."""
        import sympy as sp

        return sp.symbols(self.names, real=True)

    def symbolic_point(self, body: int, point: Sequence[Any], syms: Sequence[Any]) -> tuple[Any, Any]:
        """Global position (a pair of sympy expressions) of a local ``point`` of ``body``."""
        raise NotImplementedError(f"{type(self).__name__} has numeric kinematics only")

    def symbol_values(self, q: ArrayLike) -> np.ndarray:
        """Values of :meth:`symbols` in the configurations ``q``, shape ``(..., len(symbols))``."""
        q = np.asarray(q, dtype=float)
        if self.symbol_bodies is None:
            return q
        return self.poses(q)[0][..., list(self.symbol_bodies), 2]
