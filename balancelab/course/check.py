"""Answer checks for the labs: ``check("2.1", k)`` tells a student whether an answer is right.

Every task of every lab is registered here with the name of the variable that holds its
answer in the notebook (:func:`tasks`), so the grader (:mod:`balancelab.course.grading`) can
check a whole notebook at once. Three kinds of checks:

* **numeric**: a number in the stated SI unit, or a string or ``(value, "unit")`` pair
  with a unit (``"12 cm"``, ``(0.12, "m")``), within a stated relative tolerance;
* **symbolic**: a sympy expression (or a string sympy can parse) accepted when it is
  *equivalent* to the expected one: the difference simplifies to zero (with a numeric
  spot check at random positive values as a fallback);
* **design**: the student's design is built and its
  :meth:`~balancelab.Design.balance_report` is run; the check passes when the energy is
  constant (within the stated tolerance) and the task's constraints hold, so many
  designs are right.

A check never reveals the expected value and never raises: wrong types, NaN, a missing
unit or a wrong shape give a friendly :class:`Verdict` instead of a traceback.
"""
from __future__ import annotations

import math
import re
from dataclasses import dataclass, field
from numbers import Real
from typing import Any, Callable

import numpy as np

from ..core.design import Design, UnreachableConfiguration
from ..core.elements import G, Joint, Load, Spring, gravity_load
from ..mechanisms.fourbar import FourBarKinematics
from ..mechanisms.lever import lever_kinematics

__all__ = ["Verdict", "Task", "check", "tasks", "lab_tasks", "explain", "AnswerError",
           "lab1_fourbar", "lab2_lever", "lab3_torque_error", "lab5_technique2", "lab6_scissors", "quantity", "vector",
           "numeric", "numeric_vector", "symbolic", "design_balanced"]

# --------------------------------------------------------------------------- verdicts


@dataclass(frozen=True)
class Verdict:
    """The outcome of one check.

    Attributes
    ----------
    task : str
        Task id, e.g. ``"2.1"``.
    correct : bool
        Whether the answer is accepted.
    message : str
        What was found (never the expected value).
    hint : str
        What to look at next (empty when correct).
    score : float
        Points earned (0 or the task's points).
    points : float
        Points the task is worth.
    """

    task: str
    correct: bool
    message: str
    hint: str = ""
    score: float = 0.0
    points: float = 1.0

    def __bool__(self) -> bool:
        return self.correct

    def __str__(self) -> str:
        head = "✔ correct" if self.correct else "✘ not yet"
        text = f"Task {self.task}: {head}. {self.message}"
        if self.hint and not self.correct:
            text += f"\n  Hint: {self.hint}"
        return text

    __repr__ = __str__


class AnswerError(ValueError):
    """A malformed answer; its message is shown to the student as the verdict."""


@dataclass(frozen=True)
class Task:
    """One task of a lab.

    Attributes
    ----------
    id : str
        ``"<lab>.<n>"``, e.g. ``"1.3"``.
    lab : str
        ``"lab1"`` ... ``"lab6"``.
    title : str
        One line saying what is asked.
    variable : str
        Name of the notebook variable holding the answer (what the grader reads).
    kind : str
        ``"numeric"``, ``"symbolic"`` or ``"design"``.
    expects : str
        What an answer looks like, with units and tolerance.
    points : float
        Points the task is worth.
    """

    id: str
    lab: str
    title: str
    variable: str
    kind: str
    expects: str
    judge: Callable[[Any], tuple[bool, str, str]] = field(repr=False, compare=False)
    points: float = 1.0


_TASKS: dict[str, Task] = {}


def _task(id: str, title: str, variable: str, kind: str, expects: str, points: float = 1.0):
    def register(fn):
        _TASKS[id] = Task(id, "lab" + id.split(".")[0], title, variable, kind, expects, fn, points)
        return fn

    return register


def tasks(lab: str | int | None = None) -> list[Task]:
    """The registered tasks, in order, optionally of one lab.

    Parameters
    ----------
    lab : str or int, optional
        ``"lab2"``, ``"2"`` or ``2``; all labs when omitted.

    Returns
    -------
    list of Task

    Examples
    --------
    >>> [t.id for t in tasks(2)][:2]
    ['2.1', '2.2']
    """
    order = sorted(_TASKS.values(), key=lambda t: tuple(int(x) for x in t.id.split(".")))
    if lab is None:
        return order
    key = str(lab)
    key = key if key.startswith("lab") else "lab" + key
    return [t for t in order if t.lab == key]


lab_tasks = tasks


def explain(task_id: str) -> str:
    """What a task asks and what an answer looks like (units, tolerance).

    Parameters
    ----------
    task_id : str
        E.g. ``"2.1"``.

    Returns
    -------
    str

    Examples
    --------
    >>> print(explain("1.1").splitlines()[0])
    Task 1.1: distance of the counterweight from the pivot
    """
    t = _TASKS.get(str(task_id))
    if t is None:
        raise KeyError(f"no task {task_id!r}; tasks are {', '.join(t.id for t in tasks())}")
    return f"Task {t.id}: {t.title}\n  store your answer in `{t.variable}`: {t.expects}"


def check(task_id: str, answer: Any) -> Verdict:
    """Check a student's answer to one task.

    Parameters
    ----------
    task_id : str
        The task, e.g. ``"2.1"`` (see :func:`tasks`).
    answer : object
        The answer in the form the task states (:func:`explain`).

    Returns
    -------
    Verdict
        Prints as a one-line verdict with a hint; ``bool(verdict)`` is whether it is right.
        Never raises for a malformed answer.

    Examples
    --------
    >>> check("2.1", "12 apples").correct
    False
    >>> print(check("1.1", float("nan")))
    Task 1.1: ✘ not yet. The answer is NaN or infinite; give a finite number.
      Hint: Store a plain number in m or a string such as '2.5 m'.
    """
    t = _TASKS.get(str(task_id))
    if t is None:
        return Verdict(str(task_id), False, f"There is no task {task_id!r}.",
                       f"Tasks are: {', '.join(t.id for t in tasks())}.", 0.0, 0.0)
    try:
        ok, message, hint = t.judge(answer)
    except AnswerError as e:
        ok, message, hint = False, str(e), getattr(e, "hint", "") or t.expects
    except Exception as e:  # a check must never crash the student's notebook
        ok, message, hint = (False, f"Your answer could not be checked ({type(e).__name__}).",
                             t.expects)
    return Verdict(t.id, bool(ok), message, hint, t.points if ok else 0.0, t.points)


# ----------------------------------------------------------------------- parsing helpers

_UNITS = {
    "length": ("m", {"m": 1.0, "cm": 1e-2, "mm": 1e-3, "km": 1e3}),
    "mass": ("kg", {"kg": 1.0, "g": 1e-3}),
    "force": ("N", {"N": 1.0, "kN": 1e3, "mN": 1e-3}),
    "stiffness": ("N/m", {"N/m": 1.0, "kN/m": 1e3, "N/mm": 1e3, "N/cm": 1e2}),
    "energy": ("J", {"J": 1.0, "mJ": 1e-3, "kJ": 1e3, "Nm": 1.0, "N*m": 1.0, "N m": 1.0}),
    "first moment": ("kg m", {"kg m": 1.0, "kg*m": 1.0, "kgm": 1.0, "g mm": 1e-6}),
    "torque": ("N m", {"N m": 1.0, "Nm": 1.0, "N*m": 1.0, "N mm": 1e-3}),
    "angle": ("rad", {"rad": 1.0, "deg": math.pi / 180, "°": math.pi / 180}),
    "ratio": ("", {"": 1.0, "%": 1e-2}),
}


def _err(message: str, hint: str = "") -> AnswerError:
    e = AnswerError(message)
    e.hint = hint
    return e


def _plain_number(x) -> float | None:
    """A finite-or-not float if ``x`` is a plain real number, else None."""
    if isinstance(x, bool):
        return None
    if isinstance(x, (Real, np.integer, np.floating)):
        return float(x)
    if isinstance(x, np.ndarray) and x.shape == () and np.issubdtype(x.dtype, np.number):
        return float(x)
    try:
        import sympy as sp

        if isinstance(x, sp.Basic) and x.is_number and x.is_real is not False:
            return float(x)
    except (TypeError, ValueError):
        return None
    return None


def quantity(answer, dimension: str, what: str = "the answer") -> float:
    """Turn an answer into a float in SI units, or raise :class:`AnswerError`.

    Parameters
    ----------
    answer : float or str or (float, str)
        A plain number in the SI unit of ``dimension``, a string ``"12.5 cm"`` or a pair
        ``(12.5, "cm")``.
    dimension : str
        One of ``length, mass, force, stiffness, energy, first moment, torque, angle,
        ratio``.
    what : str
        How to name the answer in messages.

    Returns
    -------
    float
        The value in SI units.

    Examples
    --------
    >>> quantity("12.5 cm", "length")
    0.125
    >>> quantity((2, "kN/m"), "stiffness")
    2000.0
    """
    si, table = _UNITS[dimension]
    example = f"a plain number in {si} or a string such as '2.5 {si}'" if si else "a plain number"
    hint = f"Store {example}."
    value, unit = None, None
    if isinstance(answer, str):
        m = re.fullmatch(r"\s*([-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?)\s*(.*?)\s*", answer)
        if not m:
            raise _err(f"{what.capitalize()} {answer!r} does not start with a number.", hint)
        value, unit = float(m.group(1)), m.group(2)
        if unit == "" and si:
            raise _err(f"{what.capitalize()} {answer!r} has no unit.",
                       f"Write the unit, e.g. '{answer.strip()} {si}', or store a plain number in {si}.")
    elif isinstance(answer, tuple) and len(answer) == 2 and isinstance(answer[1], str):
        value, unit = _plain_number(answer[0]), answer[1].strip()
        if value is None:
            raise _err(f"The first item of {what} should be a number, got {type(answer[0]).__name__}.",
                       hint)
    else:
        value = _plain_number(answer)
        if value is None:
            kind = type(answer).__name__
            if isinstance(answer, (list, tuple, np.ndarray)):
                raise _err(f"{what.capitalize()} should be one number, got a {kind} of "
                           f"{len(answer)} items.", hint)
            raise _err(f"{what.capitalize()} should be a number, got {kind}"
                       f"{'' if answer is None else ' ' + _short(answer)}.", hint)
        unit = si
    if not math.isfinite(value):
        raise _err("The answer is NaN or infinite; give a finite number." if what == "the answer"
                   else f"{what.capitalize()} is NaN or infinite; give a finite number.", hint)
    if unit not in table:
        known = ", ".join(repr(u) for u in table if u)
        raise _err(f"Unit {unit!r} is not a unit of {dimension} here.", f"Use one of {known}.")
    return value * table[unit]


def _short(x) -> str:
    s = repr(x)
    return s if len(s) <= 40 else s[:37] + "..."


def vector(answer, n: int, dimension: str, what: str = "the answer") -> list[float]:
    """Parse a tuple of ``n`` quantities (see :func:`quantity`), or raise :class:`AnswerError`.

    Parameters
    ----------
    answer : sequence
        ``n`` items, each a number in SI units or a string with a unit.
    n : int
        Number of items expected.
    dimension : str
        Dimension of every item.
    what : str
        How to name the answer in messages.

    Returns
    -------
    list of float

    Examples
    --------
    >>> vector((1, "20 cm"), 2, "length")
    [1.0, 0.2]
    """
    if isinstance(answer, (str, bytes, dict)) or not hasattr(answer, "__len__"):
        raise _err(f"{what.capitalize()} should be a tuple of {n} numbers, got {type(answer).__name__}.",
                   f"Write it like ({', '.join(['...'] * n)}).")
    items = list(np.asarray(answer, dtype=object).ravel()) if isinstance(answer, np.ndarray) else list(answer)
    if len(items) != n:
        raise _err(f"{what.capitalize()} should have {n} items, got {len(items)}.",
                   f"Write it like ({', '.join(['...'] * n)}).")
    return [quantity(v, dimension, f"item {i + 1} of {what}") for i, v in enumerate(items)]


def point(answer, what: str) -> np.ndarray:
    """A planar point ``(x, y)`` in metres (strings with units allowed), or raise :class:`AnswerError`.

    Parameters
    ----------
    answer : sequence of two
        ``x`` and ``y``, each a number in metres or a string with a unit of length.
    what : str
        How to name the answer in messages.

    Returns
    -------
    numpy.ndarray, shape (2,)
        In metres.

    Examples
    --------
    >>> point(("10 cm", 0.2), "the anchor").tolist()
    [0.1, 0.2]
    """
    return np.array(vector(answer, 2, "length", what))


def _compare(value: float, expected: float, rtol: float, unit: str) -> tuple[bool, str, str]:
    """Numeric verdict without revealing ``expected``."""
    tol = f"{rtol * 100:g} %"
    if expected != 0 and abs(value - expected) <= rtol * abs(expected):
        return True, f"Within {tol} of the expected value.", ""
    if expected == 0 and abs(value) <= rtol:
        return True, f"Within {rtol:g} {unit} of the expected value.", ""
    hint = ""
    if expected != 0 and value != 0:
        ratio = value / expected
        for factor, why in ((G, "a factor g = 9.81 too large: did you use a mass where a weight (N) "
                               "is needed, or multiply by g twice?"),
                            (1 / G, "a factor g = 9.81 too small: did you forget g?"),
                            (1e3, "a factor 1000 too large: check mm against m."),
                            (1e-3, "a factor 1000 too small: check mm against m."),
                            (2.0, "about twice too large: look for a stray factor 2."),
                            (0.5, "about half of what it should be: look for a missing factor 2."),
                            (-1.0, "the right size but the wrong sign.")):
            if abs(ratio / factor - 1) < 0.02:
                hint = "Your answer is " + why
                break
        if not hint:
            hint = (f"Your answer is too {'large' if ratio > 1 else 'small'} "
                    f"(outside the {tol} tolerance). Recheck each step and its units.")
    return False, f"Not within {tol} of the expected value.", hint


def numeric(answer, expected: float, dimension: str, rtol: float = 5e-3) -> tuple[bool, str, str]:
    """Numeric check of one quantity (see :func:`quantity`) within relative tolerance ``rtol``.

    Parameters
    ----------
    answer : float or str or (float, str)
        The student's answer, as :func:`quantity` reads it.
    expected : float
        The right value, in the SI unit of ``dimension``; never shown in the messages.
    dimension : str
        As in :func:`quantity` (``"length"``, ``"stiffness"``, ...).
    rtol : float
        Accepted relative error (absolute, in SI units, when ``expected`` is 0).

    Returns
    -------
    (bool, str, str)
        ``(correct, message, hint)``; the hint names a common slip (a factor ``g``,
        1000, 2 or a sign) when the ratio matches one.

    Raises
    ------
    AnswerError
        If the answer cannot be read as a quantity of that dimension.

    Examples
    --------
    >>> numeric("25 cm", 0.25, "length")[0]
    True
    >>> numeric(250.0, 0.25, "length")[2]
    'Your answer is a factor 1000 too large: check mm against m.'
    """
    value = quantity(answer, dimension)
    return _compare(value, expected, rtol, _UNITS[dimension][0])


def numeric_vector(answer, expected, dimension: str, rtol: float = 5e-3,
                   names=None) -> tuple[bool, str, str]:
    """Numeric check of a tuple of quantities, item by item (see :func:`numeric`).

    Parameters
    ----------
    answer : sequence
        The student's items, as :func:`vector` reads them.
    expected : sequence of float
        The right values (SI units).
    dimension : str
        Dimension of every item.
    rtol : float
        Accepted relative error of each item.
    names : sequence of str, optional
        How to name the items in messages (``"item 1"``, ... by default).

    Returns
    -------
    (bool, str, str)
        ``(correct, message, hint)``; the message names the items that are off.

    Examples
    --------
    >>> numeric_vector((0.5, "2 kg"), (0.5, 2.0), "mass", names=("m_B", "m_C"))[0]
    True
    >>> numeric_vector((0.5, 3.0), (0.5, 2.0), "mass", names=("m_B", "m_C"))[1]
    'm_C not within 0.5 %.'
    """
    values = vector(answer, len(expected), dimension)
    names = names or [f"item {i + 1}" for i in range(len(expected))]
    bad = []
    hint = ""
    for name, v, e in zip(names, values, expected):
        ok, _, h = _compare(v, e, rtol, _UNITS[dimension][0])
        if not ok:
            bad.append(name)
            hint = hint or f"{name}: {h}"
    if not bad:
        return True, f"All {len(values)} values within {rtol * 100:g} % of the expected ones.", ""
    return False, f"{', '.join(bad)} not within {rtol * 100:g} %.", hint


def symbolic(answer, expected, names: str, what: str = "the expression") -> tuple[bool, str, str]:
    """Accept any expression equivalent to ``expected`` (a sympy expression in ``names``).

    Symbols are matched by name, whatever their assumptions. The difference must simplify
    to zero; when ``simplify`` cannot decide, the two are compared at six seeded random
    positive values of the symbols (relative 1e-9), which equivalent expressions always
    pass.

    Parameters
    ----------
    answer : sympy.Expr or str or number
        The student's expression (a string is parsed with the allowed symbols).
    expected : sympy.Expr
        The right expression.
    names : str
        The allowed symbol names, separated by spaces.
    what : str
        How to name the answer in messages.

    Returns
    -------
    (bool, str, str)
        ``(correct, message, hint)``.

    Raises
    ------
    AnswerError
        If the answer cannot be parsed, is an equation, or uses other symbols.

    Examples
    --------
    >>> import sympy as sp
    >>> m, r = sp.symbols("m r")
    >>> symbolic("r*m/2", m * r / 2, "m r")[0], symbolic(m * r, m * r / 2, "m r")[0]
    (True, False)
    """
    import sympy as sp

    allowed = {n: sp.Symbol(n, positive=True) for n in names.split()}
    hint = f"Use the symbols {', '.join(allowed)} (e.g. `{next(iter(allowed))} = sympy.Symbol(...)`)."
    if isinstance(answer, (str,)):
        try:
            expr = sp.sympify(answer, locals=dict(allowed))
        except (sp.SympifyError, SyntaxError, TypeError, ValueError):
            raise _err(f"{what.capitalize()} {answer!r} could not be read as a formula.", hint)
    elif isinstance(answer, sp.Basic) or _plain_number(answer) is not None:
        expr = sp.sympify(answer)
    else:
        raise _err(f"{what.capitalize()} should be a sympy expression, got {type(answer).__name__}.",
                   hint)
    if isinstance(expr, sp.Equality):
        raise _err(f"{what.capitalize()} is an equation; give the right-hand side only "
                   "(an expression), e.g. the value of k.", hint)
    if not isinstance(expr, sp.Expr):
        raise _err(f"{what.capitalize()} is not an algebraic expression.", hint)
    extra = sorted(str(s) for s in expr.free_symbols if str(s) not in allowed)
    if extra:
        raise _err(f"{what.capitalize()} uses symbols not in the problem: {', '.join(extra)}.", hint)
    expr = expr.subs({s: allowed[str(s)] for s in expr.free_symbols})
    if expr.has(sp.nan, sp.zoo, sp.oo, -sp.oo):
        raise _err(f"{what.capitalize()} contains an infinity or NaN.", hint)
    expected = sp.sympify(expected).subs({s: allowed[str(s)] for s in sp.sympify(expected).free_symbols})
    diff = sp.simplify(expr - expected)
    if diff == 0:
        return True, f"{what.capitalize()} is equivalent to the expected one.", ""
    rng = np.random.default_rng(1)
    syms = sorted(allowed.values(), key=str)
    f_a = sp.lambdify(syms, expr, "numpy")
    f_e = sp.lambdify(syms, expected, "numpy")
    same = True
    for _ in range(6):
        vals = rng.uniform(0.3, 2.0, len(syms))
        a, e = complex(f_a(*vals)), complex(f_e(*vals))
        if not abs(a - e) <= 1e-9 * max(1.0, abs(e)):
            same = False
            break
    if same:
        return True, f"{what.capitalize()} is equivalent to the expected one.", ""
    return False, f"{what.capitalize()} is not equivalent to the expected one.", \
        "Write the potential energy, collect the terms in sin and cos of the angle, and set " \
        "each coefficient to zero."


def _as_mapping(answer, keys, what="the design") -> dict:
    if not isinstance(answer, dict):
        raise _err(f"{what.capitalize()} should be a dict with keys {', '.join(map(repr, keys))}, "
                   f"got {type(answer).__name__}.", f"Write it like {{{', '.join(repr(k) + ': ...' for k in keys)}}}.")
    missing = [k for k in keys if k not in answer]
    if missing:
        raise _err(f"{what.capitalize()} is missing {', '.join(map(repr, missing))}.",
                   f"Give all of {', '.join(map(repr, keys))}.")
    return answer


#: Relative tolerance on the energy variation used by design checks (numbers typed by hand
#: with 4-5 significant digits balance to about 1e-4).
DESIGN_TOLERANCE = 1e-3


def design_balanced(design: Design, constraints: list[tuple[bool, str]],
                    tolerance: float = DESIGN_TOLERANCE, n: int = 400) -> tuple[bool, str, str]:
    """Verdict for a design task: balanced within ``tolerance`` and every constraint met.

    Parameters
    ----------
    design : Design
        The student's design, built by the check.
    constraints : list of (bool, str)
        ``(met, description)`` for each constraint of the task.
    tolerance : float
        Largest accepted energy variation relative to the energy scale.
    n : int
        Configurations examined.

    Returns
    -------
    (bool, str, str)
        ``(correct, message, hint)``.

    Examples
    --------
    >>> d = lab2_lever(300.0, (0.3, 0.0), (0.0, 0.2))
    >>> design_balanced(d, [(True, "k above 400 N/m")])[0]
    True
    >>> design_balanced(d, [(False, "k above 400 N/m")])[1]
    'Your design is balanced (energy varies by less than 1e-9 of its scale); it violates: k above 400 N/m.'
    """
    try:
        rep = design.balance_report(n=n, tolerance=tolerance)
    except (UnreachableConfiguration, RuntimeError, ValueError) as e:
        return False, f"Your design could not be evaluated: {e}", "Check the geometry."
    failed = [text for ok, text in constraints if not ok]
    spread = ("less than 1e-9" if rep.variation < 1e-9 else f"{rep.variation:.1e}")
    bal = (f"balanced (energy varies by {spread} of its scale)" if rep.balanced
           else f"NOT balanced: its energy varies by {rep.variation:.1e} of its scale "
                f"(at most {tolerance:g} accepted)")
    if rep.balanced and not failed:
        return True, f"Your design is {bal} and meets every constraint.", ""
    msg = f"Your design is {bal}"
    msg += "." if not failed else f"; it violates: {'; '.join(failed)}."
    hint = ("Keep 4-5 significant digits, and make the balance condition hold exactly."
            if not rep.balanced else "Use the free choices to move the design inside the constraints.")
    return False, msg, hint


# ============================================================================ lab 1

#: Four-bar of lab 1 (lengths m, masses kg): links are uniform bars, except the
#: coupler, whose centre of mass is on BC at ``g3`` from B.
LAB1_FOURBAR = dict(A=(0.0, 0.0), D=(0.6, 0.0), r2=0.2, r3=0.5, r4=0.4,
                    m2=0.8, m3=1.2, g3=0.2, m4=1.0, max_mass=6.0, max_radius=0.25)


def lab1_fourbar(crank_cw=None, rocker_cw=None) -> Design:
    """The four-bar of lab 1, optionally with counterweights on the crank and the rocker.

    Parameters
    ----------
    crank_cw, rocker_cw : (float, (float, float)), optional
        ``(mass kg, (x, y) m)``: a counterweight on the crank (local frame: origin at the
        ground pivot A, x along AB) or on the rocker (origin at pivot D, x along DC).

    Returns
    -------
    Design

    Examples
    --------
    >>> lab1_fourbar().balance_report().balanced
    False
    """
    p = LAB1_FOURBAR
    kin = FourBarKinematics(p["A"], p["D"], p["r2"], p["r3"], p["r4"], branch=1)
    loads = [gravity_load(1, (p["r2"] / 2, 0.0), p["m2"], "crank"),
             gravity_load(2, (p["g3"], 0.0), p["m3"], "coupler"),
             gravity_load(3, (p["r4"] / 2, 0.0), p["m4"], "rocker")]
    for body, cw, name in ((1, crank_cw, "crank counterweight"), (3, rocker_cw, "rocker counterweight")):
        if cw is not None:
            m, pt = cw
            loads.append(gravity_load(body, tuple(pt), float(m), name, kind="counterweight"))
    joints = [Joint(0, p["A"], 1, (0.0, 0.0)), Joint(1, (p["r2"], 0.0), 2, (0.0, 0.0)),
              Joint(2, (p["r3"], 0.0), 3, (p["r4"], 0.0)), Joint(0, p["D"], 3, (0.0, 0.0))]
    return Design("lab 1 four-bar", ("ground", "crank", "coupler", "rocker"), joints, kin, loads,
                  labels={"A": (0, p["A"]), "B": (1, (p["r2"], 0.0)), "C": (3, (p["r4"], 0.0)),
                          "D": (0, p["D"])},
                  reference="Lecture 35: coupler replaced by equivalent masses at its joints")


@_task("1.1", "distance of the counterweight from the pivot", "r_c", "numeric",
       "a number in metres (or a string like '22 cm'); accepted within 0.5 %")
def _t11(answer):
    # lamp head 1.2 kg at 0.45 m on a uniform 0.6 kg arm, counterweight 3 kg
    return numeric(answer, (1.2 * 0.45 + 0.6 * 0.45 / 2) / 3.0, "length")


@_task("1.2", "formula for the counterweight distance r_c", "r_c_formula", "symbolic",
       "a sympy expression in m, r, m_l, m_c (any equivalent form is accepted)")
def _t12(answer):
    import sympy as sp

    m, r, ml, mc = sp.symbols("m r m_l m_c", positive=True)
    return symbolic(answer, (m * r + ml * r / 2) / mc, "m r m_l m_c", "your r_c")


@_task("1.3", "equivalent masses of the coupler at B and C", "m_equivalent", "numeric",
       "a pair (m_B, m_C) in kg; each accepted within 0.5 %")
def _t13(answer):
    p = LAB1_FOURBAR
    mC = p["m3"] * p["g3"] / p["r3"]
    return numeric_vector(answer, (p["m3"] - mC, mC), "mass", names=("m_B", "m_C"))


@_task("1.4", "counterweights that balance the four-bar (open design)", "counterweights", "design",
       "a dict {'crank': (mass, (x, y)), 'rocker': (mass, (x, y))} in kg and m, local frames; "
       "each mass at most 6 kg and at most 0.25 m from its pivot; balanced to 0.1 %", points=2)
def _t14(answer):
    a = _as_mapping(answer, ("crank", "rocker"), "your counterweights")
    p = LAB1_FOURBAR
    parts, cons = {}, []
    for key in ("crank", "rocker"):
        item = a[key]
        if not isinstance(item, (tuple, list)) or len(item) != 2:
            raise _err(f"counterweights[{key!r}] should be a pair (mass, (x, y)).",
                       "E.g. (2.0, (-0.1, 0.0)).")
        m = quantity(item[0], "mass", f"the {key} counterweight mass")
        pt = point(item[1], f"the {key} counterweight position")
        if m < 0:
            raise _err(f"The {key} counterweight mass is negative.", "Masses are >= 0.")
        parts[key] = (m, tuple(pt))
        cons.append((m <= p["max_mass"] + 1e-12, f"{key} counterweight heavier than {p['max_mass']} kg"))
        cons.append((float(np.hypot(*pt)) <= p["max_radius"] + 1e-12,
                     f"{key} counterweight farther than {p['max_radius']} m from its pivot"))
    d = lab1_fourbar(parts["crank"], parts["rocker"])
    return design_balanced(d, cons)


# ============================================================================ lab 2

#: The lever of lab 2's design task: load W (N) at distance l (m) and the limits.
LAB2_LEVER = dict(W=30.0, l=0.6, k_max=400.0, anchor_max=0.35, attach_max=0.6)


def lab2_lever(k: float, a, b, *, W: float | None = None, l: float | None = None,
               free_length: float = 0.0) -> Design:
    """A lever with a load ``W`` at ``(l, 0)`` and one spring from ground point ``b`` to lever point ``a``.

    Parameters
    ----------
    k : float
        Spring rate (N/m), > 0.
    a : (float, float)
        Attachment on the lever, local frame (m).
    b : (float, float)
        Anchor on the ground (m).
    W, l : float, optional
        Load (N) and its distance (m); lab 2's design task values by default.
    free_length : float
        Free length of the spring (m); 0 for a ZFL spring.

    Returns
    -------
    Design

    Examples
    --------
    >>> lab2_lever(300.0, (0.3, 0.0), (0.0, 0.2)).balance_report().balanced
    True
    """
    W = LAB2_LEVER["W"] if W is None else W
    l = LAB2_LEVER["l"] if l is None else l
    return Design("lab 2 lever", ("ground", "lever"), [Joint(0, (0.0, 0.0), 1, (0.0, 0.0))],
                  lever_kinematics(), [Load(1, (l, 0.0), (0.0, -W), "W")],
                  [Spring(k, free_length, (0, tuple(b)), (1, tuple(a)), name="k")],
                  labels={"O": (0, (0.0, 0.0)), "a": (1, tuple(a)), "b": (0, tuple(b))})


@_task("2.1", "spring rate that balances the lamp arm", "k_lamp", "numeric",
       "a number in N/m (or a string like '0.2 N/mm'); accepted within 0.5 %")
def _t21(answer):
    return numeric(answer, 1.5 * G * 0.4 / (0.25 * 0.12), "stiffness")


@_task("2.2", "balance conditions of the generalized lever: (a_y, k)", "lever_conditions", "symbolic",
       "a pair (a_y, k) of sympy expressions in W, l, a_x, b_x, b_y; any equivalent form accepted")
def _t22(answer):
    import sympy as sp

    if isinstance(answer, dict):
        answer = (answer.get("a_y"), answer.get("k"))
    if isinstance(answer, (str, sp.Basic)) or not hasattr(answer, "__len__") or len(answer) != 2:
        raise _err("The answer should be a pair (a_y, k) of expressions.",
                   "Write it like (a_y_expr, k_expr).")
    W, l, ax, bx, by = sp.symbols("W l a_x b_x b_y", positive=True)
    names = "W l a_x b_x b_y"
    ok1, m1, h1 = symbolic(answer[0], -ax * bx / by, names, "your a_y")
    ok2, m2, h2 = symbolic(answer[1], W * l * by / (ax * (bx ** 2 + by ** 2)), names, "your k")
    return ok1 and ok2, f"{m1} {m2}", h1 or h2


@_task("2.3", "constant potential energy of the balanced LaCoste lever", "lever_energy", "numeric",
       "a number in J (energies measured from the pivot height, spring at zero length); "
       "accepted within 0.5 %")
def _t23(answer):
    W, l, ax, by = 20.0, 0.5, 0.1, 0.25
    return numeric(answer, W * l / 2 * (ax / by + by / ax), "energy")


@_task("2.4", "a ZFL spring that balances the lever within the limits (open design)", "lever_spring",
       "design", "a dict {'k': N/m, 'a': (x, y) on the lever, 'b': (x, y) on the ground} in SI units; "
       "k <= 400 N/m, |b| <= 0.35 m, |a| <= 0.6 m; balanced to 0.1 %", points=2)
def _t24(answer):
    a = _as_mapping(answer, ("k", "a", "b"), "your spring")
    p = LAB2_LEVER
    k = quantity(a["k"], "stiffness", "k")
    pa, pb = point(a["a"], "a"), point(a["b"], "b")
    if k <= 0:
        raise _err("k must be positive.", "A spring rate is > 0 N/m.")
    cons = [(k <= p["k_max"] * (1 + 1e-12), f"k above {p['k_max']:g} N/m"),
            (np.hypot(*pb) <= p["anchor_max"] + 1e-12, f"anchor b farther than {p['anchor_max']} m from the pivot"),
            (np.hypot(*pa) <= p["attach_max"] + 1e-12, f"attachment a farther than {p['attach_max']} m from the pivot")]
    return design_balanced(lab2_lever(k, tuple(pa), tuple(pb)), cons)


def _world_extent(design: Design, n: int = 300) -> np.ndarray:
    """Bounding box ``[[xmin, ymin], [xmax, ymax]]`` (m) of every spring end over ``n`` configurations."""
    q = design.sample(n)
    pts = []
    for s in design.springs:
        for at in (s.a, s.b):
            pts.append(design.world_points(q, [tuple(at)]).reshape(-1, 2))
    P = np.concatenate(pts)
    return np.array([P.min(axis=0), P.max(axis=0)])


def _is_design(x) -> bool:
    return isinstance(x, Design)


# ============================================================================ lab 4

#: The 2R arm of lab 4's parallelogram task (kg, m).
LAB4_PARALLELOGRAM = dict(m1=1.2, m2=0.8, l1=0.45, p1=(0.2, 0.0), p2=(0.3, 0.0),
                          b1=0.15, c1=0.1, b2=0.12, c2=0.1)
#: Singh & Ananthasuresh's 2R (N, m) and the limits of lab 4's design task.
LAB4_SINGH = dict(W1=10.0, W2=20.0, p1=(1.0, 0.5), p_x2=2.0, l=1.5, k_max=9.0, anchor_max=3.2)


@_task("4.1", "spring rates (k1, k2) of the parallelogram 2R arm", "k_parallelogram", "numeric",
       "a pair (k1, k2) in N/m; each accepted within 0.5 %")
def _t41(answer):
    from ..methods.lecture.serial import serial_2r_parallelogram

    p = serial_2r_parallelogram(**LAB4_PARALLELOGRAM).parameters
    return numeric_vector(answer, (p["k1"], p["k2"]), "stiffness", names=("k1", "k2"))


@_task("4.2", "least possible constant energy of any balanced version of Singh's 2R", "pe_min_2r",
       "numeric", "a number in J (loads' energy measured from the base pivot's height); within 0.5 %")
def _t42(answer):
    from ..methods.singh.serial import serial_2r_min_preload

    s = LAB4_SINGH
    d = serial_2r_min_preload(s["W1"], s["W2"], s["p1"], s["p_x2"], s["l"])
    return numeric(answer, d.parameters["PE_min"], "energy")


def _same_loads(design: Design, ref: Design) -> bool:
    key = lambda L: sorted((ld.body, round(ld.point[0], 9), round(ld.point[1], 9),  # noqa: E731
                            round(ld.force[0], 9), round(ld.force[1], 9)) for ld in L)
    if key(design.loads) != key(ref.loads) or design.dof != ref.dof:
        return False
    q = ref.sample(20)
    try:
        return bool(np.allclose(design.poses(q), ref.poses(q), atol=1e-9))
    except Exception:
        return False


@_task("4.3", "minimum-preload 2R whose springs are soft and anchored close (open design)", "arm_design",
       "design", "a balancelab Design of Singh's 2R (or a dict {'a_x': (a_x1, a_x2, a_x3)} for "
       "serial_2r_min_preload); minimum preload (energy within 0.1 % of the least possible), every "
       "spring at most 9 N/m, every ground anchor within 3.2 m of the base pivot; balanced to 0.1 %",
       points=2)
def _t43(answer):
    from ..methods.singh.serial import serial_2r_min_preload

    s = LAB4_SINGH
    args = (s["W1"], s["W2"], s["p1"], s["p_x2"], s["l"])
    ref = serial_2r_min_preload(*args)
    if _is_design(answer):
        d = answer
        if not _same_loads(d, ref):
            raise _err("Your design does not carry the loads of Singh's 2R (W1 = 10 N at (1, 0.5) m, "
                       "W2 = 20 N at 2 m, l = 1.5 m) on the same two links.",
                       "Build it from serial_2r_min_preload(10, 20, (1.0, 0.5), 2.0, 1.5, a_x=...).")
    else:
        a = _as_mapping(answer, ("a_x",), "your choice")
        ax = vector(a["a_x"], 3, "length", "a_x")
        try:
            d = serial_2r_min_preload(*args, a_x=tuple(ax))
        except (ValueError, TypeError) as e:
            raise _err(f"These free choices give no design: {e}", "Pick other values of a_x.")
    rep = d.balance_report(n=400, tolerance=DESIGN_TOLERANCE)
    pe_min = ref.parameters["PE_min"]
    anchors = [at.point for sp_ in d.springs for at in (sp_.a, sp_.b) if at.body == 0]
    cons = [(all(sp_.k <= s["k_max"] * (1 + 1e-9) for sp_ in d.springs),
             f"a spring stiffer than {s['k_max']:g} N/m"),
            (all(np.hypot(*p) <= s["anchor_max"] + 1e-9 for p in anchors),
             f"a ground anchor farther than {s['anchor_max']:g} m from the base pivot"),
            (rep.energy <= pe_min * (1 + DESIGN_TOLERANCE) + 1e-12,
             "more preload than necessary (its constant energy is above the least possible)")]
    return design_balanced(d, cons)


@_task("4.4", "spring rate k1 of Lustig et al.'s case 1 by the stiffness-matrix method", "k1_lustig",
       "numeric", "a number in N/m; accepted within 0.5 %")
def _t44(answer):
    from ..methods.lustig.stiffness import lustig_values

    return numeric(answer, lustig_values(1)["k1"], "stiffness")


# ============================================================================ lab 5

#: Lab 5's spring-loaded four-bar (technique 2) and the box its springs must fit in (m, N/m).
LAB5_TECHNIQUE2 = dict(K=(0.1, -0.2), k_l=100.0, box=((-0.25, -0.35), (0.6, 0.35)), k_max=400.0)


def lab5_technique2(base: str = "A", h: float = 0.15) -> Design:
    """Lab 5's spring-loaded four-bar balanced by technique 2 (Deepak & Ananthasuresh, Sec. 2.2.2).

    Parameters
    ----------
    base : {"A", "B"}
        Ground pivot the auxiliary parallelogram is based at.
    h : float
        The free length ``|WH|`` (m), > 0.

    Returns
    -------
    Design

    Examples
    --------
    >>> lab5_technique2("A", 0.15).balance_report().balanced
    True
    """
    from ..methods.deepak.spring_fourbar import example_fourbar, technique2

    p = LAB5_TECHNIQUE2
    return technique2(example_fourbar(), p["K"], p["k_l"], base, h)


@_task("5.1", "spring rate on the crank of the lecture's four-bar with two springs", "k_crank",
       "numeric", "a number in N/m; accepted within 0.5 %")
def _t51(answer):
    from ..methods.lecture.fourbar import fourbar_two_springs

    return numeric(answer, fourbar_two_springs().parameters["k2"], "stiffness")


@_task("5.2", "constant energy of Singh's four-bar balanced with minimum preload", "pe_min_fourbar",
       "numeric", "a number in J; accepted within 0.5 %")
def _t52(answer):
    from ..methods.singh.fourbar import singh_fourbar

    return numeric(answer, singh_fourbar().parameters["PE_min"], "energy")


@_task("5.3", "a technique-2 balancer whose springs fit in the box (open design)", "technique2_choice",
       "design", "a dict {'base': 'A' or 'B', 'h': metres}; every spring at most 400 N/m and every "
       "spring end inside -0.25 <= x <= 0.6 m, -0.35 <= y <= 0.35 m in every configuration; "
       "balanced to 0.1 %", points=2)
def _t53(answer):
    a = _as_mapping(answer, ("base", "h"), "your choice")
    if a["base"] not in ("A", "B"):
        raise _err(f"base should be 'A' or 'B', got {a['base']!r}.", "The two ground pivots are A and B.")
    h = quantity(a["h"], "length", "h")
    if h <= 0:
        raise _err("h must be positive.", "h is a length |WH| > 0.")
    try:
        d = lab5_technique2(a["base"], h)
    except (ValueError, TypeError) as e:
        raise _err(f"This choice gives no design: {e}", "Try another h.")
    p = LAB5_TECHNIQUE2
    lo, hi = np.array(p["box"][0]), np.array(p["box"][1])
    ext = _world_extent(d)
    cons = [(all(s.k <= p["k_max"] * (1 + 1e-9) for s in d.springs), f"a spring stiffer than {p['k_max']:g} N/m"),
            (bool(np.all(ext[0] >= lo - 1e-9) and np.all(ext[1] <= hi + 1e-9)),
             "a spring end leaves the box")]
    return design_balanced(d, cons)


# ============================================================================ lab 6

#: Lab 6's projector lift (kg, m) and limits of its design task.
LAB6_SCISSORS = dict(a=0.5, payload=8.0, k_max=600.0, l10_max=0.45)


def lab6_scissors(l10: float, k1: float | None = None, k2: float | None = None) -> Design:
    """Lab 6's projector lift with spring 1 of free length ``l10``, optionally with given rates.

    Parameters
    ----------
    l10 : float
        Free length of spring 1 (m), > 0.
    k1, k2 : float, optional
        Spring rates (N/m); by default those that balance the lift (Singh eqs 52-59).

    Returns
    -------
    Design

    Examples
    --------
    >>> lab6_scissors(0.42).balance_report().balanced
    True
    """
    from ..methods.singh.scissors import scissors_lift

    p = LAB6_SCISSORS
    d = scissors_lift(a=p["a"], payload=p["payload"], l10=l10)
    if k1 is None and k2 is None:
        return d
    s1, s2 = d.springs
    k1 = s1.k if k1 is None else k1
    k2 = s2.k if k2 is None else k2
    return d.replace(springs=[Spring(k1, s1.free_length, s1.a, s1.b, name=s1.name),
                              Spring(k2, s2.free_length, s2.a, s2.b, name=s2.name)])


@_task("6.1", "spring rate k1 of the projector lift with l10 = a", "k1_lift", "numeric",
       "a number in N/m; accepted within 0.5 %")
def _t61(answer):
    return numeric(answer, lab6_scissors(LAB6_SCISSORS["a"]).parameters["k1"], "stiffness")


@_task("6.2", "spring rate k1 on the Peaucellier-Lipkin board's crank for a_x1 = 0.25 m", "k1_board",
       "numeric", "a number in N/m; accepted within 0.5 %")
def _t62(answer):
    from ..methods.singh.peaucellier import peaucellier_board

    return numeric(answer, peaucellier_board(a_x1=0.25).parameters["k1"], "stiffness")


@_task("6.3", "a softer projector lift (open design)", "lift_design", "design",
       "a dict {'l10': m, 'k1': N/m, 'k2': N/m}: spring 1's free length and both rates; "
       "k1 and k2 at most 600 N/m, l10 at most 0.45 m; balanced to 0.1 %", points=2)
def _t63(answer):
    a = _as_mapping(answer, ("l10", "k1", "k2"), "your lift")
    l10 = quantity(a["l10"], "length", "l10")
    k1 = quantity(a["k1"], "stiffness", "k1")
    k2 = quantity(a["k2"], "stiffness", "k2")
    if l10 <= 0 or k1 <= 0 or k2 <= 0:
        raise _err("l10, k1 and k2 must be positive.", "Free lengths and rates are > 0.")
    p = LAB6_SCISSORS
    try:
        d = lab6_scissors(l10, k1, k2)
    except (ValueError, TypeError) as e:
        raise _err(f"This choice gives no lift: {e}", "Pick another l10.")
    cons = [(k1 <= p["k_max"] * (1 + 1e-9) and k2 <= p["k_max"] * (1 + 1e-9),
             f"a spring stiffer than {p['k_max']:g} N/m"),
            (l10 <= p["l10_max"] + 1e-12, f"l10 longer than {p['l10_max']} m")]
    return design_balanced(d, cons)


# ============================================================================ lab 3

#: Lab 3's lever (kg, m) and its limits: torque error as a fraction of ``m g r``.
LAB3_LEVER = dict(mass=2.0, r=0.5, b=0.3, c=0.2, pulley_error=0.01, free_length=0.1,
                  theta_range=(-math.pi / 3, math.pi / 3), torque_error=0.03)


def lab3_torque_error(design: Design, theta_range=None, n: int = 241) -> float:
    """Largest ``|dV/dtheta|`` of a one-link design over a range, divided by ``m g r`` of lab 3's lever.

    Parameters
    ----------
    design : Design
        A lever (one degree of freedom).
    theta_range : (float, float), optional
        Range of the link angle (rad); lab 3's working range (+-60 deg) by default.
    n : int
        Number of angles.

    Returns
    -------
    float

    Examples
    --------
    >>> lab3_torque_error(lab2_lever(2 * G * 0.5 / (0.3 * 0.2), (0.2, 0.0), (0.0, 0.3), W=2 * G, l=0.5)) < 1e-9
    True
    """
    p = LAB3_LEVER
    lo, hi = p["theta_range"] if theta_range is None else theta_range
    q = np.linspace(lo, hi, n)
    torque = design.generalized_force(q)[..., 0]
    return float(np.max(np.abs(torque)) / (p["mass"] * G * p["r"]))


_PULLEY_LIMIT: list = []


def _pulley_limit() -> float:
    """Pulley radius (m) at which the lever's largest torque error is 1 % of ``m g r``."""
    if not _PULLEY_LIMIT:
        from scipy.optimize import brentq

        from ..methods.realize import pulley_balance_error, pulley_lever

        p = LAB3_LEVER
        args = (p["mass"], p["r"], p["b"], p["c"])
        f = lambda rad: (pulley_balance_error(pulley_lever(*args, radius=rad)).residual_torque  # noqa: E731
                         / (p["mass"] * G * p["r"]) - p["pulley_error"])
        _PULLEY_LIMIT.append(brentq(f, 1e-5, 0.05, xtol=1e-8))
    return _PULLEY_LIMIT[0]


@_task("3.1", "largest pulley radius for a 1 % torque error", "pulley_radius", "numeric",
       "a number in metres (or a string like '2.8 mm'); accepted within 2 %")
def _t31(answer):
    return numeric(answer, _pulley_limit(), "length", rtol=0.02)


@_task("3.2", "free length of the partner spring that makes a ZFL pair", "partner_free_length",
       "numeric", "a number in metres (negative!); accepted within 0.5 %")
def _t32(answer):
    # an ordinary spring of 400 N/m and free length 50 mm, partner of 250 N/m
    return numeric(answer, -400.0 * 0.05 / 250.0, "length")


@_task("3.3", "an ordinary spring that balances the lever within 3 % over +-60 deg (open design)",
       "ordinary_spring", "design",
       "a dict {'k': N/m, 'a': (x, y) on the link, 'b': (x, y) on the ground} for a spring of free "
       "length 0.1 m; largest torque error over -60..60 deg at most 3 % of m g r; |a|, |b| <= 0.4 m",
       points=2)
def _t33(answer):
    a = _as_mapping(answer, ("k", "a", "b"), "your spring")
    p = LAB3_LEVER
    k = quantity(a["k"], "stiffness", "k")
    pa, pb = point(a["a"], "a"), point(a["b"], "b")
    if k <= 0:
        raise _err("k must be positive.", "A spring rate is > 0 N/m.")
    d = lab2_lever(k, tuple(pa), tuple(pb), W=p["mass"] * G, l=p["r"], free_length=p["free_length"])
    err = lab3_torque_error(d)
    fits = np.hypot(*pa) <= 0.4 + 1e-12 and np.hypot(*pb) <= 0.4 + 1e-12
    ok = err <= p["torque_error"] and fits
    msg = f"Largest torque error over the range: {100 * err:.2g} % of m g r"
    msg += (" (at most 3 % accepted)" if err > p["torque_error"] else "")
    if not fits:
        msg += "; a spring end is farther than 0.4 m from the pivot"
    hint = "" if ok else ("Start from the ZFL design and move the anchor and the rate to absorb the "
                          "free length; plot the torque over the range.")
    return ok, msg + ".", hint
