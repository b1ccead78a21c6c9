"""Payload changes: re-balance by moving anchors or changing stiffness, and the work an adjustment costs.

**Why a linear solve suffices.** For a ZFL spring whose anchor ``p`` sits on body ``A``
(pose ``X_A``, rotation ``R_A``) and whose other end is at ``r_b(q)``,
``k/2 |X_A + R_A p - r_b|^2 = k/2 |p|^2 + k p . R_A^T (X_A - r_b) + k/2 |X_A - r_b|^2``:
the design's energy is *affine* in the anchor's local coordinates (``|p|^2`` does not
depend on ``q``). It is also linear in every spring rate ``k``. So "which anchors (or
rates) make the energy constant for the new loads" is a linear least-squares problem
over sampled configurations, solved exactly by :func:`rebalance` when a solution exists
(the result is then checked with :meth:`Design.balance_report`). For the lecture's link
this gives the familiar ``b' = m' g r / (k c)``.

**The work of an adjustment** (derived here; the idea of energy-free adjustment is
Herder's, see the book's chapter 8 for the literature). Moving an anchor from ``p`` to
``p'`` while the mechanism stands still at ``q`` changes the spring energy by
``W(q) = k/2 (|B' - C(q)|^2 - |B - C(q)|^2)``: the work the adjusting hand (or motor) must
supply. It is zero when the move keeps the spring's length, i.e. the anchor travels on
a circle about the attachment point ``C(q)``; for the link with the anchor moved
straight up from ``b`` to ``b'``, ``W = k/2 (b' - b)(b' + b - 2 c sin(theta))``, zero at
``sin(theta) = (b + b') / (2 c)`` when that is reachable. :func:`adjustment_work` evaluates
it for any pair of designs. Layer: methods.
"""
from __future__ import annotations

from typing import Sequence

import numpy as np

from ...core.design import Design
from ...core.elements import Spring, gravity_load
from ...core.frames import turn_back
from ...core.validation import body_index
from .forces import configurations

__all__ = ["add_payload", "rebalance", "adjustment_work"]


def add_payload(design: Design, mass: float, body: int, point) -> Design:
    """The design with an extra mass ``mass`` (kg) at ``point`` of ``body`` (unbalanced in general).

    Examples
    --------
    >>> import balancelab as bl
    >>> d = add_payload(bl.lecture.single_link_spring(2.0, 0.5, 0.3, 0.2), 0.5, 1, (0.5, 0.0))
    >>> len(d.loads), d.balance_report().balanced
    (2, False)
    """
    load = gravity_load(body_index("body", body, len(design.bodies), moving=True), point, mass, name="payload")
    return design.replace(loads=[*design.loads, load], name=f"{design.name} + {mass:g} kg payload")


def _which(design: Design, springs) -> list[int]:
    idx = list(range(len(design.springs))) if springs is None else [int(i) for i in springs]
    if not idx or any(not 0 <= i < len(design.springs) for i in idx):
        raise ValueError(f"springs must be indices in 0..{len(design.springs) - 1}, got {springs!r}")
    return idx


def _anchor_columns(design: Design, q, idx):
    """Columns ``k_s R_A^T (X_A - r_b)`` and the design with the adjusted anchors at their body origins."""
    poses = design.poses(q)
    cols, springs = [], list(design.springs)
    for i in idx:
        s = design.springs[i]
        if not s.is_zfl:
            raise ValueError(f"spring {s.name or i} has free length {s.free_length} m: moving an anchor "
                             "re-balances exactly only ZFL springs")
        XA = poses[:, s.a.body, :2]
        rel = XA - design.world_points(q, [s.b])[:, 0]
        lx, ly = turn_back(np.cos(poses[:, s.a.body, 2]), np.sin(poses[:, s.a.body, 2]), (rel[:, 0], rel[:, 1]))
        cols += [s.k * lx, s.k * ly]
        springs[i] = Spring(s.k, 0.0, (s.a.body, (0.0, 0.0)), s.b, name=s.name, realization=s.realization)
    return cols, design.replace(springs=springs)


def rebalance(design: Design, adjust: str = "anchor", springs: Sequence[int] | None = None,
              n: int = 61) -> Design:
    """Re-balance a design (e.g. after :func:`add_payload`) by moving spring anchors or changing rates.

    Parameters
    ----------
    design : Design
        The design with its new loads.
    adjust : {"anchor", "stiffness"}
        Move the anchor ``a`` of each chosen ZFL spring (in its body's frame), or change
        the rate ``k`` of each chosen spring (its preload at every configuration scales with it).
    springs : sequence of int, optional
        Indices of the springs to adjust; all by default.
    n : int
        Configurations per coordinate of the least-squares fit.

    Returns
    -------
    Design
        Balanced (checked); ``parameters`` gain ``adjusted`` (the new anchors or rates).

    Raises
    ------
    ValueError
        When no such adjustment balances the design (the message gives the residual).

    Examples
    --------
    >>> import balancelab as bl
    >>> heavy = add_payload(bl.lecture.single_link_spring(2.0, 0.5, 0.3, 0.2), 0.5, 1, (0.5, 0.0))
    >>> d = rebalance(heavy)
    >>> np.round(d.springs[0].a.point, 6).tolist()   # b' = m' g r / (k c) = 0.375 m
    [0.0, 0.375]
    """
    if adjust not in ("anchor", "stiffness"):
        raise ValueError(f"adjust must be 'anchor' or 'stiffness', got {adjust!r}")
    idx = _which(design, springs)
    q = configurations(design, None, n)
    if adjust == "anchor":
        cols, base = _anchor_columns(design, q, idx)
    else:
        base = design.replace(springs=[s for i, s in enumerate(design.springs) if i not in idx])
        energies = design.element_energies(q)[1]
        cols = [energies[:, i] / design.springs[i].k for i in idx]
    V = base.potential_energy(q).total
    A = np.stack(cols + [np.ones(len(q))], -1)
    x, *_ = np.linalg.lstsq(A, -V, rcond=None)
    x = np.where(np.abs(x) < 1e-12 * np.abs(x[:-1]).max(), 0.0, x)  # round-off of a zero coordinate
    new = list(design.springs)
    for j, i in enumerate(idx):
        s = design.springs[i]
        if adjust == "anchor":
            new[i] = Spring(s.k, 0.0, (s.a.body, (float(x[2 * j]), float(x[2 * j + 1]))), s.b, name=s.name,
                            realization=s.realization)
        elif x[j] <= 0:
            raise ValueError(f"re-balancing needs a non-positive rate {x[j]:.4g} N/m for spring {s.name or i}")
        else:
            new[i] = Spring(float(x[j]), s.free_length, s.a, s.b, name=s.name, realization=s.realization)
    adjusted = {(s.name or str(i)): (new[i].a.point if adjust == "anchor" else new[i].k) for i, s in
                enumerate(design.springs) if i in idx}
    out = design.replace(springs=new, parameters={**design.parameters, "adjusted": adjusted},
                         name=f"{design.name}, re-balanced ({adjust})")
    report = out.balance_report()
    if not report.balanced:
        raise ValueError(f"{design.name}: adjusting the {adjust} of springs {idx} cannot balance it "
                         f"(best relative energy variation {report.variation:.3g}); adjust more springs")
    return out


def adjustment_work(before: Design, after: Design, q=None, n: int = 61) -> tuple[np.ndarray, np.ndarray]:
    """Work (J) to change the springs of ``before`` into those of ``after`` with the mechanism at rest at ``q``.

    The change of the springs' stored energy at each configuration: zero where the
    adjustment is energy-free (every adjusted spring keeps its length).

    Parameters
    ----------
    before, after : Design
        The same mechanism with the same number of springs.
    q, n
        Configurations (rad), or ``n`` per coordinate over the range.

    Returns
    -------
    (numpy.ndarray, numpy.ndarray)
        Configurations ``(m, dof)`` and the work ``(m,)`` (J).

    Examples
    --------
    >>> import balancelab as bl
    >>> d = bl.lecture.single_link_spring(2.0, 0.5, 0.3, 0.2)
    >>> new = rebalance(add_payload(d, 0.5, 1, (0.5, 0.0)))
    >>> q, W = adjustment_work(d, new, [[np.pi / 2]])
    >>> round(float(W[0]), 6)   # k/2 (b' - b)(b' + b - 2 c)
    1.686094
    """
    if len(before.springs) != len(after.springs) or before.dof != after.dof:
        raise ValueError("before and after must be the same mechanism with the same number of springs")
    q = configurations(before, q, n)
    return q, after.potential_energy(q).spring - before.potential_energy(q).spring
