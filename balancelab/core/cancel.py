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

#: Most elements (with a varying energy) whose subsets are all examined: ``2**16`` subsets.
MAX_ENUMERATED: int = 16

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

    Returns
    -------
    numpy.ndarray of bool, shape (n,)
        The part; all False when none is null (or when more than :data:`MAX_ENUMERATED` columns
        vary: the search is exhaustive or not done). Columns whose energy does not vary are never in it.

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
    if len(live) < 2 or len(live) > MAX_ENUMERATED:
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
