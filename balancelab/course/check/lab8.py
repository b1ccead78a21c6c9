"""Lab 8, from ideal to real: real springs for the lamp arm, a tolerance study, a rate error.

The tasks are registered with :func:`~.core.register_task`, so the notebook's ``check`` and
the trusted grader run the same judges on the same plain data (springs as dicts of numbers).
Every verdict is computed by physics from the submitted spring data: the real springs are
built with :mod:`balancelab.methods.practice`, put into the lab's arm, and the residual
generalized force (and, for task 8.2, a Monte Carlo of built arms) is evaluated. Expected
values are never revealed.

* 8.1 (design, open): real extension springs, over pulleys, within :data:`LAB8_BUDGET`;
* 8.2 (compute): the 95 % quantile of a tolerance study of *those* springs with the student's
  tolerances (``task_numbers("8.2")``), under :data:`LAB8_QUANTILE_LIMIT`;
* 8.3 (derive): the shoulder's residual torque when spring 1 is 2 % stiffer than ideal.
"""
from __future__ import annotations

import math

import numpy as np

from ...core.design import Design
from ...core.elements import Pulley, Spring
from ...methods.lecture import serial_2r_base_springs
from ...methods.practice.forces import generalized_force
from ...methods.practice.selection import spring_strokes
from ...methods.practice.springs import ExtensionSpring
from ...methods.practice.tolerance import Tolerances, monte_carlo
from .answers import as_mapping, numeric, quantity, symbolic, personal_option
from .core import AnswerError, register_task

__all__ = ["LAB8_ARM", "LAB8_BUDGET", "LAB8_TOLERANCES", "LAB8_QUANTILE_LIMIT", "LAB8_RATE_ERROR", "lab8_arm",
           "real_springs", "built_arm", "spring_problems", "rate_error_arm"]

#: The lamp arm of lab 8 (lecture 35's desk lamp with both springs at the base).
LAB8_ARM = dict(masses=(1.0, 1.0), length=0.5, coms=((0.25, 0.0), (0.25, 0.0)), b=(0.3, 0.25), c=(0.15, 0.1))
#: Largest acceptable residual generalized force of the built arm (N m).
LAB8_BUDGET = 0.1
#: Tolerances of the tolerance study (standard deviations: rate 2 %, positions 0.5 mm, masses 1 %).
LAB8_TOLERANCES = Tolerances(k=0.02, attachment=0.0005, mass=0.01)
#: 95 % of built arms must stay within this residual (N m).
LAB8_QUANTILE_LIMIT = 0.5
#: Task 8.3: spring 1 is this much (relative) stiffer than its ideal rate.
LAB8_RATE_ERROR = 0.02

_SPRING_KEYS = ("d", "D", "Na", "F_i")
_SPRING_FORM = "{'k1': {'d': m, 'D': m, 'Na': coils, 'F_i': N}, 'k2': {...}}"


def lab8_arm() -> Design:
    """The ideal lamp arm of lab 8 (two ZFL springs ``k1``, ``k2`` at the base).

    Returns
    -------
    Design

    Examples
    --------
    >>> [round(s.k, 1) for s in lab8_arm().springs]
    [163.5, 98.1]
    """
    return serial_2r_base_springs(**LAB8_ARM)


def real_springs(springs) -> dict:
    """``{"k1": {"d": m, "D": m, "Na": coils, "F_i": N}, ...}`` as :class:`ExtensionSpring` objects.

    Lengths and forces may carry units (``"1.8 mm"``, ``(3, "N")``).

    Parameters
    ----------
    springs : dict
        The two springs ``"k1"`` and ``"k2"``, each with ``d`` (wire diameter), ``D`` (mean
        coil diameter), ``Na`` (active coils) and ``F_i`` (initial tension).

    Returns
    -------
    dict of ExtensionSpring

    Raises
    ------
    AnswerError
        With a message for the student when the data are not two springs of that form.

    Examples
    --------
    >>> real_springs({"k1": {"d": 2e-3, "D": 20e-3, "Na": 20, "F_i": 3.0},
    ...               "k2": {"d": "1 mm", "D": 10e-3, "Na": 30, "F_i": 1.5}})["k2"].active_coils
    30.0
    """
    as_mapping(springs, ("k1", "k2"), "your springs")
    out = {}
    for name in ("k1", "k2"):
        data = as_mapping(springs[name], _SPRING_KEYS, f"spring {name}")
        d, D = (quantity(data[key], "length", f"{key} of {name}") for key in ("d", "D"))
        na = quantity(data["Na"], "ratio", f"Na of {name}")
        f_i = quantity(data["F_i"], "force", f"F_i of {name}")
        try:
            out[name] = ExtensionSpring(d, D, na, f_i)
        except (ValueError, TypeError) as err:
            raise AnswerError(f"Spring {name} cannot be made: {err}.",
                              "d and D in metres (D > d), Na coils > 0, F_i in newtons >= 0.") from None
    return out


def built_arm(springs) -> Design:
    """The lab's arm with the submitted real springs, each pulling a string over an ideal pulley.

    Parameters
    ----------
    springs : dict
        As in :func:`real_springs`.

    Returns
    -------
    Design

    Examples
    --------
    >>> arm = built_arm({"k1": {"d": 2e-3, "D": 20e-3, "Na": 20, "F_i": 4.0},
    ...                  "k2": {"d": 1e-3, "D": 10e-3, "Na": 30, "F_i": 2.5}})
    >>> [round(s.k, 1) for s in arm.springs]
    [1021.3, 340.4]
    """
    real = real_springs(springs)
    ideal = lab8_arm()
    new = [Spring(real[s.name].k, 0.0, s.a, s.b, name=s.name, realization=Pulley()) for s in ideal.springs]
    return ideal.replace(springs=new, name="lab 8 lamp arm with real springs")


_WHERE = {"body": "first in the body", "hook_torsion": "first at the hooks' roots, in torsion",
          "hook_bending": "first at the hooks' bends, in bending"}


def spring_problems(springs) -> list[str]:
    """Why each submitted spring cannot do its job over a pulley (empty when all can).

    Parameters
    ----------
    springs : dict
        As in :func:`real_springs`.

    Returns
    -------
    list of str

    Examples
    --------
    >>> spring_problems({"k1": {"d": 2e-3, "D": 20e-3, "Na": 20, "F_i": 4.0},
    ...                  "k2": {"d": 1e-3, "D": 10e-3, "Na": 30, "F_i": 2.5}})[-1]
    "k2: the wire is overstressed at the longest stroke (first at the hooks' roots, in torsion)"
    """
    real = real_springs(springs)
    strokes = dict(zip(("k1", "k2"), spring_strokes(lab8_arm(), 41)))
    problems = []
    for name, s in real.items():
        lo, hi = s.initial_tension_range()
        shortest, longest = strokes[name]
        if not lo * (1 - 1e-6) <= s.initial_tension <= hi * (1 + 1e-6):
            problems.append(f"{name}: its initial tension is outside what can be wound for index {s.index:.2f}")
        if shortest < s.initial_tension / s.k:
            problems.append(f"{name}: the string goes slack near the shortest stroke (needs x >= F_i / k)")
        if s.k * longest > s.max_force():
            problems.append(f"{name}: the wire is overstressed at the longest stroke ({_WHERE[s.governing()]})")
    return problems


def rate_error_arm(k1_error: float = 0.0, k2_error: float = 0.0) -> Design:
    """The lab's arm with ideal ZFL springs whose rates are off by the given fractions.

    Parameters
    ----------
    k1_error, k2_error : float
        Relative rate errors of springs 1 and 2 (``0.02``: 2 % stiffer), > -1.

    Returns
    -------
    Design

    Examples
    --------
    >>> rate_error_arm().balance_report().balanced, rate_error_arm(0.01).balance_report().balanced
    (True, False)
    """
    errors = {"k1": float(k1_error), "k2": float(k2_error)}
    for name, e in errors.items():
        if not math.isfinite(e) or e <= -1:
            raise ValueError(f"{name}_error must be a finite number > -1, got {e!r}")
    ideal = lab8_arm()
    new = [Spring(s.k * (1 + errors[s.name]), s.free_length, s.a, s.b, name=s.name) for s in ideal.springs]
    return ideal.replace(springs=new, name="lab 8 lamp arm with rate errors")


@register_task("8.1", "real springs (over pulleys) that keep the lamp arm within 0.1 N m (open design)",
               "my_springs", "design", f"a dict {_SPRING_FORM} (SI units); each spring's initial tension in "
               "the range its index allows, taut and within the allowable stresses of its body and its standard hooks "
               "over its stroke; the built "
               "arm's residual generalized force at most 0.1 N m", points=2)
def _t81(answer):
    problems = spring_problems(answer)
    if problems:
        return False, "; ".join(problems) + ".", "Check the stroke and the stress of each spring."
    _, Q = generalized_force(built_arm(answer), None, 41)
    worst = float(np.abs(Q).max())
    if not math.isfinite(worst) or worst > LAB8_BUDGET:
        return (False, f"The built arm's largest residual is {worst:.3g} N m, over the {LAB8_BUDGET:g} N m budget.",
                "Bring each spring's rate closer to the ideal one.")
    return True, (f"Largest residual {worst:.3g} N m, within {LAB8_BUDGET:g} N m; every spring stays taut and "
                  "within the allowable stresses of its body and hooks."), ""


def _tolerance_numbers(rng) -> dict:
    """Task 8.2's tolerances (standard deviations): rate ``k`` and ``mass`` (fractions), ``attachment`` (m);
    :data:`LAB8_TOLERANCES`, or with a student's rate tolerance (from ``rng``): the rate's dominates the
    quantile, so a rate tolerance 25 % from the published one moves the quantile past the 10 % accepted."""
    published = dict(k=LAB8_TOLERANCES.k, attachment=LAB8_TOLERANCES.attachment, mass=LAB8_TOLERANCES.mass)
    if rng is None:
        return published
    return dict(published, k=round(float(rng.uniform(0.01, 0.03)), 4))


@register_task("8.2", "95 % quantile of the worst residual of built arms with your springs", "tolerance_study",
               "design", "a dict {'springs': your springs of task 8.1, 'quantile': N m}: the 95 % quantile of "
               "the worst residual over a Monte Carlo of built arms with your tolerances (task_numbers('8.2'): "
               "standard deviations k and mass as fractions, attachment in m); accepted within 10 % of the "
               "grader's Monte Carlo, and it must be at most 0.5 N m", skill="compute",
               numbers=_tolerance_numbers, distinct=(lambda tol: tol["k"], 0.25))
def _t82(answer, numbers, n: int = 4000):
    a = as_mapping(answer, ("springs", "quantile"), "your study")
    value = quantity(a["quantile"], "torque", "the quantile")
    design = built_arm(a["springs"])
    if value <= 0:
        raise AnswerError("The quantile must be a positive number of N m.", "Use result.quantile(0.95).")
    tolerances = Tolerances(k=numbers["k"], attachment=numbers["attachment"], mass=numbers["mass"])
    reference = monte_carlo(design, tolerances, n, grid=15, seed=0).quantile(0.95)
    if abs(value / reference - 1) > 0.10:
        return (False, "Your quantile is not within 10 % of a Monte Carlo of your springs with your tolerances.",
                "Use your tolerances (task_numbers('8.2')), enough built arms (>= 2000) and a grid over both "
                "angles.")
    if reference > LAB8_QUANTILE_LIMIT:
        return (False, f"Right number, but 95 % of built arms exceed {LAB8_QUANTILE_LIMIT:g} N m.",
                "Which tolerance dominates? Springs with rates closer to ideal do not help against it.")
    return True, f"95 % of built arms stay within {value:.3g} N m, under {LAB8_QUANTILE_LIMIT:g} N m.", ""


def _rate_error_numbers(rng) -> dict:
    """Task 8.3's rate error of spring 1 (a fraction) and angle of link 1 (rad, from the horizontal; link 2
    at ``theta_2 = 0``): the published ones (2 %, horizontal), or a student's (from ``rng``)."""
    if rng is None:
        return dict(rate_error=LAB8_RATE_ERROR, theta_1=0.0)
    return dict(rate_error=round(float(rng.uniform(0.01, 0.05)), 5), theta_1=round(float(rng.uniform(-1.1, 1.1)), 4))


def _shoulder_torque(numbers: dict) -> float:
    q = np.array([[numbers["theta_1"], 0.0]])
    _, Q = generalized_force(rate_error_arm(numbers["rate_error"]), q)
    return float(abs(Q[0, 0]))


@register_task("8.3", "shoulder torque (N m) left by spring 1 being too stiff by your rate error, link 1 at your "
               "angle", "shoulder_torque", "numeric", "a number in N m (its size) for your rate error and angle "
               "(task_numbers('8.3'): theta_1 in rad, theta_2 = 0); accepted within 0.5 %",
               numbers=_rate_error_numbers, distinct=(_shoulder_torque, 0.015))
def _t83(answer, numbers):
    return numeric(answer, _shoulder_torque(numbers), "torque")


#: Task 8.4's hint: the residual is a derivative, not a condition set to zero; theta_1 is link 1's
#: angle from the student's reference line and only the extra rate of spring 1 is unbalanced.
RATE_ERROR_HINT = ("Only the extra rate epsilon k1 is unbalanced: write its spring's energy as a function of "
                   "your theta_1 (link 1's angle from your reference line; the anchor b1 above the shoulder, the end c1 "
                   "along link 1), differentiate it (dV/dtheta_1 itself, not minus it), then remove b1 and c1 "
                   "with the ideal rate's balance condition for link 1.")


def _angle_numbers(rng) -> dict:
    """Task 8.4's variant: the student's ``theta_1`` is measured from a line at ``alpha`` (SymPy text, rad)
    above the horizontal; ``"0"`` (from the horizontal, the book's) for the published problem."""
    return dict(alpha=personal_option(rng, "0", ("pi/12", "pi/6", "pi/4", "pi/3", "pi/2", "-pi/6", "-pi/4")))


@register_task("8.4", "formula for the shoulder torque dV/dtheta_1 left by a rate error eps of spring 1",
               "torque_formula", "symbolic",
               "a sympy expression in epsilon, g, m_1, p_1, m_2, l_1, theta_1: the derivative of the arm's "
               "potential energy with respect to your theta_1 (task_numbers('8.4'): measured from a line at alpha "
               "above the horizontal), sign included (any equivalent form accepted); "
               "derived by hand: a cell that calls the library's solvers is refused", numbers=_angle_numbers)
def _t84(answer, angle):
    import sympy as sp

    eps, g, m1, p1, m2, l1 = sp.symbols("epsilon g m_1 p_1 m_2 l_1", positive=True)
    th = sp.Symbol("theta_1", real=True)
    expected = -eps * g * (m1 * p1 + m2 * l1) * sp.cos(th + sp.sympify(angle["alpha"]))
    return symbolic(answer, expected, "epsilon g m_1 p_1 m_2 l_1 theta_1", "your dV/dtheta_1", signed="theta_1",
                    hint=RATE_ERROR_HINT)
