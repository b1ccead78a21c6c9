"""Routing a string over a pulley so that it stays on the pulley over the whole range.

A :class:`~balancelab.core.elements.Pulley` fixes where the real spring lies
(``spring_direction``) and the sense in which the string wraps (``turn``). The exact
model (:func:`balancelab.mechanisms.geometry.pulley_string`) measures the wrap angle
``phi`` in ``[0, 2 pi)``: the string comes in along a fixed line, wraps by ``phi`` and
leaves towards the attachment. A real string can only bend round the pulley one way.
When the attachment swings to the side where the string would have to bend the other
way (a negative wrap), the string simply leaves the pulley and the model no longer
holds; in the model this shows as the wrap jumping across ``0 = 2 pi`` (from a few
degrees to nearly a full turn). A routing is *valid* over a range when the wrap never
crosses that cut: ``max(phi) - min(phi) < pi`` (the attachment's direction swings by less
than a half turn whenever the pulley lies outside the attachment's path) and
``max(phi) < 2 pi``. :func:`pulley_routing` keeps a spring's own routing if it is valid
and refuses it otherwise; for a spring without one it picks, among the four axis
directions and both senses, the valid routing with the least largest wrap (the least
string on the pulley, so the least radius error). Layer: methods.
"""
from __future__ import annotations

import math

import numpy as np

from ...core.design import Design
from ...core.elements import Pulley
from ...core.validation import finite_real, positive_int
from ...mechanisms.geometry import pulley_string
from .forces import configurations

__all__ = ["ROUTINGS", "string_wrap", "stays_wrapped", "pulley_routing"]

#: Candidate routings: the spring above, right, below or left of the pulley, either sense.
ROUTINGS = tuple(Pulley(0.0, direction, turn) for direction in ((0.0, 1.0), (1.0, 0.0), (0.0, -1.0), (-1.0, 0.0))
                 for turn in (1, -1))


def string_wrap(design: Design, index: int, routing: Pulley, radius: float = 0.0, n: int = 61) -> np.ndarray:
    """Wrap angle (rad) of spring ``index``'s string over the design's range, for ``routing`` at ``radius`` (m).

    Examples
    --------
    >>> import balancelab as bl
    >>> d = bl.realize.pulley_lever(radius=0.0)
    >>> w = string_wrap(d, 0, d.springs[0].pulley, radius=0.001)
    >>> bool(w.min() >= 0 and w.max() < np.pi)
    True
    """
    radius = finite_real("radius (m)", radius, nonnegative=True)
    n = positive_int("n", n)
    s = design.springs[index]
    if s.a.body != 0:
        raise ValueError(f"spring {s.name or index}: a pulley needs its first attachment on the ground (body 0)")
    q = configurations(design, None, n)
    points = design.world_points(q, [s.b])[..., 0, :]
    return pulley_string(s.a.point, radius, points, routing.spring_direction, routing.turn).wrap


def stays_wrapped(wrap) -> bool:
    """True when the wrap angles (rad) never cross ``0 = 2 pi``: the string stays on the pulley.

    Examples
    --------
    >>> stays_wrapped([1.0, 1.5, 2.0]), stays_wrapped([0.1, 6.1])
    (True, False)
    """
    w = np.asarray(wrap, dtype=float)
    return bool(np.ptp(w) < math.pi and w.max() < 2 * math.pi - 1e-9)


def pulley_routing(design: Design, index: int, radius: float = 0.0, n: int = 61) -> Pulley:
    """A routing of spring ``index``'s string over a pulley of ``radius`` (m) that stays wrapped.

    The spring's own :class:`Pulley` if it has one and it stays wrapped (ValueError if
    it does not); otherwise the valid routing of :data:`ROUTINGS` with the least
    largest wrap.

    Returns
    -------
    Pulley
        With the given ``radius``.

    Raises
    ------
    ValueError
        When the spring's own routing lets the string leave the pulley, or no candidate
        keeps it on.

    Examples
    --------
    >>> import balancelab as bl
    >>> lamp = bl.lecture.serial_2r_base_springs(masses=(1.0, 1.0), length=0.5, coms=((0.25, 0), (0.25, 0)),
    ...                                          b=(0.3, 0.25), c=(0.15, 0.1))
    >>> r = pulley_routing(lamp, 0, n=41)
    >>> r.spring_direction[1] == 0.0         # from the side, the string over the top
    True
    """
    s = design.springs[index]
    own = s.pulley
    if own is not None:
        wrap = string_wrap(design, index, own, radius, n)
        if not stays_wrapped(wrap):
            raise ValueError(f"spring {s.name or index}: with spring_direction {own.spring_direction} and turn "
                             f"{own.turn} the string would have to bend the other way round the pulley (wrap "
                             f"{np.degrees(wrap.min()):.0f}-{np.degrees(wrap.max()):.0f} deg crosses 0 = 360 deg); "
                             f"route it so that the wrap stays in (0, 360) deg")
        return Pulley(radius, own.spring_direction, own.turn)
    best, best_wrap = None, np.inf
    for routing in ROUTINGS:
        wrap = string_wrap(design, index, routing, radius, n)
        if stays_wrapped(wrap) and wrap.max() < best_wrap:
            best, best_wrap = routing, float(wrap.max())
    if best is None:
        raise ValueError(f"spring {s.name or index}: no routing keeps the string on the pulley over the range")
    return Pulley(radius, best.spring_direction, best.turn)
