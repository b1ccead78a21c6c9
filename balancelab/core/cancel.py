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
    """The largest part of a design made of null sets: columns of ``energies`` that split into sets
    whose energies each sum to a constant, their own spreads adding up to the most.

    A set is null when ``ptp(sum of its columns) <= eta * sum of their ptp`` (plus the round-off of
    the sum) and it is either *irreducible* (no part of it is null) or splits into two such parts.
    So a huge null set next to an unbalanced element is found without the element: the two together
    vary by little compared with the huge set, but the element alone is not null. Columns whose energy
    does not vary are never in it.

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
    if len(live) - (1 if proper else 0) < 2 or len(live) > MAX_ENUMERATED:
        return out
    codes, weight = _null_codes(E[:, live], spread[live], eta)
    if proper:
        keep = codes != (1 << len(live)) - 1
        codes, weight = codes[keep], weight[keep]
    ok = _packable(codes)
    if ok.any():
        best = int(codes[ok][np.argmax(weight[ok])])
        out[live[[(best >> i) & 1 == 1 for i in range(len(live))]]] = True
    return out


def _null_codes(E: np.ndarray, s: np.ndarray, eta: float):
    """Bit codes and weights (sum of spreads, J) of the null subsets of the columns of ``E``."""
    codes = np.arange(1, 2 ** len(s), dtype=np.int64)
    sets = ((codes[:, None] >> np.arange(len(s))) & 1).astype(float)
    two = sets.sum(1) >= 2
    codes, sets = codes[two], sets[two]
    weight = sets @ s
    noise = 1e-14 * (sets @ np.max(np.abs(E), axis=0))  # round-off of the sum
    C = E - E.mean(0)
    _, sv, vt = np.linalg.svd(C, full_matrices=False)
    norm = np.linalg.norm((sets @ vt.T) * sv, axis=1)  # ||C x||: at most sqrt(m) ptp(C x)
    keep = np.flatnonzero(norm <= np.sqrt(len(E)) * (eta * weight + noise)
                          + 1e-12 * sv[0] * np.linalg.norm(sets, axis=1))
    found = []
    for start in range(0, len(keep), _CHUNK):
        idx = keep[start:start + _CHUNK]
        found.append(idx[np.ptp(E @ sets[idx].T, axis=0) <= eta * weight[idx] + noise[idx]])
    idx = np.concatenate(found) if found else np.zeros(0, dtype=np.int64)
    return codes[idx], weight[idx]


def _packable(codes: np.ndarray) -> np.ndarray:
    """For each null set (bit code): is it irreducible, or two packable null sets side by side?"""
    order = np.argsort([bin(int(c)).count("1") for c in codes], kind="stable")
    codes = codes[order]
    ok = np.zeros(len(codes), dtype=bool)
    for i, c in enumerate(codes):
        inner = (codes[:i] & c) == codes[:i]  # the null sets inside c (all smaller, so decided)
        inner &= codes[:i] != c
        if not inner.any():
            ok[i] = True
            continue
        parts = codes[:i][inner & ok[:i]]
        ok[i] = bool(np.isin(c ^ parts, parts).any())
    out = np.zeros(len(codes), dtype=bool)
    out[order] = ok
    return out
