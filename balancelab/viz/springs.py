"""How a spring is drawn: a coil, a gas spring, or a string over a pulley to a coil.

The shape follows the spring's ``realization``. A spring realized by a pulley
(``spring.pulley``, a :class:`balancelab.core.elements.Pulley`) is drawn from the same
object the exact string model reads (:func:`balancelab.mechanisms.geometry.pulley_string`):
the string leaves the attachment on the tangent to the pulley, wraps round it in the
pulley's sense and runs on to a coil on the pulley's ``spring_direction`` side, so the
picture cannot put the spring where the model does not.

Layer: viz; imports ``balancelab.core`` and ``balancelab.mechanisms``.
"""
from __future__ import annotations

import math
from typing import Any

import numpy as np

from ..core.elements import CablePath, Pulley, Spring
from ..mechanisms.geometry import pulley_string
from .frame import STYLE

__all__ = ["cable_angle", "cable_coil_end", "cable_coil_ends", "cable_path", "coil_path", "gas_path", "profile_outline",
           "pulley_coil_length", "pulley_drawn_radius", "pulley_path", "spring_path", "spring_style"]


def _profile(spring: Spring) -> Any:
    """The non-circular pulley of a cable spring (a ``realize.NoncircularProfile``: viz does not import
    realize), or a TypeError naming the spring."""
    prof = spring.cable
    if not isinstance(prof, CablePath) or not hasattr(prof, "local_points"):
        raise TypeError(f"spring {spring.name or spring}: its realization must be a NoncircularProfile to be "
                        f"drawn as a cable, got {type(spring.realization).__name__}")
    return prof


def coil_path(a, b, width: float, turns: int = 7, lead: float = 0.15):
    """Polyline (x, y) of a zig-zag coil from ``a`` to ``b`` with straight leads.

    Parameters
    ----------
    a, b : array_like, shape (2,)
        End points (m).
    width : float
        Half-width of the zig-zag (m); at most 35 % of the length is used.
    turns : int
        Number of zig-zags.
    lead : float
        Fraction of the length taken by each straight lead.

    Returns
    -------
    (numpy.ndarray, numpy.ndarray)
        x and y (m), starting at ``a`` and ending at ``b``.

    Examples
    --------
    >>> x, y = coil_path(np.array([0.0, 0.0]), np.array([1.0, 0.0]), 0.1, turns=2)
    >>> x[[0, -1]].tolist(), float(np.abs(y).max())
    ([0.0, 1.0], 0.1)
    """
    a, b = np.asarray(a, dtype=float), np.asarray(b, dtype=float)
    d = b - a
    length = float(np.hypot(*d))
    if length < 1e-12:
        return np.array([a[0], b[0]]), np.array([a[1], b[1]])
    u = d / length
    n = np.array([-u[1], u[0]])
    s = np.concatenate([[0.0], lead + (1 - 2 * lead) * np.linspace(0, 1, 2 * turns + 1), [1.0]])
    w = np.zeros_like(s)
    w[2:-2:2] = 1.0
    w[3:-2:2] = -1.0
    w = w * min(width, 0.35 * length)
    pts = a[None, :] + s[:, None] * length * u[None, :] + w[:, None] * n[None, :]
    return pts[:, 0], pts[:, 1]


def gas_path(a, b, width: float):
    """Polyline (x, y) of a gas spring from ``a`` to ``b``: a cylinder at ``a``, a rod to ``b``.

    Parameters
    ----------
    a, b : array_like, shape (2,)
        End points (m): the cylinder's base and the rod's end.
    width : float
        Half-width of the cylinder (m).

    Returns
    -------
    (list, list)
        x and y (m); a NaN separates the cylinder from the rod.

    Examples
    --------
    >>> x, y = gas_path([0.0, 0.0], [1.0, 0.0], 0.1)
    >>> x[-1], y[-1]
    (1.0, 0.0)
    """
    a, b = np.asarray(a, dtype=float), np.asarray(b, dtype=float)
    m = a + 0.55 * (b - a)
    u = b - a
    nrm = np.array([-u[1], u[0]]) / max(float(np.hypot(*u)), 1e-12) * width
    xs = [a[0] + nrm[0], m[0] + nrm[0], m[0] - nrm[0], a[0] - nrm[0], a[0] + nrm[0], np.nan, m[0], b[0]]
    ys = [a[1] + nrm[1], m[1] + nrm[1], m[1] - nrm[1], a[1] - nrm[1], a[1] + nrm[1], np.nan, m[1], b[1]]
    return [float(v) for v in xs], [float(v) for v in ys]


def pulley_drawn_radius(pulley: Pulley, size: float) -> float:
    """Radius (m) at which a pulley is drawn: its own, but at least 3 % of the picture's ``size``.

    Parameters
    ----------
    pulley : Pulley
    size : float
        Size of the mechanism's picture (m).

    Returns
    -------
    float

    Examples
    --------
    >>> pulley_drawn_radius(Pulley(0.05), 1.0), pulley_drawn_radius(Pulley(0.0), 1.0)
    (0.05, 0.03)
    """
    return max(pulley.radius, 0.03 * float(size))


def pulley_coil_length(passed_over, size: float):
    """How far from the pulley (m) the drawn coil of a pulley spring ends.

    The coil starts a quarter of the way out and lengthens with the passed-over length
    of string (the spring's extension in the model).

    Parameters
    ----------
    passed_over : float or array_like
        Passed-over length of string (m).
    size : float
        Size of the mechanism's picture (m).

    Returns
    -------
    float or numpy.ndarray

    Examples
    --------
    >>> round(float(pulley_coil_length(0.4, 1.0)), 3)
    0.24
    """
    return 0.12 * size + 0.3 * np.asarray(passed_over, dtype=float)[()]


def pulley_path(pulley: Pulley, centre, point, radius: float, size: float):
    """Polyline (x, y) of a string from ``point`` over a pulley at ``centre`` to its spring.

    The string leaves ``point`` on the tangent to the pulley (drawn with radius
    ``radius``), wraps round it back to where it arrives from the spring, and runs along
    ``pulley.spring_direction`` to a coil whose length grows with the passed-over length
    of string. When ``point`` is inside the drawn pulley the string runs straight to the
    centre.

    Parameters
    ----------
    pulley : Pulley
        The spring's realization (its side and sense of wrapping are used).
    centre, point : array_like, shape (2,)
        Pulley centre and the string's attachment on the moving link (m).
    radius : float
        Drawn radius (m), see :func:`pulley_drawn_radius`.
    size : float
        Size of the mechanism's picture (m), which scales the coil.

    Returns
    -------
    (numpy.ndarray, numpy.ndarray)
        x and y (m): ``point``, the tangent point where the string leaves the pulley,
        the arc, then the coil.

    Examples
    --------
    >>> x, y = pulley_path(Pulley(0.1), [0.0, 0.0], [0.0, -1.0], 0.1, 1.0)
    >>> bool(y[-1] > 0.1)  # the coil is above the pulley, where the spring is
    True
    """
    centre = np.asarray(centre, dtype=float)
    point = np.asarray(point, dtype=float)
    u = np.asarray(pulley.spring_direction, dtype=float)
    u = u / float(np.hypot(*u))
    try:
        s = pulley_string(centre, radius, point, pulley.spring_direction, pulley.turn)
        t_in, t_out, wrap, passed = s.tangent_in, s.tangent_out, float(s.wrap), float(s.passed_over)
    except ValueError:  # the attachment is inside the drawn pulley
        t_in = t_out = centre
        wrap, passed, radius = 0.0, float(np.hypot(*(point - centre))), 0.0
    psi_out = math.atan2(t_out[1] - centre[1], t_out[0] - centre[0])
    psi = psi_out - pulley.turn * np.linspace(0.0, wrap, max(2, int(wrap / (math.pi / 16)) + 2))
    arc_x, arc_y = centre[0] + radius * np.cos(psi), centre[1] + radius * np.sin(psi)
    drop = pulley_coil_length(passed, size)
    cx, cy = coil_path(t_in + 0.25 * drop * u, t_in + drop * u, 0.02 * size)
    return np.concatenate([[point[0]], arc_x, cx]), np.concatenate([[point[1]], arc_y, cy])


def spring_style(spring: Spring) -> tuple:
    """Colour and line style of a spring: solid for ZFL, dashed for a free length, black string.

    Parameters
    ----------
    spring : Spring

    Returns
    -------
    (str, str or tuple)
        A colour of :data:`~balancelab.viz.frame.STYLE` and a matplotlib line style.

    Examples
    --------
    >>> spring_style(Spring(1.0, 0.0, (0, (0, 0)), (1, (1, 0))))
    ('#D55E00', '-')
    """
    if spring.pulley is not None or spring.cable is not None:
        return STYLE["string"], "-"
    if spring.is_zfl:
        return STYLE["zfl"], "-"
    return STYLE["spring"], (0, (3, 1.5))


def spring_path(spring: Spring, pa, pb, size: float, pulley_radius: float | None = None):
    """Polyline (x, y) of a spring whose attachments are at ``pa`` and ``pb`` (m).

    A coil from ``pa`` to ``pb`` (more turns when longer), a gas spring, or, for a
    spring realized by a pulley, :func:`pulley_path` from ``pb`` over the pulley
    centred at ``pa``.

    Parameters
    ----------
    spring : Spring
    pa, pb : array_like, shape (2,)
        World positions of the attachments ``a`` and ``b`` (m).
    size : float
        Size of the mechanism's picture (m).
    pulley_radius : float, optional
        Drawn pulley radius (m); :func:`pulley_drawn_radius` by default.

    Returns
    -------
    (array_like, array_like)

    Examples
    --------
    >>> s = Spring(1.0, 0.0, (0, (0, 0)), (1, (1, 0)))
    >>> x, y = spring_path(s, [0.0, 0.0], [1.0, 0.0], 1.0)
    >>> float(x[0]), float(x[-1])
    (0.0, 1.0)
    """
    pa, pb = np.asarray(pa, dtype=float), np.asarray(pb, dtype=float)
    if spring.cable is not None:
        return cable_path(spring, cable_angle(spring, pb), size)
    pulley = spring.pulley
    if pulley is not None:
        radius = pulley_drawn_radius(pulley, size) if pulley_radius is None else pulley_radius
        return pulley_path(pulley, pa, pb, radius, size)
    if spring.realization == "gas":
        return gas_path(pa, pb, 0.025 * size)
    length = float(np.hypot(*(pb - pa)))
    turns = int(np.clip(round(length / (0.035 * size)), 2, 8))
    return coil_path(pa, pb, 0.025 * size, turns=turns)


# ------------------------------------------------------------ non-circular pulley
def cable_angle(spring: Spring, pb) -> float:
    """The link angle (rad) at which a cable spring's clamp ``b`` is at the world point ``pb`` (m).

    Examples
    --------
    >>> import math, balancelab as bl
    >>> from balancelab.methods.practice.springs import ExtensionSpring
    >>> d = bl.realize.noncircular_pulley(bl.lecture.single_link_spring(2.0, 0.5, 0.3, 0.2),
    ...     spring_model=ExtensionSpring(3e-3, 24e-3, 60, initial_tension=40.0), angle_range=(-1.0, 1.0),
    ...     min_tension=45.0)
    >>> s = d.springs[0]
    >>> round(cable_angle(s, d.world_points(0.4, [s.b])[0]), 12)
    0.4
    """
    prof = _profile(spring)
    local = np.asarray(spring.b.point, dtype=float)
    rel = np.asarray(pb, dtype=float) - np.asarray(prof.pivot)
    angle = math.atan2(rel[1], rel[0]) - math.atan2(local[1], local[0])
    return float(np.angle(np.exp(1j * angle)))


def cable_coil_ends(spring: Spring, theta) -> tuple[np.ndarray, np.ndarray]:
    """The drawn coil of a cable spring at link angles ``theta`` (rad): its fixed end and its hook end (m).

    The coil has the spring's true length, the cable's path minus the cable's length, and lies
    on the line from the pivot through the eyelet. Its far end is fixed at the profile's
    ``spring_anchor`` (the design's ``parameters['spring_anchor']``) and its hook end,
    that length nearer the eyelet, pulls the cable; a hand-built profile without an anchor
    distance gets its coil from the eyelet outwards instead.

    Returns
    -------
    (numpy.ndarray, numpy.ndarray)
        The fixed end and the hook end, each shape ``theta.shape + (2,)`` (m, world frame).

    Examples
    --------
    >>> import math, balancelab as bl
    >>> from balancelab.methods.practice.springs import ExtensionSpring
    >>> d = bl.realize.noncircular_pulley(bl.lecture.single_link_spring(2.0, 0.5, 0.3, 0.2),
    ...     spring_model=ExtensionSpring(3e-3, 24e-3, 60, initial_tension=40.0), angle_range=(-1.0, 1.0),
    ...     min_tension=45.0)
    >>> fixed, hook = cable_coil_ends(d.springs[0], 0.2)
    >>> bool(np.allclose(fixed, d.parameters["spring_anchor"]))
    True
    """
    prof = _profile(spring)
    length = np.asarray(prof.cable(theta).path - prof.cable_length)[..., None]
    eyelet = np.add(prof.pivot, prof.anchor)
    if prof.spring_anchor is None:
        return eyelet + length * prof.direction, np.broadcast_to(eyelet, length.shape[:-1] + (2,))
    fixed = np.broadcast_to(np.asarray(prof.spring_anchor), length.shape[:-1] + (2,))
    return fixed, fixed - length * prof.direction


def cable_coil_end(spring: Spring, theta) -> np.ndarray:
    """The fixed (far) end of the drawn coil of a cable spring (m), shape ``theta.shape + (2,)``.

    The farthest the drawing reaches beyond the eyelet; see :func:`cable_coil_ends`.
    """
    return cable_coil_ends(spring, theta)[0]


def profile_outline(spring: Spring, theta, n: int = 120):
    """Closed polyline (x, y) of a cable spring's non-circular pulley at link angle ``theta`` (rad).

    The profile's points come from the design (``spring.cable``), carried to the world.
    """
    prof = _profile(spring)
    pts = prof.world(theta, prof.local_points(np.linspace(-1.0, 1.0, n)))
    hub = prof.world(theta, np.zeros((1, 2)))
    closed = np.concatenate([pts, hub, pts[:1]])
    return closed[:, 0], closed[:, 1]


def cable_path(spring: Spring, theta: float, size: float):
    """Polyline (x, y) of a spring whose cable wraps a non-circular pulley, at link angle ``theta`` (rad).

    From the coil's fixed end (the spring's anchor, :func:`cable_coil_ends`) along the coil,
    at the spring's true length, to its hook end, the cable on to the eyelet, then its
    straight part to the tangent point on the profile and the wrapped arc to the clamp, all
    from the design's cable geometry (``spring.cable.cable(theta)``).

    Examples
    --------
    >>> import math, balancelab as bl
    >>> from balancelab.methods.practice.springs import ExtensionSpring
    >>> d = bl.realize.noncircular_pulley(bl.lecture.single_link_spring(2.0, 0.5, 0.3, 0.2),
    ...     spring_model=ExtensionSpring(3e-3, 24e-3, 60, initial_tension=40.0), angle_range=(-1.0, 1.0),
    ...     min_tension=45.0)
    >>> x, y = cable_path(d.springs[0], 0.3, 1.0)
    >>> bool(np.allclose([x[-1], y[-1]], d.world_points(0.3, [d.springs[0].b])[0]))
    True
    """
    prof = _profile(spring)
    cab = prof.cable(theta)
    eyelet = np.add(prof.pivot, prof.anchor)
    fixed, hook = cable_coil_ends(spring, theta)
    cx, cy = coil_path(fixed, hook, 0.02 * size, turns=6)
    x = np.linspace(float(cab.parameter), prof.end_parameter, 60)
    arc = prof.world(theta, prof.local_points(x))
    return (np.concatenate([cx, [eyelet[0], cab.tangent[0]], arc[:, 0]]),
            np.concatenate([cy, [eyelet[1], cab.tangent[1]], arc[:, 1]]))
