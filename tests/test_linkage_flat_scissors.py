"""BREAK8 / BREAK10 (brief b19): the scissors lift drawn flat (every bar along the x-axis, no guess)
builds on the branch of the lift, not on its folded component, at every scale from 1e-5 to 1e5."""
from __future__ import annotations

import numpy as np
import pytest

import balancelab as bl
from conftest import scissors_lift_linkage


def flat_lift(lam: float, stroke: bool = True) -> bl.Design:
    """The catalog's scissors lift at scale ``lam``, drawn flat: every local point on the x-axis,
    no ``guess=``; the bottom slider's stroke (0.01..0.49) * lam, or the default one."""
    return scissors_lift_linkage(lam, stroke).build(driving=["s_1"])


def wrap(x):
    return np.angle(np.exp(1j * x))


@pytest.mark.parametrize("lam", [1e-5, 1e-2, 1.0, 30.0, 1e5])
def test_the_flat_lift_moves_like_the_catalogs_at_every_scale(lam):
    d = flat_lift(lam)
    cat = bl.catalog()["scissors_lift"]()
    assert d.dof == 1 and d.q_names == ("s_1",)
    theta = np.linspace(0.25, 1.5, 11)
    P, ok = d.kinematics.poses(lam * 0.5 * np.cos(theta)[:, None])  # the bottom slider at a cos(theta)
    Pc, _ = cat.kinematics.poses(theta[:, None])
    assert ok.all()
    np.testing.assert_allclose(P[..., :2], lam * Pc[..., :2], atol=1e-9 * lam)  # slides and points scale by lam
    np.testing.assert_allclose(wrap(P[..., 2] - Pc[..., 2]), 0.0, atol=1e-9)  # angles do not change


def test_without_a_stroke_the_flat_lift_still_has_one_degree_of_freedom_and_lifts():
    d = flat_lift(1.0, stroke=False)
    assert d.dof == 1
    P = d.poses(d.sample(20, seed=0))
    assert (P[:, d.bodies.index("platform 8"), 1] > 0).all()  # the platform above the ground: the lift, not folded
