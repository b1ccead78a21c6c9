"""Long SymPy results shown as formulas that fit a phone's column.

MathJax 3 cannot break a line, and a SymPy sum of a dozen terms set on one line is 500 to
2000 px wide. :func:`equation_lines` sets ``lhs = rhs`` as an ``aligned`` display that starts a
new line (``&\\quad + ...``) before a term of a sum when the line would pass ``width``
characters of *visible* text (an estimate: TeX commands and braces are not counted, a Greek
letter or a function name counts as what it prints). A ``dict`` of results (what
``sympy.solve`` returns) is shown one equation per line (:func:`solution_lines`).

Layer: viz; imports sympy and IPython only.
"""
from __future__ import annotations

import re

__all__ = ["equation_lines", "latex_lines", "solution_lines", "visible_width"]

_COMMAND = re.compile(r"\\([a-zA-Z]+)")
#: TeX commands that print nothing themselves (layout and font switches).
_SILENT = {"left", "right", "frac", "mathrm", "operatorname", "mathbf", "quad", "qquad", "cdot",
           "limits", "displaystyle", "text", "mathit", "tfrac", "dfrac"}
#: Width of one line of a phone's display formula, in visible characters at the text size.
PHONE_WIDTH = 36


def visible_width(tex: str) -> int:
    """Estimated number of printed characters of a TeX string.

    Parameters
    ----------
    tex : str
        LaTeX source of (part of) a formula.

    Returns
    -------
    int
        Characters that print: a command such as ``\\theta`` counts 1, ``\\sin`` counts 3,
        layout commands, braces, ``^`` and ``_`` count 0.

    Examples
    --------
    >>> visible_width(r"\\frac{a_{x}}{b} + \\sin{\\left(\\theta \\right)}")   # a x b + sin ( θ )
    10
    """
    def command(m: re.Match) -> str:
        name = m.group(1)
        if name in _SILENT:
            return ""
        return "x" * (3 if name in ("sin", "cos", "tan", "log", "exp") else 1)

    text = _COMMAND.sub(command, tex)
    return len(re.sub(r"[{}^_\s&\\]", "", text))


def latex_lines(lhs: str, terms: list[str], width: int = PHONE_WIDTH) -> str:
    """``lhs = t1 + t2 ...`` as an ``aligned`` block, a new line before a term that would pass ``width``.

    Parameters
    ----------
    lhs : str
        LaTeX of the left-hand side.
    terms : list of str
        LaTeX of the terms of the right-hand side, each with its sign first when negative.
    width : int
        Visible characters per line (:func:`visible_width`).

    Returns
    -------
    str
        LaTeX of the whole block.

    Examples
    --------
    >>> print(latex_lines("V", ["a", "- b", "c"], width=6))
    \\begin{aligned}V &= a - b\\\\
    &\\quad + c\\end{aligned}
    """
    if width < 1:
        raise ValueError(f"width must be a positive number of characters, got {width!r}")
    lines, line, used = [], "", visible_width(lhs) + 1
    for term in terms:
        signed = term if term.startswith("-") else f"+ {term}"
        size = visible_width(signed)
        if line and used + size > width:
            lines.append(line)
            line, used = "", 2
        if not line:
            piece = signed[1:].lstrip() if (not lines and signed.startswith("+")) else signed
            line = f"{lhs} &= {piece}" if not lines else f"&\\quad {signed}"
        else:
            line += f" {signed}"
        used += size
    lines.append(line)
    return r"\begin{aligned}" + "\\\\\n".join(lines) + r"\end{aligned}"


def _opened(term, width: int) -> list[str]:
    """A product too wide for a line with one sum inside, as ``outside \\Big( t1``, ``t2``, ... ``tn \\Big)``."""
    import sympy as sp

    sums = [f for f in sp.Mul.make_args(term) if isinstance(f, sp.Add)]
    if len(sums) != 1 or visible_width(sp.latex(term)) <= width:
        return [sp.latex(term)]
    outside = sp.Mul(*[f for f in sp.Mul.make_args(term) if f is not sums[0]])
    inner = _terms(sums[0], width)
    head = "" if outside == 1 else sp.latex(outside) + " "
    first = inner[0][2:] if inner[0].startswith("+ ") else inner[0]
    return [f"{head}\\Big( {first}", *inner[1:-1], f"{inner[-1]} \\Big)"] if len(inner) > 1 \
        else [f"{head}\\Big( {first} \\Big)"]


def _terms(expr, width: int = PHONE_WIDTH) -> list[str]:
    import sympy as sp

    parts = sp.Add.make_args(expr) if isinstance(expr, sp.Add) else (expr,)
    out = []
    for part in sp.Add(*parts, evaluate=False).as_ordered_terms() if len(parts) > 1 else parts:
        coeff, _ = part.as_coeff_Mul()
        negative = coeff.is_negative
        pieces = _opened(-part if negative else part, width)
        pieces[0] = ("- " if negative else "") + pieces[0]
        out += pieces
    return out


def equation_lines(lhs, rhs, width: int = PHONE_WIDTH):
    """``lhs = rhs`` for the page, over as many lines as the sum's terms need.

    Parameters
    ----------
    lhs : sympy.Basic or str
        The left-hand side (a str is taken as LaTeX).
    rhs : sympy.Basic
        The right-hand side; a sum is broken between its terms.
    width : int
        Visible characters per line (default :data:`PHONE_WIDTH`, a 390 px phone).

    Returns
    -------
    IPython.display.Math

    Examples
    --------
    >>> import sympy as sp
    >>> a, b, c = sp.symbols("a b c")
    >>> shown = equation_lines("V", a**2 + b**2 - c**2, width=8)
    >>> shown.data.count(r"\\\\"), shown.data.startswith(r"\\begin{aligned}V &= a^{2}")
    (1, True)
    """
    import sympy as sp
    from IPython.display import Math

    left = lhs if isinstance(lhs, str) else sp.latex(lhs)
    return Math(latex_lines(left, _terms(sp.sympify(rhs), width), width))


def solution_lines(solution: dict, width: int = PHONE_WIDTH) -> list:
    """A ``sympy.solve`` result (symbol to value) as one :func:`equation_lines` per unknown.

    Parameters
    ----------
    solution : dict
        Unknown to its value.
    width : int
        Visible characters per line.

    Returns
    -------
    list of IPython.display.Math

    Examples
    --------
    >>> import sympy as sp
    >>> x, y = sp.symbols("x y")
    >>> [m.data for m in solution_lines({x: 2 * y, y: 3})]
    ['\\\\begin{aligned}x &= 2 y\\\\end{aligned}', '\\\\begin{aligned}y &= 3\\\\end{aligned}']
    """
    if not isinstance(solution, dict):
        raise TypeError(f"solution must be a dict of unknown to value, got {type(solution).__name__}")
    return [equation_lines(k, v, width) for k, v in solution.items()]
