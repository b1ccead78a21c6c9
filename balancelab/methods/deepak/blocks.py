"""The building blocks of Deepak & Ananthasuresh (2012, Sec. 2.1), each balanced on its own.

The basic spring force balancer (Fig. 4), the balanced parallelogram with one and two
degrees of freedom (Figs 6, 7), the composition of two ZFL springs into one (Sec.
2.1.1) and the plagiograph (Sec. 2.1.2, eq. 1). :func:`balancing_springs` is the
step every technique repeats: a ZFL spring from a fixed point to a corner of a
parallelogram based at ``W`` is composed with balancing spring 1 into a spring from
``W``, which balancing spring 2 on the other diagonal cancels (eqs 2-4, 6-8);
:func:`balancing_family` is its one-parameter family. Complex numbers stand for planar
vectors (:func:`balancelab.mechanisms.geometry.as_complex`). Layer: methods.
"""
from __future__ import annotations

import math

import numpy as np
from numpy.typing import ArrayLike

from ...core.design import Design
from ...core.elements import Joint, Spring
from ...core.validation import MAX_MAGNITUDE, finite_real, planar_point
from ...mechanisms.base import TreeKinematics
from ...mechanisms.geometry import Point, as_complex, as_point
from ...mechanisms.lever import LEVER_JOINTS, lever_kinematics

__all__ = ["basic_balancer", "balanced_parallelogram", "compose_zfl_springs", "composing_anchor",
           "composed_springs_lever", "plagiograph_map", "balanced_plagiograph", "balancing_springs",
           "balancing_family"]


def basic_balancer(k: float, length: float, anchor_distance: float, angle: float = math.pi / 2) -> Design:
    """The basic spring force balancer (Deepak Fig. 4).

    A lever ``AD`` turns about ``A`` (the origin); two equal ZFL springs ``k`` run from
    ``D`` to the ground points ``P`` and ``N`` placed symmetrically about ``A``
    (``AN = -AP``). Their pull ``k (P - D) + k (N - D) = 2 k (A - D)`` always points at
    ``A``, so the lever is balanced: the energy is ``k (|AD|^2 + |AP|^2)``.

    Parameters
    ----------
    k : float
        Stiffness of each spring (N/m), > 0.
    length : float
        ``|AD|`` (m), > 0.
    anchor_distance : float
        ``|AP| = |AN|`` (m), > 0.
    angle : float
        Direction of ``AP`` from the x-axis (rad).

    Returns
    -------
    Design

    Examples
    --------
    >>> basic_balancer(50.0, 0.3, 0.2).balance_report().balanced
    True
    """
    k = finite_real("k (N/m)", k, positive=True)
    length = finite_real("length |AD| (m)", length, positive=True)
    a = finite_real("anchor_distance |AP| (m)", anchor_distance, positive=True)
    angle = finite_real("angle (rad)", angle)
    P = as_point(a * complex(math.cos(angle), math.sin(angle)))
    N = (-P[0], -P[1])
    kin = lever_kinematics("phi")
    springs = [Spring(k, 0.0, (0, P), (1, (length, 0.0)), name="k_P"),
               Spring(k, 0.0, (0, N), (1, (length, 0.0)), name="k_N")]
    return Design("basic spring force balancer", ("ground", "lever"), LEVER_JOINTS,
                  kin, (), springs, labels={"A": (0, (0.0, 0.0)), "P": (0, P), "N": (0, N),
                                            "D": (1, (length, 0.0))},
                  parameters={"k": k, "energy": k * (length ** 2 + a ** 2)},
                  reference="Deepak & Ananthasuresh 2012, Sec. 2.1, Fig. 4")


def balanced_parallelogram(k: float, a: float, b: float, angle: float = 0.0, dof: int = 1) -> Design:
    """A parallelogram ``ADEN`` with equal ZFL springs on its two diagonals (Figs 6, 7).

    With ``u = D - A`` and ``w = N - A`` the diagonals are ``u + w`` and ``u - w``;
    ``|u + w|^2 + |u - w|^2 = 2 (|u|^2 + |w|^2)`` is constant, so two springs of equal
    stiffness on the diagonals balance each other whatever the shape of the
    parallelogram.

    Parameters
    ----------
    k : float
        Stiffness of each diagonal spring (N/m), > 0.
    a : float
        ``|AD|`` (m), > 0.
    b : float
        ``|AN|`` (m), > 0.
    angle : float
        With ``dof=1``, the direction of the ground side ``AN`` (rad).
    dof : {1, 2}
        1: ``AN`` is the ground, ``AD`` a crank, ``DE`` a coupler and ``NE`` a rocker
        (Fig. 6; springs ``A-E`` and ``D-N``). 2: ``AD`` and ``AN`` both turn about ``A``
        (Fig. 7; springs ``A-E`` and ``D-N``, the latter between two moving links).

    Returns
    -------
    Design

    Examples
    --------
    >>> balanced_parallelogram(40.0, 0.2, 0.3, dof=2).balance_report().balanced
    True
    """
    k = finite_real("k (N/m)", k, positive=True)
    a = finite_real("a = |AD| (m)", a, positive=True)
    b = finite_real("b = |AN| (m)", b, positive=True)
    angle = finite_real("angle (rad)", angle)
    ref = "Deepak & Ananthasuresh 2012, Sec. 2.1, Figs 6-7"
    if dof == 1:
        N = as_point(b * complex(math.cos(angle), math.sin(angle)))
        joints = [Joint(0, (0.0, 0.0), 1, (0.0, 0.0)), Joint(1, (a, 0.0), 2, (0.0, 0.0)),
                  Joint(2, (b, 0.0), 3, (a, 0.0)), Joint(3, (0.0, 0.0), 0, N)]
        kin = TreeKinematics(4, joints[:3] + [joints[3]], [[0.0], [1.0], [0.0], [1.0]], ("phi",),
                             ((-math.pi, math.pi),), angle_offset=[0.0, 0.0, angle, 0.0])
        springs = [Spring(k, 0.0, (0, (0.0, 0.0)), (2, (b, 0.0)), name="k_AE"),
                   Spring(k, 0.0, (1, (a, 0.0)), (0, N), name="k_DN")]
        return Design("balanced parallelogram (1 dof)", ("ground", "AD", "DE", "NE"), joints, kin, (),
                      springs, labels={"A": (0, (0.0, 0.0)), "N": (0, N), "D": (1, (a, 0.0)),
                                       "E": (2, (b, 0.0))},
                      parameters={"k": k, "energy": k * (a * a + b * b)}, reference=ref)
    if dof != 2:
        raise ValueError(f"dof must be 1 or 2, got {dof!r}")
    joints = [Joint(0, (0.0, 0.0), 1, (0.0, 0.0)), Joint(0, (0.0, 0.0), 2, (0.0, 0.0)),
              Joint(1, (a, 0.0), 3, (0.0, 0.0)), Joint(2, (b, 0.0), 4, (0.0, 0.0)),
              Joint(3, (b, 0.0), 4, (a, 0.0))]
    kin = TreeKinematics(5, joints, [[0, 0], [1, 0], [0, 1], [0, 1], [1, 0]], ("phi_1", "phi_2"),
                         ((-math.pi, math.pi), (-math.pi, math.pi)))
    springs = [Spring(k, 0.0, (0, (0.0, 0.0)), (3, (b, 0.0)), name="k_AE"),
               Spring(k, 0.0, (1, (a, 0.0)), (2, (b, 0.0)), name="k_DN")]
    return Design("balanced parallelogram (2 dof)", ("ground", "AD", "AN", "DE", "NE"), joints, kin, (),
                  springs, labels={"A": (0, (0.0, 0.0)), "D": (1, (a, 0.0)), "N": (2, (b, 0.0)),
                                   "E": (3, (b, 0.0))},
                  parameters={"k": k, "energy": k * (a * a + b * b)}, reference=ref)


def compose_zfl_springs(k1: float, anchor1: Point, k2: float, anchor2: Point) -> tuple[float, Point, float]:
    """Compose two ZFL springs that share their moving end into one (Deepak Sec. 2.1.1).

    ``k1/2 |E - P1|^2 + k2/2 |E - P2|^2 = (k1 + k2)/2 |E - P|^2 + c`` for every ``E``, with
    ``P = (k1 P1 + k2 P2) / (k1 + k2)`` and the constant
    ``c = k1 k2 |P1 - P2|^2 / (2 (k1 + k2))``.

    Parameters
    ----------
    k1, k2 : float
        Stiffnesses (N/m), > 0.
    anchor1, anchor2 : (float, float)
        Fixed anchors (m).

    Returns
    -------
    (float, (float, float), float)
        Equivalent stiffness (N/m), equivalent anchor (m) and the constant ``c`` (J).

    Examples
    --------
    >>> compose_zfl_springs(1.0, (0, 0), 3.0, (4, 0))
    (4.0, (3.0, 0.0), 6.0)
    """
    k1 = finite_real("k1 (N/m)", k1, positive=True)
    k2 = finite_real("k2 (N/m)", k2, positive=True)
    p1, p2 = np.array(planar_point("anchor1", anchor1)), np.array(planar_point("anchor2", anchor2))
    k = k1 + k2
    P = (k1 * p1 + k2 * p2) / k
    c = k1 * k2 * float(np.sum((p1 - p2) ** 2)) / (2 * k)
    return k, (float(P[0]), float(P[1])), c


def composing_anchor(k1: float, anchor1: Point, target: Point, k2: float) -> Point:
    """Anchor of a second spring ``k2`` that moves spring ``k1``'s anchor to ``target``.

    From ``k1 (target - anchor1) = -k2 (target - anchor2)`` (Deepak Sec. 2.1.1, with
    ``D = target``): ``anchor2 = target + k1/k2 (target - anchor1)``.

    Parameters
    ----------
    k1 : float
        Stiffness of the given spring (N/m), > 0.
    anchor1 : (float, float)
        Its anchor (m).
    target : (float, float)
        Desired anchor of the equivalent spring (m).
    k2 : float
        Stiffness of the added spring (N/m), > 0.

    Returns
    -------
    (float, float)

    Examples
    --------
    >>> composing_anchor(1.0, (0, 0), (3, 0), 3.0)
    (4.0, 0.0)
    """
    k1 = finite_real("k1 (N/m)", k1, positive=True)
    k2 = finite_real("k2 (N/m)", k2, positive=True)
    a1, t = np.array(planar_point("anchor1", anchor1)), np.array(planar_point("target", target))
    p = t + k1 / k2 * (t - a1)
    return float(p[0]), float(p[1])


def composed_springs_lever(k1: float, anchor1: Point, k2: float, length: float) -> Design:
    """A lever about the origin balanced by two unequal ZFL springs composed onto its pivot.

    Spring ``k1`` runs from ``anchor1`` to the lever's tip; spring ``k2`` from the anchor
    given by :func:`composing_anchor` (target: the pivot). Their composition is a spring
    of stiffness ``k1 + k2`` from the pivot to the tip, of constant length: the lever is
    balanced. With ``k1 = k2`` this is the basic balancer of Fig. 4.

    Parameters
    ----------
    k1 : float
        Stiffness of the first spring (N/m), > 0.
    anchor1 : (float, float)
        Its ground anchor (m), not the pivot.
    k2 : float
        Stiffness of the second spring (N/m), > 0.
    length : float
        Lever length (m), > 0.

    Returns
    -------
    Design

    Examples
    --------
    >>> composed_springs_lever(30.0, (0.0, 0.2), 10.0, 0.25).balance_report().balanced
    True
    """
    length = finite_real("length (m)", length, positive=True)
    a1 = planar_point("anchor1", anchor1)
    if a1 == (0.0, 0.0):
        raise ValueError("anchor1 is on the pivot: the spring is already balanced on its own")
    a2 = composing_anchor(k1, a1, (0.0, 0.0), k2)
    kin = lever_kinematics("phi")
    springs = [Spring(k1, 0.0, (0, a1), (1, (length, 0.0)), name="k1"),
               Spring(k2, 0.0, (0, a2), (1, (length, 0.0)), name="k2")]
    return Design("lever balanced by a composition of two ZFL springs", ("ground", "lever"),
                  LEVER_JOINTS, kin, (), springs,
                  labels={"A": (0, (0.0, 0.0)), "P1": (0, a1), "P2": (0, a2), "E": (1, (length, 0.0))},
                  parameters={"k1": k1, "k2": k2, "k_equivalent": k1 + k2, "anchor2_x": a2[0],
                              "anchor2_y": a2[1]},
                  reference="Deepak & Ananthasuresh 2012, Sec. 2.1.1, Fig. 8")


def plagiograph_map(m: float, alpha: float, base: Point, point: Point) -> Point:
    """Image of ``point`` under a plagiograph based at ``base``: ``PN = m R_alpha(PM)`` (eq. 1).

    Parameters
    ----------
    m : float
        Scale (-), > 0.
    alpha : float
        Rotation (rad), counter-clockwise positive.
    base : (float, float)
        Base pivot ``P`` (m).
    point : (float, float)
        Input point ``M`` (m).

    Returns
    -------
    (float, float)
        Output point ``N`` (m).

    Examples
    --------
    >>> [round(v, 12) for v in plagiograph_map(2.0, math.pi / 2, (0, 0), (1, 0))]
    [0.0, 2.0]
    """
    m = finite_real("m (scale)", m, positive=True)
    alpha = finite_real("alpha (rad)", alpha)
    P, M = as_complex(planar_point("base", base)), as_complex(planar_point("point", point))
    return as_point(P + m * np.exp(1j * alpha) * (M - P))


def balanced_plagiograph(a: float, b: float, m: float, alpha: float, K: Point, k_l: float, h: float,
                         parallelogram: str = "P") -> Design:
    """A two-degree-of-freedom plagiograph carrying a ZFL load spring, balanced (Sec. 2.1.2).

    Parallelogram ``PQRS`` (``P`` at the origin, ``PQ = a``, ``QR = b``); the input
    point ``M`` is on link ``QR`` with ``RQ / MQ = m`` and ``angle RQM = alpha``; the output
    ``N`` on link ``SR`` with ``NS / RS = m`` and ``angle NSR = alpha``, so that
    ``PN = m R_alpha(PM)`` (eq. 1). A load spring ``k_l`` from ``K`` to ``M`` has the energy
    of a spring ``k_l/m^2`` from ``L = P + m R_alpha(PK)`` to ``N``; that spring is balanced
    as in technique 2 on the two-link chain ``P-S-N``: spring 1 ``k_b`` from ``H`` to ``N`` with
    ``k_b (H - P) = k_l/m^2 (P - L)`` and spring 2 ``k_t = k_b + k_l/m^2`` from ``P`` to
    ``T = 2S - N``. Balanced for both degrees of freedom.

    Parameters
    ----------
    a, b : float
        ``|PQ|``, ``|QR|`` (m), > 0.
    m : float
        Scale (-), > 0.
    alpha : float
        Rotation (rad).
    K : (float, float)
        Anchor of the load spring (m); must not map onto ``P``.
    k_l : float
        Load spring stiffness (N/m), > 0.
    h : float
        Distance ``|PH|`` along the locus of ``H`` (m), > 0.
    parallelogram : {"P"}
        Base of the balanced parallelogram (only the base pivot ``P`` is offered).

    Returns
    -------
    Design

    Examples
    --------
    >>> d = balanced_plagiograph(0.2, 0.3, 1.5, 0.4, (0.1, -0.3), 50.0, 0.1)
    >>> d.balance_report().balanced
    True
    """
    a = finite_real("a = |PQ| (m)", a, positive=True)
    b = finite_real("b = |QR| (m)", b, positive=True)
    m = finite_real("m (scale)", m, positive=True)
    alpha = finite_real("alpha (rad)", alpha)
    K = planar_point("K (m)", K)
    k_l = finite_real("k_l (N/m)", k_l, positive=True)
    if parallelogram != "P":
        raise ValueError(f"parallelogram must be 'P', got {parallelogram!r}")
    rho = m * np.exp(1j * alpha)
    # M on link QR: (M - Q) = (R - Q) / rho   ->  local (b / rho) in QR's frame
    M_loc = as_point(b / rho)
    # N on link SR: N - S = rho (R - S)        ->  local (a rho) in SR's frame
    N_loc = as_point(a * rho)
    L = rho * as_complex(K)
    k_e = k_l / m ** 2
    H, k_b, k_t = balancing_springs(0j, L, k_e, h)
    # bodies: 1 PQ (q1), 2 QR (q2), 3 PS (q2), 4 SR (q1)
    joints = [Joint(0, (0.0, 0.0), 1, (0.0, 0.0)), Joint(0, (0.0, 0.0), 3, (0.0, 0.0)),
              Joint(1, (a, 0.0), 2, (0.0, 0.0)), Joint(3, (b, 0.0), 4, (0.0, 0.0)),
              Joint(2, (b, 0.0), 4, (a, 0.0))]
    kin = TreeKinematics(5, joints, [[0, 0], [1, 0], [0, 1], [0, 1], [1, 0]], ("q_1", "q_2"),
                         ((-math.pi, math.pi), (-math.pi, math.pi)))
    T_loc = (-N_loc[0], -N_loc[1])
    springs = [Spring(k_l, 0.0, (0, K), (2, M_loc), name="k_l"),
               Spring(k_b, 0.0, (0, as_point(H)), (4, N_loc), name="k_b"),
               Spring(k_t, 0.0, (0, (0.0, 0.0)), (4, T_loc), name="k_t")]
    return Design("balanced plagiograph", ("ground", "PQ", "QRM", "PS", "SRN"), joints, kin, (), springs,
                  labels={"P": (0, (0.0, 0.0)), "K": (0, K), "L": (0, as_point(L)), "H": (0, as_point(H)),
                          "M": (2, M_loc), "N": (4, N_loc), "T": (4, T_loc)},
                  parameters={"m": m, "alpha": alpha, "k_l": k_l, "k_b": k_b, "k_t": k_t, "h": h,
                              "L_x": L.real, "L_y": L.imag, "H_x": H.real, "H_y": H.imag},
                  reference="Deepak & Ananthasuresh 2012, Sec. 2.1.2 (eq. 1) with eqs 5-8")


def balancing_springs(W: complex, L: complex, k_e: float, h: float) -> tuple[complex, float, float]:
    """Anchor ``H`` of balancing spring 1 and the stiffnesses ``k_b``, ``k_t`` balancing a spring from ``L``.

    A ZFL spring ``k_e`` from the fixed point ``L`` pulls on a corner ``E`` of a
    parallelogram based at ``W``. Balancing spring 1 ``k_b`` from ``H`` to ``E`` with
    ``k_b (H - W) = k_e (W - L)`` (eq. 2 / 6) makes the two one spring ``k_b + k_e`` from
    ``W`` (Sec. 2.1.1); ``H`` lies at the distance ``h`` from ``W`` along ``L -> W``, so
    ``k_b = k_e |LW| / h`` (eq. 3 / 7), and balancing spring 2 on the other diagonal of
    the parallelogram needs ``k_t = k_b + k_e`` (eq. 4 as corrected, eq. 8).

    Parameters
    ----------
    W : complex
        Base pivot of the parallelogram (m, as ``x + i y``).
    L : complex
        Anchor of the (equivalent) load spring (m); must not coincide with ``W``.
    k_e : float
        Stiffness of the (equivalent) load spring (N/m), > 0.
    h : float
        Free parameter ``|WH|`` (m), > 0 (``h = 0`` needs an infinite ``k_b``, ``h < 0`` a
        negative one: both raise ValueError).

    Returns
    -------
    (complex, float, float)
        ``H`` (m), ``k_b`` and ``k_t`` (N/m).

    Examples
    --------
    >>> H, k_b, k_t = balancing_springs(0j, 0.3 + 0.4j, 100.0, 0.25)
    >>> H, k_b, k_t
    ((-0.15-0.2j), 200.0, 300.0)
    """
    h = finite_real("h (distance WH along the locus of H, m)", h)
    d = W - L
    dist = abs(d)
    if dist <= 1e-12 * max(1.0, abs(W)):
        raise ValueError("the load spring's (equivalent) anchor coincides with the parallelogram's base "
                         "pivot W: the locus of H is undefined (no balancing spring 1 is needed; a single "
                         "spring k_t = k_l from W to T balances it)")
    if h == 0:
        raise ValueError("h = 0 puts H on the pivot W and needs an infinite stiffness k_b = k_l |KW| / |WH|; "
                         "choose h > 0")
    if h < 0:
        raise ValueError(f"h = {h} puts H on the wrong side of W: k_b = k_l |KW| / |WH| would be negative "
                         "(eq. 3 says H must lie along the direction from K to W); choose h > 0")
    H = W + h * d / dist
    k_b = k_e * dist / h
    if not math.isfinite(k_b) or k_b <= 0 or k_b + k_e > MAX_MAGNITUDE:
        raise ValueError(f"h = {h} gives a stiffness k_b = {k_b} that is not finite and positive")
    return H, k_b, k_b + k_e


def balancing_family(W: complex, L: complex, k_e: float, h_values: ArrayLike) -> dict:
    """The one-parameter family of :func:`balancing_springs` over values of ``h = |WH|``.

    Parameters
    ----------
    W, L, k_e
        As in :func:`balancing_springs`.
    h_values : array_like
        Values of the free parameter (m), finite (ValueError otherwise; values <= 0
        are reported infeasible).

    Returns
    -------
    dict
        ``h``, ``H`` (n, 2), ``k_b``, ``k_t`` (NaN where infeasible) and the boolean
        ``feasible`` (False for ``h <= 0``: negative or infinite stiffness).

    Raises
    ------
    ValueError
        If ``L`` coincides with ``W`` (no locus of ``H``) or ``h_values`` is not a 1-D
        sequence of finite numbers.

    Examples
    --------
    >>> balancing_family(0j, 0.3 + 0.4j, 100.0, [0.0, 0.25])["k_b"].tolist()
    [nan, 200.0]
    """
    balancing_springs(W, L, k_e, 1.0)  # raise now if the locus is undefined
    h = np.atleast_1d(np.asarray(h_values, dtype=float))
    if h.ndim != 1:
        raise ValueError(f"h_values must be a 1-D sequence of lengths (m), got shape {h.shape}")
    if not np.all(np.isfinite(h)):
        raise ValueError(f"h_values must be finite lengths (m), got {h.tolist()}")
    H = np.full((len(h), 2), np.nan)
    kb = np.full(len(h), np.nan)
    kt = np.full(len(h), np.nan)
    ok = np.zeros(len(h), dtype=bool)
    for i, hi in enumerate(h):
        try:
            Hc, b, t = balancing_springs(W, L, k_e, hi)
        except ValueError:
            continue
        H[i], kb[i], kt[i], ok[i] = as_point(Hc), b, t, True
    return {"h": h, "H": H, "k_b": kb, "k_t": kt, "feasible": ok}
