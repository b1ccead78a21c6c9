"""A slide is named in metres wherever a ``q`` is named (outside-view attack A19, BREAK4, BREAK11).

Error messages said "q (angles in radians)" for a slide, and the residual colour bar of the energy
map said 1/rad for an x-y table; both now take their units from ``core.report.q_units``.
"""
from __future__ import annotations

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
import pytest  # noqa: E402

import balancelab as bl  # noqa: E402
from balancelab.core.report import q_meaning  # noqa: E402


def block() -> bl.Design:
    lk = bl.Linkage("block")
    lk.prismatic("ground", (0, 0), "block", (0, 0), axis=(0, 1), stroke=(-0.5, 0.5))
    lk.mass("block", 1.0)
    lk.spring("block", (0, 0), "ground", (0, 1.0), k=50.0)
    return lk.build()


def xy_table() -> bl.Design:
    lk = bl.Linkage("xy table")
    lk.prismatic("ground", (0, 0), "xs", (0, 0), axis=(1, 0), stroke=(-0.5, 0.5))
    lk.prismatic("xs", (0, 0), "ys", (0, 0), axis=(0, 1), stroke=(-0.5, 0.5))
    lk.mass("ys", 1.0)
    lk.spring("ys", (0, 0), "ground", (0, 1.0), k=10.0)
    return lk.build()


def cart_pendulum() -> bl.Design:
    """A cart sliding along x with a pendulum on it: one slide (m) and one angle (rad)."""
    lk = bl.Linkage("cart and pendulum")
    lk.prismatic("ground", (0, 0), "cart", (0, 0), axis=(1, 0), stroke=(-0.5, 0.5))
    lk.revolute("cart", (0, 0), "arm", (0, 0))
    lk.mass("arm", 1.0, at=(0.5, 0))
    lk.spring("cart", (0, 0), "ground", (0, 0), k=10.0)
    return lk.build()


@pytest.mark.parametrize("call", [lambda d: d.poses([float("nan")]), lambda d: d.potential_energy([float("inf")]),
                                  lambda d: d.balance_report(q="x")])
def test_slide_errors_say_metres(call):
    with pytest.raises((ValueError, TypeError), match=r"^q \(slides in metres\) must"):
        call(block())


def test_mixed_coordinates_say_both():
    d = cart_pendulum()
    assert q_meaning(d) == "angles in radians and slides in metres"
    with pytest.raises(ValueError, match=r"^q \(angles in radians and slides in metres\) must be finite"):
        d.potential_energy([[0.1, np.nan]])
    assert q_meaning(bl.singh.lacoste_lever(10.0, 0.5, 0.2, 0.3)) == "angles in radians"


@pytest.mark.parametrize("build, unit", [(xy_table, "(1/m)"), (cart_pendulum, None)])
def test_residual_colour_bar_units(build, unit):
    d = build()
    units = bl.core.report.q_units(d)
    expected = unit or "(" + " or ".join("1/" + u for u in sorted(set(units), reverse=True)) + ")"
    ax = bl.energy_plot(d)
    labels = [a.get_ylabel() for a in ax.figure.axes]
    assert any(lab.startswith("|dV/dq| / scale") and lab.endswith(expected) for lab in labels), labels
    assert not any("1/rad" in lab for lab in labels) or "rad" in units
    plt.close(ax.figure)
