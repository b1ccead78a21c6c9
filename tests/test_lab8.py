"""Lab 8's formative checks judge real springs by physics, never raise, and never reveal answers."""
from __future__ import annotations

import pytest

from balancelab.course.check import lab8
from balancelab.methods.practice import selection, tolerance


@pytest.fixture(scope="module")
def good():
    arm = lab8.lab8_arm()
    strokes = dict(zip(("k1", "k2"), selection.spring_strokes(arm, 41)))
    out = {}
    for s in arm.springs:
        real = selection.select_spring(s.k, strokes[s.name]).spring
        out[s.name] = {"d": real.wire_diameter, "D": real.coil_diameter, "Na": real.active_coils,
                       "F_i": real.initial_tension}
    return out


def test_a_selected_pair_of_springs_passes_and_its_residual_is_the_designs(good):
    verdict = lab8.check_spring_choice(good)
    assert verdict.correct and verdict.task == "8.1"
    built = lab8.built_arm(good)
    assert [s.k for s in built.springs] == [lab8.real_springs(good)[n].k for n in ("k1", "k2")]


def test_wrong_springs_are_refused_with_the_reason(good):
    soft = {**good, "k2": {**good["k2"], "Na": good["k2"]["Na"] * 1.5}}      # a third softer: over budget
    v = lab8.check_spring_choice(soft)
    assert not v.correct and "budget" in v.message
    thin = {**good, "k1": {"d": 0.8e-3, "D": 8e-3, "Na": 3, "F_i": 0.5}}
    v = lab8.check_spring_choice(thin)
    assert not v.correct and "k1" in v.message
    slack = {**good, "k1": {**good["k1"], "F_i": 100.0}}
    assert "initial tension" in lab8.check_spring_choice(slack).message


@pytest.mark.parametrize("bad", [None, {"k1": 1}, {"k1": {"d": "x"}, "k2": {}}, {"k1": {"d": -1, "D": 1, "Na": 1, "F_i": 0},
                                                                                 "k2": {"d": 1, "D": 1, "Na": 1, "F_i": 0}}])
def test_malformed_answers_give_a_verdict_not_a_traceback(bad):
    v = lab8.check_spring_choice(bad)
    assert not v.correct and v.hint


def test_tolerance_study_accepts_a_monte_carlo_of_the_students_springs(good):
    built = lab8.built_arm(good)
    mine = tolerance.monte_carlo(built, lab8.LAB8_TOLERANCES, n=4000, grid=15, seed=123).quantile(0.95)
    assert lab8.check_tolerance_study(good, mine).correct
    assert not lab8.check_tolerance_study(good, 2 * mine).correct
    assert not lab8.check_tolerance_study(good, "a lot").correct
    assert not lab8.check_tolerance_study(good, float("nan")).correct
