"""The smooth part of an energy is judged against what the noise alone can put there (issue 19).

When the round-off allowance is all that lets a variation pass, the verdict is that of the energy's
smooth part; but a least-squares fit takes a share of pure noise as well. Below that share the smooth
part cannot be told from noise: the report then says NOT balanced and "cannot be resolved", never
NOT balanced as if the design were wrong, and never balanced.
"""
from __future__ import annotations

import sys

import numpy as np
import pytest

import balancelab as bl
from balancelab.core.smooth import smooth_resolution, smooth_split

sys.path.insert(0, "tests")
from test_report import _with_pair  # noqa: E402


def _lever_poses(m: int) -> tuple[np.ndarray, np.ndarray]:
    th = np.linspace(-2.5, 2.5, m)
    poses = np.zeros((m, 2, 3))
    poses[:, 1, 2] = th
    return poses, th[:, None]


@pytest.mark.parametrize("seed", range(20))
def test_the_fit_of_pure_noise_stays_within_the_resolution(seed):
    poses, q = _lever_poses(300)
    noise = 3e-8 * np.random.default_rng(seed).standard_normal(300)  # J
    smooth, _ = smooth_split(poses, q, ("rad",), noise)
    assert 0.0 < smooth < smooth_resolution(poses, q, ("rad",), noise)


def test_a_smooth_variation_above_the_resolution_stands_out():
    poses, q = _lever_poses(300)
    noise = 3e-8 * np.random.default_rng(1).standard_normal(300)
    res = smooth_resolution(poses, q, ("rad",), noise)
    signal = res * np.sin(q[:, 0])   # J: sin spans [-1, 1] over (-2.5, 2.5) rad, so a spread of 2 res
    smooth, _ = smooth_split(poses, q, ("rad",), signal + noise)
    assert smooth > res


def test_a_noise_drowned_smooth_part_cannot_be_resolved():
    """deepak_gravity_fourbar with two self-cancelling 10**8.5 N/m springs: exactly balanced, but their
    6e7 J energies leave 4.5e-8 J of noise against 1e-9 of 3.4 J exchanged."""
    d = _with_pair(bl.catalog()["deepak_gravity_fourbar"](), 10 ** 8.5, 0.5, 0.125)
    r = d.balance_report(n=200)
    assert r.balanced or not r.resolvable, r
    if not r.resolvable:
        assert not r.balanced and "cannot be resolved" in str(r) and "smooth part up to" in str(r)
        assert r.smooth_variation - r.smooth_resolution <= r.tolerance < r.smooth_variation


@pytest.mark.parametrize("error", [1e-3, -1e-3])
def test_an_imbalance_next_to_the_noisy_pair_stays_resolvable_and_caught(error):
    base = bl.catalog()["deepak_gravity_fourbar"]()
    springs = list(base.springs)
    s = springs[0]
    springs[0] = bl.Spring(s.k * (1.0 + error), s.free_length, s.a, s.b)
    r = _with_pair(base.replace(springs=springs), 10 ** 8.5, 0.5, 0.125).balance_report(n=200)
    assert not r.balanced and r.resolvable and r.load_variation > 1e-5, r
