"""Issue 19, item 1: linkages drawn the way an engineer draws them (flat, at a change point) build
with their generic degrees of freedom, on a documented branch."""
from __future__ import annotations

import numpy as np
import pytest

import balancelab as bl


def wrap(a):
    return np.angle(np.exp(1j * np.asarray(a)))


def flat_parallelogram(crank=0.5, ground=1.0):
    """Crank and rocker ``crank`` long, coupler and ground ``ground`` long, every joint on the x-axis."""
    lk = bl.Linkage("parallelogram drawn flat")
    lk.revolute("ground", (0.0, 0.0), "crank", (0.0, 0.0))
    lk.revolute("crank", (crank, 0.0), "coupler", (0.0, 0.0))
    lk.revolute("coupler", (ground, 0.0), "rocker", (crank, 0.0))
    lk.revolute("rocker", (0.0, 0.0), "ground", (ground, 0.0))
    lk.mass("crank", 2.0, com=(crank / 2, 0.0))
    return lk


def lamp(**build):
    length, offset = 0.5, 0.1
    lk = bl.Linkage("desk lamp drawn flat")
    lk.revolute("ground", (0.0, 0.0), "link 1", (0.0, 0.0))
    lk.revolute("link 1", (length, 0.0), "link 2", (0.0, 0.0))
    lk.revolute("ground", (0.0, 0.0), "copy of link 2", (0.0, 0.0))
    lk.revolute("copy of link 2", (-offset, 0.0), "copy of link 1", (0.0, 0.0))
    lk.revolute("copy of link 1", (length, 0.0), "link 2", (-offset, 0.0))
    lk.mass("link 1", 1.0, com=(length / 2, 0.0))
    lk.mass("link 2", 1.0, com=(length / 2, 0.0))
    return lk.build(**build)


@pytest.mark.parametrize("crank, ground", [(0.5, 1.0), (0.3, 0.7), (1.2, 0.4)])
def test_a_parallelogram_drawn_flat_has_one_dof_and_stays_a_parallelogram(crank, ground):
    d = flat_parallelogram(crank, ground).build()
    kin = d.kinematics
    assert d.dof == 1 and kin.grubler == 1 and kin.redundant == 0 and kin.full_turn
    q = np.linspace(-np.pi, np.pi, 181)[:, None]
    th, ok = kin.angles(q)
    assert ok.all() and d.joint_error(q).max() < 1e-10
    np.testing.assert_allclose(wrap(th[:, 2]), 0.0, atol=1e-8)            # the coupler stays level
    np.testing.assert_allclose(wrap(th[:, 1] - th[:, 3]), 0.0, atol=1e-8)  # crank and rocker parallel


def test_a_parallelogram_drawn_flat_is_balanced_like_one_drawn_open():
    """The same parallelogram drawn flat and drawn with a guess: the same spring balances both."""
    cand = [(("crank", (0.25, 0.0)), ("ground", (0.0, 0.3)))]
    flat = bl.balance(flat_parallelogram().build(), springs=cand)
    guessed = bl.balance(flat_parallelogram().build(guess={"crank": 1.0, "rocker": 1.0}), springs=cand)
    assert flat.balance_report().balanced
    assert flat.parameters["k1"] == pytest.approx(guessed.parameters["k1"], rel=1e-9)
    assert flat.parameters["k1"] == pytest.approx(2.0 * 9.81 * 0.25 / (0.25 * 0.3), rel=1e-9)  # m g r/(b c)


def test_the_parallelogram_lamp_without_guess_has_two_dof():
    d = lamp()
    assert d.dof == 2 and d.kinematics.grubler == 2
    driven = lamp(driving=["link 1", "link 2"])
    assert driven.dof == 2 and driven.q_names == ("theta_1", "theta_2")
    q = driven.sample(300)
    assert driven.joint_error(q).max() < 1e-10
    th = driven.kinematics.angles(q)[0]
    np.testing.assert_allclose(wrap(th[:, 3] - th[:, 2]), 0.0, atol=1e-8)  # the copy of link 2 is parallel


def test_a_change_point_fourbar_drawn_folded_flat_builds():
    """s + l = p + q (crank 0.2 + ground 0.5 = coupler 0.4 + rocker 0.3),
    drawn folded on the x-axis (every joint on it, every body angle zero)."""
    lk = bl.Linkage("s + l = p + q, drawn flat")
    lk.revolute("ground", (0.0, 0.0), "crank", (0.0, 0.0))
    lk.revolute("crank", (-0.2, 0.0), "coupler", (0.0, 0.0))
    lk.revolute("coupler", (0.4, 0.0), "rocker", (-0.3, 0.0))
    lk.revolute("rocker", (0.0, 0.0), "ground", (0.5, 0.0))
    lk.mass("coupler", 1.0, com=(0.2, 0.0))
    d = lk.build()
    assert d.dof == 1
    q = d.sample(400)
    assert d.joint_error(q).max() < 1e-10
    assert np.ptp(q) > 1.0


def test_a_double_parallelogram_drawn_flat_moves():
    lk = bl.Linkage("double parallelogram drawn flat")
    lk.revolute("ground", (0.0, 0.0), "left", (0.0, 0.0))
    lk.revolute("ground", (1.0, 0.0), "right", (0.0, 0.0))
    lk.revolute("ground", (0.5, 0.0), "middle", (0.0, 0.0))
    lk.revolute("left", (0.6, 0.0), "top", (0.0, 0.0))
    lk.revolute("right", (0.6, 0.0), "top", (1.0, 0.0))
    lk.revolute("middle", (0.6, 0.0), "top", (0.5, 0.0))
    d = lk.build()
    assert d.dof == 1 and d.kinematics.redundant == 1
    q = d.sample(300)
    assert d.joint_error(q).max() < 1e-10
