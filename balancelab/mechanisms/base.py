"""Generic kinematics: explicit pose functions and trees of revolute joints.

:class:`ExplicitKinematics` wraps one pose function that works with numpy and sympy;
:class:`TreeKinematics` places bodies whose angles are affine in ``q`` by walking a
spanning tree of revolute joints (serial chains, parallelograms, pantographs). Both
implement :class:`balancelab.core.kinematics.Kinematics`. Layer: mechanisms.
"""
from __future__ import annotations

from typing import Callable, Sequence

import numpy as np

from ..core.elements import Joint
from ..core import frames
from ..core.frames import rotate
from ..core.kinematics import Kinematics

__all__ = ["ExplicitKinematics", "TreeKinematics"]


def _sympy():
    import sympy

    return sympy


class ExplicitKinematics(Kinematics):
    """Kinematics given by one function that works with numpy and with sympy.

    Parameters
    ----------
    nbodies : int
        Number of bodies, the ground included.
    names : sequence of str
        Names of the configuration coordinates (used as sympy symbol names).
    q_range : array_like, shape (dof, 2)
        Lower and upper bound of each coordinate (rad).
    pose_fn : callable
        ``pose_fn(q, lib) -> list of (x, y, angle)``, one per body, where ``q`` is a
        tuple of coordinates and ``lib`` is ``numpy`` or ``sympy`` (use ``lib.cos``,
        ``lib.sin``). The ground's pose is ``(0, 0, 0)``.
    valid_fn : callable, optional
        ``valid_fn(q) -> bool array``; by default every ``q`` inside ``q_range`` is valid.
    descriptions : sequence of str, optional
        What each coordinate measures, in words (shown on plots).
    """

    def __init__(self, nbodies: int, names: Sequence[str], q_range, pose_fn: Callable,
                 valid_fn: Callable | None = None, open_range: bool = False, descriptions: Sequence[str] = ()) -> None:
        self.descriptions = tuple(descriptions)
        self.nbodies = int(nbodies)
        self.names = tuple(names)
        self.q_range = np.asarray(q_range, dtype=float).reshape(len(self.names), 2)
        self._pose_fn = pose_fn
        self._valid_fn = valid_fn
        self._open = open_range

    def poses(self, q):
        q = np.asarray(q, dtype=float)
        return self._assemble(q, self._pose_fn(tuple(q[..., i] for i in range(self.dof)), np))

    def _assemble(self, q, comps):
        lead = q.shape[:-1]
        out = np.empty((self.nbodies, 3) + lead)
        for b, (x, y, a) in enumerate(comps):
            out[b, 0], out[b, 1], out[b, 2] = x, y, a
        out = np.moveaxis(out, (0, 1), (-2, -1))
        ok = np.ones(lead, dtype=bool)
        tol = 0.0 if self._open else 1e-12
        for i, (lo, hi) in enumerate(self.q_range):
            if not self._open and hi - lo >= 2 * np.pi:
                continue  # a full turn: every angle is reachable
            qi = q[..., i]
            ok &= (qi > lo - tol) & (qi < hi + tol) if self._open else (qi >= lo - tol) & (qi <= hi + tol)
        if self._valid_fn is not None:
            ok &= np.asarray(self._valid_fn(q), dtype=bool)
        return out, ok

    def symbolic_point(self, body, point, syms):
        x, y, a = self._pose_fn(tuple(syms), _sympy())[body]
        px, py = rotate(_sympy(), a, point)
        return (x + px, y + py)


class TreeKinematics(ExplicitKinematics):
    """Bodies whose angles are affine in ``q``, placed by walking a tree of revolute joints.

    This covers serial chains (``angles = q``), parallelograms and pantographs whose
    auxiliary links copy the angle of a main link, and any chain with constant angle
    offsets. Joints outside the spanning tree close loops and are checked numerically
    by the design.

    Parameters
    ----------
    nbodies : int
        Number of bodies, the ground included.
    joints : sequence of Joint
        The revolute joints; the first joints reaching each body (breadth first from
        the ground) form the tree.
    angle_matrix : array_like, shape (nbodies, dof)
        ``angle[b] = angle_matrix[b] @ q + angle_offset[b]``; row 0 (ground) is zero.
    names, q_range : see :class:`ExplicitKinematics`.
    angle_offset : array_like, shape (nbodies,), optional
    """

    def __init__(self, nbodies: int, joints: Sequence[Joint], angle_matrix, names, q_range,
                 angle_offset=None, open_range: bool = False) -> None:
        A = np.asarray(angle_matrix, dtype=float)
        if A.shape != (nbodies, len(names)):
            raise ValueError(f"angle_matrix must have shape ({nbodies}, {len(names)}), got {A.shape}")
        c = np.zeros(nbodies) if angle_offset is None else np.asarray(angle_offset, dtype=float)
        order = _spanning_tree(nbodies, joints)
        self.angle_matrix, self.angle_offset, self.tree = A, c, order

        def coef(v):
            return int(v) if float(v).is_integer() else float(v)

        def pose_fn(q, lib, trig=None):
            symbolic = lib is not np
            trig = {} if trig is None else trig
            angles = []
            for b in range(nbodies):
                a = 0
                for i in range(len(q)):
                    if A[b, i] != 0:
                        a = a + (q[i] if A[b, i] == 1 else coef(A[b, i]) * q[i])
                if c[b] != 0:
                    a = a + (lib.nsimplify(c[b], [lib.pi]) if symbolic else c[b])
                angles.append(a)
            def turn(b, p):
                if p[0] == 0 and p[1] == 0:
                    return 0, 0
                if not A[b].any() and c[b] == 0:  # a body that never turns (the ground)
                    return p[0], p[1]
                if b not in trig:
                    trig[b] = (lib.cos(angles[b]), lib.sin(angles[b]))
                cb, sb = trig[b]
                return frames.turn(cb, sb, p)

            pos = {0: (0, 0)}
            for parent, pp, child, pc in order:
                ox, oy = pos[parent]
                ax, ay = turn(parent, pp)
                bx, by = turn(child, pc)
                pos[child] = (ox + ax - bx, oy + ay - by)
            return [(pos[b][0], pos[b][1], angles[b]) for b in range(nbodies)]

        super().__init__(nbodies, names, q_range, pose_fn, open_range=open_range,
                         descriptions=_tree_descriptions(A, c))

    def poses_with_trig(self, q):
        q = np.asarray(q, dtype=float)
        trig: dict = {}
        poses, ok = self._assemble(q, self._pose_fn(tuple(q[..., i] for i in range(self.dof)), np, trig))
        return poses, ok, trig


_DIRECTIONS = {0.0: "the x-axis", 90.0: "the +y axis", -90.0: "the -y axis (straight down)",
               180.0: "the -x axis", -180.0: "the -x axis"}


def _tree_descriptions(A: np.ndarray, c: np.ndarray) -> tuple[str, ...]:
    """Words for each coordinate: the absolute or relative angle of the first link it turns."""
    out = []
    for i in range(A.shape[1]):
        unit = np.zeros(A.shape[1])
        unit[i] = 1.0
        words = ""
        for b in range(1, A.shape[0]):
            if np.array_equal(A[b], unit):            # body b's angle is q_i plus a constant
                ref = round(float(np.degrees(-c[b])), 6)
                words = (f"angle of link {b} from " + _DIRECTIONS[ref] if ref in _DIRECTIONS
                         else f"angle of link {b} from the direction at {ref:g} deg")
                break
            for p in range(1, A.shape[0]):           # body b turns by q_i relative to body p
                if p != b and np.array_equal(A[b] - A[p], unit) and c[b] == c[p]:
                    words = f"angle of link {b} relative to link {p}"
                    break
            if words:
                break
        out.append(words)
    return tuple(out)


def _spanning_tree(nbodies: int, joints: Sequence[Joint]):
    """Breadth-first spanning tree from the ground: list of (parent, p_parent, child, p_child)."""
    reached = {0}
    order = []
    frontier = [0]
    while frontier:
        nxt = []
        for b in frontier:
            for j in joints:
                for (pi, ppi, ci, pci) in ((j.body_i, j.point_i, j.body_j, j.point_j),
                                           (j.body_j, j.point_j, j.body_i, j.point_i)):
                    if pi == b and ci not in reached:
                        reached.add(ci)
                        order.append((pi, ppi, ci, pci))
                        nxt.append(ci)
        frontier = nxt
    if len(reached) != nbodies:
        missing = sorted(set(range(nbodies)) - reached)
        raise ValueError(f"bodies {missing} are not connected to the ground by any joint")
    return order
