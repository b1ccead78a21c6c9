"""Singh & Ananthasuresh: 2R arms balanced by three ZFL springs from the ground, with minimum preload.

Three ZFL springs, one to link 1 and two to link 2, simplified (eqs 21-28) and general
(eqs 35-49), with minimum preload (eqs 29-34, 42-49); the two-spring variant (eq. 50);
the free-choice count (Table II, recounted from the rank of the conditions in
:mod:`.counting`). Coordinates: absolute link angles ``theta_1``, ``theta_2``; link 2 is
pivoted at distance ``l`` on link 1.
"""
from __future__ import annotations

import math

from ..registry import example
from ...core.design import Design
from ...core.elements import Load, Spring, SymbolicParts
from ...core.validation import finite_real, finite_reals, planar_points, positive_int
from ...mechanisms.base import TreeKinematics
from ...mechanisms.chain import TWO_TURNS, serial_2r_joints, serial_2r_kinematics
from .counting import conditions_rank

__all__ = ["serial_2r_simplified", "serial_2r_min_preload", "serial_2r_two_springs", "max_work_angle",
           "free_choice_count"]


def _singh_symbolic(general: bool):
    import sympy as sp

    W1, W2, l, g = sp.symbols("W_1 W_2 l g", positive=True)
    px1, py1, px2 = sp.symbols("p_x1 p_y1 p_x2", real=True)
    k = sp.symbols("k_1:4", positive=True)
    ax = sp.symbols("a_x1:4", real=True)
    bx = sp.symbols("b_x1:4", real=True) if general else (0, 0, 0)
    by = sp.symbols("b_y1:4", real=True)
    loads = ((1, (px1, py1 if general else 0), (0, -W1)), (2, (px2, 0), (0, -W2)))
    springs = tuple((k[i], 0, (0, (bx[i], by[i])), (1 if i == 0 else 2, (ax[i], 0))) for i in range(3))
    return (W1, W2, l, px1, py1, px2, k, ax, bx, by), loads, springs


def _singh_design(name, W1, W2, p1, px2, l, ax, bx, by, ks, reference, parameters) -> Design:
    general = p1[1] != 0 or any(v != 0 for v in bx)
    (W1s, W2s, ls, px1s, py1s, px2s, k, axs, bxs, bys), loads, springs = _singh_symbolic(general)
    values = {W1s: W1, W2s: W2, ls: l, px1s: p1[0], px2s: px2, **dict(zip(k, ks)),
              **dict(zip(axs, ax)), **dict(zip(bys, by))}
    if general:
        values[py1s] = p1[1]
        values.update(dict(zip(bxs, bx)))
    springs_num, springs_sym = [], []
    for i in range(3):
        if ks[i] == 0:
            continue
        springs_num.append(Spring(ks[i], 0.0, (0, (bx[i], by[i])), (1 if i == 0 else 2, (ax[i], 0.0)),
                                  name=f"k{i + 1}"))
        springs_sym.append(springs[i])
    labels = {"O": (0, (0.0, 0.0)), "J": (1, (l, 0.0))}
    for s in springs_num:
        n = s.name[1:]
        labels[f"a{n}"] = s.b
        labels[f"b{n}"] = s.a
    sym_kin = TreeKinematics(3, serial_2r_joints(ls), [[0, 0], [1, 0], [0, 1]], ("theta_1", "theta_2"),
                             TWO_TURNS)
    return Design(name, ("ground", "body 1", "body 2"), serial_2r_joints(l),
                  serial_2r_kinematics(l),
                  [Load(1, tuple(p1), (0.0, -W1), "W1", kind="weight"),
                   Load(2, (px2, 0.0), (0.0, -W2), "W2", kind="weight")],
                  springs_num, symbolic=SymbolicParts(loads, tuple(springs_sym), values, sym_kin),
                  labels=labels, parameters=parameters, reference=reference)


def _check_loads(weights, coms, length, *, on_axis: bool = False):
    """Checked loads of Singh's 2R: ``W1, W2, p1, p_x2, l`` (the paper's symbols)."""
    W1, W2 = finite_reals("weights (on bodies 1 and 2, N)", weights, 2, positive=True)
    p1, p2 = planar_points("coms (points of W1 on body 1 and W2 on body 2, m)", coms, 2)
    if p2[1] != 0:
        raise ValueError(f"coms[1] must lie on body 2's axis, (p_x2, 0): Singh's 2R has no p_y2, got {p2}")
    if on_axis and p1[1] != 0:
        raise ValueError(f"coms[0] must lie on body 1's axis, (p_x1, 0), in the simplified 2R, got {p1}; "
                         "use serial_2r_min_preload for p_y1 != 0")
    l = finite_real("length (of body 1, m)", length, positive=True)
    return W1, W2, p1, p2[0], l


def _positive_k(name, value, hint):
    if not math.isfinite(value):
        raise ValueError(f"{name} is infinite for these free choices ({hint})")
    if value <= 0:
        raise ValueError(f"{name} = {value:.6g} N/m is not positive for these free choices, so no "
                         f"spring can realize it ({hint})")
    return value


@example("serial_2r_simplified", "Simplified 2R with three ZFL springs (Singh eqs 21-28)", chapter=4)
def serial_2r_simplified(weights=(10.0, 20.0), coms=((1.0, 0.0), (2.0, 0.0)), length: float = 1.5,
                         a_x=(1.0, 2.0, -2.0), b_y=(1.0, 3.5, -0.5)) -> Design:
    """Singh & Ananthasuresh's simplified 2R with three ZFL springs (eqs 21-28).

    Loads ``W1`` at ``(p_x1, 0)`` on body 1 and ``W2`` at ``(p_x2, 0)`` on body 2; springs
    from ground anchors ``(0, b_yi)`` to ``(a_x1, 0)`` on body 1 and to ``(a_x2, 0)``,
    ``(a_x3, 0)`` on body 2. The coefficients of ``sin theta_1``, ``sin theta_2`` and
    ``cos(theta_1 - theta_2)`` vanish (eqs 22-24) when

    ``k2 = W2 p_x2 / (a_x2 (b_y2 - b_y3))`` (eq. 26), ``k3 = -W2 p_x2 / (a_x3 (b_y2 - b_y3))``
    (eq. 27) and ``k1 = (W1 p_x1 + W2 l - l (k2 b_y2 + k3 b_y3)) / (a_x1 b_y1)`` (eq. 25).

    Parameters
    ----------
    weights : (float, float)
        ``W1``, ``W2`` (N), > 0.
    coms : two (float, float)
        Their points ``(p_x1, 0)`` on body 1 and ``(p_x2, 0)`` on body 2 (m): on the links' axes.
    length : float
        Length ``l`` of body 1 (m), > 0.
    a_x, b_y : (float, float, float)
        The six free choices ``a_x1, a_x2, a_x3`` and ``b_y1, b_y2, b_y3`` (m); see Raises.

    Returns
    -------
    Design

    Raises
    ------
    ValueError
        For a singular choice (``b_y2 == b_y3``, ``a_x2 == 0``, ``a_x3 == 0``,
        ``a_x1 b_y1 == 0``) or one that needs a non-positive stiffness.

    Examples
    --------
    >>> d = serial_2r_simplified()
    >>> round(d.parameters["k2"], 3), round(d.parameters["k3"], 3)
    (5.0, 5.0)
    """
    W1, W2, p1, p_x2, l = _check_loads(weights, coms, length, on_axis=True)
    ax = finite_reals("a_x (m)", a_x, 3)
    by = finite_reals("b_y (m)", b_y, 3)
    vals = dict(a_x1=ax[0], b_y1=by[0], a_x2=ax[1], b_y2=by[1], a_x3=ax[2], b_y3=by[2])
    if vals["b_y2"] == vals["b_y3"]:
        raise ValueError("b_y2 == b_y3 is singular: eqs 26-27 divide by b_y2 - b_y3")
    for n in ("a_x2", "a_x3"):
        if vals[n] == 0:
            raise ValueError(f"{n} == 0 is singular: a spring attached at the joint cannot act on body 2")
    if vals["a_x1"] * vals["b_y1"] == 0:
        raise ValueError("a_x1 and b_y1 must be non-zero: eq. 25 divides by a_x1 b_y1")
    dy = vals["b_y2"] - vals["b_y3"]
    hint = "choose a_x2 a_x3 < 0 and (b_y2 - b_y3) p_x2 a_x2 > 0"
    k2 = _positive_k("k2", W2 * p_x2 / (vals["a_x2"] * dy), hint)
    k3 = _positive_k("k3", -W2 * p_x2 / (vals["a_x3"] * dy), hint)
    k1 = _positive_k("k1", (W1 * p1[0] + W2 * l - l * (k2 * vals["b_y2"] + k3 * vals["b_y3"]))
                     / (vals["a_x1"] * vals["b_y1"]), "a_x1 b_y1 must have the sign of the load term")
    ax = (vals["a_x1"], vals["a_x2"], vals["a_x3"])
    by = (vals["b_y1"], vals["b_y2"], vals["b_y3"])
    return _singh_design("simplified 2R, three ZFL springs", W1, W2, p1, p_x2, l, ax, (0.0,) * 3, by,
                         (k1, k2, k3), "Singh & Ananthasuresh, eqs 21-28",
                         {"k1": k1, "k2": k2, "k3": k3, **vals})


def max_work_angle(weights, coms, length: float) -> float:
    """Angle of body 1 at which the loads' energy is largest (Singh eq. 35), with ``atan2``.

    The loads' energy ``(W1 p_x1 + W2 l) sin theta_1 + W1 p_y1 cos theta_1 + ...`` is
    largest at ``theta_1 = atan2(W1 p_x1 + W2 l, W1 p_y1)``. The paper writes a plain
    ``tan^-1`` of the ratio, which picks the wrong quadrant when ``p_y1 < 0``.

    Parameters
    ----------
    weights : (float, float)
        ``W1``, ``W2`` (N).
    coms : two (float, float)
        Points ``p1`` of ``W1`` on body 1 and ``(p_x2, 0)`` of ``W2`` on body 2 (m).
    length : float
        Length ``l`` of body 1 (m).

    Returns
    -------
    float
        The angle ``theta*`` (rad).

    Examples
    --------
    >>> round(math.degrees(max_work_angle((10, 20), ((1.0, 0.5), (2.0, 0.0)), 1.5)), 3)
    82.875
    >>> round(math.degrees(max_work_angle((10, 20), ((1.0, -0.5), (2.0, 0.0)), 1.5)), 3)
    97.125
    """
    W1, W2, p1, _, l = _check_loads(weights, coms, length)
    return _theta_star(W1, W2, p1, l)


def _theta_star(W1, W2, p1, l) -> float:
    return math.atan2(W1 * p1[0] + W2 * l, W1 * p1[1])


def _min_preload(W1, W2, p1, p_x2, l, ax1, ax2, ax3):
    """Anchors (eqs 42-46) and stiffnesses (eqs 47-49, projected form) of the min-preload 2R.

    Body 2's loads do the most work at ``theta_2* = sign(p_x2) 90 deg`` (W2 straight above
    the elbow): the paper's ``theta_2 = 90 deg`` is the case ``p_x2 > 0``. The anchors sit
    where the springs have zero length there, ``b_i = J* + sign(p_x2) (0, a_xi)``, and then
    ``k2 a_x2^2 + k3 a_x3^2 = W2 |p_x2|`` (with ``k2 a_x2 + k3 a_x3 = 0``).
    """
    th = _theta_star(W1, W2, p1, l)
    sign = 1.0 if p_x2 > 0 else -1.0
    R = math.hypot(W1 * p1[0] + W2 * l, W1 * p1[1])
    c, s = W1 * p1[1] / R, (W1 * p1[0] + W2 * l) / R   # cos, sin theta* (exact 0 for p_y1 = 0)
    b1 = (ax1 * c, ax1 * s)
    b2 = (l * c, sign * ax2 + l * s)
    b3 = (l * c, sign * ax3 + l * s)
    k2 = W2 * abs(p_x2) / (ax2 * (ax2 - ax3))
    k3 = -W2 * abs(p_x2) / (ax3 * (ax2 - ax3))
    k1 = ((W1 * p1[0] + W2 * l - l * (k2 * b2[1] + k3 * b3[1])) * s
          + (W1 * p1[1] - l * (k2 * b2[0] + k3 * b3[0])) * c) / ax1 ** 2
    return th, b1, b2, b3, k1, k2, k3


def _free_choice_limits(W1, W2, p1, p_x2, l, ax2, ax3, names=("a_x2", "a_x3")):
    """Refuse, before solving, free choices that need a spring of negative stiffness.

    With ``k2 a_x2 + k3 a_x3 = 0`` and ``k2 a_x2^2 + k3 a_x3^2 = W2 |p_x2|`` (the
    minimum-preload conditions of body 2), ``k2, k3 > 0`` exactly when ``a_x2 a_x3 < 0``,
    and then ``k2 + k3 = W2 |p_x2| / (-a_x2 a_x3)``; ``k1 a_x1^2 = R - (k2 + k3) l^2`` with
    ``R = |(W1 p_x1 + W2 l, W1 p_y1)|``, so ``k1 > 0`` exactly when
    ``-a_x2 a_x3 > W2 |p_x2| l^2 / R``.
    """
    n2, n3 = names
    if ax2 * ax3 >= 0:
        raise ValueError(f"{n2} and {n3} must have opposite signs (springs on both sides of the elbow), "
                         f"got {n2} = {ax2}, {n3} = {ax3}: otherwise k2 or k3 is not positive (k2 a_x2 + k3 a_x3 = 0 "
                         f"and k2 a_x2^2 + k3 a_x3^2 = W2 |p_x2| > 0 need a_x2 a_x3 < 0)")
    return W2 * abs(p_x2) * l ** 2 / math.hypot(W1 * p1[0] + W2 * l, W1 * p1[1])


@example("serial_2r_min_preload", "General 2R with minimum preload (Singh eqs 35-49, Sec. III.A numbers)",
         chapter=4)
def serial_2r_min_preload(weights=(10.0, 20.0), coms=((1.0, 0.5), (2.0, 0.0)), length: float = 1.5,
                          a_x=(1.0, 2.0, -2.0)) -> Design:
    """2R balanced by three ZFL springs with the least preload (Singh eqs 29-49).

    Every spring has zero length in the configuration of maximum external work,
    ``theta_1 = theta*`` of eq. 35 (computed with ``atan2``) and ``theta_2* = 90 deg``
    for ``p_x2 > 0`` (``-90 deg`` for ``p_x2 < 0``: W2 is highest when it is straight
    above the elbow), so the balanced energy equals the largest energy of the loads, its
    lower bound. With the free choices ``a_x1, a_x2, a_x3`` and ``sigma = sign(p_x2)`` the
    anchors are (eqs 42-46) ``b_1 = a_x1 (cos theta*, sin theta*)``,
    ``b_2 = (l cos theta*, sigma a_x2 + l sin theta*)``,
    ``b_3 = (l cos theta*, sigma a_x3 + l sin theta*)`` and the stiffnesses (eqs 47-49)
    ``k2 = W2 |p_x2| / (a_x2 (a_x2 - a_x3))``, ``k3 = -W2 |p_x2| / (a_x3 (a_x2 - a_x3))``,
    and ``k1`` from eqs 40-41. Eq. 49 divides by ``cos theta*``, which vanishes in the
    simplified case ``p_y1 = 0`` (eqs 29-34); we use the equivalent form
    ``k1 a_x1^2 = [W1 p_x1 + W2 l - l(k2 b_y2 + k3 b_y3)] sin theta* + [W1 p_y1 - l(k2 + k3) b_x2] cos theta*``,
    valid in both cases.

    The paper takes ``theta_2* = 90 deg`` for any ``p_x2``; with ``p_x2 < 0`` that is the
    configuration of *least* work and its formulas give ``k2 a_x2^2 + k3 a_x3^2 = W2 p_x2 < 0``,
    which no pair of positive springs meets (for every choice of ``a_x``).

    With the defaults this is the 2R of the paper's four-bar example (Sec. III.A:
    ``W1 = 10 N``, ``W2 = 20 N``, ``p1 = (1, 0.5) m``, ``p_x2 = 2 m``, ``a_x = (1, 2, -2) m``);
    ``l = 1.5 m`` is not printed but is the length for which the printed
    ``b_x1 = 0.124 m`` and ``b_y1 = 0.9923 m`` follow.

    Parameters
    ----------
    weights : (float, float)
        ``W1``, ``W2`` (N), > 0.
    coms : two (float, float)
        Point ``p1`` of W1 on body 1 and ``(p_x2, 0)`` of W2 on body 2 (m), ``p_x2 != 0``
        (either sign).
    length : float
        Length ``l`` of body 1 (m), > 0.
    a_x : (float, float, float)
        Free choices ``a_x1, a_x2, a_x3`` (m), non-zero; ``a_x2`` and ``a_x3`` of opposite
        signs with ``-a_x2 a_x3 > W2 |p_x2| l^2 / |(W1 p_x1 + W2 l, W1 p_y1)|`` (else ``k1 <= 0``).

    Returns
    -------
    Design

    Raises
    ------
    ValueError
        Naming the parameter, for a free choice outside the ranges above or ``p_x2 == 0``.

    Examples
    --------
    >>> d = serial_2r_min_preload()
    >>> round(d.parameters["k1"], 2), round(d.parameters["b_y2"], 4)
    (17.81, 3.4884)
    >>> serial_2r_min_preload(coms=((1.0, 0.5), (-2.0, 0.0))).balance_report().balanced
    True
    """
    W1, W2, p1, p_x2, l = _check_loads(weights, coms, length)
    try:
        ax1, ax2, ax3 = finite_reals("a_x (m)", a_x, 3)
    except (TypeError, ValueError) as err:
        raise type(err)(f"a_x must be three numbers (a_x1, a_x2, a_x3) in metres: {err}") from None
    if ax2 == ax3:
        raise ValueError("a_x2 == a_x3 is singular: eqs 47-48 divide by a_x2 - a_x3")
    if ax1 == 0 or ax2 == 0 or ax3 == 0:
        raise ValueError("a_x1, a_x2 and a_x3 must be non-zero: a spring attached at a joint "
                         "cannot balance the body")
    if p_x2 == 0:
        raise ValueError("coms[1]: p_x2 must be non-zero: with W2 on the elbow, body 2 needs no springs")
    bound = _free_choice_limits(W1, W2, p1, p_x2, l, ax2, ax3)
    th, b1, b2, b3, k1, k2, k3 = _min_preload(W1, W2, p1, p_x2, l, ax1, ax2, ax3)
    c, s = math.cos(th), math.sin(th)
    k1 = _positive_k("k1", k1, f"k1 > 0 needs -a_x2 a_x3 > W2 |p_x2| l^2 / |(W1 p_x1 + W2 l, W1 p_y1)| "
                     f"= {bound:.6g} m^2, got {-ax2 * ax3:.6g} m^2")
    params = {"theta_star": th, "theta_2_star": math.copysign(math.pi / 2, p_x2), "k1": k1, "k2": k2,
              "k3": k3, "a_x1": ax1, "a_x2": ax2, "a_x3": ax3,
              "b_x1": b1[0], "b_y1": b1[1], "b_x2": b2[0], "b_y2": b2[1], "b_x3": b3[0], "b_y3": b3[1],
              "PE_min": (W1 * p1[0] + W2 * l) * s + W1 * p1[1] * c + W2 * abs(p_x2)}
    return _singh_design("2R with minimum preload, three ZFL springs", W1, W2, p1, p_x2, l,
                         (ax1, ax2, ax3), (b1[0], b2[0], b3[0]), (b1[1], b2[1], b3[1]), (k1, k2, k3),
                         "Singh & Ananthasuresh, eqs 35-49", params)


@example("serial_2r_two_springs", "General 2R with two ZFL springs (Singh eq. 50)", chapter=4)
def serial_2r_two_springs(weights=(10.0, 20.0), coms=((1.0, 0.5), (2.0, 0.0)), length: float = 1.5,
                          a_x2: float = 2.0) -> Design:
    """The general 2R balanced by only two ZFL springs, both on body 2 (Singh eq. 50).

    Setting ``k1 = 0`` in eq. 49 fixes ``a_x2 a_x3 = -l W2 p_x2 b_x2 / (W1 p_y1)``; the
    springs keep the minimum-preload anchors of eqs 44-48 (see
    :func:`serial_2r_min_preload`, also for ``p_x2 < 0``). With
    ``b_x2 = l cos theta* = l W1 p_y1 / R``, ``R = |(W1 p_x1 + W2 l, W1 p_y1)|``, eq. 50 is
    ``a_x2 a_x3 = -W2 |p_x2| l^2 / R``, which we use: it also holds for ``p_y1 = 0``, where
    the printed form is ``0/0`` (the two springs then pull the elbow straight up).

    Parameters
    ----------
    weights, coms, length : see :func:`serial_2r_min_preload`.
    a_x2 : float
        The free choice (m), non-zero; ``a_x3`` follows from eq. 50.

    Returns
    -------
    Design

    Examples
    --------
    >>> d = serial_2r_two_springs()
    >>> len(d.springs), round(d.parameters["a_x3"], 4)
    (2, -1.1163)
    """
    W1, W2, p1, p_x2, l = _check_loads(weights, coms, length)
    a_x2 = finite_real("a_x2 (m)", a_x2)
    if p_x2 == 0:
        raise ValueError("coms[1]: p_x2 must be non-zero: with W2 on the elbow, body 2 needs no springs")
    if a_x2 == 0:
        raise ValueError("a_x2 must be non-zero: a spring attached at the elbow cannot balance body 2")
    a_x3 = -W2 * abs(p_x2) * l ** 2 / (math.hypot(W1 * p1[0] + W2 * l, W1 * p1[1]) * a_x2)
    if a_x3 == 0 or not math.isfinite(a_x3):
        raise ValueError(f"a_x2 = {a_x2} m gives a_x3 = {a_x3} m (eq. 50): choose a_x2 of the size of the "
                         "links")
    th, _, b2, b3, k1, k2, k3 = _min_preload(W1, W2, p1, p_x2, l, 1.0, a_x2, a_x3)
    hint = "a_x2 a_x3 < 0 makes both positive"
    _positive_k("k2", k2, hint)
    _positive_k("k3", k3, hint)
    ax = (1.0, a_x2, a_x3)
    bx = (0.0, b2[0], b3[0])
    by = (0.0, b2[1], b3[1])
    params = {"theta_star": th, "theta_2_star": math.copysign(math.pi / 2, p_x2), "k2": k2, "k3": k3,
              "a_x2": a_x2, "a_x3": a_x3, "b_x2": b2[0],
              "b_y2": b2[1], "b_x3": b3[0], "b_y3": b3[1], "k1_eq49": k1}
    return _singh_design("2R with two ZFL springs", W1, W2, p1, p_x2, l, ax, bx, by,
                         (0.0, k2, k3), "Singh & Ananthasuresh, eq. 50",
                         params)


def free_choice_count(N: int) -> dict:
    """Free choices left after balancing with minimum preload, from the rank of the conditions.

    A chain of ``N`` bodies with body 1 pivoted on the ground needs ``2N - 1`` ZFL springs
    from the ground (one to body 1, two to each other body) of five parameters each
    (``k`` and both end points). The conditions are the ``4N - 2`` independent balance
    equations and, for minimum preload, the zero length of every spring at the
    maximum-work configuration: two scalar equations a spring, ``2(2N - 1)``. ``N`` of
    them are implied by the others (with every spring at zero length the springs'
    energy is stationary at that configuration, and so is the loads'), so the rank is
    ``7N - 4`` and ``3N - 1`` choices remain. The rank is computed, not assumed:
    :func:`balancelab.methods.singh.counting.conditions_rank` at an exact generic solution.

    Singh & Ananthasuresh's Table II prints ``4N - 2``: it counts one zero-length
    condition per spring and none implied, ``5(2N - 1) - (4N - 2) - (2N - 1)``. For the
    2R that is 6 ("a_x1..a_x3 and the three a_y"), but ``k2 a_y2 + k3 a_y3 = 0`` is one of
    the balance conditions, so only 5 are free.

    Parameters
    ----------
    N : int
        Number of moving bodies, >= 1.

    Returns
    -------
    dict
        ``N``, ``springs``, ``parameters`` (unknowns), ``equations`` (independent balance
        equations), ``min_preload_conditions`` (two a spring), ``implied`` (=
        equations + min_preload_conditions - rank), ``rank``, ``free`` (= parameters -
        rank) and ``paper_free`` (Table II's ``4N - 2``).

    Examples
    --------
    >>> c = free_choice_count(2)
    >>> c["rank"], c["free"], c["paper_free"]
    (10, 5, 6)
    """
    N = positive_int("N", N)
    r = conditions_rank(N)
    springs = 2 * N - 1
    conditions = r["balance_rank"] + r["zero_length_rank"]
    return {"N": N, "springs": springs, "parameters": r["unknowns"], "equations": r["balance_rank"],
            "min_preload_conditions": r["zero_length_rank"], "implied": conditions - r["rank"],
            "rank": r["rank"], "free": r["free"], "paper_free": 4 * N - 2}
