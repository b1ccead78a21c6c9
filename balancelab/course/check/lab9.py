"""Lab 9, the non-circular pulley: a pulley you could cut, judged from its points.

Every verdict is computed by physics from the submitted numbers; nothing is taken from a
``Design`` the notebook made. The judge of 9.1 builds the submitted extension spring with
:mod:`balancelab.methods.practice.springs`, carries the submitted pitch-curve points round the
pivot, winds the cable on them from the eyelet (:func:`~balancelab.methods.realize.profile_check.polyline_path`:
tangent from the eyelet, then the polyline's length to the clamp), and asks

* is the link balanced: the load's energy plus the spring's, ``k/2 u^2`` with the stretch
  ``u`` from that path, constant to :data:`LAB9_TOLERANCE` of what the load exchanges;
* does the part fit: every point within :data:`LAB9_MAX_RADIUS` of the axle;
* can the cable wrap it: the polyline turns one way only, the cable's way (``turn``) towards the
  clamped end, and its radius of curvature is at least :data:`LAB9_MIN_CURVATURE` (ten diameters
  of a 1.2 mm cable) everywhere;
* does the cable wrap it: over the range the tangent point travels along the polyline by at
  least :data:`LAB9_MIN_WRAP` of its length (the wrapped length changes by that much). A cable
  that runs straight from the eyelet to the clamp at every angle, past points it never touches,
  is an eyelet, not a pulley;
* does the spring survive: taut (tension at least its initial tension) and within the allowable
  force of its body and hooks over the whole range.

The link's load is personal (``task_numbers("9.1")``). Expected values are never revealed.

* 9.1 (design, open): a pulley and a spring within the limits;
* 9.2 (compute): the largest tension of the chapter's spring for the student's load;
* 9.3 (derive): the signed arm of the cable's line, eq. (ch9-arm), as a formula.
"""
from __future__ import annotations

import math
from typing import Any, Mapping

import numpy as np

from ...core.elements import G
from ...methods.practice.springs import ExtensionSpring
from ...methods.realize.profile_check import polyline_path, polyline_wrap
from .answers import as_mapping, numeric, personal_option, quantity, symbolic
from .variant import read_expression
from .core import AnswerError, register_task

__all__ = ["LAB9_LINK", "LAB9_EYELET", "LAB9_RANGE", "LAB9_MAX_RADIUS", "LAB9_MIN_CURVATURE", "LAB9_TOLERANCE",
           "LAB9_MIN_WRAP", "LAB9_SPRING", "LAB9_MIN_TENSION", "lab9_spring", "pulley_problems", "pulley_energy_variation"]

#: The published link: ``mass`` (kg) at ``length`` (m) from the pivot (chapter 9's link).
LAB9_LINK = dict(mass=2.0, length=0.5)
#: The eyelet, world frame (m): 0.3 m straight above the pivot.
LAB9_EYELET = (0.0, 0.3)
#: The working range of the link's angle from the x-axis (rad): -60 to +60 degrees.
LAB9_RANGE = (-math.pi / 3, math.pi / 3)
#: Every point of the pulley within this distance of the axle (m).
LAB9_MAX_RADIUS = 0.15
#: Smallest radius of curvature a 1.2 mm cable accepts (m): ten cable diameters.
LAB9_MIN_CURVATURE = 0.012
#: Smallest travel of the cable's tangent point along the submitted curve over the range, as a
#: fraction of the curve's length: the wrapped length must change by at least this much.
LAB9_MIN_WRAP = 0.5
#: Largest relative energy variation accepted (of the energy the load exchanges over the range).
LAB9_TOLERANCE = 1e-3
#: Task 9.2's spring, chapter 9's stock spring: wire, coil (m), active coils, initial tension (N).
LAB9_SPRING = dict(d=3e-3, D=24e-3, Na=60, F_i=40.0)
#: Task 9.2's smallest tension (N).
LAB9_MIN_TENSION = 45.0
#: link angles at which a submitted pulley is judged
_ANGLES = 721
_SPRING_FORM = "{'d': m, 'D': m, 'Na': coils, 'F_i': N}"


def _link_numbers(rng) -> dict:
    """The link's load: ``mass`` (kg) at ``length`` (m), published or a student's (from ``rng``)."""
    if rng is None:
        return dict(LAB9_LINK)
    return dict(mass=round(float(rng.uniform(1.9, 2.5)), 2), length=round(float(rng.uniform(0.46, 0.6)), 3))


def _tension_numbers(rng) -> dict:
    """Task 9.2's load, spread wider than 9.1's (no pulley has to fit it): a classmate's answer is
    within 9.2's tolerance for under 1 % of pairs (tests/test_check.py)."""
    if rng is None:
        return dict(LAB9_LINK)
    return dict(mass=round(float(rng.uniform(0.3, 3.0)), 2), length=round(float(rng.uniform(0.2, 0.6)), 3))


def lab9_spring(spring: Mapping[str, float]) -> ExtensionSpring:
    """The submitted spring ``{'d': m, 'D': m, 'Na': coils, 'F_i': N}`` as an :class:`ExtensionSpring`.

    Parameters
    ----------
    spring : dict
        Wire diameter ``d``, mean coil diameter ``D``, active coils ``Na``, initial tension ``F_i``.

    Returns
    -------
    ExtensionSpring

    Raises
    ------
    AnswerError
        With a message for the student when the spring cannot be made.

    Examples
    --------
    >>> round(lab9_spring({"d": 2e-3, "D": "16 mm", "Na": 30, "F_i": 10.0}).k, 1)
    1329.8
    """
    data = as_mapping(spring, ("d", "D", "Na", "F_i"), "your spring")
    d, D = (quantity(data[key], "length", f"{key} of your spring") for key in ("d", "D"))
    na = quantity(data["Na"], "ratio", "Na of your spring")
    f_i = quantity(data["F_i"], "force", "F_i of your spring")
    try:
        return ExtensionSpring(d, D, na, f_i)
    except (ValueError, TypeError) as err:
        raise AnswerError(f"Your spring cannot be made: {err}.",
                          "d and D in metres (D > d), Na coils > 0, F_i in newtons >= 0.") from None


def _points(value) -> np.ndarray:
    try:
        pts = np.array(value, dtype=float)
    except (TypeError, ValueError):
        raise AnswerError("The points must be a list of (x, y) pairs in metres.",
                          "Use part.pitch of bl.realize.profile_part(design).") from None
    if pts.ndim != 2 or pts.shape[1] != 2 or not 50 <= len(pts) <= 500 or not np.all(np.isfinite(pts)):
        raise AnswerError("The points must be 50 to 500 finite (x, y) pairs in metres.",
                          "Use part.pitch of bl.realize.profile_part(design).")
    if np.hypot(*np.diff(pts, axis=0).T).min() <= 0:
        raise AnswerError("Two consecutive points coincide.", "Give each point of the pitch curve once.")
    return pts


def _read(answer):
    a = as_mapping(answer, ("spring", "points", "cable_length", "turn"), "your pulley")
    turn = a["turn"]
    if isinstance(turn, bool) or turn not in (1, -1):
        raise AnswerError("turn must be 1 (the cable turns counter-clockwise onto the pulley) or -1.",
                          "Use design.springs[0].cable.turn.")
    return lab9_spring(a["spring"]), _points(a["points"]), quantity(a["cable_length"], "length", "cable_length"), \
        int(turn)


def _curvature_radii(pts: np.ndarray) -> np.ndarray:
    """Signed radius of the circle through each three points about 1 mm of arc apart (m)."""
    step = max(1, int(round(1e-3 / float(np.median(np.hypot(*np.diff(pts, axis=0).T))))))
    a, b, c = pts[:-2 * step], pts[step:-step], pts[2 * step:]
    if not len(a):
        raise AnswerError("The pulley is shorter than 2 mm.", "Export the whole pitch curve.")
    ab, bc, ca = (np.hypot(*(q - p).T) for p, q in ((a, b), (b, c), (c, a)))
    twice_area = (b[:, 0] - a[:, 0]) * (c[:, 1] - a[:, 1]) - (b[:, 1] - a[:, 1]) * (c[:, 0] - a[:, 0])
    with np.errstate(divide="ignore"):
        return ab * bc * ca / (2 * twice_area)


def _wrap_problems(pts: np.ndarray, turn: int) -> list[str]:
    """Why the cable does not wrap the curve over the range (empty when it does, :data:`LAB9_MIN_WRAP`)."""
    _, wrapped = polyline_wrap(pts, np.linspace(*LAB9_RANGE, _ANGLES), LAB9_EYELET, pts[-1], turn)
    length = float(np.hypot(*np.diff(pts, axis=0).T).sum())
    travel = float(np.ptp(wrapped))
    if travel >= LAB9_MIN_WRAP * length:
        return []
    return [f"the cable does not wrap it: over ±60° its tangent point travels {1000 * travel:.1f} mm along the "
            f"{1000 * length:.1f} mm curve, less than the {100 * LAB9_MIN_WRAP:.0f} % required (a cable that runs "
            f"straight from the eyelet to the clamp is an eyelet, not a pulley)"]


def pulley_energy_variation(answer: Mapping[str, Any], load: Mapping[str, float]) -> tuple[float, np.ndarray]:
    """Relative energy variation of the link with the submitted pulley, and the cable's tensions (N).

    Parameters
    ----------
    answer : dict
        ``{'spring': {...}, 'points': [(x, y), ...], 'cable_length': m, 'turn': 1 or -1}``.
    load : dict
        ``mass`` (kg) at ``length`` (m) from the pivot.

    Returns
    -------
    (float, numpy.ndarray)
        ``ptp(E) / ptp(V)`` over :data:`LAB9_RANGE`, and the tension at each judged angle.
    """
    spring, pts, cable_length, turn = _read(answer)
    theta = np.linspace(*LAB9_RANGE, _ANGLES)
    path = polyline_path(pts, theta, LAB9_EYELET, pts[-1], turn)
    stretch = path - cable_length - spring.equivalent_free_length
    v_load = load["mass"] * G * load["length"] * np.sin(theta)
    energy = v_load + 0.5 * spring.k * stretch ** 2
    return float(np.ptp(energy) / np.ptp(v_load)), spring.k * stretch


def pulley_problems(answer: Mapping[str, Any]) -> list[str]:
    """What keeps the submitted pulley from being made or wound (empty when nothing does).

    Parameters
    ----------
    answer : dict
        As in :func:`pulley_energy_variation`.

    Returns
    -------
    list of str
    """
    spring, pts, _, turn = _read(answer)
    problems = []
    far = float(np.hypot(*pts.T).max())
    if far > LAB9_MAX_RADIUS * (1 + 1e-9):
        problems.append(f"a point lies {1000 * far:.1f} mm from the axle (at most {1000 * LAB9_MAX_RADIUS:.0f} mm)")
    radii = _curvature_radii(pts)
    if not (np.all(radii > 0) or np.all(radii < 0)):
        problems.append("the curve is not convex (it turns both ways): a cable cannot wrap a concave arc")
    else:
        if np.abs(radii).min() < LAB9_MIN_CURVATURE:
            problems.append(f"its smallest radius of curvature is {1000 * np.abs(radii).min():.1f} mm "
                            f"(the cable needs {1000 * LAB9_MIN_CURVATURE:.0f} mm)")
        if np.sign(radii[0]) != turn:
            problems.append(f"followed to the clamped end (the last point) the curve turns the other way than the "
                            f"cable (turn = {turn}): the cable would cut across its hollow side")
        else:
            problems.extend(_wrap_problems(pts, turn))
    lo, hi = spring.initial_tension_range()
    if not lo * (1 - 1e-6) <= spring.initial_tension <= hi * (1 + 1e-6):
        problems.append("the spring's initial tension is outside what can be wound for its index")
    return problems


@register_task("9.1", "a non-circular pulley and a spring that balance your link within the limits (open design)",
               "my_pulley", "design", "a dict {'spring': " + _SPRING_FORM + ", 'points': the pitch curve in the "
               "link's frame (m, 50 to 500 points, the cable's clamped end last), 'cable_length': m, "
               "'turn': 1 or -1}; every point within 150 mm of the axle, convex and turning the cable's way towards "
               "the clamped end, radius of curvature >= 12 mm, wrapped by the cable (over ±60° the tangent point "
               "travels along at least half of the curve), "
               "the spring taut and within its allowable force; the energy constant to 0.1 % with your link "
               "(task_numbers('9.1'))", points=2, numbers=_link_numbers,
               distinct=(lambda load: load["mass"] * load["length"], 0.03))
def _t91(answer, load):
    problems = pulley_problems(answer)
    if problems:
        hint = "Move the smallest tension, the spring or the eyelet side and build it again."
        if any("cable" in p for p in problems):
            hint = ("Submit the pitch curve of bl.realize.profile_part(design) for a design of "
                    "bl.realize.noncircular_pulley, the clamped end last, with the design's turn.")
        return False, "The pulley cannot be built: " + "; ".join(problems) + ".", hint
    spring = lab9_spring(answer["spring"])
    variation, tension = pulley_energy_variation(answer, load)
    if not math.isfinite(variation) or variation > LAB9_TOLERANCE:
        return (False, "Wound on your points, the cable does not balance your link: the energy is not constant.",
                "Use your own link (task_numbers('9.1')), the eyelet at (0, 0.3) m, the range ±60°, the design's "
                "cable_length and turn, the clamped end last, and enough points (up to 500).")
    if tension.min() < spring.initial_tension * (1 - 1e-9):
        return False, "The spring goes slack (its tension falls below its initial tension).", \
            "Raise the smallest tension."
    if tension.max() > spring.max_force():
        return False, "The spring is overstressed at its longest stretch.", "A stronger spring, or a lower tension."
    return True, ("Balanced, within 150 mm of the axle, wrapped by the cable, and the spring stays taut and within "
                  "its allowable force."), ""


def _largest_tension(load) -> float:
    """Task 9.2's expected value: eq. (ch9-tension) at the largest load energy over the range."""
    s = lab9_spring(LAB9_SPRING)
    swing = load["mass"] * G * load["length"] * (math.sin(LAB9_RANGE[1]) - math.sin(LAB9_RANGE[0]))
    return math.sqrt(LAB9_MIN_TENSION ** 2 + 2 * s.k * swing)


@register_task("9.2", "largest tension (N) of the chapter's spring on a pulley for your link", "largest_tension",
               "numeric", "a number in N (or a string like '0.2 kN'); accepted within 0.2 %; your link "
               "(task_numbers('9.2'))", numbers=_tension_numbers,
               distinct=(lambda load: load["mass"] * load["length"], 0.03))
def _t92(answer, load):
    return numeric(answer, _largest_tension(load), "force", rtol=2e-3)


def _arm_expression(alpha: str = "0"):
    """Task 9.3's expected arm ``h(theta)``, derived here with sympy from the energy balance, for ``theta``
    measured from a line at ``alpha`` (SymPy text, rad) above the horizontal."""
    import sympy as sp

    m, g, r, k, C, theta, u = sp.symbols("m g r k C theta u", positive=True)
    V = m * g * r * sp.sin(theta + sp.sympify(alpha))
    stretch = [s for s in sp.solve(sp.Eq(k * u ** 2 / 2 + V, C), u) if s.could_extract_minus_sign() is False][0]
    return -sp.diff(V, theta) / (k * stretch)


def _angle_numbers(rng) -> dict:
    """Task 9.3's variant: ``theta`` measured from a line at ``alpha`` (SymPy text, rad) above the horizontal;
    ``"0"`` (from the horizontal, the book's eq. ch9-arm) for the published problem."""
    return dict(alpha=personal_option(rng, "0", ("pi/12", "pi/6", "pi/4", "-pi/12", "-pi/6", "-pi/4")))


@register_task("9.3", "the signed arm h(theta) of the cable's line for the lecture's link (derive)", "arm_formula",
               "symbolic", "a sympy expression (or string) in m, g, r, k, C and theta: the distance from the pivot "
               "to the cable's line, with the sign of eq. (ch9-arm), for your theta (task_numbers('9.3'): measured "
               "from a line at alpha above the horizontal); any equivalent form", numbers=_angle_numbers)
def _t93(answer, angle):
    import warnings

    import sympy as sp

    expected = _arm_expression(angle["alpha"])
    names = "m g r k C theta"
    hint = ("Write the link's energy V with your theta, solve k u^2/2 + V = C for the stretch u; the tension "
            "is k u, and eq. (ch9-arm) gives h = -V'/T.")
    with warnings.catch_warnings(), np.errstate(all="ignore"):
        warnings.simplefilter("ignore", RuntimeWarning)
        ok, message, _ = symbolic(answer, expected, names, "your h(theta)", signed="theta")
        if ok:
            return True, message, ""
        # the spot check meets square roots of negative numbers where C < m g r sin(theta): compare
        # h^2 (no root), then the sign where the root is real
        mine = read_expression(answer, names, "your h(theta)")  # read without running code, like symbolic
        ok2, _, _ = symbolic(mine ** 2, expected ** 2, names, "your h(theta)", signed="theta")
    if ok2:
        for theta in (-1.0, -0.3, 0.4, 1.2):
            at = dict(m=1.3, g=9.81, r=0.5, k=900.0, C=40.0, theta=theta)
            signs = [sp.sign(sp.N(e.subs({x: at[str(x)] for x in e.free_symbols}))) for e in (mine, expected)]
            if signs[0] != signs[1]:
                return False, "Your h(theta) has the wrong sign somewhere.", hint
        return True, "Your h(theta) is equivalent to the expected one.", ""
    return False, message, hint
