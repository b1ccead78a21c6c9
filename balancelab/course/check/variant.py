"""Judging a derived formula by equivalence on random instances of its symbols.

A derive task asks for a formula in the task's own symbols. :func:`equivalent` accepts any form
of the right formula (expanded, factored, rewritten with other trigonometric identities) by
evaluating the student's expression and the reference at random points of the symbols' valid
ranges and comparing them with a relative tolerance scaled by the reference's typical size. No
symbolic simplification runs, so a judge stays fast whatever it is given; an answer that is not
an expression, that uses a symbol the task does not have, or that is too large or too deeply
nested is refused with a message saying why (:func:`read_expression`).

The expressions are evaluated by a small interpreter of a fixed set of sympy node types
(:data:`FUNCTIONS` and arithmetic) on numpy arrays: nothing is compiled or executed.

A task with a *personal variant* (the student's own numbering or geometry, drawn with
:func:`~.core.student_rng`) builds its reference from the variant, so a formula copied from
the book or a docstring is wrong for most students.
"""
from __future__ import annotations

import io
import re
import tokenize
from typing import Any, Mapping, Sequence

import numpy as np

from ...core.errors import AnswerError

__all__ = ["MAX_NODES", "MAX_DEPTH", "FUNCTIONS", "read_expression", "evaluate", "equivalent",
           "equivalent_parts"]

#: The largest expression (sympy nodes) and the deepest nesting a judge evaluates.
MAX_NODES = 600
MAX_DEPTH = 40
#: The functions a formula may use, by sympy name, with their numpy counterparts (complex-valued).
FUNCTIONS: dict[str, Any] = {"sin": np.sin, "cos": np.cos, "tan": np.tan, "asin": np.arcsin, "acos": np.arccos,
                             "atan": np.arctan, "sinh": np.sinh, "cosh": np.cosh, "tanh": np.tanh, "exp": np.exp,
                             "log": np.log, "sqrt": np.sqrt, "Abs": np.abs}
_CONSTANTS = ("pi", "E")
_MAX_STRING = 2000


def _hint(names: Sequence[str]) -> str:
    return f"Use only the symbols {', '.join(names)} (e.g. `{names[0]} = sympy.Symbol({names[0]!r})`)."


def _parse_string(text: str, names: Sequence[str], what: str):
    """A sympy expression from a formula written as text, after checking every name it uses."""
    import sympy as sp
    from sympy.parsing.sympy_parser import convert_xor, parse_expr, standard_transformations

    if len(text) > _MAX_STRING:
        raise AnswerError(f"{what.capitalize()} is too long to be read ({len(text)} characters).",
                          "Give the formula as a sympy expression.")
    if "__" in text or re.search(r"\.\s*[A-Za-z_]", text) or re.search(r"[\[\]{}:;=@!\\'\"]", text):
        raise AnswerError(f"{what.capitalize()} could not be read as a formula.", _hint(names))
    try:
        toks = [t.string for t in tokenize.generate_tokens(io.StringIO(text).readline) if t.type == tokenize.NAME]
    except (tokenize.TokenError, IndentationError, SyntaxError) as err:
        raise AnswerError(f"{what.capitalize()} could not be read as a formula.", _hint(names)) from err
    unknown = sorted({t for t in toks if t not in names and t not in FUNCTIONS and t not in _CONSTANTS})
    if unknown:
        raise AnswerError(f"{what.capitalize()} uses names not in the problem: {', '.join(unknown)}.", _hint(names))
    local = {n: sp.Symbol(n) for n in names}
    local.update({f: getattr(sp, f) for f in FUNCTIONS})
    local.update(pi=sp.pi, E=sp.E)
    try:
        return parse_expr(text, local_dict=local, transformations=standard_transformations + (convert_xor,),
                          evaluate=False)
    except Exception as err:  # any parse failure is the student's text, not a crash
        raise AnswerError(f"{what.capitalize()} could not be read as a formula.", _hint(names)) from err


def read_expression(answer: Any, names: Sequence[str] | str, what: str = "your formula") -> Any:
    """The student's formula as a sympy expression whose symbols are plain ``Symbol(name)``.

    Parameters
    ----------
    answer : sympy.Expr or str or number
        The formula; a string is read with only ``names``, :data:`FUNCTIONS`, ``pi`` and ``E``.
    names : sequence of str or str
        The task's symbol names (a string: separated by spaces). Symbols are matched by name,
        whatever their assumptions.
    what : str
        How messages name the answer.

    Returns
    -------
    sympy.Expr

    Raises
    ------
    AnswerError
        Not an expression (an equation, a list, another type), a symbol not in ``names``, a
        function not in :data:`FUNCTIONS`, more than :data:`MAX_NODES` nodes or deeper than
        :data:`MAX_DEPTH`.

    Examples
    --------
    >>> read_expression("k*a^2/2", "k a")
    a**2*k/2
    >>> read_expression("k*x", "k a")
    Traceback (most recent call last):
    ...
    balancelab.core.errors.AnswerError: Your formula uses names not in the problem: x.
    """
    import sympy as sp

    names = tuple(names.split()) if isinstance(names, str) else tuple(names)
    if not names:
        raise ValueError("names: give at least one symbol name")
    if isinstance(answer, str):
        expr = _parse_string(answer, names, what)
    elif isinstance(answer, sp.Basic):
        expr = answer
    elif isinstance(answer, (int, float, np.integer, np.floating)) and not isinstance(answer, bool):
        expr = sp.Float(float(answer))
    else:
        raise AnswerError(f"{what.capitalize()} should be a sympy expression, got {type(answer).__name__}.",
                          _hint(names))
    if isinstance(expr, sp.Equality):
        raise AnswerError(f"{what.capitalize()} is an equation; give its right-hand side (an expression).",
                          _hint(names))
    if not isinstance(expr, sp.Expr):
        raise AnswerError(f"{what.capitalize()} is not an algebraic expression.", _hint(names))
    _check_shape(expr, what)
    extra = sorted({str(s) for s in expr.free_symbols} - set(names))
    if extra:
        raise AnswerError(f"{what.capitalize()} uses symbols not in the problem: {', '.join(extra)}.", _hint(names))
    return expr.xreplace({s: sp.Symbol(str(s)) for s in expr.free_symbols})


def _check_shape(expr, what: str) -> None:
    """Refuse an expression with too many nodes, too deep a nesting or a node the interpreter does not know."""
    stack, count = [(expr, 1)], 0
    while stack:
        node, depth = stack.pop()
        count += 1
        if count > MAX_NODES or depth > MAX_DEPTH:
            raise AnswerError(f"{what.capitalize()} is too large or too deeply nested to be checked "
                              f"(at most {MAX_NODES} terms and factors, {MAX_DEPTH} levels).",
                              "Simplify it, or write it with fewer nested parts.")
        kind = _kind(node)
        if kind is None:
            raise AnswerError(f"{what.capitalize()} uses {type(node).__name__}, which the check does not evaluate.",
                              f"Use + - * / ** and the functions {', '.join(FUNCTIONS)}.")
        stack.extend((a, depth + 1) for a in node.args)


def _kind(node) -> str | None:
    import sympy as sp

    if isinstance(node, sp.Symbol):
        return "symbol"
    if isinstance(node, sp.Number) or (node.is_Atom and node.is_number):  # also pi, E, I, oo, zoo, nan
        return "number"
    if isinstance(node, (sp.Add, sp.Mul, sp.Pow)):
        return type(node).__name__
    if isinstance(node, sp.Function) and type(node).__name__ in FUNCTIONS:
        return "function"
    return None


def evaluate(expr: Any, values: Mapping[str, np.ndarray]) -> np.ndarray:
    """The value of an expression read by :func:`read_expression` at arrays of its symbols' values.

    Parameters
    ----------
    expr : sympy.Expr
        An expression of the kinds :func:`read_expression` accepts.
    values : mapping of str to array
        Each symbol's values, by name (arrays of one shape).

    Returns
    -------
    numpy.ndarray
        Complex values (``nan`` where the expression is undefined), of the arrays' shape.

    Examples
    --------
    >>> import sympy as sp
    >>> evaluate(sp.sympify("2*sin(x)**2 + cos(2*x)"), {"x": np.array([0.1, 1.0])}).real
    array([1., 1.])
    """
    import sympy as sp

    shape = np.shape(next(iter(values.values()))) if values else ()

    def ev(node):
        kind = _kind(node)
        if kind == "symbol":
            return np.asarray(values[str(node)], dtype=complex)
        if kind == "number":
            try:
                return np.full(shape, complex(node))
            except (OverflowError, TypeError):  # a number too large for a float
                return np.full(shape, complex(np.inf, 0.0))
        args = [ev(a) for a in node.args]
        if kind == "Add":
            return np.sum(args, axis=0)
        if kind == "Mul":
            return np.prod(args, axis=0)
        if kind == "Pow":
            base, exponent = args
            if node.exp == sp.Rational(1, 2):
                return np.sqrt(base)
            return base ** exponent
        return FUNCTIONS[type(node).__name__](*args)

    with np.errstate(all="ignore"):
        return ev(expr)


def _instances(ranges: Mapping[str, tuple[float, float]], points: int, seed: int | None) -> dict[str, np.ndarray]:
    if not isinstance(points, int) or points < 3:
        raise ValueError(f"points must be an integer >= 3, got {points!r}")
    rng = np.random.default_rng(seed)
    drawn = {}
    for name, span in ranges.items():
        try:
            lo, hi = (float(v) for v in span)
        except (TypeError, ValueError):
            raise TypeError(f"ranges[{name!r}] must be a pair (low, high) of numbers, got {span!r}") from None
        if not (np.isfinite(lo) and np.isfinite(hi) and lo < hi):
            raise ValueError(f"ranges[{name!r}] must be finite with low < high, got {span!r}")
        drawn[name] = rng.uniform(lo, hi, points)
    return drawn


def equivalent(answer: Any, expected: Any, ranges: Mapping[str, tuple[float, float]], what: str = "your formula",
               *, points: int = 16, rtol: float = 1e-7, seed: int | None = None, hint: str = "") -> tuple[bool, str, str]:
    """Whether a formula equals the reference at ``points`` random instances of its symbols.

    Each symbol is drawn uniformly from its range in ``ranges``, afresh at every call unless
    ``seed`` is given (instances known in advance would let an answer be built to agree there).
    At each instance where the reference is finite, the two values must agree
    within ``rtol`` times the larger of the reference's size there and its median size over
    all instances (so a reference that crosses zero is not judged by a tolerance of zero).

    Parameters
    ----------
    answer : sympy.Expr or str or number
        The student's formula (:func:`read_expression`).
    expected : sympy.Expr
        The reference, in symbols named as in ``ranges``.
    ranges : mapping of str to (float, float)
        Every symbol of the task with its valid range (its units' values the task allows).
    what : str
        How messages name the answer.
    points : int
        Number of random instances, >= 3.
    rtol : float
        Relative tolerance, > 0.
    seed : int, optional
        Seed of the instances (default: fresh ones at every call).
    hint : str
        The hint given with a wrong answer.

    Returns
    -------
    (bool, str, str)
        ``(correct, message, hint)``; the message never shows the reference.

    Raises
    ------
    AnswerError
        If the answer is malformed (:func:`read_expression`).

    Examples
    --------
    >>> import sympy as sp
    >>> k, a, t = sp.symbols("k a theta")
    >>> spans = {"k": (10, 500), "a": (0.05, 0.5), "theta": (-3, 3)}
    >>> equivalent(k * a * sp.sin(2 * t), 2 * k * a * sp.sin(t) * sp.cos(t), spans)[0]
    True
    >>> equivalent("-k*a*sin(2*theta)", k * a * sp.sin(2 * t), spans)[1]
    'Your formula has the wrong sign.'
    """
    if not (isinstance(rtol, float) and 0 < rtol < 1):
        raise ValueError(f"rtol must be a float in (0, 1), got {rtol!r}")
    found = _compare(answer, expected, ranges, what, points, rtol, seed)
    if found == "":
        return True, f"{what.capitalize()} is equivalent to the expected formula.", ""
    default = {"has the wrong sign": "Check the direction of each term.",
               "is off by a constant factor": "Check the numerical factors."}.get(found, "")
    return False, f"{what.capitalize()} {found}.", hint or default


def _compare(answer, expected, ranges, what: str, points: int, rtol: float, seed: int | None) -> str:
    """``""`` when equivalent, else what is wrong (``"has the wrong sign"``, ...)."""
    names = tuple(ranges)
    mine = read_expression(answer, names, what)
    ref = read_expression(expected, names, "the reference")
    if not mine.free_symbols and ref.free_symbols:
        return "is a number: the task asks for a formula in its symbols"
    at = _instances(ranges, points, seed)
    e, a = evaluate(ref, at), evaluate(mine, at)
    valid = np.isfinite(e)
    if valid.sum() < max(3, points // 2):
        raise ValueError("ranges: the reference is undefined at most instances; narrow the symbols' ranges")
    e, a = e[valid], a[valid]
    scale = np.maximum(np.abs(e), np.median(np.abs(e)))
    scale = np.where(scale > 0, scale, 1e-300)
    close = np.isfinite(a) & (np.abs(a - e) <= rtol * scale)
    if close.all():
        return ""
    if np.all(np.isfinite(a) & (np.abs(a + e) <= rtol * scale)):
        return "has the wrong sign"
    with np.errstate(all="ignore"):
        ratio = a / np.where(e == 0, np.nan, e)
    if np.all(np.isfinite(ratio)) and np.allclose(ratio, ratio[0], rtol=1e-6):
        return "is off by a constant factor"
    return (f"is not equivalent to the expected formula: it differs at {int((~close).sum())} of {len(e)} "
            "random instances of the symbols")


def equivalent_parts(answer: Any, expected: Mapping[str, Any], ranges: Mapping[str, tuple[float, float]],
                     what: str = "your answer", **options: Any) -> tuple[bool, str, str]:
    """:func:`equivalent` for an answer of several named formulas (a dict, or a tuple in the keys' order).

    Parameters
    ----------
    answer : dict or tuple or list
        The student's formulas, by name (the keys of ``expected``) or in their order.
    expected : mapping of str to sympy.Expr
        The reference formulas, by name.
    ranges, what, **options
        As in :func:`equivalent`.

    Returns
    -------
    (bool, str, str)
        Correct when every part is; the message says which parts are not.

    Examples
    --------
    >>> import sympy as sp
    >>> k, a = sp.symbols("k a")
    >>> ok, message, _ = equivalent_parts((k * a, "a"), {"F": a * k, "s": 2 * a}, {"k": (1, 9), "a": (1, 9)})
    >>> ok, message
    (False, 'Your F is equivalent. Your s is off by a constant factor.')
    """
    import sympy as sp

    keys = tuple(expected)
    if isinstance(answer, sp.Tuple):  # sympify of a tuple
        answer = tuple(answer)
    if isinstance(answer, dict):
        missing = [k for k in keys if k not in answer]
        if missing:
            raise AnswerError(f"{what.capitalize()} has no {', '.join(missing)}.",
                              f"Give a dict with the keys {', '.join(keys)} (or a tuple in that order).")
        parts = [answer[k] for k in keys]
    elif isinstance(answer, (tuple, list)) and not isinstance(answer, sp.Basic):
        if len(answer) != len(keys):
            raise AnswerError(f"{what.capitalize()} should have {len(keys)} formulas ({', '.join(keys)}), "
                              f"got {len(answer)}.", f"Give them as a tuple ({', '.join(keys)}).")
        parts = list(answer)
    else:
        raise AnswerError(f"{what.capitalize()} should be a tuple ({', '.join(keys)}) of formulas.",
                          f"Give them as a tuple ({', '.join(keys)}) or a dict with those keys.")
    options.setdefault("points", 16)
    options.setdefault("rtol", 1e-7)
    options.setdefault("seed", None)
    hint = options.pop("hint", "")
    found = [_compare(p, expected[k], ranges, f"your {k}", options["points"], options["rtol"], options["seed"])
             for k, p in zip(keys, parts)]
    if not any(found):
        return True, f"{what.capitalize()}: every formula is equivalent to the expected one.", ""
    notes = " ".join(f"Your {k} {f or 'is equivalent'}." for k, f in zip(keys, found))
    return False, notes, hint or "Derive each formula from the potential energy, one coefficient at a time."
