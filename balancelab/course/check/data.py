"""Answers as plain data: what leaves a student's kernel and what a check judges.

Every answer is turned into JSON-able data by :func:`encode_answer` (numbers, strings,
tuples, lists, dicts, sympy expressions as ``srepr`` text, a :class:`~balancelab.Design` as
its bodies' joints, loads and springs) and read back by :func:`decode_answer`. The check a
student runs in the notebook (:func:`~.core.check`) judges ``decode_answer(encode_answer(x))``,
and so does the trusted grader on the data exported from the student's kernel: both run the
same judge on the same data, and nothing else of the kernel (no object, no method, no
verdict) reaches the grade.

:func:`encode_answer` is self-contained (it imports only inside) so that the grader can send
its source text into the student's kernel. :func:`decode_answer` never evaluates code: sympy
text is parsed by a whitelist of sympy names (:func:`parse_srepr`), and a design stays plain
data (:class:`DesignData`) that a task's judge rebuilds on its own trusted mechanism.
"""
from __future__ import annotations

import ast
import math
from dataclasses import dataclass

__all__ = ["encode_answer", "decode_answer", "parse_srepr", "DesignData", "Unreadable", "SYMPY_NAMES"]

#: The sympy names an ``srepr`` text may use (anything else is refused).
SYMPY_NAMES = frozenset("""Symbol Integer Rational Float Add Mul Pow sin cos tan cot sec csc asin acos atan
atan2 sinh cosh tanh exp log sqrt Abs sign pi E I oo nan zoo Equality Tuple re im Half One Zero NegativeOne
Infinity NegativeInfinity NaN ComplexInfinity ImaginaryUnit Exp1 Pi""".split())
_MAX_NODES = 5000
_MAX_INT = 10 ** 12
_MAX_POWER = 1000


@dataclass(frozen=True)
class Unreadable:
    """An answer that plain data cannot carry (an object of an unknown type, too deep, too large).

    Examples
    --------
    >>> Unreadable("Verdict").what
    'Verdict'
    """

    what: str


@dataclass(frozen=True)
class DesignData:
    """A design as plain data: its mechanism's kind and joints, its loads and springs.

    Attributes
    ----------
    cls : str
        The class the answer had in the notebook (``"Design"`` unless a subclass).
    mechanism : str
        Class name of its kinematics.
    joints : tuple
        ``(body_i, (x, y), body_j, (x, y))`` per joint (m).
    loads : tuple
        ``(body, (x, y), (f_x, f_y), name, kind)`` per load (m, N).
    springs : tuple
        ``(k, free_length, (body, (x, y)), (body, (x, y)), name)`` per spring (N/m, m).

    Examples
    --------
    >>> DesignData("Design", "TreeKinematics", (), (), ()).cls
    'Design'
    """

    cls: str
    mechanism: str
    joints: tuple
    loads: tuple
    springs: tuple


def encode_answer(x, _depth=0):
    """Plain JSON-able data for an answer (self-contained: the grader sends its source to the kernel).

    Parameters
    ----------
    x : object
        The answer.

    Returns
    -------
    dict
        One tag per kind: ``num``, ``str``, ``bool``, ``none``, ``tuple``, ``list``, ``dict``,
        ``sympy``, ``design``, ``missing`` (``...``) or ``other`` (anything else).

    Examples
    --------
    >>> encode_answer((0.5, "kg"))
    {'tuple': [{'num': '0.5'}, {'str': 'kg'}]}
    """
    import numbers
    import sys

    def num(v):
        return {"num": repr(float(v))}

    def pair(p):
        return [float(p[0]), float(p[1])]

    if _depth > 12:
        return {"other": "too deeply nested"}
    if x is None:
        return {"none": None}
    if x is Ellipsis:
        return {"missing": "..."}
    if isinstance(x, bool):
        return {"bool": bool(x)}
    if isinstance(x, str):
        return {"str": str(x)[:5000]}
    np = sys.modules.get("numpy")
    if np is not None and isinstance(x, (np.bool_,)):
        return {"bool": bool(x)}
    if isinstance(x, numbers.Real) and type(x).__module__ in ("builtins", "numpy"):
        return num(x)
    if np is not None and isinstance(x, np.ndarray):
        return encode_answer(x.tolist(), _depth + 1) if x.size <= 1000 else {"other": "a huge array"}
    sp = sys.modules.get("sympy")
    if sp is not None and isinstance(x, sp.Basic):
        return {"sympy": sp.srepr(x)[:20000]}
    if type(x) in (tuple, list):
        if len(x) > 1000:
            return {"other": "a huge sequence"}
        return {type(x).__name__: [encode_answer(v, _depth + 1) for v in x]}
    if type(x) is dict:
        if len(x) > 1000:
            return {"other": "a huge dict"}
        return {"dict": [[encode_answer(k, _depth + 1), encode_answer(v, _depth + 1)] for k, v in x.items()]}
    if any(c.__name__ == "Design" and c.__module__.startswith("balancelab.") for c in type(x).__mro__):
        try:
            return {"design": {
                "cls": type(x).__name__, "mechanism": type(x.kinematics).__name__,
                "joints": [[int(j.body_i), pair(j.point_i), int(j.body_j), pair(j.point_j)] for j in x.joints],
                "loads": [[int(ld.body), pair(ld.point), pair(ld.force), str(ld.name), str(ld.kind)]
                          for ld in x.loads],
                "springs": [[float(s.k), float(s.free_length), [int(s.a.body), pair(s.a.point)],
                             [int(s.b.body), pair(s.b.point)], str(s.name), str(s.realization)]
                            for s in x.springs]}}
        except Exception as e:  # a broken design object
            return {"other": f"a design that cannot be read ({type(e).__name__})"}
    return {"other": type(x).__name__}


def parse_srepr(text: str):
    """A sympy expression from ``srepr`` text, built without evaluating code.

    Only calls of the names in :data:`SYMPY_NAMES` with literal arguments are accepted.

    Parameters
    ----------
    text : str
        E.g. ``"Mul(Symbol('m'), Symbol('r'))"``.

    Returns
    -------
    sympy.Basic

    Raises
    ------
    ValueError
        If the text uses anything else (an attribute, an unknown name, a huge integer).

    Examples
    --------
    >>> parse_srepr("Mul(Rational(1, 2), Symbol('m', positive=True))")
    m/2
    >>> parse_srepr("__import__('os').system('ls')")
    Traceback (most recent call last):
    ...
    ValueError: not a sympy expression: Call
    """
    import sympy as sp

    if len(text) > 20000:
        raise ValueError("the expression is too large")
    tree = ast.parse(text, mode="eval")
    if sum(1 for _ in ast.walk(tree)) > _MAX_NODES:
        raise ValueError("the expression is too large")

    def build(node):
        if isinstance(node, ast.Constant) and isinstance(node.value, (int, float, str, bool)):
            if isinstance(node.value, int) and abs(node.value) > _MAX_INT:
                raise ValueError("an integer in the expression is too large")
            return node.value
        if isinstance(node, ast.UnaryOp) and isinstance(node.op, ast.USub):
            return -build(node.operand)
        if isinstance(node, ast.Name) and node.id in SYMPY_NAMES:
            return getattr(sp, node.id, None) if node.id not in ("Half", "One", "Zero", "NegativeOne") \
                else getattr(sp.S, node.id)
        if isinstance(node, ast.Tuple):
            return tuple(build(e) for e in node.elts)
        if isinstance(node, ast.Call) and isinstance(node.func, ast.Name) and node.func.id in SYMPY_NAMES:
            fn = getattr(sp, node.func.id)
            kwargs = {k.arg: build(k.value) for k in node.keywords if k.arg}
            args = [build(a) for a in node.args]
            if node.func.id == "Pow" and len(args) == 2 and getattr(args[1], "is_number", False) \
                    and abs(args[1]) > _MAX_POWER:
                raise ValueError("an exponent in the expression is too large")
            return fn(*args, **kwargs)
        raise ValueError(f"not a sympy expression: {type(node).__name__}")

    return build(tree.body)


def _decode_design(d) -> DesignData:
    def pt(p):
        x, y = (float(v) for v in p)
        if not (math.isfinite(x) and math.isfinite(y)):
            raise ValueError("a point is not finite")
        return (x, y)

    joints = tuple((int(b1), pt(p1), int(b2), pt(p2)) for b1, p1, b2, p2 in d["joints"])
    loads = tuple((int(b), pt(p), pt(f), str(n), str(k)) for b, p, f, n, k in d["loads"])
    springs = tuple((float(k), float(ell), (int(a[0]), pt(a[1])), (int(b[0]), pt(b[1])), str(name))
                    for k, ell, a, b, name, *_ in d["springs"])
    bad = [s for s in d["springs"] if len(s) > 5 and s[5] != "coil"]
    if bad:
        raise ValueError("only coil springs can be graded")
    return DesignData(str(d["cls"]), str(d["mechanism"]), joints, loads, springs)


def decode_answer(data):
    """The answer back from :func:`encode_answer`'s data (never evaluates code).

    Parameters
    ----------
    data : dict
        Plain data, e.g. parsed from the JSON a notebook exported.

    Returns
    -------
    object
        Floats, strings, tuples, lists, dicts, sympy expressions, :class:`DesignData`,
        ``...`` for a missing answer, or :class:`Unreadable`.

    Examples
    --------
    >>> decode_answer({"tuple": [{"num": "0.5"}, {"str": "kg"}]})
    (0.5, 'kg')
    >>> decode_answer({"other": "Verdict"})
    Unreadable(what='Verdict')
    """
    try:
        return _decode(data)
    except (ValueError, TypeError, KeyError, IndexError, SyntaxError, RecursionError, AttributeError) as e:
        return Unreadable(f"data that cannot be read ({type(e).__name__})")


def _decode(data):
    if not isinstance(data, dict) or len(data) != 1:
        raise ValueError("not an encoded answer")
    (tag, v), = data.items()
    if tag == "num":
        return float(v)
    if tag == "str":
        return str(v)[:5000]
    if tag == "bool":
        return bool(v)
    if tag == "none":
        return None
    if tag == "missing":
        return Ellipsis
    if tag in ("tuple", "list"):
        items = [_decode(e) for e in v]
        return tuple(items) if tag == "tuple" else items
    if tag == "dict":
        return {_decode(k): _decode(e) for k, e in v}
    if tag == "sympy":
        return parse_srepr(str(v))
    if tag == "design":
        return _decode_design(v)
    if tag == "other":
        return Unreadable(str(v)[:80])
    raise ValueError(f"unknown tag {tag!r}")
