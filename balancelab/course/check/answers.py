"""Reading and judging answers: the building blocks of every task's judge.

Reading: :func:`quantity` (a number with an optional unit), :func:`vector`, :func:`point`
and :func:`as_mapping` turn an answer into SI numbers or raise :class:`AnswerError` with a
friendly message. Judging: :func:`numeric`, :func:`numeric_vector`, :func:`symbolic` and
:func:`design_balanced` return ``(correct, message, hint)`` and never reveal the expected
value.
"""
from __future__ import annotations

import math
import re
from numbers import Real

import numpy as np

from ...core.design import Design, UnreachableConfiguration
from ...core.elements import G
from .core import AnswerError

__all__ = ["quantity", "vector", "point", "spring", "numeric", "numeric_vector", "symbolic", "BALANCE_HINT", "personal_option", "as_mapping",
           "DESIGN_TOLERANCE", "design_balanced"]

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


def _cap(what: str) -> str:
    """``what`` with its first letter in upper case and the rest as written (symbols keep their case).

    >>> _cap("your dV/dtheta_1")
    'Your dV/dtheta_1'
    """
    return what[:1].upper() + what[1:]


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
            raise AnswerError(f"{_cap(what)} {_short(answer)} does not start with a number.", hint)
        value, unit = float(m.group(1)), m.group(2)
        if unit == "" and si:
            raise AnswerError(f"{_cap(what)} {_short(answer)} has no unit.",
                              f"Write the unit, e.g. '{_short(answer.strip())[1:-1]} {si}', or store a plain number in {si}.")
    elif isinstance(answer, tuple) and len(answer) == 2 and isinstance(answer[1], str):
        value, unit = _plain_number(answer[0]), answer[1].strip()
        if value is None:
            raise AnswerError(f"The first item of {what} should be a number, got {type(answer[0]).__name__}.",
                              hint)
    else:
        value = _plain_number(answer)
        if value is None:
            kind = type(answer).__name__
            if isinstance(answer, (list, tuple, np.ndarray)):
                raise AnswerError(f"{_cap(what)} should be one number, got a {kind} of "
                                  f"{len(answer)} items.", hint)
            raise AnswerError(f"{_cap(what)} should be a number, got {kind}"
                              f"{'' if answer is None else ' ' + _short(answer)}.", hint)
        unit = si
    if not math.isfinite(value):
        raise AnswerError("The answer is NaN or infinite; give a finite number." if what == "the answer"
                          else f"{_cap(what)} is NaN or infinite; give a finite number.", hint)
    if unit not in table:
        known = ", ".join(repr(u) for u in table if u)
        raise AnswerError(f"Unit {unit!r} is not a unit of {dimension} here.", f"Use one of {known}.")
    return value * table[unit]


def _short(x) -> str:
    """A short excerpt of a student's answer for a message: printable, at most 40 characters."""
    s = "".join(c if c.isprintable() else "?" for c in repr(x)[:200])
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
        raise AnswerError(f"{_cap(what)} should be a tuple of {n} numbers, got {type(answer).__name__}.",
                          f"Write it like ({', '.join(['...'] * n)}).")
    items = list(np.asarray(answer, dtype=object).ravel()) if isinstance(answer, np.ndarray) else list(answer)
    if len(items) != n:
        raise AnswerError(f"{_cap(what)} should have {n} items, got {len(items)}.",
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


def spring(answer) -> tuple[float, np.ndarray, np.ndarray]:
    """A spring answer ``{'k': N/m, 'a': (x, y), 'b': (x, y)}`` as ``(k, a, b)``, or raise :class:`AnswerError`.

    Parameters
    ----------
    answer : mapping
        The rate ``k`` (> 0, N/m or a string with a unit) and the two ends ``a`` and ``b``.

    Returns
    -------
    (float, numpy.ndarray, numpy.ndarray)
        ``k`` in N/m, ``a`` and ``b`` in metres.

    Examples
    --------
    >>> k, a, b = spring({"k": "0.3 kN/m", "a": (0.3, 0), "b": (0, "20 cm")})
    >>> k, a.tolist(), b.tolist()
    (300.0, [0.3, 0.0], [0.0, 0.2])
    """
    a = as_mapping(answer, ("k", "a", "b"), "your spring")
    k = quantity(a["k"], "stiffness", "k")
    pa, pb = point(a["a"], "a"), point(a["b"], "b")
    if k <= 0:
        raise AnswerError("k must be positive.", "A spring rate is > 0 N/m.")
    return k, pa, pb


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
            hint = _band(abs(ratio - 1)) + " Recheck each step and its units."
    return False, f"Not within {tol} of the expected value.", hint


#: Bands of the relative error a hint may name: wide enough, and without a direction, so that
#: the hints cannot be used to bisect towards the expected value.
ERROR_BANDS = ((0.05, "less than 5 %"), (0.5, "5 % to 50 %"), (float("inf"), "more than 50 %"))


def _band(error: float) -> str:
    """The error band of a relative error, without its direction.

    >>> _band(0.2)
    'Your answer is off by 5 % to 50 % (too large or too small: the hint does not say).'
    """
    text = next(t for limit, t in ERROR_BANDS if error < limit)
    return f"Your answer is off by {text} (too large or too small: the hint does not say)."


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


#: The hint of a wrong expression when its task gives none: the way to a balance condition.
BALANCE_HINT = ("Write the potential energy, collect the terms in sin and cos of the angle, and set each "
                "coefficient to zero.")


def symbolic(answer, expected, names: str, what: str = "the expression",
             signed: str = "", hint: str = BALANCE_HINT) -> tuple[bool, str, str]:
    """Accept any expression equivalent to ``expected`` (a sympy expression in ``names``).

    Symbols are matched by name, whatever their assumptions. The answer is read without running
    code (:func:`~.variant.read_expression`: a string may use only ``names``, a fixed set of
    functions and ``pi``) and compared with ``expected`` at 16 random values of the symbols drawn
    afresh at every call (:func:`~.variant.equivalent`, relative 1e-7): equivalent expressions
    always pass, and an expression built to agree at known points does not. No symbolic
    simplification runs, so a huge answer cannot stall the check.

    Parameters
    ----------
    answer : sympy.Expr or str or number
        The student's expression (a string is parsed with the allowed symbols only).
    expected : sympy.Expr
        The right expression.
    names : str
        The allowed symbol names, separated by spaces.
    what : str
        How to name the answer in messages.
    signed : str
        Names (among ``names``) that may be negative: drawn in ``[-2, 2]``; the others are
        positive, drawn in ``[0.3, 2]``.
    hint : str
        The hint for a wrong expression: the way to the task's result (by default the way to a
        balance condition, :data:`BALANCE_HINT`). An expression that is the expected one with the
        opposite sign gets a hint that says so instead.

    Returns
    -------
    (bool, str, str)
        ``(correct, message, hint)``.

    Raises
    ------
    AnswerError
        If the answer cannot be read, is an equation, or uses other symbols or functions.

    Examples
    --------
    >>> import sympy as sp
    >>> m, r = sp.symbols("m r")
    >>> symbolic("r*m/2", m * r / 2, "m r")[0], symbolic(m * r, m * r / 2, "m r")[0]
    (True, False)
    >>> symbolic("__import__('os').system('ls')", m * r / 2, "m r")
    Traceback (most recent call last):
    ...
    balancelab.core.errors.AnswerError: The expression could not be read as a formula.
    """
    from .variant import equivalent, read_expression

    sign = set(signed.split())
    ranges = {n: (-2.0, 2.0) if n in sign else (0.3, 2.0) for n in names.split()}
    mine = read_expression(answer, tuple(ranges), what)
    if mine.has(*_infinities()):
        raise AnswerError(f"{_cap(what)} contains an infinity or NaN.", f"Use the symbols {', '.join(ranges)}.")
    ok, message, _ = equivalent(mine, expected, ranges, what, seed=None)
    if ok:
        return True, f"{_cap(what)} is equivalent to the expected one.", ""
    if message.endswith("is a number: the task asks for a formula in its symbols."):
        return False, message, hint
    flipped, _, _ = equivalent(-mine, expected, ranges, what, seed=None)
    if flipped:
        return False, f"{_cap(what)} is not equivalent to the expected one.", \
            "It is the expected expression with the opposite sign: check which way each term acts."
    return False, f"{_cap(what)} is not equivalent to the expected one.", hint


def _infinities() -> tuple:
    import sympy as sp

    return (sp.nan, sp.zoo, sp.oo, -sp.oo)


def personal_option(rng: np.random.Generator | None, published: str, options: tuple[str, ...]) -> str:
    """The option a derive task's personal variant draws: ``published`` for the published numbers, else one of ``options``.

    A derive task whose formula stands in the book or a docstring gets a personal variant of its
    problem (a centre of mass elsewhere, an extra weight, an angle from another line), so that the
    printed formula, read by a student or found with ``getattr``, is wrong for them; the judge
    compares the answer by equivalence with the variant's own formula.

    Parameters
    ----------
    rng : numpy.random.Generator or None
        The student's generator (:func:`~.core.student_rng`), or ``None`` for the published problem.
    published : str
        The published value, as SymPy text (e.g. ``"1/2"``).
    options : tuple of str
        The personal values (none equal to ``published``).

    Returns
    -------
    str
        SymPy text, e.g. ``"2/5"`` or ``"pi/6"``.

    Examples
    --------
    >>> personal_option(None, "1/2", ("1/3", "2/3"))
    '1/2'
    >>> import numpy as np
    >>> personal_option(np.random.default_rng(0), "1/2", ("1/3", "2/3")) in ("1/3", "2/3")
    True
    """
    if published in options:
        raise ValueError(f"options must not hold the published value {published!r}")
    return published if rng is None else options[int(rng.integers(len(options)))]


def as_mapping(answer, keys, what: str = "the design") -> dict:
    """The answer itself if it is a dict holding every key, or raise :class:`AnswerError`.

    Parameters
    ----------
    answer : object
        The student's answer.
    keys : sequence of str
        Keys the dict must hold (others are ignored).
    what : str
        How to name the answer in messages.

    Returns
    -------
    dict

    Examples
    --------
    >>> as_mapping({"k": 300.0, "a": (0.3, 0.0)}, ("k", "a"))["k"]
    300.0
    >>> as_mapping({"k": 300.0}, ("k", "a"), "your spring")
    Traceback (most recent call last):
    ...
    balancelab.core.errors.AnswerError: Your spring is missing 'a'.
    """
    if not isinstance(answer, dict):
        layout = ", ".join(repr(k) + ": ..." for k in keys)
        raise AnswerError(f"{_cap(what)} should be a dict with keys {', '.join(map(repr, keys))}, "
                          f"got {type(answer).__name__}.", f"Write it like {{{layout}}}.")
    missing = [k for k in keys if k not in answer]
    if missing:
        raise AnswerError(f"{_cap(what)} is missing {', '.join(map(repr, missing))}.",
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
    >>> import balancelab as bl
    >>> d = bl.lecture.single_link_spring(mass=2.0, length=0.5, b=0.3, c=0.2)
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
    # qualitative on purpose: the verdict is no signal to optimize against (the library's own
    # balance_report gives the variation to whoever designs with it)
    spread = "less than 1e-9" if rep.variation < 1e-9 else f"less than the accepted {tolerance:g}"
    bal = (f"balanced (energy varies by {spread} of its scale)" if rep.balanced
           else f"NOT balanced: its energy varies by more than {tolerance:g} of its scale")
    if rep.balanced and not failed:
        return True, f"Your design is {bal} and meets every constraint.", ""
    msg = f"Your design is {bal}"
    msg += "." if not failed else f"; it violates: {'; '.join(failed)}."
    hint = ("Keep 4-5 significant digits, and make the balance condition hold exactly."
            if not rep.balanced else "Use the free choices to move the design inside the constraints.")
    return False, msg, hint
