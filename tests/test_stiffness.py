"""Stiffness-matrix method for serial chains (Lustig, Dunning & Herder 2015)."""
from __future__ import annotations

import math

import numpy as np
import pytest
import sympy as sp
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from balancelab import G, Spring
from balancelab.methods import lustig
from balancelab.methods.lustig import (LUSTIG_TOPOLOGY, LUSTIG_UNKNOWNS, InfeasibleDesign, SerialChain,
                                       balance_all_pairs, chain_parameter_names, constraint_equations,
                                       constraint_residuals, diagonal_residual, gravity_conditions,
                                       lustig_a1, lustig_alpha, lustig_b1, lustig_min_energy_pose,
                                       lustig_table3e_case, lustig_values, quadratic_energy, solve,
                                       solve_symbolic, spring2_invariant, stiffness_matrix,
                                       stiffness_matrix_symbolic, synthesize)
from balancelab.methods.lustig import solving

from conftest import assert_exactly_balanced, assert_symbolic_matches_numeric, spring_perturbations

# Table 3e as printed (solved rows above the line, inputs below).
TABLE_3E = {
    "ax1": (0, 0, -0.025, -0.025),
    "bx1": (0.1125, 0.1125, 0.1059, 0.1059),
    "by1": (0, 0, 0.0265, 0.0265),
    "bx2": (-0.0981, -0.0785, -0.0923, -0.06),
    "by2": (0, -0.0589, -0.0231, -0.0739),
    "k1": (261.6, 261.6, 261.6, 261.6),
    "k2": (600, 600, 600, 600),
    "ay1": (0.1, 0.1, 0.1, 0.1),
    "ax2": (0.15, 0.18, 0.15, 0.18),
    "ay2": (0, -0.09, 0, -0.09),
    "m2": (2, 2, 2, 2),
    "m3": (2, 2, 2, 2),
    "L2": (0.3, 0.3, 0.3, 0.3),
    "sx2": (0.1, 0.1, 0.1, 0.1),
    "sy2": (0, 0, -0.1, -0.1),
    "sx3": (0.15, 0.15, 0.15, 0.15),
    "sy3": (0, 0, 0, 0),
}
PRINTED_DECIMALS = {"k1": 1, "k2": 0, "m2": 0, "m3": 0}
CASES = (1, 2, 3, 4)


def _inputs(case):
    return {k: v for k, v in lustig_values(case, solved=False).items()}


def _all_pairs(n):
    return tuple((i, j) for j in range(1, n + 1) for i in range(j))


def _independent_energy(lengths, masses, coms, springs, q, g=G):
    """Potential energy (J) from the geometry alone, at absolute link angles ``q`` (samples, n).

    Joint positions added link by link, ``1/2 k |A - B|^2`` per ZFL spring, ``m g y`` per
    weight: nothing of the stiffness-matrix method or of ``Design``.
    """
    q = np.atleast_2d(np.asarray(q, dtype=float))
    direction = np.stack([np.cos(q), np.sin(q)], axis=2)  # (samples, n, 2)
    origins = [np.zeros((len(q), 2)), np.zeros((len(q), 2))]  # ground, body 1
    for i in range(1, len(lengths)):
        origins.append(origins[i] + lengths[i - 1] * direction[:, i - 1])

    def world(body, point):
        if body == 0:
            return np.broadcast_to(np.asarray(point, dtype=float), (len(q), 2))
        c, s = direction[:, body - 1, 0], direction[:, body - 1, 1]
        x, y = point
        return origins[body] + np.stack([c * x - s * y, s * x + c * y], axis=1)

    energy = np.zeros(len(q))
    for s in springs:
        energy += 0.5 * s.k * np.sum((world(s.a.body, s.a.point) - world(s.b.body, s.b.point)) ** 2, axis=1)
    for i, (m, com) in enumerate(zip(masses, coms)):
        energy += m * g * world(i + 1, com)[:, 1]
    return energy


# ----------------------------------------------------------------------------- Table 3e
@pytest.mark.parametrize("case", CASES)
def test_table3e_every_printed_digit(case):
    d = lustig_table3e_case(case)
    for name, row in TABLE_3E.items():
        printed = row[case - 1]
        value = d.parameters[name]
        assert round(value, PRINTED_DECIMALS.get(name, 4)) == pytest.approx(printed, abs=1e-12), name


@pytest.mark.parametrize("case", CASES)
def test_table3e_cases_balanced_and_perturbations_detected(case):
    d = lustig_table3e_case(case)
    assert d.dof == 2 and d.q_names == ("theta_1", "theta_2")
    assert_exactly_balanced(d, n=1000)
    chain = SerialChain.from_values(2, LUSTIG_TOPOLOGY, d.parameters)
    assert max(abs(v) for v in constraint_residuals(chain).values()) < 1e-12


@pytest.mark.parametrize("case", CASES)
def test_case_factories_balanced_by_an_independent_energy(case):
    # the registered zero-argument factories: the springs solve() found keep the energy,
    # summed by hand, constant over many configurations; a 1e-3 change of any spring breaks it
    d = getattr(lustig, f"lustig_case{case}")()
    assert d.name.endswith(f"case {case}")
    v = d.parameters
    lengths, masses = (v["L2"], v["L3"]), (v["m2"], v["m3"])
    coms = ((v["sx2"], v["sy2"]), (v["sx3"], v["sy3"]))
    q = np.random.default_rng(case).uniform(-np.pi, np.pi, (2000, 2))
    scale = np.ptp(_independent_energy(lengths, masses, coms, (), q))  # the unbalanced chain
    assert scale > 10.0  # J
    assert np.ptp(_independent_energy(lengths, masses, coms, d.springs, q)) < 1e-12 * scale
    perturbed = list(spring_perturbations(d))
    assert len(perturbed) >= 6  # k, a and b of both springs, less the zero coordinates
    for label, bad in perturbed:
        assert np.ptp(_independent_energy(lengths, masses, coms, bad.springs, q)) > 1e-6 * scale, label


def test_table3e_case_rejects_other_cases():
    for bad in (0, 5):  # an integer out of range: ValueError; not an integer: TypeError (core.validation)
        with pytest.raises(ValueError, match=r"case must be an integer in 1\.\.4"):
            lustig_table3e_case(bad)
    for bad in ("1", True, 1.0):
        with pytest.raises(TypeError, match=r"case must be an integer in 1\.\.4"):
            lustig_table3e_case(bad)


# ------------------------------------------------------------------------------ eq. 17
def test_eq17_constraint_equations():
    s = {name: sp.Symbol(name, real=True) for name in chain_parameter_names(2, LUSTIG_TOPOLOGY)}
    k1, k2, g, L2 = s["k1"], s["k2"], s["g"], s["L2"]
    ax1, ay1, bx1, by1 = s["ax1"], s["ay1"], s["bx1"], s["by1"]
    ax2, ay2, bx2, by2 = s["ax2"], s["ay2"], s["bx2"], s["by2"]
    m2, m3, sx2, sy2, sx3, sy3 = s["m2"], s["m3"], s["sx2"], s["sy2"], s["sx3"], s["sy3"]
    paper = {
        (1, 3): -k1 * ax1 * L2 + m2 * g * sy2,
        (1, 4): -k1 * ay1 * L2 + m2 * g * sx2 + m3 * g * L2,
        (1, 5): -k1 * (ax1 * bx1 + ay1 * by1) + m3 * g * sy3,
        (1, 6): k1 * (ax1 * by1 - ay1 * bx1) + m3 * g * sx3,
        (3, 5): k1 * bx1 * L2 - k2 * (ay2 * by2 - bx2 * (L2 - ax2)),
        (3, 6): -k1 * by1 * L2 - k2 * (ay2 * bx2 + by2 * (L2 - ax2)),
    }
    eqs = constraint_equations(2, LUSTIG_TOPOLOGY)
    assert list(eqs) == list(paper)
    for rc, expr in paper.items():
        assert sp.expand(eqs[rc].lhs - expr) == 0, rc


@pytest.mark.parametrize("n", [1, 2, 3, 4])
def test_constraint_count_and_block_structure(n):
    topo = _all_pairs(n)
    N = n + 1
    eqs = constraint_equations(n, topo)
    assert len(eqs) == N * (N - 1)
    K, _ = stiffness_matrix_symbolic(n, topo)
    assert K.shape == (2 * N, 2 * N)
    assert sp.expand(K - K.T) == sp.zeros(2 * N, 2 * N)
    # every 2x2 block is p I + s R: the even rows repeat the odd ones (Sec. II.B.4)
    for I in range(N):
        for J in range(N):
            b = K[2 * I:2 * I + 2, 2 * J:2 * J + 2]
            assert sp.expand(b[0, 0] - b[1, 1]) == 0
            assert sp.expand(b[0, 1] + b[1, 0]) == 0
    assert sp.simplify(diagonal_residual(K)) == 0


@pytest.mark.parametrize("n", [1, 2, 3])
def test_gravity_conditions_are_the_ground_row(n):
    topo = _all_pairs(n)
    eqs = constraint_equations(n, topo)
    grav = gravity_conditions(n, topo)
    g = sp.Symbol("g", real=True)
    assert len(grav) == 2 * n
    for rc, eq in eqs.items():
        assert eq.lhs.has(g) == (rc in grav), rc
    # with no springs, each gravity condition is a first moment of the weights
    K, s = stiffness_matrix_symbolic(n, ())
    for u in range(2, n + 2):
        below = sum((s[f"m{i}"] for i in range(u + 1, n + 2)), sp.S.Zero)
        assert sp.expand(K[0, 2 * u - 2] - g * s[f"m{u}"] * s[f"sy{u}"]) == 0
        assert sp.expand(K[0, 2 * u - 1] - g * (s[f"m{u}"] * s[f"sx{u}"] + below * s[f"L{u}"])) == 0


@pytest.mark.parametrize("n", [1, 2, 3, 4])
def test_stiffness_matrix_reproduces_an_independent_energy(n):
    # 1/2 Q^T K_t Q against the energy summed spring by spring and weight by weight, for a
    # random chain with a spring across every pair (one more given distal body first), any g
    rng = np.random.default_rng(40 + n)
    topo = _all_pairs(n) + ((n, 0),)
    lengths = tuple(rng.uniform(0.1, 1.0, n))
    masses = tuple(rng.uniform(0.2, 5.0, n))
    coms = tuple(map(tuple, rng.uniform(-0.3, 0.5, (n, 2))))
    springs = [Spring(rng.uniform(50, 2000), 0.0, (a, tuple(rng.uniform(-0.5, 0.5, 2))),
                      (b, tuple(rng.uniform(-0.5, 0.5, 2)))) for a, b in topo]
    chain = SerialChain(lengths, masses, coms, tuple(springs))
    g = rng.uniform(1.0, 20.0)
    q = rng.uniform(-np.pi, np.pi, (300, n))
    want = _independent_energy(lengths, masses, coms, springs, q, g)
    assert np.ptp(want) > 1.0  # J: the random chain is far from balanced
    trig = np.stack([np.cos(q), np.sin(q)], axis=2).reshape(len(q), 2 * n)
    Q = np.hstack([np.ones((len(q), 1)), np.zeros((len(q), 1)), trig])
    K = stiffness_matrix(chain, g)
    atol = 1e-12 * np.abs(want).max()
    np.testing.assert_allclose(0.5 * np.einsum("si,ij,sj->s", Q, K, Q), want, rtol=0, atol=atol)
    np.testing.assert_allclose(quadratic_energy(chain, q, g), want, rtol=0, atol=atol)


# ------------------------------------------------------- symbolic vs numeric, energy
def _random_chain(rng, n, topo):
    lengths = rng.uniform(0.1, 1.0, n)
    masses = rng.uniform(0.2, 5.0, n)
    coms = rng.uniform(-0.3, 0.5, (n, 2))
    springs = [Spring(rng.uniform(50, 2000), 0.0, (a, tuple(rng.uniform(-0.5, 0.5, 2))),
                      (b, tuple(rng.uniform(-0.5, 0.5, 2)))) for a, b in topo]
    return SerialChain(tuple(lengths), tuple(masses), tuple(map(tuple, coms)), tuple(springs))


@pytest.mark.parametrize("n", [1, 2, 3, 4])
def test_symbolic_and_numeric_stiffness_matrices_agree(n):
    rng = np.random.default_rng(n)
    topo = _all_pairs(n) + ((0, n),)
    chain = _random_chain(rng, n, topo)
    K, syms = stiffness_matrix_symbolic(n, topo)
    subs = {syms[k]: v for k, v in chain.values().items()}
    Ks = np.array(K.xreplace(subs).evalf(), dtype=float)
    Kn = stiffness_matrix(chain)
    np.testing.assert_allclose(Ks, Kn, rtol=1e-12, atol=1e-12 * np.abs(Kn).max())
    res = constraint_residuals(chain)
    eqs = constraint_equations(n, topo)
    for rc, eq in eqs.items():
        assert float(eq.lhs.xreplace(subs)) == pytest.approx(res[rc], rel=1e-12, abs=1e-12)


@pytest.mark.parametrize("n", [1, 2, 3, 4])
def test_quadratic_form_is_the_design_energy(n):
    rng = np.random.default_rng(10 + n)
    topo = _all_pairs(n)
    chain = _random_chain(rng, n, topo)
    d = chain.design()
    q = rng.uniform(-np.pi, np.pi, (50, n))
    np.testing.assert_allclose(quadratic_energy(chain, q), d.potential_energy(q).total,
                               rtol=1e-12, atol=1e-12)


@pytest.mark.parametrize("n", [2, 3])
def test_symbolic_energy_matches_numeric_energy(n):
    rng = np.random.default_rng(20 + n)
    topo = _all_pairs(n)
    chain = _random_chain(rng, n, topo)
    d = chain.design(symbolic=True)
    assert_symbolic_matches_numeric(d, samples=7)
    # the design's parametric energy is 1/2 Q^T K_t Q in the same symbols
    K, syms = stiffness_matrix_symbolic(n, topo)
    th = d.kinematics.symbols()
    Q = sp.Matrix([1, 0] + [f(t) for t in th for f in (sp.cos, sp.sin)])
    quad = (Q.T * K * Q)[0, 0] / 2
    expr = d.potential_energy_symbolic()
    f1 = sp.lambdify(list(th) + list(syms.values()), quad)
    f2 = sp.lambdify(list(th) + list(syms.values()), expr)
    vals = [chain.values()[k] for k in syms]
    for q in rng.uniform(-np.pi, np.pi, (5, n)):
        assert f1(*q, *vals) == pytest.approx(f2(*q, *vals), rel=1e-12)
        assert f1(*q, *vals) == pytest.approx(float(quadratic_energy(chain, q)), rel=1e-12)


@pytest.mark.parametrize("case", [1, 4])
def test_case_symbolic_energy(case):
    assert_symbolic_matches_numeric(lustig_table3e_case(case), samples=7)


# ----------------------------------------------------------------- eqs 18-20, Fig. 4
def test_eq19_is_the_solution_for_b1():
    K, s = stiffness_matrix_symbolic(2, LUSTIG_TOPOLOGY)
    sols = solve_symbolic(2, LUSTIG_TOPOLOGY, LUSTIG_UNKNOWNS)
    assert len(sols) == 1
    b = {s[k]: v for k, v in sols[0].items()}
    L2, m2, m3 = s["L2"], s["m2"], s["m3"]
    sx2, sy2, sx3, sy3 = s["sx2"], s["sy2"], s["sx3"], s["sy3"]
    den = (L2 * m3 + m2 * sx2) ** 2 + m2 ** 2 * sy2 ** 2
    eq19a = (L2 ** 2 * m3 ** 2 * sx3 + L2 * m2 * m3 * (sx2 * sx3 + sy2 * sy3)) / den
    eq19b = (L2 ** 2 * m3 ** 2 * sy3 + L2 * m2 * m3 * (sx2 * sy3 - sx3 * sy2)) / den
    assert sp.simplify(b[s["bx1"]] - eq19a) == 0
    assert sp.simplify(b[s["by1"]] - eq19b) == 0
    # B1 does not depend on any spring parameter
    assert not (b[s["bx1"]].free_symbols | b[s["by1"]].free_symbols) & {
        s["k2"], s["ay1"], s["ax2"], s["ay2"], s["g"]}
    for case in CASES:
        v = lustig_values(case)
        assert lustig_b1(v) == pytest.approx((v["bx1"], v["by1"]), rel=1e-12, abs=1e-15)


def test_eq20_ground_anchor_inverse_to_k1():
    K, s = stiffness_matrix_symbolic(2, LUSTIG_TOPOLOGY)
    eqs = constraint_equations(2, LUSTIG_TOPOLOGY)
    sol = sp.solve([eqs[(1, 3)].lhs, eqs[(1, 4)].lhs], [s["ax1"], s["ay1"]], dict=True)[0]
    g, L2, k1 = s["g"], s["L2"], s["k1"]
    assert sp.simplify(sol[s["ax1"]] - s["m2"] * g * s["sy2"] / L2 / k1) == 0
    assert sp.simplify(sol[s["ay1"]] - (s["m2"] * g * s["sx2"] + s["m3"] * g * L2) / L2 / k1) == 0
    for case in CASES:
        v = lustig_values(case, solved=False)
        for k1 in (100.0, 261.6, 900.0):
            ax1, ay1 = lustig_a1(dict(v, k1=k1))
            # eq. 20: k1 |A1| is fixed, and ax1/ay1 = tan(alpha) (eq. 20c)
            assert k1 * math.hypot(ax1, ay1) == pytest.approx(
                261.6 * math.hypot(*lustig_a1(dict(v, k1=261.6))), rel=1e-12)
            assert math.atan2(ax1, ay1) == pytest.approx(lustig_alpha(v), abs=1e-14)
            d = synthesize(2, LUSTIG_TOPOLOGY, dict(v, k1=k1, ay1=ay1),
                           ("ax1", "bx1", "by1", "bx2", "by2"))
            assert d.parameters["ax1"] == pytest.approx(ax1, rel=1e-12, abs=1e-15)
            assert d.balance_report(n=1000).balanced


def _gravity_energy(v, q):
    t2, t3 = q
    y_s2 = v["sx2"] * math.sin(t2) + v["sy2"] * math.cos(t2)
    y_s3 = v["L2"] * math.sin(t2) + v["sx3"] * math.sin(t3) + v["sy3"] * math.cos(t3)
    return G * (v["m2"] * y_s2 + v["m3"] * y_s3)


def _cross(o, a, b):
    return (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0])


@pytest.mark.parametrize("case", CASES)
def test_eq18_min_energy_pose_and_fig4_alignments(case):
    from scipy.optimize import minimize

    v = lustig_values(case)
    q0 = lustig_min_energy_pose(v)
    # eq. 18: it is the minimum of the unbalanced chain's gravity energy
    best = minimize(lambda q: _gravity_energy(v, q), q0 + 0.3, method="BFGS", options={"gtol": 1e-12})
    diff = (best.x - q0 + np.pi) % (2 * np.pi) - np.pi
    np.testing.assert_allclose(diff, 0.0, atol=1e-6)
    assert lustig_alpha(v) == pytest.approx(
        math.atan(v["m2"] * v["sy2"] / (v["m2"] * v["sx2"] + v["m3"] * v["L2"])), abs=1e-15)
    # Fig. 4c: A1, J1, J2, B1 on one line; A2, J2, B2 on one line
    d = lustig_table3e_case(case)
    names = ["A1", "J1", "J2", "B1", "A2", "B2"]
    P = dict(zip(names, d.world_points(q0, [d.labels[k] for k in names])))
    for a, b in (("A1", "J2"), ("B1", "J2")):
        assert abs(_cross(P["J1"], P[a], P[b])) < 1e-14
    assert abs(_cross(P["J2"], P["A2"], P["B2"])) < 1e-14
    # A1 is above J1, on the far side from the hanging link 2
    assert np.dot(P["A1"] - P["J1"], P["J2"] - P["J1"]) < 0


def test_spring2_invariant_over_the_family():
    rng = np.random.default_rng(7)
    for case in CASES:
        base = lustig_values(case)
        const = base["k1"] * base["L2"] * math.hypot(base["bx1"], base["by1"])
        assert spring2_invariant(base) == pytest.approx(const, rel=1e-12)
        known = {k: x for k, x in base.items() if k not in ("bx2", "by2")}
        for _ in range(6):
            r, beta = rng.uniform(0.02, 0.4), rng.uniform(-np.pi, np.pi)
            k2 = rng.uniform(100.0, 3000.0)
            fam = dict(known, k2=k2, ax2=base["L2"] + r * math.cos(beta), ay2=r * math.sin(beta))
            sol = solve(2, LUSTIG_TOPOLOGY, fam, ("bx2", "by2"))
            fam.update(sol)
            assert spring2_invariant(fam) == pytest.approx(const, rel=1e-12)
            # B2 turns with A2 about J2 (Fig. 3b, 4c): arg(B2) - arg(A2 - J2) = arg(B1)
            turn = math.atan2(sol["by2"], sol["bx2"]) - beta - math.atan2(base["by1"], base["bx1"])
            assert (turn + np.pi) % (2 * np.pi) - np.pi == pytest.approx(0.0, abs=1e-12)
            d = SerialChain.from_values(2, LUSTIG_TOPOLOGY, fam).design()
            assert d.balance_report(n=1000).balanced


def test_spring2_rotates_with_a2():
    # case 1 -> case 2 turns A2 about J2; B2 turns by the same angle (Sec. III.A)
    v1, v2 = lustig_values(1), lustig_values(2)
    turn_a = math.atan2(v2["ay2"], v2["ax2"] - v2["L2"]) - math.atan2(v1["ay2"], v1["ax2"] - v1["L2"])
    turn_b = math.atan2(v2["by2"], v2["bx2"]) - math.atan2(v1["by2"], v1["bx2"])
    assert (turn_a - turn_b + np.pi) % (2 * np.pi) - np.pi == pytest.approx(0.0, abs=1e-12)


# --------------------------------------------------------------------------- solving
def test_solve_cached_symbolic_solution():
    solving._symbolic_solution.cache_clear()
    v = _inputs(2)
    solve(2, LUSTIG_TOPOLOGY, v, LUSTIG_UNKNOWNS)
    before = solving._symbolic_solution.cache_info()
    solve(2, LUSTIG_TOPOLOGY, v, LUSTIG_UNKNOWNS)
    after = solving._symbolic_solution.cache_info()
    assert after.hits == before.hits + 1 and after.misses == before.misses


@pytest.mark.parametrize("n", [2, 3, 4])
def test_symbolic_solve_agrees_with_numeric_all_pairs(n):
    d = balance_all_pairs((0.4, 0.3, 0.25, 0.2)[:n], (3.0, 2.0, 1.0, 0.5)[:n],
                          ((0.2, 0.01), (0.15, -0.02), (0.1, 0.0), (0.1, 0.03))[:n], k=800.0)
    topo = _all_pairs(n)
    unknowns = tuple(f"b{c}{j}" for j in range(1, len(topo) + 1) for c in "xy")
    sol = solve(n, topo, d.parameters, unknowns)
    for k in unknowns:
        assert sol[k] == pytest.approx(d.parameters[k], rel=1e-10, abs=1e-13)
    d2 = synthesize(n, topo, {k: v for k, v in d.parameters.items() if k not in unknowns}, unknowns)
    assert_exactly_balanced(d2)


def test_solve_errors():
    v = _inputs(1)
    with pytest.raises(ValueError, match="not parameters"):
        solve(2, LUSTIG_TOPOLOGY, v, ("k9",))
    with pytest.raises(ValueError, match="empty"):
        solve(2, LUSTIG_TOPOLOGY, v, ())
    with pytest.raises(ValueError, match="repeated"):
        solve(2, LUSTIG_TOPOLOGY, v, ("k1", "k1"))
    with pytest.raises(ValueError, match="missing"):
        solve(2, LUSTIG_TOPOLOGY, {k: x for k, x in v.items() if k != "m2"}, LUSTIG_UNKNOWNS)
    with pytest.raises(ValueError, match="not parameters of this chain"):
        solve(2, LUSTIG_TOPOLOGY, dict(v, zz=1.0), LUSTIG_UNKNOWNS)
    with pytest.raises(ValueError, match="do not enter"):
        solve(2, LUSTIG_TOPOLOGY, lustig_values(1), ("L3",))
    with pytest.raises(ValueError, match="more|underdetermined"):
        solve(2, LUSTIG_TOPOLOGY, v, LUSTIG_UNKNOWNS + ("ay1",))
    with pytest.raises(ValueError, match="> 0"):
        solve(2, LUSTIG_TOPOLOGY, dict(v, m2=0.0), LUSTIG_UNKNOWNS)
    with pytest.raises(ValueError, match="> 0"):
        solve(2, LUSTIG_TOPOLOGY, dict(v, k2=-600.0), LUSTIG_UNKNOWNS)


def test_solve_singular_choice_is_reported():
    full = lustig_values(1)
    # spring 2's five parameters against its two conditions: infinitely many solutions
    with pytest.raises(ValueError, match="singular"):
        solve(2, LUSTIG_TOPOLOGY, full, ("k2", "ax2", "bx2", "by2", "ay2", "k1"))


def test_solve_no_solution_is_reported():
    full = dict(lustig_values(1), k1=300.0)  # inconsistent with the gravity conditions
    with pytest.raises(ValueError, match="no solution"):
        solve(2, LUSTIG_TOPOLOGY, full, ("bx2", "by2"))


def test_negative_stiffness_is_infeasible():
    full = dict(lustig_values(1))
    full["bx2"] = -full["bx2"]  # B2 on the same side as A2: spring 2 would have to push
    with pytest.raises(InfeasibleDesign, match="k2"):
        solve(2, LUSTIG_TOPOLOGY, full, ("k2", "by2"))
    assert issubclass(InfeasibleDesign, ValueError)


def test_synthesize_rejects_other_gravity():
    with pytest.raises(ValueError, match="9.81"):
        synthesize(2, LUSTIG_TOPOLOGY, dict(_inputs(1), g=9.8), LUSTIG_UNKNOWNS)


def test_solve_with_other_gravity_scales_k1():
    v = dict(_inputs(1), g=1.62)
    assert solve(2, LUSTIG_TOPOLOGY, v, LUSTIG_UNKNOWNS)["k1"] == pytest.approx(261.6 * 1.62 / 9.81)


# ------------------------------------------------------------------------ bad inputs
def test_chain_bad_inputs():
    ok = dict(lengths=(0.3, 0.3), masses=(2.0, 2.0), coms=((0.1, 0.0), (0.15, 0.0)))
    with pytest.raises(ValueError, match="lengths"):
        SerialChain(**dict(ok, lengths=(0.3, 0.0)))
    with pytest.raises(ValueError, match="lengths"):
        SerialChain(**dict(ok, lengths=(-0.3, 0.3)))
    with pytest.raises(ValueError, match="masses"):
        SerialChain(**dict(ok, masses=(2.0, 0.0)))
    with pytest.raises(ValueError, match="masses"):
        SerialChain(**dict(ok, masses=(2.0, -1.0)))
    with pytest.raises(ValueError, match=r"masses \(kg\) must be 2 numbers, got 1"):
        SerialChain(**dict(ok, masses=(2.0,)))
    with pytest.raises(ValueError, match=r"coms \(m\) must be 2 points \(x, y\), got 1"):
        SerialChain(**dict(ok, coms=((0.1, 0.0),)))
    with pytest.raises(ValueError, match="two coordinates"):
        SerialChain(**dict(ok, coms=((0.1, 0.0, 0.0), (0.1, 0.0))))
    with pytest.raises(TypeError):
        SerialChain(**dict(ok, lengths="0.3"))
    with pytest.raises(ValueError, match="free length"):
        SerialChain(**ok, springs=(Spring(100.0, 0.05, (0, (0, 0.1)), (2, (0.1, 0))),))
    with pytest.raises(ValueError, match="body 3"):
        SerialChain(**ok, springs=(Spring(100.0, 0.0, (0, (0, 0.1)), (3, (0.1, 0))),))
    with pytest.raises(TypeError, match="Spring"):
        SerialChain(**ok, springs=((100.0, 0.0),))
    with pytest.raises(ValueError, match="> 0"):
        Spring(0.0, 0.0, (0, (0, 0.1)), (2, (0.1, 0)))
    with pytest.raises(ValueError, match="> 0"):
        Spring(-5.0, 0.0, (0, (0, 0.1)), (2, (0.1, 0)))
    chain = SerialChain(**ok)
    with pytest.raises(ValueError, match="shape"):
        quadratic_energy(chain, [0.1, 0.2, 0.3])
    with pytest.raises(ValueError, match="square"):
        diagonal_residual(np.zeros((3, 3)))
    with pytest.raises(TypeError, match="SerialChain"):
        stiffness_matrix("chain")


def test_topology_errors():
    with pytest.raises(ValueError, match="itself"):
        chain_parameter_names(2, [(1, 1)])
    with pytest.raises(ValueError, match="outside"):
        chain_parameter_names(2, [(0, 3)])
    with pytest.raises(ValueError, match="1..8"):
        chain_parameter_names(0, [])


def test_reversed_spring_is_turned_around():
    s = Spring(100.0, 0.0, (2, (0.1, 0.0)), (0, (0.0, 0.1)))
    c = SerialChain((0.3, 0.3), (2.0, 2.0), ((0.1, 0.0), (0.15, 0.0)), (s,))
    assert c.topology == ((0, 2),)
    assert c.springs[0].a.point == (0.0, 0.1)


def test_all_pairs_bad_anchor():
    with pytest.raises(ValueError, match="distal joint"):
        balance_all_pairs((0.3, 0.3), (1.0, 1.0), ((0.1, 0.0), (0.1, 0.0)), anchors={(1, 2): (0.3, 0.0)})
    with pytest.raises(ValueError, match="> 0"):
        balance_all_pairs((0.3, 0.3), (1.0, 1.0), ((0.1, 0.0), (0.1, 0.0)), k=0.0)


# ----------------------------------------------------------------- property tests
_len = st.floats(0.05, 1.0)
_mass = st.floats(0.1, 10.0)
_off = st.floats(-0.5, 0.5)


@settings(max_examples=25, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(n=st.integers(2, 4), data=st.data())
def test_property_all_pairs_balanced(n, data):
    lengths = data.draw(st.lists(_len, min_size=n, max_size=n))
    masses = data.draw(st.lists(_mass, min_size=n, max_size=n))
    coms = data.draw(st.lists(st.tuples(_off, _off), min_size=n, max_size=n))
    k = data.draw(st.floats(50.0, 5000.0))
    d = balance_all_pairs(lengths, masses, coms, k=k)
    r = d.balance_report(n=1000)
    assert r.balanced, r
    chain = SerialChain(tuple(lengths), tuple(masses), tuple(coms), d.springs)
    K = stiffness_matrix(chain)
    assert max(abs(x) for x in constraint_residuals(chain).values()) <= 1e-9 * np.abs(K).max()
    # 1e-3 change of the busiest spring's stiffness is seen (a spring whose b lands on
    # the joint of its proximal link keeps a constant length and carries nothing)
    springs = list(d.springs)
    i = int(np.argmax([sp_.k * math.hypot(*sp_.b.point) for sp_ in springs]))
    s = springs[i]
    springs[i] = Spring(s.k * 1.001, 0.0, s.a, s.b)
    assert not d.replace(springs=springs).balance_report(n=300).balanced


@settings(max_examples=25, deadline=None)
@given(L2=_len, m2=_mass, m3=_mass, sx2=_off, sy2=_off, sx3=_off, sy3=_off,
       ay1=st.floats(0.02, 0.5), k2=st.floats(50.0, 5000.0), ax2=_off, ay2=_off)
def test_property_paper_topology_balanced(L2, m2, m3, sx2, sy2, sx3, sy3, ay1, k2, ax2, ay2):
    from hypothesis import assume

    assume(abs(m2 * sx2 + m3 * L2) > 1e-3)
    assume(math.hypot(L2 - ax2, ay2) > 1e-3)
    assume(math.hypot(sx3, sy3) > 1e-3)
    v = dict(L2=L2, m2=m2, sx2=sx2, sy2=sy2, L3=0.3, m3=m3, sx3=sx3, sy3=sy3, ay1=ay1, k2=k2,
             ax2=ax2, ay2=ay2)
    try:
        d = synthesize(2, LUSTIG_TOPOLOGY, v, LUSTIG_UNKNOWNS, symbolic=False)
    except InfeasibleDesign:
        # k1 = g (m2 sx2 + m3 L2) / (L2 ay1) must be positive (eq. 20b)
        assert m2 * sx2 + m3 * L2 < 0
        return
    assert d.parameters["k1"] > 0
    assert d.balance_report(n=1000).balanced
    assert lustig_b1(v) == pytest.approx((d.parameters["bx1"], d.parameters["by1"]), rel=1e-9, abs=1e-12)


def test_design_balance_conditions_are_eq17():
    # the Design's own trigonometric-coefficient conditions are the same equations as the
    # off-diagonal entries of K_t (up to sign)
    d = lustig_table3e_case(1)
    ours = [eq.lhs for eq in constraint_equations(2, LUSTIG_TOPOLOGY).values()]
    theirs = [eq.lhs for eq in d.balance_conditions()]
    for t in theirs:
        assert any(sp.expand(t - o) == 0 or sp.expand(t + o) == 0 for o in ours), t
    for o in ours:
        assert any(sp.expand(t - o) == 0 or sp.expand(t + o) == 0 for t in theirs), o
    assert d.conditions_residual() < 1e-12


def test_paper_helpers_refuse_missing_or_nonsense_values():
    v = lustig_values(3)
    with pytest.raises(ValueError, match="lacks m2"):
        lustig_alpha({k: x for k, x in v.items() if k != "m2"})
    for fn, name, bad in ((lustig_b1, "m3", -2.0), (lustig_alpha, "L2", 0.0), (lustig_a1, "k1", -261.6),
                          (spring2_invariant, "k2", float("nan")), (lustig_min_energy_pose, "sy3", float("inf")),
                          (lustig_a1, "g", 0.0)):
        with pytest.raises(ValueError, match=name):
            fn(dict(v, **{name: bad}))
    with pytest.raises(TypeError, match="mapping"):
        lustig_b1([1.0, 2.0])
    chain = SerialChain.from_values(2, LUSTIG_TOPOLOGY, v)
    with pytest.raises(ValueError, match="finite"):
        quadratic_energy(chain, [float("nan"), 0.0])


# ------------------------------------------------------------------------ families of solutions
def _independent_chain_energy(design, q):
    """Gravity and ZFL springs from world points, written here (not the library's energy)."""
    pts = design.world_points(q, [(ld.body, ld.point) for ld in design.loads])
    v = -np.einsum("...ij,ij->...", pts, np.array([ld.force for ld in design.loads], dtype=float))
    a = design.world_points(q, [(s.a.body, s.a.point) for s in design.springs])
    b = design.world_points(q, [(s.b.body, s.b.point) for s in design.springs])
    k = np.array([s.k for s in design.springs])
    return v + (0.5 * k * ((b - a) ** 2).sum(axis=-1)).sum(axis=-1)


@pytest.mark.parametrize("unknowns", [("k1", "ax1", "ay1", "bx1", "by1", "k2"), ("k1", "ay1", "bx1", "k2")])
def test_case1_one_parameter_family_is_reported_and_each_member_balances(unknowns):
    from balancelab.methods.lustig import SingularChoice, solve_family

    full = lustig_values(1)
    v = {k: x for k, x in full.items() if k not in unknowns}
    with pytest.raises(SingularChoice, match="singular.*1-parameter family") as err:
        solve(2, LUSTIG_TOPOLOGY, v, unknowns)
    families = solve_family(2, LUSTIG_TOPOLOGY, v, unknowns)
    assert [f.free for f in err.value.families] == [f.free for f in families]
    assert len(families) == 1 and len(families[0].free) == 1
    family = families[0]
    (free,) = family.free
    assert family(**{free: full[free]})[free] == full[free]
    for key, x in family(**{free: full[free]}).items():   # the paper's design is a member
        assert x == pytest.approx(full[key], rel=1e-12, abs=1e-15)
    members = [family(**{free: full[free] * f}) for f in (0.6, 1.7)]
    assert members[0]["k1"] != pytest.approx(members[1]["k1"])
    q = np.random.default_rng(3).uniform(-np.pi, np.pi, (400, 2))
    for member in members:
        assert all(member[k] > 0 for k in member if k[0] == "k")
        d = SerialChain.from_values(2, LUSTIG_TOPOLOGY, dict(v, **member)).design("member")
        assert d.balance_report().balanced
        e = _independent_chain_energy(d, q)
        assert np.ptp(e) < 1e-9 * np.abs(e).max()
    with pytest.raises(ValueError, match="free unknowns"):
        family()


def test_a_choice_singular_only_for_the_papers_numbers_is_still_solved():
    """The generic solution of (k1, ax1, bx1, k2) divides by sy2 = 0; the exact one does not."""
    full = lustig_values(1)
    unknowns = ("k1", "ax1", "bx1", "k2")
    sol = solve(2, LUSTIG_TOPOLOGY, {k: x for k, x in full.items() if k not in unknowns}, unknowns)
    for key in unknowns:
        assert sol[key] == pytest.approx(full[key], rel=1e-12, abs=1e-15)
