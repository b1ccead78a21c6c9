"""What a drawing of a design shows, and where: the points of every body, joint, spring, load and
named point gathered for one vectorized transform (:class:`Geometry`), the bodies' outlines
(:func:`hull`) and the box the mechanism sweeps over its range (:func:`extent`).

:mod:`balancelab.viz.drawing` draws them. No physics: every position comes from the design's own
poses. Layer: viz.
"""
from __future__ import annotations

import math

import numpy as np

from ..core.design import Design
from ..core.kinematics import body_to_world
from .frame import range_grid
from .springs import cable_angle, cable_coil_end, pulley_coil_length, pulley_drawn_radius

__all__ = ["Geometry", "extent", "hull"]


def hull(points: np.ndarray) -> np.ndarray:
    """Convex hull (counter-clockwise) of 2-D points (m); two extremes for collinear points.

    Parameters
    ----------
    points : numpy.ndarray
        Shape ``(n, 2)``.

    Returns
    -------
    numpy.ndarray
        The hull's corners, shape ``(h, 2)``.

    Examples
    --------
    >>> import numpy as np
    >>> hull(np.array([[0.0, 0.0], [1.0, 0.0], [0.5, 0.2], [1.0, 1.0], [0.0, 1.0]])).tolist()
    [[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]]
    """
    pts = np.unique(np.round(points, 12), axis=0)
    if len(pts) <= 2:
        return pts
    order = np.lexsort((pts[:, 1], pts[:, 0]))
    pts = pts[order]

    def cross(o, a, b):
        return (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0])

    scale = float(np.ptp(pts, axis=0).max()) or 1.0
    eps = 1e-9 * scale * scale
    lower: list = []
    for p in pts:
        while len(lower) >= 2 and cross(lower[-2], lower[-1], p) <= eps:
            lower.pop()
        lower.append(p)
    upper: list = []
    for p in pts[::-1]:
        while len(upper) >= 2 and cross(upper[-2], upper[-1], p) <= eps:
            upper.pop()
        upper.append(p)
    return np.array(lower[:-1] + upper[:-1])


def _body_points(design: Design) -> list[list[tuple[float, float]]]:
    """Local points of each body that its drawn shape must pass through."""
    pts: list[list] = [[] for _ in design.bodies]
    for j in design.joints:
        pts[j.body_i].append(tuple(j.point_i))
        pts[j.body_j].append(tuple(j.point_j))
    for s in design.springs:
        pts[s.a.body].append(tuple(s.a.point))
        if s.cable is None:   # a cable's clamp sits on its pulley, drawn with it
            pts[s.b.body].append(tuple(s.b.point))
    for ld in design.loads:
        pts[ld.body].append(tuple(ld.point))
    for body, point in design.labels.values():
        if 0 <= int(body) < len(pts):
            pts[int(body)].append((float(point[0]), float(point[1])))
    for b in range(1, len(pts)):
        pts[b].append((0.0, 0.0))
    return [list(dict.fromkeys(p)) for p in pts]


def _ground_points(design: Design) -> list[tuple[float, ...]]:
    out: list[tuple[float, ...]] = []
    for j in design.joints:
        if j.body_i == 0:
            out.append(tuple(j.point_i))
        if j.body_j == 0:
            out.append(tuple(j.point_j))
    for s in design.springs:
        for at in (s.a, s.b):
            if at.body == 0:
                out.append(at.point)
    return list(dict.fromkeys(out))


def _structure(design: Design):
    return (len(design.bodies), tuple((j.body_i, j.body_j) for j in design.joints),
            tuple((s.a.body, s.b.body, s.realization, s.is_zfl) for s in design.springs),
            tuple((ld.body, ld.kind) for ld in design.loads), tuple(design.labels),
            tuple(len(p) for p in _body_points(design)), len(_ground_points(design)))


class Geometry:
    """Every point a drawing of ``design`` needs, gathered for one vectorized world transform.

    Parameters
    ----------
    design : Design

    Attributes
    ----------
    body_idx : list of list of int
        Rows of :meth:`world` holding the outline points of each body.
    joint_idx : list of int
        Row of each joint.
    spring_idx : list of (int, int)
        Rows of each spring's attachments ``a`` and ``b``.
    load_idx : list of int
        Row of each load's point of action.
    label_idx : dict of str to int
        Row of each named point.
    ground : list of (float, float)
        The ground's pivots and anchors (m), drawn hatched.
    structure : tuple
        What the drawing's artists depend on (bodies, joints, kinds of springs and loads, named
        points): two designs of the same structure are drawn by moving the same artists.

    Examples
    --------
    >>> import balancelab as bl
    >>> d = bl.singh.lacoste_lever(10.0, 0.5, 0.2, 0.3)
    >>> g = Geometry(d)
    >>> g.world([0.0])[g.label_idx["p"]].tolist()
    [0.5, 0.0]
    """

    def __init__(self, design: Design) -> None:
        self.design = design
        self.body_pts = _body_points(design)
        self.ground = _ground_points(design)
        self.structure = _structure(design)
        att: list = []
        self.body_idx = []
        for b, pts in enumerate(self.body_pts):
            self.body_idx.append(list(range(len(att), len(att) + len(pts))))
            att += [(b, p) for p in pts]
        self.joint_idx = []
        for j in design.joints:
            self.joint_idx.append(len(att))
            att.append((j.body_i, tuple(j.point_i)))
        self.spring_idx = []
        for s in design.springs:
            self.spring_idx.append((len(att), len(att) + 1))
            att += [(s.a.body, tuple(s.a.point)), (s.b.body, tuple(s.b.point))]
        self.load_idx = []
        for ld in design.loads:
            self.load_idx.append(len(att))
            att.append((ld.body, tuple(ld.point)))
        self.label_idx = {}
        for name, (body, point) in design.labels.items():
            self.label_idx[name] = len(att)
            att.append((int(body), (float(point[0]), float(point[1]))))
        self.bodies = np.array([a[0] for a in att], dtype=int)
        self.points = np.array([a[1] for a in att], dtype=float).reshape(-1, 2)

    def world(self, q) -> np.ndarray:
        """World positions (m) of every point at configuration(s) ``q`` (rad), shape (..., m, 2)."""
        poses = self.design.poses(q)
        x, y = body_to_world(poses, self.bodies, self.points)
        return np.stack([x, y], axis=-1)


def extent(design: Design, geom: Geometry | None = None, n: int = 64):
    """Bounding box of the mechanism over its range, and its size.

    Parameters
    ----------
    design : Design
    geom : Geometry, optional
        The points to bound (those of a drawing of ``design`` by default).
    n : int
        Configurations sampled over the range.

    Returns
    -------
    (numpy.ndarray, float)
        ``[xmin, xmax, ymin, ymax]`` (m) and the larger side (m).

    Examples
    --------
    >>> import balancelab as bl
    >>> box, size = extent(bl.singh.lacoste_lever(10.0, 0.5, 0.2, 0.3))
    >>> round(size, 3)
    1.0
    """
    geom = Geometry(design) if geom is None else geom
    q = range_grid(design, n)
    ok = design.reachable(q)
    q = q[ok] if ok.any() else design.sample(8, seed=0)
    W = geom.world(q)
    pts = W.reshape(-1, 2)
    xmin, ymin = pts.min(axis=0)
    xmax, ymax = pts.max(axis=0)
    size = float(max(xmax - xmin, ymax - ymin, 1e-9))
    ends = _pulley_coil_ends(design, geom, W, size)
    if len(ends):
        (xmin, ymin), (xmax, ymax) = np.minimum(ends.min(axis=0), (xmin, ymin)), np.maximum(
            ends.max(axis=0), (xmax, ymax))
    return np.array([xmin, xmax, ymin, ymax]), size


def _pulley_coil_ends(design: Design, geom: Geometry, W: np.ndarray, size: float) -> np.ndarray:
    """Farthest point (m) the coil of every pulley spring reaches over the configurations ``W``."""
    ends = []
    for s, (ia, ib) in zip(design.springs, geom.spring_idx):
        if s.pulley is not None:
            u = np.asarray(s.pulley.spring_direction) / float(np.hypot(*s.pulley.spring_direction))
            run = float(np.max(np.hypot(*(W[:, ib] - W[:, ia]).T)))
            passed = run + 2 * math.pi * pulley_drawn_radius(s.pulley, size)
            ends.append(W[0, ia] + pulley_coil_length(passed, size) * u)
        elif s.cable is not None:
            ends.extend(cable_coil_end(s, [cable_angle(s, w) for w in W[:, ib]]))
    return np.array(ends).reshape(-1, 2)
