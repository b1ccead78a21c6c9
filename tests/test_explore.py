"""The live explorer, driven from code over grids of slider values (valid and invalid)."""
from __future__ import annotations

import io
import math
import os

os.environ.setdefault("MPLBACKEND", "Agg")

import numpy as np  # noqa: E402
import pytest  # noqa: E402
from PIL import Image  # noqa: E402

import balancelab as bl  # noqa: E402
from balancelab.viz.explorer import Explorer, explore, scaled_design_factory  # noqa: E402
from test_plotting import ALL, build, two_link_arm  # noqa: E402


def lever(a_x: float = 0.2, b_y: float = 0.3) -> bl.Design:
    return bl.singh.lacoste_lever(10.0, 0.5, a_x, b_y)


def pixels(png: bytes) -> np.ndarray:
    return np.asarray(Image.open(io.BytesIO(png)).convert("RGB"))


def test_lever_explorer_over_a_grid_with_invalid_values():
    ex = explore(lever, {"a_x": (0.0, 0.5, 0.05), "b_y": (-0.1, 0.5, 0.05)})
    assert ex.values == {"a_x": 0.2, "b_y": 0.3}  # the factory's defaults
    last_valid = (0.2, 0.3)
    for a_x in np.arange(0.0, 0.51, 0.1):
        for b_y in (-0.1, 0.0, 0.15, 0.45):
            before = ex.png
            ok = ex.set(a_x=a_x, b_y=b_y)
            assert ex.values == {"a_x": a_x, "b_y": b_y}
            if a_x > 0 and b_y > 0:
                assert ok and ex.message == ""
                last_valid = (a_x, b_y)
                k = 10.0 * 0.5 / (a_x * b_y)
                assert ex.design.springs[0].k == pytest.approx(k)
                assert f"k = {k:.6g} N/m" in ex.report_text
                assert ex.report.balanced and "balanced" in ex.report_text
                # the spring is drawn from the anchor (0, b_y) to a_x along the lever
                xy = ex.drawing.springs[0].get_xydata()
                q = ex.q[0]
                np.testing.assert_allclose(xy[0], [0.0, b_y], atol=1e-12)
                np.testing.assert_allclose(xy[-1], [a_x * math.cos(q), a_x * math.sin(q)], atol=1e-12)
            else:
                assert not ok
                bad = "a_x" if a_x <= 0 else "b_y"
                assert ex.message.startswith(f"a_x = {a_x:.4g}, b_y = {b_y:.4g}: {bad} (m) must be > 0")
                assert "Traceback" not in ex.message
                assert ex.png == before  # the last valid picture stays
                assert ex.valid_values == {"a_x": last_valid[0], "b_y": last_valid[1]}
                assert ex.design.parameters["a_x"] == pytest.approx(last_valid[0])


def test_configuration_sliders_move_the_mechanism_and_marker():
    ex = explore(lever)
    for deg in (-170, -45, 0, 30, 120):
        assert ex.set(theta=math.radians(deg))
        (p,) = ex.drawing.load_segments[0][:1]
        np.testing.assert_allclose(p, [0.5 * math.cos(math.radians(deg)), 0.5 * math.sin(math.radians(deg))],
                                   atol=1e-12)
        x, y = ex.energy.marker.get_data()
        assert x[0] == pytest.approx(deg)
        assert y[0] == pytest.approx(float(ex.design.potential_energy([math.radians(deg)]).total))


def test_blitted_picture_equals_a_full_redraw():
    ex = explore(lever, {"a_x": (0.05, 0.5)})
    ex.set(a_x=0.31, theta=0.8)
    blitted = pixels(ex.png)
    ex._render(full=True)
    full = pixels(ex.png)
    assert blitted.shape == full.shape
    assert np.mean(np.any(blitted != full, axis=-1)) < 1e-3


def test_fourbar_that_cannot_assemble_keeps_the_last_picture():
    ex = explore(bl.lecture.fourbar_two_springs, {"rocker": (0.2, 2.0, 0.05)}, q=[0.2])
    assert ex.values["rocker"] == 0.6
    assert ex.set(rocker=0.9) and ex.report.balanced
    good = ex.png
    assert not ex.set(rocker=2.0)
    assert "cannot assemble" in ex.message and ex.message.startswith("rocker = 2:")
    assert ex.png == good and ex.design.parameters.get("rocker", 0.9) == pytest.approx(0.9)
    # a rocker whose crank range leaves out the current angle: the angle moves into the range
    assert ex.set(rocker=0.3)
    lo, hi = ex.design.q_range[0]
    assert lo - 1e-12 <= ex.q[0] <= hi + 1e-12
    assert bool(ex.design.reachable(ex.q))


def test_unreachable_configuration_is_refused_with_a_message():
    ex = explore(bl.singh.scissors_lift, {"length": (0.2, 0.8, 0.05)})
    hi = ex.design.q_range[0, 1]
    before = ex.png
    assert not ex.set(theta=hi + 0.5)
    assert "cannot be reached" in ex.message
    assert ex.png == before
    assert ex.set(theta=0.5 * hi) and ex.message == ""


def test_unexpected_errors_become_messages():
    def factory(x: float = 1.0):
        if x > 2:
            raise KeyError("boom")
        if x > 1.5:
            return "not a design"
        return lever(a_x=0.1 * x)

    ex = explore(factory, {"x": (0.5, 3.0)})
    assert not ex.set(x=2.5)
    assert ex.message.startswith("unexpected error (KeyError)")
    assert not ex.set(x=1.8)
    assert "must return a balancelab.Design" in ex.message
    assert ex.set(x=1.2) and ex.message == ""
    with pytest.raises(KeyError, match="unknown slider"):
        ex.set(y=1.0)


def test_exploring_a_design_scales_its_springs():
    d = bl.lecture.single_link_spring(2.0, 0.5, 0.3, 0.2)
    ex = explore(d)
    assert list(ex.params) == ["stiffness"] and ex.values["stiffness"] == 1.0
    assert ex.report.balanced
    ex.set(stiffness=1.001)  # a 1e-3 relative change of k must be reported unbalanced
    assert not ex.report.balanced
    assert ex.report_text.splitlines()[0].startswith(f"{d.name}: NOT balanced")
    assert ex.design.springs[0].k == pytest.approx(1.001 * d.springs[0].k)
    f, params = scaled_design_factory(bl.lecture.single_link_counterweight(2.0, 0.5, 4.0))
    assert params == {"counterweight": (0.5, 1.5, 0.01, 1.0)}
    assert f(counterweight=1.5).loads[-1].mass == pytest.approx(6.0)


def test_widget_sliders_drive_the_callback():
    ex = explore(bl.lecture.fourbar_two_springs, {"rocker": (0.2, 2.0, 0.05)})
    box = ex.widget
    rocker, theta = ex._sliders["rocker"], ex._q_sliders["theta"]
    assert rocker in box.children and theta in box.children
    theta.value = 10.0
    assert ex.q[0] == pytest.approx(math.radians(10.0))
    assert ex._image.value == ex.png
    rocker.value = 2.0
    assert "cannot assemble" in ex._message_html.value
    assert ex.design.parameters.get("rocker", 0.6) != 2.0
    rocker.value = 0.3  # the crank range shrinks: the angle slider follows it
    lo, hi = np.degrees(ex.design.q_range[0])
    assert theta.min == pytest.approx(lo) and theta.max == pytest.approx(hi)
    assert theta.value == pytest.approx(np.degrees(ex.q[0]))
    assert ex._message_html.value == ""
    assert "balanced" in ex._report_html.value


def test_two_dof_explorer_updates_the_map():
    ex = explore(two_link_arm, {"W2": (1.0, 10.0, 0.5)})
    assert ex.energy.image is not None
    ex.set(W2=8.0, theta_1=0.3, theta_2=-1.0)
    x, y = ex.energy.marker.get_data()
    np.testing.assert_allclose([x[0], y[0]], np.degrees([0.3, -1.0]))
    Z = np.asarray(ex.energy.image.get_array())
    assert np.ptp(Z) <= 1e-9  # flat: balanced for every W2 (k2 = W2 / b2)
    assert ex.design.parameters["k2"] == pytest.approx(8.0 / 0.3)


@pytest.mark.parametrize("name", ALL)
def test_every_design_can_be_explored(name):
    d = build(name)
    ex = Explorer(d)
    expected = getattr(bl.catalog().get(name), "expected_balanced", True)
    assert ex.report.balanced == expected
    q = d.sample(3, seed=1)
    for qq in q:
        assert ex.set(**dict(zip(d.q_names, qq)))
        np.testing.assert_allclose(ex.q, qq)
    if ex.params:
        (p,) = ex.params
        assert ex.set(**{p: 1.2}) and ex.message == ""
        assert ex.report.balanced == ex.design.balance_report().balanced
        # springs (or counterweights) that balanced varying load energy no longer do when
        # scaled; springs that only balance each other stay balanced (V scales with them)
        rep = d.balance_report()
        if rep.balanced and np.ptp(d.potential_energy(d.sample(200)).load) > 1e-6 * rep.scale:
            assert not ex.report.balanced
        assert not ex.set(**{p: 0.0}) and "must be > 0" in ex.message
    assert ex.renders >= 4


def test_bad_parameter_specs():
    with pytest.raises(ValueError, match="min < max"):
        explore(lever, {"a_x": (0.5, 0.1)})
    with pytest.raises(TypeError, match="must be"):
        explore(lever, {"a_x": "wide"})
    with pytest.raises(ValueError, match="outside"):
        explore(lever, {"a_x": (0.1, 0.5, 0.1, 0.9)})
    with pytest.raises(TypeError, match="callable"):
        explore(42)


def test_sliders_are_named_described_and_the_report_is_live():
    """The widget carries the script that names each slider's handle and makes the report live."""
    import json
    import re

    ex = explore(lambda a_x=0.2: bl.singh.lacoste_lever(10.0, 0.5, a_x, 0.3), {"a_x": (0.05, 0.4, 0.01)})
    box = ex.widget
    sliders = [c for c in box.children if c.__class__.__name__ == "FloatSlider"]
    script = [c for c in box.children if c.__class__.__name__ == "Output"]
    assert len(script) == 1
    js = script[0].outputs[0]["data"]["application/javascript"]
    spec = json.loads(re.search(r"var spec = (\{.*?\}), tries", js, re.S).group(1))
    # every slider, by its visible label, with a description that gives its range
    assert [s[1] for s in spec["sliders"]] == [s.description for s in sliders]
    for (cls, _label, text), s in zip(spec["sliders"], sliders):
        assert cls in s._dom_classes and s.tooltip == text
        assert f"from {s.min:.4g}" in text.replace(".0 ", " ") or f"from {s.min:.1f}" in text, text
    assert "aria-live" in js and "role" in js and spec["report"] in ex._report_html._dom_classes
