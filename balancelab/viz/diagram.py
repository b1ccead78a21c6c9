"""Labelled diagrams: a design drawn with named points, dimension lines and angle arcs.

A chapter that explains a construction (the lecture's triangle, a balancer's points P, N
and D, a focal pivot) needs the picture a teacher would draw on the board, with the same
letters as the text. :func:`diagram` draws the design with :func:`~balancelab.viz.draw`
and adds

* named points (a design's own ``labels`` or any ``{name: (body, local point)}``),
  placed so that labels do not sit on each other;
* dimension lines between named points, with their symbol at the midpoint;
* angle arcs at a named vertex, from a reference direction or point to another point.

Every position comes from :func:`point_positions`, which reads the design's own poses,
so the diagram cannot disagree with the numbers computed from the same design. Layer: viz.
"""
from __future__ import annotations

import math
from collections.abc import Iterable, Mapping

import numpy as np

from ..core.design import Design
from ..core.kinematics import body_to_world
from ..core.validation import body_index, planar_point
from .drawing import draw
from .frame import STYLE, as_config, check_design, new_axes

__all__ = ["diagram", "point_positions"]

#: Reference directions an angle may be measured from, by name.
DIRECTIONS = {"+x": 0.0, "-x": math.pi, "+y": math.pi / 2, "-y": -math.pi / 2}


def _checked_points(design: Design, points) -> dict[str, tuple[int, tuple[float, float]]]:
    """``{name: (body, point)}`` validated against the design (default: its labels)."""
    if points is None:
        points = design.labels
    if not isinstance(points, Mapping):
        raise TypeError(f"points must be a mapping of name to (body, (x, y)), got {type(points).__name__}")
    out = {}
    for name, spec in points.items():
        if not isinstance(name, str) or not name:
            raise TypeError(f"points: every name must be a non-empty string, got {name!r}")
        if not isinstance(spec, (tuple, list)) or len(spec) != 2:
            raise ValueError(f"points[{name!r}] must be (body, (x, y)), got {spec!r}")
        body = body_index(f"points[{name!r}] body", spec[0], design.kinematics.nbodies)
        out[name] = (body, planar_point(f"points[{name!r}] point", spec[1]))
    return out


def point_positions(design: Design, q=None, points=None) -> dict[str, np.ndarray]:
    """World positions (m) of named points of a design in one configuration.

    Parameters
    ----------
    design : Design
        Any design of the course.
    q : array_like, shape (dof,), optional
        Configuration (rad); the design's default configuration when omitted.
    points : mapping of str to (int, (float, float)), optional
        Name -> (body, point in that body's frame, m). The design's ``labels`` by default.

    Returns
    -------
    dict of str to numpy.ndarray, shape (2,)
        World position of every named point (m).

    Examples
    --------
    >>> import balancelab as bl
    >>> d = bl.singh.lacoste_lever(weight=10.0, length=0.5, a_x=0.2, b_y=0.3)
    >>> {k: v.round(3).tolist() for k, v in point_positions(d, [0.0]).items()}["p"]
    [0.5, 0.0]
    """
    check_design(design)
    named = _checked_points(design, points)
    if not named:
        return {}
    q = as_config(design, q)
    bodies = np.array([b for b, _ in named.values()], dtype=int)
    local = np.array([p for _, p in named.values()], dtype=float).reshape(-1, 2)
    x, y = body_to_world(design.poses(q), bodies, local)
    return {name: np.array([x[i], y[i]], dtype=float) for i, name in enumerate(named)}


def _label_offsets(pos: dict[str, np.ndarray], scale: float) -> dict[str, np.ndarray]:
    """Unit directions (display) that push each label away from the others' centre and each other."""
    names = list(pos)
    P = np.array([pos[n] for n in names]).reshape(-1, 2)
    centre = P.mean(axis=0) if len(P) else np.zeros(2)
    dirs = {}
    for i, n in enumerate(names):
        d = P[i] - centre
        near = [P[j] - P[i] for j in range(len(P)) if j != i and np.hypot(*(P[j] - P[i])) < 0.15 * scale]
        if near:                      # crowded: point away from the crowd instead of the centre
            d = -np.sum(near, axis=0)
        norm = float(np.hypot(*d))
        dirs[n] = d / norm if norm > 1e-12 * max(scale, 1e-300) else np.array([0.0, 1.0])
    return dirs


def _dimension(ax, p, r, text: str, scale: float) -> None:
    """A thin double-headed line from ``p`` to ``r`` beside the segment, ``text`` at its middle."""
    p, r = np.asarray(p, float), np.asarray(r, float)
    t = r - p
    length = float(np.hypot(*t))
    if length == 0.0:
        raise ValueError(f"lengths: the two points of {text!r} coincide in this configuration")
    n = np.array([-t[1], t[0]]) / length
    off = 0.06 * scale * n
    ax.annotate("", xy=r + off, xytext=p + off,
                arrowprops=dict(arrowstyle="<->", color=STYLE["label"], lw=0.8, shrinkA=0, shrinkB=0))
    mid = (p + r) / 2 + 1.9 * off
    ax.text(mid[0], mid[1], text, ha="center", va="center", fontsize=11, color=STYLE["label"],
            bbox=dict(boxstyle="round,pad=0.1", fc="white", ec="none", alpha=0.8))


def _direction(spec, vertex: np.ndarray, pos: dict[str, np.ndarray], what: str) -> float:
    """Angle (rad) of a reference: a named point seen from ``vertex`` or one of DIRECTIONS."""
    if spec in DIRECTIONS:
        return DIRECTIONS[spec]
    if spec not in pos:
        raise ValueError(f"angles: {what} {spec!r} is neither a named point ({sorted(pos)}) "
                         f"nor a direction ({sorted(DIRECTIONS)})")
    d = pos[spec] - vertex
    return math.atan2(d[1], d[0])


def _arc(ax, vertex, start: float, stop: float, text: str, radius: float) -> None:
    """A counter-clockwise arc at ``vertex`` from angle ``start`` to ``stop`` (rad), labelled."""
    sweep = (stop - start) % (2 * math.pi)
    if sweep > math.pi:                           # draw the smaller of the two angles
        start, sweep = stop, 2 * math.pi - sweep
    t = np.linspace(start, start + sweep, 40)
    ax.plot(vertex[0] + radius * np.cos(t), vertex[1] + radius * np.sin(t), color=STYLE["label"], lw=0.9)
    mid = start + sweep / 2
    ax.text(vertex[0] + 1.45 * radius * math.cos(mid), vertex[1] + 1.45 * radius * math.sin(mid), text,
            ha="center", va="center", fontsize=11, color=STYLE["label"])


def diagram(design: Design, q=None, *, points: Mapping | None = None,
            lengths: Iterable[tuple[str, str, str]] = (),
            angles: Iterable[tuple[str, str, str, str]] = (), ax=None, title: bool | str = True):
    """Draw a design as a labelled diagram: named points, dimension lines and angle arcs.

    Parameters
    ----------
    design : Design
        Any design of the course.
    q : array_like, shape (dof,), optional
        Configuration (rad); the design's default configuration when omitted.
    points : mapping of str to (int, (float, float)), optional
        Points to name: name -> (body, point in the body's frame, m). The design's
        ``labels`` by default.
    lengths : iterable of (str, str, str)
        Dimension lines ``(from_point, to_point, symbol)`` between named points.
    angles : iterable of (str, str, str, str)
        Angle arcs ``(vertex, reference, to_point, symbol)``: the angle at the named
        ``vertex`` from ``reference`` (a named point, or ``"+x"``, ``"-x"``, ``"+y"``,
        ``"-y"``) to the named ``to_point``; the smaller of the two angles is drawn.
    ax : matplotlib.axes.Axes, optional
        Axes to draw on; a new figure by default.
    title : bool or str
        As in :func:`~balancelab.viz.draw`.

    Returns
    -------
    matplotlib.axes.Axes
        The Axes; ``ax.drawing`` is the design's :class:`~balancelab.viz.Drawing` and
        ``ax.positions`` the world positions (m) of the named points.

    Raises
    ------
    ValueError
        If a length or angle names a point that is not among ``points``.

    Examples
    --------
    >>> import balancelab as bl
    >>> d = bl.singh.lacoste_lever(weight=10.0, length=0.5, a_x=0.2, b_y=0.3)
    >>> ax = diagram(d, [0.6], points={"O": (0, (0.0, 0.0)), "B": (0, (0.0, 0.3)),
    ...                                "A": (1, (0.2, 0.0))},
    ...              lengths=[("O", "B", "$b$"), ("O", "A", "$a$")], angles=[("O", "+x", "A", r"$\\theta$")])
    >>> sorted(ax.positions)
    ['A', 'B', 'O']
    """
    check_design(design)
    pos = point_positions(design, q, points)
    lengths, angles = list(lengths), list(angles)
    for spec in lengths:
        if len(spec) != 3:
            raise ValueError(f"lengths: each item must be (from_point, to_point, symbol), got {spec!r}")
        for name in spec[:2]:
            if name not in pos:
                raise ValueError(f"lengths: {name!r} is not a named point ({sorted(pos)})")
    for angle in angles:
        if len(angle) != 4 or angle[0] not in pos or (angle[2] not in pos):
            raise ValueError(f"angles: each item must be (vertex, reference, to_point, symbol) with named "
                             f"vertex and to_point ({sorted(pos)}), got {angle!r}")
    ax = draw(design, q, ax=new_axes(ax), labels=False, title=title)
    P = np.array(list(pos.values())).reshape(-1, 2)
    scale = max(float(np.ptp(P, axis=0).max()) if len(P) > 1 else 0.0, 0.5 * float(ax.drawing.size))
    scale = scale if scale > 0 else 1.0
    for name, d in _label_offsets(pos, scale).items():
        ax.plot(*pos[name], "o", ms=4, color=STYLE["label"], zorder=6)
        ax.annotate(name, pos[name], xytext=(11 * d[0], 11 * d[1]), textcoords="offset points",
                    ha="center", va="center", fontsize=12, fontweight="bold", color=STYLE["label"], zorder=7)
    for a, b, text in lengths:
        _dimension(ax, pos[a], pos[b], text, scale)
    for vertex, ref, to, text in angles:
        v = pos[vertex]
        start = _direction(ref, v, pos, "reference")
        stop = _direction(to, v, pos, "to_point")
        _arc(ax, v, start, stop, text, 0.12 * scale)
    ax.positions = pos
    return ax
