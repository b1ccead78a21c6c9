"""Lecture 35: a single link balanced by a counterweight, a ZFL spring or (not) an ordinary spring.

The basic balancer :func:`link_spring` (``k = m g r / (b c)``, generalized to any first
moment) is the building block the lecture's 2R arms and four-bars reuse.
"""
from __future__ import annotations


import numpy as np

from ..registry import example
from ...core.design import Design
from ...core.elements import G, Spring, SymbolicParts, gravity_load
from ...core.validation import body_index, finite_real, planar_point
from ...mechanisms.lever import lever_design

__all__ = ["link_spring", "single_link_counterweight", "single_link_spring",
           "single_link_ordinary_spring"]


def link_spring(first_moment, b: float, c: float, *, body: int = 1, pivot_on_anchor=(0.0, 0.0),
                anchor_body: int = 0, pivot_on_link=(0.0, 0.0), anchor_up=(0.0, 1.0),
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
    pivot_on_anchor : (float, float)
        The pivot as a local point of ``anchor_body`` (m).
    anchor_body : int
        Body carrying the anchor (0: ground; a link that stays vertical also works).
    pivot_on_link : (float, float)
        The pivot as a local point of the link (m); usually its origin.
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
    anchor_body = body_index("anchor_body", anchor_body)
    body = body_index("body", body)
    M = np.asarray(planar_point("first_moment", first_moment))
    b = finite_real("b (anchor height above the pivot, m)", b, positive=True)
    c = finite_real("c (attachment distance from the pivot, m)", c, positive=True)
    norm = float(np.hypot(*M))
    if norm == 0:
        raise ValueError("first_moment is zero: the link's masses are centred on the pivot and "
                         "need no spring")
    u = M / norm
    k = G * norm / (b * c)
    ao = np.asarray(planar_point("pivot_on_link", pivot_on_link))
    pivot = planar_point("pivot_on_anchor", pivot_on_anchor)
    up = np.asarray(planar_point("anchor_up", anchor_up))
    if not np.isclose(np.hypot(*up), 1.0):
        raise ValueError(f"anchor_up must be a unit vector, got {tuple(up)}")
    return Spring(k, 0.0, (anchor_body, (pivot[0] + b * up[0], pivot[1] + b * up[1])),
                  (body, (ao[0] + c * u[0], ao[1] + c * u[1])), name=name)


@example("single_link_counterweight", "Single link balanced by a counterweight (lecture 35 recap)",
         chapter=1, mass=2.0, length=0.5, counter_mass=4.0, link_mass=0.5)
def single_link_counterweight(mass: float, length: float, counter_mass: float, *,
                              link_mass: float = 0.0) -> Design:
    """A link carrying ``mass`` at its tip, a distance ``length`` from the pivot, balanced by a counterweight.

    With ``r = length``, the counterweight sits at distance
    ``r_c = (mass r + link_mass r/2) / counter_mass`` on the far side of the pivot, so the centre of mass of the link stays on the pivot
    (lecture 35, recap of the previous lecture).

    Parameters
    ----------
    mass : float
        Mass at the end (kg), > 0.
    length : float
        Length of the link: the distance of the mass from the pivot (m), > 0.
    counter_mass : float
        Counterweight mass (kg), > 0.
    link_mass : float
        Mass of the uniform link itself (kg), >= 0, centred at ``length/2``.

    Returns
    -------
    Design

    Examples
    --------
    >>> d = single_link_counterweight(2.0, 0.5, 4.0)
    >>> round(d.parameters["r_c"], 3), d.balance_report().balanced
    (0.25, True)
    """
    mass = finite_real("mass (kg)", mass, positive=True)
    r = finite_real("length (m)", length, positive=True)
    counter_mass = finite_real("counter_mass (kg)", counter_mass, positive=True)
    link_mass = finite_real("link_mass (kg)", link_mass, nonnegative=True)
    rc = (mass * r + link_mass * r / 2) / counter_mass
    loads = [gravity_load(1, (r, 0.0), mass, "m")]
    if link_mass > 0:
        loads.append(gravity_load(1, (r / 2, 0.0), link_mass, "link"))
    loads.append(gravity_load(1, (-rc, 0.0), counter_mass, "counterweight", kind="counterweight"))
    return lever_design("single link with a counterweight", loads, [],
                         labels={"A": (0, (0.0, 0.0))},
                         parameters={"r_c": rc, "counter_mass": counter_mass},
                         reference="Lecture 35 (recap of counterweights)")


@example("single_link_zfl", "Single link with a ZFL spring, k = m g r/(b c) (lecture 35)",
         chapter=2, mass=2.0, length=0.5, b=0.3, c=0.2)
@example("single_link_zfl_below", "Single link with a ZFL spring below the pivot (lecture 35, second "
         "arrangement)", chapter=2, mass=2.0, length=0.5, b=0.3, c=0.2, arrangement="below")
def single_link_spring(mass: float, length: float, b: float, c: float, *,
                       arrangement: str = "above") -> Design:
    """The lecture's single link balanced by a ZFL spring, ``k = m g r / (b c)``.

    Parameters
    ----------
    mass : float
        Mass (kg) at the tip of the link, > 0.
    length : float
        Length of the link: the distance ``r`` of the mass from the pivot A (m), > 0.
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
    mass = finite_real("mass (kg)", mass, positive=True)
    r = finite_real("length (m)", length, positive=True)
    b = finite_real("b (m)", b, positive=True)
    c = finite_real("c (m)", c, positive=True)
    if arrangement not in ("above", "below"):
        raise ValueError(f"arrangement must be 'above' or 'below', got {arrangement!r}")
    k = mass * G * r / (b * c)
    sign = 1 if arrangement == "above" else -1
    B, C = (0.0, sign * b), (sign * c, 0.0)
    spring = Spring(k, 0.0, (0, B), (1, C), name="k")
    build_symbolic = _single_link_symbolic(sign)
    return lever_design(f"single link, ZFL spring ({arrangement})", [gravity_load(1, (r, 0.0), mass, "m")],
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


@example("single_link_ordinary_spring", "The same link with an ordinary spring: not balanced (lecture 35)",
         chapter=2, expected_balanced=False, mass=2.0, length=0.5, b=0.3, c=0.2, free_length=0.05)
def single_link_ordinary_spring(mass: float, length: float, b: float, c: float,
                                free_length: float) -> Design:
    """The single link with an *ordinary* spring of the same stiffness: not balanced.

    The spring has the lecture's ``k = m g r / (b c)`` but a free length ``a0 > 0``; the
    moment balance ``m g r = k (a - a0) b c / a`` then fails for every configuration but
    one, which the design's balance report shows.

    Parameters
    ----------
    mass, length, b, c : float
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
    free_length = finite_real("free_length (m)", free_length, positive=True)
    d = single_link_spring(mass, length, b, c)
    s = d.springs[0]
    spring = Spring(s.k, free_length, s.a, s.b, name="k")
    params = dict(d.parameters, free_length=free_length)
    return d.replace(name="single link, ordinary spring", springs=[spring], parameters=params)
