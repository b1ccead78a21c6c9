"""Why a balance problem has no admissible solution: one of three verdicts, each with its evidence.

* ``"impossible"`` — *impossible for any rates*: even with rates and masses of any sign (and
  free points anywhere) the candidates cannot make the energy constant; the message names the
  energy terms left over that no candidate can produce (those above ``1e-9`` of the energy the
  loads exchange);
* ``"negative"`` — *needs a negative rate or mass*: a solution exists, but only with a negative
  rate or counter mass, named in the message;
* ``"box"`` — *needs a point outside the box*: a solution with rates and masses ``>= 0`` exists
  once the free points may leave the box; the message names the points and a box that would do
  (``err.box``).

The verdict is stored on the exception (``err.verdict``). Layer: methods.
"""
from __future__ import annotations

import numpy as np

from ..lustig.solving import InfeasibleDesign
from .problem import Problem, harmonics

__all__ = ["VERDICTS", "infeasible", "nice_box"]

#: the three reasons a balance problem has no admissible solution
VERDICTS = ("impossible", "negative", "box")

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
    found = [(n, v) for n, v in harmonics(p.design, p.poses, residual) if abs(v) > tol]
    return ", ".join(f"{v:.3g} J × {name}" for name, v in found) or f"{np.ptp(residual):.3g} J in all"


def _rates(p: Problem) -> np.ndarray:
    lo = np.full(p.nvar, -np.inf)
    for b in p.blocks:
        lo[b.cols[0]] = 0.0
    return lo


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
    from scipy.optimize import linprog, lsq_linear

    head = f"no balanced design from these candidates (objective {objective!r}{detail}): "
    tol = 1e-10 * max(p.load_spread, 1e-300)
    free = np.linalg.lstsq(p.A / D, -p.v, rcond=1e-12)[0] / D
    unsigned = p.A @ free + p.v
    if np.ptp(unsigned) > tol:
        return _error("impossible", head + "impossible for any rates: even with rates and masses of any sign "
                      f"they cannot make the energy constant; left over: {terms(p, unsigned)}")
    lo = _rates(p)
    sigma = max(np.linalg.norm(p.v), 1e-300)
    U, s, Vt = np.linalg.svd(p.A / D, full_matrices=False)
    r = int((s > 1e-9 * max(s.max(initial=0.0), 1e-300)).sum())
    cost = np.where(np.isfinite(lo), 1.0, 0.0)
    bounds = [(0.0, None) if np.isfinite(v) else (None, None) for v in lo]
    lp = linprog(cost, A_eq=Vt[:r], b_eq=-(U[:, :r].T @ p.v) / s[:r] / sigma, bounds=bounds, method="highs")
    if lp.status == 0:
        x = lp.x * sigma / D
        outside, far = [], 0.0
        for i, b in enumerate(p.blocks):
            k = x[b.cols[0]]
            if b.free not in (0, 1) or k <= 0:
                continue
            pt = x[b.cols[1:]] / k
            far = max(far, float(np.abs(pt).max()))
            (xl, xh), (yl, yh) = b.box
            if not (xl <= pt[0] <= xh and yl <= pt[1] <= yh):
                end = "counterweight" if b.kind == "mass" else f"end {b.free}"
                outside.append(f"{label(p, i)} {end} at ({pt[0]:.4g}, {pt[1]:.4g}) m")
        box = nice_box(1.1 * far)
        where = ", ".join(outside) or "the free points at the box's edge"
        return _error("box", head + f"needs a point outside the box {p.blocks[0].box}: {where}; "
                      f"box={box} would do", box)
    signed = lsq_linear(p.A / D, -p.v, bounds=(lo, np.full(p.nvar, np.inf))).x / D
    big = max(np.abs(free).max(), 1e-300)
    need = [label(p, i) for i, b in enumerate(p.blocks) if free[b.cols[0]] < -1e-9 * big]
    who = ", ".join(need) if need else "some of the candidates (no combination with all of them >= 0)"
    return _error("negative", head + f"balance needs a negative rate or mass for {who}; with rates and masses "
                  f">= 0 these energy terms cannot all vanish: {terms(p, p.A @ signed + p.v)}")
