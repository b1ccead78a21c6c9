"""The total stiffness matrix ``K_t`` of a serial chain, numerically and in the paper's symbols.

Every point of the chain is linear in the stacked state ``Q = (q_1, ..., q_N)`` of unit
vectors ``q_u = (cos theta_u, sin theta_u)``, so the energy of the ZFL springs and of
gravity is the quadratic form ``U = 1/2 Q^T K_t Q`` (eqs 5-13). A spring from link ``u``
to link ``v`` contributes ``k C^T C`` with the row of rotation-scale blocks
``C = (C_1, ..., C_N)`` of eq. 7; a weight contributes the blocks ``D_u`` pairing the
constant ground state ``q_1 = (1, 0)`` with link ``u`` (eqs 10-12).

Typo in the paper: eq. 16a carries a factor ``1/2`` in front of ``K_si``; with it, eq. 17
would read ``k_1/2``. Eq. 8e (no factor) is the consistent definition and is the one
used here; eq. 17 and Table 3e agree with it.
"""
from __future__ import annotations

import functools

import numpy as np

from ...core.elements import G
from ...core.validation import finite_real, instance_of, real_array
from .chain import SerialChain, chain_parameter_names, check_topology

__all__ = ["stiffness_matrix", "stiffness_matrix_symbolic", "quadratic_energy"]


def _rs(p, s):
    """Rotation-scale 2x2 block ``[[p, -s], [s, p]]`` = ``p I + s R``."""
    return ((p, -s), (s, p))


def _spring_blocks(N, ua, ub, Ls, a, b):
    """The paper's C_1..C_N (eq. 7) of a spring from link ``ua`` to ``ub`` (paper numbers)."""
    zero = _rs(0, 0)
    blocks = [zero] * N
    La = Ls[ua - 1]
    blocks[ua - 1] = _rs(La - a[0], -a[1])
    for i in range(ua + 1, ub):
        blocks[i - 1] = _rs(Ls[i - 1], 0)
    blocks[ub - 1] = _rs(b[0], b[1])
    return blocks


def stiffness_matrix(chain: SerialChain, g: float = G) -> np.ndarray:
    """The total stiffness matrix ``K_t`` of a chain, numerically (eqs 7, 8e, 11, 12b, 13b).

    Parameters
    ----------
    chain : SerialChain
        The chain with its springs.
    g : float
        Gravitational acceleration (m/s^2) along -y.

    Returns
    -------
    numpy.ndarray, shape (2N, 2N)
        ``K_t`` with ``N = n + 1`` links (ground first), in N/m * m^2 = J per unit
        state product: the energy is ``1/2 Q^T K_t Q`` (J).

    Examples
    --------
    >>> from balancelab.methods.lustig import LUSTIG_TOPOLOGY, lustig_values
    >>> K = stiffness_matrix(SerialChain.from_values(2, LUSTIG_TOPOLOGY, lustig_values(1)))
    >>> K.shape
    (6, 6)
    >>> float(abs(K[0, 2:]).max()) < 1e-12
    True
    """
    if not isinstance(chain, SerialChain):
        raise TypeError(f"chain must be a SerialChain, got {type(chain).__name__}")
    g = finite_real("g (m/s^2)", g)
    n = chain.n
    N = n + 1
    Ls = (0.0,) + chain.lengths
    K = np.zeros((2 * N, 2 * N))
    for s in chain.springs:
        blocks = _spring_blocks(N, s.a.body + 1, s.b.body + 1, Ls, s.a.point, s.b.point)
        C = np.hstack([np.array(c, dtype=float) for c in blocks])
        K += s.k * (C.T @ C)
    m = chain.masses
    for u in range(2, N + 1):
        i = u - 2
        below = sum(m[i + 1:])
        D = np.array(_rs(m[i] * g * chain.coms[i][1],
                         -(m[i] * g * chain.coms[i][0] + below * g * Ls[u - 1])))
        K[0:2, 2 * (u - 1):2 * u] += D
        K[2 * (u - 1):2 * u, 0:2] += D.T
    return K


def _state_vector(q: np.ndarray) -> np.ndarray:
    q = np.asarray(q, dtype=float)
    c, s = np.cos(q), np.sin(q)
    Q = np.empty(q.shape[:-1] + (2 * (q.shape[-1] + 1),))
    Q[..., 0], Q[..., 1] = 1.0, 0.0
    Q[..., 2::2], Q[..., 3::2] = c, s
    return Q


def quadratic_energy(chain: SerialChain, q, g: float = G) -> np.ndarray:
    """Potential energy ``U_t = 1/2 Q^T K_t Q`` (J) at absolute link angles ``q`` (eq. 13a).

    Parameters
    ----------
    chain : SerialChain
    q : array_like, shape (..., n)
        Absolute link angles (rad).
    g : float
        Gravitational acceleration (m/s^2).

    Returns
    -------
    numpy.ndarray, shape (...)

    Examples
    --------
    >>> from balancelab.methods.lustig import LUSTIG_TOPOLOGY, lustig_values
    >>> c = SerialChain.from_values(2, LUSTIG_TOPOLOGY, lustig_values(1))
    >>> e = quadratic_energy(c, [[0.0, 0.0], [1.0, -2.0]])
    >>> bool(abs(e[0] - e[1]) < 1e-12)
    True
    """
    instance_of("chain", chain, SerialChain, "a SerialChain")
    q = real_array("q (absolute link angles, rad)", q)
    if q.ndim == 0 or q.shape[-1] != chain.n:
        raise ValueError(f"q must have shape (..., {chain.n}), got {q.shape}")
    if not np.all(np.isfinite(q)):
        raise ValueError("q (absolute link angles, rad) must be finite")
    K = stiffness_matrix(chain, g)
    Q = _state_vector(q)
    return 0.5 * np.einsum("...i,ij,...j->...", Q, K, Q)


# ------------------------------------------------------------------------- symbolic
@functools.lru_cache(maxsize=64)
def _symbolic_matrix(n: int, topology: tuple):
    """``(K_t, symbols by name)`` in the paper's symbols; ``n``, ``topology`` already checked."""
    import sympy as sp

    names = chain_parameter_names(n, topology)
    syms = {name: sp.Symbol(name, real=True) for name in names}
    N = n + 1
    Ls = [sp.S.Zero] + [syms[f"L{u}"] for u in range(2, N + 1)]
    K = sp.zeros(2 * N, 2 * N)
    for j, (ba, bb) in enumerate(topology, start=1):
        a = (syms[f"ax{j}"], syms[f"ay{j}"])
        b = (syms[f"bx{j}"], syms[f"by{j}"])
        blocks = _spring_blocks(N, ba + 1, bb + 1, Ls, a, b)
        C = sp.Matrix.hstack(*[sp.Matrix(c) for c in blocks])
        K += syms[f"k{j}"] * (C.T * C)
    g = syms["g"]
    for u in range(2, N + 1):
        m = syms[f"m{u}"]
        below = sp.Add(*[syms[f"m{i}"] for i in range(u + 1, N + 1)])
        D = sp.Matrix(_rs(m * g * syms[f"sy{u}"], -(m * g * syms[f"sx{u}"] + below * g * Ls[u - 1])))
        K[0:2, 2 * (u - 1):2 * u] = K[0:2, 2 * (u - 1):2 * u] + D
        K[2 * (u - 1):2 * u, 0:2] = K[2 * (u - 1):2 * u, 0:2] + D.T
    return K.applyfunc(sp.expand), syms


def stiffness_matrix_symbolic(n: int, topology):
    """The total stiffness matrix ``K_t`` in the paper's symbols (eqs 7, 8e, 11, 12b, 13b).

    Cached per ``(n, topology)``.

    Parameters
    ----------
    n : int
        Number of moving links.
    topology : sequence of (int, int)
        ``(proximal body, distal body)`` of each spring (balancelab body indices: 0 is
        the ground, body ``i`` is the paper's link ``i + 1``).

    Returns
    -------
    K : sympy.Matrix, shape (2N, 2N)
    symbols : dict of str to sympy.Symbol
        Every parameter symbol by name (:func:`chain_parameter_names`).

    Examples
    --------
    >>> K, s = stiffness_matrix_symbolic(2, ((0, 2), (1, 2)))
    >>> K[0, 2]
    -L2*ax1*k1 + g*m2*sy2
    """
    n, topology = check_topology(n, topology)
    K, syms = _symbolic_matrix(n, topology)
    return K.copy(), dict(syms)
