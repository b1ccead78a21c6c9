"""Long SymPy results set over lines that fit a phone (balancelab.viz.formula)."""
from __future__ import annotations

import re

import pytest
import sympy as sp

from balancelab.viz.formula import equation_lines, latex_lines, solution_lines, visible_width


def _lines(tex: str) -> list[str]:
    body = tex.removeprefix(r"\begin{aligned}").removesuffix(r"\end{aligned}")
    return body.split("\\\\\n")


@pytest.mark.parametrize("n, width", [(3, 20), (12, 20), (25, 36), (40, 12)])
def test_every_line_fits_and_every_term_is_kept(n, width):
    xs = sp.symbols(f"x_1:{n + 1}")
    expr = sum((-1) ** i * (i + 2) * x**2 for i, x in enumerate(xs))
    lines = _lines(equation_lines("V", expr, width=width).data)
    for line in lines:
        assert visible_width(line) <= width + 1, line   # +1: the "&=" sign of the first line
    shown = " ".join(lines)
    assert sorted(re.findall(r"x_\{(\d+)\}", shown), key=int) == [str(i) for i in range(1, n + 1)]
    # the signs survive: as many minus signs as negative terms
    assert shown.count("- ") == sum(1 for i in range(n) if i % 2)


def test_a_product_with_a_long_sum_inside_is_opened_over_lines():
    a, b, c, d, e, k = sp.symbols("a b c d e k")
    expr = k / 2 * (a**2 + b**2 + c**2 + d**2 + e**2) + a
    lines = _lines(equation_lines("V", expr, width=14).data)
    assert len(lines) >= 2 and all(visible_width(line) <= 15 for line in lines), lines
    assert any(r"\Big(" in line for line in lines) and lines[-1].rstrip().endswith(r"\Big)")
    assert sum(line.count(r"\Big(") for line in lines) == sum(line.count(r"\Big)") for line in lines) == 1


def test_short_results_stay_on_one_line_and_solutions_are_one_per_unknown():
    x, y = sp.symbols("x y")
    assert "\\\\" not in equation_lines("y", x + 1).data
    shown = solution_lines({x: 2 * y, y: sp.Integer(3)})
    assert [s.data for s in shown] == [r"\begin{aligned}x &= 2 y\end{aligned}", r"\begin{aligned}y &= 3\end{aligned}"]


def test_bad_input_is_refused_with_its_name():
    with pytest.raises(ValueError, match="width"):
        latex_lines("V", ["a"], width=0)
    with pytest.raises(TypeError, match="solution"):
        solution_lines([1, 2])
