"""Serial chains: ``n`` links in a row, link 1 pivoted at the origin, each next link at the tip of the last.

Configuration coordinates are the *absolute* angles ``theta_1 .. theta_n`` of the links from
the global x-axis, as in the papers (Singh's 2R arm, Lustig's N-link chain). Body ``i`` is
link ``i``; its local frame has its origin at its proximal joint and its x-axis through its
distal joint at ``(lengths[i-1], 0)``. :func:`serial_2r_kinematics` is the 2R arm of this
chain; :class:`SymbolicChainKinematics` writes the same chain with symbolic link lengths (for
a design's symbolic energy). Layer: mechanisms.
"""
from __future__ import annotations

import math
from typing import Any, Sequence

import numpy as np
from numpy.typing import ArrayLike

from ..core.elements import Joint
from ..core.frames import rotate
from ..core.kinematics import Kinematics
from ..core.validation import finite_real, finite_reals, length_or_symbol
from .base import TreeKinematics

__all__ = ["TWO_TURNS", "serial_2r_joints", "serial_2r_kinematics", "serial_chain_joints",
           "serial_chain_kinematics", "SymbolicChainKinematics"]


TWO_TURNS = ((-math.pi, math.pi), (-math.pi, math.pi))


def _joints(offsets) -> list:
    """Joints of a chain whose link ``i`` carries link ``i + 1`` at ``(offsets[i-1], 0)``."""
    joints = [Joint(0, (0.0, 0.0), 1, (0.0, 0.0))]
    for i, length in enumerate(offsets, start=1):
        joints.append(Joint(i, (length, 0.0), i + 1, (0.0, 0.0)))
    return joints


def _kinematics(joints: list) -> TreeKinematics:
    """The chain of ``joints`` with absolute link angles (identity rows of ``angle_matrix``)."""
    n = len(joints)
    A = [[0.0] * n] + [[1.0 if j == i else 0.0 for j in range(n)] for i in range(n)]
    names = tuple(f"theta_{i}" for i in range(1, n + 1))
    return TreeKinematics(n + 1, joints, A, names, [(-math.pi, math.pi)] * n)


def serial_chain_joints(lengths: Sequence[float]) -> list:
    """The revolute joints of a serial chain of ``len(lengths)`` links.

    Parameters
    ----------
    lengths : sequence of float
        Link lengths (m), one per moving link, each > 0. The last one only places the tip:
        no joint sits there.

    Returns
    -------
    list of Joint
        The ground joint at the origin, then link ``i``'s point ``(lengths[i-1], 0)`` joined
        to link ``i + 1``'s origin.

    Examples
    --------
    >>> [j.point_i for j in serial_chain_joints((0.3, 0.2, 0.1))]
    [(0.0, 0.0), (0.3, 0.0), (0.2, 0.0)]
    """
    lengths = finite_reals("lengths (m)", lengths, None, positive=True)
    if not lengths:
        raise ValueError("lengths (m) must hold at least one link length")
    return _joints(lengths[:-1])


def serial_chain_kinematics(lengths: Sequence[float]) -> TreeKinematics:
    """Kinematics of a serial chain with absolute link angles as coordinates.

    Parameters
    ----------
    lengths : sequence of float
        Link lengths (m), one per moving link, each > 0 (see :func:`serial_chain_joints`).

    Returns
    -------
    TreeKinematics
        Coordinates ``theta_1 .. theta_n``: the **absolute** angle (rad) of each moving
        link from the global x-axis, each in ``[-pi, pi]``.

    Examples
    --------
    >>> k = serial_chain_kinematics((0.3, 0.2))
    >>> k.names
    ('theta_1', 'theta_2')
    >>> k.poses([0.0, 1.5707963267948966])[0][2].round(6).tolist()
    [0.3, 0.0, 1.570796]
    """
    return _kinematics(serial_chain_joints(lengths))


def serial_2r_joints(length: float) -> list:
    """The revolute joints of a 2R arm whose link 1 is ``length`` long (m, or a sympy symbol).

    Examples
    --------
    >>> serial_2r_joints(1.0)[1].point_i
    (1.0, 0.0)
    """
    length = length_or_symbol("length (of link 1, m)", length)
    return _joints((length,))


def serial_2r_kinematics(length: float) -> TreeKinematics:
    """Kinematics of a 2R arm: link 1 pivoted at the origin, link 2 at distance ``length`` on it.

    The serial chain of :func:`serial_chain_kinematics` with two links (link 2's own length
    does not enter the kinematics).

    Parameters
    ----------
    length : float
        Length of link 1 (m), > 0.

    Returns
    -------
    TreeKinematics
        Coordinates ``theta_1``, ``theta_2``: absolute link angles (rad).

    Examples
    --------
    >>> serial_2r_kinematics(1.0).names
    ('theta_1', 'theta_2')
    """
    length = finite_real("length (of link 1, m)", length, positive=True)
    return _kinematics(serial_2r_joints(length))


class SymbolicChainKinematics(Kinematics):
    """A serial chain's kinematics whose symbolic points use symbols for the link lengths.

    Numeric poses are those of ``numeric`` (a :func:`serial_chain_kinematics`); for the
    design's symbolic energy, body ``i``'s origin is ``J_i = sum_{u < i} L_u (cos theta_u,
    sin theta_u)`` with the symbolic lengths ``lengths`` (Lustig's eq. 2b).

    Parameters
    ----------
    numeric : TreeKinematics
        The chain with numeric lengths.
    lengths : sequence of sympy expressions
        One symbolic length per moving link.

    Examples
    --------
    >>> import sympy as sp
    >>> L2, L3 = sp.symbols("L2 L3", positive=True)
    >>> kin = SymbolicChainKinematics(serial_chain_kinematics((0.3, 0.2)), (L2, L3))
    >>> t1, t2 = kin.symbols()
    >>> kin.symbolic_point(2, (0, 0), (t1, t2))
    (L2*cos(theta_1), L2*sin(theta_1))
    """

    def __init__(self, numeric: TreeKinematics, lengths: Sequence[Any]) -> None:
        self.nbodies = numeric.nbodies
        self.names = numeric.names
        self.q_range = numeric.q_range
        self._numeric = numeric
        self._L = tuple(lengths)

    def poses(self, q: ArrayLike) -> tuple[np.ndarray, np.ndarray]:
        return self._numeric.poses(q)

    def symbolic_point(self, body: int, point: Sequence[Any], syms: Any) -> tuple:
        import sympy as sp

        x, y = sp.S.Zero, sp.S.Zero
        for i in range(1, body):
            dx, dy = rotate(sp, syms[i - 1], (self._L[i - 1], 0))
            x, y = x + dx, y + dy
        if body == 0:
            return (x + point[0], y + point[1])
        px, py = rotate(sp, syms[body - 1], point)
        return (x + px, y + py)
