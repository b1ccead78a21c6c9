"""Answers written to attack the derive checks (an outside student's attack, issue 18/21).

A formula given as text is read by a whitelist and never run; numbers too large for a float and
answers nested too deep get a verdict, not an exception; and the instances an answer is compared
at are drawn afresh, so an answer built to agree with the reference at instances seen once fails.
"""
from __future__ import annotations

import numpy as np
import pytest
import sympy as sp

from balancelab.course.check import check, set_student
from balancelab.course.check.variant import equivalent

DERIVE = ["1.2", "3.4", "4.5", "5.4", "6.4", "7.5", "8.4", "9.3"]


@pytest.fixture(autouse=True)
def _student():
    set_student("s123")
    yield
    set_student("")


def _payloads(marker):
    return [f"__import__('os').system('touch {marker}')",
            f"open('{marker}', 'w').write('x')",
            f"m + (lambda: __import__('os').system('touch {marker}'))()",
            f"exec(\"open('{marker}','w')\")",
            "().__class__.__bases__[0].__subclasses__()"]


@pytest.mark.parametrize("tid", DERIVE + ["2.2"])
def test_a_formula_written_as_text_is_never_run(tid, tmp_path):
    marker = tmp_path / "ran"
    for text in _payloads(marker):
        answer = (text, text) if tid == "2.2" else text
        verdict = check(tid, answer)
        assert not verdict.correct
        assert not marker.exists(), f"task {tid} ran the answer's text {text!r}"


@pytest.mark.parametrize("tid", DERIVE)
def test_numbers_too_large_for_a_float_get_a_verdict(tid):
    verdict = check(tid, 10 ** 400)
    assert not verdict.correct and verdict.message


def test_an_answer_built_to_agree_at_known_instances_fails_with_fresh_ones():
    k, a = sp.symbols("k a")
    ranges = {"k": (10.0, 500.0), "a": (0.05, 0.5)}
    reference = k * a ** 2 / 2
    seen = np.random.default_rng(0)
    ks = seen.uniform(*ranges["k"], 16)  # the instances a fixed seed would use (k is drawn first)
    forged = reference + sp.Mul(*[(k - float(v)) for v in ks])
    assert equivalent(forged, reference, ranges, seed=0)[0]  # agrees where it was built to
    assert not equivalent(forged, reference, ranges)[0]      # not at fresh instances
    assert equivalent(sp.expand(2 * reference) / 2, reference, ranges)[0]  # a true identity always passes


def test_a_huge_power_is_judged_not_simplified():
    verdict = check("1.2", "(m + r + m_l + m_c)**300/m_c")
    assert not verdict.correct
