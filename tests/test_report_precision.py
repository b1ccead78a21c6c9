"""Energies too large for double precision never make a design "balanced" (outside-view attack A19).

An idle stiff spring (constant length: no torque), a far ground point or a pair of huge opposite
forces at one point add energies some 1e14 times what the loads exchange; the round-off allowance
then swamped the verdict and an unbalanced lever was reported balanced. Now the report says NOT
balanced and that the verdict cannot be resolved. Each design's energy is written out by hand.
"""
from __future__ import annotations

import numpy as np
import pytest

import balancelab as bl
from balancelab.core.report import MAX_ROUND_OFF_RATIO

G = 9.81
T = np.linspace(-np.pi, np.pi, 4001)


def _lever(spring_error: float | None = None) -> bl.Linkage:
    """2 kg at 0.5 m; with ``spring_error`` the balancing ZFL spring (0.25, 0) -> (0, 0.4), its rate off by it."""
    lk = bl.Linkage("lever")
    lk.revolute("ground", (0, 0), "arm", (0, 0))
    lk.mass("arm", 2.0, com=(0.5, 0))
    if spring_error is not None:
        lk.spring("arm", (0.25, 0), "ground", (0, 0.4), k=2 * G * 0.5 / (0.25 * 0.4) * (1 + spring_error))
    return lk


def _own_variation(spring_error: float | None) -> float:
    """The lever's energy variation by hand, over the weight's exchange 2 m g l."""
    v = 2 * G * 0.5 * np.sin(T)
    if spring_error is not None:
        k = 2 * G * 0.5 / 0.1 * (1 + spring_error)
        v = v + 0.5 * k * ((0.25 * np.cos(T)) ** 2 + (0.25 * np.sin(T) - 0.4) ** 2)
    return float(np.ptp(v)) / (2 * 2 * G * 0.5)


@pytest.mark.parametrize("k, x", [(1e12, 60.0), (1e12, 100.0), (1e6, 1e5), (1e10, 10.0)])
@pytest.mark.parametrize("spring_error", [None, 1e-4])
def test_an_idle_stiff_spring_never_hides_an_imbalance(k, x, spring_error):
    assert _own_variation(spring_error) > 1e-5            # by hand: not balanced
    lk = _lever(spring_error)
    lk.spring("arm", (0, 0), "ground", (x, 0), k=k)      # from the pivot: constant length, no torque
    r = lk.build().balance_report()
    assert not r.balanced, r
    if not r.resolvable:
        assert "cannot be resolved" in str(r)


@pytest.mark.parametrize("force, x", [(1e12, 0.5), (1e12, 1e3), (1e9, 1e6)])
@pytest.mark.parametrize("spring_error", [None, 1e-3])
def test_opposite_forces_at_one_point_never_hide_an_imbalance(force, x, spring_error):
    assert _own_variation(spring_error) > 1e-4
    lk = _lever(spring_error)
    lk.load("arm", (force, force), com=(x, 0))
    lk.load("arm", (-force, -force), com=(x, 0))
    r = lk.build().balance_report()
    assert not r.balanced, r


@pytest.mark.parametrize("k, x", [(1e3, 1.0), (1e6, 1.0)])
def test_an_exact_lever_next_to_a_moderate_idle_spring_stays_balanced(k, x):
    lk = _lever(0.0)
    lk.spring("arm", (0, 0), "ground", (x, 0), k=k)
    r = lk.build().balance_report()
    assert r.balanced and r.resolvable, r
    assert r.roundoff <= MAX_ROUND_OFF_RATIO * r.tolerance * r.load_scale


def _parallelogram(force: float, k: float) -> bl.Design:
    """Crank 0.6 m, coupler 1 m; loads F on the crank tip, F on the rocker tip and -2F on the coupler
    cancel through the kinematics; 1 kg at 0.5 m on the crank, a ZFL spring (0.25, 0) -> (0, 0.4)."""
    lk = bl.Linkage("parallelogram")
    lk.revolute("ground", (0, 0), "crank", (0, 0))
    lk.revolute("crank", (0.6, 0), "coupler", (0, 0))
    lk.revolute("coupler", (1.0, 0), "rocker", (0.6, 0))
    lk.revolute("rocker", (0, 0), "ground", (1.0, 0))
    lk.load("crank", (force, 0.3 * force), com=(0.6, 0))
    lk.load("rocker", (force, 0.3 * force), com=(0.6, 0))
    lk.load("coupler", (-2 * force, -0.6 * force), com=(0, 0))
    lk.mass("crank", 1.0, com=(0.5, 0))
    lk.spring("crank", (0.25, 0), "ground", (0, 0.4), k=k)
    return lk.build()


@pytest.mark.parametrize("force", [1e3, 1e4, 1e5])
def test_huge_loads_cancelling_across_a_loop_leave_the_exact_design_balanced(force):
    """Attack A19: the loop's solving error (joint gaps of 1e-13 m) times 1e4 N loads made the exact
    design 'NOT balanced' and ``bl.balance`` call its own spring infeasible. The exact rate by hand:
    m g r / (a b) = 1 * 9.81 * 0.5 / (0.25 * 0.4) = 49.05 N/m."""
    assert _parallelogram(force, 49.05).balance_report().balanced
    off = _parallelogram(force, 49.05 * (1 + 1e-3)).balance_report()
    assert not off.balanced and off.load_variation > 1e-4
