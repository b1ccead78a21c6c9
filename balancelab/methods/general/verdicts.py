"""Why a balance problem has no admissible solution: one of three verdicts, each with its evidence.

* ``"impossible"`` — *impossible for any rates*: even with rates and masses of any sign (and
  free points anywhere) the candidates cannot make the energy constant; the message names the
  energy terms left over that no candidate can produce (those above ``1e-9`` of the energy the
  loads exchange);
* ``"negative"`` — *needs a negative rate or mass*: a solution exists, but only with a negative
  rate or counter mass, named in the message;
* ``"box"`` — *needs a point outside the box*: a solution with rates and masses ``>= 0`` exists
  once the free points may leave the box (up to :data:`WIDER` times wider); the message names the
  points and a box that would do (``err.box``).

A ZFL spring's free end is found through its moment ``k p``; with ``k -> 0`` and ``|p| -> inf``
the spring tends to a constant force, which balances anything and is no design. The first
verdict is proved by a relaxation that allows it (so it is sound); the second is said when no
solution exists with free points within :data:`WIDER` times the box.

The verdict is stored on the exception (``err.verdict``). Layer: methods.
"""
from __future__ import annotations

from typing import Any, Sequence

import numpy as np

from ...core.errors import InfeasibleDesign
from ...core.report import BALANCE_TOLERANCE, q_units, roundoff_allowance as allowance
from ...core.smooth import smooth_split
from .problem import Problem, harmonics, lp_constraints

__all__ = ["VERDICTS", "infeasible", "nice_box", "suggest", "limit", "smooth_within"]

#: the reasons a balance problem has no admissible solution (``"limit"``: a rate or mass beyond
#: what a design may hold, see :func:`limit`)
VERDICTS = ("impossible", "negative", "box", "not_found", "limit")

_TERM_TOL = 1e-9  # energy terms below this fraction of the loads' exchanged energy are round-off


def _error(verdict: str, message: str, box=None) -> InfeasibleDesign:
    err = InfeasibleDesign(message)
    err.verdict = verdict
    err.box = box
    return err


def label(p: Problem, index: int) -> str:
    """``springs[i]`` or ``counterweights[j]``: a candidate as the caller wrote it."""
    kind = p.blocks[index].kind
    return f"{kind}s[{sum(b.kind == kind for b in p.blocks[:index])}]".replace("masss", "counterweights")


def nice_box(half: float) -> tuple:
    """The square box ``((-w, w), (-w, w))`` with ``w`` the next 1, 2 or 5 times a power of ten above ``half``.

    Examples
    --------
    >>> nice_box(0.73)
    ((-1.0, 1.0), (-1.0, 1.0))
    """
    e = 10.0 ** np.floor(np.log10(max(half, 1e-12)))
    w = next(float(m * e) for m in (1, 2, 5, 10) if m * e >= half)
    return ((-w, w), (-w, w))


def terms(p: Problem, residual: np.ndarray) -> str:
    """``"0.98 J × cos θ_1, ..."``: the energy terms of a residual above the scale-relative tolerance."""
    tol = _TERM_TOL * max(p.load_spread, 1e-300)
    found = [(n, v) for n, v in harmonics(p.design, p.poses, residual, q=p.q) if abs(v) > tol]
    return ", ".join(f"{v:.3g} J × {name}" for name, v in found) or f"{np.ptp(residual):.3g} J in all"


def _rates(p: Problem) -> np.ndarray:
    lo = np.full(p.nvar, -np.inf)
    for b in p.blocks:
        lo[b.cols[0]] = 0.0
    return lo


def _signed(p: Problem, D: np.ndarray, lo: np.ndarray) -> np.ndarray:
    """Least squares with rates and masses >= 0 (scipy's trust-region solver can meet 0 * inf on a
    rank-deficient problem: its RuntimeWarning is silenced and the bounded-variable solver used then)."""
    import warnings

    from scipy.optimize import lsq_linear

    bounds = (lo, np.full(p.nvar, np.inf))
    with warnings.catch_warnings(), np.errstate(all="ignore"):
        warnings.simplefilter("ignore", RuntimeWarning)
        x = lsq_linear(p.A / D, -p.v, bounds=bounds).x
        if not np.all(np.isfinite(x)):
            x = lsq_linear(p.A / D, -p.v, bounds=bounds, method="bvls").x
    return x / D


def smooth_within(p: Problem, residual: np.ndarray, tol: float) -> bool:
    """Whether an energy ``residual`` (J) is noise: its smooth part (:func:`~balancelab.core.smooth.smooth_split`)
    within ``tol`` and the rest within the report's tolerance, both up to the round-off the report allows
    (:func:`~balancelab.core.report.roundoff_allowance`): a far origin's positions carry 1e-10 m of round-off, and a balance that holds at the
    origin is not called impossible there. A solution accepted so is still checked by the report.

    Examples
    --------
    Used by :func:`~balancelab.methods.general.solver.solve` and :func:`infeasible`.
    """
    design: Any = p.design
    if design is None or not len(residual):
        return False
    smooth, rest = smooth_split(p.poses, p.q, q_units(design), residual)
    slack = allowance(design, p.q)  # the report's own allowance and tolerance for the noise: the report settles it
    return smooth <= tol + slack and rest <= BALANCE_TOLERANCE * p.load_spread + slack


def infeasible(p: Problem, D: np.ndarray, objective: str, detail: str = "") -> InfeasibleDesign:
    """The :class:`InfeasibleDesign` (with ``verdict``) of a problem that has no admissible solution.

    Parameters
    ----------
    p : Problem
    D : numpy.ndarray
        Column norms of ``p.A`` (scaling).
    objective : str
    detail : str
        Appended to the head of the message.

    Examples
    --------
    Used by :func:`balancelab.balance`; the tests raise each verdict.
    """
    head = f"no balanced design from these candidates (objective {objective!r}{detail}): "
    tol = 1e-10 * max(p.load_spread, 1e-300)
    free = np.linalg.lstsq(p.A / D, -p.v, rcond=1e-12)[0] / D
    unsigned = p.A @ free + p.v
    if np.ptp(unsigned) > tol and not smooth_within(p, unsigned, tol):
        return _error("impossible", head + "impossible for any rates: even with rates and masses of any sign "
                      f"they cannot make the energy constant; left over: {terms(p, unsigned)}")
    lo = _rates(p)
    found = _wider(p, D) if any(b.free in (0, 1) for b in p.blocks) else None
    if found is not None:
        x, far = found
        outside, points = [], []
        for i, b in enumerate(p.blocks):
            k = x[b.cols[0]]
            if b.free not in (0, 1) or k <= 0:
                continue
            pt = x[b.cols[1:]] / k
            points.append(pt)
            (xl, xh), (yl, yh) = b.box
            if not (xl <= pt[0] <= xh and yl <= pt[1] <= yh):
                end = "counterweight" if b.kind == "mass" else f"end {b.free}"
                outside.append(f"{label(p, i)} {end} at ({pt[0]:.4g}, {pt[1]:.4g}) m")
        box = suggest(p.blocks[0].box, points)
        where = ", ".join(outside) or "the free points at the box's edge"
        err = _error("box", head + f"needs a point outside the box {p.blocks[0].box}: {where}; "
                     f"box={box} would do", box)
        err.factor = far / max(_half(p), 1e-300)  # type: ignore[attr-defined]  # how far the default boxes must grow
        return err
    signed = _signed(p, D, lo)
    big = max(np.abs(free).max(), 1e-300)
    need = [label(p, i) for i, b in enumerate(p.blocks) if free[b.cols[0]] < -1e-9 * big]
    who = ", ".join(need) if need else "some of the candidates"
    far = (" (or, for a free point, the limit of a vanishing rate with the point at infinity: a constant force)"
           if any(b.free in (0, 1) for b in p.blocks) else "")
    residual = p.A @ signed + p.v
    left = (f"these energy terms cannot all vanish: {terms(p, residual)}"
            if np.ptp(residual) > _TERM_TOL * max(p.load_spread, 1e-300) else
            "the energy comes out constant only in that limit")
    return _error("negative", head + f"balance needs a negative rate or mass for {who}{far}; with rates and "
                  f"masses >= 0 and free points within {WIDER:g} times the box {left}")


#: how much wider than the given box (a square about the origin) a free point may go before the
#: verdict is "negative"
WIDER = 1000.0


def _half(p: Problem) -> float:
    """The largest half-width (m) of the candidates' boxes."""
    return max([(hi - lo) / 2 for b in p.blocks for lo, hi in b.box] + [0.0])


def _wider(p: Problem, D: np.ndarray):
    """A balanced solution with rates and masses >= 0 and free points in the smallest square about
    each box's centre, of half-width 2, 4, ... up to :data:`WIDER` times the larger of the boxes'
    half-width and the linkage's size (``p.size``; a box far smaller than the linkage is no yardstick),
    that has one: ``(x, half-width)``, or None."""
    U, s, Vt = np.linalg.svd(p.A / D, full_matrices=False)
    r = int((s > 1e-9 * max(s.max(initial=0.0), 1e-300)).sum())
    sigma = max(float(np.linalg.norm(p.v)), 1e-300)
    base = max(_half(p), p.size, 1e-300)
    eq = (Vt[:r], -(U[:, :r].T @ p.v) / s[:r] / sigma)
    if _in_square(p, D, WIDER * base, eq, sigma) is None:  # none even at the widest: no need to grow
        return None
    factor = 2.0
    while factor <= WIDER * 1.0001:
        x = _in_square(p, D, factor * base, eq, sigma)
        if x is not None:
            return x, factor * base
        factor *= 2.0 if factor < WIDER / 2 else WIDER / factor if factor < WIDER else 2.0
    return None


def _in_square(p: Problem, D: np.ndarray, w: float, eq, sigma: float):
    from scipy.optimize import linprog

    boxes = [(b.box, b.end_boxes) for b in p.blocks]
    try:
        for b in p.blocks:
            b.box = _square(b.box, w)
            if b.end_boxes is not None:
                b.end_boxes = [_square(box, w) for box in b.end_boxes]
        S = sigma / D
        bounds, A_ub, b_ub = lp_constraints(p, S)
    finally:
        for b, (box, ends) in zip(p.blocks, boxes):
            b.box, b.end_boxes = box, ends
    lp = linprog(np.zeros(p.nvar), A_ub=A_ub, b_ub=b_ub, A_eq=eq[0], b_eq=eq[1], bounds=bounds, method="highs")
    return lp.x * S if lp.status == 0 else None


def suggest(box: tuple, points: Sequence[np.ndarray]) -> tuple:
    """The box ``box`` widened to hold ``points`` (with a margin of a tenth of its new size), its
    bounds rounded outwards to two significant digits of that size.

    Examples
    --------
    >>> suggest(((-1.0, 1.0), (-1.0, 0.19)), [np.array([0.0, 0.1962])])
    ((-1.0, 1.0), (-1.0, 0.4))
    """
    out = []
    for axis, (lo, hi) in enumerate(box):
        vals = [lo, hi] + [float(pt[axis]) for pt in points]
        lo2, hi2 = min(vals), max(vals)
        margin = 0.1 * max(hi2 - lo2, abs(lo2), abs(hi2), 1e-300)
        lo2, hi2 = min(lo, lo2 - margin) if lo2 < lo else lo, max(hi, hi2 + margin) if hi2 > hi else hi
        step = 10.0 ** np.floor(np.log10(max(hi2 - lo2, 1e-300))) / 10
        out.append((float(lo) if lo2 == lo else float(np.floor(lo2 / step) * step),
                    float(hi) if hi2 == hi else float(np.ceil(hi2 / step) * step)))
    return tuple(out)


def limit(name: str, what: str, value: float, unit: str, bound: float, above: bool) -> InfeasibleDesign:
    """The :class:`InfeasibleDesign` (verdict ``"limit"``) of a balance that needs a rate or mass beyond
    the limits every design obeys (``1e-12 <= k <= 1e12`` N/m, loads up to ``1e12`` N).

    Examples
    --------
    >>> err = limit("lever", "springs[0] rate k", 9.81e14, "N/m", 1e12, above=True)
    >>> err.verdict, str(err)[:60]
    ('limit', 'lever: no balanced design from these candidates: springs[0] ')
    """
    side = "above the largest" if above else "below the smallest"
    hint = "a longer lever arm needs less" if above else "a shorter lever arm needs more"
    return _error("limit", f"{name}: no balanced design from these candidates: {what} would have to be "
                  f"{value:.3g} {unit}, {side} a design may hold ({bound:g} {unit}); move the candidate's "
                  f"points ({hint}) or choose other candidates")


def _square(box: tuple, w: float) -> tuple:
    """The square of half-width ``w`` (m) about ``box``'s centre."""
    (xl, xh), (yl, yh) = box
    cx, cy = (xl + xh) / 2, (yl + yh) / 2
    return ((cx - w, cx + w), (cy - w, cy + w))
