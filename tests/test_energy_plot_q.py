"""energy_plot(design, q=...) refuses a configuration outside the design's range (brief b19, break 7)."""
from __future__ import annotations

import matplotlib

matplotlib.use("Agg")

import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
import pytest  # noqa: E402

import balancelab as bl  # noqa: E402


def block_on_guide(stroke=(0.0, 0.4)):
    lk = bl.Linkage("block")
    lk.prismatic("ground", (0.0, 0.0), "block", (0.0, 0.0), axis=(0.0, 1.0), stroke=stroke)
    lk.mass("block", 1.0)
    lk.spring("ground", (0.0, 1.0), "block", (0.0, 0.0), k=9.81)
    return lk.build()


@pytest.mark.parametrize("q", [2.0, -0.3, np.pi / 2 + 1e-3])
def test_an_angle_outside_the_range_is_refused_by_name(q):
    d = bl.singh.scissors_lift()  # theta in 0..90 degrees
    with pytest.raises(ValueError, match=r"q must lie in the design's range .*0\.0°\.\.90\.0°"):
        bl.energy_plot(d, q=q)
    plt.close("all")


def test_an_angle_inside_the_range_or_whole_turns_away_is_marked():
    d = bl.singh.scissors_lift()
    for q in (0.5, 0.5 + 2 * np.pi, 0.1 - 2 * np.pi, 1.5):
        ax = bl.energy_plot(d, q=q)
        x, _ = ax.energy.marker.get_data()
        assert np.degrees(np.angle(np.exp(1j * q))) == pytest.approx(float(np.asarray(x)[0]), abs=1e-9)
        plt.close("all")


def test_a_slide_outside_its_stroke_is_refused_in_metres():
    d = block_on_guide()
    with pytest.raises(ValueError, match=r"q must lie in the design's range s_1 = 0 m\.\.0\.4 m, got s_1 = 0\.5 m"):
        bl.energy_plot(d, q=0.5)
    ax = bl.energy_plot(d, q=0.2)
    assert float(np.asarray(ax.energy.marker.get_data()[0])[0]) == pytest.approx(0.2)
    plt.close("all")


def test_a_micro_stroke_is_plotted_over_its_whole_range():
    """Break 4: a 1 µm stroke: the curves sample the whole stroke (no step of an absolute size), a
    marker inside it is drawn, one just outside it is refused."""
    d = block_on_guide(stroke=(0.0, 1e-6))
    ax = bl.energy_plot(d, q=5e-7)
    x, y = ax.energy.lines["total"].get_data()
    assert len(x) == 241 and np.isfinite(y).all()
    assert float(np.min(x)) == pytest.approx(0.0, abs=1e-15) and float(np.max(x)) == pytest.approx(1e-6, rel=1e-9)
    assert np.ptp(y) == pytest.approx(9.81 / 2 * 1e-12, rel=1e-6)  # k s^2 / 2 over the stroke (k = m g / 1 m)
    with pytest.raises(ValueError, match="q must lie"):
        bl.energy_plot(d, q=1.1e-6)
    plt.close("all")
