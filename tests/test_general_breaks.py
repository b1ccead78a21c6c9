"""Breaks found by an outside engineer on the general balancer (brief b19), each reproduced from the
user's seat (``import balancelab as bl``) and kept as a regression test."""
from __future__ import annotations

import warnings

import numpy as np
import pytest

import balancelab as bl
from balancelab.methods.general import free_choices

G = 9.81
C = 100.0  # N/m: the rate of the given spring, which fixes the candidate's rate
M2 = 2.0  # kg on the second link


def arm(rot=0.0, shift=(0.0, 0.0), scale=1.0):
    """A 2R arm (links 1 m, mass 2 kg at the middle of link 2) carrying a ZFL spring of rate C from
    link 1 at (2, 0) to link 2 at (0.5, 0). A candidate ZFL spring from link 2 at (0.5, 0) to the
    ground must cancel -C/2 cos(theta_2 - theta_1) (so its rate is C) and the weight: its ground end
    must sit exactly at (0, M2 G / C) = (0, 0.1962) m above the shoulder. Every local point is drawn
    rotated by ``rot``, scaled by ``scale`` and moved by ``shift`` (the ground's by the shift only); the mass
    is ``M2 / scale`` and the spring's rate ``C / scale**2``, so that the needed anchor is scaled too."""
    c, s = np.cos(rot), np.sin(rot)

    def local(p):
        return (scale * (c * p[0] - s * p[1]) + shift[0], scale * (s * p[0] + c * p[1]) + shift[1])

    lk = bl.Linkage("2R with a given spring")
    lk.revolute("ground", shift, "l1", local((0.0, 0.0)))
    lk.revolute("l1", local((1.0, 0.0)), "l2", local((0.0, 0.0)))
    lk.mass("l2", M2 / scale, com=local((0.5, 0.0)))  # so that the needed anchor scales with the drawing
    lk.spring("l1", local((2.0, 0.0)), "l2", local((0.5, 0.0)), k=C / scale ** 2)
    return lk.build(), local


NEEDED_Y = M2 * G / C


def candidate(local):
    return [(("l2", local((0.5, 0.0))), ("ground", None))]


@pytest.mark.parametrize("rot", [0.0, 0.7, 2.5, -2.0])
@pytest.mark.parametrize("box, verdict", [
    (((-1.0, 1.0), (-1.0, NEEDED_Y - 0.01)), "box"),
    (((-1.0, 1.0), (NEEDED_Y + 0.01, 1.0)), "box"),
    (((0.0, 1e-4), (0.0, 1e-4)), "box"),  # BREAK9: a box far smaller than the linkage was "negative"
    (((-1.0, 1.0), (NEEDED_Y - 0.01, NEEDED_Y + 0.01)), None),
])
def test_the_verdict_is_the_true_one_whatever_the_drawing(rot, box, verdict):
    d, local = arm(rot)
    if verdict is None:
        out = bl.balance(d, springs=candidate(local), box=box)
        assert out.parameters["b_x2"] == pytest.approx(0.0, abs=1e-9)
        assert out.parameters["b_y2"] == pytest.approx(NEEDED_Y, rel=1e-9)
        assert out.parameters["k2"] == pytest.approx(C, rel=1e-9)
        return
    with pytest.raises(bl.InfeasibleDesign) as info:
        bl.balance(d, springs=candidate(local), box=box)
    assert info.value.verdict == verdict, str(info.value)
    assert "outside the box" in str(info.value) and "0.1962" in str(info.value)
    out = bl.balance(d, springs=candidate(local), box=info.value.box)  # the box the message suggests does
    assert out.parameters["b_y2"] == pytest.approx(NEEDED_Y, rel=1e-9)


def test_a_spring_that_needs_a_negative_rate_is_named_so():
    d, local = arm()
    # the ground end fixed below the shoulder: the weight needs the opposite sign of rate
    with pytest.raises(bl.InfeasibleDesign) as info:
        bl.balance(d, springs=[(("l2", (0.5, 0.0)), ("ground", (0.0, -0.2)))])
    assert info.value.verdict in ("impossible", "negative")
    lever = bl.Linkage("lever")
    lever.revolute("ground", (0.0, 0.0), "arm", (0.0, 0.0))
    lever.mass("arm", 2.0, com=(0.5, 0.0))
    with pytest.raises(bl.InfeasibleDesign) as info:
        bl.balance(lever.build(), springs=[(("arm", (0.25, 0.0)), ("ground", (0.0, -0.4)))])
    assert info.value.verdict == "negative" and "springs[0]" in str(info.value)


def test_impossible_names_the_term_no_candidate_produces():
    d, local = arm()
    with pytest.raises(bl.InfeasibleDesign) as info:  # a counterweight cannot cancel the spring's cos term
        bl.balance(d, counterweights=[("l2", None), ("l1", None)])
    assert info.value.verdict == "impossible" and "cos(θ_2 - θ_1)" in str(info.value)


# ---------------------------------------------------------------- break 2: the default box
@pytest.mark.parametrize("dx, dy, scale", [(0.0, 0.0, 1e-4), (1000.0, 0.0, 1.0), (-3.0, 700.0, 1e-2), (0.3, -0.2, 30.0),
                                            (250.0, 250.0, 1e3), (-1e3, -1e3, 3e-5), (0.0, 0.0, 1.0)])
def test_the_default_box_follows_the_drawing(dx, dy, scale):
    """Translating every point translates each body's default box; scaling scales it (no box about the
    origin for a linkage drawn 1 km away, no 1 mm floor for a 10 µm one)."""
    ref, _ = arm()
    moved, local = arm(shift=(dx * scale, dy * scale), scale=scale)
    a = bl.balance(ref, springs=candidate(lambda p: p))
    b = bl.balance(moved, springs=candidate(local))
    for name in ("box_x_lo", "box_x_hi", "box_y_lo", "box_y_hi"):
        shift = dx * scale if "_x_" in name else dy * scale
        assert b.parameters[name] == pytest.approx(a.parameters[name] * scale + shift, rel=1e-9, abs=1e-9 * scale)
    assert b.parameters["k2"] == pytest.approx(a.parameters["k2"] / scale ** 2, rel=1e-7)
    assert b.parameters["b_x2"] == pytest.approx(dx * scale, rel=1e-7, abs=1e-7 * scale)
    assert b.parameters["b_y2"] == pytest.approx(dy * scale + NEEDED_Y * scale, rel=1e-7)


def test_a_micro_linkage_gets_a_micro_box():
    d, local = arm(scale=3e-5)
    out = bl.balance(d, springs=candidate(local))
    assert out.parameters["box_x_hi"] - out.parameters["box_x_lo"] == pytest.approx(2 * 2 * 3e-5, rel=1e-9)


# ---------------------------------------------------------------- breaks 5, 6, 9: configurations, n, a balanced design
def lever():
    lk = bl.Linkage("lever")
    lk.revolute("ground", (0.0, 0.0), "arm", (0.0, 0.0))
    lk.mass("arm", 2.0, com=(0.5, 0.0))
    return lk.build()


def two_r():
    lk = bl.Linkage("2R")
    lk.revolute("ground", (0.0, 0.0), "l1", (0.0, 0.0))
    lk.revolute("l1", (1.0, 0.0), "l2", (0.0, 0.0))
    lk.mass("l1", 1.0, com=(0.5, 0.0))
    lk.mass("l2", 1.0, com=(0.5, 0.0))
    return lk.build()


@pytest.mark.parametrize("jitter", [1e-12, 1e-9, 1e-6])
def test_degenerate_configurations_are_refused(jitter):
    """BREAK13: one pose jittered, or a line through a 2-DOF space, is no evidence of balance."""
    rng = np.random.default_rng(0)
    d = two_r()
    t = np.linspace(-3.0, 3.0, 200)
    with pytest.raises(ValueError, match="q must"):
        d.balance_report(np.c_[t, t] + rng.normal(0.0, jitter, (200, 2)))
    with pytest.raises(ValueError, match="q must"):
        d.balance_report(np.full((60, 2), 0.3) + rng.normal(0.0, jitter, (60, 2)))


def test_a_huge_n_is_refused_by_name_before_any_allocation():
    d = lever()
    for call in (lambda: bl.balance(d, springs=[(("arm", (0.25, 0.0)), ("ground", None))], n=10 ** 12),
                 lambda: d.balance_report(n=10 ** 12),
                 lambda: free_choices(d, springs=[(("arm", (0.25, 0.0)), ("ground", None))], n=10 ** 9)):
        with pytest.raises(ValueError, match=r"n \(number of configurations\).*200000"):
            call()


@pytest.mark.parametrize("objective", ["min_preload", "min_stiffness"])
def test_a_balanced_design_passed_again_keeps_its_springs_quietly(objective):
    """Break 9: the solver may find k = 2e-15 for a candidate a balanced design does not need: dropped."""
    d = bl.balance(lever(), springs=[(("arm", (0.25, 0.0)), ("ground", (0.0, 0.4)))])
    for cands in ([(("arm", (0.25, 0.0)), ("ground", (0.0, 0.4)))], [(("arm", (0.3, 0.1)), ("ground", (0.1, 0.4)))],
                  [(("arm", (0.3, 0.1)), ("ground", None))]):
        with warnings.catch_warnings():
            warnings.simplefilter("error")  # no RuntimeWarning of a 0 / 0 inside the solver either
            out = bl.balance(d, springs=cands, objective=objective)
        assert len(out.springs) in (1, 2) and out.balance_report().balanced
        assert all(s.k >= 1e-12 for s in out.springs)
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        out = bl.balance(d, counterweights=[("arm", (-0.1, 0.0))], objective=objective)
    assert out.balance_report().balanced and len(out.loads) == 1  # a zero counter mass is left out


def test_the_default_objective_owes_no_warning_for_a_counterweight():
    """Break 8: with the default objective (minimum preload) and a counterweight whose point is free, the
    objective counts no mass; the counterweight is made the lightest (its point at the box's far edge), quietly."""
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        out = bl.balance(lever(), counterweights=[("arm", None)], box=((-0.5, 0.1), (-0.1, 0.1)))
    assert out.parameters["c_x1"] == pytest.approx(-0.5, rel=1e-9)
    assert out.parameters["counter_mass1"] == pytest.approx(2.0 * 0.5 / 0.5, rel=1e-9)
    assert out.balance_report().balanced


@pytest.mark.parametrize("rot", [0.3, 0.7854, 2.0])
def test_turning_the_drawing_keeps_the_default_box_size_and_the_design(rot):
    """BREAK7: the default box's size is a distance, not an x or y extent: a drawing turned by any angle
    gets a box as large, and the same anchor (the ground frame is the world's)."""
    ref, _ = arm()
    turned, local = arm(rot)
    a = bl.balance(ref, springs=candidate(lambda p: p))
    b = bl.balance(turned, springs=candidate(local))
    assert b.parameters["box_x_hi"] - b.parameters["box_x_lo"] == pytest.approx(
        a.parameters["box_x_hi"] - a.parameters["box_x_lo"], rel=1e-12)
    assert (b.parameters["b_x2"], b.parameters["b_y2"]) == pytest.approx((0.0, NEEDED_Y), abs=1e-9)
