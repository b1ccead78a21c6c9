"""Stiffness-matrix method for planar serial chains balanced by ZFL springs.

Source: M. P. Lustig, A. G. Dunning, J. L. Herder, *Parameter analysis for the design of
statically balanced serial linkages using a stiffness matrix approach with Cartesian
coordinates*, 14th IFToMM World Congress (2015), eqs 1-20 and Table 3e; it recasts the
stiffness-matrix approach of Lin, Shieh & Chen (Mechanism and Machine Theory 45, 2010)
in Cartesian coordinates.

The idea
--------
Describe the state of every link by the unit vector ``q_u = (cos theta_u, sin theta_u)``
along its x-axis and stack them, ground first, into ``Q = (q_1, ..., q_N)`` with the
constant ``q_1 = (1, 0)``. Every point of the chain is then *linear* in ``Q``, so the
energy of ZFL springs (quadratic in the spring vector) and of gravity (linear in a
height, written ``(R q_1)^T S``) is one quadratic form ``U = 1/2 Q^T K_t Q`` (eqs 5-13).
The diagonal 2x2 blocks of ``K_t`` are multiples of the identity and contribute
constants (``q_u^T q_u = 1``); every off-diagonal block is a rotation-scale matrix
``[[p, -s], [s, p]]`` that multiplies ``cos(theta_v - theta_u)`` and
``sin(theta_v - theta_u)``. The chain is balanced, for every pose, exactly when all
off-diagonal entries vanish: ``N (N - 1)`` scalar equations for ``N`` links (the ground
counted), read off the odd rows of ``K_t`` (Sec. II.B.4). The equations in the ground
row hold the gravity terms; the others couple two moving links.

Notation and how it maps to balancelab
--------------------------------------
==========================  ==============================================
paper                       balancelab
==========================  ==============================================
link 1 (fixed world)        body 0 (ground); its frame is the global frame
link ``u`` (u = 2..N)       body ``u - 1``; ``n = N - 1`` moving links
joint ``J_1`` (origin)      ground point ``(0, 0)`` = body 1's origin
joint ``J_u`` (u >= 2)      body ``u - 1`` point ``(L_u, 0)`` = body ``u``'s origin
``L_u``                     ``lengths[u - 2]``
``(a_xj, a_yj)`` on link u  local point of spring ``j`` on body ``u - 1``
``(b_xj, b_yj)`` on link v  local point of spring ``j`` on body ``v - 1``
``(s_xu, s_yu)``, ``m_u``   ``coms[u - 2]``, ``masses[u - 2]``
state ``q_u``               ``(cos q[u - 2], sin q[u - 2])``
==========================  ==============================================

The paper's local coordinates are exactly balancelab's body-local coordinates (origin at
the proximal joint, x along the link), so no conversion is needed; on the ground they
are global coordinates. Configuration coordinates ``q`` are **absolute** link angles
(rad, from the global x-axis), one per moving link: ``TreeKinematics`` with identity
rows in its ``angle_matrix``. Spring ``j`` goes from its proximal body (``A_j``) to its
distal body (``B_j``); a spring given the other way round is turned around.

Parameter names follow the paper with the subscripts written flat: ``L2, m2, sx2, sy2``
for link 2 (body 1), ``k1, ax1, ay1, bx1, by1`` for spring 1, ``g`` for gravity.

Typo in the paper: eq. 16a carries a factor ``1/2`` in front of ``K_si``; with it, eq. 17
would read ``k_1/2``. Eq. 8e (no factor) is the consistent definition and is the one
used here; eq. 17 and Table 3e agree with it.
"""
from __future__ import annotations

import functools
import math
from dataclasses import dataclass
from typing import Mapping, Sequence

import numpy as np

from ...core.design import Design
from ...core.elements import G, Joint, Spring, SymbolicParts, gravity_load
from ...core.validation import finite_real, planar_point
from ...core.kinematics import Kinematics
from ...mechanisms.base import TreeKinematics
from ...mechanisms.geometry import rotate
from ..registry import example

__all__ = [
    "SerialChain",
    "InfeasibleDesign",
    "chain_kinematics",
    "chain_parameter_names",
    "stiffness_matrix",
    "stiffness_matrix_symbolic",
    "constraint_equations",
    "constraint_residuals",
    "gravity_conditions",
    "diagonal_residual",
    "quadratic_energy",
    "solve",
    "solve_symbolic",
    "synthesize",
    "balance_all_pairs",
    "LUSTIG_TOPOLOGY",
    "LUSTIG_UNKNOWNS",
    "lustig_values",
    "lustig_table3e_case",
    "lustig_case1",
    "lustig_case2",
    "lustig_case3",
    "lustig_case4",
    "lustig_alpha",
    "lustig_b1",
    "lustig_a1",
    "lustig_min_energy_pose",
    "spring2_invariant",
]

REFERENCE = ("Lustig, Dunning & Herder, IFToMM World Congress 2015, stiffness-matrix approach "
             "in Cartesian coordinates, eqs 1-20, Table 3e")


class InfeasibleDesign(ValueError):
    """Raised when the balance equations only have physically impossible solutions.

    For instance a negative spring stiffness, or a non-positive mass or length.
    """


# --------------------------------------------------------------------------- the chain
def _positive_tuple(name: str, values, n: int | None = None) -> tuple[float, ...]:
    if isinstance(values, (str, bytes)):
        raise TypeError(f"{name} must be a sequence of numbers, got a string")
    try:
        items = list(values)
    except TypeError:
        raise TypeError(f"{name} must be a sequence of numbers, got {values!r}") from None
    if n is not None and len(items) != n:
        raise ValueError(f"{name} must have {n} entries (one per moving link), got {len(items)}")
    return tuple(finite_real(f"{name}[{i}]", v, positive=True) for i, v in enumerate(items))


@dataclass(frozen=True)
class SerialChain:
    """A planar serial chain of ``n`` moving links with weights and ZFL springs.

    Body 0 is the ground; body ``i`` (``i = 1..n``) is pivoted at the distal joint of
    body ``i - 1`` (the ground joint is at the origin), its local frame has its origin
    at that joint and its x-axis through the next joint at ``(lengths[i-1], 0)``.

    Parameters
    ----------
    lengths : sequence of float
        Link lengths ``L`` (m), one per moving link, each > 0. The last one only places
        the tip (it does not enter the energy).
    masses : sequence of float
        Link masses (kg), each > 0.
    coms : sequence of (float, float)
        Centre of mass of each link in its local frame, ``(s_x, s_y)`` (m).
    springs : sequence of Spring
        ZFL springs (``free_length == 0``) between any two bodies, ground included.

    Examples
    --------
    >>> from balancelab import Spring
    >>> c = SerialChain((0.3, 0.3), (2.0, 2.0), ((0.1, 0.0), (0.15, 0.0)),
    ...                 (Spring(261.6, 0.0, (0, (0.0, 0.1)), (2, (0.1125, 0.0))),))
    >>> c.n, c.topology
    (2, ((0, 2),))
    """

    lengths: tuple
    masses: tuple
    coms: tuple
    springs: tuple = ()

    def __post_init__(self) -> None:
        lengths = _positive_tuple("lengths (m)", self.lengths)
        n = len(lengths)
        if not 1 <= n <= 8:
            raise ValueError(f"a serial chain needs 1 to 8 moving links, got {n}")
        masses = _positive_tuple("masses (kg)", self.masses, n)
        try:
            coms = list(self.coms)
        except TypeError:
            raise TypeError(f"coms must be a sequence of (s_x, s_y) points, got {self.coms!r}") from None
        if len(coms) != n:
            raise ValueError(f"coms must have {n} entries (one per moving link), got {len(coms)}")
        coms = tuple(planar_point(f"coms[{i}]", c) for i, c in enumerate(coms))
        springs = []
        for j, s in enumerate(self.springs):
            if not isinstance(s, Spring):
                raise TypeError(f"springs[{j}] must be a balancelab Spring, got {type(s).__name__}")
            if s.free_length != 0.0:
                raise ValueError(f"springs[{j}] has free length {s.free_length} m; the stiffness-matrix "
                                 "method needs zero-free-length springs")
            for at in (s.a, s.b):
                if at.body > n:
                    raise ValueError(f"springs[{j}] is attached to body {at.body}; the chain has bodies "
                                     f"0..{n}")
            if s.a.body > s.b.body:  # A on the proximal body, as in the paper
                s = Spring(s.k, 0.0, s.b, s.a, name=s.name, realization=s.realization)
            springs.append(s)
        object.__setattr__(self, "lengths", lengths)
        object.__setattr__(self, "masses", masses)
        object.__setattr__(self, "coms", coms)
        object.__setattr__(self, "springs", tuple(springs))

    @property
    def n(self) -> int:
        """Number of moving links."""
        return len(self.lengths)

    @property
    def topology(self) -> tuple:
        """``((proximal body, distal body), ...)`` of every spring, in order."""
        return tuple((s.a.body, s.b.body) for s in self.springs)

    def values(self, g: float = G) -> dict:
        """The chain's numbers under the paper's names (see :func:`chain_parameter_names`).

        Parameters
        ----------
        g : float
            Gravitational acceleration (m/s^2) stored under ``"g"``.

        Returns
        -------
        dict of str to float
            Lengths and attachment coordinates in m, masses in kg, stiffnesses in N/m.

        Examples
        --------
        >>> SerialChain((0.3,), (1.0,), ((0.1, 0.0),)).values()["L2"]
        0.3
        """
        out = {}
        for i in range(self.n):
            u = i + 2
            out[f"L{u}"] = self.lengths[i]
            out[f"m{u}"] = self.masses[i]
            out[f"sx{u}"], out[f"sy{u}"] = self.coms[i]
        for j, s in enumerate(self.springs, start=1):
            out[f"k{j}"] = s.k
            out[f"ax{j}"], out[f"ay{j}"] = s.a.point
            out[f"bx{j}"], out[f"by{j}"] = s.b.point
        out["g"] = float(g)
        return out

    @classmethod
    def from_values(cls, n: int, topology, values: Mapping[str, float]) -> "SerialChain":
        """Build a chain from the paper-named numbers of :meth:`values`.

        Parameters
        ----------
        n : int
            Number of moving links.
        topology : sequence of (int, int)
            ``(proximal body, distal body)`` of each spring.
        values : mapping of str to float
            Every name of :func:`chain_parameter_names` except ``g`` (ignored here).

        Returns
        -------
        SerialChain

        Examples
        --------
        >>> v = lustig_values(1)
        >>> SerialChain.from_values(2, ((0, 2), (1, 2)), v).springs[0].k
        261.6
        """
        n, topology = _check_topology(n, topology)
        missing = [k for k in chain_parameter_names(n, topology) if k != "g" and k not in values]
        if missing:
            raise ValueError(f"values is missing {missing}")
        lengths = [values[f"L{u}"] for u in range(2, n + 2)]
        masses = [values[f"m{u}"] for u in range(2, n + 2)]
        coms = [(values[f"sx{u}"], values[f"sy{u}"]) for u in range(2, n + 2)]
        springs = []
        for j, (ba, bb) in enumerate(topology, start=1):
            k = values[f"k{j}"]
            springs.append(Spring(k, 0.0, (ba, (values[f"ax{j}"], values[f"ay{j}"])),
                                  (bb, (values[f"bx{j}"], values[f"by{j}"])), name=f"k{j}"))
        return cls(tuple(lengths), tuple(masses), tuple(coms), tuple(springs))

    def stiffness_matrix(self, g: float = G) -> np.ndarray:
        """The paper's ``K_t`` (eq. 13b), shape ``(2N, 2N)``; see :func:`stiffness_matrix`.

        Examples
        --------
        >>> SerialChain((0.3,), (1.0,), ((0.1, 0.0),)).stiffness_matrix().shape
        (4, 4)
        """
        return stiffness_matrix(self, g)

    def design(self, name: str = "serial chain with ZFL springs", *, symbolic: bool = False,
               reference: str = REFERENCE) -> Design:
        """This chain as a :class:`balancelab.Design`.

        Parameters
        ----------
        name : str
            Title of the design.
        symbolic : bool
            Attach :class:`SymbolicParts` in the paper's symbols (imports sympy).
        reference : str
            Source text stored on the design.

        Returns
        -------
        Design
            Bodies ``ground, link 2, ..., link N`` (paper numbering); ``q`` are the
            absolute link angles ``theta_1..theta_n`` (rad); labels ``J1..``, ``A1..``,
            ``B1..``, ``S2..``; ``parameters`` holds :meth:`values`.

        Examples
        --------
        >>> lustig_case1().dof
        2
        """
        n = self.n
        bodies = ["ground"] + [f"link {u}" for u in range(2, n + 2)]
        joints = _chain_joints(self.lengths)
        loads = [gravity_load(i + 1, self.coms[i], self.masses[i], name=f"m{i + 2}") for i in range(n)]
        labels = {"J1": (0, (0.0, 0.0))}
        for i in range(n):
            labels[f"J{i + 2}"] = (i + 1, (self.lengths[i], 0.0))
            labels[f"S{i + 2}"] = (i + 1, self.coms[i])
        for j, s in enumerate(self.springs, start=1):
            labels[f"A{j}"] = tuple(s.a)
            labels[f"B{j}"] = tuple(s.b)
        springs = [s if s.name else Spring(s.k, 0.0, s.a, s.b, name=f"k{j}", realization=s.realization)
                   for j, s in enumerate(self.springs, start=1)]
        sym = _symbolic_parts(self) if symbolic else None
        return Design(name, bodies, joints, chain_kinematics(self.lengths), loads, springs,
                      symbolic=sym, labels=labels, parameters=self.values(), reference=reference)


def _chain_joints(lengths) -> list:
    joints = [Joint(0, (0.0, 0.0), 1, (0.0, 0.0))]
    for i, L in enumerate(lengths[:-1], start=1):
        joints.append(Joint(i, (float(L), 0.0), i + 1, (0.0, 0.0)))
    return joints


def chain_kinematics(lengths: Sequence[float]) -> TreeKinematics:
    """Kinematics of a serial chain with absolute link angles as coordinates.

    Parameters
    ----------
    lengths : sequence of float
        Link lengths (m), one per moving link, each > 0.

    Returns
    -------
    TreeKinematics
        Coordinates ``theta_1 .. theta_n``: the **absolute** angle (rad) of each moving
        link from the global x-axis, each in ``[-pi, pi]``; ``angle_matrix`` has
        identity rows.

    Examples
    --------
    >>> k = chain_kinematics((0.3, 0.2))
    >>> k.names
    ('theta_1', 'theta_2')
    >>> k.poses([0.0, 1.5707963267948966])[0][2].round(6).tolist()
    [0.3, 0.0, 1.570796]
    """
    lengths = _positive_tuple("lengths (m)", lengths)
    n = len(lengths)
    A = np.vstack([np.zeros((1, n)), np.eye(n)])
    names = tuple(f"theta_{i}" for i in range(1, n + 1))
    return TreeKinematics(n + 1, _chain_joints(lengths), A, names, [(-math.pi, math.pi)] * n)


def _check_topology(n, topology) -> tuple[int, tuple]:
    if isinstance(n, bool) or not isinstance(n, (int, np.integer)) or not 1 <= n <= 8:
        raise ValueError(f"n (number of moving links) must be an integer in 1..8, got {n!r}")
    try:
        pairs = [tuple(int(b) for b in p) for p in topology]
    except (TypeError, ValueError):
        raise TypeError(f"topology must be a sequence of (body, body) pairs, got {topology!r}") from None
    out = []
    for j, p in enumerate(pairs):
        if len(p) != 2:
            raise ValueError(f"topology[{j}] must be a pair of body indices, got {p}")
        a, b = sorted(p)
        if a == b:
            raise ValueError(f"topology[{j}] joins body {a} to itself")
        if a < 0 or b > n:
            raise ValueError(f"topology[{j}] = {p} names a body outside 0..{n}")
        out.append((a, b))
    return int(n), tuple(out)


def chain_parameter_names(n: int, topology) -> tuple[str, ...]:
    """Names of every parameter of a chain, in the paper's notation.

    Parameters
    ----------
    n : int
        Number of moving links (the paper's ``N - 1``).
    topology : sequence of (int, int)
        ``(proximal body, distal body)`` of each spring (balancelab body indices).

    Returns
    -------
    tuple of str
        ``L2, m2, sx2, sy2, ..., k1, ax1, ay1, bx1, by1, ..., g``.

    Examples
    --------
    >>> chain_parameter_names(1, [(0, 1)])
    ('L2', 'm2', 'sx2', 'sy2', 'k1', 'ax1', 'ay1', 'bx1', 'by1', 'g')
    """
    n, topology = _check_topology(n, topology)
    names = []
    for u in range(2, n + 2):
        names += [f"L{u}", f"m{u}", f"sx{u}", f"sy{u}"]
    for j in range(1, len(topology) + 1):
        names += [f"k{j}", f"ax{j}", f"ay{j}", f"bx{j}", f"by{j}"]
    return tuple(names) + ("g",)


# ------------------------------------------------------------------ stiffness matrices
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
    >>> c = SerialChain.from_values(2, LUSTIG_TOPOLOGY, lustig_values(1))
    >>> e = quadratic_energy(c, [[0.0, 0.0], [1.0, -2.0]])
    >>> bool(abs(e[0] - e[1]) < 1e-12)
    True
    """
    q = np.asarray(q, dtype=float)
    if q.ndim == 0 or q.shape[-1] != chain.n:
        raise ValueError(f"q must have shape (..., {chain.n}), got {q.shape}")
    if not np.all(np.isfinite(q)):
        raise ValueError("q (absolute link angles, rad) must be finite")
    K = stiffness_matrix(chain, g)
    Q = _state_vector(q)
    return 0.5 * np.einsum("...i,ij,...j->...", Q, K, Q)


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


# ------------------------------------------------------------------------- symbolic
@functools.lru_cache(maxsize=64)
def _symbolic_system(n: int, topology: tuple):
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
    K = K.applyfunc(sp.expand)
    eqs = {rc: sp.Eq(K[rc[0] - 1, rc[1] - 1], 0) for rc in _constraint_entries(N)}
    return K, syms, eqs


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
    >>> K, s = stiffness_matrix_symbolic(2, LUSTIG_TOPOLOGY)
    >>> K[0, 2]
    -L2*ax1*k1 + g*m2*sy2
    """
    n, topology = _check_topology(n, topology)
    K, syms, _ = _symbolic_system(n, topology)
    return K.copy(), dict(syms)


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
    >>> eqs = constraint_equations(2, LUSTIG_TOPOLOGY)
    >>> eqs[(1, 4)]
    Eq(-L2*ay1*k1 + L2*g*m3 + g*m2*sx2, 0)
    """
    n, topology = _check_topology(n, topology)
    return dict(_symbolic_system(n, topology)[2])


class _SymbolicChainKinematics(Kinematics):
    """The chain's kinematics with the link lengths as the paper's symbols ``L2, L3, ...``.

    Used only for the design's symbolic energy: body ``i``'s origin is
    ``J_i = sum_{u <= i} L_u q_u`` (eq. 2b) with absolute angles ``theta_1..theta_n``.
    """

    def __init__(self, numeric: TreeKinematics, lengths_sym):
        self.nbodies = numeric.nbodies
        self.names = numeric.names
        self.q_range = numeric.q_range
        self._numeric = numeric
        self._L = tuple(lengths_sym)

    def poses(self, q):
        return self._numeric.poses(q)

    def symbolic_point(self, body, point, syms):
        import sympy as sp

        x, y = sp.S.Zero, sp.S.Zero
        for i in range(1, body):
            x += self._L[i - 1] * sp.cos(syms[i - 1])
            y += self._L[i - 1] * sp.sin(syms[i - 1])
        if body == 0:
            return (x + point[0], y + point[1])
        px, py = rotate(sp, syms[body - 1], point)
        return (x + px, y + py)


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
    >>> sorted(gravity_conditions(2, LUSTIG_TOPOLOGY))
    [(1, 3), (1, 4), (1, 5), (1, 6)]
    """
    return {rc: eq for rc, eq in constraint_equations(n, topology).items() if rc[0] == 1}


def _symbolic_parts(chain: SerialChain) -> SymbolicParts:
    _, syms, _ = _symbolic_system(chain.n, chain.topology)
    g = syms["g"]
    loads = tuple((u - 1, (syms[f"sx{u}"], syms[f"sy{u}"]), (0, -syms[f"m{u}"] * g))
                  for u in range(2, chain.n + 2))
    springs = tuple((syms[f"k{j}"], 0, (ba, (syms[f"ax{j}"], syms[f"ay{j}"])),
                     (bb, (syms[f"bx{j}"], syms[f"by{j}"])))
                    for j, (ba, bb) in enumerate(chain.topology, start=1))
    values = {syms[k]: v for k, v in chain.values().items()}
    kin = _SymbolicChainKinematics(chain_kinematics(chain.lengths),
                                   [syms[f"L{u}"] for u in range(2, chain.n + 2)])
    return SymbolicParts(loads, springs, values, kinematics=kin)


# --------------------------------------------------------------------------- solving
_POSITIVE_PREFIX = ("k", "m", "L")


def _is_positive_name(name: str) -> bool:
    return name[0] in _POSITIVE_PREFIX and name[1:].isdigit()


class _Program:
    """One solution branch as a sequence of small assignments, evaluated in order.

    ``steps`` is a tuple of ``(targets, exprs, args, fn)``: the unknown names a block
    solves for, their sympy expressions in the known parameters *and the unknowns
    solved by earlier steps* (no substitution, so nothing swells), the names ``fn``
    takes and ``fn`` itself (lambdified with ``math``). ``free`` lists the unknowns no
    step determines.
    """

    def __init__(self, steps, free):
        self.steps = tuple(steps)
        self.free = tuple(free)

    def __call__(self, known: dict) -> dict:
        env = dict(known)
        pending = list(range(len(self.steps)))
        while pending:
            ready = [i for i in pending if all(a in env for a in self.steps[i][2])]
            if not ready:
                raise ValueError("singular choice of unknowns: the solution steps depend on each "
                                 "other in a cycle (some unknowns are not determined)")
            for i in ready:
                targets, _, args, fn = self.steps[i]
                env.update(zip(targets, fn(*[env[a] for a in args])))
            pending = [i for i in pending if i not in ready]
        return env

    def expressions(self) -> dict:
        """Closed-form expression of every solved unknown in the known parameters."""
        import sympy as sp

        sub: dict = {}
        for targets, exprs, _, _ in self.steps:
            for t, e in zip(targets, exprs):
                sub[sp.Symbol(t, real=True)] = e
        for _ in range(len(self.steps) + 1):
            new = {k: v.xreplace(sub) for k, v in sub.items()}
            if new == sub:
                break
            sub = new
        return {str(k): v for k, v in sub.items()}


@functools.lru_cache(maxsize=128)
def _symbolic_solution(n: int, topology: tuple, unknowns: tuple) -> tuple:
    """Generic symbolic solution branches of the constraints for ``unknowns`` (cached)."""
    _, syms, eqs = _symbolic_system(n, topology)
    exprs = [e.lhs for e in eqs.values()]
    unk = [syms[u] for u in unknowns]
    return tuple(_block_solve(exprs, unk))


def _block_solve(exprs, unk, steps=(), whole: bool = False) -> list:
    """Solve polynomial equations for ``unk`` block by block with sympy, every branch.

    The balance conditions are nearly triangular: an equation often contains a single
    unknown, or two equations (one rotation-scale block) share the same two. Solving
    such small blocks first, then treating their unknowns as known, is far faster than
    one ``sympy.solve`` on the whole system; whatever is left over is handed to
    ``sympy.solve`` in one piece. Equations the remaining unknowns do not enter only
    restrict the known values; the caller checks them with the numbers.

    Returns
    -------
    list of _Program
    """
    import sympy as sp

    unkset = set(unk)
    live = [e for e in exprs if e.free_symbols & unkset]
    if not unk or not live:
        return [_Program(steps, [str(u) for u in unk])]
    has = [e.free_symbols & unkset for e in live]
    block = list(range(len(live))) if whole else None
    for i, h in enumerate(has):
        if block is not None:
            break
        if len(h) == 1:
            block = [i]
            break
    if block is None:
        for i, h in enumerate(has):
            if len(h) == 2:
                js = [j for j, h2 in enumerate(has) if h2 <= h]
                if len(js) >= 2:
                    block = js
                    break
    if block is None:
        block = list(range(len(live)))
    bunk = sorted(set().union(*(has[i] for i in block)), key=str)
    sols = sp.solve([live[i] for i in block], bunk, dict=True, simplify=False, rational=False)
    rest = [live[i] for i in range(len(live)) if i not in block]
    out = []
    for sol in sols:
        solved = [u for u in bunk if u in sol and not (sol[u].free_symbols & set(bunk))]
        if not solved:
            if len(block) < len(live):  # a degenerate small block: solve everything at once
                return _block_solve(live, unk, steps, whole=True)
            # the conditions leave some unknowns free: infinitely many solutions
            out.append(_Program(steps, [str(u) for u in bunk if u not in sol] or
                                [str(u) for u in bunk]))
            continue
        targets = tuple(str(u) for u in solved)
        texprs = tuple(sol[u] for u in solved)
        args = tuple(sorted({str(a) for e in texprs for a in e.free_symbols}))
        fn = sp.lambdify([sp.Symbol(a, real=True) for a in args], list(texprs), modules="math")
        remaining = [u for u in unk if u not in solved]
        # the block's own equations may still tie unsolved block unknowns together
        again = [live[i] for i in block] if len(solved) < len(bunk) else []
        out += _block_solve(rest + again, remaining, steps + ((targets, texprs, args, fn),))
    return out


def solve_symbolic(n: int, topology, unknowns: Sequence[str], *, simplify: bool = True) -> list:
    """Closed-form solutions of the balance conditions for ``unknowns`` (sympy).

    The same generic solution that :func:`solve` evaluates (cached), written out in
    the remaining parameters. Equations the unknowns do not enter are not included;
    they are conditions on the other parameters.

    Parameters
    ----------
    n : int
        Number of moving links.
    topology : sequence of (int, int)
        ``(proximal body, distal body)`` of each spring.
    unknowns : sequence of str
        Parameters to solve for.
    simplify : bool
        Bring every expression to a factored rational form (``sympy.factor`` of
        ``sympy.cancel``); can be slow for long chains.

    Returns
    -------
    list of dict
        One dict per solution branch, ``{name: sympy expression}``.

    Examples
    --------
    >>> sol = solve_symbolic(2, LUSTIG_TOPOLOGY, ("ax1", "ay1"))[0]
    >>> sol["ax1"]
    g*m2*sy2/(L2*k1)
    """
    n, topology = _check_topology(n, topology)
    names = chain_parameter_names(n, topology)
    unknowns = tuple(unknowns)
    bad = [u for u in unknowns if u not in names]
    if bad:
        raise ValueError(f"unknowns {bad} are not parameters of this chain; valid names: {names}")
    out = [p.expressions() for p in _symbolic_solution(n, topology, unknowns)]
    if simplify:
        import sympy as sp

        out = [{k: sp.factor(sp.cancel(v)) for k, v in sol.items()} for sol in out]
    return out


def _solve_numeric_values(n, topology, known_values: dict, unknowns: tuple):
    """Fallback: solve with the known numbers substituted (floats)."""
    import sympy as sp

    K, syms, eqs = _symbolic_system(n, topology)
    subs = {syms[k]: sp.Float(v, 17) for k, v in known_values.items()}
    exprs = [sp.expand(e.lhs.xreplace(subs)) for e in eqs.values()]
    unk = [syms[u] for u in unknowns]
    return _block_solve(exprs, unk)


def solve(n: int, topology, values: Mapping[str, float], unknowns: Sequence[str], *,
          tol: float = 1e-9) -> dict:
    """Solve the balance conditions of a chain for a chosen set of unknown parameters.

    The ``N (N - 1)`` constraint equations (:func:`constraint_equations`) are solved
    with ``sympy.solve`` for ``unknowns``, symbolically in all the other parameters
    (cached per ``(n, topology, unknowns)``, so later calls only evaluate the cached
    solution), then the known ``values`` are substituted. When the generic solution
    does not apply to the given numbers (a vanishing denominator) the system is solved
    again with the numbers substituted.

    Parameters
    ----------
    n : int
        Number of moving links.
    topology : sequence of (int, int)
        ``(proximal body, distal body)`` of each spring (0 is the ground).
    values : mapping of str to float
        Numbers of every other parameter, by the names of
        :func:`chain_parameter_names` (m, kg, N/m); ``g`` defaults to 9.81 m/s^2.
        Entries for the unknowns themselves are ignored.
    unknowns : sequence of str
        Parameters to solve for.
    tol : float
        Relative tolerance on the constraint residuals of the solution.

    Returns
    -------
    dict of str to float
        The value of every unknown.

    Raises
    ------
    ValueError
        Unknown names, missing values, an unknown that does not enter any condition,
        more unknowns than conditions, a singular choice (some unknowns left free) or
        no solution / several admissible solutions.
    InfeasibleDesign
        If every real solution needs a negative stiffness (or a non-positive mass or
        length).

    Examples
    --------
    >>> v = {k: x for k, x in lustig_values(1).items() if k not in LUSTIG_UNKNOWNS}
    >>> sol = solve(2, LUSTIG_TOPOLOGY, v, LUSTIG_UNKNOWNS)
    >>> round(sol["k1"], 1), round(sol["bx1"], 4), round(sol["bx2"], 4)
    (261.6, 0.1125, -0.0981)
    """
    n, topology = _check_topology(n, topology)
    names = chain_parameter_names(n, topology)
    if isinstance(unknowns, str):
        unknowns = (unknowns,)
    unknowns = tuple(unknowns)
    if not unknowns:
        raise ValueError("unknowns is empty: name the parameters to solve for")
    bad = [u for u in unknowns if u not in names]
    if bad:
        raise ValueError(f"unknowns {bad} are not parameters of this chain; valid names: {names}")
    if len(set(unknowns)) != len(unknowns):
        raise ValueError(f"unknowns has repeated names: {unknowns}")
    extra = [k for k in values if k not in names]
    if extra:
        raise ValueError(f"values has entries {extra} that are not parameters of this chain; "
                         f"valid names: {names}")
    known = {}
    for k in names:
        if k in unknowns:
            continue
        if k == "g" and k not in values:
            known[k] = G
            continue
        if k not in values:
            missing = [m for m in names if m not in unknowns and m not in values and m != "g"]
            raise ValueError(f"values is missing {missing} (every parameter that is not an unknown "
                             "needs a number)")
        known[k] = finite_real(f"values[{k!r}]", values[k], positive=_is_positive_name(k) or k == "g")
    _, syms, eqs = _symbolic_system(n, topology)
    used = set().union(*(e.lhs.free_symbols for e in eqs.values()))
    absent = [u for u in unknowns if syms[u] not in used]
    if absent:
        raise ValueError(f"unknowns {absent} do not enter any balance condition of this chain, so "
                         "the conditions cannot determine them")
    if len(unknowns) > len(eqs):
        raise ValueError(f"{len(unknowns)} unknowns but only {len(eqs)} balance conditions: the "
                         "choice is singular (underdetermined); fix some of them")

    candidates = []
    singular = None
    for attempt in ("generic", "numbers"):
        programs = (_symbolic_solution(n, topology, unknowns) if attempt == "generic"
                    else _solve_numeric_values(n, topology, known, unknowns))
        failed = False
        for prog in programs:
            if prog.free:
                singular = prog.free
                continue
            try:
                env = prog(known)
            except (ZeroDivisionError, OverflowError, TypeError):
                failed = True  # the generic solution divides by zero for these numbers
                continue
            except ValueError as err:
                if "singular" in str(err):
                    singular = unknowns
                    continue
                failed = True
                continue
            candidates.append({u: complex(env[u]) for u in unknowns})
        if candidates or not failed:
            break
    if not candidates and singular:
        raise ValueError(f"singular choice of unknowns: the balance conditions leave {list(singular)} "
                         "free (infinitely many solutions); choose fewer or other unknowns")
    if not candidates:
        raise ValueError(f"the balance conditions have no solution for the unknowns {list(unknowns)} "
                         "with these values (the system is overdetermined or inconsistent)")
    real = []
    for c in candidates:
        scale = max(1.0, *(abs(v) for v in c.values()))
        if all(abs(v.imag) <= 1e-9 * scale for v in c.values()):
            real.append({k: v.real for k, v in c.items()})
    if not real:
        raise ValueError(f"the balance conditions have only complex solutions for {list(unknowns)}")
    # check residuals with the numbers (guards against spurious generic solutions)
    checked = []
    for r in real:
        allv = dict(known, **r)
        res = _numeric_residual(n, topology, allv)
        if res <= tol:
            checked.append(r)
    if not checked:
        raise ValueError(f"the balance conditions have no solution for the unknowns {list(unknowns)} "
                         "with these values: the conditions the unknowns do not enter are violated "
                         "(overdetermined or inconsistent choice)")
    feasible = [r for r in checked if all(r[k] > 0 for k in r if _is_positive_name(k))]
    if not feasible:
        bad = {k: v for k, v in checked[0].items() if _is_positive_name(k) and v <= 0}
        raise InfeasibleDesign(f"the only solutions need non-positive {bad}: a negative stiffness, "
                               "mass or length cannot be built")
    unique = []
    for r in feasible:
        if not any(all(math.isclose(r[k], u[k], rel_tol=1e-9, abs_tol=1e-12) for k in r) for u in unique):
            unique.append(r)
    if len(unique) > 1:
        raise ValueError(f"the balance conditions have {len(unique)} admissible solutions for "
                         f"{list(unknowns)}: {unique}; fix more parameters to pick one")
    return unique[0]


@functools.lru_cache(maxsize=64)
def _constraint_function(n: int, topology: tuple):
    """Lambdified constraint entries: f(*values in chain_parameter_names order) -> list."""
    import sympy as sp

    _, syms, eqs = _symbolic_system(n, topology)
    names = chain_parameter_names(n, topology)
    return sp.lambdify([syms[k] for k in names], [e.lhs for e in eqs.values()], modules="math")


def _numeric_residual(n, topology, allv) -> float:
    """Largest constraint entry divided by a gravity moment scale (dimensionless)."""
    names = chain_parameter_names(n, topology)
    vals = _constraint_function(n, topology)(*[allv[k] for k in names])
    g = allv["g"]
    scale = g * sum(allv[f"m{u}"] * (math.hypot(allv[f"sx{u}"], allv[f"sy{u}"]) + allv[f"L{u}"])
                    for u in range(2, n + 2))
    return max(abs(v) for v in vals) / scale


def synthesize(n: int, topology, values: Mapping[str, float], unknowns: Sequence[str], *,
               name: str = "serial chain balanced by the stiffness-matrix method",
               symbolic: bool = True) -> Design:
    """Solve the balance conditions (:func:`solve`) and return the balanced design.

    Parameters
    ----------
    n, topology, values, unknowns
        As in :func:`solve`.
    name : str
        Title of the design.
    symbolic : bool
        Attach the symbolic parts in the paper's symbols.

    Returns
    -------
    Design
        Configuration ``q`` = absolute link angles (rad); ``parameters`` holds every
        parameter by its paper name.

    Examples
    --------
    >>> v = {k: x for k, x in lustig_values(3).items() if k not in LUSTIG_UNKNOWNS}
    >>> d = synthesize(2, LUSTIG_TOPOLOGY, v, LUSTIG_UNKNOWNS)
    >>> d.balance_report().balanced
    True
    """
    n, topology = _check_topology(n, topology)
    if values.get("g", G) != G:
        raise ValueError("a Design uses g = 9.81 m/s^2; leave g out of values (or set it to 9.81)")
    sol = solve(n, topology, values, unknowns)
    allv = {k: v for k, v in values.items() if k not in sol}
    allv.update(sol)
    chain = SerialChain.from_values(n, topology, allv)
    return chain.design(name, symbolic=symbolic)


def balance_all_pairs(lengths: Sequence[float], masses: Sequence[float], coms, stiffness=None,
                      anchors=None, *, name: str = "serial chain, one ZFL spring per pair of links"
                      ) -> Design:
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
    stiffness : mapping of (int, int) to float, or float, optional
        Stiffness (N/m, > 0) of the spring between bodies ``(i, j)``, ``i < j``; one
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
    lengths = _positive_tuple("lengths (m)", lengths)
    n = len(lengths)
    chain0 = SerialChain(lengths, masses, coms)  # validates masses and coms
    masses, coms = chain0.masses, chain0.coms
    pairs = [(i, j) for j in range(1, n + 1) for i in range(j)]
    if stiffness is None:
        stiffness = 1000.0
    if isinstance(stiffness, Mapping):
        ks = {p: finite_real(f"stiffness[{p}] (N/m)", stiffness[p], positive=True) if p in stiffness
              else 1000.0 for p in pairs}
    else:
        k = finite_real("stiffness (N/m)", stiffness, positive=True)
        ks = {p: k for p in pairs}
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
    # complex blocks: z_IK = sum_j k conj(c_I) c_K (+ gravity on row 1)
    mu = []
    for u in range(1, n + 1):  # body u = paper link u+1
        below = sum(masses[u:])
        mu.append(masses[u - 1] * complex(*coms[u - 1]) + below * Ls[u])
    b = {}
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
                        own = ks[(i, j)] * cI.conjugate()
                        continue
                    cK = complex(*b[(i, j)])
                else:
                    cK = complex(Ls[K_])
                total += ks[(i, j)] * cI.conjugate() * cK
            z = -total / own
            b[(I, K_)] = (z.real, z.imag)
    springs = [Spring(ks[p], 0.0, (p[0], a[p]), (p[1], b[p]), name=f"k{idx}")
               for idx, p in enumerate(pairs, start=1)]
    chain = SerialChain(lengths, masses, coms, tuple(springs))
    return chain.design(name, reference=REFERENCE + "; triangular solution of the block conditions")


# ----------------------------------------------------------------- the paper's example
#: Spring topology of the paper's example 2 (Fig. 2c): spring 1 from the ground to link 3
#: (body 2, bi-articular), spring 2 from link 2 to link 3 (bodies 1 and 2, mono-articular).
LUSTIG_TOPOLOGY: tuple = ((0, 2), (1, 2))

#: The parameters the paper solves for in every case of Table 3e.
LUSTIG_UNKNOWNS: tuple = ("ax1", "bx1", "by1", "bx2", "by2", "k1")

#: Length of link 3 (m). It does not enter any condition and is not printed (Fig. 3 is
#: missing from the text); 0.3 m is assumed, so that s_x3 = 0.15 m is mid-link.
LUSTIG_L3: float = 0.3

_TABLE3E_INPUTS = {
    # case: (ax2, ay2, sy2)
    1: (0.15, 0.0, 0.0),
    2: (0.18, -0.09, 0.0),
    3: (0.15, 0.0, -0.1),
    4: (0.18, -0.09, -0.1),
}


def _case(case) -> int:
    if isinstance(case, bool) or case not in _TABLE3E_INPUTS:
        raise ValueError(f"case must be 1, 2, 3 or 4 (Table 3e), got {case!r}")
    return int(case)


def lustig_values(case: int, *, solved: bool = True) -> dict:
    """Every parameter of a case of the paper's Table 3e, by name.

    Parameters
    ----------
    case : {1, 2, 3, 4}
        Column of Table 3e.
    solved : bool
        Include the six solved parameters (:data:`LUSTIG_UNKNOWNS`), computed from the
        chosen inputs with :func:`solve`; ``False`` gives only the inputs below the
        table's line (plus the assumed ``L3``).

    Returns
    -------
    dict of str to float
        Inputs: ``k2 = 600`` N/m, ``ay1 = 0.1`` m, ``ax2, ay2`` (m), ``m2 = m3 = 2`` kg,
        ``L2 = 0.3`` m, ``sx2 = 0.1``, ``sy2``, ``sx3 = 0.15``, ``sy3 = 0`` (m),
        ``L3 = 0.3`` m (assumed), ``g = 9.81``.

    Examples
    --------
    >>> round(lustig_values(4)["by2"], 4)
    -0.0739
    """
    case = _case(case)
    ax2, ay2, sy2 = _TABLE3E_INPUTS[case]
    v = dict(L2=0.3, m2=2.0, sx2=0.1, sy2=sy2, L3=LUSTIG_L3, m3=2.0, sx3=0.15, sy3=0.0,
             k2=600.0, ax2=ax2, ay2=ay2, ay1=0.1, g=G)
    if solved:
        v.update(solve(2, LUSTIG_TOPOLOGY, v, LUSTIG_UNKNOWNS))
    return v


def lustig_table3e_case(case: int) -> Design:
    """The balanced three-link chain (two moving links) of a case of Table 3e.

    Two ZFL springs: spring 1 from the ground point ``A1 = (ax1, ay1)`` to ``B1`` on link
    3, spring 2 from ``A2`` on link 2 to ``B2`` on link 3 (Fig. 2c). The six parameters
    ``ax1, bx1, by1, bx2, by2, k1`` are solved from eq. 17; the rest are the table's
    inputs. ``L3`` (not printed) is taken as 0.3 m; it does not affect the balance.

    Parameters
    ----------
    case : {1, 2, 3, 4}
        1: springs along the links; 2: ``A2`` turned about ``J2``; 3: centre of mass of
        link 2 moved off its axis (``sy2 = -0.1`` m); 4: both.

    Returns
    -------
    Design
        ``q`` = absolute angles (rad) of links 2 and 3 (bodies 1 and 2).

    Examples
    --------
    >>> d = lustig_table3e_case(2)
    >>> round(d.parameters["bx2"], 4), d.balance_report().balanced
    (-0.0785, True)
    """
    case = _case(case)
    v = lustig_values(case)
    chain = SerialChain.from_values(2, LUSTIG_TOPOLOGY, v)
    return chain.design(f"Lustig et al. Table 3e, case {case}", symbolic=True,
                        reference=REFERENCE + f" (case {case})")


@example("lustig_case1", "Stiffness-matrix 2R, Table 3e case 1: springs along the links (Lustig et al.)", chapter=4)
def lustig_case1() -> Design:
    """Table 3e case 1: both springs along the links. See :func:`lustig_table3e_case`.

    Examples
    --------
    >>> round(lustig_case1().parameters["k1"], 1)
    261.6
    """
    return lustig_table3e_case(1)


@example("lustig_case2", "Stiffness-matrix 2R, Table 3e case 2: A2 turned about J2 (Lustig et al.)", chapter=4)
def lustig_case2() -> Design:
    """Table 3e case 2: ``A2`` turned about ``J2``. See :func:`lustig_table3e_case`.

    Examples
    --------
    >>> round(lustig_case2().parameters["by2"], 4)
    -0.0589
    """
    return lustig_table3e_case(2)


@example("lustig_case3", "Stiffness-matrix 2R, Table 3e case 3: centre of mass of link 2 off its axis (Lustig et al.)", chapter=4)
def lustig_case3() -> Design:
    """Table 3e case 3: centre of mass of link 2 off its axis. See :func:`lustig_table3e_case`.

    Examples
    --------
    >>> round(lustig_case3().parameters["ax1"], 3)
    -0.025
    """
    return lustig_table3e_case(3)


@example("lustig_case4", "Stiffness-matrix 2R, Table 3e case 4: cases 2 and 3 combined (Lustig et al.)", chapter=4)
def lustig_case4() -> Design:
    """Table 3e case 4: cases 2 and 3 combined. See :func:`lustig_table3e_case`.

    Examples
    --------
    >>> round(lustig_case4().parameters["bx2"], 2)
    -0.06
    """
    return lustig_table3e_case(4)


_POSITIVE_NAMES = ("m2", "m3", "L2", "k1", "k2", "g")


def _vals(values, needs: tuple = ()) -> dict:
    """The parameters as a dict; each name in ``needs`` must be there and finite
    (masses, ``L2``, spring rates and ``g`` > 0)."""
    if isinstance(values, Design):
        v = dict(values.parameters)
    elif isinstance(values, Mapping):
        v = dict(values)
    else:
        raise TypeError(f"values must be a mapping of parameter names or a Design, got {type(values).__name__}")
    missing = [name for name in needs if name not in v]
    if missing:
        raise ValueError(f"values lacks {', '.join(missing)} (needed: {', '.join(needs)})")
    for name in needs:
        unit = {"m": "kg", "k": "N/m", "g": "m/s^2"}.get(name[0], "m")
        v[name] = finite_real(f"values[{name!r}] ({unit})", v[name], positive=name in _POSITIVE_NAMES)
    return v


def lustig_alpha(values) -> float:
    """Angle ``alpha`` (rad) of link 2 from the downward vertical at minimum gravity energy (eq. 18d).

    ``alpha = atan(m2 sy2 / (m2 sx2 + m3 L2))``: in the pose of least gravity energy of
    the unbalanced chain, link 2's x-axis points at ``-pi/2 - alpha`` from the global
    x-axis (so that its first moment ``(m2 sx2 + m3 L2, m2 sy2)`` hangs straight down).

    Parameters
    ----------
    values : mapping or Design
        Needs ``m2, m3, L2, sx2, sy2``.

    Returns
    -------
    float

    Examples
    --------
    >>> round(lustig_alpha(lustig_values(3, solved=False)), 6)
    -0.244979
    """
    v = _vals(values, ("m2", "m3", "L2", "sx2", "sy2"))
    return math.atan2(v["m2"] * v["sy2"], v["m2"] * v["sx2"] + v["m3"] * v["L2"])


def lustig_b1(values) -> tuple[float, float]:
    """Attachment ``B1 = (bx1, by1)`` on link 3 from the linkage alone (eq. 19), in m.

    Parameters
    ----------
    values : mapping or Design
        Needs ``L2, m2, m3, sx2, sy2, sx3, sy3``.

    Returns
    -------
    (float, float)

    Examples
    --------
    >>> [round(x, 4) for x in lustig_b1(lustig_values(3, solved=False))]
    [0.1059, 0.0265]
    """
    v = _vals(values, ("L2", "m2", "m3", "sx2", "sy2", "sx3", "sy3"))
    L, m2, m3 = v["L2"], v["m2"], v["m3"]
    den = (L * m3 + m2 * v["sx2"]) ** 2 + m2 ** 2 * v["sy2"] ** 2
    bx = (L ** 2 * m3 ** 2 * v["sx3"] + L * m2 * m3 * (v["sx2"] * v["sx3"] + v["sy2"] * v["sy3"])) / den
    by = (L ** 2 * m3 ** 2 * v["sy3"] + L * m2 * m3 * (v["sx2"] * v["sy3"] - v["sx3"] * v["sy2"])) / den
    return bx, by


def lustig_a1(values) -> tuple[float, float]:
    """Ground attachment ``A1 = (ax1, ay1)`` for a stiffness ``k1`` (eqs 20a, 20b), in m.

    ``|A1|`` is inversely proportional to ``k1`` and ``ax1 / ay1 = tan(alpha)`` (eq. 20c).

    Parameters
    ----------
    values : mapping or Design
        Needs ``k1, L2, m2, m3, sx2, sy2`` (and ``g``, default 9.81).

    Returns
    -------
    (float, float)

    Examples
    --------
    >>> [round(x, 4) for x in lustig_a1(dict(lustig_values(3, solved=False), k1=261.6))]
    [-0.025, 0.1]
    """
    v = _vals(dict({"g": G}, **_vals(values)), ("k1", "L2", "m2", "m3", "sx2", "sy2", "g"))
    g, k1 = v["g"], v["k1"]
    return (v["m2"] * g * v["sy2"] / (v["L2"] * k1),
            (v["m2"] * g * v["sx2"] + v["m3"] * g * v["L2"]) / (v["L2"] * k1))


def lustig_min_energy_pose(values) -> np.ndarray:
    """Absolute link angles (rad) of the unbalanced chain's least gravity energy (Fig. 4a).

    Link 2 at ``-pi/2 - alpha`` (eq. 18) and link 3 with its centre of mass straight
    below ``J2``. In this pose ``A1, J1, J2, B1`` lie on one line, and so do
    ``A2, J2, B2`` (Fig. 4c).

    Parameters
    ----------
    values : mapping or Design

    Returns
    -------
    numpy.ndarray, shape (2,)

    Examples
    --------
    >>> lustig_min_energy_pose(lustig_values(1, solved=False)).round(4).tolist()
    [-1.5708, -1.5708]
    """
    v = _vals(values, ("m2", "m3", "L2", "sx2", "sy2", "sx3", "sy3"))
    return np.array([-math.pi / 2 - lustig_alpha(v), -math.pi / 2 - math.atan2(v["sy3"], v["sx3"])])


def spring2_invariant(values) -> float:
    """``k2 |A2 - J2| |B2 - J2|`` (N m) of the paper's example: constant over the family.

    With spring 1 fixed, spring 2 may be moved and re-sized freely as long as this
    product stays the same (Sec. III.B); it equals ``k1 L2 |B1|``.

    Parameters
    ----------
    values : mapping or Design
        Needs ``k2, L2, ax2, ay2, bx2, by2``.

    Returns
    -------
    float

    Examples
    --------
    >>> round(spring2_invariant(lustig_values(1)), 3)
    8.829
    """
    v = _vals(values, ("k2", "L2", "ax2", "ay2", "bx2", "by2"))
    return v["k2"] * math.hypot(v["ax2"] - v["L2"], v["ay2"]) * math.hypot(v["bx2"], v["by2"])
