"""Issue 19, item 10: loads that cancel each other cannot hide an unbalanced body from the report."""
from __future__ import annotations

import numpy as np
import pytest

import balancelab as bl


def parallelogram(extra, balanced_crank=False, force=1e10):
    lk = bl.Linkage("parallelogram with huge loads")
    lk.revolute("ground", (0.0, 0.0), "crank", (0.0, 0.0))
    lk.revolute("crank", (0.5, 0.0), "coupler", (0.0, 0.0))
    lk.revolute("coupler", (1.0, 0.0), "rocker", (0.5, 0.0))
    lk.revolute("rocker", (0.0, 0.0), "ground", (1.0, 0.0))
    lk.mass("crank", 2.0, at=(0.25, 0.0))
    if balanced_crank:
        lk.mass("crank", 2.0, at=(-0.25, 0.0), name="counterweight")
    extra(lk, force)
    return lk.build(guess={"crank": 1.0, "rocker": 1.0})


def on_the_coupler(lk, f):  # the coupler translates: equal and opposite forces at two of its points cancel
    lk.load("coupler", (0.0, f), at=(0.2, 0.0))
    lk.load("coupler", (0.0, -f), at=(0.8, 0.1))


def on_crank_and_rocker(lk, f):  # crank and rocker turn alike: opposite forces at the same local point cancel
    lk.load("crank", (f, 0.0), at=(0.5, 0.0))
    lk.load("rocker", (-f, 0.0), at=(0.5, 0.0))


@pytest.mark.parametrize("extra", [on_the_coupler, on_crank_and_rocker])
def test_cancelling_loads_do_not_hide_an_unbalanced_crank(extra):
    d = parallelogram(extra)
    q = d.sample(200)
    vl = d.element_energies(q)[0]
    assert np.ptp(vl[:, 1:].sum(-1)) < 1e-5 * np.ptp(vl[:, 1])  # the two loads do cancel
    report = d.balance_report()
    assert not report.balanced
    assert report.load_scale < 100.0  # the crank's weight (about 2 * 9.81 * 0.5 J), not 1e10 J


@pytest.mark.parametrize("extra", [on_the_coupler, on_crank_and_rocker])
def test_cancelling_loads_leave_a_balanced_design_balanced(extra):
    """(Forces of 1e3 N: with 1e10 N the kinematics' round-off, 1e-12 m, is worth 0.01 J, more than the
    verdict's tolerance on the crank's 10 J, and the report rightly does not claim balance.)"""
    assert parallelogram(extra, balanced_crank=True, force=1e3).balance_report().balanced
