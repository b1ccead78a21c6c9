"""Configuration -> body poses, numerically (vectorized) and symbolically.

A :class:`Kinematics` object turns configuration coordinates ``q`` (radians) into the
pose ``(x, y, angle)`` of every body. Open chains and closed loops with a known
closed-form solution (four-bar, scissors, Peaucellier-Lipkin) are all expressed this
way, each on a declared assembly branch. ``poses`` also returns a mask of the
configurations the linkage can reach; :class:`balancelab.Design` turns an unreachable
configuration into a clear error.

Symbolically a kinematics gives the global position of any body point as a sympy
2-vector in the configuration symbols (``symbolic_point``), which is all the
potential energy needs.
"""
from __future__ import annotations

from typing import Callable, Sequence

import numpy as np

from .elements import Joint

__all__ = [
    "Kinematics",
    "ExplicitKinematics",
    "TreeKinematics",
    "FourBarKinematics",
    "rotate",
    "binary_link_point",
]


def rotate(lib, angle, point):
    """Rotate the local ``point`` by ``angle`` with the math library ``lib`` (numpy or sympy)."""
    c, s = lib.cos(angle), lib.sin(angle)
    return (c * point[0] - s * point[1], s * point[0] + c * point[1])


def binary_link_point(p1, p2, q1, q2, q):
    """Global position of the local point ``q`` of a link from the positions of two of its points.

    A rigid planar body is fixed by two of its points: if its local points ``q1`` and
    ``q2`` sit at global ``p1`` and ``p2``, the local point ``q`` sits at
    ``p1 + M (p2 - p1)`` where ``M`` is the rotation-and-scale taking ``q2 - q1`` to
    ``q - q1`` (the complex ratio ``(q - q1)/(q2 - q1)``). This is the lecture's
    decomposition of the coupler of a four-bar: a point of the coupler is a fixed
    complex multiple of the vector between its two joints. Works with numbers and
    sympy expressions alike.
    """
    ux, uy = q2[0] - q1[0], q2[1] - q1[1]
    vx, vy = q[0] - q1[0], q[1] - q1[1]
    den = ux * ux + uy * uy
    cr = (vx * ux + vy * uy) / den
    ci = (vy * ux - vx * uy) / den
    dx, dy = p2[0] - p1[0], p2[1] - p1[1]
    return (p1[0] + cr * dx - ci * dy, p1[1] + ci * dx + cr * dy)


def _sympy():
    import sympy

    return sympy


class Kinematics:
    """Base class: ``dof`` coordinates with names and ranges, poses of ``nbodies`` bodies."""

    nbodies: int
    names: tuple[str, ...]
    q_range: np.ndarray

    @property
    def dof(self) -> int:
        return len(self.names)

    def poses(self, q: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """Return ``(poses, ok)``: poses of shape ``(..., nbodies, 3)`` and a boolean mask."""
        raise NotImplementedError

    def poses_with_trig(self, q: np.ndarray) -> tuple[np.ndarray, np.ndarray, dict]:
        """:meth:`poses` plus any ``{body: (cos(angle), sin(angle))}`` already computed."""
        poses, ok = self.poses(q)
        return poses, ok, {}

    def symbols(self):
        """The sympy symbols of the configuration coordinates."""
        sp = _sympy()
        return sp.symbols(self.names, real=True)

    def symbolic_point(self, body: int, point, syms):
        """Global position (a pair of sympy expressions) of a local ``point`` of ``body``."""
        raise NotImplementedError

    #: bodies whose angles are the symbolic coordinates, when they are not ``q`` itself
    symbol_bodies: tuple | None = None

    def symbol_values(self, q) -> np.ndarray:
        """Values of :meth:`symbols` in the configurations ``q``, shape ``(..., len(symbols))``."""
        q = np.asarray(q, dtype=float)
        if self.symbol_bodies is None:
            return q
        return self.poses(q)[0][..., list(self.symbol_bodies), 2]


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
    """

    def __init__(self, nbodies: int, names: Sequence[str], q_range, pose_fn: Callable,
                 valid_fn: Callable | None = None, open_range: bool = False):
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
                 angle_offset=None, open_range: bool = False):
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
                return cb * p[0] - sb * p[1], sb * p[0] + cb * p[1]

            pos = {0: (0, 0)}
            for parent, pp, child, pc in order:
                ox, oy = pos[parent]
                ax, ay = turn(parent, pp)
                bx, by = turn(child, pc)
                pos[child] = (ox + ax - bx, oy + ay - by)
            return [(pos[b][0], pos[b][1], angles[b]) for b in range(nbodies)]

        super().__init__(nbodies, names, q_range, pose_fn, open_range=open_range)

    def poses_with_trig(self, q):
        q = np.asarray(q, dtype=float)
        trig: dict = {}
        poses, ok = self._assemble(q, self._pose_fn(tuple(q[..., i] for i in range(self.dof)), np, trig))
        return poses, ok, trig


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


class FourBarKinematics(Kinematics):
    """Closed-form position analysis of a four-bar linkage.

    Bodies: 0 ground, 1 crank (from pivot ``A``), 2 coupler (from the crank tip), 3
    rocker (from pivot ``B``). The coordinate is the crank angle ``theta`` measured
    from the global x-axis. ``branch`` (+1 or -1) picks the assembly: the coupler
    direction is the direction from the crank tip to ``B`` turned by ``+-`` the
    triangle angle.

    Symbolically the design can be seen two ways (``symbolic``):

    * ``"loop"``: crank and rocker angles are the symbols ``theta_2``, ``theta_4`` and
      every coupler point is written through the two moving joints (the lecture's
      equivalent-mass decomposition). Constant energy in these symbols means
      constant energy of the four-bar.
    * ``"relaxed"``: the coupler-rocker joint is released and crank, coupler and rocker
      each get their own angle (Singh & Ananthasuresh, Sec. III.A). Constant energy
      of the relaxed chain is sufficient for the four-bar.
    """

    def __init__(self, A, B, crank: float, coupler: float, rocker: float, branch: int = 1,
                 symbolic: str = "loop", circuit: float | None = None):
        from .elements import _finite, _point

        self.A = np.array(_point("pivot A", A))
        self.B = np.array(_point("pivot B", B))
        self.r2 = _finite("crank length (m)", crank, positive=True)
        self.r3 = _finite("coupler length (m)", coupler, positive=True)
        self.r4 = _finite("rocker length (m)", rocker, positive=True)
        if branch not in (1, -1):
            raise ValueError(f"branch must be +1 or -1, got {branch!r}")
        if symbolic not in ("loop", "relaxed"):
            raise ValueError(f"symbolic must be 'loop' or 'relaxed', got {symbolic!r}")
        self.branch = branch
        self.symbolic = symbolic
        self.r1 = float(np.hypot(*(self.B - self.A)))
        if self.r1 == 0:
            raise ValueError("ground pivots A and B coincide; a four-bar needs two distinct pivots")
        self.nbodies = 4
        self.names = ("theta",)
        self.symbol_bodies = (1, 3) if symbolic == "loop" else (1, 2, 3)
        self.q_range = self._crank_range(circuit)

    def _assembles(self, theta):
        jx = self.A[0] + self.r2 * np.cos(theta)
        jy = self.A[1] + self.r2 * np.sin(theta)
        D = np.hypot(self.B[0] - jx, self.B[1] - jy)
        return (D <= self.r3 + self.r4) & (D >= abs(self.r3 - self.r4)) & (D > 0)

    def _crank_range(self, circuit: float | None = None) -> np.ndarray:
        """Interval of crank angles over which the linkage assembles.

        With ``circuit`` (a crank angle, rad) the interval containing it; otherwise the
        widest one (a crank that cannot turn fully may have two).
        """
        base = np.arctan2(*(self.B - self.A)[::-1])
        t = base + np.linspace(-np.pi, np.pi, 7201)
        ok = self._assembles(t)
        if circuit is not None:
            from .elements import _finite

            c = _finite("circuit (crank angle, rad)", circuit)
            if not self._assembles(np.array(c)):
                raise ValueError(f"the four-bar cannot assemble at the crank angle circuit = {c} rad")
            if ok.all():
                return np.array([[c - np.pi, c + np.pi]])
            t = c + np.linspace(-2 * np.pi, 2 * np.pi, 14401)
            ok = self._assembles(t)
            bad = np.flatnonzero(~ok)
            left, right = bad[bad < 7200].max(), bad[bad > 7200].min()
            return np.array([[self._refine(t[left + 1], -1), self._refine(t[right - 1], +1)]])
        if ok.all():
            return np.array([[base - np.pi, base + np.pi]])
        if not ok.any():
            raise ValueError(
                "this four-bar cannot assemble: with crank {:.4g} m, coupler {:.4g} m, rocker {:.4g} m "
                "and ground {:.4g} m no crank angle closes the loop (each link must be shorter than "
                "the sum of the other three)".format(self.r2, self.r3, self.r4, self.r1))
        # ok is False at the ends (opposite side of B) or True there; roll so runs are contiguous
        idx = np.flatnonzero(ok)
        runs = np.split(idx, np.flatnonzero(np.diff(idx) > 1) + 1)
        if ok[0] and ok[-1] and len(runs) > 1:
            first, last = runs[0], runs[-1]
            runs = runs[1:-1] + [np.concatenate([last, first + len(t) - 1])]
            t = np.concatenate([t, t[1:] + 2 * np.pi])
        best = max(runs, key=len)
        lo, hi = t[best[0]], t[best[-1]]
        lo, hi = self._refine(lo, -1), self._refine(hi, +1)
        return np.array([[lo, hi]])

    def _refine(self, t0, direction):
        """Bisect the crank limit near ``t0`` to machine precision."""
        step = 2 * np.pi / 7200
        a, b = t0, t0 + direction * step
        for _ in range(60):
            m = 0.5 * (a + b)
            if self._assembles(np.array(m)):
                a = m
            else:
                b = m
        return a

    def poses(self, q):
        q = np.asarray(q, dtype=float)
        th = q[..., 0]
        A, B = self.A, self.B
        jx = A[0] + self.r2 * np.cos(th)
        jy = A[1] + self.r2 * np.sin(th)
        dx, dy = B[0] - jx, B[1] - jy
        D = np.hypot(dx, dy)
        cosg = (self.r3 ** 2 + D ** 2 - self.r4 ** 2) / (2 * self.r3 * np.where(D > 0, D, 1.0))
        lo, hi = self.q_range[0]
        ok = (np.abs(cosg) <= 1 + 1e-12) & (D > 0) & (th >= lo - 1e-12) & (th <= hi + 1e-12)
        gam = np.arccos(np.clip(cosg, -1.0, 1.0))
        phi = np.arctan2(dy, dx) + self.branch * gam
        kx = jx + self.r3 * np.cos(phi)
        ky = jy + self.r3 * np.sin(phi)
        psi = np.arctan2(ky - B[1], kx - B[0])
        out = np.zeros(th.shape + (4, 3))
        out[..., 1, 0], out[..., 1, 1], out[..., 1, 2] = A[0], A[1], th
        out[..., 2, 0], out[..., 2, 1], out[..., 2, 2] = jx, jy, phi
        out[..., 3, 0], out[..., 3, 1], out[..., 3, 2] = B[0], B[1], psi
        return out, ok

    def symbols(self):
        sp = _sympy()
        if self.symbolic == "loop":
            return sp.symbols("theta_2 theta_4", real=True)
        return sp.symbols("theta_1 theta_2 theta_3", real=True)

    def symbolic_point(self, body, point, syms):
        sp = _sympy()
        A = [sp.nsimplify(v) if v == int(v) else sp.Float(v) for v in self.A]
        B = [sp.nsimplify(v) if v == int(v) else sp.Float(v) for v in self.B]
        if body == 0:
            return tuple(point)
        if self.symbolic == "loop":
            t2, t4 = syms
            J2 = (A[0] + self.r2 * sp.cos(t2), A[1] + self.r2 * sp.sin(t2))
            J3 = (B[0] + self.r4 * sp.cos(t4), B[1] + self.r4 * sp.sin(t4))
            if body == 1:
                px, py = rotate(sp, t2, point)
                return (A[0] + px, A[1] + py)
            if body == 3:
                px, py = rotate(sp, t4, point)
                return (B[0] + px, B[1] + py)
            return binary_link_point(J2, J3, (0, 0), (self.r3, 0), point)
        t1, t2, t3 = syms
        if body == 1:
            px, py = rotate(sp, t1, point)
            return (A[0] + px, A[1] + py)
        if body == 2:
            jx, jy = rotate(sp, t1, (self.r2, 0))
            px, py = rotate(sp, t2, point)
            return (A[0] + jx + px, A[1] + jy + py)
        px, py = rotate(sp, t3, point)
        return (B[0] + px, B[1] + py)
