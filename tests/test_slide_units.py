"""Issue 19 (H19c, item 2): a prismatic joint's coordinate is a length wherever a q is shown: the
explorer's sliders and their spoken descriptions, its messages, and an animation's frame labels and
description give the slide in millimetres and only angles in degrees."""
from __future__ import annotations

import os

os.environ.setdefault("MPLBACKEND", "Agg")

import numpy as np  # noqa: E402
import pytest  # noqa: E402

import balancelab as bl  # noqa: E402
from balancelab.viz.animation import animate, configuration_label  # noqa: E402
from balancelab.viz.explorer import explore  # noqa: E402


def cart_pendulum():
    """A cart sliding along the ground's x-axis with a pendulum hinged on it: q = (slide m, angle rad)."""
    lk = bl.Linkage("cart and pendulum")
    lk.prismatic("ground", (0.0, 0.0), "cart", (0.0, 0.0), axis=(1.0, 0.0), stroke=(-0.3, 0.4))
    lk.revolute("cart", (0.0, 0.0), "pendulum", (0.0, 0.0))
    lk.mass("cart", 2.0)
    lk.mass("pendulum", 1.0, com=(0.3, 0.0))
    lk.spring("cart", (0.0, 0.0), "ground", (0.0, 0.0), 50.0)
    return lk.build()


def slider_crank_driven_by_its_slide():
    lk = bl.Linkage("slider-crank")
    lk.revolute("ground", (0.0, 0.0), "crank", (0.0, 0.0))
    lk.revolute("crank", (0.2, 0.0), "rod", (0.0, 0.0))
    lk.revolute("rod", (0.6, 0.0), "slider", (0.0, 0.0))
    lk.prismatic("ground", (0.0, 0.0), "slider", (0.0, 0.0), axis=(1.0, 0.0))
    lk.mass("crank", 1.0, com=(0.1, 0.0))
    lk.mass("slider", 2.0)
    return lk.build(driving=["s_1"], guess={"crank": 1.0})


def units(design):
    return bl.core.report.q_units(design)


@pytest.mark.parametrize("make", [cart_pendulum, slider_crank_driven_by_its_slide])
def test_explorer_sliders_show_a_slide_in_mm_and_an_angle_in_degrees(make):
    design = make()
    assert "m" in units(design)
    ex = explore(design)
    ex.widget  # noqa: B018  (builds the sliders)
    words = ex.slider_descriptions
    for i, (name, unit) in enumerate(zip(design.q_names, units(design))):
        slider = ex._q_sliders[name]
        lo, hi = design.q_range[i]
        if unit == "m":
            assert slider.description == f"{name} (mm)"
            assert (slider.min, slider.max) == pytest.approx((1000 * lo, 1000 * hi))
            assert "millimetres" in words[f"{name} (mm)"] and "degrees" not in words[f"{name} (mm)"]
            target = 1000 * (lo + 0.4 * (hi - lo))  # mm
            slider.value = target
            assert ex.q[i] == pytest.approx(target / 1000)  # the slide moved by that many millimetres, in metres
            assert slider.value == pytest.approx(1000 * ex.q[i])
        else:
            assert slider.description == f"{name} (deg)"
            assert (slider.min, slider.max) == pytest.approx(tuple(np.degrees([lo, hi])))
            assert "degrees" in words[f"{name} (deg)"]


def test_an_unreachable_slide_is_named_in_metres():
    design = slider_crank_driven_by_its_slide()
    ex = explore(design)
    hi = design.q_range[0, 1]
    assert not ex.set(s_1=hi + 0.5)
    assert "cannot be reached" in ex.message
    assert f"s_1 = {hi + 0.5:.4g} m" in ex.message and "°" not in ex.message


def test_frame_labels_show_a_slide_in_mm_and_an_angle_in_degrees():
    design = cart_pendulum()
    u = units(design)
    assert sorted(u) == ["m", "rad"]
    q = [0.125 if unit == "m" else np.pi / 2 for unit in u]
    shown = {"m": "125 mm", "rad": "90°"}
    assert configuration_label(design, q) == ", ".join(f"{_sym(design, i)} = {shown[unit]}" for i, unit in enumerate(u))
    anim = animate(design, frames=4)
    lo, hi = anim.path.min(axis=0), anim.path.max(axis=0)
    for i, unit in enumerate(u):
        for label, qq in zip(anim.frame_labels, anim.path):
            text = f"{round(1000 * qq[i])} mm" if unit == "m" else f"{round(np.degrees(qq[i]))}°"
            assert f"{_sym(design, i)} = {text}" in label
        if unit == "m":
            assert f"from {round(1000 * lo[i])} mm to {round(1000 * hi[i])} mm" in anim.description


def _sym(design, i):
    from balancelab.viz.energy import q_symbol
    return q_symbol(design, i)


def test_errors_about_configurations_give_a_slide_in_metres():
    design = slider_crank_driven_by_its_slide()
    lo, hi = design.q_range[0]
    with pytest.raises(bl.UnreachableConfiguration) as err:
        design.poses([hi + 0.5])
    text = str(err.value)
    assert f"{hi + 0.5:.4g} m)" in text and f"s_1 in [{lo:.4g} m, {hi:.4g} m]" in text and "°" not in text
    q = np.linspace(lo, lo + 0.01 * (hi - lo), 20)[:, None]
    with pytest.raises(ValueError, match=r"s_1 spans [0-9.e-]+ m of [0-9.e-]+ m"):
        design.balance_report(q)
