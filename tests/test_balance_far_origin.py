"""A linkage with a loop drawn far from the origin is balanced as at the origin (attack A19b, BREAK2).

The kinematics stores absolute positions: at 1e6 m they carry 1e-10 m of round-off, and the balancer
judged the leftover noise by a tolerance 10 times stricter than the report's, calling a slider-crank
"impossible for any rates" that its hand-built counterweight balances. Noise (the residual's
non-smooth part) is now judged by the report's tolerance and allowance; the report still settles it.
"""
from __future__ import annotations

import pytest

import balancelab as bl


def slider_crank(height: float) -> bl.Design:
    lk = bl.Linkage("slider-crank")
    lk.revolute("ground", (0, height), "crank", (0, 0))
    lk.revolute("crank", (0.2, 0), "rod", (0, 0))
    lk.revolute("rod", (0.6, 0), "slider", (0, 0))
    lk.prismatic("ground", (0, height), "slider", (0, 0), axis=(1, 0))
    lk.mass("crank", 1.0, com=(0.1, 0))
    lk.mass("rod", 1.0, com=(0.3, 0))
    lk.mass("slider", 2.0)
    return lk.build()


@pytest.mark.parametrize("height", [0.0, 1e3, 1e6])
def test_far_slider_crank_balances_like_at_the_origin(height):
    # 1 kg x 0.1 m + 1 kg x 0.2 m / 2 (the rod's centre at half the pin's height) = m x 0.6 m: m = 1/3 kg
    out = bl.balance(slider_crank(height), counterweights=[("crank", (-0.6, 0.0))])
    assert out.loads[-1].force[1] / -9.81 == pytest.approx(1 / 3, rel=1e-8)
    assert out.balance_report().balanced


@pytest.mark.parametrize("height", [0.0, 1e6])
def test_far_slider_crank_is_not_balanced_by_what_cannot(height):
    # a weight on the slider never rises: it cannot balance the crank anywhere
    with pytest.raises(bl.InfeasibleDesign):
        bl.balance(slider_crank(height), counterweights=[("slider", (0.0, 0.0))])
