"""The one geometry kernel of the mechanisms: rigid-body points, circle intersections (rotations: core).

Every closed-form loop solution in :mod:`balancelab.mechanisms` places its joints with
these functions; they work on numpy arrays (vectorized over configurations) and, where
noted, on sympy expressions. Methods that write planar vectors as complex numbers
convert with :func:`as_complex` and :func:`as_point`; a pose function built on these
numeric-only tools guards its sympy path with :func:`numeric_only`. :func:`pulley_string`
is the exact path of a string over a round pulley, which both the string-over-pulley
model (:mod:`balancelab.methods.realize`) and the drawing (:mod:`balancelab.viz.springs`) read. :func:`rotate` is the
transform kernel's (:mod:`balancelab.core.frames`), re-exported here. Layer: mechanisms;
imports the input checks and the transform kernel of ``core``.
"""
from __future__ import annotations

import math
from types import ModuleType
from typing import NamedTuple

from numpy.typing import ArrayLike

import numpy as np

from ..core.frames import rotate
from ..core.validation import finite_real, planar_point, real_array

__all__ = ["Point", "rotate", "binary_link_point", "circle_intersection", "as_complex", "as_point",
           "numeric_only", "PulleyString", "pulley_string"]

#: a planar point or vector ``(x, y)`` (m), in type hints
Point = tuple[float, float]


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


def circle_intersection(c0, r0, c1, r1, side=1):
    """Intersection of the circles ``|p - c0| = r0`` and ``|p - c1| = r1`` on one side of ``c0 -> c1``.

    Vectorized: centres may be arrays of shape ``(..., 2)`` given as pairs ``(x, y)`` of
    arrays; radii are numbers. ``side = +1`` takes the point to the left of the
    direction from ``c0`` to ``c1`` (counter-clockwise), ``-1`` the one to the right.

    Parameters
    ----------
    c0, c1 : (array_like, array_like)
        Centres ``(x, y)`` (m).
    r0, r1 : float
        Radii (m), > 0.
    side : {1, -1} or array_like
        Which of the two intersections.

    Returns
    -------
    (x, y, ok)
        The intersection (m) and a boolean mask, false where the circles do not meet (or
        the centres coincide); there ``x``, ``y`` are those of the nearest tangent point.

    Examples
    --------
    >>> x, y, ok = circle_intersection((0.0, 0.0), 1.0, (1.0, 0.0), 1.0)
    >>> round(float(x), 12), round(float(y), 12), bool(ok)
    (0.5, 0.866025403784, True)
    """
    dx, dy = np.subtract(c1[0], c0[0]), np.subtract(c1[1], c0[1])
    d = np.hypot(dx, dy)
    ds = np.where(d > 0, d, 1.0)
    a = (r0 * r0 - r1 * r1 + d * d) / (2 * ds)
    ok = (d > 0) & (np.abs(a) <= r0 * (1 + 1e-12))
    h = np.sqrt(np.clip(r0 * r0 - a * a, 0.0, None))
    ux, uy = dx / ds, dy / ds
    return c0[0] + a * ux - side * h * uy, c0[1] + a * uy + side * h * ux, ok


def as_complex(point: Point | complex) -> complex:
    """A planar point or vector ``(x, y)`` as the complex number ``x + i y``.

    Parameters
    ----------
    point : (float, float) or complex
        Coordinates (m); a complex number is returned unchanged.

    Returns
    -------
    complex

    Examples
    --------
    >>> as_complex((0.3, -0.2))
    (0.3-0.2j)
    """
    if isinstance(point, (complex, np.complexfloating)):
        value = complex(point)
        if not (math.isfinite(value.real) and math.isfinite(value.imag)):
            raise ValueError(f"point must be finite, got {value}")
        return value
    x, y = planar_point("point", point)
    return complex(x, y)


def as_point(value: complex) -> tuple[float, float]:
    """A complex number as a point ``(x, y)`` of floats; round-off below 1e-15 m becomes an exact zero.

    Parameters
    ----------
    value : complex
        ``x + i y`` (m).

    Returns
    -------
    (float, float)

    Examples
    --------
    >>> as_point(0.25 + 1e-17j)
    (0.25, 0.0)
    """
    x, y = float(value.real), float(value.imag)
    return (0.0 if abs(x) < 1e-15 else x, 0.0 if abs(y) < 1e-15 else y)


def numeric_only(lib: ModuleType) -> None:
    """Refuse the sympy path of a pose function built on numeric-only geometry.

    A pose function of :class:`balancelab.mechanisms.base.ExplicitKinematics` receives
    the math library ``lib`` (numpy or sympy); one that uses complex arithmetic or
    :func:`circle_intersection` calls this first, so a symbolic request raises a clear
    ``NotImplementedError`` (the design's energy is then checked numerically).

    Parameters
    ----------
    lib : module
        ``numpy`` passes; anything else raises.

    Raises
    ------
    NotImplementedError
        If ``lib`` is not numpy.

    Examples
    --------
    >>> numeric_only(np)
    >>> import sympy
    >>> numeric_only(sympy)  # doctest: +ELLIPSIS
    Traceback (most recent call last):
    ...
    NotImplementedError: this design's kinematics is numeric only; ...
    """
    if lib is not np:
        raise NotImplementedError("this design's kinematics is numeric only; its energy is checked "
                                  "numerically by balance_report()")


# ------------------------------------------------------------------------ a string over a pulley
class PulleyString(NamedTuple):
    """Geometry of a string over a pulley (arrays over configurations).

    ``tangent_in`` and ``tangent_out`` (..., 2): where the string meets and leaves the
    pulley (m); ``wrap`` the wrap angle (rad); ``free`` the straight part from the
    pulley to the attachment (m); ``passed_over`` = ``radius * wrap + free`` (m).
    """

    tangent_in: np.ndarray
    tangent_out: np.ndarray
    wrap: np.ndarray
    free: np.ndarray
    passed_over: np.ndarray


def pulley_string(center: ArrayLike, radius: float, point: ArrayLike, spring_direction: ArrayLike = (0.0, 1.0),
                  turn: int = 1) -> PulleyString:
    """Exact geometry of a string coming from a spring, over a pulley, to ``point``.

    The string arrives parallel to ``-spring_direction`` (the spring lies on the side
    ``spring_direction`` of the pulley), touches the pulley at the fixed point where its
    line is tangent, wraps round it counter-clockwise (``turn = 1``) or clockwise
    (``turn = -1``) and leaves along the tangent through ``point``.

    Parameters
    ----------
    center : (float, float)
        Pulley centre (m).
    radius : float
        Pulley radius (m), >= 0 (0 gives the ideal point anchor).
    point : array_like, shape (..., 2)
        Attachment point(s) of the string on the moving link (m); each must be farther
        than ``radius`` from the centre.
    spring_direction : (float, float)
        Direction from the pulley towards the spring (any length).
    turn : {1, -1}
        Sense of wrapping.

    Returns
    -------
    PulleyString

    Examples
    --------
    >>> s = pulley_string((0, 0), 0.01, [0.0, -0.5])
    >>> round(float(s.passed_over), 6), round(float(s.wrap), 6)
    (0.5001, 0.020001)
    """
    c = complex(*planar_point("center", center))
    radius = finite_real("radius (m)", radius, nonnegative=True)
    sd = complex(*planar_point("spring_direction", spring_direction))
    if sd == 0:
        raise ValueError("spring_direction must be non-zero")
    if turn not in (1, -1):
        raise ValueError(f"turn must be +1 or -1, got {turn!r}")
    p = real_array("point (attachment on the moving link, m)", point)
    if p.ndim == 0 or p.shape[-1] != 2:
        raise ValueError(f"point must have shape (..., 2), got {p.shape}")
    if not np.all(np.isfinite(p)):
        raise ValueError("point (attachment on the moving link, m) must be finite")
    rel = p[..., 0] + 1j * p[..., 1] - c
    d = np.abs(rel)
    if np.any(d <= radius):
        raise ValueError("the attachment point comes within the pulley's radius of its centre")
    g = -sd / abs(sd)  # travel direction of the incoming string
    psi_in = np.angle(g) - turn * math.pi / 2
    free = np.sqrt(d * d - radius * radius)
    psi_out = np.angle(rel) - turn * np.arctan2(free, radius)
    wrap = np.mod(turn * (psi_out - psi_in), 2 * math.pi)
    wrap = np.where(wrap > 2 * math.pi - 1e-12, 0.0, wrap)
    t_in = c + radius * np.exp(1j * psi_in)
    t_out = c + radius * np.exp(1j * psi_out)
    passed = radius * wrap + free
    tin = np.empty(d.shape + (2,))
    tin[..., 0], tin[..., 1] = t_in.real, t_in.imag
    return PulleyString(tin, np.stack([t_out.real, t_out.imag], -1), wrap, free, passed)
