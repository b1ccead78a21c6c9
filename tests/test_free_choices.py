"""Free choices of Singh's chain with minimum preload: counted from the rank of the conditions (not
Table II's 4N - 2), checked numerically on the 2R by moving along and against the null space."""
from __future__ import annotations

import numpy as np
import pytest
import sympy as sp

import balancelab as bl
from balancelab.methods.singh.counting import (chain_conditions, chain_solution_point, conditions_rank,
                                               design_point)


@pytest.mark.parametrize("N", [1, 2, 3, 4])
def test_rank_count_is_3N_minus_1(N):
    c = bl.singh.free_choice_count(N)
    assert c["springs"] == 2 * N - 1 and c["parameters"] == 5 * (2 * N - 1)
    assert c["equations"] == 4 * N - 2                 # the paper's balance count is right
    assert c["min_preload_conditions"] == 2 * (2 * N - 1)  # two scalar equations a spring, not one
    assert c["implied"] == N
    assert c["rank"] == 7 * N - 4 and c["free"] == 3 * N - 1
    assert c["paper_free"] == 4 * N - 2


@pytest.mark.parametrize("N", [2, 3])
def test_rank_does_not_depend_on_the_solution_point(N):
    frees = {conditions_rank(N, seed=seed)["free"] for seed in (1, 2, 3)}
    assert frees == {3 * N - 1}


def test_solution_points_are_exact_and_realizable():
    for N in (1, 2, 3, 4):
        cond, point = chain_conditions(N), chain_solution_point(N, seed=5)
        assert all(r == 0 for r in cond.residuals(point))
        ks = [point[cond.unknowns[5 * s]] for s in range(2 * N - 1)]
        assert all(k > 0 for k in ks)


def test_bad_input():
    with pytest.raises(ValueError, match="N must be"):
        bl.singh.free_choice_count(0)
    with pytest.raises(ValueError, match="N"):
        chain_conditions(0)
    point = chain_solution_point(2)
    point[chain_conditions(2).unknowns[0]] += 1
    with pytest.raises(ValueError, match="values must solve"):
        conditions_rank(2, point)


def test_library_2r_is_a_solution_with_five_free_choices():
    """The rank at serial_2r_min_preload's own design (loads with a rational max-work angle)."""
    d = bl.singh.serial_2r_min_preload(coms=((1.0, 3.0), (2.0, 0.0)))
    r = conditions_rank(2, design_point(d, exact=True))
    assert (r["rank"], r["free"]) == (10, 5)


def test_a_y2_and_a_y3_are_tied():
    cond = chain_conditions(2)
    t1, t2 = sp.symbols("theta_1:3", real=True)
    k2, ay2, k3, ay3 = (cond.unknowns[i] for i in (5, 7, 10, 12))
    l1 = cond.loads[-1]
    assert [str(v) for v in (k2, ay2, k3, ay3, l1)] == ["k_2", "a_y2", "k_3", "a_y3", "l_1"]
    assert sp.expand(cond.balance[sp.sin(t1 - t2)] - l1 * (k2 * ay2 + k3 * ay3)) == 0


# --------------------------------------------------------------- numeric check on the default 2R
def _numeric(design):
    """Residual and Jacobian functions of the 2R's conditions (loads of ``design``), the start point."""
    cond = chain_conditions(2)
    values = design_point(design)
    loads = {s: values[s] for s in cond.loads}
    eqs = [sp.sympify(e).xreplace(loads) for e in cond.equations()]
    F = sp.lambdify([cond.unknowns], eqs, "numpy")
    J = sp.lambdify([cond.unknowns], sp.Matrix(eqs).jacobian(cond.unknowns), "numpy")
    x0 = np.array([float(values[s]) for s in cond.unknowns])
    return (lambda x: np.array(F(x), dtype=float)), (lambda x: np.array(J(x), dtype=float)), x0


def _project(F, J, x, free=()):
    """Gauss-Newton (minimum-norm steps) onto the conditions, moving only the unknowns not in ``free``."""
    x = x.copy()
    move = np.array([i not in free for i in range(len(x))])
    for _ in range(30):
        step = np.linalg.lstsq(J(x)[:, move], -F(x), rcond=None)[0]
        x[move] += step
        if np.linalg.norm(step) < 1e-15:
            break
    return x


def _design(design, x):
    springs = [bl.Spring(x[5 * s], 0.0, (0, (x[5 * s + 3], x[5 * s + 4])), (1 if s == 0 else 2,
                         (x[5 * s + 1], x[5 * s + 2])), name=f"k{s + 1}") for s in range(3)]
    return design.replace(springs=springs)


def _zero_length_gap(design):
    q_star = np.array([design.parameters["theta_star"], np.pi / 2])   # p_y2 = 0: theta_2* = 90 deg
    gaps = [np.linalg.norm(np.diff(design.world_points(q_star, [s.a, s.b]), axis=0)) for s in design.springs]
    return max(gaps)


@pytest.fixture(scope="module")
def arm():
    d = bl.singh.serial_2r_min_preload()
    F, J, x0 = _numeric(d)
    _, sv, Vt = np.linalg.svd(J(x0))
    return d, F, J, x0, sv, Vt


def test_numeric_jacobian_has_a_five_dimensional_null_space(arm):
    d, F, J, x0, sv, _ = arm
    assert np.abs(F(x0)).max() < 1e-12
    assert J(x0).shape == (12, 15)
    assert sv[9] > 1e-3 * sv[0] and np.all(sv[10:] < 1e-12 * sv[0])   # rank 10 of 15 columns: 5 free


def test_moving_along_the_null_space_keeps_balance_and_zero_length(arm):
    d, F, J, x0, _, Vt = arm
    eps = 0.05
    for v in Vt[10:]:
        x = _project(F, J, x0 + eps * v)
        assert np.dot(x - x0, v) == pytest.approx(eps, rel=0.02)   # still moved along v
        moved = _design(d, x)
        assert moved.balance_report().balanced
        assert _zero_length_gap(moved) < 1e-9


def test_moving_against_the_null_space_breaks_balance_or_zero_length(arm):
    d, F, J, x0, _, Vt = arm
    for u in Vt[:10]:
        moved = _design(d, x0 + 1e-3 * u)
        assert not (moved.balance_report().balanced and _zero_length_gap(moved) < 1e-9)


def test_the_three_a_y_are_not_free(arm):
    d, F, J, x0, _, Vt = arm
    ay = [2, 7, 12]                                  # a_y1, a_y2, a_y3 among k, a_x, a_y, b_x, b_y
    null = Vt[10:]
    assert np.linalg.matrix_rank(null[:, ay], tol=1e-9) == 2
    k2, k3 = x0[5], x0[10]
    np.testing.assert_allclose(k2 * null[:, 7] + k3 * null[:, 12], 0.0, atol=1e-12)
    # the paper's six (a_x1..3, a_y1..3) prescribed: k and b cannot always follow
    chosen = {1, 2, 6, 7, 11, 12}
    for i, ok in ((2, True), (7, False)):             # change a_y1 (free) or a_y2 alone (tied)
        x = x0.copy()
        x[i] = 0.05
        x = _project(F, J, x, free=chosen)
        assert bool(np.abs(F(x)).max() < 1e-10) is ok
        assert bool(_design(d, x).balance_report().balanced) is ok
