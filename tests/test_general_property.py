"""Issue 19, "Done when": random linkages of every kind (serial 2R and 3R, four-bars, parallelograms
drawn flat, five-bars, a Watt six-bar, slider-cranks): a design balanced by some candidates is also
found from any superset of them, every failure carries one of the three verdicts, and nothing but
``InfeasibleDesign`` escapes."""
from __future__ import annotations

import warnings

import numpy as np
import pytest

import balancelab as bl
from balancelab.methods.general import OBJECTIVES
from balancelab.methods.general.verdicts import VERDICTS
from random_linkages import KINDS, ground_springs, moving


def attempt(design, springs, counterweights, objective):
    """The balanced design, or the verdict of the failure (any other exception fails the test)."""
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")  # an objective that leaves the design arbitrary says so: not tested here
        try:
            out = bl.balance(design, springs=springs, counterweights=counterweights, objective=objective)
        except bl.InfeasibleDesign as err:
            assert getattr(err, "verdict", None) in VERDICTS, str(err)
            return err.verdict
    assert out.balance_report().balanced  # never a false "balanced"
    return out


CASES = [(kind, seed) for kind in KINDS for seed in range(2)]


@pytest.mark.parametrize("kind, seed", CASES, ids=[f"{k}-{s}" for k, s in CASES])
def test_a_superset_of_balancing_candidates_balances_too(kind, seed):
    rng = np.random.default_rng(seed)
    design = KINDS[kind](rng)
    objective = OBJECTIVES[(seed + len(kind)) % 3]
    base = ground_springs(design, np.random.default_rng(seed + 100), "moving")
    cws = [(b, None) for b in moving(design)][:1]
    first = attempt(design, base, cws, objective)
    extra = ground_springs(design, np.random.default_rng(seed + 200), "ground")
    extra += ground_springs(design, np.random.default_rng(seed + 300), "fixed")
    if kind in ("2R", "four-bar", "slider-crank"):  # springs with both ends free (slow on the big ones)
        extra += ground_springs(design, np.random.default_rng(seed + 400), "both")[:2]
    more = attempt(design, base + extra, cws + [(b, None) for b in moving(design)][1:2], objective)
    if not isinstance(first, str):
        assert not isinstance(more, str), f"the subset balanced {kind}, the superset said {more!r}"


@pytest.mark.parametrize("kind", list(KINDS))
def test_random_candidates_balance_or_carry_a_verdict(kind):
    rng = np.random.default_rng(7)
    design = KINDS[kind](rng)
    for objective in OBJECTIVES:
        attempt(design, ground_springs(design, rng, "fixed")[:2], [], objective)
