"""Loop closure of any planar linkage of revolute joints, in the absolute body angles.

A spanning tree of the joints, grown breadth first from the ground, places every body
once its angle is known: the world position of any body point is a fixed linear
combination of the rotations of the bodies met on the way from the ground,

.. math:: w = c_0 + \\sum_b R(\\theta_b)\\, c_b ,

with constant vectors ``c_b`` (m). :class:`Topology` stores these coefficients (arrays
of shape ``(nbodies, 2)``) for every body origin and for every joint outside the tree;
each such joint closes a loop with two scalar equations of the same form. Residuals,
their Jacobian with respect to the angles (``d/dtheta R c = R J c``) and a vectorized
Newton solve for the dependent angles follow from these arrays in a few lines of numpy.
Layer: mechanisms.
"""
from __future__ import annotations

from typing import Sequence

import numpy as np

from ...core.elements import Joint

__all__ = ["Topology", "combine", "newton"]


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
    """Spanning tree, body-origin coefficients and loop-closure equations of a linkage.

    Parameters
    ----------
    nbodies : int
        Number of bodies, the ground (body 0) included.
    joints : sequence of Joint
        Revolute joints between the bodies.

    Attributes
    ----------
    tree : list of (int, int)
        ``(joint index, child body)`` of the spanning-tree joints, in breadth-first order.
    loops : list of int
        Indices of the joints that close loops (two equations each).
    origin : numpy.ndarray, shape (nbodies, nbodies, 2)
        ``origin[b]``: coefficients of the world position of body ``b``'s frame origin.
    closure : numpy.ndarray, shape (len(loops), nbodies, 2)
        Coefficients of the gap vector (side ``i`` minus side ``j``) of each loop joint.

    Raises
    ------
    ValueError
        If a body is not connected to the ground through the joints.

    Examples
    --------
    >>> t = Topology(3, [Joint(0, (0.0, 0.0), 1, (0.0, 0.0)), Joint(1, (1.0, 0.0), 2, (0.0, 0.0))])
    >>> t.loops, t.origin[2].tolist()
    ([], [[0.0, 0.0], [1.0, 0.0], [0.0, 0.0]])
    """

    def __init__(self, nbodies: int, joints: Sequence[Joint]):
        self.nbodies = int(nbodies)
        self.joints = [Joint(*j) for j in joints]
        self.tree, self.loops = self._spanning_tree()
        n = self.nbodies
        self.origin = np.zeros((n, n, 2))
        for j, child in self.tree:
            jt = self.joints[j]
            parent, pp, pc = ((jt.body_i, jt.point_i, jt.point_j) if jt.body_j == child
                              else (jt.body_j, jt.point_j, jt.point_i))
            self.origin[child] = self.origin[parent]
            self.origin[child, parent] += pp
            self.origin[child, child] -= pc
        self.closure = np.array([self.point(jt.body_i, jt.point_i) - self.point(jt.body_j, jt.point_j)
                                 for jt in (self.joints[j] for j in self.loops)]).reshape(-1, n, 2)

    def _spanning_tree(self):
        reached, tree, frontier = {0}, [], [0]
        while frontier:
            nxt = []
            for b in frontier:
                for j, jt in enumerate(self.joints):
                    other = jt.body_j if jt.body_i == b else jt.body_i if jt.body_j == b else None
                    if other is not None and other not in reached:
                        reached.add(other)
                        tree.append((j, other))
                        nxt.append(other)
            frontier = nxt
        if len(reached) != self.nbodies:
            missing = sorted(set(range(self.nbodies)) - reached)
            raise ValueError(f"bodies {missing} are not connected to the ground through any chain of joints")
        used = {j for j, _ in tree}
        return tree, [j for j in range(len(self.joints)) if j not in used]

    def point(self, body: int, point) -> np.ndarray:
        """Coefficients ``(nbodies, 2)`` of the world position of a local ``point`` of ``body``."""
        c = self.origin[body].copy()
        c[body] += np.asarray(point, dtype=float)
        return c

    @property
    def nequations(self) -> int:
        """Number of scalar loop-closure equations (two per loop joint)."""
        return 2 * len(self.loops)

    def residual_and_jacobian(self, angles: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """Loop-closure gaps ``(..., 2L)`` (m) and their Jacobian ``(..., 2L, nbodies)`` (m/rad).

        ``angles`` has shape ``(..., nbodies)`` with the ground's angle (column 0) zero.
        """
        x, y = combine(self.closure, np.cos(angles), np.sin(angles))
        lead = angles.shape[:-1]
        res = np.empty(lead + (self.nequations,))
        res[..., 0::2], res[..., 1::2] = x.sum(-1), y.sum(-1)
        jac = np.empty(lead + (self.nequations, self.nbodies))
        jac[..., 0::2, :], jac[..., 1::2, :] = -y, x
        return res, jac

    def poses(self, angles: np.ndarray) -> np.ndarray:
        """Body poses ``(x, y, angle)``, shape ``(..., nbodies, 3)``, from all body angles."""
        c, s = np.cos(angles), np.sin(angles)  # x = sum_b c_b O[., b, 0] - s_b O[., b, 1], as matrix products
        x = c @ self.origin[..., 0].T - s @ self.origin[..., 1].T
        y = s @ self.origin[..., 0].T + c @ self.origin[..., 1].T
        return np.stack([x, y, angles], axis=-1)


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
    angles : numpy.ndarray, shape (..., nbodies)
        Starting angles (rad); modified copy returned.
    dependent : sequence of int
        Bodies whose angles are solved for.
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
    prev = np.full(th.shape[:-1], np.inf)
    for _ in range(iterations + 1):
        res, jac = topology.residual_and_jacobian(th)
        err = np.abs(res).max(axis=-1) if res.shape[-1] else np.zeros(th.shape[:-1])
        # converged, or stalled at the round-off floor (a step gained less than a factor 10) close to tol
        done = (err <= tol) | ((err > 0.1 * prev) & (err <= 1e3 * tol))
        prev = np.minimum(prev, err)
        if done.all() or _ == iterations:
            break
        J = jac[..., dep]
        Jt = np.swapaxes(J, -1, -2)
        A = Jt @ J
        mu = damping * np.trace(A, axis1=-2, axis2=-1)[..., None, None] + 1e-300
        A = A + mu * np.eye(len(dep))
        with np.errstate(all="ignore"):
            step = _solve_small(A, -(Jt @ res[..., None])[..., 0])
        step = np.where(np.isfinite(step) & ~done[..., None], step, 0.0)
        th[..., dep] += np.clip(step, -0.5, 0.5)
    return th, np.where(np.isfinite(err), err, np.inf)
