"""Does the part as cut still balance? The cable recomputed on the exported polyline.

An export writes the profile as a polyline of ``n`` points, not as the curve the synthesis
made. This module recomputes the spring's energy from that polyline alone, without the
profile's series: at each link angle the polyline is carried to the world, the cable's
tangent vertex is the vertex where the line from the eyelet touches the polygon with the
polygon on the wrap's side (the cable turns the wrap's way there, towards the clamp), the
cable's path is that straight line plus the polyline's length from the vertex to the
clamp's end, and the spring's length is that path minus the cable's length. The energy
the rest of the design exchanges along the link's angle plus this spring's energy must vary
by at most a tolerance of what the rest exchanges (by default the balance bound of
:meth:`balancelab.Design.balance_report`, ``1e-9``).

A polyline whose vertices lie on the curve errs in the path by about ``s^2 / r`` (``s`` the
spacing, ``r`` the radius of curvature), so the variation falls as ``1/n^2``; the export
doubles ``n`` until the bound holds (:func:`balancelab.realize.export_profile`).
"""
from __future__ import annotations

import math  # noqa: F401 (the doctests use it)

import numpy as np
from numpy.typing import ArrayLike

from ...core.design import Design
from ...core.frames import rotate
from .profile import NoncircularProfile

__all__ = ["polyline_path", "polyline_variation", "polyline_wrap"]

#: link angles (evenly spaced, both ends included) at which an exported polyline is checked
ANGLES = 501


def polyline_path(points, theta, anchor, clamp, turn: int) -> np.ndarray:
    """The cable's path (m) from the eyelet round a convex polyline fixed to a link, at link angles ``theta``.

    Parameters
    ----------
    points : array_like, shape (n, 2)
        The polyline in the link's frame (m), the link turning about the world origin.
    theta : array_like, shape (m,)
        Link angles (rad).
    anchor : (float, float)
        The eyelet, world frame (m).
    clamp : (float, float)
        The cable's clamped end in the link's frame (m): the polyline's end nearer to it is
        where the cable ends.
    turn : {1, -1}
        The wrap's sense: 1 counter-clockwise (the cable turns left onto the profile).

    Returns
    -------
    numpy.ndarray, shape (m,)
        The straight run plus the wrapped length of :func:`polyline_wrap`.

    Examples
    --------
    A unit circle (2,000 points from -90° to 180°, clamped at (-1, 0)), the eyelet 3 m from its
    centre: the tangent from the eyelet, ``sqrt(8)``, plus the arc from ``acos(1/3)`` to ``pi``:

    >>> phi = np.linspace(-np.pi / 2, np.pi, 2000)
    >>> circle = np.column_stack([np.cos(phi), np.sin(phi)])
    >>> got = float(polyline_path(circle, [0.0], (3.0, 0.0), (-1.0, 0.0), 1)[0])
    >>> round(got, 4), round(math.sqrt(8) + math.pi - math.acos(1 / 3), 4)
    (4.7391, 4.7391)
    """
    straight, wrapped = polyline_wrap(points, theta, anchor, clamp, turn)
    return straight + wrapped


def polyline_wrap(points: ArrayLike, theta: ArrayLike, anchor: ArrayLike, clamp: ArrayLike, turn: int) -> tuple[np.ndarray, np.ndarray]:
    """The cable's straight run from the eyelet and its length wrapped on the polyline (m), at link angles ``theta``.

    The tangent vertex is the vertex where the line from the eyelet touches the polyline with
    the whole polyline on the wrap's side; the cable lies on the polyline from there to the
    clamp's end. A cable that runs straight from the eyelet to the clamp's end wraps 0 m.

    Parameters
    ----------
    points, theta, anchor, clamp, turn
        As in :func:`polyline_path`.

    Returns
    -------
    (numpy.ndarray, numpy.ndarray), each of shape (m,)
        The eyelet-to-tangent-vertex distance and the polyline's length from that vertex to
        the clamp's end.

    Examples
    --------
    The unit circle of :func:`polyline_path`: the tangent ``sqrt(8)``, the arc ``pi - acos(1/3)``
    (to the polyline's accuracy, 2,000 points); the quarter below the x-axis, clamped at (1, 0),
    lies beside the straight line from the eyelet to its clamped end: the cable wraps nothing:

    >>> phi = np.linspace(-np.pi / 2, np.pi, 2000)
    >>> circle = np.column_stack([np.cos(phi), np.sin(phi)])
    >>> straight, wrapped = polyline_wrap(circle, [0.0], (3.0, 0.0), (-1.0, 0.0), 1)
    >>> round(float(straight[0]), 2), round(float(wrapped[0]), 2), round(math.pi - math.acos(1 / 3), 2)
    (2.83, 1.91, 1.91)
    >>> quarter = circle[phi <= 0]
    >>> straight, wrapped = polyline_wrap(quarter, [0.0], (3.0, 0.0), (1.0, 0.0), 1)
    >>> round(float(straight[0]), 4), float(wrapped[0])
    (2.0, 0.0)
    """
    pts = np.asarray(points, dtype=float)
    if np.hypot(*(pts[0] - clamp)) < np.hypot(*(pts[-1] - clamp)):
        pts = pts[::-1]                                   # the clamp's end last
    cum = np.concatenate([[0.0], np.cumsum(np.hypot(*np.diff(pts, axis=0).T))])
    theta = np.atleast_1d(np.asarray(theta, dtype=float))
    straight, wrapped = np.empty(len(theta)), np.empty(len(theta))
    for start in range(0, len(theta), 32):          # 32 angles at a time: (32, n, 2) arrays
        t = theta[start:start + 32, None]
        world = np.stack(rotate(np, t, (pts[:, 0], pts[:, 1])), -1)
        rel = world - np.asarray(anchor, dtype=float)
        # each vertex's direction from the eyelet, as an angle from the first one's (a convex part seen
        # from outside spans less than 180°); the cable touches where the whole part lies on the wrap's
        # side of its line: the smallest angle (counter-clockwise wrap) or the largest (clockwise)
        r0 = rel[:, :1]
        ang = np.arctan2(r0[..., 0] * rel[..., 1] - r0[..., 1] * rel[..., 0], np.sum(r0 * rel, -1))
        vertex = np.argmin(turn * ang, axis=1)
        rows = np.arange(len(t))
        straight[start:start + 32] = np.hypot(*rel[rows, vertex].T)
        wrapped[start:start + 32] = cum[-1] - cum[vertex]
    return straight, wrapped


def _coordinate(design: Design, body: int) -> int:
    """The coordinate that is ``body``'s angle (the synthesis made sure there is one)."""
    q = design.sample(8, seed=1)
    angle = np.asarray(design.poses(q))[:, body, 2]
    return next(i for i in range(design.dof) if np.allclose(angle, q[:, i], rtol=0.0, atol=1e-9))


def polyline_variation(design: Design, spring: int, points) -> float:
    """Energy variation of ``design`` with spring ``spring``'s cable on the polyline ``points`` instead of its curve.

    Over :data:`ANGLES` link angles across the profile's range (the design's other
    coordinates held at the middle of their ranges): ``max E - min E`` divided by what the
    rest of the design exchanges, ``E`` being the rest's energy plus the spring's
    ``k/2 (L - free_length)^2`` with ``L`` from :func:`polyline_path`.

    Parameters
    ----------
    design : Design
        From :func:`balancelab.realize.noncircular_pulley`.
    spring : int
        Index of its spring on a non-circular pulley.
    points : array_like, shape (n, 2)
        The exported polyline, link frame (m).

    Returns
    -------
    float
        The relative variation (0 for a perfect balance).
    """
    s = design.springs[spring]
    prof = s.cable
    if not isinstance(prof, NoncircularProfile):
        raise ValueError(f"{design.name}: spring {spring} is not wound on a non-circular pulley")
    theta = np.linspace(*prof.angle_range, ANGLES)
    coordinate = _coordinate(design, s.b.body)
    q = np.repeat(design.q_range.mean(1)[None, :], ANGLES, axis=0)
    q[:, coordinate] = theta
    rest = design.replace(springs=[x for i, x in enumerate(design.springs) if i != spring])
    v_rest = rest.potential_energy(q).total
    path = polyline_path(points, theta, np.add(prof.pivot, prof.anchor), s.b.point, prof.turn)
    energy = v_rest + 0.5 * s.k * (path - prof.cable_length - s.free_length) ** 2
    return float(np.ptp(energy) / max(float(np.ptp(v_rest)), 1e-300))
