"""The spring-loaded four-bar balanced by techniques 2 and 3 and by Herder's method.

Source: S. R. Deepak and G. K. Ananthasuresh, *Static balancing of a four-bar linkage
and its cognates*, Mechanism and Machine Theory 48 (2012) 62-80 (cited below as
"Deepak"). A four-bar ``A-D-C-B`` (ground pivots ``A`` and ``B``, crank ``AD``,
coupler ``DC`` carrying the coupler point ``E``, rocker ``BC``;
:class:`balancelab.mechanisms.fourbar.FourBar`) is loaded by a ZFL spring ``k_l`` from
``E`` to a ground anchor ``K``. This module holds the loaded four-bar itself,
technique 2 (no auxiliary link, two balancing springs; parallelogram based at ``A``
or ``B``, eqs 2-4), technique 3 (plagiograph + technique 2, four options, eqs 5-8),
Herder's method (the two options of technique 3 whose bases coincide) and the
one-parameter families of techniques 2 and 3, whose infeasible members (negative or
infinite stiffness) are reported, never returned. Technique 1 is in
:mod:`.technique1`, the building blocks in :mod:`.blocks`.

Notation in code: complex numbers stand for planar vectors. With the crank vector
``u = D - A``, the coupler vector ``v = C - D`` and the rocker vector ``w = C - B``, the
coupler point is ``E = D + z v`` where ``z = (e_x + i e_y) / |DC|`` is the complex ratio
fixed by the coupler triangle.

**Typo in the paper.** Eq. (4) is printed ``k_b = k_b + k_l``. Composing the load
spring ``k_l`` (anchor ``K``) with balancing spring 1 ``k_b`` (anchor ``H``), both on
``E``, gives one ZFL spring of stiffness ``k_l + k_b`` anchored at
``(k_l K + k_b H) / (k_l + k_b)``; eq. (2) puts that anchor at ``W``. The equivalent
spring along the diagonal ``WE`` of a parallelogram is balanced by a spring of the same
stiffness along the other diagonal, so balancing spring 2 must have
``k_t = k_b + k_l``. (Technique 3's eq. 8, ``k_t = k_b + k_l / m^2``, has the same form.)
The paper's own prototype (Sec. 2.3), said to satisfy eqs 2-4, confirms the reading: its
springs are in the ratio ``k_l : k_b : k_t = 1 : 1 : 2``, i.e. ``k_t = k_b + k_l``.
"""
from __future__ import annotations

import math
from typing import NamedTuple

import numpy as np
from numpy.typing import ArrayLike

from ...core.design import Design
from ...core.elements import Joint, Spring
from ...core.kinematics import Kinematics
from ...core.validation import finite_real, instance_of, planar_point, real_array
from ...mechanisms.base import ExplicitKinematics
from ...mechanisms.fourbar import FourBar, coupler_curve, fourbar_design, pivot_name
from ...mechanisms.geometry import Point, as_complex, as_point, numeric_only
from .blocks import balancing_family, balancing_springs

__all__ = ["load_spring", "spring_loaded_fourbar", "Technique2Parameters", "technique2_parameters",
           "technique2", "technique2_family", "Technique3Parameters", "technique3_parameters", "technique3",
           "technique3_family", "herder"]


def load_spring(fourbar: FourBar, K: Point, k_l: float) -> Spring:
    """The load: a ZFL spring ``k_l`` (named ``"k_l"``) from the ground anchor ``K`` to the coupler point.

    Parameters
    ----------
    fourbar : FourBar
    K : (float, float)
        Ground anchor (m).
    k_l : float
        Stiffness (N/m), > 0.

    Returns
    -------
    Spring

    Examples
    --------
    >>> from balancelab.methods.deepak import example_fourbar
    >>> load_spring(example_fourbar(), (0.1, -0.2), 100.0).b.point
    (0.2, 0.12)
    """
    instance_of("fourbar", fourbar, FourBar, "a FourBar (balancelab.mechanisms.FourBar)")
    return Spring(k_l, 0.0, (0, K), (2, fourbar.coupler_point), name="k_l")


def spring_loaded_fourbar(fourbar: FourBar, K: Point, k_l: float) -> Design:
    """The four-bar loaded by a ZFL spring ``k_l`` from its coupler point ``E`` to ``K``.

    Without balancing springs its energy ``k_l/2 |E - K|^2`` is constant only if the
    coupler curve is a circle about ``K``, which it is not in general (Deepak Sec. 2.2,
    Fig. 10); ``parameters["distance_spread"]`` gives ``max |KE| - min |KE|``.

    Parameters
    ----------
    fourbar : FourBar
    K : (float, float)
        Ground anchor of the load spring (m).
    k_l : float
        Load spring stiffness (N/m), > 0.

    Returns
    -------
    Design

    Examples
    --------
    >>> from balancelab.methods.deepak import example_fourbar
    >>> d = spring_loaded_fourbar(example_fourbar(), (0.1, -0.2), 100.0)
    >>> d.balance_report().balanced
    False
    """
    instance_of("fourbar", fourbar, FourBar, "a FourBar (balancelab.mechanisms.FourBar)")
    K = planar_point("K (load spring anchor, m)", K)
    k_l = finite_real("k_l (load spring stiffness, N/m)", k_l, positive=True)
    E = coupler_curve(fourbar, 2001)
    dist = np.hypot(E[:, 0] - K[0], E[:, 1] - K[1])
    return fourbar_design("spring-loaded four-bar (unbalanced)", fourbar, (), [load_spring(fourbar, K, k_l)],
                          labels={"K": (0, K)},
                          parameters={"k_l": k_l, "distance_spread": float(np.ptp(dist))},
                          reference="Deepak & Ananthasuresh 2012, Sec. 2.2, Fig. 10")


# ----------------------------------------------------------------------- technique 2
class Technique2Parameters(NamedTuple):
    """Balancing parameters of technique 2 (Deepak eqs 2-4).

    ``W`` base pivot, ``H`` anchor of balancing spring 1 (on ``E``), ``k_b`` and ``k_t``
    (N/m); balancing spring 2 runs from ``W`` to ``T`` (coupler frame, m);
    ``direction`` the unit vector of the locus of ``H`` (``K`` to ``W``).

    Examples
    --------
    >>> from balancelab.methods.deepak import example_fourbar
    >>> technique2_parameters(example_fourbar(), (0.1, -0.2), 100.0, "B", 0.1).W
    (0.4, 0.0)
    """

    W: tuple
    H: tuple
    k_b: float
    k_t: float
    T: tuple
    direction: tuple


def technique2_parameters(fourbar: FourBar, K: Point, k_l: float, base: str = "A", h: float = 0.1
                          ) -> Technique2Parameters:
    """Balancing parameters of technique 2, parallelogram based at ``base`` (eqs 2-4).

    ``H = W + h (W - K)/|W - K|`` (eq. 2: the locus starts at ``W`` along ``KW``),
    ``k_b = k_l |KW| / h`` (eq. 3) and ``k_t = k_b + k_l`` (eq. 4 as derived; the paper
    prints ``k_b = k_b + k_l``). Spring 2 runs from ``W`` to ``T``, the reflection of ``E``
    through ``D`` (base ``A``) or through ``C`` (base ``B``).

    Parameters
    ----------
    fourbar : FourBar
    K : (float, float)
        Load spring anchor (m); must not coincide with ``W``.
    k_l : float
        Load spring stiffness (N/m), > 0.
    base : {"A", "B"}
        Where the balanced parallelogram is based.
    h : float
        Free parameter: distance ``|WH|`` (m), > 0 (``h <= 0`` means infinite or negative
        ``k_b`` and raises ValueError).

    Returns
    -------
    Technique2Parameters

    Examples
    --------
    >>> from balancelab.methods.deepak import example_fourbar
    >>> p = technique2_parameters(example_fourbar(), (0.1, -0.2), 100.0, "A", 0.1)
    >>> round(p.k_b, 3), round(p.k_t, 3)
    (223.607, 323.607)
    """
    instance_of("fourbar", fourbar, FourBar, "a FourBar (balancelab.mechanisms.FourBar)")
    pivot_name("base", base)
    K = planar_point("K (load spring anchor, m)", K)
    k_l = finite_real("k_l (load spring stiffness, N/m)", k_l, positive=True)
    base = pivot_name("base", base)
    W = fourbar.pivot(base)
    H, k_b, k_t = balancing_springs(W, as_complex(K), k_l, h)
    ex, ey = fourbar.coupler_point
    T = (-ex, -ey) if base == "A" else (2 * fourbar.coupler - ex, -ey)
    d = (W - as_complex(K)) / abs(W - as_complex(K))
    return Technique2Parameters(as_point(W), as_point(H), k_b, k_t, T, as_point(d))


def technique2(fourbar: FourBar, K: Point, k_l: float, base: str = "A", h: float = 0.1, *,
               driver: Kinematics | None = None) -> Design:
    """The spring-loaded four-bar balanced by technique 2: no auxiliary link, two springs.

    See :func:`technique2_parameters` for the equations. Springs: the load ``k_l``
    (``K`` to ``E``), balancing spring 1 ``k_b`` (``H`` to ``E``) and balancing spring 2
    ``k_t`` (``W`` to ``T`` on the coupler, Deepak Fig. 16).

    Parameters
    ----------
    fourbar, K, k_l, base, h
        As in :func:`technique2_parameters`.
    driver : Kinematics, optional
        Kinematics placing the four-bar's bodies 0-3 (by default ``fourbar.kinematics``);
        the cognates use one driven by another cognate's crank.

    Returns
    -------
    Design

    Examples
    --------
    >>> from balancelab.methods.deepak import example_fourbar
    >>> technique2(example_fourbar(), (0.1, -0.2), 100.0, "B", 0.05).balance_report().balanced
    True
    """
    p = technique2_parameters(fourbar, K, k_l, base, h)
    K = planar_point("K", K)
    springs = [load_spring(fourbar, K, k_l),
               Spring(p.k_b, 0.0, (0, p.H), (2, fourbar.coupler_point), name="k_b"),
               Spring(p.k_t, 0.0, (0, p.W), (2, p.T), name="k_t")]
    return fourbar_design(
        f"spring-loaded four-bar, technique 2 (parallelogram at {base})", fourbar, (), springs,
        kinematics=driver,
        labels={"K": (0, K), "H": (0, p.H), "W": (0, p.W), "T": (2, p.T)},
        parameters={"k_l": float(k_l), "k_b": p.k_b, "k_t": p.k_t, "h": float(h), "H_x": p.H[0],
                    "H_y": p.H[1]},
        reference="Deepak & Ananthasuresh 2012, Sec. 2.2.2, eqs 2-4 (eq. 4 corrected: k_t = k_b + k_l)")


def technique2_family(fourbar: FourBar, K: Point, k_l: float, base: str, h_values: ArrayLike) -> dict:
    """The one-parameter family of technique 2 as a function of ``h = |WH|``.

    Parameters
    ----------
    fourbar, K, k_l, base
        As in :func:`technique2_parameters`.
    h_values : array_like
        Values of the free parameter (m), finite (ValueError otherwise; values <= 0
        are reported infeasible).

    Returns
    -------
    dict
        ``h``, ``H`` (n, 2), ``k_b``, ``k_t`` (NaN where infeasible) and the boolean
        ``feasible`` (False for ``h <= 0``: negative or infinite stiffness).

    Examples
    --------
    >>> from balancelab.methods.deepak import example_fourbar
    >>> f = technique2_family(example_fourbar(), (0.1, -0.2), 100.0, "A", [-0.1, 0.0, 0.1])
    >>> f["feasible"].tolist()
    [False, False, True]
    """
    instance_of("fourbar", fourbar, FourBar, "a FourBar (balancelab.mechanisms.FourBar)")
    pivot_name("base", base)
    h_values = real_array("h_values (m)", h_values)
    Kc = as_complex(planar_point("K", K))
    k_l = finite_real("k_l (N/m)", k_l, positive=True)
    return balancing_family(fourbar.pivot(base), Kc, k_l, h_values)


# ----------------------------------------------------------------------- technique 3
class Technique3Parameters(NamedTuple):
    """Balancing parameters of technique 3 (Deepak eqs 5-8).

    ``U`` plagiograph base, ``W`` parallelogram base, ``m`` and ``alpha`` the
    plagiograph's scale and rotation, ``L`` the anchor of the equivalent load spring
    ``k_l/m^2``, ``H``, ``k_b``, ``k_t`` as in technique 2; ``G`` and ``T`` are the
    attachments of the two balancing springs on the auxiliary link ``SRG`` (its frame:
    origin ``S``, x-axis towards ``R``), ``R_local`` the joint with the coupler.

    Examples
    --------
    >>> from balancelab.methods.deepak import example_fourbar
    >>> p = technique3_parameters(example_fourbar(), (0.1, -0.2), 100.0, "A", "B", 0.1)
    >>> p.U, p.W
    ((0.0, 0.0), (0.4, 0.0))
    """

    U: tuple
    W: tuple
    m: float
    alpha: float
    L: tuple
    H: tuple
    k_b: float
    k_t: float
    G: tuple
    T: tuple
    R_local: tuple
    direction: tuple


def _t3_setup(fourbar: FourBar, K, plagiograph_base: str):
    fourbar.check_triangle()
    U = fourbar.pivot(pivot_name("plagiograph_base", plagiograph_base))
    rho = 1 / fourbar.z if plagiograph_base == "A" else 1 / (1 - fourbar.z)
    L = U + rho * (as_complex(K) - U)
    return U, rho, L


def technique3_parameters(fourbar: FourBar, K: Point, k_l: float, plagiograph_base: str = "A",
                          parallelogram_base: str = "A", h: float = 0.1) -> Technique3Parameters:
    """Balancing parameters of technique 3 (Deepak Sec. 2.2.3, eqs 5-8).

    A plagiograph completed on the four-bar with base ``U`` makes the point ``G`` of an
    auxiliary link follow ``UG = m R_alpha(UE)`` (eq. 1). With base ``A``:
    ``m = |DC|/|DE|`` and ``alpha`` the counter-clockwise angle that turns ``DE`` onto ``DC``
    (``m e^{i alpha} = 1/z``); with base ``B``: ``m = |CD|/|CE|`` and ``alpha`` the angle that
    turns ``CE`` onto ``CD`` (``m e^{i alpha} = 1/(1 - z)``; Fig. 18 calls it angle ``ECD``,
    clockwise in its drawing). The load
    spring then has the energy of a spring ``k_l/m^2`` from ``L`` (``UL = m R_alpha(UK)``,
    eq. 5) to ``G``, which technique 2 balances with the parallelogram based at ``W``:
    ``WH = k_l/(m^2 k_b) LW`` (eq. 6), ``k_b = k_l |LW| / (m^2 |WH|)`` (eq. 7),
    ``k_t = k_b + k_l/m^2`` (eq. 8).

    Parameters
    ----------
    fourbar : FourBar
        The coupler point must not coincide with ``D`` or ``C``.
    K : (float, float)
        Load spring anchor (m).
    k_l : float
        Load spring stiffness (N/m), > 0.
    plagiograph_base, parallelogram_base : {"A", "B"}
        ``U`` and ``W``.
    h : float
        Free parameter ``|WH|`` (m), > 0.

    Returns
    -------
    Technique3Parameters

    Examples
    --------
    >>> from balancelab.methods.deepak import example_fourbar
    >>> p = technique3_parameters(example_fourbar(), (0.1, -0.2), 100.0, "A", "B", 0.1)
    >>> round(p.m, 4)
    1.5006
    """
    instance_of("fourbar", fourbar, FourBar, "a FourBar (balancelab.mechanisms.FourBar)")
    pivot_name("plagiograph_base", plagiograph_base)
    pivot_name("parallelogram_base", parallelogram_base)
    K = planar_point("K (load spring anchor, m)", K)
    k_l = finite_real("k_l (N/m)", k_l, positive=True)
    U, rho, L = _t3_setup(fourbar, K, plagiograph_base)
    W = fourbar.pivot(pivot_name("parallelogram_base", parallelogram_base))
    m = abs(rho)
    k_e = k_l / m ** 2
    H, k_b, k_t = balancing_springs(W, L, k_e, h)
    ell = fourbar.crank if plagiograph_base == "A" else fourbar.rocker
    g = ell * rho
    T = -g if plagiograph_base == parallelogram_base else 2 * ell - g
    d = (W - L) / abs(W - L)
    return Technique3Parameters(as_point(U), as_point(W), float(m), float(np.angle(rho)), as_point(L),
                                as_point(H), k_b, k_t, as_point(g), as_point(T), (ell, 0.0), as_point(d))


def technique3(fourbar: FourBar, K: Point, k_l: float, plagiograph_base: str = "A",
               parallelogram_base: str = "A", h: float = 0.1, *, driver: Kinematics | None = None) -> Design:
    """The spring-loaded four-bar balanced by technique 3 (Deepak Fig. 17d / Fig. 18).

    Two auxiliary links complete a plagiograph: link 4 from ``U`` parallel to ``DC``
    (length ``|DC|``), link 5 from its tip ``S`` parallel to the crank (base ``A``) or to
    the rocker (base ``B``), jointed to the coupler at ``C`` (base ``A``) or ``D`` (base
    ``B``). Both balancing springs act on link 5. Equations: see
    :func:`technique3_parameters`.

    Parameters
    ----------
    fourbar, K, k_l, plagiograph_base, parallelogram_base, h
        As in :func:`technique3_parameters`.
    driver : Kinematics, optional
        As in :func:`technique2`.

    Returns
    -------
    Design

    Examples
    --------
    >>> from balancelab.methods.deepak import example_fourbar
    >>> d = technique3(example_fourbar(), (0.1, -0.2), 100.0, "B", "A", 0.1)
    >>> d.balance_report().balanced
    True
    """
    p = technique3_parameters(fourbar, K, k_l, plagiograph_base, parallelogram_base, h)
    K = planar_point("K", K)
    kin4 = fourbar.kinematics if driver is None else driver
    UA = plagiograph_base == "A"
    U = as_complex(p.U)
    r3 = fourbar.coupler

    def pose_fn(q, lib):
        numeric_only(lib)
        P4, _ = kin4.poses(np.stack(q, axis=-1))
        th3 = P4[..., 2, 2]
        a4 = th3 if UA else th3 + math.pi
        S = U + r3 * np.exp(1j * a4)
        a5 = P4[..., 1, 2] if UA else P4[..., 3, 2]
        out = [tuple(P4[..., i, j] for j in range(3)) for i in range(4)]
        out.append((np.full(S.shape, U.real), np.full(S.shape, U.imag), a4))
        out.append((S.real, S.imag, a5))
        return out

    kin = ExplicitKinematics(6, kin4.names, kin4.q_range, pose_fn, lambda q: kin4.poses(q)[1],
                              descriptions=kin4.describe())
    R_on_coupler = (r3, 0.0) if UA else (0.0, 0.0)
    joints = fourbar.joints() + [Joint(0, p.U, 4, (0.0, 0.0)), Joint(4, (r3, 0.0), 5, (0.0, 0.0)),
                                 Joint(5, p.R_local, 2, R_on_coupler)]
    springs = [load_spring(fourbar, K, k_l), Spring(p.k_b, 0.0, (0, p.H), (5, p.G), name="k_b"),
               Spring(p.k_t, 0.0, (0, p.W), (5, p.T), name="k_t")]
    lab = fourbar.labels()
    lab.update({"K": (0, K), "L": (0, p.L), "H": (0, p.H), "U": (0, p.U), "W": (0, p.W),
                "S": (4, (r3, 0.0)), "G": (5, p.G), "T": (5, p.T)})
    return Design(f"spring-loaded four-bar, technique 3 (plagiograph at {plagiograph_base}, "
                  f"parallelogram at {parallelogram_base})",
                  ("ground", "crank", "coupler", "rocker", "US", "SRG"), joints, kin, (), springs, labels=lab,
                  parameters={"k_l": float(k_l), "k_b": p.k_b, "k_t": p.k_t, "m": p.m, "alpha": p.alpha,
                              "h": float(h), "H_x": p.H[0], "H_y": p.H[1], "L_x": p.L[0], "L_y": p.L[1]},
                  reference="Deepak & Ananthasuresh 2012, Sec. 2.2.3, eqs 5-8, Figs 17-18")


def technique3_family(fourbar: FourBar, K: Point, k_l: float, plagiograph_base: str, parallelogram_base: str,
                      h_values: ArrayLike) -> dict:
    """The one-parameter family of a technique-3 option as a function of ``h = |WH|``.

    Parameters
    ----------
    fourbar, K, k_l, plagiograph_base, parallelogram_base
        As in :func:`technique3_parameters`.
    h_values : array_like
        Values of the free parameter (m), finite (ValueError otherwise; values <= 0
        are reported infeasible).

    Returns
    -------
    dict
        As :func:`technique2_family`.

    Examples
    --------
    >>> from balancelab.methods.deepak import example_fourbar
    >>> f = technique3_family(example_fourbar(), (0.1, -0.2), 100.0, "A", "A", [0.0, 0.2])
    >>> f["feasible"].tolist()
    [False, True]
    """
    instance_of("fourbar", fourbar, FourBar, "a FourBar (balancelab.mechanisms.FourBar)")
    pivot_name("plagiograph_base", plagiograph_base)
    pivot_name("parallelogram_base", parallelogram_base)
    h_values = real_array("h_values (m)", h_values)
    K = planar_point("K", K)
    k_l = finite_real("k_l (N/m)", k_l, positive=True)
    U, rho, L = _t3_setup(fourbar, K, plagiograph_base)
    W = fourbar.pivot(pivot_name("parallelogram_base", parallelogram_base))
    return balancing_family(W, L, k_l / abs(rho) ** 2, h_values)


def herder(fourbar: FourBar, K: Point, k_l: float, pivot: str = "A", h: float = 0.1) -> Design:
    """Herder's method (Herder 1998): technique 3 with coinciding bases ``U = W = pivot``.

    Herder balances a plagiograph first and then reduces it to the four-bar; the result
    is the technique-3 option whose plagiograph and balanced parallelogram share a base
    (Deepak Sec. 2.2.3), so Herder's method gives two of technique 3's four options:
    ``(A, A)`` and ``(B, B)``. The geometry of the auxiliary links and the attachments
    ``G``, ``T`` are fixed; ``H`` moves on a straight line (Fig. 2b).

    Parameters
    ----------
    fourbar, K, k_l, h
        As in :func:`technique3_parameters`.
    pivot : {"A", "B"}
        The common base.

    Returns
    -------
    Design

    Examples
    --------
    >>> from balancelab.methods.deepak import example_fourbar
    >>> herder(example_fourbar(), (0.1, -0.2), 100.0, "B", 0.1).balance_report().balanced
    True
    """
    instance_of("fourbar", fourbar, FourBar, "a FourBar (balancelab.mechanisms.FourBar)")
    pivot_name("pivot", pivot)
    pivot = pivot_name("pivot", pivot)
    d = technique3(fourbar, K, k_l, pivot, pivot, h)
    return d.replace(name=f"spring-loaded four-bar, Herder's method (base {pivot})",
                     reference="Herder 1998, as technique 3 with U = W (Deepak & Ananthasuresh 2012, "
                               "Sec. 2.2.3, Fig. 2b)")
