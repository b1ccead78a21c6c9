"""The serial chain of the stiffness-matrix method and its :class:`balancelab.Design`.

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

The chain's kinematics is :mod:`balancelab.mechanisms.chain`'s serial chain
(:func:`chain_kinematics` is :func:`balancelab.mechanisms.serial_chain_kinematics` under the
name this family has always used); this module adds the paper's notation and its design.

Parameter names follow the paper with the subscripts written flat: ``L2, m2, sx2, sy2``
for link 2 (body 1), ``k1, ax1, ay1, bx1, by1`` for spring 1, ``g`` for gravity.
"""
from __future__ import annotations

from dataclasses import dataclass
from typing import TYPE_CHECKING, Mapping, Sequence


from ...core.design import Design
from ...core.elements import G, Spring, SymbolicParts, gravity_load
from ...core.validation import body_index, finite_reals, planar_points, positive_int
from ...mechanisms.chain import SymbolicChainKinematics, serial_chain_joints
from ...mechanisms.chain import serial_chain_kinematics as chain_kinematics

__all__ = ["REFERENCE", "SerialChain", "chain_kinematics", "chain_parameter_names", "check_topology"]

#: Source text stored on the designs of this family.
REFERENCE = ("Lustig, Dunning & Herder, IFToMM World Congress 2015, stiffness-matrix approach "
             "in Cartesian coordinates, eqs 1-20, Table 3e")


def _checked_springs(springs, n: int) -> tuple:
    """ZFL springs on bodies 0..n, each turned so that ``a`` is on the proximal body."""
    if isinstance(springs, (str, bytes, Spring)) or not hasattr(springs, "__iter__"):
        raise TypeError(f"springs must be a sequence of Springs, got {springs!r}")
    out = []
    for j, s in enumerate(springs):
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
        out.append(s)
    return tuple(out)


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
    ...                 (Spring(250.0, 0.0, (0, (0.0, 0.1)), (2, (0.1125, 0.0))),))
    >>> c.n, c.topology
    (2, ((0, 2),))
    """

    lengths: tuple[float, ...]
    masses: tuple[float, ...]
    coms: tuple[tuple[float, float], ...]
    springs: tuple[Spring, ...] = ()

    if TYPE_CHECKING:  # the generated __init__ takes any sequences and stores tuples
        def __init__(self, lengths: Sequence[float], masses: Sequence[float],
                     coms: Sequence[Sequence[float]], springs: Sequence[Spring] = ()) -> None: ...

    def __post_init__(self) -> None:
        lengths = finite_reals("lengths (m)", self.lengths, None, positive=True)
        n = len(lengths)
        if not 1 <= n <= 8:
            raise ValueError(f"a serial chain needs 1 to 8 moving links, got {n}")
        masses = finite_reals("masses (kg)", self.masses, n, positive=True)
        coms = planar_points("coms (m)", self.coms, n)
        springs = _checked_springs(self.springs, n)
        object.__setattr__(self, "lengths", lengths)
        object.__setattr__(self, "masses", masses)
        object.__setattr__(self, "coms", coms)
        object.__setattr__(self, "springs", springs)

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
    def from_values(cls, n: int, topology, values: Mapping[str, float]) -> SerialChain:
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
        >>> from balancelab.methods.lustig import lustig_values
        >>> v = lustig_values(1)
        >>> [s.free_length for s in SerialChain.from_values(2, ((0, 2), (1, 2)), v).springs]
        [0.0, 0.0]
        """
        n, topology = check_topology(n, topology)
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
        >>> from balancelab.methods.lustig import lustig_case1
        >>> lustig_case1().dof
        2
        """
        n = self.n
        bodies = ["ground"] + [f"link {u}" for u in range(2, n + 2)]
        loads = [gravity_load(i + 1, self.coms[i], self.masses[i], name=f"m{i + 2}") for i in range(n)]
        springs = [s if s.name else Spring(s.k, 0.0, s.a, s.b, name=f"k{j}", realization=s.realization)
                   for j, s in enumerate(self.springs, start=1)]
        sym = _symbolic_parts(self) if symbolic else None
        return Design(name, bodies, serial_chain_joints(self.lengths), chain_kinematics(self.lengths), loads,
                      springs, symbolic=sym, labels=self._labels(), parameters=self.values(),
                      reference=reference)

    def _labels(self) -> dict:
        """Joints ``J1..``, centres of mass ``S2..`` and spring ends ``A1.., B1..``."""
        labels: dict[str, tuple[int, tuple[float, float]]] = {"J1": (0, (0.0, 0.0))}
        for i in range(self.n):
            labels[f"J{i + 2}"] = (i + 1, (self.lengths[i], 0.0))
            labels[f"S{i + 2}"] = (i + 1, self.coms[i])
        for j, s in enumerate(self.springs, start=1):
            labels[f"A{j}"] = (s.a.body, s.a.point)
            labels[f"B{j}"] = (s.b.body, s.b.point)
        return labels


def check_topology(n: int, topology) -> tuple[int, tuple]:
    """Check a chain's size and spring topology; every spring pair sorted proximal first.

    Parameters
    ----------
    n : int
        Number of moving links, 1..8.
    topology : sequence of (int, int)
        The two bodies of each spring (0 is the ground), in either order.

    Returns
    -------
    n : int
    topology : tuple of (int, int)
        ``(proximal body, distal body)`` of each spring.

    Raises
    ------
    ValueError
        ``n`` outside 1..8, a spring joining a body to itself or naming a body outside
        ``0..n``.
    TypeError
        ``topology`` is not a sequence of pairs of integers.

    Examples
    --------
    >>> check_topology(2, [(2, 0), [1, 2]])
    (2, ((0, 2), (1, 2)))
    """
    n = positive_int("n (number of moving links)", n, 1, 8)
    if isinstance(topology, (str, bytes, dict)) or topology is None:
        raise TypeError(f"topology must be a sequence of (body, body) pairs, got {topology!r}")
    try:
        pairs = [tuple(body_index(f"topology[{j}]", b) for b in p) for j, p in enumerate(topology)]
    except TypeError as err:
        raise TypeError(f"topology must be a sequence of (body, body) pairs of ints: {err}") from None
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
    n, topology = check_topology(n, topology)
    names = []
    for u in range(2, n + 2):
        names += [f"L{u}", f"m{u}", f"sx{u}", f"sy{u}"]
    for j in range(1, len(topology) + 1):
        names += [f"k{j}", f"ax{j}", f"ay{j}", f"bx{j}", f"by{j}"]
    return tuple(names) + ("g",)


# ------------------------------------------------------------ the symbolic design parts
def _symbolic_parts(chain: SerialChain) -> SymbolicParts:
    """The chain's loads and springs in the paper's symbols (real sympy symbols by name)."""
    import sympy as sp

    syms = {name: sp.Symbol(name, real=True) for name in chain_parameter_names(chain.n, chain.topology)}
    g = syms["g"]
    loads = tuple((u - 1, (syms[f"sx{u}"], syms[f"sy{u}"]), (0, -syms[f"m{u}"] * g))
                  for u in range(2, chain.n + 2))
    springs = tuple((syms[f"k{j}"], 0, (ba, (syms[f"ax{j}"], syms[f"ay{j}"])),
                     (bb, (syms[f"bx{j}"], syms[f"by{j}"])))
                    for j, (ba, bb) in enumerate(chain.topology, start=1))
    values = {syms[k]: v for k, v in chain.values().items()}
    kin = SymbolicChainKinematics(chain_kinematics(chain.lengths),
                                  [syms[f"L{u}"] for u in range(2, chain.n + 2)])
    return SymbolicParts(loads, springs, values, kinematics=kin)
