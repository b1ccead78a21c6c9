"""Lab 8's checks judge real springs by physics, from plain data, never raise, and never reveal answers."""
from __future__ import annotations

import numpy as np
import pytest

import balancelab as bl
from balancelab.course.check import check, check_data, encode_answer, lab8, tasks
from balancelab.methods.practice import forces, tolerance
from conftest import lab8_reference_springs


@pytest.fixture(scope="module")
def good():
    return lab8_reference_springs()


def test_lab8_is_registered():
    lab = tasks("lab8")
    assert [t.id for t in lab] == ["8.1", "8.2", "8.3", "8.4"]
    assert any(t.kind == "design" for t in lab)
    for t in lab:
        v = check(t.id, None)
        assert not v.correct and v.score == 0 and v.hint


def test_a_selected_pair_of_springs_passes_and_its_residual_is_the_designs(good):
    verdict = check("8.1", good)
    assert verdict.correct and verdict.task == "8.1" and verdict.score == verdict.points == 2
    assert check_data("8.1", encode_answer(good)) == verdict  # what the grader sees
    built = lab8.built_arm(good)
    assert [s.k for s in built.springs] == [lab8.real_springs(good)[n].k for n in ("k1", "k2")]
    # units in strings are understood
    with_units = {**good, "k1": {**good["k1"], "d": f"{good['k1']['d'] * 1000} mm"}}
    assert check("8.1", with_units).correct


def test_wrong_springs_are_refused_with_the_reason(good):
    soft = {**good, "k2": {**good["k2"], "Na": good["k2"]["Na"] * 1.5}}      # a third softer: over budget
    v = check("8.1", soft)
    assert not v.correct and "budget" in v.message
    thin = {**good, "k1": {"d": 0.8e-3, "D": 8e-3, "Na": 3, "F_i": 0.5}}
    v = check("8.1", thin)
    assert not v.correct and "k1" in v.message
    slack = {**good, "k1": {**good["k1"], "F_i": 100.0}}
    assert "initial tension" in check("8.1", slack).message


@pytest.mark.parametrize("bad", [None, {"k1": 1}, {"k1": {"d": "x"}, "k2": {}}, {"k1": {"d": -1, "D": 1, "Na": 1, "F_i": 0},
                                                                                 "k2": {"d": 1, "D": 1, "Na": 1, "F_i": 0}}])
def test_malformed_answers_give_a_verdict_not_a_traceback(bad):
    for tid, answer in (("8.1", bad), ("8.2", {"springs": bad, "quantile": 0.3})):
        v = check(tid, answer)
        assert not v.correct and v.hint and v.score == 0


def test_tolerance_study_accepts_a_monte_carlo_of_the_students_springs(good):
    built = lab8.built_arm(good)
    mine = tolerance.monte_carlo(built, lab8.LAB8_TOLERANCES, n=4000, grid=15, seed=123).quantile(0.95)
    assert check("8.2", {"springs": good, "quantile": mine}).correct
    assert check("8.2", {"springs": good, "quantile": f"{mine * 1000} N mm"}).correct
    assert not check("8.2", {"springs": good, "quantile": 2 * mine}).correct
    assert not check("8.2", {"springs": good, "quantile": "a lot"}).correct
    assert not check("8.2", {"springs": good, "quantile": float("nan")}).correct
    assert not check("8.2", mine).correct  # the springs are part of the answer


def test_rate_error_torque_is_the_hand_calculation():
    """V = k (b^2 + c^2 - 2 b c sin t) / 2, so an extra 2 % of k1 leaves 0.02 k1 b1 c1 cos t at the shoulder."""
    p = lab8.LAB8_ARM
    k1 = lab8.lab8_arm().springs[0].k
    assert np.isclose(k1 * p["b"][0] * p["c"][0], bl.G * (p["masses"][0] * p["coms"][0][0]
                                                          + p["masses"][1] * p["length"]))
    rng = np.random.default_rng(8)
    t = rng.uniform(-np.pi, np.pi, (20, 2))
    _, Q = forces.generalized_force(lab8.rate_error_arm(0.02), t)
    assert np.allclose(Q[:, 0], -0.02 * k1 * p["b"][0] * p["c"][0] * np.cos(t[:, 0]), atol=1e-9)
    assert np.allclose(Q[:, 1], 0.0, atol=1e-9)
    hand = 0.02 * k1 * p["b"][0] * p["c"][0]
    assert check("8.3", hand).correct and check("8.3", f"{hand * 1000} N mm").correct
    assert not check("8.3", hand * 1.01).correct and not check("8.3", hand / 2).correct
    with pytest.raises(ValueError, match="k1_error"):
        lab8.rate_error_arm(-1.0)
