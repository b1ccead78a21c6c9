"""Sliders of any size, from 1 nm to 1 km (outside-view attack A19, BREAK9).

An elliptic trammel (two sliders joined by a rod of length ``l``) driven by its vertical slide, with
a mass on the vertical slider and two ZFL springs that balance it exactly: with the horizontal
slider at ``x``, the vertical at ``y`` and ``x^2 + y^2 = l^2``,
``k/2 x^2 + k/2 (y - l/2)^2 + m g y = k/2 l^2 + k l^2/8`` when ``k = 2 m g / l``.
The 1 um trammel died in an IndexError (a Newton damping relative to the slides' columns swamped
the rod's angle); every size now builds, reaches its whole stroke and is balanced.
"""
from __future__ import annotations

import numpy as np
import pytest

import balancelab as bl

G = 9.81


def trammel(length: float, mass: float = 2.0) -> bl.Design:
    lk = bl.Linkage("trammel")
    lk.prismatic("ground", (0, 0), "H", (0, 0), axis=(1, 0), stroke=(-0.9 * length, 0.9 * length))
    lk.prismatic("ground", (0, 0), "V", (0, 0), axis=(0, 1), stroke=(-0.9 * length, 0.9 * length))
    lk.revolute("H", (0, 0), "rod", (0, 0))
    lk.revolute("rod", (length, 0), "V", (0, 0))
    lk.mass("V", mass)
    k = 2 * mass * G / length
    lk.spring("H", (0, 0), "ground", (0, 0), k=k)
    lk.spring("V", (0, 0), "ground", (0, 0.5 * length), k=k)
    return lk.build(driving=["s_2"], guess={"rod": 2.0})


@pytest.mark.parametrize("length", [1e-9, 1e-6, 1e-3, 1.0, 1e3])
def test_trammel_of_any_size(length):
    d = trammel(length)
    lo, hi = d.q_range[0]
    assert lo == pytest.approx(-0.9 * length, rel=1e-9) and hi == pytest.approx(0.9 * length, rel=1e-9)
    q = d.sample(200, seed=1)
    poses = d.poses(q)
    x, y = poses[:, d.bodies.index("H"), 0], poses[:, d.bodies.index("V"), 1]
    np.testing.assert_allclose(y, q[:, 0], rtol=0, atol=1e-12 * length)  # the driving slide is V's height
    np.testing.assert_allclose(x * x + y * y, length ** 2, rtol=1e-9)  # the rod keeps its length
    r = d.balance_report()
    assert r.balanced, r
    assert d.q_names == ("s_2",) and "m" in str(r)


def test_unbalanced_trammel_is_not_balanced_at_any_size():
    """The same springs with a 1 % heavier mass: the energy varies by 0.01 m g (2 * 0.9 l)."""
    for length in (1e-9, 1e-6, 1e3):
        d = trammel(length)
        heavy = d.replace(loads=[bl.Load(d.loads[0].body, (0.0, 0.0), (0.0, -2.0 * 1.01 * G))])
        assert not heavy.balance_report().balanced
