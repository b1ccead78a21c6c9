"""Sets of elements whose energies sum to a constant: together they do no work in any motion.

A report's yardstick must not count them (:func:`balancelab.core.report.load_scale`): three loads
``F, F, -F`` on three bodies of a parallelogram, or two stiff springs pulling from opposite sides,
exchange no energy with the rest of the design however large they are. Such sets are found here by
the energies themselves (not by which bodies the elements act on), so a set that cancels only
through the kinematics is found too. Layer: core.
"""
from __future__ import annotations

import numpy as np
from numpy.typing import ArrayLike

__all__ = ["EXACT", "MAX_ENUMERATED", "null_subset"]

#: A set of elements is *null* when the spread of its summed energy is at most this fraction of the
#: sum of its elements' own spreads (the closed-loop kinematics is solved to about 1e-12).
EXACT: float = 1e-9

#: Most elements (with a varying energy) whose subsets are all examined: ``2**16`` subsets; more
#: elements are searched by a mixed-integer program.
MAX_ENUMERATED: int = 16

#: Rows of the energies the integer program constrains (evenly spaced), before its answer is
#: checked on every row.
_MILP_ROWS = 256

_CHUNK = 2048
_ROWS = 128


def _subsets(n: int) -> np.ndarray:
    """Every subset of ``range(n)`` with at least two members, as rows of 0/1 (float)."""
    codes = np.arange(1, 2 ** n, dtype=np.int64)
    bits = ((codes[:, None] >> np.arange(n)) & 1).astype(float)
    return bits[bits.sum(1) >= 2]


def null_subset(energies: ArrayLike, eta: float = EXACT) -> np.ndarray:
    """The largest part of a design made of null sets: columns of ``energies`` that split into sets
    whose energies each sum to a constant, their own spreads adding up to the most.

    A set is null when ``ptp(sum of its columns) <= eta * sum of their ptp`` (plus the round-off of
    the sum). It counts as one piece when no part of it is null with a smaller residual ``ptp``
    (its cancellation is its own, not borrowed from a part), else only when it splits into two
    pieces. So a huge null set next to an unbalanced element is found without the element (the two
    together vary little compared with the huge set, but more than the huge set alone), while a
    balanced design with a spring of negligible rate is found whole.

    Parameters
    ----------
    energies : array_like, shape (m, n)
        Energy (J) of each element over ``m`` configurations.
    eta : float
        Relative tolerance of "sums to a constant", ``0 < eta < 1``.

    Up to :data:`MAX_ENUMERATED` varying columns every subset is examined; beyond, the heaviest null
    set is found by a mixed-integer program (:func:`_largest_by_milp`, HiGHS: exact for the null
    condition on every row), and members it only borrows cancellation from are then dropped one at a
    time (the enumeration's "one piece" rule, applied greedily).

    Returns
    -------
    numpy.ndarray of bool, shape (n,)
        The part; all False when none is null. Columns whose energy does not vary are never in it.

    Examples
    --------
    >>> t = np.linspace(0.0, 3.0, 50)
    >>> E = np.stack([np.sin(t), 2 * np.sin(t), -3 * np.sin(t), np.cos(t)], -1)  # J
    >>> null_subset(E).tolist()  # the first three cancel; the cosine cannot be cancelled
    [True, True, True, False]
    """
    E = np.asarray(energies, dtype=float)
    out = np.zeros(E.shape[1], dtype=bool)
    spread = np.ptp(E, axis=0)
    live = np.flatnonzero(spread > 0)
    if len(live) < 2:
        return out
    if len(live) > MAX_ENUMERATED:  # 2**n subsets are too many: one integer program instead
        out[live[_largest_by_milp(E[:, live], spread[live], eta)]] = True
        return out
    codes, weight, residual = _null_codes(E[:, live], spread[live], eta)
    ok = _pieces(codes, residual)
    if ok.any():
        best = int(codes[ok][np.argmax(weight[ok])])
        out[live[[(best >> i) & 1 == 1 for i in range(len(live))]]] = True
    return out


def _null_codes(E: np.ndarray, s: np.ndarray, eta: float):
    """Bit codes, weights (sum of spreads, J) and residuals (ptp of the sum, J) of the null subsets of
    the columns of ``E``."""
    codes = np.arange(1, 2 ** len(s), dtype=np.int64)
    sets = ((codes[:, None] >> np.arange(len(s))) & 1).astype(float)
    two = sets.sum(1) >= 2
    codes, sets = codes[two], sets[two]
    weight = sets @ s
    noise = 1e-14 * (sets @ np.max(np.abs(E), axis=0))  # round-off of the sum
    C = E[::max(1, len(E) // _ROWS)][:_ROWS]  # a prefilter on some rows (a large SVD calls BLAS threads)
    C = C - E.mean(0)
    _, sv, vt = np.linalg.svd(C, full_matrices=False)
    norm = np.linalg.norm((sets @ vt.T) * sv, axis=1)  # ||C x||: at most sqrt(rows) ptp(E x)
    keep = np.flatnonzero(norm <= np.sqrt(len(C)) * (eta * weight + noise)
                          + 1e-12 * sv[0] * np.linalg.norm(sets, axis=1))
    found, res = [], []
    for start in range(0, len(keep), _CHUNK):
        idx = keep[start:start + _CHUNK]
        ptp = np.ptp(E @ sets[idx].T, axis=0)
        ok = ptp <= eta * weight[idx] + noise[idx]
        found.append(idx[ok])
        res.append(ptp[ok])
    idx = np.concatenate(found) if found else np.zeros(0, dtype=np.int64)
    return codes[idx], weight[idx], (np.concatenate(res) if res else np.zeros(0))


def _pieces(codes: np.ndarray, residual: np.ndarray) -> np.ndarray:
    """For each null set (bit code): is it one piece (no null part of it cancels better), or two
    pieces side by side?"""
    order = np.argsort([bin(int(c)).count("1") for c in codes], kind="stable")
    codes, residual = codes[order], residual[order]
    ok = np.zeros(len(codes), dtype=bool)
    for i, c in enumerate(codes):
        inner = ((codes[:i] & c) == codes[:i]) & (codes[:i] != c)  # the null sets inside c (decided)
        if not (residual[:i][inner] < residual[i]).any():
            ok[i] = True
            continue
        parts = codes[:i][inner & ok[:i]]
        ok[i] = bool(np.isin(c ^ parts, parts).any())
    out = np.zeros(len(codes), dtype=bool)
    out[order] = ok
    return out


def _milp_null(E: np.ndarray, s: np.ndarray, eta: float, allowed: np.ndarray):
    """The heaviest null set (``s . x`` largest) of the ``allowed`` columns of ``E`` (spreads ``s``), by
    a mixed-integer program (HiGHS).

    Binary ``x`` (membership), continuous ``u``, ``l``: ``l <= E_r x <= u`` on every row ``r`` of
    :data:`_MILP_ROWS` evenly spaced rows, ``u - l <= eta s . x + noise . x`` (the null condition) and
    ``sum x >= 2``. Returns the mask, or None when there is none."""
    from scipy.optimize import Bounds, LinearConstraint, milp

    n = E.shape[1]
    noise = 1e-14 * np.max(np.abs(E), axis=0)
    rows = E[np.unique(np.linspace(0, len(E) - 1, min(len(E), _MILP_ROWS)).astype(int))]
    rows = rows - rows[0]  # energies about the first row: a constant offset changes nothing
    m = len(rows)
    A = np.zeros((2 * m + 2, n + 2))
    A[:m, :n], A[:m, n] = rows, -1.0  # E_r x - u <= 0
    A[m:2 * m, :n], A[m:2 * m, n + 1] = -rows, 1.0  # l - E_r x <= 0
    A[2 * m, :n], A[2 * m, n], A[2 * m, n + 1] = -(eta * s + noise), 1.0, -1.0  # u - l <= (eta s + noise) . x
    A[2 * m + 1, :n] = -1.0  # at least two members
    upper = np.r_[np.zeros(2 * m + 1), -2.0]
    big = float(np.abs(rows).sum(1).max(initial=0.0)) + 1.0
    cost = np.r_[-s / s.max(), 0.0, 0.0]
    bounds = Bounds(np.r_[np.zeros(n), -big, -big], np.r_[allowed.astype(float), big, big])
    res = milp(cost, constraints=LinearConstraint(A, -np.inf, upper), integrality=np.r_[np.ones(n), 0, 0],
               bounds=bounds, options={"time_limit": 10.0})
    return None if res.x is None else res.x[:n] > 0.5


#: Largest null set looked for inside a null set found by the integer program, by enumeration (the
#: integer program cannot tell residuals below its tolerances, some 1e-7 of the energies, apart).
_SMALL_PIECE = 3


def _smallest_null(E, s, eta, noise, within: np.ndarray):
    """The null set of at most :data:`_SMALL_PIECE` members of ``within`` whose summed energy varies
    least, as a mask (None when none is null)."""
    from itertools import combinations

    idx = np.flatnonzero(within)
    sets = [c for size in range(2, _SMALL_PIECE + 1) for c in combinations(idx, size)]
    if not sets:
        return None
    X = np.zeros((E.shape[1], len(sets)))
    for j, c in enumerate(sets):
        X[list(c), j] = 1.0
    ptp = np.ptp(E @ X, axis=0)
    ok = ptp <= eta * (s @ X) + noise @ X
    if not ok.any():
        return None
    best = np.flatnonzero(ok)[np.argmin(ptp[ok])]
    return X[:, best] > 0.5


def _largest_by_milp(E: np.ndarray, s: np.ndarray, eta: float) -> np.ndarray:
    """The largest part made of null sets, each one piece, as a mask (mixed-integer programs).

    The heaviest null set ``S`` of what is left is one piece when no null set of at most
    :data:`_SMALL_PIECE` members inside it varies less (its cancellation is its own); else that
    smaller set is a piece (a huge null set does not carry an unbalanced element along). Pieces are
    taken out until none is left; each is checked on every row."""
    n = E.shape[1]
    noise = 1e-14 * np.max(np.abs(E), axis=0)

    def residual(mask):
        return float(np.ptp(E[:, mask].sum(-1)))

    def null(mask):
        return mask.sum() >= 2 and residual(mask) <= eta * float(s[mask].sum()) + float(noise[mask].sum())

    out = np.zeros(n, dtype=bool)
    left = np.ones(n, dtype=bool)
    for _ in range(n):
        heavy = _milp_null(E, s, eta, left)
        if heavy is None or not null(heavy):
            break
        light = _smallest_null(E, s, eta, noise, heavy)
        piece = light if light is not None and residual(light) < residual(heavy) else heavy
        out |= piece
        left &= ~piece
    return out
