"""Issue 19 (H19c, item 3): a constructed solvable instance is never called not_found or impossible.
The instances are the catalog's balanced designs with their springs' ends hidden: every spring becomes a
candidate with both ends free between the same two bodies, so a balancing design is known to exist."""
from __future__ import annotations

import warnings

import numpy as np
import pytest

import balancelab as bl

FOUND = ["lacoste_lever", "serial_2r_two_springs", "lustig_case1", "general_fourbar", "deepak_gravity_fourbar"]


def hidden(name):
    design = bl.catalog()[name]()
    assert design.springs and all(s.is_zfl for s in design.springs)
    assert design.balance_report().balanced  # the solution that is hidden
    cands = [((design.bodies[s.a[0]], None), (design.bodies[s.b[0]], None)) for s in design.springs]
    return design.replace(springs=[]), cands


def solve(name):
    bare, cands = hidden(name)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        out = bl.balance(bare, springs=cands)
    q = out.sample(300, seed=4)
    vl, vs = out.element_energies(q)
    assert np.ptp(vl.sum(-1) + vs.sum(-1)) <= 1e-8 * np.ptp(vl, axis=0).sum()  # balanced, by its energies
    assert out.balance_report().balanced
    return out


@pytest.mark.parametrize("name", FOUND)
def test_a_hidden_catalog_solution_is_found_again(name):
    solve(name)


def test_the_lifted_relaxation_holds_the_hidden_solution():
    """The lifted columns (k, k p_a, k p_b, k p_a p_b^T) at the catalog's springs make the energy constant:
    the relaxation is feasible, so "impossible" can never be said here, and the search has a point to reach."""
    from balancelab.methods.general import balancer, bilinear
    from balancelab.methods.general.problem import columns

    design = bl.catalog()["lustig_case3"]()
    bare, cands = hidden("lustig_case3")
    blocks = balancer._blocks(bare, cands, [], ((-5.0, 5.0), (-5.0, 5.0)))
    bilinear._lift(blocks, blocks)
    p = columns(bare, blocks, bare.sample(200, seed=0))
    x = np.zeros(p.nvar)
    for b, s in zip(blocks, design.springs):
        pa, pb = np.asarray(s.a[1]), np.asarray(s.b[1])
        x[b.cols] = [s.k, *(s.k * pa), *(s.k * pb), *(s.k * np.outer(pa, pb)).ravel()]
    assert np.all(x[[b.cols[0] for b in blocks]] > 0)
    assert np.ptp(p.A @ x + p.v) <= 1e-12 * np.ptp(p.v)


def test_lustig_case3_hidden_is_found_again():
    """Lustig's case 3 (a spring between two moving links): no alternating start reaches it; the
    nonlinear least-squares starts (bilinear.nls_starts) do, and the result is checked by its energies."""
    solve("lustig_case3")
