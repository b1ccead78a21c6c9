"""A two-stage scissors lift balanced by one ordinary and one ZFL spring (Singh Sec. IV).

Bodies (Singh's numbers in brackets; ours are one less): 0 ground [1]; 1 lower arm from
the fixed pivot [2]; 2 lower arm from the bottom slider [3]; 3 bottom slider [4]; 4 upper
arm [5]; 5 upper arm [6]; 6 top slider [7]; 7 platform [8]. Every arm has length ``a``
and the arms of a stage cross at their midpoints, so with ``theta`` the angle of the
arms from the ground the centres of the stages are at heights ``a/2 sin theta`` and
``3a/2 sin theta`` and the platform at ``2a sin theta``.

Spring 1 joins the two crossing points (length ``a sin theta``, free length ``l10``);
spring 2 joins the fixed pivot to the bottom slider (length ``a cos theta``). The energy
is constant when ``k1 = k2`` (eq. 54), ``k1 l10 = g (m2/2 + m3/2 + 3 m5/2 + 3 m6/2 + 2 m7 + 2 m8)``
(eq. 55, the platform load included in ``m8``) and ``l20 = 0`` (eq. 56): spring 2 must be
a ZFL spring while spring 1 has a finite free length. The balanced energy
``k1/2 (a^2 + l10^2)`` is least for ``l10 = a`` (eq. 59).
"""
from __future__ import annotations



from ..registry import example
from ...core.design import Design
from ...core.elements import G, Spring, SymbolicParts, gravity_load
from ...core.validation import finite_real
from ...mechanisms.scissors import SCISSORS_BODIES, scissors_joints, scissors_kinematics

__all__ = ["scissors_lift"]


@example("scissors_lift", "Projector scissors lift, one ZFL and one finite-free-length spring (Singh Sec. IV)",
         chapter=6)
def scissors_lift(length: float = 0.5, arm_mass: float = 1.0, slider_mass: float = 0.2,
                  platform_mass: float = 2.0, payload_mass: float = 5.0,
                  free_length: float | None = None) -> Design:
    """The projector lift: a two-stage scissors balanced by two springs (Singh eqs 52-59).

    Parameters
    ----------
    length : float
        Arm length ``a`` (m), > 0.
    arm_mass : float
        Mass of each of the four arms (kg), > 0, at its midpoint.
    slider_mass : float
        Mass of each slider (kg), > 0.
    platform_mass : float
        Mass of the platform (kg), > 0.
    payload_mass : float
        Mass of the projector on the platform (kg), >= 0.
    free_length : float, optional
        Free length ``l10`` of spring 1 (m), > 0; by default ``a``, the minimum-preload
        choice (eq. 59). Spring 2 is always a ZFL spring (eq. 56).

    Returns
    -------
    Design

    Examples
    --------
    >>> d = scissors_lift()
    >>> d.parameters["k1"] == d.parameters["k2"], d.springs[1].is_zfl
    (True, True)
    >>> round(d.parameters["k1"] * d.parameters["l10"], 4)
    180.504
    """
    a = finite_real("length (of the arms, m)", length, positive=True)
    ma = finite_real("arm_mass (kg)", arm_mass, positive=True)
    ms = finite_real("slider_mass (kg)", slider_mass, positive=True)
    mp = finite_real("platform_mass (kg)", platform_mass, positive=True)
    mload = finite_real("payload_mass (kg)", payload_mass, nonnegative=True)
    l10 = a if free_length is None else finite_real("free_length (of spring 1, m)", free_length, positive=True)
    m8 = mp + mload
    c = G * (ma / 2 + ma / 2 + 3 * ma / 2 + 3 * ma / 2 + 2 * ms + 2 * m8)
    k = c / l10
    h = a / 2
    loads = [gravity_load(b, (h, 0.0), ma, f"m{b + 1}") for b in (1, 2, 4, 5)]
    loads += [gravity_load(3, (0.0, 0.0), ms, "m4"), gravity_load(6, (0.0, 0.0), ms, "m7"),
              gravity_load(7, (h, 0.0), mp, "m8")]
    if mload > 0:
        loads.append(gravity_load(7, (h, 0.0), mload, "projector"))
    springs = [Spring(k, l10, (1, (h, 0.0)), (4, (h, 0.0)), name="k1"),
               Spring(k, 0.0, (0, (0.0, 0.0)), (3, (0.0, 0.0)), name="k2")]
    import sympy as sp

    As, g, k1, k2, L10, L20 = sp.symbols("a g k_1 k_2 l_10 l_20", positive=True)
    m = {i: sp.Symbol(f"m_{i}", positive=True) for i in (2, 3, 4, 5, 6, 7, 8)}
    body_of = {2: 1, 3: 2, 5: 4, 6: 5}
    sym_loads = [(body_of[i], (As / 2, 0), (0, -m[i] * g)) for i in (2, 3, 5, 6)]
    sym_loads += [(3, (0, 0), (0, -m[4] * g)), (6, (0, 0), (0, -m[7] * g)), (7, (As / 2, 0), (0, -m[8] * g))]
    sym_springs = [(k1, L10, (1, (As / 2, 0)), (4, (As / 2, 0))), (k2, L20, (0, (0, 0)), (3, (0, 0)))]
    values = {As: a, g: G, k1: k, k2: k, L10: l10, L20: 0.0, m[2]: ma, m[3]: ma, m[5]: ma, m[6]: ma,
              m[4]: ms, m[7]: ms, m[8]: m8}
    sym = SymbolicParts(tuple(sym_loads), tuple(sym_springs), values, scissors_kinematics(As))
    return Design("scissors lift (projector)", SCISSORS_BODIES, scissors_joints(a), scissors_kinematics(a),
                  loads, springs, symbolic=sym,
                  labels={"O": (0, (0.0, 0.0)), "S": (3, (0.0, 0.0)), "P": (7, (0.0, 0.0))},
                  parameters={"k1": k, "k2": k, "l10": l10, "l20": 0.0, "k1_l10": c,
                              "PE": k / 2 * (a ** 2 + l10 ** 2)},
                  reference="Singh & Ananthasuresh, Sec. IV, eqs 52-59")
