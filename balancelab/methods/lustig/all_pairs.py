"""A serial chain balanced by one ZFL spring between every pair of links, without sympy.

With a spring between every pair ``(I, K)`` of paper links (ground included), the balance
condition of block ``(I, K)`` of ``K_t`` is linear in the distal attachments ``b`` of the
springs ending on link ``K``, and only those starting at or before ``I`` enter it, so
the conditions are solved in order as a triangular sequence of complex divisions.
"""
from __future__ import annotations

from typing import Mapping, Sequence

from ...core.design import Design
from ...core.elements import G, Spring
from ...core.validation import finite_real, planar_point
from .chain import REFERENCE, SerialChain

__all__ = ["balance_all_pairs"]

_DEFAULT_K = 1000.0  # N/m


def _pair_rates(k, pairs: list) -> dict:
    """Spring rate (N/m) of every pair: one number for all, or a mapping (default 1000 N/m)."""
    if k is None:
        k = _DEFAULT_K
    if isinstance(k, Mapping):
        return {p: finite_real(f"k[{p}] (N/m)", k[p], positive=True) if p in k else _DEFAULT_K
                for p in pairs}
    rate = finite_real("k (N/m)", k, positive=True)
    return {p: rate for p in pairs}


def _pair_anchors(anchors, pairs: list, lengths: tuple) -> dict:
    """Proximal attachment (local, m) of every pair's spring, off the proximal body's distal joint."""
    anchors = dict(anchors or {})
    Ls = (0.0,) + lengths
    a = {}
    for (i, j) in pairs:
        pt = anchors.get((i, j), (0.0, 0.1) if i == 0 else (lengths[i - 1] / 2, 0.05))
        pt = planar_point(f"anchors[{(i, j)}]", pt)
        c = complex(Ls[i] - pt[0], -pt[1])
        if abs(c) < 1e-12:
            raise ValueError(f"anchors[{(i, j)}] = {pt} sits on the distal joint of body {i} "
                             "(the origin on the ground); the spring could not act across the pair")
        a[(i, j)] = pt
    return a


def _distal_attachments(chain: SerialChain, pairs: list, rates: dict, a: dict) -> dict:
    """Distal attachment (local, m) of every pair's spring from the block conditions, in order.

    Each rotation-scale block ``p I + s R`` is the complex number ``p + i s``; block
    ``(I, K)`` is ``sum_j k conj(c_I) c_K`` (plus gravity on the ground row), with
    ``c_I = L_I - a`` on the spring's proximal body and ``L`` on the links it spans.
    """
    n, lengths, masses, coms = chain.n, chain.lengths, chain.masses, chain.coms
    Ls = (0.0,) + lengths
    # first moment of the weights on and beyond body u, in body u's frame
    mu = [masses[u - 1] * complex(*coms[u - 1]) + sum(masses[u:]) * Ls[u] for u in range(1, n + 1)]
    b: dict[tuple[int, int], tuple[float, float]] = {}
    for K_ in range(1, n + 1):          # distal body of the block
        for I in range(0, K_):          # proximal body of the block
            total = -1j * G * mu[K_ - 1] if I == 0 else 0j
            own = None
            for (i, j) in pairs:
                if not (i <= I and j >= K_):
                    continue
                cI = complex(Ls[I] - a[(i, j)][0], -a[(i, j)][1]) if i == I else complex(Ls[I])
                if j == K_:
                    if (i, j) == (I, K_):
                        own = rates[(i, j)] * cI.conjugate()
                        continue
                    cK = complex(*b[(i, j)])
                else:
                    cK = complex(Ls[K_])
                total += rates[(i, j)] * cI.conjugate() * cK
            assert own is not None  # the pair (I, K) itself is among the pairs
            z = -total / own
            b[(I, K_)] = (z.real, z.imag)
    return b


def balance_all_pairs(lengths: Sequence[float], masses: Sequence[float],
                      coms: Sequence[tuple[float, float]],
                      k: float | Mapping[tuple[int, int], float] | None = None,
                      anchors: Mapping[tuple[int, int], tuple[float, float]] | None = None, *,
                      name: str = "serial chain, one ZFL spring per pair of links") -> Design:
    """Balance an n-link chain with one ZFL spring between every pair of links, numerically.

    With a spring between every pair ``(I, K)`` of paper links (ground included), the
    condition of block ``(I, K)`` is linear in the distal attachments ``b`` of the
    springs ending on link ``K``, and only those starting at or before ``I`` enter it;
    solving the blocks in order ``I = 1, 2, ...`` is therefore a triangular sequence of
    complex divisions (writing each rotation-scale block ``p I + s R`` as ``p + i s``):
    ``b_IK = -(sum of the other terms) / (k_IK conj(c_I))`` with ``c_I = L_I - a_IK``
    (``-a`` on the ground). Stiffnesses and proximal attachments are chosen; the
    distal attachments are the result. No sympy is needed.

    Parameters
    ----------
    lengths : sequence of float
        Link lengths (m), one per moving link (n = 1..8), each > 0.
    masses : sequence of float
        Link masses (kg), each > 0.
    coms : sequence of (float, float)
        Centre of mass of each link in its local frame (m).
    k : mapping of (int, int) to float, or float, optional
        Spring rate (N/m, > 0) of the spring between bodies ``(i, j)``, ``i < j``; one
        number for all; default 1000 N/m.
    anchors : mapping of (int, int) to (float, float), optional
        Proximal attachment of each spring on body ``i`` (local, m). Default: on the
        ground ``(0, 0.1)``; on a moving link ``(L/2, 0.05)``. It must differ from the
        proximal body's distal joint (from the origin on the ground).

    Returns
    -------
    Design
        The balanced chain; ``q`` are absolute link angles (rad).

    Examples
    --------
    >>> d = balance_all_pairs((0.4, 0.3, 0.2), (3.0, 2.0, 1.0), ((0.2, 0.0), (0.15, 0.02), (0.1, 0.0)))
    >>> len(d.springs), d.balance_report().balanced
    (6, True)
    """
    chain = SerialChain(lengths, masses, coms)  # validates lengths, masses and coms
    n = chain.n
    pairs = [(i, j) for j in range(1, n + 1) for i in range(j)]
    rates = _pair_rates(k, pairs)
    a = _pair_anchors(anchors, pairs, chain.lengths)
    b = _distal_attachments(chain, pairs, rates, a)
    springs = [Spring(rates[p], 0.0, (p[0], a[p]), (p[1], b[p]), name=f"k{idx}")
               for idx, p in enumerate(pairs, start=1)]
    balanced = SerialChain(chain.lengths, chain.masses, chain.coms, tuple(springs))
    return balanced.design(name, reference=REFERENCE + "; triangular solution of the block conditions")
