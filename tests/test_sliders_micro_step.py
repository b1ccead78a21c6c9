"""Finite-difference steps that scale with a slide's range (outside-view attack A19b, BREAK3).

With a fixed 1e-6 step, a 1 um guide had both neighbours of every configuration out of reach and
``generalized_force`` returned 0 N (the report's residual and the explorer's readout too). A slide's
default step is now a fraction of its range; angles keep 1e-6 rad.
"""
from __future__ import annotations

import numpy as np
import pytest

import balancelab as bl
from conftest import scissors_lift_linkage

K, F, B = 100.0, 20.0, 0.3


def block(length: float) -> bl.Design:
    """A block on a guide of stroke ``length`` with a ZFL spring to (0, B length) and a push F along x."""
    lk = bl.Linkage("block")
    lk.prismatic("ground", (0, 0), "block", (0, 0), axis=(1, 0), stroke=(-0.5 * length, 0.5 * length))
    lk.spring("block", (0, 0), "ground", (0, B * length), k=K)
    lk.load("block", (F, 0.0))
    return lk.build()


@pytest.mark.parametrize("length", [1e-9, 1e-6, 1e-3, 1.0, 1e3])
def test_block_force_is_exact_at_any_stroke(length):
    # V = k/2 (s^2 + (B L)^2) - F s, so dV/ds = k s - F (N), at the ends of the stroke too
    d = block(length)
    s = np.linspace(-0.5, 0.5, 11)[:, None] * length
    # at the ends the difference is one-sided: off by k h / 2 with the step h = 1e-6 L
    np.testing.assert_allclose(d.generalized_force(s)[:, 0], K * s[:, 0] - F, rtol=1e-6, atol=K * 1e-6 * length)


def test_micro_block_report_sees_the_residual():
    d = block(1e-6)
    r = d.balance_report()
    assert not r.balanced
    assert np.max(np.abs(d.generalized_force(d.sample(50, seed=3)))) > 0.9 * F


def test_steps_scale_with_slides_only():
    d = block(1e-6)
    assert d.difference_steps()[0] == pytest.approx(1e-12)
    lever = bl.singh.lacoste_lever(10.0, 0.5, 0.2, 0.3)
    assert lever.difference_steps()[0] == 1e-6  # angles keep their step
    with pytest.raises(ValueError, match="relative"):
        d.difference_steps(0.0)


def scissors(lam: float) -> bl.Design:
    """The catalog's scissors lift rebuilt at scale ``lam`` (lengths x lam, rates / lam)."""
    cat = bl.catalog()["scissors_lift"]()
    lk = scissors_lift_linkage(lam)
    s1 = cat.springs[0]
    lk.spring(s1.a[0], tuple(np.multiply(s1.a[1], lam)), s1.b[0], tuple(np.multiply(s1.b[1], lam)),
              k=s1.k / lam, free_length=s1.free_length * lam, name="k1")
    return lk.build(driving=["s_1"], guess={"arm 2": 0.6, "arm 3": 2.5, "arm 5": 0.6, "arm 6": 2.5})


def test_scissors_lift_force_is_scale_invariant():
    # lengths x lam and rates / lam: the same forces, so dV/ds(lam s) at lam equals dV/ds(s) at 1
    unit, micro = scissors(1.0), scissors(1e-6)
    s = np.linspace(0.05, 0.45, 9)[:, None]
    big = unit.generalized_force(s)
    assert np.max(np.abs(big)) > 1.0  # the lift without its second spring is far from balanced
    np.testing.assert_allclose(micro.generalized_force(s * 1e-6), big, rtol=1e-5, atol=1e-8 * np.max(np.abs(big)))
    assert not micro.balance_report().balanced
