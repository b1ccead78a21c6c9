"""Single links and levers: counterweight, ZFL spring, LaCoste lever, generalized lever.

Sources: Lecture 35 (*Theory of Mechanisms*), single link with a ZFL spring,
``k = m g r / (b c)``; Singh & Ananthasuresh, *Minimization of preload in springs used
in static balancing of linkages under constant loads*, eqs 1-20.

Every function returns a :class:`balancelab.Design` whose body 1 is the link, pivoted
at the origin, with the configuration coordinate ``theta`` = the link's angle from the
global x-axis (the lecture measures its angle from the vertical: ``pi/2 - theta``).
"""
from __future__ import annotations

import math

import numpy as np

from .design import Design
from .elements import G, Joint, Load, Spring, SymbolicParts, _finite, _point, weight
from .kinematics import TreeKinematics

__all__ = [
    "lever_kinematics",
    "link_spring",
    "single_link_counterweight",
    "single_link_spring",
    "single_link_ordinary_spring",
    "lacoste_lever",
    "generalized_lever",
    "min_preload_lever",
]

FULL_TURN = ((-math.pi, math.pi),)


def lever_kinematics(name: str = "theta") -> TreeKinematics:
    """Kinematics of one link pivoted at the origin (bodies: ground, link).

    Parameters
    ----------
    name : str
        Name of the angle coordinate.

    Returns
    -------
    TreeKinematics

    Examples
    --------
    >>> lever_kinematics().dof
    1
    """
    joints = [Joint(0, (0.0, 0.0), 1, (0.0, 0.0))]
    return TreeKinematics(2, joints, [[0.0], [1.0]], (name,), FULL_TURN)


def _lever_design(name, loads, springs, *, symbolic=None, labels=None, parameters=None,
                  reference="", link="link") -> Design:
    return Design(name, ("ground", link), [Joint(0, (0.0, 0.0), 1, (0.0, 0.0))], lever_kinematics(),
                  loads, springs, symbolic=symbolic, labels=labels, parameters=parameters,
                  reference=reference)


def link_spring(first_moment, b: float, c: float, *, body: int = 1, pivot=(0.0, 0.0),
                anchor_body: int = 0, anchor_origin=(0.0, 0.0), anchor_up=(0.0, 1.0),
                name: str = "k") -> Spring:
    """ZFL spring that balances the weight of masses carried by a link turning about a pivot.

    A link carrying masses with first moment ``M = sum m_i p_i`` (kg m, local frame,
    about the pivot) has gravity energy ``G Im(M e^{i theta})`` (complex notation).
    A ZFL spring from an anchor a distance ``b`` straight above the pivot to the point
    a distance ``c`` from the pivot along ``M`` cancels it exactly when
    ``k = G |M| / (b c)``: the lecture's ``k = m g r / (b c)`` with ``m r = |M|``.

    Parameters
    ----------
    first_moment : (float, float)
        ``M`` in the link's local frame (kg m), about the pivot; must not be zero.
    b : float
        Height of the anchor above the pivot (m), > 0.
    c : float
        Distance of the attachment from the pivot along ``M`` (m), > 0.
    body : int
        The link.
    pivot : (float, float)
        Local point of ``anchor_body`` where the link is pivoted (m).
    anchor_body : int
        Body carrying the anchor (0: ground; a link that stays vertical also works).
    anchor_origin : (float, float)
        Local point of the link where the pivot is (m); usually the origin.
    anchor_up : (float, float)
        The global upward direction in ``anchor_body``'s local frame (a unit vector; that
        body must never turn). ``(0, 1)`` for the ground; ``(1, 0)`` for a link kept
        vertical with its x-axis pointing up.
    name : str
        Label of the spring.

    Returns
    -------
    Spring

    Examples
    --------
    >>> s = link_spring((2.0, 0.0), b=0.2, c=0.1)
    >>> round(s.k, 2)
    981.0
    """
    M = np.asarray(_point("first_moment", first_moment))
    b = _finite("b (anchor height above the pivot, m)", b, positive=True)
    c = _finite("c (attachment distance from the pivot, m)", c, positive=True)
    norm = float(np.hypot(*M))
    if norm == 0:
        raise ValueError("first_moment is zero: the link's masses are centred on the pivot and "
                         "need no spring")
    u = M / norm
    k = G * norm / (b * c)
    ao = np.asarray(anchor_origin, dtype=float)
    up = np.asarray(_point("anchor_up", anchor_up))
    if not np.isclose(np.hypot(*up), 1.0):
        raise ValueError(f"anchor_up must be a unit vector, got {tuple(up)}")
    return Spring(k, 0.0, (anchor_body, (pivot[0] + b * up[0], pivot[1] + b * up[1])),
                  (body, (ao[0] + c * u[0], ao[1] + c * u[1])), name=name)


def single_link_counterweight(mass: float, r: float, counter_mass: float, *,
                              link_mass: float = 0.0) -> Design:
    """A link carrying ``mass`` at distance ``r``, balanced by a counterweight behind the pivot.

    The counterweight sits at distance ``r_c = (mass r + link_mass r/2) / counter_mass``
    on the far side of the pivot, so the centre of mass of the link stays on the pivot
    (lecture 35, recap of the previous lecture).

    Parameters
    ----------
    mass : float
        Mass at the end (kg), > 0.
    r : float
        Its distance from the pivot (m), > 0.
    counter_mass : float
        Counterweight mass (kg), > 0.
    link_mass : float
        Mass of the uniform link itself (kg), >= 0, centred at ``r/2``.

    Returns
    -------
    Design

    Examples
    --------
    >>> d = single_link_counterweight(2.0, 0.5, 4.0)
    >>> round(d.parameters["r_c"], 3), d.balance_report().balanced
    (0.25, True)
    """
    mass = _finite("mass (kg)", mass, positive=True)
    r = _finite("r (m)", r, positive=True)
    counter_mass = _finite("counter_mass (kg)", counter_mass, positive=True)
    link_mass = _finite("link_mass (kg)", link_mass, nonnegative=True)
    rc = (mass * r + link_mass * r / 2) / counter_mass
    loads = [weight(1, (r, 0.0), mass, "m")]
    if link_mass > 0:
        loads.append(weight(1, (r / 2, 0.0), link_mass, "link"))
    loads.append(weight(1, (-rc, 0.0), counter_mass, "counterweight", kind="counterweight"))
    return _lever_design("single link with a counterweight", loads, [],
                         labels={"A": (0, (0.0, 0.0))},
                         parameters={"r_c": rc, "counter_mass": counter_mass},
                         reference="Lecture 35 (recap of counterweights)")


def single_link_spring(mass: float, r: float, b: float, c: float, *,
                       arrangement: str = "above") -> Design:
    """The lecture's single link balanced by a ZFL spring, ``k = m g r / (b c)``.

    Parameters
    ----------
    mass : float
        Mass (kg) at distance ``r`` from the pivot A, > 0.
    r : float
        Distance of the mass from A (m), > 0.
    b : float
        Distance AB from the pivot to the fixed spring anchor B (m), > 0.
    c : float
        Distance AC from the pivot to the spring's attachment C on the link (m), > 0.
    arrangement : {"above", "below"}
        ``"above"``: B straight above A and C on the link between A and the mass (the
        lecture's first slide). ``"below"``: B straight below A and C on the extension
        of the link behind the pivot (the second arrangement); same ``k``.

    Returns
    -------
    Design

    Examples
    --------
    >>> d = single_link_spring(2.0, 0.5, 0.3, 0.2)
    >>> round(d.parameters["k"], 3)
    163.5
    """
    mass = _finite("mass (kg)", mass, positive=True)
    r = _finite("r (m)", r, positive=True)
    b = _finite("b (m)", b, positive=True)
    c = _finite("c (m)", c, positive=True)
    if arrangement not in ("above", "below"):
        raise ValueError(f"arrangement must be 'above' or 'below', got {arrangement!r}")
    k = mass * G * r / (b * c)
    sign = 1 if arrangement == "above" else -1
    B, C = (0.0, sign * b), (sign * c, 0.0)
    spring = Spring(k, 0.0, (0, B), (1, C), name="k")
    build_symbolic = _single_link_symbolic(sign)
    return _lever_design(f"single link, ZFL spring ({arrangement})", [weight(1, (r, 0.0), mass, "m")],
                         [spring], symbolic=build_symbolic(mass, r, b, c, k),
                         labels={"A": (0, (0.0, 0.0)), "B": (0, B), "C": (1, C)},
                         parameters={"k": k, "b": b, "c": c, "r": r},
                         reference="Lecture 35, k = m g r / (b c)")


def _single_link_symbolic(sign):
    def build(mass, r, b, c, k):
        import sympy as sp

        m, rr, bb, cc, kk, g = sp.symbols("m r b c k g", positive=True)
        loads = [(1, (rr, 0), (0, -m * g))]
        springs = [(kk, 0, (0, (0, sign * bb)), (1, (sign * cc, 0)))]
        return SymbolicParts(tuple(loads), tuple(springs),
                             {m: mass, rr: r, bb: b, cc: c, kk: k, g: G})

    return build


def single_link_ordinary_spring(mass: float, r: float, b: float, c: float,
                                free_length: float) -> Design:
    """The single link with an *ordinary* spring of the same stiffness: not balanced.

    The spring has the lecture's ``k = m g r / (b c)`` but a free length ``a0 > 0``; the
    moment balance ``m g r = k (a - a0) b c / a`` then fails for every configuration but
    one, which the design's balance report shows.

    Parameters
    ----------
    mass, r, b, c : float
        As in :func:`single_link_spring`.
    free_length : float
        Free length ``a0`` of the spring (m), > 0.

    Returns
    -------
    Design

    Examples
    --------
    >>> single_link_ordinary_spring(2.0, 0.5, 0.3, 0.2, 0.05).balance_report().balanced
    False
    """
    free_length = _finite("free_length (m)", free_length, positive=True)
    d = single_link_spring(mass, r, b, c)
    s = d.springs[0]
    spring = Spring(s.k, free_length, s.a, s.b, name="k")
    params = dict(d.parameters, free_length=free_length)
    return d.replace(name="single link, ordinary spring", springs=[spring], parameters=params)


def lacoste_lever(weight: float, l: float, a_x: float, b_y: float) -> Design:
    """LaCoste's lever: a load ``W`` at ``(l, 0)`` balanced by one ZFL spring (Singh eqs 1-3).

    The spring runs from the fixed anchor ``b = (0, b_y)`` to ``a = (a_x, 0)`` on the
    lever. The energy ``k/2 (a_x^2 + b_y^2) + (W l - k a_x b_y) sin(theta)`` is constant
    when ``k = W l / (a_x b_y)`` (eq. 2); its constant value is
    ``W l / 2 (a_x / b_y + b_y / a_x)`` (eq. 3), smallest (``W l``) when ``a_x = b_y``.

    Parameters
    ----------
    weight : float
        The load W (N), > 0, acting downwards.
    l : float
        Its distance from the pivot along the lever (m), > 0.
    a_x : float
        Attachment on the lever (m), > 0.
    b_y : float
        Height of the fixed anchor above the pivot (m), > 0.

    Returns
    -------
    Design

    Examples
    --------
    >>> d = lacoste_lever(weight=10.0, l=0.5, a_x=0.2, b_y=0.3)
    >>> round(d.parameters["k"], 4), round(d.parameters["PE"], 4)
    (83.3333, 5.4167)
    """
    W = _finite("weight W (N)", weight, positive=True)
    l = _finite("l (m)", l, positive=True)
    a_x = _finite("a_x (m)", a_x, positive=True)
    b_y = _finite("b_y (m)", b_y, positive=True)
    k = W * l / (a_x * b_y)
    import sympy as sp

    Ws, ls, axs, bys, ks = sp.symbols("W l a_x b_y k", positive=True)
    sym = SymbolicParts(((1, (ls, 0), (0, -Ws)),), ((ks, 0, (0, (0, bys)), (1, (axs, 0))),),
                        {Ws: W, ls: l, axs: a_x, bys: b_y, ks: k})
    return _lever_design(
        "LaCoste lever", [Load(1, (l, 0.0), (0.0, -W), "W", kind="weight")],
        [Spring(k, 0.0, (0, (0.0, b_y)), (1, (a_x, 0.0)), name="k")], symbolic=sym,
        labels={"O": (0, (0.0, 0.0)), "a": (1, (a_x, 0.0)), "b": (0, (0.0, b_y)), "p": (1, (l, 0.0))},
        parameters={"k": k, "a_x": a_x, "b_y": b_y, "PE": W * l / 2 * (a_x / b_y + b_y / a_x)},
        reference="Singh & Ananthasuresh, eqs 1-3 (LaCoste 1934)", link="lever")


def generalized_lever(weight: float, l: float, a_x: float, b_x: float, b_y: float) -> Design:
    """The generalized lever of Singh & Ananthasuresh (eqs 12-17).

    A load ``W`` at ``p = (l, 0)`` and one ZFL spring from ``b = (b_x, b_y)`` (ground) to
    ``a = (a_x, a_y)`` (lever). Balance needs ``a_x b_x + a_y b_y = 0`` (eq. 13) and
    ``W l + k(-a_x b_y + a_y b_x) = 0`` (eq. 14), hence ``a_y = -a_x b_x / b_y`` (eq. 15) and
    ``k = W l b_y / (a_x (b_x^2 + b_y^2))`` (eq. 16). The balanced energy
    ``W l / (2 a_x b_y) (a_x^2 + b_y^2)`` (eq. 17) does not depend on ``b_x``.

    Parameters
    ----------
    weight : float
        W (N), > 0.
    l : float
        Distance of the load from the pivot (m), > 0.
    a_x, b_x, b_y : float
        Free choices (m). ``a_x`` and ``b_y`` must be non-zero and of the same sign
        (otherwise ``k`` would be negative).

    Returns
    -------
    Design

    Examples
    --------
    >>> d = generalized_lever(10.0, 0.5, 0.2, 0.1, 0.3)
    >>> round(d.parameters["a_y"], 4), round(d.parameters["k"], 3)
    (-0.0667, 75.0)
    """
    W = _finite("weight W (N)", weight, positive=True)
    l = _finite("l (m)", l, positive=True)
    a_x = _finite("a_x (m)", a_x)
    b_x = _finite("b_x (m)", b_x)
    b_y = _finite("b_y (m)", b_y)
    if a_x == 0:
        raise ValueError("a_x must be non-zero: a spring attached on the line through the pivot "
                         "perpendicular to the lever cannot balance it (eq. 16 divides by a_x)")
    if b_y == 0:
        raise ValueError("b_y must be non-zero: eq. 15 divides by b_y")
    if a_x * b_y < 0:
        raise ValueError(f"a_x and b_y must have the same sign (k = W l b_y / (a_x (b_x^2 + b_y^2)) "
                         f"would be negative); got a_x = {a_x}, b_y = {b_y}")
    a_y = -a_x * b_x / b_y
    k = W * l * b_y / (a_x * (b_x ** 2 + b_y ** 2))
    return _general_lever_design("generalized lever", W, l, (a_x, a_y), (b_x, b_y), k,
                                 "Singh & Ananthasuresh, eqs 12-17")


def _general_lever_design(name, W, l, a, b, k, reference) -> Design:
    import sympy as sp

    Ws, ls, ks = sp.symbols("W l k", positive=True)
    axs, ays, bxs, bys = sp.symbols("a_x a_y b_x b_y", real=True)
    sym = SymbolicParts(((1, (ls, 0), (0, -Ws)),), ((ks, 0, (0, (bxs, bys)), (1, (axs, ays))),),
                        {Ws: W, ls: l, ks: k, axs: a[0], ays: a[1], bxs: b[0], bys: b[1]})
    pe = W * l / (2 * a[0] * b[1]) * (a[0] ** 2 + b[1] ** 2)
    return _lever_design(
        name, [Load(1, (l, 0.0), (0.0, -W), "W", kind="weight")],
        [Spring(k, 0.0, (0, b), (1, a), name="k")], symbolic=sym,
        labels={"O": (0, (0.0, 0.0)), "a": (1, a), "b": (0, b), "p": (1, (l, 0.0))},
        parameters={"k": k, "a_x": a[0], "a_y": a[1], "b_x": b[0], "b_y": b[1], "PE": pe},
        reference=reference, link="lever")


def min_preload_lever(weight: float, l: float, a_x: float, a_y: float = 0.0) -> Design:
    """The lever balanced with the least spring preload (Singh eqs 18-20, ``PE_min = W l``).

    The spring's two ends coincide in the configuration of maximum external work
    (``theta = 90 deg``): ``b = (-a_y, a_x)``, i.e. ``a_x = b_y`` (eq. 18) and
    ``a_y = -b_x`` (eq. 19), and ``k = W l / (b_x^2 + b_y^2)`` (eq. 20). The constant
    energy is then ``W l``, the maximum of the load's energy: the lower bound for any
    balanced design (the spring energy cannot be negative).

    Parameters
    ----------
    weight : float
        W (N), > 0.
    l : float
        Distance of the load from the pivot (m), > 0.
    a_x : float
        Attachment on the lever along it (m), > 0.
    a_y : float
        Attachment across the lever (m).

    Returns
    -------
    Design

    Examples
    --------
    >>> d = min_preload_lever(10.0, 0.5, 0.5)
    >>> d.parameters["b_x"], d.parameters["b_y"], d.parameters["k"], d.parameters["PE"]
    (0.0, 0.5, 20.0, 5.0)
    """
    W = _finite("weight W (N)", weight, positive=True)
    l = _finite("l (m)", l, positive=True)
    a_x = _finite("a_x (m)", a_x, positive=True)
    a_y = _finite("a_y (m)", a_y)
    b = (0.0 - a_y, a_x)
    k = W * l / (b[0] ** 2 + b[1] ** 2)
    return _general_lever_design("lever with minimum preload", W, l, (a_x, a_y), b, k,
                                 "Singh & Ananthasuresh, eqs 18-20")
