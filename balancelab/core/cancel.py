"""Sets of elements whose energies sum to a constant: together they do no work in any motion.

A report's yardstick must not count them (:func:`balancelab.core.report.load_scale`): three loads
``F, F, -F`` on three bodies of a parallelogram, or two stiff springs pulling from opposite sides,
exchange no energy with the rest of the design however large they are. Such sets are found here by
the energies themselves (not by which bodies the elements act on), so a set that cancels only
through the kinematics is found too. Layer: core.
"""
from __future__ import annotations

import numpy as np

__all__ = ["EXACT", "MAX_ENUMERATED", "null_subset"]

#: A set of elements is *null* when the spread of its summed energy is at most this fraction of the
#: sum of its elements' own spreads (the closed-loop kinematics is solved to about 1e-12).
EXACT: float = 1e-9

#: Most elements (with a varying energy) whose subsets are all examined: ``2**16`` subsets.
MAX_ENUMERATED: int = 16

_CHUNK = 2048


def _subsets(n: int) -> np.ndarray:
    """Every subset of ``range(n)`` with at least two members, as rows of 0/1 (float)."""
    codes = np.arange(1, 2 ** n, dtype=np.int64)
    bits = ((codes[:, None] >> np.arange(n)) & 1).astype(float)
    return bits[bits.sum(1) >= 2]


def null_subset(energies, eta: float = EXACT, proper: bool = True) -> np.ndarray:
    """The null set of columns of ``energies`` whose own spreads add up to the most.

    A set is null when ``ptp(sum of its columns) <= eta * sum of their ptp`` (plus the round-off of
    the sum). Columns whose energy does not vary are never in it.

    Parameters
    ----------
    energies : array_like, shape (m, n)
        Energy (J) of each element over ``m`` configurations.
    eta : float
        Relative tolerance of "sums to a constant", ``0 < eta < 1``.
    proper : bool
        Leave at least one varying column out (the set sought is then a part of the design).

    Returns
    -------
    numpy.ndarray of bool, shape (n,)
        The set; all False when none is null (or when more than :data:`MAX_ENUMERATED` columns
        vary: the search is exhaustive or not done).

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
    n = len(live) - (1 if proper else 0)
    if n < 2 or len(live) > MAX_ENUMERATED:
        return out
    C = E[:, live] - E[:, live].mean(0)
    s = spread[live]
    sets = _subsets(len(live))
    if proper:
        sets = sets[sets.sum(1) < len(live)]
    weight = sets @ s
    noise = 1e-14 * (sets @ np.max(np.abs(E[:, live]), axis=0))  # round-off of the sum
    _, sv, vt = np.linalg.svd(C, full_matrices=False)
    norm = np.linalg.norm((sets @ vt.T) * sv, axis=1)  # ||C x||: at most sqrt(m) ptp(C x)
    keep = norm <= np.sqrt(len(E)) * (eta * weight + noise) + 1e-12 * sv[0] * np.linalg.norm(sets, axis=1)
    order = np.flatnonzero(keep)[np.argsort(-weight[keep], kind="stable")]
    for start in range(0, len(order), _CHUNK):
        idx = order[start:start + _CHUNK]
        ok = np.ptp(E[:, live] @ sets[idx].T, axis=0) <= eta * weight[idx] + noise[idx]
        if ok.any():
            out[live[sets[idx[np.argmax(ok)]] > 0]] = True
            return out
    return out
