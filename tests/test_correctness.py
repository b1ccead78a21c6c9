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
