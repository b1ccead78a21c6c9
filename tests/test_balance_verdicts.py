"""Issue 19, items 4-9 and 12: the general balancer finds a solution whenever one exists, and says
why not with one of three verdicts otherwise."""
from __future__ import annotations

import warnings

import numpy as np
import pytest

import balancelab as bl
from balancelab.methods.general import OBJECTIVES
from balancelab.methods.general.examples import watt_sixbar
from balancelab.methods.general.verdicts import VERDICTS
from conftest import independent_energy

G = 9.81


def lever(mass=2.0, com=0.5):
    lk = bl.Linkage("lever")
    lk.revolute("ground", (0.0, 0.0), "arm", (0.0, 0.0))
    lk.mass("arm", mass, com=(com, 0.0))
    return lk.build()


def chain(lengths, masses, coms):
    lk = bl.Linkage(f"{len(lengths)}R chain")
    prev, tip = "ground", (0.0, 0.0)
    for i, (length, mass, com) in enumerate(zip(lengths, masses, coms)):
        lk.revolute(prev, tip, f"link{i + 1}", (0.0, 0.0))
        lk.mass(f"link{i + 1}", mass, com=com)
        prev, tip = f"link{i + 1}", (length, 0.0)
    return lk.build()


def own_energy(design, q):
    """Weights and springs summed independently (conftest.independent_energy: a second bookkeeping)."""
    return independent_energy(design, q)


def assert_balanced(design):
    q = design.sample(500, seed=3)
    V = own_energy(design, q)
    weights = sum(abs(ld.force[1]) for ld in design.loads) * 2.0
    assert np.ptp(V) <= 1e-9 * weights, np.ptp(V)
    assert design.balance_report().balanced


# ------------------------------------------------------------------ item 4: both ends free
BOTH = [(lambda: chain((0.5, 0.4), (2.0, 1.0), ((0.25, 0.0), (0.2, 0.05))), "2R"),
        (lambda: chain((0.5, 0.4, 0.3), (2.0, 1.5, 1.0), ((0.25, 0.0), (0.2, 0.0), (0.15, 0.02))), "3R"),
        (watt_sixbar, "Watt")]


WIDE = ((-5.0, 5.0), (-5.0, 5.0))
BOTH_CASES = [(make, kind, box) for make, kind in BOTH for box in ((None, WIDE) if kind != "Watt" else (None,))]


@pytest.mark.parametrize("make, kind, box", BOTH_CASES,
                         ids=[f"{k}-{'default box' if b is None else '5 m box'}" for _, k, b in BOTH_CASES])
def test_two_ground_springs_per_link_with_both_ends_free_balance(make, kind, box):
    d = make()  # (the six-bar takes seconds per box: the default box only)
    cands = [(("ground", None), (b, None)) for b in d.bodies[1:] for _ in range(2)]
    fixed = [(("ground", (x, 0.3)), (b, None)) for b in d.bodies[1:] for x in (-0.2, 0.2)]
    assert_balanced(bl.balance(d, springs=fixed, box=box))  # a subset of the same candidates balances...
    assert_balanced(bl.balance(d, springs=cands, box=box))  # ...so the superset does


def test_an_impossible_both_free_set_is_proved_impossible_by_the_lifted_relaxation():
    d = chain((0.5, 0.4), (2.0, 1.0), ((0.25, 0.0), (0.2, 0.05)))
    with pytest.raises(bl.InfeasibleDesign) as err:  # springs between the links only: nothing holds the arm up
        bl.balance(d, springs=[(("link1", None), ("link2", None))])
    assert err.value.verdict == "impossible" and "impossible for any rates" in str(err.value)


# ------------------------------------------------------------------ items 5, 6: every objective alike
@pytest.mark.parametrize("seed", range(4))
def test_feasibility_does_not_depend_on_the_objective(seed):
    """Whether a balanced design exists is a property of the candidates: min_preload and min_mass
    succeed wherever min_stiffness does (five-bar and Watt, springs and counterweights together)."""
    rng = np.random.default_rng(seed)
    d = watt_sixbar() if seed % 2 else chain(rng.uniform(0.3, 0.6, 3), rng.uniform(0.5, 2, 3),
                                               [(rng.uniform(0, 0.3), 0.0) for _ in range(3)])
    springs = [(("ground", (float(rng.uniform(-0.3, 0.3)), 0.4)), (b, None)) for b in d.bodies[1:]]
    cws = [(b, None) for b in d.bodies[1:]]
    results = {}
    for objective in OBJECTIVES:
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            try:
                out = bl.balance(d, springs=springs, counterweights=cws, objective=objective)
                assert_balanced(out)
                results[objective] = "ok"
            except bl.InfeasibleDesign as e:
                results[objective] = e.verdict
    assert len(set(results.values())) == 1, results


def test_no_spring_rate_below_the_smallest_admissible_one_is_left():
    d = chain((0.5, 0.4), (2.0, 1.0), ((0.25, 0.0), (0.2, 0.05)))
    cands = [(("ground", (x, y)), (b, None)) for b in d.bodies[1:] for x, y in ((0.0, 0.3), (0.1, 0.2), (-0.1, 0.25))]
    out = bl.balance(d, springs=cands, counterweights=[("link1", None), ("link2", None)], objective="min_preload")
    assert all(s.k >= 1e-12 for s in out.springs)
    assert_balanced(out)


# ------------------------------------------------------------------ item 7: three verdicts
def test_verdict_impossible_names_only_terms_above_the_scale():
    with pytest.raises(bl.InfeasibleDesign) as err:  # an anchor off the vertical above the pivot
        bl.balance(lever(), springs=[(("arm", (0.25, 0.0)), ("ground", (0.3, 0.4)))])
    e = err.value
    assert e.verdict == "impossible" and "impossible for any rates" in str(e)
    amplitudes = [float(t.split(" J ×")[0]) for t in str(e).split("left over: ")[1].split(", ")]
    assert amplitudes and min(abs(a) for a in amplitudes) > 1e-9 * 2.0 * G * 0.5


def test_verdict_negative_names_the_candidate():
    with pytest.raises(bl.InfeasibleDesign) as err:  # an anchor below the pivot would need k < 0
        bl.balance(lever(), springs=[(("arm", (0.25, 0.0)), ("ground", (0.0, -0.4)))])
    assert err.value.verdict == "negative" and "negative rate or mass for springs[0]" in str(err.value)


def test_verdict_negative_for_fixed_points_that_are_not_antiparallel_whatever_the_box():
    """Two ground springs to link 2 of a 2R arm, both attached on the same side of its joint: their
    cross terms cos(theta_2 - theta_1) cancel only with one rate negative, so no box helps."""
    d = chain((0.5, 0.4), (2.0, 1.0), ((0.25, 0.0), (0.2, 0.0)))
    cands = [(("ground", None), ("link1", (0.2, 0.0))), (("ground", None), ("link2", (0.1, 0.0))),
             (("ground", None), ("link2", (0.3, 0.0)))]
    for box in (None, ((-5e4, 5e4), (-5e4, 5e4))):
        with pytest.raises(bl.InfeasibleDesign) as err:
            bl.balance(d, springs=cands, box=box)
        assert err.value.verdict == "negative", str(err.value)


def test_verdict_box_names_the_point_and_a_box_that_does():
    """A counterweight must sit behind the pivot (x < 0); a box in front of it cannot hold it."""
    d = lever(2.0, 0.5)
    ahead = ((0.1, 0.5), (-0.1, 0.1))
    with pytest.raises(bl.InfeasibleDesign) as err:
        bl.balance(d, counterweights=[("arm", None)], box=ahead)
    e = err.value
    assert e.verdict == "box" and "outside the box" in str(e) and "counterweights[0]" in str(e)
    out = bl.balance(d, counterweights=[("arm", None)], box=e.box)
    assert_balanced(out)
    assert out.loads[-1].point[0] < 0 and out.parameters["box_x_lo"] == e.box[0][0]


@pytest.mark.parametrize("seed", range(6))
def test_every_failure_carries_one_of_the_three_verdicts(seed):
    rng = np.random.default_rng(seed)
    d = chain(rng.uniform(0.3, 0.6, 2), rng.uniform(0.5, 2, 2), [(rng.uniform(-0.2, 0.3), 0.0) for _ in range(2)])
    cands = [(("ground", (float(rng.uniform(-0.5, 0.5)), float(rng.uniform(-0.5, 0.5)))),
              (b, (float(rng.uniform(-0.3, 0.3)), 0.0))) for b in d.bodies[1:] for _ in range(2)]
    try:
        assert_balanced(bl.balance(d, springs=cands))
    except bl.InfeasibleDesign as e:
        assert e.verdict in VERDICTS


# ------------------------------------------------------------------ item 8: silent choices
def test_a_binding_default_box_is_reported():
    s = bl.singh.serial_2r_min_preload()
    cands = [((0, None), sp.b) for sp in s.springs]
    boxed = bl.balance(s.replace(springs=()), springs=cands, objective="min_preload")
    wide = bl.balance(s.replace(springs=()), springs=cands, objective="min_preload", box=((-5, 5), (-5, 5)))
    assert boxed.balance_report().energy > wide.balance_report().energy + 1.0  # 88.5 J against 80.3 J
    assert boxed.parameters["active_bounds"] >= 1 and wide.parameters["active_bounds"] == 0
    active = {k: v for k, v in boxed.parameters.items() if k.startswith("active_") and k != "active_bounds"}
    assert active and all(abs(v) == boxed.parameters["box_x_hi"] for v in active.values())


def test_an_objective_that_ignores_the_candidates_warns():
    d = lever()
    springs = [(("arm", (0.25, 0.0)), ("ground", (0.0, 0.4))), (("arm", (0.4, 0.0)), ("ground", (0.0, 0.2)))]
    with pytest.warns(UserWarning, match="does not select a unique design"):
        assert_balanced(bl.balance(d, springs=springs, objective="min_mass"))
    with pytest.warns(UserWarning, match="does not select a unique design"):
        bl.balance(d, counterweights=[("arm", (-0.5, 0.0)), ("arm", (-0.25, 0.0))], objective="min_stiffness")
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        bl.balance(d, springs=springs, objective="min_stiffness")  # this one picks a vertex of its own


# ------------------------------------------------------------------ item 9: threads
def test_the_solver_runs_on_one_blas_thread(monkeypatch):
    from threadpoolctl import threadpool_info

    from balancelab.methods.general import balancer

    seen = []
    real = balancer.solve

    def spy(p, objective):
        seen.append(max((i["num_threads"] for i in threadpool_info()), default=1))
        return real(p, objective)

    monkeypatch.setattr(balancer, "solve", spy)
    bl.balance(lever(), springs=[(("arm", (0.25, 0.0)), ("ground", None))])
    assert seen == [1]


# ------------------------------------------------------------------ item 12
def test_mass_errors_agree_and_counts_are_integers():
    for bad in (-1.0, 0.0):
        with pytest.raises(ValueError, match=r"mass must be > 0 \(kg\), got"):
            bl.Linkage().mass("arm", bad)
    out = bl.balance(lever(), springs=[(("arm", (0.25, 0.0)), ("ground", None))])
    for key in ("conditions_rank", "free_choices", "active_bounds"):
        assert type(out.parameters[key]) is int
