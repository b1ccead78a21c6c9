"""Issue 19, item 2: prismatic joints (sliders) in the builder, against closed forms, and balanced."""
from __future__ import annotations

import numpy as np
import pytest

import balancelab as bl

G = 9.81


def wrap(a):
    return np.angle(np.exp(1j * np.asarray(a)))


def slider_crank(crank=0.2, rod=0.6, driving=None):
    lk = bl.Linkage("slider-crank")
    lk.revolute("ground", (0.0, 0.0), "crank", (0.0, 0.0))
    lk.revolute("crank", (crank, 0.0), "rod", (0.0, 0.0))
    lk.revolute("rod", (rod, 0.0), "slider", (0.0, 0.0))
    assert lk.prismatic("ground", (0.0, 0.0), "slider", (0.0, 0.0), axis=(2.0, 0.0)) == "s_1"  # any length
    lk.mass("crank", 1.0, com=(crank / 2, 0.0))
    lk.mass("rod", 1.0, com=(rod / 2, 0.0))
    lk.mass("slider", 2.0)
    return lk.build(driving=driving, guess={"crank": 1.0})


def test_a_slider_crank_follows_its_closed_form():
    d = slider_crank()
    assert d.dof == 1 and d.q_names == ("theta_1",) and d.kinematics.full_turn and d.kinematics.grubler == 1
    th = np.linspace(-np.pi, np.pi, 73)
    P, ok = d.kinematics.poses(th[:, None])
    assert ok.all()
    x = 0.2 * np.cos(th) + np.sqrt(0.6 ** 2 - (0.2 * np.sin(th)) ** 2)  # the slider's position
    np.testing.assert_allclose(P[:, 3, 0], x, atol=1e-10)
    np.testing.assert_allclose(P[:, 3, 1:], 0.0, atol=1e-10)  # on the axis, never turning
    np.testing.assert_allclose(np.sin(P[:, 2, 2]), -0.2 * np.sin(th) / 0.6, atol=1e-10)


def test_a_slider_crank_driven_by_its_slide_has_the_stroke_as_range():
    d = slider_crank(driving=["s_1"])
    assert d.q_names == ("s_1",) and "slide of slider along ground (m)" in d.kinematics.descriptions[0]
    np.testing.assert_allclose(d.q_range, [[0.4, 0.8]], atol=1e-6)  # rod - crank to rod + crank
    s = d.sample(200)
    P = d.poses(s)
    np.testing.assert_allclose(P[:, 3, 0], s[:, 0], atol=1e-10)
    crank_tip = 0.2 * np.stack([np.cos(P[:, 1, 2]), np.sin(P[:, 1, 2])], -1)
    np.testing.assert_allclose(np.linalg.norm(P[:, 3, :2] - crank_tip, axis=-1), 0.6, atol=1e-10)


def test_springs_and_counterweights_balance_a_slider_crank():
    d = slider_crank()
    out = bl.balance(d, springs=[(("ground", None), ("crank", None)), (("ground", (0.0, 0.0)), ("slider", (0.0, 0.0)))],
                     counterweights=[("crank", None), ("rod", None)])
    assert out.balance_report().balanced
    q = out.sample(400, seed=5)
    V = out.potential_energy(q).total
    assert np.ptp(V) <= 1e-9 * G * 4.0 * 1.0


def test_an_inverted_slider_crank_follows_its_closed_form():
    """A block pinned to the crank's tip slides along a guide pivoted on the ground at B = (0.5, 0)."""
    lk = bl.Linkage("inverted slider-crank")
    lk.revolute("ground", (0.0, 0.0), "crank", (0.0, 0.0))
    lk.revolute("crank", (0.2, 0.0), "block", (0.0, 0.0))
    lk.prismatic("guide", (0.0, 0.0), "block", (0.0, 0.0), axis=(1.0, 0.0))
    lk.revolute("guide", (0.0, 0.0), "ground", (0.5, 0.0))
    lk.mass("guide", 1.0, com=(0.3, 0.0))
    d = lk.build(guess={"crank": 1.0, "guide": 2.5, "s_1": 0.5})
    assert d.dof == 1 and d.kinematics.full_turn
    th = np.linspace(-np.pi, np.pi, 61)
    P, ok = d.kinematics.poses(th[:, None])
    assert ok.all()
    tip = 0.2 * np.stack([np.cos(th), np.sin(th)], -1)
    guide = np.arctan2(tip[:, 1], tip[:, 0] - 0.5)
    np.testing.assert_allclose(wrap(P[:, 3, 2] - guide), 0.0, atol=1e-9)  # the guide points at the tip
    np.testing.assert_allclose(wrap(P[:, 2, 2] - P[:, 3, 2]), 0.0, atol=1e-9)  # the block turns with it
    out = bl.balance(d, counterweights=[("guide", None)])
    assert out.balance_report().balanced and out.loads[-1].point[0] < 0  # behind the pivot B


def test_a_lever_driven_by_a_slider_is_balanced_by_a_spring_on_the_slider():
    """A piston on a horizontal guide at height 0.3 m pushes a weighted lever through a rod."""
    lk = bl.Linkage("lever driven by a slider")
    lk.revolute("ground", (0.0, 0.0), "lever", (0.0, 0.0))
    lk.revolute("lever", (0.4, 0.0), "rod", (0.0, 0.0))
    lk.revolute("rod", (0.5, 0.0), "piston", (0.0, 0.0))
    lk.prismatic("ground", (-1.0, 0.3), "piston", (0.0, 0.0), axis=(1.0, 0.0), stroke=(0.7, 1.3))
    lk.mass("lever", 3.0, com=(0.3, 0.0))
    d = lk.build(driving=["s_1"], guess={"lever": 1.0})
    assert d.q_names == ("s_1",) and d.dof == 1
    out = bl.balance(d, springs=[(("ground", None), ("piston", (0.0, 0.0)))], counterweights=[("lever", None)])
    assert out.balance_report().balanced
    q = out.sample(300, seed=2)
    lever_tip = out.world_points(q, [(1, (0.3, 0.0))])[:, 0]
    np.testing.assert_allclose(np.ptp(out.potential_energy(q).total), 0.0, atol=1e-9 * 3.0 * G * np.ptp(lever_tip[:, 1]))


def scissors_from_scratch(a=0.5):
    """Chapter 6's scissors lift, body for body as in the catalog, with its two sliders as prismatic joints."""
    h = a / 2
    cat = bl.catalog()["scissors_lift"]()
    lk = bl.Linkage("scissors lift from scratch")
    for name in cat.bodies[1:]:
        lk.body(name)
    lk.revolute("ground", (0.0, 0.0), "arm 2", (0.0, 0.0))
    lk.revolute("arm 2", (h, 0.0), "arm 3", (h, 0.0))
    lk.revolute("arm 3", (0.0, 0.0), "slider 4", (0.0, 0.0))
    lk.prismatic("ground", (0.0, 0.0), "slider 4", (0.0, 0.0), axis=(1.0, 0.0), stroke=(0.02 * a, 0.98 * a))
    lk.revolute("arm 3", (a, 0.0), "arm 5", (0.0, 0.0))
    lk.revolute("arm 2", (a, 0.0), "arm 6", (0.0, 0.0))
    lk.revolute("arm 5", (h, 0.0), "arm 6", (h, 0.0))
    lk.revolute("arm 6", (a, 0.0), "platform 8", (0.0, 0.0))
    lk.revolute("arm 5", (a, 0.0), "slider 7", (0.0, 0.0))
    lk.prismatic("platform 8", (0.0, 0.0), "slider 7", (0.0, 0.0), axis=(1.0, 0.0))
    for ld in cat.loads:
        lk.load(ld.body, ld.force, com=ld.point, name=ld.name)
    s1 = cat.springs[0]  # the finite-free-length spring between the crossings stays; bl.balance finds the other
    lk.spring(s1.a[0], s1.a[1], s1.b[0], s1.b[1], k=s1.k, free_length=s1.free_length, name="k1")
    guess = {"arm 2": 0.6, "arm 3": np.pi - 0.6, "arm 5": 0.6, "arm 6": np.pi - 0.6}
    return cat, lk.build(driving=["s_1"], guess=guess)


def test_the_scissors_lift_built_from_scratch_moves_like_the_catalogs():
    cat, d = scissors_from_scratch()
    assert d.bodies == cat.bodies and d.dof == 1 and d.q_names == ("s_1",)
    theta = np.linspace(0.25, 1.5, 26)  # inside the stroke 0.01..0.49 m
    P, ok = d.kinematics.poses(0.5 * np.cos(theta)[:, None])  # the bottom slider at a cos(theta)
    Pc, _ = cat.kinematics.poses(theta[:, None])
    assert ok.all()
    np.testing.assert_allclose(P[..., :2], Pc[..., :2], atol=1e-9)
    np.testing.assert_allclose(wrap(P[..., 2] - Pc[..., 2]), 0.0, atol=1e-9)


def test_bl_balance_rederives_the_scissors_lifts_second_spring():
    """Singh's eqs 54 and 56: the spring from the pivot to the bottom slider is a ZFL spring with k2 = k1,
    anchored at the pivot (its height is a free choice; the least preload puts it at zero)."""
    cat, d = scissors_from_scratch()
    out = bl.balance(d, springs=[(("ground", None), ("slider 4", (0.0, 0.0)))])
    assert out.parameters["k2"] == pytest.approx(cat.parameters["k2"], rel=1e-9)
    assert (out.parameters["a_x2"], out.parameters["a_y2"]) == pytest.approx((0.0, 0.0), abs=1e-9)
    assert out.balance_report().balanced


def test_a_block_on_a_guide_is_a_tree_with_a_slide_coordinate():
    lk = bl.Linkage("block")
    lk.prismatic("ground", (0.0, 0.0), "block", (0.0, 0.0), axis=(np.cos(0.5), np.sin(0.5)), stroke=(-0.5, 0.5))
    lk.mass("block", 2.0)
    d = lk.build()
    assert d.q_names == ("s_1",) and d.dof == 1
    s = d.sample(50)
    P = d.poses(s)
    np.testing.assert_allclose(P[:, 1, 1], s[:, 0] * np.sin(0.5), atol=1e-12)  # up the incline
    with pytest.raises(bl.InfeasibleDesign) as err:  # k s^2 / 2 cannot cancel m g s sin(0.5): only a constant
        bl.balance(d, springs=[(("block", (0.0, 0.0)), ("ground", None))])  # force (k -> 0, anchor far) would
    assert err.value.verdict == "negative" and "constant force" in str(err.value)


def test_bad_sliders_are_refused_by_name():
    lk = bl.Linkage()
    with pytest.raises(ValueError, match="axis must be a nonzero direction"):
        lk.prismatic("ground", (0.0, 0.0), "block", (0.0, 0.0), axis=(0.0, 0.0))
    with pytest.raises(ValueError, match="stroke must be"):
        lk.prismatic("ground", (0.0, 0.0), "block", (0.0, 0.0), axis=(1.0, 0.0), stroke=(1.0, -1.0))
    with pytest.raises(ValueError, match="two different bodies"):
        lk.prismatic("ground", (0.0, 0.0), "ground", (0.0, 0.0))
    lk.prismatic("ground", (0.0, 0.0), "block", (0.0, 0.0))
    lk.mass("block", 1.0)
    with pytest.raises(ValueError, match="no slide 's_2'"):
        lk.build(driving=["s_2"])


def test_a_slide_is_labelled_and_reported_in_metres_not_degrees():
    """B3: a slide coordinate (m) is never converted to degrees in labels, reports or plots."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    from balancelab.core.report import q_units
    from balancelab.viz.energy import energy_plot
    from balancelab.viz.frame import angle_label

    d = slider_crank(driving=["s_1"])
    assert q_units(d) == ("m",)
    assert q_units(slider_crank()) == ("rad",)
    label = angle_label(d, 0)
    assert label.endswith("(m)") and "deg" not in label and "(m) (m)" not in label
    text = str(d.balance_report())
    assert "°" not in text and " m)" in text and "per m" in text and "per rad" not in text
    fig, ax = plt.subplots()
    try:
        energy_plot(d, ax=ax)
        lo, hi = d.q_range[0]
        x0, x1 = ax.get_xlim()
        assert x0 == pytest.approx(lo, abs=1e-9 + 1e-6 * (hi - lo)) and x1 == pytest.approx(hi, abs=1e-9 + 1e-6 * (hi - lo))
        assert "deg" not in ax.get_xlabel()
    finally:
        plt.close(fig)
