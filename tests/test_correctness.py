"""Physics checks made independently of the library's own energy: the Peaucellier board with
unequal loads, its reach, and balance conditions that are never false."""
from __future__ import annotations

import dataclasses

import numpy as np
import pytest

import balancelab as bl
from balancelab.core.kinematics import joint_gaps


# ------------------------------------------------------------- Peaucellier board, any loads
def _energy(design, q):
    """V(q) written here from world points: loads' work and ZFL/finite springs, nothing else."""
    loads = design.loads
    springs = design.springs
    pts = design.world_points(q, [(ld.body, ld.point) for ld in loads])
    v = -np.einsum("...ij,ij->...", pts, np.array([ld.force for ld in loads], dtype=float))
    a = design.world_points(q, [(s.a.body, s.a.point) for s in springs])
    b = design.world_points(q, [(s.b.body, s.b.point) for s in springs])
    length = np.linalg.norm(b - a, axis=-1)
    k = np.array([s.k for s in springs])
    l0 = np.array([s.free_length for s in springs])
    return v + (0.5 * k * (length - l0) ** 2).sum(axis=-1)


def test_peaucellier_unequal_weights_are_balanced_by_an_independent_energy():
    rng = np.random.default_rng(20240611)
    for _ in range(40):
        weights = tuple(rng.uniform(0.5, 30.0, 7))
        board = float(rng.uniform(0.0, 100.0))
        d = bl.singh.peaucellier_board(weights=weights, board_weight=board)
        q = np.linspace(*d.q_range[0], 301)[1:-1, None]
        assert d.reachable(q).all()
        v = _energy(d, q)
        scale = np.abs(v).max() + sum(weights) + board
        assert np.ptp(v) < 1e-10 * scale, (weights, board, np.ptp(v) / scale)
        p = d.parameters
        if weights[1:6:2] != weights[2:7:2]:
            # each side its own springs; the old D-only design is not balanced
            assert (p["k2D"], p["a_x2D"]) != (p["k2E"], p["a_x2E"])


def test_peaucellier_sides_use_their_own_weights_and_equal_pairs_keep_the_papers_numbers():
    p = bl.singh.peaucellier_board().parameters
    assert round(p["k1"], 2) == 45.88
    for side in "DE":
        assert round(p[f"k2{side}"], 2) == 33.02 and p[f"k3{side}"] == p[f"k2{side}"]
        assert round(p[f"a_x2{side}"], 3) == 0.468 and round(p[f"b_y2{side}"], 3) == 1.218
        assert round(p[f"b_y3{side}"], 3) == 0.283
    heavy_e = bl.singh.peaucellier_board(weights=(6.88, 11.43, 20.0, 4.78, 9.0, 7.62, 12.0)).parameters
    assert heavy_e["k2E"] > heavy_e["k2D"] == pytest.approx(p["k2D"])
    assert heavy_e["k1"] > p["k1"]  # the crank carries half of W5 too


# ------------------------------------------------------------- Peaucellier reach
@pytest.mark.parametrize("geometry", [(0.22326, 0.7505, 0.363), (0.5, 0.7505, 0.363), (0.5568, 0.7505, 0.363),
                                      (0.6, 0.7505, 0.363), (1.0, 0.7505, 0.363), (0.3, 1.0, 0.5),
                                      (2.0, 1.0, 0.5)])
def test_peaucellier_reachable_only_where_the_loop_closes(geometry):
    d = bl.singh.peaucellier_board(crank=geometry[0], arm=geometry[1], side=geometry[2])
    kin = d.kinematics
    phi = np.linspace(-np.pi, np.pi, 20001)[:, None]
    poses, ok = kin.poses(phi)
    gaps = joint_gaps(poses, d.joints).max(axis=-1)
    assert ok.any()
    assert gaps[ok].max() < 1e-9
    np.testing.assert_array_equal(ok, kin.reachable(phi))
    # C out of reach of the rhombus (|OC| > l + s) near phi = 0 for a long crank
    oc = 2 * kin.d * np.abs(np.cos(phi[:, 0] / 2))
    assert not ok[oc > (kin.l + kin.s) * (1 + 1e-9)].any()
    assert not ok[oc < (kin.l - kin.s) * (1 - 1e-9)].any()
    long_crank = 2 * kin.d > kin.l + kin.s
    assert ok[np.abs(phi[:, 0]) < 1e-9].all() != long_crank
    # P on its line, covering exactly the travel
    P = d.world_points(phi[ok], [(6, (kin.s, 0.0))])[:, 0]
    np.testing.assert_allclose(P[:, 0], kin.line_x, atol=1e-9)
    covered = np.ptp(P[P[:, 1] > 0, 1]) + np.ptp(P[P[:, 1] < 0, 1]) if long_crank else np.ptp(P[:, 1])
    assert covered == pytest.approx(d.parameters["travel"], rel=1e-3)


# ------------------------------------------------------------- balance conditions
@pytest.mark.parametrize("name", list(bl.catalog()))
def test_catalog_conditions_are_true_or_refused(name):
    entry = bl.catalog()[name]
    d = entry()
    try:
        residual = d.conditions_residual()
        conditions = d.balance_conditions(parametric=False)
    except NotImplementedError as err:
        assert str(err).strip()
        return
    if entry.expected_balanced:
        assert residual < 1e-9
    else:
        assert residual > 1e-3 and conditions


@pytest.mark.parametrize("factory", [
    lambda: bl.catalog()["deepak_watt_prototype"](),
    lambda: bl.deepak.technique2(bl.deepak.example_fourbar(), (0.1, -0.2), 100.0, "A", 0.1),
    lambda: bl.deepak.technique2(bl.deepak.example_fourbar(), (0.1, -0.2), 100.0, "B", 0.1),
    lambda: bl.catalog()["deepak_gravity_fourbar"](),
])
def test_loop_fourbar_conditions_hold_for_balanced_designs(factory):
    d = factory()
    assert d.balance_report().balanced
    assert d.conditions_residual() < 1e-9
    for eq in d.balance_conditions(parametric=False):
        assert abs(float(eq.lhs)) < 1e-9 * d.balance_report(n=200).scale


def test_loop_fourbar_conditions_catch_an_unbalanced_design():
    d = bl.catalog()["deepak_watt_prototype"]()
    s = d.springs[0]
    bad = d.replace(springs=(dataclasses.replace(s, k=1.1 * s.k),) + tuple(d.springs[1:]))
    assert not bad.balance_report().balanced
    assert bad.conditions_residual() > 1e-4


class _ParallelOnly(bl.FourBarKinematics):
    """A parallelogram kept on its parallel circuit (rocker angle = crank angle): only one of the
    two components of its loop-closure curve is ever reached."""

    def poses(self, q):
        q = np.asarray(q, dtype=float)
        th = q[..., 0]
        out = np.zeros(th.shape + (4, 3))
        out[..., 1, 2] = th
        out[..., 2, 0], out[..., 2, 1] = self.r2 * np.cos(th), self.r2 * np.sin(th)
        out[..., 3, 0], out[..., 3, 2] = self.B[0], th
        return out, np.ones(th.shape, dtype=bool)


def test_degenerate_loop_refuses_instead_of_giving_false_conditions():
    """On the parallel circuit V = 0.2 (sin theta_2 - sin theta_4) = 0 is balanced, but the
    coefficients modulo the whole (reducible) loop equation are not zero: refuse them."""
    kin = _ParallelOnly((0.0, 0.0), (0.8, 0.0), 0.3, 0.8, 0.3)
    loads = [bl.Load(1, (0.2, 0.0), (0.0, -1.0)), bl.Load(3, (0.2, 0.0), (0.0, 1.0))]
    d = bl.Design("parallel circuit", ("ground", "crank", "coupler", "rocker"), bl.fourbar_joints(kin),
                  kin, loads, [])
    assert d.balance_report().balanced
    with pytest.raises(NotImplementedError, match="balance_report"):
        d.balance_conditions()
    with pytest.raises(NotImplementedError, match="balance_report"):
        d.conditions_residual()


def test_parallelogram_over_both_circuits_keeps_exact_conditions():
    """FourBarKinematics reaches both circuits of a parallelogram: the conditions are exact."""
    d = bl.lecture.fourbar_counterweights(A=(0.0, 0.0), B=(0.8, 0.0), crank=0.3, coupler=0.8, rocker=0.3)
    assert d.balance_report().balanced and d.conditions_residual() < 1e-9


def test_relaxed_models_keep_their_conditions():
    for d in (bl.singh.singh_fourbar(), bl.singh.peaucellier_board()):
        assert d.conditions_residual() < 1e-12
        assert d.balance_conditions(parametric=False) == [] or all(
            abs(float(eq.lhs)) < 1e-9 for eq in d.balance_conditions(parametric=False))


@pytest.mark.parametrize("name", ["single_link_ordinary_spring", "negative_free_length_lever",
                                  "approximate_spring_lever"])
def test_finite_free_length_gives_a_clear_error(name):
    d = bl.catalog()[name]()
    with pytest.raises(NotImplementedError, match="balance_report"):
        d.balance_conditions()


# ------------------------------------------------------------- Singh's 2R and four-bar, p_x2 < 0
def test_min_preload_body2_conditions_fix_the_sign_of_p_x2():
    """Derived here with sympy: springs on body 2 at (a_i, 0), anchored where they have zero length
    at theta_2 = +-90 deg. Balance of the theta_2 terms needs sum k a = 0 and sum k a^2 = sigma W2 p_x2:
    with the paper's sigma = +1 no pair of positive springs exists for p_x2 < 0; sigma = sign(p_x2) works."""
    import sympy as sp

    t1, t2, l, W2, p = sp.symbols("theta_1 theta_2 l W_2 p_x2", real=True)
    k = sp.symbols("k2 k3", positive=True)
    a = sp.symbols("a2 a3", real=True)
    c, s, sigma = sp.symbols("c s sigma", real=True)
    J = sp.Matrix([l * sp.cos(t1), l * sp.sin(t1)])
    R2 = sp.Matrix([[sp.cos(t2), -sp.sin(t2)], [sp.sin(t2), sp.cos(t2)]])
    energy = W2 * (l * sp.sin(t1) + p * sp.sin(t2))
    for ki, ai in zip(k, a):
        anchor = sp.Matrix([l * c, l * s + sigma * ai])   # = J* + R(sigma 90 deg) (a_i, 0)
        gap = J + R2 * sp.Matrix([ai, 0]) - anchor
        energy += ki / 2 * gap.dot(gap)
    energy = sp.expand(sp.expand_trig(energy))
    coeff_cos12 = energy.coeff(sp.cos(t1)).coeff(sp.cos(t2))   # cos(t1 - t2) = c1 c2 + s1 s2
    coeff_sin2 = energy.coeff(sp.sin(t2)).subs({sp.sin(t1): 0, sp.cos(t1): 0})
    assert sp.simplify(coeff_cos12 - l * (k[0] * a[0] + k[1] * a[1])) == 0
    tied = coeff_sin2.subs(k[1], -k[0] * a[0] / a[1])            # sum k a = 0
    # W2 p_x2 - sigma k2 a2 (a2 - a3) = 0, and k2 a2^2 + k3 a3^2 = k2 a2 (a2 - a3)
    assert sp.simplify(tied - (W2 * p - sigma * k[0] * a[0] * (a[0] - a[1]))) == 0
    # k2 a2 (a2 - a3) = k2 a2^2 + k3 a3^2 > 0 for positive springs: sigma must be sign(p_x2)
    assert sp.simplify(k[0] * a[0] * (a[0] - a[1]) - (k[0] * a[0] ** 2 + (-k[0] * a[0] / a[1]) * a[1] ** 2)) == 0


def _random_min_preload_inputs(rng, sign):
    W1, W2 = rng.uniform(0.5, 50.0, 2)
    p1 = (rng.uniform(0.05, 2.0), rng.uniform(-1.0, 1.0))
    p_x2 = sign * rng.uniform(0.05, 3.0)
    l = rng.uniform(0.1, 3.0)
    bound = W2 * abs(p_x2) * l ** 2 / np.hypot(W1 * p1[0] + W2 * l, W1 * p1[1])
    a2 = rng.choice([-1.0, 1.0]) * rng.uniform(0.1, 3.0)
    a3 = -np.sign(a2) * bound / abs(a2) * rng.uniform(1.05, 5.0)   # -a2 a3 > bound: k1 > 0
    a1 = rng.choice([-1.0, 1.0]) * rng.uniform(0.1, 3.0)
    return (W1, W2), (p1, (p_x2, 0.0)), l, (a1, a2, a3)


@pytest.mark.parametrize("sign", [1.0, -1.0])
def test_min_preload_2r_with_either_sign_of_p_x2_is_balanced_by_an_independent_energy(sign):
    rng = np.random.default_rng(7 if sign > 0 else 11)
    for _ in range(40):
        weights, coms, l, a_x = _random_min_preload_inputs(rng, sign)
        d = bl.singh.serial_2r_min_preload(weights, coms, l, a_x)
        q = d.sample(400, seed=3)
        v = _energy(d, q)
        assert np.ptp(v) < 1e-9 * (np.abs(v).max() + sum(weights) * 10), (weights, coms, l, a_x)
        assert min(s.k for s in d.springs) > 0
        # least preload: every spring has zero length where the loads' energy is largest
        q_star = np.array([[d.parameters["theta_star"], sign * np.pi / 2]])
        assert _energy(d, q_star)[0] == pytest.approx(v.mean(), rel=1e-9)
        assert v.mean() == pytest.approx(d.potential_energy(q_star).load[0], rel=1e-9)
        two = bl.singh.serial_2r_two_springs(weights, coms, l, a_x[1])
        v2 = _energy(two, q)
        assert len(two.springs) == 2 and np.ptp(v2) < 1e-9 * (np.abs(v2).max() + sum(weights) * 10)


def test_singh_fourbar_with_negative_coupler_and_rocker_offsets():
    rng = np.random.default_rng(5)
    for _ in range(10):
        weights, coms, _, a_x = _random_min_preload_inputs(rng, -1.0)
        p_x3 = float(rng.uniform(-0.9, -0.1))
        crank, coupler, rocker, ground = 1.0, 3.0, 1.0, 3.0
        bound = weights[1] * abs(coms[1][0]) * crank ** 2 / np.hypot(weights[0] * coms[0][0] + weights[1] * crank,
                                                                     weights[0] * coms[0][1])
        a_x = (a_x[0], 1.0, -1.5 * bound)
        d = bl.singh.singh_fourbar(weights + (7.0,), coms + ((p_x3, 0.0),), crank, coupler, rocker, ground, a_x,
                                   a4=tuple(rng.uniform(-1, 1, 2)))
        q = np.linspace(*d.q_range[0], 300)[1:-1, None]
        ok = d.reachable(q)
        v = _energy(d, q[ok])
        assert ok.sum() > 10 and np.ptp(v) < 1e-9 * (np.abs(v).max() + 100)


@pytest.mark.parametrize("call, names", [
    (lambda: bl.singh.serial_2r_min_preload(coms=((1.0, 0.5), (0.0, 0.0))), ["p_x2"]),
    (lambda: bl.singh.serial_2r_min_preload(coms=((1.0, 0.5), (-2.0, 0.0)), a_x=(1.0, 2.0, 1.0)),
     ["a_x2", "a_x3", "opposite signs"]),
    (lambda: bl.singh.serial_2r_min_preload(a_x=(1.0, 0.5, -0.5)), ["k1", "-a_x2 a_x3 >", "2.23263 m^2"]),
    (lambda: bl.singh.serial_2r_two_springs(coms=((1.0, 0.5), (0.0, 0.0))), ["p_x2"]),
    (lambda: bl.singh.singh_fourbar(coms=((1.0, 0.5), (2.0, 0.0), (0.0, 0.0))), ["p_x3"]),
    (lambda: bl.singh.singh_fourbar(a4=(0.0, 0.0)), ["a4"]),
])
def test_min_preload_restrictions_are_named(call, names):
    with pytest.raises(ValueError) as err:
        call()
    for name in names:
        assert name in str(err.value)
