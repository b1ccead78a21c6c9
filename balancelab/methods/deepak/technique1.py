"""Technique 1 of Deepak & Ananthasuresh (2012, Sec. 2.2.1): two auxiliary links, one spring.

A dyad ``K-P-E`` (link ``KP`` pivoted on the ground at the load spring's anchor ``K``,
link ``PET`` pivoted to it at ``P`` and to the coupler at ``E``) completes a
parallelogram ``KPEQ`` whose diagonal ``KE`` carries the load spring; a spring of the
same stiffness on the other diagonal balances it. The family has two free lengths,
``length_1 = |PE|`` and ``length_2 = |PK|`` (the paper's ``l1``, ``l2``); a member is
feasible when the dyad closes along the whole coupler curve. The dyad's joint ``P`` is
placed with :func:`balancelab.mechanisms.geometry.circle_intersection`. Layer: methods.
"""
from __future__ import annotations

import numpy as np
from numpy.typing import ArrayLike

from ...core.design import Design
from ...core.elements import Joint, Spring
from ...core.validation import finite_real, instance_of, planar_point, real_array
from ...mechanisms.base import ExplicitKinematics
from ...mechanisms.fourbar import FourBar, coupler_curve
from ...mechanisms.geometry import Point, as_complex, circle_intersection, numeric_only
from .techniques import load_spring

__all__ = ["technique1_feasible", "technique1_family", "technique1"]


def _dyad_joint(K, E, length_1: float, length_2: float, branch: int):
    """Joint ``P`` of the dyad ``K-P-E`` (``|PK| = length_2``, ``|PE| = length_1``) and where it closes."""
    x, y, ok = circle_intersection(K, length_2, (E.real, E.imag), length_1, branch)
    return x + 1j * y, ok


def _coupler_point(fourbar: FourBar, poses):
    """The coupler point ``E`` (complex) from the four-bar's body poses."""
    D = poses[..., 2, 0] + 1j * poses[..., 2, 1]
    return D + fourbar.coupler * fourbar.z * np.exp(1j * poses[..., 2, 2])


def _lengths(length_1, length_2) -> tuple[float, float]:
    return (finite_real("length_1 (the paper's l1 = |PE|, m)", length_1, positive=True),
            finite_real("length_2 (the paper's l2 = |PK|, m)", length_2, positive=True))


def technique1_feasible(fourbar: FourBar, K: Point, length_1: float, length_2: float) -> bool:
    """True when the auxiliary dyad of technique 1 assembles over the whole crank range.

    The dyad ``K-P-E`` closes when ``|l1 - l2| <= |KE| <= l1 + l2`` for every point of the
    coupler curve (``l1 = length_1``, ``l2 = length_2``).

    Parameters
    ----------
    fourbar : FourBar
    K : (float, float)
        Load spring anchor (m).
    length_1, length_2 : float
        ``|PE|`` and ``|PK|`` (m), > 0: the paper's ``l1``, ``l2``.

    Returns
    -------
    bool

    Raises
    ------
    ValueError
        If ``length_1`` or ``length_2`` is not a finite positive length.

    Examples
    --------
    >>> from balancelab.methods.deepak import example_fourbar
    >>> technique1_feasible(example_fourbar(), (0.1, -0.2), 0.3, 0.3)
    True
    """
    instance_of("fourbar", fourbar, FourBar, "a FourBar (balancelab.mechanisms.FourBar)")
    K = planar_point("K", K)
    l1, l2 = _lengths(length_1, length_2)
    E = coupler_curve(fourbar, 4001)
    dist = np.hypot(E[:, 0] - K[0], E[:, 1] - K[1])
    return bool(dist.min() > abs(l1 - l2) and dist.max() < l1 + l2)


def technique1_family(fourbar: FourBar, K: Point, k_l: float, length_1_values: ArrayLike,
                      length_2_values: ArrayLike) -> dict:
    """The two-parameter family of technique 1 over a grid of ``l1 = |PE|``, ``l2 = |PK|``.

    The balancing spring always has the load spring's stiffness ``k_l``; a member is
    feasible when the auxiliary dyad assembles along the whole coupler curve
    (``|l1 - l2| < |KE| < l1 + l2``).

    Parameters
    ----------
    fourbar : FourBar
    K : (float, float)
        Load spring anchor (m).
    k_l : float
        Load spring stiffness (N/m), > 0.
    length_1_values, length_2_values : array_like
        Values of ``l1 = |PE|`` and ``l2 = |PK|`` (m).

    Returns
    -------
    dict
        ``l1``, ``l2`` (1-D), ``feasible`` (bool, shape ``(len(l1), len(l2))``), ``k_b``
        (``k_l`` where feasible, NaN elsewhere) and the span ``KE_min``, ``KE_max`` (m).

    Examples
    --------
    >>> from balancelab.methods.deepak import example_fourbar
    >>> f = technique1_family(example_fourbar(), (0.1, -0.2), 100.0, [0.05, 0.3], [0.05, 0.3])
    >>> f["feasible"].tolist()
    [[False, False], [False, True]]
    """
    instance_of("fourbar", fourbar, FourBar, "a FourBar (balancelab.mechanisms.FourBar)")
    length_1_values = real_array("length_1_values (m)", length_1_values)
    length_2_values = real_array("length_2_values (m)", length_2_values)
    K = planar_point("K (load spring anchor, m)", K)
    k_l = finite_real("k_l (N/m)", k_l, positive=True)
    l1 = np.atleast_1d(np.asarray(length_1_values, dtype=float))
    l2 = np.atleast_1d(np.asarray(length_2_values, dtype=float))
    for name, v in (("length_1_values", l1), ("length_2_values", l2)):
        if v.ndim != 1 or not np.all(np.isfinite(v)):
            raise ValueError(f"{name} must be a 1-D sequence of finite lengths (m), got {v.tolist()}")
    E = coupler_curve(fourbar, 4001)
    dist = np.hypot(E[:, 0] - K[0], E[:, 1] - K[1])
    L1, L2 = np.meshgrid(l1, l2, indexing="ij")
    ok = (L1 > 0) & (L2 > 0) & (dist.min() > np.abs(L1 - L2)) & (dist.max() < L1 + L2)
    return {"l1": l1, "l2": l2, "feasible": ok, "k_b": np.where(ok, k_l, np.nan),
            "KE_min": float(dist.min()), "KE_max": float(dist.max())}


def technique1(fourbar: FourBar, K: Point, k_l: float, length_1: float, length_2: float, branch: int = 1
               ) -> Design:
    """The spring-loaded four-bar balanced by technique 1 (Deepak Sec. 2.2.1, Fig. 12).

    Two auxiliary links: ``KP`` (length ``l2``, pivoted on the ground at ``K``) and ``PET``
    (pivoted to ``KP`` at ``P`` and to the coupler at ``E``, ``|PE| = |PT| = l1``). With
    ``Q = K + E - P`` the parallelogram ``KPEQ`` has the load spring on the diagonal
    ``KE``; a spring of the same stiffness ``k_l`` on the other diagonal balances it
    (``|KE|^2 + |PQ|^2 = 2 (l1^2 + l2^2)``), and ``PQ = T - K`` lets it run from ``K`` to
    ``T`` instead. The family is two-parameter (``l1 = length_1``, ``l2 = length_2`` free); it
    is feasible when the dyad assembles along the whole coupler curve.

    Parameters
    ----------
    fourbar : FourBar
    K : (float, float)
        Load spring anchor (m).
    k_l : float
        Load spring stiffness (N/m), > 0; the balancing spring has the same.
    length_1, length_2 : float
        ``|PE|`` and ``|PK|`` (m), > 0: the paper's ``l1``, ``l2``.
    branch : {1, -1}
        Side of ``KE`` on which ``P`` lies.

    Returns
    -------
    Design

    Raises
    ------
    ValueError
        If the dyad cannot assemble over the whole crank range.

    Examples
    --------
    >>> from balancelab.methods.deepak import example_fourbar
    >>> technique1(example_fourbar(), (0.1, -0.2), 100.0, 0.3, 0.3).balance_report().balanced
    True
    """
    instance_of("fourbar", fourbar, FourBar, "a FourBar (balancelab.mechanisms.FourBar)")
    K = planar_point("K (load spring anchor, m)", K)
    k_l = finite_real("k_l (N/m)", k_l, positive=True)
    l1, l2 = _lengths(length_1, length_2)
    if branch not in (1, -1):
        raise ValueError(f"branch must be +1 or -1, got {branch!r}")
    if not technique1_feasible(fourbar, K, l1, l2):
        E = coupler_curve(fourbar, 4001)
        dist = np.hypot(E[:, 0] - K[0], E[:, 1] - K[1])
        raise ValueError(f"technique 1 with length_1 = {l1} m, length_2 = {l2} m cannot assemble: |KE| spans "
                         f"[{dist.min():.4g}, {dist.max():.4g}] m but the dyad closes only for "
                         f"|l1 - l2| < |KE| < l1 + l2 = [{abs(l1 - l2):.4g}, {l1 + l2:.4g}] m")
    Kc = as_complex(K)
    kin4 = fourbar.kinematics

    def pose_fn(q, lib):
        numeric_only(lib)
        qq = np.stack(q, axis=-1)
        P4, _ = kin4.poses(qq)
        E = _coupler_point(fourbar, P4)
        P, _ = _dyad_joint(K, E, l1, l2, branch)
        out = [tuple(P4[..., i, j] for j in range(3)) for i in range(4)]
        out.append((np.full(P.shape, K[0]), np.full(P.shape, K[1]), np.angle(P - Kc)))
        out.append((P.real, P.imag, np.angle(E - P)))
        return out

    def valid_fn(q):
        P4, ok = kin4.poses(q)
        return ok & _dyad_joint(K, _coupler_point(fourbar, P4), l1, l2, branch)[1]

    kin = ExplicitKinematics(6, ("theta",), kin4.q_range, pose_fn, valid_fn, descriptions=kin4.describe())
    joints = fourbar.joints() + [Joint(0, K, 4, (0.0, 0.0)), Joint(4, (l2, 0.0), 5, (0.0, 0.0)),
                                 Joint(5, (l1, 0.0), 2, fourbar.coupler_point)]
    springs = [load_spring(fourbar, K, k_l), Spring(k_l, 0.0, (0, K), (5, (-l1, 0.0)), name="k_b")]
    lab = fourbar.labels()
    lab.update({"K": (0, K), "P": (4, (l2, 0.0)), "T": (5, (-l1, 0.0))})
    return Design("spring-loaded four-bar, technique 1",
                  ("ground", "crank", "coupler", "rocker", "KP", "PET"),
                  joints, kin, (), springs, labels=lab,
                  parameters={"k_l": k_l, "k_b": k_l, "l1": l1, "l2": l2},
                  reference="Deepak & Ananthasuresh 2012, Sec. 2.2.1, Figs 11-12")


