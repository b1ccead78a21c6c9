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


# ------------------------------------------------------------- derive tasks with a personal variant

def _rates_at(formulas, values):
    return [float(sp.sympify(f).subs({sp.Symbol(n): v for n, v in values.items()})) for f in formulas]


def test_task_7_5s_reference_balances_the_librarys_arm_in_every_variant():
    """The judge's formulas, evaluated at numbers, give rates with which the library's balance report
    of lab7_own_arm says balanced; another variant's formulas do not."""
    from balancelab.course.check import lab7

    values = dict(g=9.81, m_1=1.7, p_1=0.18, l_1=0.42, m_2=0.9, p_2=0.16, m_L=0.6, l_2=0.33, a=0.22,
                  s_1=0.13, s_2=0.27, s_3=0.09, c=0.06)
    variants = [(arr, lamp) for arr in lab7.LAB7_OWN_ARRANGEMENTS for lamp in (True, False)]
    for arr, lamp in variants:
        rates = _rates_at(lab7._own_rates(arr, lamp).values(), values)
        assert all(k > 0 for k in rates)
        assert lab7.lab7_own_arm(arr, lamp, values, rates).balance_report().balanced, (arr, lamp)
        for other in variants:
            if other != (arr, lamp):
                wrong = _rates_at(lab7._own_rates(*other).values(), values)
                assert not lab7.lab7_own_arm(arr, lamp, values, wrong).balance_report().balanced, (arr, lamp, other)


def test_task_7_5s_published_formulas_fail_every_students_variant():
    from balancelab.course.check import core, data, lab7, task_numbers

    published = tuple(lab7._own_rates("above", True).values())
    assert core.check_data("7.5", data.encode_answer(published), "").correct
    seen = set()
    for sid in (f"s{i}" for i in range(40)):
        own = task_numbers("7.5", sid)
        seen.add((own["arrangement"], own["lamp"]))
        assert (own["arrangement"], own["lamp"]) != ("above", True)
        assert not core.check_data("7.5", data.encode_answer(published), sid).correct
        mine = tuple(lab7._own_rates(own["arrangement"], own["lamp"]).values())
        assert core.check_data("7.5", data.encode_answer(mine), sid).correct
    assert len(seen) == 3  # every other variant is drawn


def test_task_5_4s_reference_is_the_librarys_rates_in_every_numbering():
    import itertools

    import balancelab as bl
    from balancelab.course.check import lab5
    from balancelab.methods.lecture import fourbar_two_springs

    links = dict(crank=(0.35, 1.3, 0.14), coupler=(0.75, 2.4, 0.31), rocker=(0.55, 1.6, 0.22))  # l, m, r
    design = fourbar_two_springs(crank=0.35, coupler=0.75, rocker=0.55, masses=(1.3, 2.4, 1.6),
                                 coms=((0.14, 0.0), (0.31, 0.0), (0.22, 0.0)), b=(0.21, 0.17), c=(0.12, 0.26))
    library = [design.parameters["k2"], design.parameters["k4"]]
    for order in itertools.permutations((2, 3, 4)):
        numbering = dict(zip(lab5.LAB5_LINKS, order))
        at = dict(g=bl.G, b_A=0.21, c_A=0.12, b_B=0.17, c_B=0.26)
        for link, (length, mass, com) in links.items():
            at.update({f"l_{numbering[link]}": length, f"m_{numbering[link]}": mass, f"r_{numbering[link]}": com})
        assert _rates_at(lab5._fourbar_rates(numbering).values(), at) == pytest.approx(library, rel=1e-12)


def test_task_5_4s_chapter_numbering_fails_every_student():
    from balancelab.course.check import core, data, lab5, task_numbers

    chapter = tuple(lab5._fourbar_rates({"crank": 2, "coupler": 3, "rocker": 4}).values())
    assert core.check_data("5.4", data.encode_answer(chapter), "").correct
    for sid in (f"s{i}" for i in range(30)):
        numbering = task_numbers("5.4", sid)["numbering"]
        assert numbering != {"crank": 2, "coupler": 3, "rocker": 4}
        assert not core.check_data("5.4", data.encode_answer(chapter), sid).correct
        assert core.check_data("5.4", data.encode_answer(tuple(lab5._fourbar_rates(numbering).values())), sid).correct
    with pytest.raises(ValueError, match="numbering"):
        lab5.lab5_symbol_ranges({"crank": 2, "coupler": 2, "rocker": 4})


def _scissors_energy(n, j, k1, k2, values, theta):
    """The energy of task 6.4's lift from its points, computed here without the judge's formulas."""
    import numpy as np

    g, a, l10, ma, M = (values[s] for s in ("g", "a", "l_10", "m_a", "M"))
    x, y = a * np.cos(theta), a * np.sin(theta)  # one arm spans (x, y); stage i sits on [(i-1) y, i y]
    crossings = [(x / 2, (i - 0.5) * y) for i in range(1, n + 1)]
    energy = g * (sum(2 * ma * cy for _, cy in crossings) + M * n * y)
    (x1, y1), (xj, yj) = crossings[0], crossings[j - 1]
    energy += k1 * (np.hypot(xj - x1, yj - y1) - l10) ** 2 / 2 + k2 * (np.hypot(x, 0.0)) ** 2 / 2
    return energy


def test_task_6_4s_reference_makes_every_variants_energy_constant():
    import numpy as np

    import balancelab as bl
    from balancelab.course.check import lab6
    from balancelab.methods.singh import scissors_lift

    values = dict(g=bl.G, a=0.45, l_10=0.2, m_a=1.3, M=7.0)
    theta = np.linspace(0.3, 1.2, 25)
    for n, j in [(2, 2), (3, 2), (3, 3), (4, 2), (4, 3), (4, 4)]:
        k1, k2 = _rates_at(lab6._stage_rates(n, j).values(), values)
        energy = _scissors_energy(n, j, k1, k2, values, theta)
        assert np.ptp(energy) < 1e-9 * np.abs(energy).max(), (n, j)
        assert np.ptp(_scissors_energy(n, j, 1.1 * k1, k2, values, theta)) > 1e-3 * np.abs(energy).max()
    # Singh's lift, slider masses near zero, is the published variant
    singh = scissors_lift(length=0.45, arm_mass=1.3, slider_mass=1e-12, platform_mass=3.0, payload_mass=4.0,
                          free_length=0.2)
    assert _rates_at(lab6._stage_rates(2, 2).values(), values) == pytest.approx(
        [singh.parameters["k1"], singh.parameters["k2"]], rel=1e-9)


def test_task_6_4s_published_formulas_fail_every_student():
    from balancelab.course.check import core, data, lab6, task_numbers

    singh = tuple(lab6._stage_rates(2, 2).values())
    assert core.check_data("6.4", data.encode_answer(singh), "").correct
    for sid in (f"s{i}" for i in range(30)):
        lift = task_numbers("6.4", sid)
        assert (lift["stages"], lift["upper"]) != (2, 2)
        assert not core.check_data("6.4", data.encode_answer(singh), sid).correct
        mine = tuple(lab6._stage_rates(lift["stages"], lift["upper"]).values())
        assert core.check_data("6.4", data.encode_answer(mine), sid).correct


def test_task_3_4s_reference_is_the_librarys_torque_in_every_variant():
    """The published variant is the library's generalized force of the lever built with a free length;
    the vertical convention is the same lever turned (theta -> pi/2 - theta), the holding torque its negative."""
    import numpy as np

    import balancelab as bl
    from balancelab.course.check import lab2_lever, lab3

    m, r, b, c, l0 = 1.7, 0.45, 0.32, 0.18, 0.07
    lever = lab2_lever(m * bl.G * r / (b * c), (c, 0.0), (0.0, b), W=m * bl.G, l=r, free_length=l0)
    angles = np.linspace(-1.1, 1.1, 9)
    library = lever.generalized_force(angles[:, None])[..., 0].ravel()  # dV/dtheta from the horizontal
    at = dict(m=m, g=bl.G, r=r, b=b, c=c, l_0=l0)

    def reference(angle, torque, t):
        expr = lab3._free_length_torque(angle, torque)
        return float(expr.subs({sp.Symbol(n): v for n, v in {**at, "theta": t}.items()}))

    assert [reference("horizontal", "dV/dtheta", t) for t in angles] == pytest.approx(library, rel=1e-6)
    assert [reference("horizontal", "holding", t) for t in angles] == pytest.approx(-library, rel=1e-6)
    # phi from the upward vertical, clockwise, is pi/2 - theta: dV/dphi = -dV/dtheta
    assert [reference("vertical", "dV/dtheta", np.pi / 2 - t) for t in angles] == pytest.approx(-library, rel=1e-6)
    assert [reference("vertical", "holding", np.pi / 2 - t) for t in angles] == pytest.approx(library, rel=1e-6)


def test_task_3_4s_published_formula_fails_every_student():
    from balancelab.course.check import core, data, lab3, task_numbers

    published = lab3._free_length_torque("horizontal", "dV/dtheta")
    assert core.check_data("3.4", data.encode_answer(published), "").correct
    for sid in (f"s{i}" for i in range(30)):
        v = task_numbers("3.4", sid)
        assert not core.check_data("3.4", data.encode_answer(published), sid).correct
        assert core.check_data("3.4", data.encode_answer(lab3._free_length_torque(v["angle"], v["torque"])), sid).correct


@pytest.mark.parametrize("tid", ["3.4", "5.4", "6.4", "7.5"])
def test_the_variant_judges_are_quick_on_right_wrong_and_hostile_answers(tid):
    """The grader caps a judge in a child process; these judges stay far below the cap by themselves."""
    from balancelab.course.check import core, data

    parts = {"3.4": 1, "5.4": 2, "6.4": 2, "7.5": 3}[tid]
    huge = sp.Add(*[sp.Symbol("g") ** i for i in range(550)])
    for answer in ("g", sp.Integer(3), huge, "9**9**9"):
        encoded = data.encode_answer(answer if parts == 1 else (answer,) * parts)
        start = time.perf_counter()
        assert not core.check_data(tid, encoded).correct
        assert time.perf_counter() - start < 3.0, (tid, str(answer)[:20])
