"""Loop closure of any planar linkage of revolute and prismatic joints, in the absolute body
angles and the slides.

A spanning tree of the joints, grown breadth first from the ground, places every body
once its angle (and the slides met on the way) are known: the world position of any body
point is a fixed linear combination of the rotations of the bodies met on the way from the
ground,

.. math:: w = c_0 + \\sum_b R(\\theta_b)\\, c_b + \\sum_p \\sigma_p s_p R(\\theta_{a_p}) u_p ,

with constant vectors ``c_b`` (m), and for each prismatic joint ``p`` (a :class:`Slider`:
``point_b`` of ``body_b`` on the line through ``point_a`` of ``body_a`` along the unit ``axis``
``u_p`` of ``body_a``) its slide ``s_p`` (m) with a sign ``sigma_p`` of -1, 0 or 1.
:class:`Topology` stores these coefficients for every body origin and for every joint
outside the tree; a revolute joint outside the tree closes a loop with two scalar
equations, a prismatic one with three (its point on its line, two; the relative angle of its
bodies kept, one), and a prismatic joint in the tree adds the relative-angle equation only.
The variables are the body angles followed by the slides. Residuals,
their Jacobian with respect to the angles (``d/dtheta R c = R J c``) and a vectorized
Newton solve for the dependent angles follow from these arrays in a few lines of numpy.
Layer: mechanisms.
"""
from __future__ import annotations

from dataclasses import dataclass
from typing import Sequence

import numpy as np

from ...core.elements import Joint

__all__ = ["Slider", "Topology", "combine", "newton"]


@dataclass(frozen=True)
class Slider:
    """A prismatic joint: ``point_b`` of ``body_b`` slides along the line through ``point_a`` of
    ``body_a`` with the unit direction ``axis`` (in ``body_a``'s frame); the two bodies keep their
    relative angle (the drawn one, zero). The slide ``s`` (m) is the distance from ``point_a``.

    Examples
    --------
    >>> Slider(0, (0.0, 0.0), 1, (0.0, 0.0), (1.0, 0.0)).axis
    (1.0, 0.0)
    """

    body_a: int
    point_a: tuple
    body_b: int
    point_b: tuple
    axis: tuple


def combine(coef: np.ndarray, cos: np.ndarray, sin: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Each body's rotated contribution ``R(theta_b) c_b`` (two arrays of shape ``(..., m, nbodies)``).

    Parameters
    ----------
    coef : numpy.ndarray, shape (m, nbodies, 2)
        Coefficient vectors ``c_b`` of ``m`` expressions (m).
    cos, sin : numpy.ndarray, shape (..., nbodies)
        Cosines and sines of the body angles (the ground's angle is 0).

    Returns
    -------
    (numpy.ndarray, numpy.ndarray)
        x and y parts; summed over the last axis they are the expressions' values.

    Examples
    --------
    >>> import numpy as np
    >>> coef = np.array([[[1.0, 0.0], [0.5, 0.0]]])  # c_0 = (1, 0), c_1 = (0.5, 0)
    >>> x, y = combine(coef, np.cos([0.0, np.pi / 2]), np.sin([0.0, np.pi / 2]))
    >>> round(float(x.sum()), 12), round(float(y.sum()), 12)
    (1.0, 0.5)
    """
    c, s = cos[..., None, :], sin[..., None, :]
    return c * coef[..., 0] - s * coef[..., 1], s * coef[..., 0] + c * coef[..., 1]


class Topology:
    """Spanning tree, body-origin coefficients and closure equations of a linkage.

    Parameters
    ----------
    nbodies : int
        Number of bodies, the ground (body 0) included.
    joints : sequence of Joint
        Revolute joints between the bodies.
    sliders : sequence of Slider, optional
        Prismatic joints.
    size : float
        Length scale (m) of the angle equations (so that every equation is in metres).

    Attributes
    ----------
    tree : list of (int, int)
        ``(joint index, child body)`` of the spanning-tree joints, in breadth-first order; a
        prismatic joint ``p`` has the index ``len(joints) + p``.
    loops : list of int
        Indices of the joints that close loops.
    origin : numpy.ndarray, shape (nbodies, nbodies, 2)
        ``origin[b]``: coefficients of the world position of body ``b``'s frame origin.
    origin_slide : numpy.ndarray, shape (nbodies, nsliders)
        ``origin_slide[b, p]``: the sign with which slide ``p`` enters it.
    nvar : int
        Number of variables: ``nbodies`` angles, then one slide per prismatic joint.

    Raises
    ------
    ValueError
        If a body is not connected to the ground through the joints.

    Examples
    --------
    >>> t = Topology(3, [Joint(0, (0.0, 0.0), 1, (0.0, 0.0)), Joint(1, (1.0, 0.0), 2, (0.0, 0.0))])
    >>> t.loops, t.origin[2].tolist(), t.nvar
    ([], [[0.0, 0.0], [1.0, 0.0], [0.0, 0.0]], 3)
    """

    def __init__(self, nbodies: int, joints: Sequence[Joint], sliders: Sequence[Slider] = (), size: float = 1.0) -> None:
        self.nbodies = int(nbodies)
        self.joints = [Joint(*j) for j in joints]
        self.sliders = [p if isinstance(p, Slider) else Slider(*p) for p in sliders]
        self.size = float(size)
        n, P = self.nbodies, len(self.sliders)
        self.nvar = n + P
        # direction of each slide, as a coefficient array on its body a: R(theta_a) u_p
        self.slide_dir = np.zeros((P, n, 2))
        for i, sl in enumerate(self.sliders):
            self.slide_dir[i, sl.body_a] = sl.axis
        self.tree, self.loops = self._spanning_tree()
        self.origin = np.zeros((n, n, 2))
        self.origin_slide = np.zeros((n, P))
        nj = len(self.joints)
        for j, child in self.tree:
            if j < nj:
                jt = self.joints[j]
                parent, pp, pc = ((jt.body_i, jt.point_i, jt.point_j) if jt.body_j == child
                                  else (jt.body_j, jt.point_j, jt.point_i))
                sign = 0.0
            else:
                sl = self.sliders[j - nj]
                parent, pp, pc = ((sl.body_a, sl.point_a, sl.point_b) if sl.body_b == child
                                  else (sl.body_b, sl.point_b, sl.point_a))
                sign = 1.0 if sl.body_b == child else -1.0
            self.origin[child] = self.origin[parent]
            self.origin_slide[child] = self.origin_slide[parent]
            self.origin[child, parent] += pp
            self.origin[child, child] -= pc
            if sign:
                self.origin_slide[child, j - nj] += sign
        rows, srows, self.angle_rows = [], [], []
        for j in self.loops:
            if j < nj:
                jt = self.joints[j]
                (ci, si), (cj, sj) = self.point(jt.body_i, jt.point_i), self.point(jt.body_j, jt.point_j)
                rows.append(ci - cj)
                srows.append(si - sj)
            else:
                p = j - nj
                sl = self.sliders[p]
                (ca, sa), (cb, sb) = self.point(sl.body_a, sl.point_a), self.point(sl.body_b, sl.point_b)
                sa = sa.copy()
                sa[p] += 1.0  # point_a + s_p u_p - point_b
                rows.append(ca - cb)
                srows.append(sa - sb)
        self.angle_rows = [(sl.body_a, sl.body_b) for sl in self.sliders]
        self.closure = np.array(rows).reshape(-1, n, 2)
        self.closure_slide = np.array(srows, dtype=float).reshape(len(rows), P)

    def _spanning_tree(self):
        edges = [(jt.body_i, jt.body_j) for jt in self.joints] + [(s.body_a, s.body_b) for s in self.sliders]
        reached, tree, frontier = {0}, [], [0]
        while frontier:
            nxt = []
            for b in frontier:
                for j, (bi, bj) in enumerate(edges):
                    other = bj if bi == b else bi if bj == b else None
                    if other is not None and other not in reached:
                        reached.add(other)
                        tree.append((j, other))
                        nxt.append(other)
            frontier = nxt
        if len(reached) != self.nbodies:
            missing = sorted(set(range(self.nbodies)) - reached)
            raise ValueError(f"bodies {missing} are not connected to the ground through any chain of joints")
        used = {j for j, _ in tree}
        return tree, [j for j in range(len(edges)) if j not in used]

    def point(self, body: int, point) -> tuple[np.ndarray, np.ndarray]:
        """Coefficients ``(nbodies, 2)`` and slide signs ``(nsliders,)`` of the world position of a
        local ``point`` of ``body``."""
        c = self.origin[body].copy()
        c[body] += np.asarray(point, dtype=float)
        return c, self.origin_slide[body].copy()

    @property
    def nequations(self) -> int:
        """Number of scalar closure equations: two per loop joint, one per prismatic joint's angle."""
        return 2 * len(self.loops) + len(self.sliders)

    def _effective(self, coef: np.ndarray, signs: np.ndarray, slides: np.ndarray) -> np.ndarray:
        """``coef`` with the slide terms folded in: ``c_b + sum_p sign_p s_p u_p [b == a_p]``."""
        if not len(self.sliders):
            return coef
        return coef + np.einsum("...p,mp,pbk->...mbk", slides, signs, self.slide_dir)

    def residual_and_jacobian(self, x: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """Closure gaps ``(..., E)`` (m) and their Jacobian ``(..., E, nvar)`` (m/rad, m/m).

        ``x`` has shape ``(..., nvar)``: the body angles (the ground's, column 0, zero), then the slides.
        """
        n = self.nbodies
        angles, slides = x[..., :n], x[..., n:]
        c, s = np.cos(angles), np.sin(angles)
        lead = x.shape[:-1]
        L = len(self.loops)
        res = np.zeros(lead + (self.nequations,))
        jac = np.zeros(lead + (self.nequations, self.nvar))
        if L:
            coef = self._effective(self.closure, self.closure_slide, slides)
            gx, gy = combine(coef, c, s)
            res[..., 0:2 * L:2], res[..., 1:2 * L:2] = gx.sum(-1), gy.sum(-1)
            jac[..., 0:2 * L:2, :n], jac[..., 1:2 * L:2, :n] = -gy, gx
            for p in range(len(self.sliders)):
                dx, dy = combine(self.closure_slide[:, p, None, None] * self.slide_dir[p], c, s)
                jac[..., 0:2 * L:2, n + p], jac[..., 1:2 * L:2, n + p] = dx.sum(-1), dy.sum(-1)
        for k, (a, b) in enumerate(self.angle_rows):  # the relative angle kept, in metres
            res[..., 2 * L + k] = self.size * (angles[..., b] - angles[..., a])
            jac[..., 2 * L + k, b] += self.size
            jac[..., 2 * L + k, a] -= self.size
        return res, jac

    def poses(self, x: np.ndarray) -> np.ndarray:
        """Body poses ``(x, y, angle)``, shape ``(..., nbodies, 3)``, from the variables ``(..., nvar)``."""
        n = self.nbodies
        angles = x[..., :n]
        c, s = np.cos(angles), np.sin(angles)  # x = sum_b c_b O[., b, 0] - s_b O[., b, 1], as matrix products
        px = c @ self.origin[..., 0].T - s @ self.origin[..., 1].T
        py = s @ self.origin[..., 0].T + c @ self.origin[..., 1].T
        if self.sliders:
            sx, sy = combine(self.slide_dir, c, s)  # (..., P, n): R(theta_a) u_p, on its body's column
            ux, uy = sx.sum(-1), sy.sum(-1)
            slides = x[..., n:]
            px = px + (slides * ux) @ self.origin_slide.T
            py = py + (slides * uy) @ self.origin_slide.T
        return np.stack([px, py, angles], axis=-1)


def _solve_small(A: np.ndarray, b: np.ndarray) -> np.ndarray:
    """Solve the batched systems ``A x = b`` (``A`` of shape ``(..., n, n)``), fast for n <= 2."""
    n = A.shape[-1]
    if n == 1:
        return b / A[..., 0, 0, None]
    if n == 2:
        a, bb, c, d = A[..., 0, 0], A[..., 0, 1], A[..., 1, 0], A[..., 1, 1]
        det = a * d - bb * c
        return np.stack([(d * b[..., 0] - bb * b[..., 1]) / det, (a * b[..., 1] - c * b[..., 0]) / det], -1)
    return np.linalg.solve(A, b[..., None])[..., 0]


def newton(topology: Topology, angles: np.ndarray, dependent: Sequence[int], tol: float,
           iterations: int = 12, damping: float = 1e-12) -> tuple[np.ndarray, np.ndarray]:
    """Solve the loop closure for the ``dependent`` angles by Newton's method, vectorized.

    The other angles are held fixed. Each step solves the regularized normal equations
    ``(J^T J + mu I) d = -J^T r`` (``mu`` a fraction ``damping`` of ``J^T J``'s trace), which is
    Newton's step for a square regular ``J``, Gauss-Newton for redundant loops (more
    equations than unknowns, consistent), and stays finite at singular configurations.

    Parameters
    ----------
    topology : Topology
    angles : numpy.ndarray, shape (..., nvar)
        Starting variables (rad, and m for slides); modified copy returned.
    dependent : sequence of int
        Variables solved for (body indices; ``nbodies + p`` for slide ``p``).
    tol : float
        Convergence tolerance on the largest gap (m); a configuration whose gap stops shrinking
        (round-off) within ``1000 tol`` counts as converged too.
    iterations : int
        Largest number of steps.
    damping : float
        Levenberg damping, relative to the trace of ``J^T J``.

    Returns
    -------
    (numpy.ndarray, numpy.ndarray)
        The angles and the largest gap (m) of each configuration (``inf`` if not finite).

    Examples
    --------
    >>> t = Topology(3, [Joint(0, (0.0, 0.0), 1, (0.0, 0.0)), Joint(1, (1.0, 0.0), 2, (0.0, 0.0)),
    ...                  Joint(2, (1.0, 0.0), 0, (1.0, 1.0))])  # a right angle: theta_2 = 90 deg
    >>> th, err = newton(t, np.array([0.0, 0.0, 1.0]), [2], 1e-14)
    >>> round(float(th[2]), 12), bool(err < 1e-14)
    (1.570796326795, True)
    """
    th = np.array(angles, dtype=float, copy=True)
    dep = list(dependent)
    unit = np.where(np.array(dep, dtype=int) >= topology.nbodies, topology.size, 1.0)  # rad; m for slides
    lim = 0.5 * unit
    prev = np.full(th.shape[:-1], np.inf)
    for _ in range(iterations + 1):
        res, jac = topology.residual_and_jacobian(th)
        err = np.abs(res).max(axis=-1) if res.shape[-1] else np.zeros(th.shape[:-1])
        # converged, or stalled at the round-off floor (a step gained less than a factor 10) close to tol
        done = (err <= tol) | ((err > 0.1 * prev) & (err <= 1e3 * tol))
        prev = np.minimum(prev, err)
        if done.all() or _ == iterations:
            break
        J = jac[..., dep] * unit  # columns alike (m per rad, m per size of slide): a tiny linkage's damping
        Jt = np.swapaxes(J, -1, -2)  # must not swamp its angles (a 1 um slider)
        A = Jt @ J
        mu = damping * np.trace(A, axis1=-2, axis2=-1)[..., None, None] + 1e-300
        A = A + mu * np.eye(len(dep))
        with np.errstate(all="ignore"):
            step = _solve_small(A, -(Jt @ res[..., None])[..., 0])
        step = np.where(np.isfinite(step) & ~done[..., None], step * unit, 0.0)
        th[..., dep] += np.clip(step, -lim, lim)
    return th, np.where(np.isfinite(err), err, np.inf)
