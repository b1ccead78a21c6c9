"""`bl.balance` at the edges (outside-view attack A19: BREAK6, BREAK7, BREAK12).

* a design balanced already, plus a candidate: the candidate comes out at zero (round-off) and is
  left out, never a ValueError from the stiffness validator (BREAK12);
* a balance that needs a rate above 1e12 N/m or below 1e-12 N/m, or a counter mass whose weight
  exceeds 1e12 N, is an ``InfeasibleDesign`` with verdict ``"limit"`` naming the value and the limit
  (BREAK6);
* a spring with both ends free on a four-bar prints nothing on stderr (LAPACK's "illegal value"
  came from an optimizer called with no free choice: BREAK7).

Every needed rate is computed here by hand: a lever of weight ``W`` at ``l`` and a ZFL spring from
``(a, 0)`` to ``(0, b)`` balance when ``k a b = W l``.
"""
from __future__ import annotations

import numpy as np
import pytest

import balancelab as bl
from balancelab.methods.general.verdicts import VERDICTS

G = 9.81


def lever(m=2.0, l=0.5, spring_k=None) -> bl.Design:
    lk = bl.Linkage("lever")
    lk.revolute("ground", (0, 0), "arm", (0, 0))
    lk.mass("arm", m, at=(l, 0))
    if spring_k is not None:
        lk.spring("arm", (0.25, 0), "ground", (0, 0.4), k=spring_k)
    return lk.build()


def own_spread(d: bl.Design, q) -> float:
    """Energy spread by hand (loads -F.r, ZFL springs k/2 |r_a - r_b|^2) from the design's poses."""
    from conftest import independent_energy

    return float(np.ptp(independent_energy(d, q)))


@pytest.mark.parametrize("objective", ["min_preload", "min_stiffness"])
@pytest.mark.parametrize("candidate", [(("arm", (0.3, 0)), ("ground", (0, 0.5))),
                                       (("arm", (0.3, 0)), ("ground", None))])
def test_balanced_already_drops_the_candidate(objective, candidate):
    """BREAK12: k = m g l / (a b) = 2 g 0.5 / (0.25 0.4) balances the lever already."""
    d = lever(spring_k=2 * G * 0.5 / (0.25 * 0.4))
    q = d.sample(200, seed=2)
    assert own_spread(d, q) <= 1e-12 * 2 * 2 * G * 0.5
    out = bl.balance(d, springs=[candidate], objective=objective)
    assert len(out.springs) == 1 and out.springs[0].k == d.springs[0].k  # nothing added
    assert out.balance_report().balanced
    assert own_spread(out, q) <= 1e-12 * 2 * 2 * G * 0.5


def test_counterweight_balanced_already():
    lk = bl.Linkage("lever")
    lk.revolute("ground", (0, 0), "arm", (0, 0))
    lk.mass("arm", 2.0, at=(0.5, 0))
    lk.mass("arm", 2.0, at=(-0.5, 0))
    out = bl.balance(lk.build(), counterweights=[("arm", (-0.3, 0))])
    assert len(out.loads) == 2 and out.balance_report().balanced


def _limit(call):
    with pytest.raises(bl.InfeasibleDesign) as info:
        call()
    assert info.value.verdict == "limit" and "limit" in VERDICTS
    return str(info.value)


def test_rate_above_the_limit():
    """W l = 100 g 1 with a = b = 1e-6 m: k = 9.81e14 N/m, above 1e12."""
    need = 100 * G * 1.0 / (1e-6 * 1e-6)
    msg = _limit(lambda: bl.balance(lever(100.0, 1.0), springs=[(("arm", (1e-6, 0)), ("ground", (0, 1e-6)))]))
    assert "springs[0] rate k" in msg and f"{need:.3g} N/m" in msg and "1e+12 N/m" in msg
    # just inside the limit: found, with the rate by hand
    found = bl.balance(lever(100.0, 1.0), springs=[(("arm", (1e-4, 0)), ("ground", (0, 1e-4)))])
    assert found.parameters["k1"] == pytest.approx(100 * G / 1e-8, rel=1e-9)


def test_rate_below_the_limit():
    """W l = 1e-9 g 1e-3 with a = b = 100 m: k = 9.81e-16 N/m, below 1e-12."""
    need = 1e-9 * G * 1e-3 / (100.0 * 100.0)
    msg = _limit(lambda: bl.balance(lever(1e-9, 1e-3), springs=[(("arm", (100.0, 0)), ("ground", (0, 100.0)))]))
    assert "below the smallest" in msg and f"{need:.3g} N/m" in msg


def test_counter_mass_above_the_limit():
    """M 1e-4 = 1e9 1e3: M = 1e16 kg, a weight of 9.8e16 N above 1e12 N."""
    msg = _limit(lambda: bl.balance(lever(1e9, 1e3), counterweights=[("arm", (-1e-4, 0))]))
    assert "counterweights[0] counter mass" in msg and "1e+16 kg" in msg


def test_one_candidate_beyond_the_limit_one_within():
    """The solver picks the admissible candidate: k = 100 g 1 / (0.5 0.5) = 3924 N/m."""
    out = bl.balance(lever(100.0, 1.0), springs=[(("arm", (1e-6, 0)), ("ground", (0, 1e-6))),
                                                  (("arm", (0.5, 0)), ("ground", (0, 0.5)))])
    assert [round(s.k, 6) for s in out.springs] == [round(100 * G / 0.25, 6)]


def test_both_free_coupler_spring_prints_nothing(capfd):
    """BREAK7: a four-bar with masses on every link and a coupler-to-ground spring with both ends free."""
    lk = bl.Linkage("fourbar")
    lk.revolute("ground", (0, 0), "crank", (0, 0))
    lk.revolute("crank", (0.4, 0), "coupler", (0, 0))
    lk.revolute("coupler", (1.0, 0), "rocker", (0.8, 0))
    lk.revolute("rocker", (0, 0), "ground", (1.0, 0))
    lk.mass("crank", 2.0, at=(0.2, 0))
    lk.mass("coupler", 5.0, at=(0.5, 0))
    lk.mass("rocker", 3.0, at=(0.4, 0))
    d = lk.build(guess={"crank": 1.0, "rocker": 1.5})
    try:
        out = bl.balance(d, springs=[(("coupler", None), ("ground", None))])
        assert out.balance_report().balanced
    except bl.InfeasibleDesign as err:
        assert err.verdict in VERDICTS
    captured = capfd.readouterr()
    assert captured.err == ""
