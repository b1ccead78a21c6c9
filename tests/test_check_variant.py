"""Derived formulas judged by equivalence on random instances (balancelab.course.check.variant)."""
import time

import pytest
import sympy as sp
from hypothesis import given, settings
from hypothesis import strategies as st

from balancelab.core.errors import AnswerError
from balancelab.course.check.variant import MAX_DEPTH, equivalent, equivalent_parts, read_expression

k, a, b, t = sp.symbols("k a b theta")
RANGES = {"k": (10.0, 500.0), "a": (0.05, 0.5), "b": (0.05, 0.5), "theta": (-3.0, 3.0)}

coefficient = st.integers(-6, 6).filter(lambda n: n != 0)
# the building blocks of a balancing condition: products of rates, lengths and trig functions of the angle
monomial = st.sampled_from([k * a, k * b, a * b, k * a * b, a ** 2, k * b ** 2, a / b, k / (a + b)])
trig = st.sampled_from([sp.Integer(1), sp.sin(t), sp.cos(t), sp.sin(t) ** 2, sp.sin(t) * sp.cos(t), sp.cos(2 * t)])
term = st.tuples(coefficient, monomial, trig).map(lambda c: c[0] * c[1] * c[2])
formula = st.lists(term, min_size=1, max_size=4).map(lambda ts: sp.Add(*ts)).filter(lambda e: e != 0)


@settings(max_examples=15, deadline=None)
@given(formula)
def test_equivalent_forms_pass(expr):
    for form in (sp.expand(expr), sp.factor(expr), sp.expand_trig(expr), expr.rewrite(sp.exp),
                 sp.trigsimp(expr), sp.together(expr)):
        assert equivalent(form, expr, RANGES)[0], form
    assert equivalent(str(sp.expand(expr)), expr, RANGES)[0]  # as text too


@settings(max_examples=15, deadline=None)
@given(formula, term)
def test_wrong_sign_and_a_missing_or_extra_term_fail(expr, extra):
    ok, message, _ = equivalent(-expr, expr, RANGES)
    assert not ok and "wrong sign" in message
    assert not equivalent(2 * expr, expr, RANGES)[0]
    if sp.simplify(extra) != 0 and sp.simplify(expr + extra) != 0:
        assert not equivalent(expr + extra, expr, RANGES)[0]
        assert not equivalent(expr, expr + extra, RANGES)[0]  # the reference's term missing


def test_a_reference_that_crosses_zero_is_judged_on_its_typical_size():
    # k a (sin theta - sin 1): zero at theta = 1; round-off in another form must not fail there
    expr = k * a * (sp.sin(t) - sp.sin(1))
    form = k * a * 2 * sp.cos((t + 1) / 2) * sp.sin((t - 1) / 2)
    assert equivalent(form, expr, RANGES)[0]


@pytest.mark.parametrize("answer, words", [
    (sp.Eq(k, a), "equation"),
    ([k, a], "should be a sympy expression"),
    (k * sp.Symbol("x"), "symbols not in the problem: x"),
    ("k*x", "names not in the problem: x"),
    ("__import__('os').system('true')", "could not be read"),
    ("k.func", "could not be read"),
    (sp.S.true, "not an algebraic expression"),
    (sp.Matrix([k]), "should be a sympy expression"),
    (sp.Function("f")(k), "which the check does not evaluate"),
    (sp.Integral(k, a), "which the check does not evaluate"),
    ("k" * 3000, "too long"),
])
def test_malformed_answers_are_refused_kindly(answer, words):
    with pytest.raises(AnswerError, match=words):
        equivalent(answer, k * a, RANGES)


def test_huge_or_deep_answers_are_refused_quickly():
    deep = k
    for _ in range(MAX_DEPTH + 5):
        deep = sp.sin(deep)
    wide = sp.Add(*[k * a ** i for i in range(700)])
    for answer in (deep, wide):
        start = time.perf_counter()
        with pytest.raises(AnswerError, match="too large or too deeply nested"):
            read_expression(answer, "k a b theta")
        assert time.perf_counter() - start < 1.0
    start = time.perf_counter()
    assert not equivalent("9**9**9*k", k, RANGES)[0]  # not evaluated symbolically: no hang
    assert not equivalent(sp.Pow(k, 10 ** 6, evaluate=False), k, RANGES)[0]
    assert time.perf_counter() - start < 2.0


def test_symbols_are_matched_by_name_whatever_their_assumptions():
    kp, ap = sp.symbols("k a", positive=True)
    assert equivalent(kp * ap, k * a, RANGES)[0]


def test_bad_ranges_and_options_raise_naming_the_parameter():
    with pytest.raises(ValueError, match=r"ranges\['k'\]"):
        equivalent(k, k, {"k": (1.0, 1.0)})
    with pytest.raises(TypeError, match=r"ranges\['k'\]"):
        equivalent(k, k, {"k": "wide"})
    with pytest.raises(ValueError, match="points"):
        equivalent(k, k, {"k": (1.0, 2.0)}, points=2)
    with pytest.raises(ValueError, match="rtol"):
        equivalent(k, k, {"k": (1.0, 2.0)}, rtol=0.0)
    with pytest.raises(ValueError, match="undefined"):
        equivalent(k, sp.zoo * k, {"k": (1.0, 2.0)})


def test_several_formulas_by_name_or_in_order():
    expected = {"k1": k * a, "k2": k * b}
    assert equivalent_parts({"k2": b * k, "k1": a * k}, expected, RANGES)[0]
    ok, message, _ = equivalent_parts((a * k, -b * k), expected, RANGES)
    assert not ok and message == "Your k1 is equivalent. Your k2 has the wrong sign."
    with pytest.raises(AnswerError, match="has no k2"):
        equivalent_parts({"k1": k}, expected, RANGES)
    with pytest.raises(AnswerError, match="should have 2 formulas"):
        equivalent_parts((k,), expected, RANGES)
    with pytest.raises(AnswerError, match="should be a tuple"):
        equivalent_parts(k, expected, RANGES)
