"""Lab 9: the pulley judged from its points, for each student's own link."""
from __future__ import annotations

import math

import numpy as np
import pytest

import balancelab as bl
from balancelab.course.check import check, set_student, task_numbers, tasks
from balancelab.course.check import lab9
from balancelab.course.check.data import decode_answer, encode_answer
from balancelab.methods.practice.springs import ExtensionSpring

STOCK = ExtensionSpring(3e-3, 24e-3, 60, initial_tension=40.0)
SPRING = {"d": 3e-3, "D": 24e-3, "Na": 60, "F_i": 40.0}


def _pulley(load, t_min, n=400):
    link = bl.lecture.single_link_spring(load["mass"], load["length"], 0.3, 0.2)
    d = bl.realize.noncircular_pulley(link, spring_model=STOCK, angle_range=lab9.LAB9_RANGE, min_tension=t_min,
                                      eyelet=lab9.LAB9_EYELET)
    pitch, clamp = bl.realize.profile_part(d, n=n).pitch, d.springs[0].b.point
    if np.hypot(*(pitch[0] - clamp)) < np.hypot(*(pitch[-1] - clamp)):
        pitch = pitch[::-1]
    return d, {"spring": dict(SPRING), "points": pitch, "cable_length": d.springs[0].cable.cable_length,
               "turn": d.springs[0].cable.turn}


def _fitting(load):
    for t_min in np.arange(41.0, 80.0, 1.0):
        try:
            d, answer = _pulley(load, float(t_min))
        except ValueError:
            continue
        if np.hypot(*answer["points"].T).max() <= lab9.LAB9_MAX_RADIUS and \
                d.parameters["min_radius_of_curvature"] >= lab9.LAB9_MIN_CURVATURE:
            return d, answer
    raise AssertionError(f"no stock-spring pulley fits for {load}")


@pytest.fixture(autouse=True)
def _no_student():
    set_student("")
    yield
    set_student("")


def test_lab9_is_registered_with_a_personal_open_design_task():
    ts = {t.id: t for t in tasks("lab9")}
    assert set(ts) == {"9.1", "9.2", "9.3"}
    assert ts["9.1"].kind == "design" and ts["9.1"].numbers is not None and ts["9.1"].points == 2


@pytest.mark.parametrize("student", ["s1", "s7", "lab9-student"])
def test_every_students_link_has_a_pulley_that_fits_and_only_theirs_passes(student):
    set_student(student)
    load = task_numbers("9.1")
    published = dict(lab9.LAB9_LINK)
    assert abs(load["mass"] * load["length"] / (published["mass"] * published["length"]) - 1) > 0.03
    design, answer = _fitting(load)
    assert check("9.1", answer).correct
    # the judge's cable tensions, from the points alone, are the design's (its smallest and largest)
    variation, tension = lab9.pulley_energy_variation(answer, load)
    assert variation < 1e-4
    assert math.isclose(tension.min(), design.parameters["min_tension"], rel_tol=1e-3)
    assert math.isclose(tension.max(), design.parameters["max_tension"], rel_tol=1e-3)
    # the published link's pulley (a friend's, or the book's) leaves this student's link unbalanced
    _, theirs = _fitting(published)
    verdict = check("9.1", theirs)
    assert not verdict.correct and "does not balance" in verdict.message


def test_the_answer_survives_the_graders_plain_data():
    _, answer = _fitting(lab9.LAB9_LINK)
    assert check("9.1", decode_answer(encode_answer(answer))).correct


def test_limits_are_judged_from_the_points():
    _, good = _fitting(lab9.LAB9_LINK)
    # too large: a pulley grown by 5 % about the axle leaves the 150 mm disc (and no longer balances)
    big = dict(good, points=good["points"] * (1.05 * lab9.LAB9_MAX_RADIUS / np.hypot(*good["points"].T).max()))
    assert "from the axle" in check("9.1", big).message
    # a dent: one point pushed in makes the curve turn both ways
    dented = good["points"].copy()
    mid = len(dented) // 2
    dented[mid] *= 0.97
    assert "not convex" in check("9.1", dict(good, points=dented)).message
    # a sharp but convex curve: an arc of 8 mm radius
    phi = np.linspace(0.0, 3.0, 200)
    arc = np.column_stack([0.05 + 0.008 * np.cos(phi), 0.008 * np.sin(phi)])
    assert "radius of curvature" in check("9.1", dict(good, points=arc)).message


def test_a_slack_spring_is_refused_even_when_the_energy_is_right():
    """The same stretches with a higher initial tension: the spring's equivalent free length
    shrinks by the extra F_i / k, so a cable that much longer keeps every tension, but the
    smallest one is now below the spring's own initial tension: it would go slack."""
    _, good = _fitting(lab9.LAB9_LINK)
    spring = lab9.lab9_spring(good["spring"])
    lo, hi = spring.initial_tension_range()
    f_i = min(hi, 60.0)
    if f_i <= 46.0:
        pytest.skip("the stock spring cannot be wound above 46 N")
    tighter = ExtensionSpring(3e-3, 24e-3, 60, initial_tension=f_i)
    answer = dict(good, spring=dict(SPRING, F_i=f_i),
                  cable_length=good["cable_length"] + spring.equivalent_free_length - tighter.equivalent_free_length)
    variation, tension = lab9.pulley_energy_variation(answer, lab9.LAB9_LINK)
    assert variation < 1e-4 and tension.min() < f_i
    assert "slack" in check("9.1", answer).message


@pytest.mark.parametrize("junk", [None, 3.0, "pulley", {"spring": SPRING}, {"spring": SPRING, "points": [[0, 0]] * 10,
                                  "cable_length": 0.1, "turn": 1},
                                  {"spring": SPRING, "points": np.zeros((100, 2)), "cable_length": 0.1, "turn": 1},
                                  {"spring": SPRING, "points": np.ones((100, 2)) * np.nan, "cable_length": 0.1,
                                   "turn": 1}])
def test_malformed_pulleys_get_a_verdict_not_a_traceback(junk):
    v = check("9.1", junk)
    assert not v.correct and v.message


def test_turn_must_be_one_or_minus_one():
    _, good = _fitting(lab9.LAB9_LINK)
    for bad in (0, 2, True, "left"):
        v = check("9.1", dict(good, turn=bad))
        assert not v.correct and "turn" in v.message


def test_largest_tension_follows_from_energy_alone():
    # the library's design reaches the same largest tension from its own synthesis
    design, _ = _pulley(lab9.LAB9_LINK, lab9.LAB9_MIN_TENSION)
    assert check("9.2", design.parameters["max_tension"]).correct
    assert not check("9.2", design.parameters["max_tension"] * 1.02).correct
