"""The general balancer: balanced by an energy computed here, agreement with every recipe, clear failures."""
from __future__ import annotations

import numpy as np
import pytest

import balancelab as bl
from balancelab.methods.general import free_choices
from balancelab.methods.general.examples import all_pairs, arm_3r, fourbar_issue11, parallelogram_lamp

G = 9.81


# ------------------------------------------------------------------ independent energies
def rot(angle, p):
    c, s = np.cos(angle), np.sin(angle)
    return np.stack([c * p[0] - s * p[1], s * p[0] + c * p[1]], -1)


def chain_energy(lengths, angles, masses, springs, counter=()):
    """Energy of a serial chain (link i pinned at (lengths[i-1], 0) of link i-1) from its absolute angles.

    ``masses``: (body, (x, y), kg); ``springs``: (k, (body, p), (body, p)); written from scratch here.
    """
    m = angles.shape[0]
    origins = [np.zeros((m, 2))]
    for i, length in enumerate(lengths[:-1]):
        origins.append(origins[-1] + rot(angles[:, i], (length, 0.0)))

    def world(body, p):
        if body == 0:
            return np.broadcast_to(np.asarray(p, dtype=float), (m, 2))
        return origins[body - 1] + rot(angles[:, body - 1], p)

    V = np.zeros(m)
    for body, p, kg in list(masses) + list(counter):
        V += kg * G * world(body, p)[:, 1]
    for k, (ba, pa), (bb, pb) in springs:
        d = world(ba, pa) - world(bb, pb)
        V += 0.5 * k * (d * d).sum(-1)
    return V


def fourbar_energy(fb: bl.FourBar, theta, masses, springs):
    """Energy of a four-bar placed by the closed form (bodies 0 ground, 1 crank, 2 coupler, 3 rocker)."""
    st = fb.state(theta)
    frames = {1: (st["A"], st["th2"]), 2: (st["D"], st["th3"]), 3: (st["B"], st["th4"])}

    def world(body, p):
        if body == 0:
            return complex(*p)
        origin, angle = frames[body]
        return origin + complex(*p) * np.exp(1j * angle)

    V = np.zeros(np.shape(theta))
    for body, p, kg in masses:
        V += kg * G * world(body, p).imag
    for k, (ba, pa), (bb, pb) in springs:
        V += 0.5 * k * np.abs(world(ba, pa) - world(bb, pb)) ** 2
    return V


def parts(design):
    masses = [(ld.body, ld.point, -ld.force[1] / G) for ld in design.loads]
    springs = [(s.k, s.a, s.b) for s in design.springs]
    assert all(s.is_zfl for s in design.springs)
    return masses, springs


def flat(V, reference):
    return np.ptp(V) <= 1e-9 * reference


# ------------------------------------------------------------------ random trees
def random_chain(rng, n):
    lengths = rng.uniform(0.2, 0.8, n)
    lk = bl.Linkage(f"{n}R chain")
    prev, tip = "ground", (0.0, 0.0)
    for i in range(n):
        lk.revolute(prev, tip, f"link{i + 1}", (0.0, 0.0))
        lk.mass(f"link{i + 1}", rng.uniform(0.5, 3.0), com=(rng.uniform(0.0, lengths[i]), rng.uniform(-0.1, 0.1)))
        prev, tip = f"link{i + 1}", (lengths[i], 0.0)
    return lk.build(), lengths


@pytest.mark.parametrize("seed", range(8))
@pytest.mark.parametrize("objective", ["min_stiffness", "min_preload"])
def test_random_chains_balanced_by_an_energy_written_here(seed, objective):
    rng = np.random.default_rng(seed)
    n = 2 + seed % 2
    d, lengths = random_chain(rng, n)
    out = bl.balance(d, springs=all_pairs(d), objective=objective)
    masses, springs = parts(out)
    q = rng.uniform(-np.pi, np.pi, (500, n))
    loads_only = chain_energy(lengths, q, masses, [])
    assert np.ptp(loads_only) > 0.1
    assert flat(chain_energy(lengths, q, masses, springs), np.ptp(loads_only))
    assert all(s.k > 0 for s in out.springs)
    size = max(max(lengths), max(abs(v) for ld in d.loads for v in ld.point))
    for s in out.springs:  # free ends stay in the default box
        assert -size - 1e-9 <= s.b.point[0] <= size + 1e-9 and -size - 1e-9 <= s.b.point[1] <= size + 1e-9
    assert out.balance_report().balanced


def test_objectives_pick_what_they_say_among_the_free_choices():
    arm = arm_3r()
    cands = all_pairs(arm)
    stiff = bl.balance(arm, springs=cands, objective="min_stiffness")
    low = bl.balance(arm, springs=cands, objective="min_preload")
    assert stiff.parameters["free_choices"] > 0
    total = lambda d: sum(s.k for s in d.springs)  # noqa: E731
    spring_energy = lambda d: float(np.mean(d.element_energies(d.sample(500))[1].sum(-1)))  # noqa: E731
    assert total(stiff) <= total(low) * (1 + 1e-9)
    assert spring_energy(low) <= spring_energy(stiff) * (1 + 1e-9)


def test_a_box_keeps_the_free_points_inside():
    arm = arm_3r()
    box = ((-0.2, 0.3), (-0.25, 0.25))
    out = bl.balance(arm, springs=all_pairs(arm), objective="min_stiffness", box=box)
    for s in out.springs:
        assert box[0][0] - 1e-9 <= s.b.point[0] <= box[0][1] + 1e-9
        assert box[1][0] - 1e-9 <= s.b.point[1] <= box[1][1] + 1e-9
    assert out.balance_report().balanced


# ------------------------------------------------------------------ random four-bars (loops)
@pytest.mark.parametrize("seed", range(6))
def test_random_fourbars_balanced_by_the_closed_form_energy(seed):
    rng = np.random.default_rng(100 + seed)
    while True:
        crank, coupler, rocker, ground = rng.uniform(0.2, 1.0, 4)
        try:
            bl.mechanisms.check_assembly(crank, coupler, rocker, ground)
            break
        except ValueError:
            continue
    lk = bl.Linkage("random four-bar")
    lk.revolute("ground", (0.0, 0.0), "crank", (0.0, 0.0))
    lk.revolute("crank", (crank, 0.0), "coupler", (0.0, 0.0))
    lk.revolute("coupler", (coupler, 0.0), "rocker", (rocker, 0.0))
    lk.revolute("rocker", (0.0, 0.0), "ground", (ground, 0.0))
    for body, length in (("crank", crank), ("coupler", coupler), ("rocker", rocker)):
        lk.mass(body, rng.uniform(0.5, 2.0), com=(rng.uniform(0, length), rng.uniform(-0.1, 0.1)))
    d = lk.build(guess={"crank": rng.uniform(-3, 3), "rocker": rng.uniform(-3, 3)})
    out = bl.balance(d, springs=[(("ground", None), ("crank", (crank, 0.0))),
                                 (("ground", None), ("rocker", (rocker, 0.0)))],
                     counterweights=[("crank", None), ("rocker", None)], objective="min_stiffness", box=((-2, 2), (-2, 2)))
    masses, springs = parts(out)
    kin = d.kinematics
    branch = [b for b in (1, -1) if abs(np.angle(np.exp(1j * (bl.FourBar((0, 0), (ground, 0), crank, coupler, rocker,
              (0.5, 0.0), branch=b, circuit=float(np.angle(np.exp(1j * kin.assembled[1])))).kinematics.poses(
              [[kin.assembled[1]]])[0][0, 3, 2] - kin.assembled[3])))) < 1e-8][0]
    fb = bl.FourBar((0, 0), (ground, 0), crank, coupler, rocker, (0.5, 0.0), branch=branch,
                    circuit=float(np.angle(np.exp(1j * kin.assembled[1]))))
    lo, hi = fb.kinematics.q_range[0]
    theta = np.linspace(lo, hi, 400)[1:-1]
    loads_only = fourbar_energy(fb, theta, masses[:3], [])
    assert flat(fourbar_energy(fb, theta, masses, springs), np.ptp(loads_only))


def test_the_issue_fourbar_with_both_ends_free_and_a_counterweight():
    d = fourbar_issue11()
    for objective in ("min_stiffness", "min_preload", "min_mass"):
        out = bl.balance(d, springs=[(("ground", None), ("crank", None)), (("ground", (0.0, 0.5)), ("rocker", None))],
                         counterweights=[("coupler", None)], objective=objective)
        assert out.balance_report().balanced, objective
        assert out.parameters["free_choices"] >= 1


# ------------------------------------------------------------------ agreement with the course's recipes
ZFL = [(n, e) for n, e in bl.catalog().items() if e.expected_balanced and e.family != "general"]


@pytest.mark.parametrize("name, entry", ZFL, ids=[n for n, _ in ZFL])
def test_every_zfl_recipe_of_the_catalog_is_what_the_general_solver_finds(name, entry):
    d = entry()
    if not d.springs or not all(s.is_zfl for s in d.springs):
        pytest.skip("no ZFL springs to compare (counterweights or ordinary springs)")
    keep = 0 if d.loads else 1  # a spring-loaded mechanism keeps its loading spring: it is the load
    cands = [(s.a, s.b) for s in d.springs[keep:]]
    bare = d.replace(springs=d.springs[:keep])
    count = free_choices(bare, springs=cands)
    if count.free_choices:
        pytest.skip(f"the candidates leave {count.free_choices} free choice(s): the stiffnesses are not unique")
    out = bl.balance(bare, springs=cands)
    got = [out.parameters.get(f"k{keep + i + 1}", 0.0) for i in range(len(cands))]
    np.testing.assert_allclose(got, [s.k for s in d.springs[keep:]], rtol=1e-7)


def test_a_recipe_with_free_choices_is_one_of_the_balanced_solutions():
    d = bl.catalog()["peaucellier_board"]()
    cands = [(s.a, s.b) for s in d.springs]
    assert free_choices(d.replace(springs=()), springs=cands).free_choices == 1
    out = bl.balance(d.replace(springs=()), springs=cands, objective="min_stiffness")
    assert out.balance_report().balanced
    assert sum(s.k for s in out.springs) <= sum(s.k for s in d.springs) * (1 + 1e-9)


def test_the_lamp_built_from_scratch_gets_the_lectures_springs():
    recipe = bl.catalog()["serial_2r_base_springs"]()  # lecture 35's closed form, on its own kinematics
    lamp = parallelogram_lamp()  # the same lamp from the builder: a loop, solved numerically
    assert lamp.bodies == recipe.bodies
    out = bl.balance(lamp, springs=[(s.a, s.b) for s in recipe.springs])
    np.testing.assert_allclose([s.k for s in out.springs], [s.k for s in recipe.springs], rtol=1e-9)
    q = recipe.sample(300)
    np.testing.assert_allclose(out.potential_energy(q).load, recipe.potential_energy(q).load, atol=1e-12)


def test_minimum_preload_reproduces_singh():
    s = bl.singh.serial_2r_min_preload()
    cands = [((0, None), sp.b) for sp in s.springs]  # the ground anchors are left to the solver
    out = bl.balance(s.replace(springs=()), springs=cands, objective="min_preload", box=((-5, 5), (-5, 5)))
    np.testing.assert_allclose([sp.k for sp in out.springs], [sp.k for sp in s.springs], rtol=1e-6)
    np.testing.assert_allclose([sp.a.point for sp in out.springs], [sp.a.point for sp in s.springs], atol=1e-6)
    assert abs(out.balance_report().energy - s.parameters["PE_min"]) < 1e-6 * s.parameters["PE_min"]


# ------------------------------------------------------------------ failures
def lever():
    lk = bl.Linkage("lever")
    lk.revolute("ground", (0.0, 0.0), "arm", (0.0, 0.0))
    lk.mass("arm", 2.0, com=(0.5, 0.0))
    return lk.build()


def test_a_spring_that_would_need_a_negative_rate_is_infeasible_and_named():
    with pytest.raises(bl.InfeasibleDesign, match=r"negative rate or mass for springs\[0\].*sin θ_1"):
        bl.balance(lever(), springs=[(("arm", (0.25, 0.0)), ("ground", (0.0, -0.4)))])
    with pytest.raises(bl.InfeasibleDesign, match="any sign"):  # an anchor off the vertical cannot balance
        bl.balance(lever(), springs=[(("arm", (0.25, 0.0)), ("ground", (0.3, 0.4)))])
    assert bl.InfeasibleDesign is bl.lustig.InfeasibleDesign and issubclass(bl.InfeasibleDesign, ValueError)


def test_bad_input_is_refused_by_name():
    d = lever()
    with pytest.raises(ValueError, match="objective must be one of"):
        bl.balance(d, springs=[(("arm", None), ("ground", (0.0, 0.4)))], objective="cheapest")
    with pytest.raises(ValueError, match="must name a body"):
        bl.balance(d, springs=[(("hand", None), ("ground", (0.0, 0.4)))])
    with pytest.raises(ValueError, match="to itself"):
        bl.balance(d, springs=[(("arm", None), ("arm", (0.0, 0.4)))])
    with pytest.raises(ValueError, match="at least one candidate"):
        bl.balance(d)
    with pytest.raises(ValueError, match="on the ground"):
        bl.balance(d, counterweights=[("ground", None)])
    with pytest.raises(ValueError, match="nothing to balance"):
        bl.balance(d.replace(loads=()), springs=[(("arm", None), ("ground", (0.0, 0.4)))])
    with pytest.raises(TypeError, match="Design"):
        bl.balance("lever", springs=[])


def test_free_choices_count_the_rank_of_the_conditions():
    d = lever()
    one = free_choices(d, springs=[(("arm", (0.25, 0.0)), ("ground", (0.0, 0.4)))])
    assert (one.nvar, one.rank, one.free_choices) == (1, 1, 0)
    anchor = free_choices(d, springs=[(("arm", (0.25, 0.0)), ("ground", None))])
    assert (anchor.nvar, anchor.rank, anchor.free_choices) == (3, 2, 1)  # k and the anchor's k b: k b_y fixed


def test_a_balanced_chain_satisfies_its_symbolic_balance_conditions():
    arm = arm_3r()
    out = bl.balance(arm, springs=all_pairs(arm), objective="min_stiffness")
    assert out.kinematics.independent_symbols  # a tree: every angle is a symbol
    assert out.conditions_residual() < 1e-12
    assert arm.conditions_residual() > 1e-3  # the bare arm is not balanced
