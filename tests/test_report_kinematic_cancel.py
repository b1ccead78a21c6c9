"""Issue 19 (H19c, item 1): loads (or springs) that cancel only ACROSS bodies, through the kinematics,
cannot make an unbalanced design look balanced: the verdict's yardstick leaves out every set of elements
whose energies sum to a constant, whatever bodies they act on."""
from __future__ import annotations

import numpy as np
import pytest

import balancelab as bl

G = 9.81
M, COM = 2.0, 0.25  # the crank's mass (kg) and its centre of mass on the crank (m)
A, B = 0.2, 0.4  # a ZFL spring from the crank's (A, 0) to the ground's (0, B) balances it when k A B = M g COM
K = M * G * COM / (A * B)


def triple(lk, f):
    """Down, down and up by F on crank, rocker and coupler of the parallelogram: the three points rise
    by 0.3 sin t, 0.2 sin t and 0.5 sin t (t the crank's angle), so the energies F 0.3 sin t +
    F 0.2 sin t - F 0.5 sin t sum to zero, though no two of them cancel."""
    lk.load("crank", (0.0, -f), com=(0.3, 0.0))
    lk.load("rocker", (0.0, -f), com=(0.2, 0.0))
    lk.load("coupler", (0.0, f), com=(0.3, 0.0))


def parallelogram(force=0.0, spring_error=None, extra=triple):
    """Crank (0,0)-(0.5,0), coupler, rocker pivoted at (1, 0): a parallelogram, one coordinate q."""
    lk = bl.Linkage("parallelogram")
    lk.revolute("ground", (0.0, 0.0), "crank", (0.0, 0.0))
    lk.revolute("crank", (0.5, 0.0), "coupler", (0.0, 0.0))
    lk.revolute("coupler", (1.0, 0.0), "rocker", (0.5, 0.0))
    lk.revolute("rocker", (0.0, 0.0), "ground", (1.0, 0.0))
    lk.mass("crank", M, com=(COM, 0.0))
    if spring_error is not None:
        lk.spring("crank", (A, 0.0), "ground", (0.0, B), K * (1.0 + spring_error))
    if force:
        extra(lk, force)
    return lk.build(guess={"crank": 1.0, "rocker": 1.0})


def by_hand(design, q, force, spring_error):
    """The energy (J) written out: the weight M g COM sin(t); the three loads F (0.3 + 0.2 - 0.5) sin(t) = 0;
    the spring (k/2)(A^2 + B^2 - 2 A B sin t); t the crank's angle."""
    t = design.poses(q)[:, design.bodies.index("crank"), 2]
    V = M * G * COM * np.sin(t) + force * (0.3 + 0.2 - 0.5) * np.sin(t)
    if spring_error is not None:
        k = K * (1.0 + spring_error)
        V = V + 0.5 * k * (A * A + B * B - 2.0 * A * B * np.sin(t))
    return V


@pytest.mark.parametrize("spring_error, force", [(None, 1e10), (1e-3, 1e8), (1e-6, 1e5)],
                         ids=["no spring", "spring off by 1e-3", "spring off by 1e-6"])
def test_loads_cancelling_across_three_bodies_do_not_hide_an_imbalance(spring_error, force):
    d = parallelogram(force, spring_error)
    q = d.sample(400, seed=1)
    V = by_hand(d, q, force, spring_error)
    own = M * G * COM * np.ptp(np.sin(d.poses(q)[:, 1, 2]))  # the crank's weight exchanges this much (J)
    assert np.ptp(V) > 1e-7 * own  # NOT balanced, by hand...
    vl = d.element_energies(q)[0]
    assert np.ptp(vl[:, 1:].sum(-1)) < 1e-12 * force  # ...the three loads do cancel...
    assert min(np.ptp(vl[:, i] + vl[:, j]) for i in (1, 2, 3) for j in (1, 2, 3) if i < j) > 0.1 * force  # ...no two do
    report = d.balance_report()
    assert not report.balanced, str(report)
    assert report.load_scale < 100.0  # the crank's weight, not the 1e10 N loads


def test_the_same_design_without_the_error_stays_balanced():
    for force in (0.0, 1e3, 1e8):
        assert parallelogram(force, 0.0).balance_report().balanced


def test_cancelling_loads_do_not_inflate_a_spring_loaded_yardstick():
    """A spring-loaded parallelogram (no weights, a ZFL spring fighting another) that is off, with loads
    that cancel as a set: the springs are the load and the loads' 1e10 J must not count."""
    lk = bl.Linkage("spring-loaded parallelogram")
    lk.revolute("ground", (0.0, 0.0), "crank", (0.0, 0.0))
    lk.revolute("crank", (0.5, 0.0), "coupler", (0.0, 0.0))
    lk.revolute("coupler", (1.0, 0.0), "rocker", (0.5, 0.0))
    lk.revolute("rocker", (0.0, 0.0), "ground", (1.0, 0.0))
    lk.spring("crank", (0.2, 0.0), "ground", (0.0, 0.4), 100.0)
    lk.spring("rocker", (0.2, 0.0), "ground", (1.0, -0.4), 100.0 * (1 + 1e-3))  # would balance it at exactly 100
    lk.load("coupler", (0.0, 1e10), com=(0.2, 0.0))
    lk.load("coupler", (0.0, -1e10), com=(0.7, 0.1))
    triple(lk, 1e10)
    d = lk.build(guess={"crank": 1.0, "rocker": 1.0})
    q = d.sample(300, seed=2)
    t = d.poses(q)[:, 1, 2]
    V = 0.5 * 100.0 * (0.2 ** 2 + 0.4 ** 2 - 2 * 0.2 * 0.4 * np.sin(t)) \
        + 0.5 * 100.0 * (1 + 1e-3) * (0.2 ** 2 + 0.4 ** 2 + 2 * 0.2 * 0.4 * np.sin(t))
    assert np.ptp(V) > 1e-3  # J: not balanced
    assert not d.balance_report().balanced


def test_stiff_springs_cancelling_as_a_set_do_not_hide_a_spring_loaded_error():
    """Deepak's spring-against-spring balance, off by 1e-3, next to two 1e9 N/m ZFL springs whose
    energies sum to a constant (opposite ground points, the same crank point)."""
    lk = bl.Linkage("spring-loaded lever")
    lk.revolute("ground", (0.0, 0.0), "arm", (0.0, 0.0))
    lk.spring("arm", (0.2, 0.0), "ground", (0.0, 0.4), 100.0)
    lk.spring("arm", (0.2, 0.0), "ground", (0.0, -0.4), 100.0 * (1 + 1e-3))
    lk.spring("arm", (0.3, 0.0), "ground", (0.3, 0.5), 1e9)
    lk.spring("arm", (0.3, 0.0), "ground", (-0.3, -0.5), 1e9)
    assert not lk.build().balance_report().balanced
