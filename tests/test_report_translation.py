"""Where the origin is changes nothing (outside-view attack A19, BREAK3 and BREAK8).

The same linkage, with every ground point moved by an offset up to 1e6 times its size, must get
the same verdict and the same generalized force ``dV/dq``; ``bl.balance`` must find the spring that
balances it. Energies of far elements are taken about a ground point of the design
(:func:`balancelab.core.report.reference_point`) and ``dV/dq`` sums each element's own change, so a
far origin or an idle stiff spring costs no digits. The exact torques are written out here by hand.
"""
from __future__ import annotations

import numpy as np
import pytest
from hypothesis import given, settings, strategies as st

import balancelab as bl
from balancelab.core.report import reference_point

G = 9.81


def lever(origin=(0.0, 0.0), length=1.0, spring=True) -> bl.Design:
    """A mass ``m = 1 kg`` at ``length`` on a pivot at ``origin``, balanced by the ZFL spring
    ``(length/2, 0) -> pivot + (0, b)``; ``k = m g l / (a b_eff)`` with ``b_eff`` the anchor height the
    floats really hold (``origin_y + b`` rounds), so the spring balances exactly."""
    ox, oy = origin
    a, b = length / 2, 0.4 * length
    anchor = (ox, oy + b)
    lk = bl.Linkage("lever")
    lk.revolute("ground", (ox, oy), "arm", (0, 0))
    lk.mass("arm", 1.0, at=(length, 0))
    if spring:
        b_eff = (oy + b) - oy  # exact in floating point (Sterbenz), the height the design holds
        lk.spring("arm", (a, 0), "ground", anchor, k=G * length / (a * b_eff))
    return lk.build()


def chain(origin, masses=(1.0, 2.0), spring_k=None) -> bl.Design:
    """A 2R arm (links of 1 m and 0.8 m) on a pivot at ``origin``; optionally a ZFL spring from link 1
    to the ground above the pivot (it balances link 1's own weight only: an unbalanced design)."""
    ox, oy = origin
    lk = bl.Linkage("2R")
    lk.revolute("ground", (ox, oy), "l1", (0, 0))
    lk.revolute("l1", (1.0, 0), "l2", (0, 0))
    lk.mass("l1", masses[0], at=(0.5, 0))
    lk.mass("l2", masses[1], at=(0.6, 0))
    if spring_k is not None:
        lk.spring("l1", (0.5, 0), "ground", (ox, oy + 0.4), k=spring_k)
    return lk.build()


def fourbar(origin) -> bl.Design:
    ox, oy = origin
    lk = bl.Linkage("fourbar")
    lk.revolute("ground", (ox, oy), "crank", (0, 0))
    lk.revolute("crank", (0.4, 0), "coupler", (0, 0))
    lk.revolute("coupler", (1.0, 0), "rocker", (0.8, 0))
    lk.revolute("rocker", (0, 0), "ground", (ox + 1.0, oy))
    lk.mass("crank", 2.0, at=(0.2, 0))
    lk.mass("coupler", 5.0, at=(0.5, 0))
    lk.mass("rocker", 3.0, at=(0.4, 0))
    return lk.build(guess={"crank": 1.0, "rocker": 1.5})


@pytest.mark.parametrize("length", [1.0, 1e-3])
@pytest.mark.parametrize("height", [0.0, 1e2, 1e4, 1e6])
def test_balanced_lever_far_from_the_origin(length, height):
    """BREAK3: the exactly balanced lever, its pivot up to 1e9 times its length above the origin."""
    d = lever((0.0, height), length)
    r = d.balance_report()
    assert r.balanced and r.load_variation <= 1e-10, (height, length, r)
    # torque by hand: m g l cos(q) from the weight, - k a b_eff cos(q) from the spring: zero
    assert np.max(np.abs(d.generalized_force(np.linspace(-3, 3, 13)))) <= 1e-6 * G * length
    a, b = length / 2, 0.4 * length
    found = bl.balance(lever((0.0, height), length, spring=False),
                       springs=[(("arm", (a, 0)), ("ground", (0.0, height + b)))])
    b_eff = (height + b) - height
    assert found.parameters["k1"] == pytest.approx(G * length / (a * b_eff), rel=1e-6)


@pytest.mark.parametrize("height", [0.0, 1e6, 1e9])
def test_generalized_force_of_a_far_lever(height):
    """BREAK8 (a): a 1 mm lever of 1 kg: dV/dq = m g l cos q, wherever its pivot is."""
    lk = bl.Linkage("far lever")
    lk.revolute("ground", (0, height), "arm", (0, 0))
    lk.mass("arm", 1.0, at=(1e-3, 0))
    q = np.linspace(-3.0, 3.0, 25)
    gf = lk.build().generalized_force(q[:, None])[:, 0]
    np.testing.assert_allclose(gf, G * 1e-3 * np.cos(q), rtol=0, atol=1e-9 * G * 1e-3)


def test_idle_stiff_spring_costs_no_digits():
    """BREAK8 (b): a 1e9 N/m spring of constant length (10 m, from the pivot to the ground) stores
    5e10 J and exchanges none: dV/dq is the weight's torque m g l cos q alone."""
    lk = bl.Linkage("lever")
    lk.revolute("ground", (0, 0), "arm", (0, 0))
    lk.mass("arm", 1.0, at=(1, 0))
    lk.spring("arm", (0, 0), "ground", (10, 0), k=1e9)
    q = np.linspace(-3.0, 3.0, 25)
    gf = lk.build().generalized_force(q[:, None])[:, 0]
    np.testing.assert_allclose(gf, G * np.cos(q), rtol=0, atol=1e-6 * G)


def test_reference_point_is_a_ground_point_of_the_design():
    d = chain((3.0, -7.0))
    assert reference_point(d).tolist() == [3.0, -7.0]
    # the absolute potential energy keeps its meaning: m g y about the origin, by hand
    q = np.array([[0.3, -1.1]])
    y1 = -7.0 + 0.5 * np.sin(0.3)
    y2 = -7.0 + np.sin(0.3) + 0.6 * np.sin(-1.1)
    assert d.potential_energy(q).total[0] == pytest.approx(G * (1.0 * y1 + 2.0 * y2), rel=1e-12)


def _same(build, offset, q):
    """Verdict, load variation and dV/dq of ``build`` at the origin and moved by ``offset``."""
    d0, d1 = build((0.0, 0.0)), build(tuple(offset))
    r0, r1 = d0.balance_report(), d1.balance_report()
    g0, g1 = d0.generalized_force(q), d1.generalized_force(q)
    return r0, r1, g0, g1


@settings(max_examples=12, deadline=None)
@given(kind=st.sampled_from(["lever", "chain", "unbalanced_chain", "fourbar"]),
       ratio=st.floats(0.0, 1e6), angle=st.floats(-np.pi, np.pi))
def test_translation_leaves_verdict_and_force_unchanged(kind, ratio, angle):
    """Property: every ground point and the whole design moved by an offset up to 1e6 times the
    design's size (about 1 m here) keeps the verdict and dV/dq. The kinematics places the bodies in
    absolute coordinates, so a pose holds ``ratio`` x 1e-16 of round-off, and dV/dq (a difference over
    a step of 1e-6) agrees to about ``1e-10 ratio`` of its size: the tolerance is ``1e-9 (1 + ratio)``."""
    offset = ratio * np.array([np.cos(angle), np.sin(angle)])
    build = {"lever": lambda o: lever(o, 1.0),
             "chain": lambda o: chain(o),
             "unbalanced_chain": lambda o: chain(o, spring_k=G * 1.0 * 0.5 / (0.5 * 0.4) * 1.3),
             "fourbar": fourbar}[kind]
    q = build((0.0, 0.0)).sample(40, seed=5)
    r0, r1, g0, g1 = _same(build, offset, q)
    assert r0.balanced == r1.balanced
    assert r1.load_variation == pytest.approx(r0.load_variation, rel=1e-6, abs=1e-10)
    scale = max(float(np.abs(g0).max()), r0.load_scale)
    assert float(np.abs(g1 - g0).max()) <= 1e-9 * (1.0 + ratio) * scale
