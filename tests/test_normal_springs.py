"""Perfect balance with normal springs in sleeves: exact physics, checked from the points."""
from __future__ import annotations

import math

import numpy as np
import pytest
import sympy as sp
from hypothesis import given, settings
from hypothesis import strategies as st

import balancelab as bl
from balancelab.methods import realize
from conftest import assert_exactly_balanced, independent_energy


def _line_facts(zfl: bl.Design, mounted: bl.Design, q):
    """For each mounted spring: its ends' distance from the line AC, its length minus
    (|AC| + l0), and the joint gaps, computed here from the mounted design's poses."""
    poses = mounted.poses(q)

    def world(body, p):
        x, y, a = poses[:, body, 0], poses[:, body, 1], poses[:, body, 2]
        return np.stack([x + np.cos(a) * p[0] - np.sin(a) * p[1], y + np.sin(a) * p[0] + np.cos(a) * p[1]], -1)

    out = []
    for old, new in zip(zfl.springs, mounted.springs):
        if old.free_length != 0:
            continue
        A, C = world(*old.a), world(*old.b)
        P, R = world(*new.a), world(*new.b)
        u = (C - A) / np.linalg.norm(C - A, axis=-1)[:, None]
        cross = lambda v, u=u: u[:, 0] * v[:, 1] - u[:, 1] * v[:, 0]  # noqa: E731
        off_line = max(np.abs(cross(P - A)).max(), np.abs(cross(R - A)).max())
        length = np.linalg.norm(R - P, axis=-1)
        out.append((off_line, np.abs(length - np.linalg.norm(C - A, axis=-1) - new.free_length).max()))
    return out


CATALOG = bl.catalog()
WITH_ZFL = [n for n, e in CATALOG.items() if e.expected_balanced and n != "lamp_arm_normal_springs"]


@pytest.mark.parametrize("name", WITH_ZFL)
def test_every_zfl_spring_of_a_balanced_design_becomes_a_normal_one_and_stays_balanced(name):
    zfl = CATALOG[name]()
    if not any(s.free_length == 0 for s in zfl.springs):
        pytest.skip(f"{name} has no ZFL spring")
    try:
        mounted = realize.mount_normal_springs(zfl, 0.07)
    except ValueError as err:        # a spring whose ends meet somewhere in the range has no sleeve
        assert "ends meet" in str(err)
        return
    assert [s.free_length for s in mounted.springs] == [0.07 if s.free_length == 0 else s.free_length
                                                       for s in zfl.springs]
    report = mounted.balance_report()
    assert report.balanced and report.variation <= 1e-9, report
    q = zfl.sample(300, seed=5)
    # the energy, summed independently from the poses, is the ZFL design's at every configuration
    V0, V1 = independent_energy(zfl, q), independent_energy(mounted, q)
    scale = np.ptp(V0) + np.abs(V0).max()
    assert np.abs(V1 - V0).max() <= 1e-12 * scale
    for off_line, length_error in _line_facts(zfl, mounted, q):
        assert off_line < 1e-12 and length_error < 1e-12
    assert mounted.joint_error(q).max() < 1e-12


def test_the_lamp_arm_example_is_exact_and_a_wrong_offset_is_caught():
    arm = realize.lamp_arm_normal_springs(0.05)
    assert_exactly_balanced(arm)
    # the sleeve point must sit l0 further back than the rod's end: 1 mm off and the arm drifts
    s = arm.springs[0]
    bad = arm.replace(springs=[s.__class__(s.k, s.free_length + 1e-3, s.a, s.b, name=s.name), arm.springs[1]])
    r = bad.balance_report()
    assert not r.balanced and r.variation > 1e-6


def test_a_spring_mounted_directly_is_not_balanced_but_in_a_sleeve_it_is():
    direct = bl.lecture.single_link_ordinary_spring(2.0, 0.5, 0.3, 0.2, free_length=0.05)
    assert not direct.balance_report().balanced
    sleeve = realize.mount_normal_springs(bl.lecture.single_link_spring(2.0, 0.5, 0.3, 0.2), 0.05)
    assert sleeve.balance_report().balanced
    assert math.isclose(sleeve.springs[0].k, direct.springs[0].k) and sleeve.springs[0].free_length == 0.05


def test_the_derivation_has_full_rank_and_the_lecture_rate():
    out = realize.normal_spring_derivation()
    m, g, r, b, c, e, l0 = sp.symbols("m g r b c e l0", positive=True)
    sol = {str(k): v for k, v in out["solution"].items()}
    assert sp.simplify(sol["k"] - m * g * r / (b * c)) == 0
    assert sp.simplify(sol["d"] - (e + l0)) == 0
    assert out["rank"] == 2 and out["residual"] == 0
    # the direct mount keeps -k l0 s, which no rate cancels
    s, k = sp.symbols("s k", positive=True)
    assert sp.simplify(out["direct"].coeff(s) + k * l0) == 0


@settings(max_examples=25, deadline=None)
@given(mass=st.floats(0.2, 20.0), r=st.floats(0.1, 1.5), b=st.floats(0.05, 0.6), c=st.floats(0.05, 0.6),
       l0=st.floats(0.005, 0.5), angle=st.floats(-math.pi, math.pi))
def test_random_levers_balanced_by_bl_balance_with_normal_springs(mass, r, b, c, l0, angle):
    """A random link and anchor: balance_normal's springs are ordinary and the link is balanced,
    checked by an energy summed here; the rate is the lecture's k = m g r / (b c)."""
    if abs(b - c) < 0.01:
        return
    lk = bl.Linkage("random link")
    lk.revolute("ground", (0.0, 0.0), "link", (0.0, 0.0))
    lk.mass("link", mass, at=(r * math.cos(angle), r * math.sin(angle)))
    anchor, pin = (0.0, b), (c * math.cos(angle), c * math.sin(angle))   # the pin on the line to the mass
    d = realize.balance_normal(lk.build(), springs=[(("ground", anchor), ("link", pin))], free_length=l0)
    assert [s.free_length for s in d.springs] == [l0]
    q = d.sample(400, seed=1)
    V = independent_energy(d, q)
    assert np.ptp(V) <= 1e-9 * mass * 9.81 * r * 2
    # the rate balances the weight's torque amplitude: k b c = m g r (lecture 35)
    assert math.isclose(d.springs[0].k * b * c, mass * 9.81 * r, rel_tol=1e-6)


def test_a_free_end_at_least_preload_meets_the_anchor_and_is_refused_not_misreported():
    lk = bl.Linkage("link")
    lk.revolute("ground", (0.0, 0.0), "link", (0.0, 0.0))
    lk.mass("link", 1.0, at=(0.5, 0.0))
    with pytest.raises(ValueError, match="ends meet"):
        realize.balance_normal(lk.build(), springs=[(("ground", (0.0, 0.3)), ("link", None))], free_length=0.05)


def test_bad_input_names_the_parameter():
    lever = bl.lecture.single_link_spring(2.0, 0.5, 0.3, 0.2)
    with pytest.raises(ValueError, match="free_length"):
        realize.mount_normal_springs(lever, 0.0)
    with pytest.raises(ValueError, match="free_length"):
        realize.mount_normal_springs(lever, float("nan"))
    with pytest.raises(TypeError, match="free_length"):
        realize.mount_normal_springs(lever, True)
    with pytest.raises(ValueError, match="springs"):
        realize.mount_normal_springs(lever, 0.05, springs=[1])
    with pytest.raises(TypeError, match="springs"):
        realize.mount_normal_springs(lever, 0.05, springs=[0.0])
    with pytest.raises(ValueError, match="no ZFL spring"):
        realize.mount_normal_springs(bl.lecture.single_link_ordinary_spring(2.0, 0.5, 0.3, 0.2, free_length=0.05),
                                     0.05)
    with pytest.raises(TypeError, match="design"):
        realize.mount_normal_springs("lever", 0.05)
    with pytest.raises(ValueError, match="n must"):
        realize.mount_normal_springs(lever, 0.05, n=3)
    with pytest.raises(ValueError, match="margin"):
        realize.mount_normal_springs(lever, 0.05, margin=-1.0)
    # b == c: the spring's ends meet at 90 degrees, where a sleeve has no direction
    meeting = bl.lecture.single_link_spring(2.0, 0.5, 0.2, 0.2)
    with pytest.raises(ValueError, match="ends meet"):
        realize.mount_normal_springs(meeting, 0.05)
