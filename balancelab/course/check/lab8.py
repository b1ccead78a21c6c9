"""Lab 8, from ideal to real: real springs for the lamp arm, and a tolerance study.

Self-contained formative checks: pure functions on plain data (dicts of numbers) that
return a :class:`Lab8Result` and never raise. They are not registered with the task
registry of :mod:`.core` (the grading pipeline decides how lab 8 is graded); a notebook
calls them directly. Every verdict is computed by physics from the submitted spring data:
the real springs are built with :mod:`balancelab.methods.practice`, put into the lab's
arm, and the residual torque (and, for task 8.2, a Monte Carlo of built arms) is
evaluated. Expected values are never revealed.
"""
from __future__ import annotations

import math
from typing import NamedTuple

import numpy as np

from ...core.design import Design
from ...core.elements import Pulley, Spring
from ...methods.lecture import serial_2r_base_springs
from ...methods.practice.forces import generalized_force
from ...methods.practice.selection import spring_strokes
from ...methods.practice.springs import ExtensionSpring
from ...methods.practice.tolerance import Tolerances, monte_carlo

__all__ = ["LAB8_ARM", "LAB8_BUDGET", "LAB8_TOLERANCES", "LAB8_QUANTILE_LIMIT", "Lab8Result", "lab8_arm",
           "real_springs", "built_arm", "check_spring_choice", "check_tolerance_study"]

#: The lamp arm of lab 8 (lecture 35's desk lamp with both springs at the base).
LAB8_ARM = dict(masses=(1.0, 1.0), length=0.5, coms=((0.25, 0.0), (0.25, 0.0)), b=(0.3, 0.25), c=(0.15, 0.1))
#: Largest acceptable residual generalized force of the built arm (N m).
LAB8_BUDGET = 0.1
#: Tolerances of the tolerance study (standard deviations: rate 2 %, positions 0.5 mm, masses 1 %).
LAB8_TOLERANCES = Tolerances(k=0.02, attachment=0.0005, mass=0.01)
#: 95 % of built arms must stay within this residual (N m).
LAB8_QUANTILE_LIMIT = 0.5


class Lab8Result(NamedTuple):
    """Outcome of a lab-8 check: ``task``, ``correct``, ``message`` and a ``hint`` when not correct."""

    task: str
    correct: bool
    message: str
    hint: str = ""

    def __str__(self) -> str:
        head = "✔ correct" if self.correct else "✘ not yet"
        return f"Task {self.task}: {head}. {self.message}" + (f"\n  Hint: {self.hint}" if self.hint and not self.correct
                                                               else "")


def lab8_arm() -> Design:
    """The ideal lamp arm of lab 8 (two ZFL springs ``k1``, ``k2`` at the base).

    Examples
    --------
    >>> [round(s.k, 1) for s in lab8_arm().springs]
    [163.5, 98.1]
    """
    return serial_2r_base_springs(**LAB8_ARM)


def real_springs(springs) -> dict:
    """``{"k1": {"d": m, "D": m, "Na": coils, "F_i": N}, ...}`` as :class:`ExtensionSpring` objects.

    Raises
    ------
    ValueError, TypeError
        With a message for the student when the data are not two springs of that form.

    Examples
    --------
    >>> real_springs({"k1": {"d": 1.8e-3, "D": 25.2e-3, "Na": 41, "F_i": 3.0},
    ...               "k2": {"d": 1e-3, "D": 10e-3, "Na": 105, "F_i": 1.5}})["k2"].active_coils
    105.0
    """
    if not isinstance(springs, dict) or set(springs) != {"k1", "k2"}:
        raise TypeError("give a dict with the two springs 'k1' and 'k2'")
    out = {}
    for name, data in springs.items():
        if not isinstance(data, dict) or set(data) != {"d", "D", "Na", "F_i"}:
            raise TypeError(f"spring {name} must be a dict with 'd' (m), 'D' (m), 'Na' and 'F_i' (N)")
        out[name] = ExtensionSpring(float(data["d"]), float(data["D"]), float(data["Na"]), float(data["F_i"]))
    return out


def built_arm(springs) -> Design:
    """The lab's arm with the submitted real springs, each pulling a string over an ideal pulley.

    Examples
    --------
    >>> arm = built_arm({"k1": {"d": 1.8e-3, "D": 25.2e-3, "Na": 41, "F_i": 4.0},
    ...                  "k2": {"d": 1e-3, "D": 10e-3, "Na": 105, "F_i": 2.5}})
    >>> [round(s.k, 1) for s in arm.springs]
    [163.4, 97.3]
    """
    real = real_springs(springs)
    ideal = lab8_arm()
    new = [Spring(real[s.name].k, 0.0, s.a, s.b, name=s.name, realization=Pulley()) for s in ideal.springs]
    return ideal.replace(springs=new, name="lab 8 lamp arm with real springs")


def _spring_problems(springs) -> list[str]:
    """Why each submitted spring cannot do its job (empty when all can)."""
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
            problems.append(f"{name}: the wire is overstressed at the longest stroke")
    return problems


def check_spring_choice(springs, budget: float = LAB8_BUDGET) -> Lab8Result:
    """Task 8.1: real springs (over pulleys) that keep the lamp arm within the torque budget.

    Examples
    --------
    >>> ok = {"k1": {"d": 1.8e-3, "D": 25.2e-3, "Na": 41, "F_i": 4.0},
    ...       "k2": {"d": 1e-3, "D": 10e-3, "Na": 105, "F_i": 2.5}}
    >>> check_spring_choice(ok).correct
    True
    """
    try:
        problems = _spring_problems(springs)
        q, Q = generalized_force(built_arm(springs), None, 41)
    except (TypeError, ValueError, KeyError) as err:
        return Lab8Result("8.1", False, f"These spring data cannot be read: {err}.",
                          "Each spring needs d and D in metres, Na coils and F_i in newtons.")
    if problems:
        return Lab8Result("8.1", False, "; ".join(problems) + ".", "Check the stroke and the stress of each spring.")
    worst = float(np.abs(Q).max())
    if not math.isfinite(worst) or worst > budget:
        return Lab8Result("8.1", False, f"The built arm's largest residual is {worst:.3g} N m, over the "
                          f"{budget:g} N m budget.", "Bring each spring's rate closer to the ideal one.")
    return Lab8Result("8.1", True, f"Largest residual {worst:.3g} N m, within {budget:g} N m; every spring "
                      "stays taut and within its allowable stress.")


def check_tolerance_study(springs, quantile: float, n: int = 4000) -> Lab8Result:
    """Task 8.2: the 95 % quantile of the worst residual of built arms, and whether it meets the limit.

    The student's number (N m) is accepted within 10 % of a Monte Carlo with
    :data:`LAB8_TOLERANCES` (``n`` built arms, 15 configurations per angle), and the
    quantile must be at most :data:`LAB8_QUANTILE_LIMIT`.

    Examples
    --------
    >>> ok = {"k1": {"d": 1.8e-3, "D": 25.2e-3, "Na": 41, "F_i": 4.0},
    ...       "k2": {"d": 1e-3, "D": 10e-3, "Na": 105, "F_i": 2.5}}
    >>> check_tolerance_study(ok, 0.01).correct
    False
    """
    try:
        value = float(quantile)
        design = built_arm(springs)
    except (TypeError, ValueError) as err:
        return Lab8Result("8.2", False, f"Cannot read the answer: {err}.", "Give the quantile as a number in N m.")
    if not math.isfinite(value) or value <= 0:
        return Lab8Result("8.2", False, "The quantile must be a positive number of N m.", "Use result.quantile(0.95).")
    reference = monte_carlo(design, LAB8_TOLERANCES, n, grid=15, seed=0).quantile(0.95)
    if abs(value / reference - 1) > 0.10:
        return Lab8Result("8.2", False, "Your quantile is not within 10 % of a Monte Carlo of your springs.",
                          "Use the lab's tolerances, enough built arms (>= 2000) and a grid over both angles.")
    if reference > LAB8_QUANTILE_LIMIT:
        return Lab8Result("8.2", False, f"Right number, but 95 % of built arms exceed {LAB8_QUANTILE_LIMIT:g} N m.",
                          "Which tolerance dominates? Springs with rates closer to ideal do not help against it.")
    return Lab8Result("8.2", True, f"95 % of built arms stay within {value:.3g} N m, under "
                      f"{LAB8_QUANTILE_LIMIT:g} N m.")
