"""The balance conditions of a serial chain: the off-diagonal entries of ``K_t`` set to zero.

The diagonal 2x2 blocks of ``K_t`` are multiples of the identity and contribute
constants (``q_u^T q_u = 1``); every off-diagonal block is a rotation-scale matrix
``[[p, -s], [s, p]]`` that multiplies ``cos(theta_v - theta_u)`` and
``sin(theta_v - theta_u)``. The chain is balanced, for every pose, exactly when all
off-diagonal entries vanish: ``N (N - 1)`` scalar equations for ``N`` links (the ground
counted), read off the odd rows of ``K_t`` (Sec. II.B.4). The equations in the ground
row hold the gravity terms; the others couple two moving links.
"""
from __future__ import annotations

import functools
from types import MappingProxyType

import numpy as np

from ...core.elements import G
from .chain import SerialChain, check_topology
from .matrix import stiffness_matrix, stiffness_matrix_symbolic

__all__ = ["constraint_equations", "constraint_residuals", "gravity_conditions", "diagonal_residual",
           "condition_system"]


def _constraint_entries(N: int) -> list[tuple[int, int]]:
    """1-based (row, col) of the N(N-1) independent off-diagonal entries (odd rows)."""
    out = []
    for I in range(1, N + 1):
        for Kb in range(I + 1, N + 1):
            out.append((2 * I - 1, 2 * Kb - 1))
            out.append((2 * I - 1, 2 * Kb))
    return out


def constraint_residuals(chain: SerialChain, g: float = G) -> dict:
    """The off-diagonal entries of ``K_t`` that must vanish, numerically.

    Parameters
    ----------
    chain : SerialChain
    g : float
        Gravitational acceleration (m/s^2).

    Returns
    -------
    dict
        ``{(row, col): value}`` with the paper's 1-based indices, ``N (N - 1)`` entries
        (J); all zero for a balanced chain. The first ``2 n`` (row 1) are the gravity
        conditions.

    Examples
    --------
    >>> from balancelab.methods.lustig import LUSTIG_TOPOLOGY, lustig_values
    >>> r = constraint_residuals(SerialChain.from_values(2, LUSTIG_TOPOLOGY, lustig_values(2)))
    >>> len(r), bool(max(abs(v) for v in r.values()) < 1e-12)
    (6, True)
    """
    K = stiffness_matrix(chain, g)
    return {(r, c): float(K[r - 1, c - 1]) for r, c in _constraint_entries(chain.n + 1)}


def diagonal_residual(K) -> float:
    """Largest departure of the diagonal 2x2 blocks of ``K_t`` from a multiple of ``I``.

    A diagonal block ``K_uu`` contributes ``q_u^T K_uu q_u``, which is constant for a
    unit vector ``q_u`` exactly when ``K_uu`` is isotropic; the paper's components make
    it so for every ZFL spring and mass (``C^T C = (p^2 + s^2) I``, Sec. II.B.4), so
    only the off-diagonal entries carry conditions. Works for numeric and sympy
    matrices (returns a float or a sympy expression).

    Parameters
    ----------
    K : array_like or sympy.Matrix, shape (2N, 2N)

    Returns
    -------
    float or sympy.Expr

    Examples
    --------
    >>> from balancelab.methods.lustig import LUSTIG_TOPOLOGY, lustig_values, stiffness_matrix
    >>> K = stiffness_matrix(SerialChain.from_values(2, LUSTIG_TOPOLOGY, lustig_values(3)))
    >>> diagonal_residual(K) < 1e-12
    True
    """
    if hasattr(K, "is_symbolic") or type(K).__module__.startswith("sympy"):
        import sympy as sp

        terms = []
        for u in range(K.shape[0] // 2):
            b = K[2 * u:2 * u + 2, 2 * u:2 * u + 2]
            terms += [sp.expand(b[0, 0] - b[1, 1]), sp.expand(b[0, 1]), sp.expand(b[1, 0])]
        return sp.Add(*[sp.Abs(t) for t in terms])
    K = np.asarray(K, dtype=float)
    if K.ndim != 2 or K.shape[0] != K.shape[1] or K.shape[0] % 2:
        raise ValueError(f"K must be a square matrix of even size, got shape {K.shape}")
    worst = 0.0
    for u in range(K.shape[0] // 2):
        b = K[2 * u:2 * u + 2, 2 * u:2 * u + 2]
        worst = max(worst, abs(b[0, 0] - b[1, 1]), abs(b[0, 1]), abs(b[1, 0]))
    return float(worst)


@functools.lru_cache(maxsize=64)
def _condition_system(n: int, topology: tuple):
    import sympy as sp

    K, syms = stiffness_matrix_symbolic(n, topology)
    eqs = {rc: sp.Eq(K[rc[0] - 1, rc[1] - 1], 0) for rc in _constraint_entries(n + 1)}
    return MappingProxyType(syms), MappingProxyType(eqs)


def condition_system(n: int, topology):
    """The parameter symbols and the balance conditions of a chain, shared and read-only.

    Cached per ``(n, topology)``: the solver builds on these objects. Use
    :func:`constraint_equations` for a copy of the conditions.

    Parameters
    ----------
    n : int
        Number of moving links.
    topology : sequence of (int, int)
        ``(proximal body, distal body)`` of each spring.

    Returns
    -------
    symbols : mapping of str to sympy.Symbol
        Every parameter symbol by name (:func:`chain_parameter_names`).
    equations : mapping of (int, int) to sympy.Eq
        As :func:`constraint_equations`.

    Examples
    --------
    >>> symbols, equations = condition_system(1, [(0, 1)])
    >>> len(equations), symbols["k1"] in equations[(1, 3)].lhs.free_symbols
    (2, True)
    """
    n, topology = check_topology(n, topology)
    return _condition_system(n, topology)


def constraint_equations(n: int, topology) -> dict:
    """The balance conditions: every independent off-diagonal entry of ``K_t`` set to zero.

    For ``N = n + 1`` links there are ``N (N - 1)`` of them (Sec. II.B.4), taken from the
    odd rows ``2I - 1`` and the columns of the blocks to the right of the diagonal. Row
    1 holds the gravity conditions (ground-link coupling); the others couple two moving
    links. For the paper's example (``n = 2``, springs ``(0, 2)`` and ``(1, 2)``) these
    are eq. 17.

    Parameters
    ----------
    n : int
        Number of moving links.
    topology : sequence of (int, int)
        ``(proximal body, distal body)`` of each spring.

    Returns
    -------
    dict
        ``{(row, col): sympy.Eq(entry, 0)}`` with the paper's 1-based indices.

    Examples
    --------
    >>> eqs = constraint_equations(2, ((0, 2), (1, 2)))
    >>> eqs[(1, 4)]
    Eq(-L2*ay1*k1 + L2*g*m3 + g*m2*sx2, 0)
    """
    return dict(condition_system(n, topology)[1])


def gravity_conditions(n: int, topology) -> dict:
    """The gravity conditions: the constraint equations of the ground row of ``K_t``.

    Gravity enters ``K_t`` only through the blocks ``D_u`` that pair the constant ground
    state ``q_1`` with each link (eqs 10-12), so exactly the ``2 n`` equations of row 1
    carry ``g``: each says that the springs reaching the ground cancel the first moment
    of the weights on and beyond link ``u``. The remaining conditions (rows 3, 5, ...)
    involve springs only. The diagonal blocks carry no condition at all (see
    :func:`diagonal_residual`).

    Parameters
    ----------
    n : int
        Number of moving links.
    topology : sequence of (int, int)
        ``(proximal body, distal body)`` of each spring.

    Returns
    -------
    dict
        ``{(1, col): sympy.Eq}``, a subset of :func:`constraint_equations`.

    Examples
    --------
    >>> sorted(gravity_conditions(2, ((0, 2), (1, 2))))
    [(1, 3), (1, 4), (1, 5), (1, 6)]
    """
    return {rc: eq for rc, eq in constraint_equations(n, topology).items() if rc[0] == 1}
