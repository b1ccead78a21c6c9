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
