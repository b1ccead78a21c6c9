"""A design balanced already, plus candidates: they get rate 0 and are left out (attack A19b, BREAK1).

The balancer normalised the design's own energy by its norm; for a balanced design that energy is
round-off, so round-off became a term to cancel ("needs a negative rate ... 5.83e-07 J x sin theta_1")
while the report called the same design balanced. The balancer now asks the report's own verdict.
"""
from __future__ import annotations

import numpy as np
import pytest

import balancelab as bl

G = 9.81
BELOW = (("arm", (0.1, 0.0)), ("ground", (0.0, -0.3)))   # a positive rate adds + sin(theta) energy
ABOVE = (("arm", (0.1, 0.0)), ("ground", (0.0, 0.3)))    # a positive rate adds - sin(theta) energy


def lever(mass=2.0, length=0.5, a=0.25, b=0.4, factor=1.0) -> bl.Design:
    lk = bl.Linkage("lever")
    lk.revolute("ground", (0, 0), "arm", (0, 0))
    lk.mass("arm", mass, com=(length, 0))
    lk.spring("arm", (a, 0), "ground", (0, b), k=factor * mass * G * length / (a * b))  # k = m g l / (a b)
    return lk.build()


@pytest.mark.parametrize("objective", ["min_preload", "min_stiffness", "min_mass"])
@pytest.mark.parametrize("cand", [dict(springs=[BELOW]), dict(springs=[ABOVE]),
                                  dict(counterweights=[("arm", (0.3, 0.0))]),
                                  dict(springs=[BELOW], counterweights=[("arm", (-0.3, 0.0))])])
def test_balanced_lever_leaves_candidates_out(objective, cand):
    d = lever()
    assert d.balance_report().balanced
    out = bl.balance(d, objective=objective, **cand)
    assert out.springs == d.springs and out.loads == d.loads   # every candidate at rate or mass 0, dropped
    assert out.balance_report().balanced


def test_random_balanced_levers_never_infeasible():
    rng = np.random.default_rng(7)
    for _ in range(12):
        m, l, a, b = rng.uniform(0.1, 10.0), rng.uniform(0.1, 2.0), rng.uniform(0.05, 1.0), rng.uniform(0.05, 1.0)
        d = lever(m, l, a, b)
        cand = (("arm", tuple(rng.uniform(-1, 1, 2))), ("ground", tuple(rng.uniform(-1, 1, 2))))
        out = bl.balance(d, springs=[cand])
        assert out.springs == d.springs and out.balance_report().balanced


def test_nearly_balanced_is_still_judged():
    # 1e-6 too stiff: BELOW makes up for it with a positive rate; 1e-6 too soft: only a negative rate would
    stiff = bl.balance(lever(factor=1 + 1e-6), springs=[BELOW])
    k = stiff.springs[-1].k
    # its + k (0.1)(0.3) sin(theta) cancels the spring's excess - 1e-6 m g l sin(theta)
    assert k == pytest.approx(1e-6 * 2.0 * G * 0.5 / (0.1 * 0.3), rel=1e-4)
    with pytest.raises(bl.InfeasibleDesign) as err:
        bl.balance(lever(factor=1 - 1e-6), springs=[BELOW])
    assert err.value.verdict == "negative"


def test_balanced_slider_crank_leaves_candidates_out():
    lk = bl.Linkage("slider-crank")
    lk.revolute("ground", (0, 0), "crank", (0, 0))
    lk.revolute("crank", (0.2, 0), "rod", (0, 0))
    lk.revolute("rod", (0.6, 0), "slider", (0, 0))
    lk.prismatic("ground", (0, 0), "slider", (0, 0), axis=(1, 0))
    lk.mass("crank", 1.0, com=(0.1, 0))
    lk.mass("rod", 1.0, com=(0.3, 0))
    lk.mass("slider", 2.0)
    # the crank's 1 kg x 0.1 m plus the rod's 1 kg at half the pin's height (0.2 m / 2), the slider
    # never rises: 0.2 kg m, cancelled by 1/3 kg at -0.6 m
    lk.mass("crank", 1 / 3, com=(-0.6, 0))
    d = lk.build()
    assert d.balance_report().balanced
    for cand in (dict(counterweights=[("rod", (0.3, 0))]), dict(springs=[(("slider", (0, 0)), ("ground", (0, 0.2)))])):
        out = bl.balance(d, **cand)
        assert out.springs == d.springs and out.loads == d.loads and out.balance_report().balanced
