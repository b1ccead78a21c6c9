"""More than 16 elements that cancel across bodies still cannot hide an imbalance (issue 19, B19 item 8).

The kinematic-cancel search of the verdict's yardstick examined every subset of up to 16 elements
and skipped larger designs; beyond 16 it now solves a mixed-integer program for the heaviest set of
elements whose energies sum to a constant. The design: the parallelogram of
``test_report_kinematic_cancel`` with seven triples of large loads (1e5 to 1e8 N) (21 loads, each triple down on
crank and rocker and up on the coupler, cancelling as a triple and through the kinematics only),
the crank's weight and its balancing spring off by 1e-6. Its energy is written out by hand.
"""
from __future__ import annotations

import numpy as np
import pytest

import balancelab as bl
from balancelab.core.cancel import MAX_ENUMERATED, null_subset

G = 9.81
M, COM, A, B = 2.0, 0.25, 0.2, 0.4
K = M * G * COM / (A * B)


def triples(force: float):
    """(crank point a_i, force F_i) of the seven triples."""
    return [(0.05 + 0.06 * i, force * (1.0 + 0.37 * i)) for i in range(7)]


def parallelogram(spring_error: float, force: float = 1e5) -> bl.Design:
    lk = bl.Linkage("parallelogram, 23 elements")
    lk.revolute("ground", (0.0, 0.0), "crank", (0.0, 0.0))
    lk.revolute("crank", (0.5, 0.0), "coupler", (0.0, 0.0))
    lk.revolute("coupler", (1.0, 0.0), "rocker", (0.5, 0.0))
    lk.revolute("rocker", (0.0, 0.0), "ground", (1.0, 0.0))
    lk.mass("crank", M, at=(COM, 0.0))
    lk.spring("crank", (A, 0.0), "ground", (0.0, B), K * (1.0 + spring_error))
    for i, (a, f) in enumerate(triples(force)):
        # heights a sin t, (0.5 - a) sin t and 0.5 sin t: F a + F (0.5 - a) - F 0.5 = 0
        lk.load("crank", (0.0, -f), at=(a, 0.0))
        lk.load("rocker", (0.0, -f), at=(0.5 - a, 0.0))
        lk.load("coupler", (0.0, f), at=(0.1 * i, 0.0))
    return lk.build(guess={"crank": 1.0, "rocker": 1.0})


def by_hand(d: bl.Design, q, spring_error: float):
    """M g COM sin t + (k/2)(A^2 + B^2 - 2 A B sin t); the loads sum to zero."""
    t = d.poses(q)[:, d.bodies.index("crank"), 2]
    k = K * (1.0 + spring_error)
    return M * G * COM * np.sin(t) + 0.5 * k * (A * A + B * B - 2 * A * B * np.sin(t))


@pytest.mark.parametrize("spring_error, force", [(1e-6, 1e5), (1e-3, 1e8)])
def test_many_cancelling_loads_do_not_hide_an_imbalance(spring_error, force):
    d = parallelogram(spring_error, force)
    assert len(d.loads) + len(d.springs) > MAX_ENUMERATED + 4
    q = d.sample(400, seed=1)
    own = M * G * COM * np.ptp(np.sin(d.poses(q)[:, 1, 2]))  # J the crank's weight exchanges
    assert np.ptp(by_hand(d, q, spring_error)) > 0.5 * spring_error * own  # NOT balanced, by hand
    vl = d.element_energies(q)[0]
    assert np.ptp(vl[:, 1:].sum(-1)) < 1e-12 * sum(f for _, f in triples(force))  # the 21 loads cancel
    report = d.balance_report()
    assert not report.balanced, str(report)
    assert report.load_scale < 100.0  # the crank's weight, not the 1e8 N loads


def test_the_same_design_balanced_is_balanced():
    assert parallelogram(0.0).balance_report().balanced
    assert parallelogram(0.0, 1e8).balance_report().balanced


def test_null_subset_beyond_the_enumeration():
    """20 columns: sin t in 18 of them summing to zero in two sets of nine, plus cos t and an unbalanced
    sin t that no set may take."""
    t = np.linspace(0.0, 6.0, 300)
    coef = [1.0, 2.0, 3.0, 4.0, 5.0, 6.0, 7.0, 8.0, -36.0, 1.5, 2.5, 3.5, 4.5, 5.5, 6.5, 7.5, 8.5, -40.0]
    E = np.stack([c * np.sin(t) for c in coef] + [np.cos(t), 0.3 * np.sin(t) + 0.1 * np.cos(2 * t)], -1)
    mask = null_subset(E)
    assert mask[:18].all() and not mask[18:].any()
