"""A report's ``q`` must be able to show that the energy is constant (outside-view attack A19, BREAK5).

Configurations that repeat, that are too few, a single one, NaN, or a set on which a term of the
energy never changes (``theta_2`` only 0 or pi, ``theta_2 = theta_1`` throughout) are refused with a
ValueError naming ``q`` and what is needed. The design used is a 2R arm whose second link's weight
is unbalanced: its energy, written out here, varies by several joules.
"""
from __future__ import annotations

import numpy as np
import pytest

import balancelab as bl

G = 9.81


def arm() -> bl.Design:
    lk = bl.Linkage("2R, link-2 weight unbalanced")
    lk.revolute("ground", (0, 0), "l1", (0, 0))
    lk.revolute("l1", (1.0, 0), "l2", (0, 0))
    lk.mass("l2", 1.0, at=(0.8, 0))
    lk.spring("l1", (0.5, 0), "ground", (0, 0.4), k=G * 1.0 * 1.0 / (0.5 * 0.4))  # cancels the sin(theta_1) term only
    return lk.build()


def own_energy(q):
    """By hand: the spring cancels m g l1 sin(theta_1); m g 0.8 sin(theta_2) is left (plus a constant)."""
    return G * 0.8 * np.sin(q[:, 1])


T = np.linspace(-np.pi, np.pi, 100)


def test_the_arm_is_unbalanced_by_its_own_energy():
    d = arm()
    q = d.sample(300)
    assert np.ptp(own_energy(q)) > 10.0  # J: 2 m g 0.8 sampled
    assert not d.balance_report().balanced
    assert not d.balance_report(q).balanced


def test_second_angle_only_at_0_and_pi_is_refused():
    """BREAK5: theta_2 in {0, pi} spans the whole range, yet sin(theta_2) is 0 on every configuration."""
    q = np.r_[np.c_[T, np.zeros_like(T)], np.c_[T, np.full_like(T, np.pi - 1e-9)]]
    assert np.ptp(own_energy(q)) < 1e-7  # the energy is indeed constant there
    with pytest.raises(ValueError, match=r"^q must give each coordinate at least 5 distinct values.*theta_2 takes 2"):
        arm().balance_report(q=q)


def test_a_diagonal_is_refused():
    """theta_2 = theta_1 + 1 throughout: cos(theta_2 - theta_1) never changes."""
    q = np.c_[T, T + 1.0]
    with pytest.raises(ValueError, match=r"^q must vary every coordinate independently.*cos\(q2 - q1\)"):
        arm().balance_report(q=q)


@pytest.mark.parametrize("q, message", [
    (np.full((50, 2), 0.3), r"at least 10 distinct configurations .* got 1"),             # one point, repeated
    (np.c_[T[:9], T[:9]], r"at least 10 distinct configurations .* got 9"),                  # too few
    (np.r_[np.c_[T[:8], -T[:8]]] .repeat(5, axis=0), r"at least 10 distinct configurations .* got 8"),
    (np.array([[0.1, np.nan]] * 20), r"q \(angles in radians\) must be finite"),
])
def test_degenerate_sets_are_refused(q, message):
    with pytest.raises(ValueError, match=message):
        arm().balance_report(q=q)


def test_a_grid_and_a_sample_are_accepted():
    d = arm()
    g = np.linspace(-np.pi, np.pi, 9)
    grid = np.stack(np.meshgrid(g, g), -1).reshape(-1, 2)
    assert not d.balance_report(q=grid).balanced
    assert not d.balance_report(q=d.sample(30, seed=4)).balanced
