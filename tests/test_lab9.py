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


# --- issue 25, A25: a cable that never touches the points is an eyelet, not a pulley ---------------------------

def _a25_answer():
    """A25's exact answer for student s1234567: the lecture's ZFL rule ``k b c = m g r`` through the eyelet
    (b = 0.3 m), a 12.5 mm arc hung below the clamp P = (c, 0) that the cable never touches, and a negative
    cable length that makes the spring's stretch the eyelet-to-P distance."""
    set_student("s1234567")
    load = task_numbers("9.1")
    spd = {"d": 3e-3, "D": 24e-3, "Na": 120, "F_i": 40.0}
    spr = lab9.lab9_spring(spd)
    c = load["mass"] * 9.81 * load["length"] / (spr.k * 0.3)
    phi = np.linspace(0, -0.2 * 5, 60)
    arc = np.array([c, -0.0125]) + 0.0125 * np.stack([np.sin(phi), np.cos(phi)], 1)
    return load, spr, {"spring": spd, "points": arc[::-1], "cable_length": -spr.equivalent_free_length, "turn": -1}


def _one_side_of_the_straight_cable(points, turn) -> bool:
    """True when, at every angle of the range, every point lies on the wrap's side of the straight line
    from the eyelet to the clamped end (the last point): the taut cable runs straight and touches
    the curve at the clamp only. Computed here, independently of the judge."""
    pts = np.asarray(points, dtype=float)
    for theta in np.linspace(*lab9.LAB9_RANGE, 241):
        c, s = math.cos(theta), math.sin(theta)
        world = pts @ np.array([[c, s], [-s, c]])
        rel = world - np.array(lab9.LAB9_EYELET)
        cross = rel[-1, 0] * rel[:, 1] - rel[-1, 1] * rel[:, 0]
        if np.any(turn * cross < -1e-12):
            return False
    return True


def test_a25_zfl_through_the_eyelet_with_an_untouched_arc_is_refused():
    load, _, answer = _a25_answer()
    assert _one_side_of_the_straight_cable(answer["points"], answer["turn"])
    # the energy alone is balanced (a ZFL spring through an eyelet): only the wrap rule can refuse it
    variation, _ = lab9.pulley_energy_variation(answer, load)
    assert variation < lab9.LAB9_TOLERANCE
    verdict = check("9.1", answer)
    assert not verdict.correct
    assert "does not wrap" in verdict.message and "wrapped" not in verdict.message
    # the other turn makes the judge wind the cable across the arc's hollow side: refused as well
    flipped = check("9.1", dict(answer, turn=1))
    assert not flipped.correct and "other way" in flipped.message


def test_profiles_the_straight_cable_never_wraps_are_never_accepted():
    """Property: random convex arcs (radius of curvature >= 12 mm, within the 150 mm disc, turning the
    cable's way) ending at the point P where a ZFL spring through the eyelet balances the link, so that
    the energy is constant; whenever every point lies beside the straight eyelet-to-P line at every
    angle, the judge refuses, and says the cable does not wrap the curve."""
    load, spr, base = _a25_answer()
    clamp = np.array([load["mass"] * 9.81 * load["length"] / (spr.k * 0.3), 0.0])
    rng = np.random.default_rng(25)
    tried = 0
    for _ in range(1200):
        turn = int(rng.choice([-1, 1]))
        radius, span = rng.uniform(0.0125, 0.08), rng.uniform(0.3, 2.5)
        start, n = rng.uniform(0, 2 * math.pi), int(rng.integers(50, 200))
        t = start + turn * np.linspace(0.0, span, n)
        arc = radius * np.column_stack([np.cos(t), np.sin(t)])
        arc += clamp - arc[-1]
        if np.hypot(*arc.T).max() > lab9.LAB9_MAX_RADIUS or not _one_side_of_the_straight_cable(arc, turn):
            continue
        tried += 1
        answer = dict(base, points=arc, turn=turn)
        assert lab9.pulley_energy_variation(answer, load)[0] < lab9.LAB9_TOLERANCE
        assert not check("9.1", answer).correct
        assert any("does not wrap" in p for p in lab9.pulley_problems(answer))
    assert tried >= 50


def test_a_curve_turning_against_the_cable_is_refused():
    _, good = _fitting(lab9.LAB9_LINK)
    verdict = check("9.1", dict(good, turn=-good["turn"]))
    assert not verdict.correct and "other way" in verdict.message


def test_a_wrapped_pulley_with_a_long_spring_is_accepted_whatever_the_sign_of_cable_length():
    """With a spring longer than the cable's path (Na = 90) the design's cable_length (path minus spring
    length) is negative; the spring hangs beyond the eyelet, the cable wraps the profile and the design
    is sound: the judge must not refuse it for the sign."""
    set_student("s1234567")
    load = task_numbers("9.1")
    spd = dict(SPRING, Na=90)
    spring = lab9.lab9_spring(spd)
    link = bl.lecture.single_link_spring(load["mass"], load["length"], 0.3, 0.2)
    for t_min in np.arange(41.0, 80.0, 1.0):
        try:
            d = bl.realize.noncircular_pulley(link, spring_model=spring, angle_range=lab9.LAB9_RANGE,
                                              min_tension=float(t_min), eyelet=lab9.LAB9_EYELET)
        except ValueError:
            continue
        pitch, clamp = bl.realize.profile_part(d, n=400).pitch, d.springs[0].b.point
        if np.hypot(*(pitch[0] - clamp)) < np.hypot(*(pitch[-1] - clamp)):
            pitch = pitch[::-1]
        if np.hypot(*pitch.T).max() <= lab9.LAB9_MAX_RADIUS and \
                d.parameters["min_radius_of_curvature"] >= lab9.LAB9_MIN_CURVATURE:
            break
    answer = {"spring": spd, "points": pitch, "cable_length": d.springs[0].cable.cable_length,
              "turn": d.springs[0].cable.turn}
    assert answer["cable_length"] < 0
    assert not _one_side_of_the_straight_cable(pitch, answer["turn"])
    assert check("9.1", answer).correct
