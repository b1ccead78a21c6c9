"""Solving the sampled balance problem: rank, non-negative solutions, objectives, infeasibility.

``A x + v = const`` over the sampled configurations is reduced, through a singular value
decomposition of the column-scaled ``A``, to ``rank`` independent conditions with
orthonormal rows. The number of *free choices* is ``nvar - rank``: the dimension of the
set of solutions when signs and boxes are ignored. A linear program (HiGHS) then picks the
solution with ``k >= 0``, counter masses ``>= 0`` and free points in their boxes that
minimizes the objective; minimum preload with free points (a convex objective,
``k/2 |p|^2 = |m|^2 / (2 k)``) continues from there with SLSQP. The result is finally
polished to round-off by a least-norm correction of the variables not at a bound.
Layer: methods.
"""
from __future__ import annotations

import numpy as np

from ...core.validation import MIN_POSITIVE
from .problem import Problem, lp_constraints
from .verdicts import infeasible, smooth_within

__all__ = ["OBJECTIVES", "Solution", "solve", "rank_of", "column_norms"]

#: what ``objective`` may ask for
OBJECTIVES = ("min_preload", "min_stiffness", "min_mass")

_RANK_TOL = 1e-9


class Solution:
    """Values ``x`` of the unknowns, the rank of the conditions and the free choices left."""

    def __init__(self, x: np.ndarray, rank: int, nvar: int, residual: float) -> None:
        self.x, self.rank, self.nvar, self.residual = x, int(rank), int(nvar), residual
        self.unique: bool | None = None

    @property
    def free_choices(self) -> int:
        """Unknowns minus the rank of the balance conditions."""
        return self.nvar - self.rank


def rank_of(M: np.ndarray) -> tuple[int, np.ndarray, np.ndarray, np.ndarray]:
    """Numeric rank of ``M`` (singular values above 1e-9 of the largest) and its SVD ``(U, s, Vt)``.

    Examples
    --------
    >>> rank_of(np.array([[1.0, 2.0], [2.0, 4.0], [0.0, 0.0]]))[0]
    1
    """
    if M.shape[1] == 0:
        return 0, np.zeros((M.shape[0], 0)), np.zeros(0), np.zeros((0, 0))
    U, s, Vt = np.linalg.svd(M, full_matrices=False)
    r = int((s > _RANK_TOL * max(s.max(), 1e-300)).sum())
    return r, U, s, Vt


def column_norms(p: Problem) -> np.ndarray:
    """Norms of the columns of ``p.A``; columns of round-off size (a spring whose length never
    changes) are set to exact zeros and get the largest norm, so that scaling stays finite; if every
    column is zero (no candidate can change the energy), all norms are one.

    Examples
    --------
    >>> p = Problem(np.array([[1.0, 1e-17], [-1.0, 0.0]]), np.zeros(2), np.zeros(2), [], None, None, 0.0)
    >>> column_norms(p).round(4).tolist(), p.A[:, 1].tolist()
    ([1.4142, 1.4142], [0.0, 0.0])
    """
    D = np.linalg.norm(p.A, axis=0)
    top = D.max(initial=0.0)
    if not top > 0.0:
        p.A[:] = 0.0
        return np.ones_like(D)
    dead = D <= 1e-12 * top
    p.A[:, dead] = 0.0
    return np.where(dead, top, D)


def _cost(p: Problem, objective: str) -> np.ndarray:
    c = np.zeros(p.nvar)
    for b in p.blocks:
        if objective == "min_stiffness" and b.kind == "spring":
            c[b.cols[0]] = 1.0
        elif objective == "min_mass" and b.kind == "mass":
            c[b.cols[0]] = 1.0
        elif objective == "min_preload" and b.kind == "spring":
            c[b.cols] = p.mean[b.cols]
    return c


def _preload(p: Problem, D: np.ndarray, c: np.ndarray, y0: np.ndarray, eq, ineq, bounds, null,
             maxiter: int = 500) -> np.ndarray:
    """Minimum mean spring energy with free points: ``c.x + sum |m|^2 / (2 k)``, convex, by SLSQP on
    the balanced solutions only (the null space ``null`` of the equalities, of the free choices'
    dimension, from the linear program's answer ``y0``)."""
    from scipy.optimize import minimize

    if null.shape[1] == 0:  # no free choice: the LP's answer is the only one (and SLSQP, given no
        return y0  # unknowns, hands LAPACK empty arrays that print "illegal value" on stderr)
    free = np.array([b.cols for b in p.blocks if b.kind == "spring" and b.free is not None], dtype=int)
    k, mx, my = free.T

    def f(y):
        x = D * y
        kk = np.maximum(x[k], 1e-12 * D[k])
        q = x[mx] ** 2 + x[my] ** 2
        val = c @ x + float(np.sum(0.5 * q / kk))
        grad = c * D
        grad[k] += -0.5 * q / kk ** 2 * D[k]
        grad[mx] += x[mx] / kk * D[mx]
        grad[my] += x[my] / kk * D[my]
        return val, grad

    # on the solutions of the (orthonormal) equalities only: y = y_p + N z, N spanning their null space
    y_p = eq[0].T @ eq[1]
    N = null
    lower = np.array([0.0 if lo == 0.0 else -np.inf for lo, _ in bounds])
    sign = np.isfinite(lower)
    rows = [N[sign]] + ([-(ineq[0] @ N)] if ineq[0] is not None else [])
    rhs = [-y_p[sign]] + ([ineq[0] @ y_p] if ineq[0] is not None else [])
    G, h = np.vstack(rows), np.concatenate(rhs)  # G z >= h

    def fz(z):
        val, grad = f(y_p + N @ z)
        return val, N.T @ grad

    z0 = N.T @ (y0 - y_p)
    cons = [{"type": "ineq", "fun": lambda z: G @ z - h, "jac": lambda z: G}]
    res = minimize(fz, z0, jac=True, method="SLSQP", constraints=cons, options={"maxiter": maxiter, "ftol": 1e-15})
    y = y_p + N @ res.x
    return y if np.all(np.isfinite(y)) else y0


def _negligible(p: Problem, x: np.ndarray) -> np.ndarray:
    """Candidates whose value is <= 0, or whose energy is below ``1e-12`` of the design's energy
    variation (leftover rates of 1e-13 N/m and the like): a mask over the variables. That variation
    is the one of what the design carries (``v``) or, for a design balanced already (``v`` is then
    round-off), the spreads of its elements' own energies: a round-off rate is dropped, not returned."""
    scale = max(float(np.linalg.norm(p.v)), p.load_spread * np.sqrt(len(p.v)), 1e-300)
    out = np.zeros(p.nvar, dtype=bool)
    for b in p.blocks:
        if x[b.cols[0]] <= 0 or np.linalg.norm(p.A[:, b.cols] @ x[b.cols]) <= 1e-12 * scale:
            out[b.cols] = True
    return out


def _polish(p: Problem, x: np.ndarray, U: np.ndarray) -> np.ndarray:
    """Least-norm correction of the variables off their bounds, to round-off balance.

    Candidates that come out negligible (:func:`_negligible`) are set to exact zeros first,
    again after each correction. The sampled equations are compressed to the ``rank`` rows
    ``U^T A`` (``U`` the left singular vectors of the scaled ``A``): the same least-squares
    problem, smaller. If correcting the moments ``k p`` freely would carry a free point out of
    its box (or a rate below the smallest admissible one), the points are kept where the
    solver put them and only the rates and masses are corrected."""
    C, d = U.T @ p.A, U.T @ p.v
    free = _correct(p, x, C, d, np.eye(p.nvar))
    if _admissible(p, free):
        return free
    basis = np.zeros((p.nvar, len(p.blocks)))  # each candidate scales as a whole: its point stays
    for i, b in enumerate(p.blocks):
        if x[b.cols[0]] > 0:
            basis[b.cols, i] = x[b.cols] / x[b.cols[0]]
    return _correct(p, x, C, d, basis)


def _correct(p: Problem, x: np.ndarray, C: np.ndarray, d: np.ndarray, basis: np.ndarray) -> np.ndarray:
    """``x`` corrected along the columns of ``basis`` (those of live candidates) to least squares."""
    x = np.array(x, dtype=float, copy=True)
    for _ in range(4):
        dead = _negligible(p, x)
        x[dead] = 0.0
        B = basis[:, ~(dead[:, None] & (basis != 0)).any(0)]
        if B.shape[1]:
            x -= B @ np.linalg.lstsq(C @ B, C @ x + d, rcond=1e-13)[0]
    x[_negligible(p, x)] = 0.0
    return x


def _admissible(p: Problem, x: np.ndarray) -> bool:
    """Every spring rate 0 or >= MIN_POSITIVE, every free point in its box (to 1e-9 of its size)."""
    for b in p.blocks:
        k = x[b.cols[0]]
        if k < 0 or b.kind == "spring" and 0 < k < MIN_POSITIVE:
            return False
        if b.free is not None and k > 0:
            for axis, (lo, hi) in enumerate(b.box):
                v, tol = x[b.cols[1 + axis]] / k, 1e-9 * max(hi - lo, abs(lo), abs(hi), 1e-12)
                if not lo - tol <= v <= hi + tol:
                    return False
    return True


def solve(p: Problem, objective: str, maxiter: int = 500) -> Solution:
    """Solve the sampled problem ``p`` for ``objective`` (one of :data:`OBJECTIVES`).

    ``maxiter`` bounds the iterations of the minimum-preload step (SLSQP).

    Returns
    -------
    Solution
        ``x`` (rates, masses and moments in the order of ``p.blocks``' columns), the rank of
        the conditions, the free choices, and ``unique``: False when a linear objective leaves
        other designs of the same objective value (None when not checked).

    Raises
    ------
    InfeasibleDesign
        When no solution with non-negative rates and masses (and free points in their
        boxes) balances the design; ``err.verdict`` is one of
        :data:`~balancelab.methods.general.verdicts.VERDICTS`.

    Examples
    --------
    Used by :func:`balancelab.balance`; see there.
    """
    from scipy.optimize import linprog

    D = column_norms(p)
    r, U, s, Vt = rank_of(p.A / D)
    sigma = _scale(p)
    eq = (Vt[:r], -(U[:, :r].T @ p.v) / s[:r] / sigma)
    S = sigma / D  # x = S y
    bounds, A_ub, b_ub = lp_constraints(p, S)
    c = _cost(p, objective)
    convex = objective == "min_preload" and any(b.free is not None and b.kind == "spring" for b in p.blocks)
    start = _cost(p, "min_stiffness") if convex else c  # the linear part alone is unbounded with free points
    lp = linprog(start * S, A_ub=A_ub, b_ub=b_ub, A_eq=eq[0], b_eq=eq[1], bounds=bounds, method="highs")
    if lp.status != 0:
        raise infeasible(p, D, objective)
    face = (c * S, A_ub, b_ub)  # the objective and inequalities whose optimal face _unique explores
    if objective == "min_preload" and not convex and any(b.kind == "mass" for b in p.blocks):
        lp, face = _lightest(p, lp, c * S, S, A_ub, b_ub, eq, bounds)
    tries = [_preload(p, S, c, lp.x, eq, (A_ub, b_ub), bounds, Vt[r:].T, maxiter), lp.x] if convex else [lp.x]
    tol = 1e-10 * max(p.load_spread, 1e-300)
    for y in tries:  # the convex step from the LP's answer, else the LP's (feasible) answer itself
        x = _polish(p, S * y, U[:, :r])
        res = p.A @ x + p.v
        spread = float(np.ptp(res)) if len(res) else 0.0
        if spread <= tol or smooth_within(p, res, tol):
            break
    else:
        raise infeasible(p, D, objective, f"; the best solution leaves {spread:.3g} J")
    sol = Solution(x, r, p.nvar, spread)
    if not convex and r < p.nvar:
        sol.unique = _unique(p, face[0], lp, face[1], face[2], eq, bounds)
    return sol


def _lightest(p: Problem, lp, cost: np.ndarray, S: np.ndarray, A_ub, b_ub, eq, bounds):
    """The minimum preload's counterweights, which its objective does not count, made the lightest
    among the designs of that preload (a second linear program, on the scaled variables): the
    design is then no arbitrary vertex, and the default objective owes no warning. Returns the
    second program's answer and its face ``(mass cost, inequalities with the preload's bound)``."""
    from scipy.optimize import linprog

    mass = _cost(p, "min_mass") * S
    slack = 1e-9 * max(abs(lp.fun), 1e-300) + 1e-12 * float(np.abs(cost) @ np.abs(lp.x))
    rows = np.vstack([A_ub, cost]) if A_ub is not None else cost[None]
    lims = np.append(b_ub, lp.fun + slack) if b_ub is not None else np.array([lp.fun + slack])
    second = linprog(mass, A_ub=rows, b_ub=lims, A_eq=eq[0], b_eq=eq[1], bounds=bounds, method="highs")
    if second.status != 0:
        return lp, (cost, A_ub, b_ub)
    return second, (mass, rows, lims)


def _scale(p: Problem) -> float:
    """The energy (J) the variables are scaled by: that of what the design carries, or, for a design
    balanced already (``v`` is then exactly zero), the spreads of its elements' energies (a scale of
    1e-300 would make the scaled rates 0 / 0)."""
    norm = float(np.linalg.norm(p.v))
    return norm if norm > 0 else max(p.load_spread * np.sqrt(max(len(p.v), 1)), 1e-300)


def _unique(p: Problem, cost: np.ndarray, lp, A_ub, b_ub, eq, bounds) -> bool:
    """Whether the optimum of a linear objective is one design: the variables of candidates the
    objective ignores (zero cost) are pushed both ways along a fixed direction on the optimal face."""
    from scipy.optimize import linprog

    ignored = np.zeros(p.nvar, dtype=bool)
    for b in p.blocks:
        ignored[b.cols] = not cost[b.cols].any()
    if not ignored.any():
        return True
    direction = np.where(ignored, np.random.default_rng(0).uniform(0.5, 1.5, p.nvar), 0.0)
    slack = 1e-9 * max(abs(lp.fun), 1.0)
    rows = np.vstack([A_ub, cost]) if A_ub is not None else cost[None]
    lims = np.append(b_ub, lp.fun + slack) if b_ub is not None else np.array([lp.fun + slack])
    ends = [linprog(sgn * direction, A_ub=rows, b_ub=lims, A_eq=eq[0], b_eq=eq[1], bounds=bounds, method="highs")
            for sgn in (1.0, -1.0)]
    if any(e.status == 3 for e in ends):  # unbounded along the face: a whole ray of designs of that value
        return False
    if any(e.status != 0 for e in ends):
        return True
    return bool(abs(direction @ (ends[0].x - ends[1].x)) <= 1e-6 * max(np.abs(direction @ lp.x), 1e-3))
