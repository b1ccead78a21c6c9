"""Springs with both ends free: a bilinear problem, searched from many starts, judged honestly.

With both ends of a ZFL spring free, its energy holds the products ``k p_a p_b``: not linear in
any choice of unknowns. The search fixes one end, solves the linear problem for the other (a
*round*), then fixes that one and frees the first, and so on (:func:`rounds`); it does so from
many starts (:func:`start_points`): the defaults of :func:`balancer._default_point`, the corners,
edge midpoints and centre of the box for either end, and the ends recovered from the *lifted*
problem (the moments ``k p_a``, ``k p_b`` and ``k p_a p_b^T`` as unknowns of their own: linear).
Every start is tried and the best objective value is kept (not the first that balances).

When no start balances, the real unknowns of the both-free springs (``log k``, ``p_a``, ``p_b``) are
fitted by nonlinear least squares from :data:`NLS_STARTS` seeded random points of the box, the other
candidates' variables projected out (:func:`nls_starts`); each fit's ends start the rounds again.

The verdicts are honest: "impossible" only when the lifted problem (a relaxation: any design
is a solution of it) has no solution even with rates of any sign; otherwise, when no start
balances, the verdict is ``"not_found"``: a solution may exist, the search did not find it.
Layer: methods.
"""
from __future__ import annotations

from typing import TYPE_CHECKING

import numpy as np

from ...core.errors import InfeasibleDesign

if TYPE_CHECKING:
    from ...core.design import Design
from .problem import columns, lp_constraints
from .solver import column_norms, rank_of, solve
from .verdicts import infeasible

__all__ = ["search", "start_points", "lifted_ends", "nls_starts"]

#: alternations per start
ROUNDS = 8
#: box points tried as a start for the fixed end: corners, edge midpoints, centre (fractions of the half-width)
_GRID = ((1, 1), (-1, -1), (-1, 1), (1, -1), (0, 1), (0, -1), (1, 0), (-1, 0), (0, 0))


def objective_value(p, x: np.ndarray, objective: str) -> float:
    """The objective of a solution ``x`` of ``p`` (N/m, kg or J)."""
    val = 0.0
    for b in p.blocks:
        k = x[b.cols[0]]
        if objective == "min_stiffness" and b.kind == "spring" or objective == "min_mass" and b.kind == "mass":
            val += k
        elif objective == "min_preload" and b.kind == "spring":
            val += p.mean[b.cols] @ x[b.cols] + (0.5 * (x[b.cols[1]] ** 2 + x[b.cols[2]] ** 2) / k
                                                 if b.free is not None and k > 0 else 0.0)
    return float(val)


def rounds(design, blocks, both, q, objective):
    """Alternate which end of the both-free springs is free (each round keeps balance): the best
    round ``(value, p, sol)``; the blocks are left as in that round. Raises InfeasibleDesign when
    the first round does not balance."""
    best = None
    for _ in range(ROUNDS):
        p = columns(design, blocks, q)
        try:
            sol = solve(p, objective, maxiter=60)  # each round is a step of a heuristic: a short convex step
        except InfeasibleDesign:
            if best is None:
                raise
            break
        value = objective_value(p, sol.x, objective)
        if best is not None and value >= best[0] * (1 - 1e-9):
            break
        best = (value, p, sol, [list(b.ends) for b in blocks], [b.free for b in blocks])
        for b in both:  # fix the end just found, free the other
            k, mx, my = sol.x[b.cols]
            if k > 0:
                b.ends[b.free] = (b.ends[b.free][0], (mx / k, my / k))
                b.set_free(1 - b.free)
                b.ends[b.free] = (b.ends[b.free][0], None)
    assert best is not None  # the first round either balances or raised
    value, p, sol, ends, frees = best
    for b, e, f in zip(blocks, ends, frees):
        b.ends = e
        b.set_free(f)
    return value, p, sol


def _lift(blocks, both):
    saved = [(list(b.ends), b.free) for b in blocks]
    for b in both:
        b.ends = [(b.ends[0][0], None), (b.ends[1][0], None)]
        b.set_free("both")
    return saved


def _restore(blocks, saved):
    for b, (e, f) in zip(blocks, saved):
        b.ends = e
        b.set_free(f)


def lifted_ends(design, blocks, both, q) -> list:
    """Ends ``[(p_a, p_b) or None per both-free spring]`` recovered from the lifted linear program
    (rates >= 0, ``p_a`` in the box): ``p_a = (k p_a) / k``, ``p_b = (k p_b) / k``."""
    from scipy.optimize import linprog

    saved = _lift(blocks, both)
    try:
        p = columns(design, blocks, q)
        D = column_norms(p)
        r, U, s, Vt = rank_of(p.A / D)
        sigma = max(np.linalg.norm(p.v), 1e-300)
        S = sigma / D
        bounds, A_ub, b_ub = lp_constraints(p, S)
        c = np.zeros(p.nvar)
        for b in p.blocks:
            c[b.cols[0]] = 1.0 if b.kind == "spring" else 0.0
        lp = linprog(c * S, A_ub=A_ub, b_ub=b_ub, A_eq=Vt[:r], b_eq=-(U[:, :r].T @ p.v) / s[:r] / sigma,
                     bounds=bounds, method="highs")
        if lp.status != 0:
            return [None] * len(both)
        x = lp.x * S
        out = []
        for b in both:
            k = x[b.cols[0]]
            out.append((tuple(x[b.cols[1:3]] / k), tuple(x[b.cols[3:5]] / k)) if k > 0 else None)
        return out
    finally:
        _restore(blocks, saved)


def start_points(design, blocks, both, q, default_point, size: float):
    """Starts ``[(fixed end index, [point for each both-free spring])]``: the defaults, the lifted
    problem's ends (each end in turn), then the box's corners, edge midpoints and centre."""
    starts = []
    for start in range(6):
        fixed = 1 if start % 2 == 0 else 0
        starts.append((fixed, [default_point(design, b.ends[fixed][0], size, i, start) for i, b in enumerate(both)]))
    lifted = lifted_ends(design, blocks, both, q)
    for fixed in (0, 1):
        if all(e is not None for e in lifted):
            starts.append((fixed, [_clip(e[fixed], b.box_of(fixed)) for e, b in zip(lifted, both)]))
    for fx, fy in _GRID:
        for fixed in (0, 1):
            pts = []
            for b in both:
                (xl, xh), (yl, yh) = b.box_of(fixed)
                pts.append(((xl + xh) / 2 + fx * (xh - xl) / 2, (yl + yh) / 2 + fy * (yh - yl) / 2))
            starts.append((fixed, pts))
    return starts


def _clip(point, box):
    (xl, xh), (yl, yh) = box
    return (float(np.clip(point[0], xl, xh)), float(np.clip(point[1], yl, yh)))


def _best_start(design, blocks, both, q, objective, starts):
    """The alternating rounds from each start ``(fixed end, points)``: the best result
    ``(value, p, sol, ends)`` (None if none balanced) and the last InfeasibleDesign."""
    best, last = None, None
    for fixed, pts in starts:
        for b, pt in zip(both, pts):
            b.ends = [(b.ends[0][0], None), (b.ends[1][0], None)]
            b.ends[fixed] = (b.ends[fixed][0], pt)
            b.set_free(1 - fixed)
        try:
            value, p, sol = rounds(design, blocks, both, q, objective)
        except InfeasibleDesign as err:
            last = err
            continue
        if best is None or value < best[0] * (1 - 1e-9):
            best = (value, p, sol, [(list(b.ends), b.free) for b in blocks])
    return best, last


def search(design, blocks, both, q, objective, default_point, size: float):
    """The best balanced design over every start ``(p, sol)``; InfeasibleDesign with verdict
    "impossible" (proved by the lifted relaxation) or "not_found" (the search found none)."""
    starts = start_points(design, blocks, both, q, default_point, size)
    best, last = _best_start(design, blocks, both, q, objective, starts)
    if best is None:  # no alternating start balanced: start again from nonlinear least squares
        best, last_nls = _best_start(design, blocks, both, q, objective, nls_starts(design, blocks, both, q))
        last = last_nls or last
    if best is not None:
        _restore(blocks, best[3])
        return best[1], best[2]
    saved = _lift(blocks, both)
    lifted = columns(design, blocks, q)
    relaxed = infeasible(lifted, column_norms(lifted), objective, "; springs with both ends free, lifted")
    _restore(blocks, saved)
    if relaxed.verdict == "impossible":
        raise relaxed
    if relaxed.verdict == "box" and last is not None and getattr(last, "verdict", None) == "box":
        raise last
    out = InfeasibleDesign(
        f"no balanced design found from these candidates (objective {objective!r}): the search over "
        f"{len(starts)} starts (and {NLS_STARTS} nonlinear "
        "least-squares fits) for the springs with both ends free found none, but this is NOT proved impossible: the linear relaxation (the moments k p_a, k p_b, "
        f"k p_a p_b^T as unknowns) has a solution ({relaxed.verdict!r}: {relaxed}); try fixing one end of a spring at a "
        "point you choose, or a wider box")
    out.verdict, out.box = "not_found", getattr(relaxed, "box", None)
    raise out


#: random starts of the nonlinear least-squares fallback (seeded: the search is repeatable)
NLS_STARTS = 8


def nls_starts(design: Design, blocks: list, both: list, q: np.ndarray, keep: int = 4) -> list:
    """Starts ``[(fixed end index, [point for each both-free spring])]`` from nonlinear least squares.

    The energy of the both-free springs is fitted in their real unknowns ``(log k, p_a, p_b)`` so that,
    with the other candidates' linear variables (of any sign) and what the design carries, it is
    constant; the fits that come closest (at most ``keep``) give their ends, each end in turn, clipped
    to the box. The rounds then solve the linear problem with the signs and boxes enforced."""
    from scipy.optimize import least_squares

    others = [b for b in blocks if b not in both]
    p = columns(design, others, q)
    Q = np.linalg.qr(p.A)[0] if p.nvar else np.zeros((len(q), 0))
    poses, scale = p.poses, max(float(np.ptp(p.v)), p.load_spread, 1e-300)

    def world(body, point):
        x, y, a = poses[:, body, 0], poses[:, body, 1], poses[:, body, 2]
        c, s = np.cos(a), np.sin(a)
        return np.stack([x + c * point[0] - s * point[1], y + s * point[0] + c * point[1]], -1)

    def residual(z):
        r = p.v.copy()
        for i, b in enumerate(both):
            lk, ax, ay, bx, by = z[5 * i:5 * i + 5]
            d = world(b.ends[0][0], (ax, ay)) - world(b.ends[1][0], (bx, by))
            e = 0.5 * np.exp(lk) * (d * d).sum(-1)
            r = r + e - e.mean()
        return (r - Q @ (Q.T @ r)) / scale

    rng = np.random.default_rng(0)
    fits = []
    for _ in range(NLS_STARTS):
        z0 = []
        for b in both:
            (xl, xh), (yl, yh) = b.box_of(0)
            (ul, uh), (vl, vh) = b.box_of(1)
            pts = rng.uniform((xl, yl, ul, vl), (xh, yh, uh, vh))
            z0 += [np.log(scale / max(np.sqrt((xh - xl) * (yh - yl) * (uh - ul) * (vh - vl)), 1e-300)), *pts]
        with np.errstate(all="ignore"):
            fit = least_squares(residual, np.array(z0), method="lm", max_nfev=200)
        if np.all(np.isfinite(fit.x)):
            fits.append((float(np.ptp(residual(fit.x))), fit.x))
    fits.sort(key=lambda f: f[0])
    starts = []
    for _, z in fits[:keep]:
        for fixed in (0, 1):
            starts.append((fixed, [_clip(tuple(z[5 * i + 1 + 2 * fixed:5 * i + 3 + 2 * fixed]), b.box_of(fixed))
                                   for i, b in enumerate(both)]))
    return starts
