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
    lk.mass("crank", 2.0, com=(0.25, 0.0))
    if balanced_crank:
        lk.mass("crank", 2.0, com=(-0.25, 0.0), name="counterweight")
    extra(lk, force)
    return lk.build(guess={"crank": 1.0, "rocker": 1.0})


def on_the_coupler(lk, f):  # the coupler translates: equal and opposite forces at two of its points cancel
    lk.load("coupler", (0.0, f), com=(0.2, 0.0))
    lk.load("coupler", (0.0, -f), com=(0.8, 0.1))


def on_crank_and_rocker(lk, f):  # crank and rocker turn alike: opposite forces at the same local point cancel
    lk.load("crank", (f, 0.0), com=(0.5, 0.0))
    lk.load("rocker", (-f, 0.0), com=(0.5, 0.0))


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


# ---- loads or springs that cancel as a SET (outside attack, B4) ----

def _spring_lever(rel_error, extra=()):
    """Lever, 2 kg at 0.5 m, ZFL spring arm (0.25, 0) to ground (0, 0.4): k = m g l / (a b) = 98.1 N/m."""
    lk = bl.Linkage("lever")
    lk.revolute("ground", (0.0, 0.0), "arm", (0.0, 0.0))
    lk.mass("arm", 2.0, com=(0.5, 0.0))
    lk.spring("arm", (0.25, 0.0), "ground", (0.0, 0.4), 2.0 * 9.81 * 0.5 / (0.25 * 0.4) * (1 + rel_error))
    for force, at in extra:
        lk.load("arm", force, com=at)
    return lk.build()


# zero resultant and zero moment on the arm: three vertical loads that cancel as a set
_TRIPLE = [((0.0, -1000.0), (0.0, 0.0)), ((0.0, -1000.0), (1.0, 0.0)), ((0.0, 2000.0), (0.5, 0.0))]


def test_a_cancelling_set_of_three_loads_does_not_hide_an_error():
    assert _spring_lever(0.0, _TRIPLE).balance_report().balanced
    assert not _spring_lever(1e-7).balance_report().balanced
    assert not _spring_lever(1e-7, _TRIPLE).balance_report().balanced


def test_two_opposing_stiff_springs_do_not_hide_a_small_mass():
    """Two 1e9 N/m ZFL springs to (0, 0.4) and (0, -0.4) store k (|a|^2 + |b|^2): a constant; the
    1 mg at 0.5 m is not balanced by anything."""
    lk = bl.Linkage("lever")
    lk.revolute("ground", (0.0, 0.0), "arm", (0.0, 0.0))
    lk.mass("arm", 1e-6, com=(0.5, 0.0))
    lk.spring("arm", (0.25, 0.0), "ground", (0.0, 0.4), 1e9)
    lk.spring("arm", (0.25, 0.0), "ground", (0.0, -0.4), 1e9)
    assert not lk.build().balance_report().balanced


def test_balance_never_returns_a_design_its_report_calls_unbalanced():
    lk = bl.Linkage("2R")
    lk.revolute("ground", (0, 0), "L1", (0, 0))
    lk.revolute("L1", (0.5, 0), "L2", (0, 0))
    lk.mass("L1", 1, com=(0.25, 0))
    lk.mass("L2", 1, com=(0.25, 0))
    lk.load("L1", (0, 1e11), com=(0.1, 0))
    lk.load("L1", (0, -1e11), com=(0.3, 0.05))
    cands = [(("L1", (0.2, 0)), ("ground", None)), (("L2", (0.2, 0)), ("ground", None)), (("L2", (0.1, 0)), ("L1", None))]
    try:
        out = bl.balance(lk.build(), springs=cands)
    except bl.InfeasibleDesign as err:
        assert err.verdict in ("not_found", "negative", "box"), str(err)
    else:
        assert out.balance_report().balanced
