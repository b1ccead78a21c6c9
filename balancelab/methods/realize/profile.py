"""The non-circular pulley's profile: a convex curve given by its support function, and the cable on it.

A cable runs from a fixed eyelet ``A`` (on the ground) straight to a profile fixed to a link
that turns about a ground pivot ``O``, touches it tangentially at ``T`` and lies on it up to
its clamped end ``E``. In the link's frame the cable's line is the tangent of the profile
with outward normal ``n(psi) = (cos psi, sin psi)``; its distance from the pivot is the
*support function* ``h(psi)``, and the profile is the envelope of these lines::

    x(psi) = h n + h' t,        t = (-sin psi, cos psi),     radius of curvature = h + h''.

The cable wraps counter-clockwise (towards larger ``psi``) in a *canonical* frame; a
clockwise wrap is the mirror image (``y -> -y`` and every angle negated), which is how
``turn = -1`` is handled. Along the curve the arc length is ``S(psi) = H(psi) + h'(psi)``
with ``H = int h dpsi``; the cable's path from the eyelet is the straight tangent
``lambda = rho sin(beta) + h'`` plus the wrapped arc ``S(psi_E) - S(psi)``, where
``beta = psi + theta - alpha`` is the angle between the line's world normal and the
eyelet's direction ``alpha`` (distance ``rho`` from the pivot), and the tangency condition
is ``rho cos(beta) = h(psi)``. This module holds the geometry only: the synthesis that
makes the torque balance is :mod:`balancelab.methods.realize.noncircular`.

``h`` and ``psi`` are Chebyshev series in ``x`` in ``[-1, 1]``, the profile's parameter, which
maps to the link angle ``mid + half x`` at which that point is the tangent point; derivatives
and integrals are exact operations on the series.
"""
from __future__ import annotations

import math
from typing import NamedTuple

import numpy as np
from numpy.polynomial import chebyshev as cheb

from ...core.elements import CablePath
from ...core.errors import ProfileError
from ...core.frames import place, turn

__all__ = ["CableGeometry", "NoncircularProfile", "ProfileError"]

#: how far (in the profile's parameter, 1 = half the range) the tangent point may leave the
#: profile before the model refuses: the step of a numerical derivative at the range's ends
_EDGE = 1e-5


class CableGeometry(NamedTuple):
    """The cable at link angles ``theta`` (arrays; points shape (..., 2), world frame, m).

    ``tangent``: where the cable meets the profile; ``end``: its clamped end ``E``;
    ``anchor``: the eyelet; ``straight``: eyelet to tangent point (m); ``wrapped``: arc
    on the profile (m); ``path``: their sum; ``parameter``: the profile parameter of the
    tangent point, in ``[-1, 1]``.
    """

    tangent: np.ndarray
    end: np.ndarray
    anchor: np.ndarray
    straight: np.ndarray
    wrapped: np.ndarray
    path: np.ndarray
    parameter: np.ndarray


class NoncircularProfile(CablePath):
    """A convex profile fixed to a link, and a cable from a fixed eyelet wound on it.

    Parameters
    ----------
    h, psi : array_like
        Chebyshev coefficients (in the parameter ``x`` in ``[-1, 1]``) of the support
        function (m) and of the normal angle (rad), in the canonical frame.
    angle_range : (float, float)
        Link angles (rad) ``x = -1`` and ``x = 1`` stand for.
    anchor : (float, float)
        The eyelet, world frame relative to the pivot (m).
    pivot : (float, float)
        The link's ground pivot, world frame (m).
    turn : {1, -1}
        1: the cable wraps counter-clockwise round the profile; -1: clockwise.
    cable_length : float
        The path's length minus the spring's length (m): the cable from the spring's end
        to the clamp ``E`` less the spring's anchor distance beyond the eyelet (the design's
        ``parameters`` give both, ``cable_length`` and ``anchor_distance``).
    anchor_distance : float, optional
        How far (m, > 0) beyond the eyelet, on the line from the pivot through it, the
        spring's far end is fixed to the ground (:attr:`spring_anchor`); ``None`` when not
        known (a hand-built profile): the spring is then drawn beyond the eyelet.

    Examples
    --------
    A circular pulley of radius 2 cm centred on the pivot is the profile with ``h = 0.02``;
    with the eyelet 0.3 m above the pivot, ``psi = pi/2 + acos(0.02/0.3) - theta``:

    >>> psi0 = math.pi / 2 + math.acos(0.02 / 0.3)
    >>> p = NoncircularProfile([0.02], [psi0, -1.0], (-1.0, 1.0), (0.0, 0.3), (0.0, 0.0), 1, 0.0)
    >>> round(float(p.radius_of_curvature(np.linspace(-1, 1, 5)).min()), 12)
    0.02
    """

    def __init__(self, h, psi, angle_range, anchor, pivot, turn: int, cable_length: float,
                 anchor_distance: float | None = None) -> None:
        self.h = np.asarray(h, dtype=float)
        self.psi = np.asarray(psi, dtype=float)
        lo, hi = (float(v) for v in angle_range)
        self.angle_range = (lo, hi)
        self.mid, self.half = 0.5 * (lo + hi), 0.5 * (hi - lo)
        self.anchor = tuple(float(v) for v in anchor)
        self.pivot = tuple(float(v) for v in pivot)
        if turn not in (1, -1):
            raise ValueError(f"turn must be 1 or -1, got {turn!r}")
        self.turn = int(turn)
        self.cable_length = float(cable_length)
        if anchor_distance is not None:
            anchor_distance = float(anchor_distance)
            if not (math.isfinite(anchor_distance) and anchor_distance > 0):
                raise ValueError(f"anchor_distance must be a finite length > 0 (m) or None, got {anchor_distance}")
        self.anchor_distance = anchor_distance
        ax, ay = self.anchor[0], self.turn * self.anchor[1]
        self.rho, self.alpha = math.hypot(ax, ay), math.atan2(ay, ax)
        self._dh, self._dpsi = cheb.chebder(self.h), cheb.chebder(self.psi)
        self._ddpsi = cheb.chebder(self._dpsi)
        self._H = cheb.chebint(cheb.chebmul(self.h, self._dpsi))  # int h dpsi, as a series in x
        slope = cheb.chebval(np.array([-1.0, 1.0]), self._dpsi)
        self.end_parameter = -1.0 if slope[0] < 0 else 1.0  # the end with the largest psi

    def __repr__(self) -> str:
        lo, hi = np.degrees(self.angle_range)
        return (f"NoncircularProfile(link angles {lo:.1f}° to {hi:.1f}°, turn {self.turn}, "
                f"{len(self.h)} Chebyshev terms)")

    def __str__(self) -> str:
        return "cable over a non-circular pulley"

    @property
    def direction(self) -> np.ndarray:
        """Unit vector from the pivot through the eyelet: the spring hangs on this line beyond the eyelet."""
        u = np.asarray(self.anchor, dtype=float)
        return u / max(float(np.hypot(*u)), 1e-300)

    @property
    def spring_anchor(self) -> tuple[float, float] | None:
        """World point (m) where the spring's far end is fixed, ``anchor_distance`` beyond the eyelet, or ``None``."""
        if self.anchor_distance is None:
            return None
        point = np.add(self.pivot, self.anchor) + self.anchor_distance * self.direction
        return (float(point[0]), float(point[1]))

    # --------------------------------------------------------- the curve itself
    def _canonical(self, theta):
        return self.turn * np.asarray(theta, dtype=float)

    def support(self, x) -> tuple[np.ndarray, np.ndarray]:
        """Support function ``h`` (m) and normal angle ``psi`` (rad) at parameters ``x`` (canonical frame)."""
        return cheb.chebval(x, self.h), cheb.chebval(x, self.psi)

    def _h_psi(self, x):
        return cheb.chebval(x, self._dh) / cheb.chebval(x, self._dpsi)

    def arc_length(self, x) -> np.ndarray:
        """Arc length function ``S = H + h'`` (m) at parameters ``x``; it grows with ``psi``."""
        return cheb.chebval(x, self._H) + self._h_psi(x)

    def radius_of_curvature(self, x) -> np.ndarray:
        """``h + d^2h/dpsi^2`` (m) at parameters ``x``; positive where the profile is convex."""
        dpsi = cheb.chebval(x, self._dpsi)
        ddh = cheb.chebval(x, cheb.chebder(self._dh))
        hpp = (ddh - cheb.chebval(x, self._dh) * cheb.chebval(x, self._ddpsi) / dpsi) / dpsi ** 2
        return cheb.chebval(x, self.h) + hpp

    def local_points(self, x) -> np.ndarray:
        """Points of the profile (the cable's centre line) in the link's frame (m), shape (..., 2)."""
        x = np.asarray(x, dtype=float)
        h, psi = self.support(x)
        hp = self._h_psi(x)
        px, py = turn(np.cos(psi), np.sin(psi), (h, hp))     # h along the normal, h' along the tangent
        return np.stack([px, self.turn * py], -1)

    def normals(self, x) -> np.ndarray:
        """Outward unit normals of the profile in the link's frame, shape (..., 2)."""
        psi = cheb.chebval(np.asarray(x, dtype=float), self.psi)
        return np.stack([np.cos(psi), self.turn * np.sin(psi)], -1)

    # ----------------------------------------------------------------- the cable
    def tangent_parameter(self, theta) -> np.ndarray:
        """Profile parameter of the cable's tangent point at link angles ``theta`` (rad).

        Solves the tangency ``rho cos(psi(x) + theta' - alpha) = h(x)`` by Newton's method.

        Raises
        ------
        ProfileError
            Where the tangent point leaves the profile: the message names the angle and
            the range the profile covers.
        """
        theta = np.asarray(theta, dtype=float)
        outside = ~(np.abs(theta - self.mid) <= self.half * (1 + _EDGE))     # NaN counts as outside
        if np.any(outside):
            self._refuse(theta[outside] if theta.ndim else theta)
        x = self._tangent(theta, self.rho, self.alpha)
        bad = np.abs(x) > 1 + _EDGE
        if np.any(bad) or not np.all(np.isfinite(x)):
            self._refuse(theta[bad | ~np.isfinite(x)] if theta.ndim else theta)
        return x

    def _tangent(self, theta, rho, alpha):
        """Newton's method on the tangency, eyelet at distance ``rho`` and angle ``alpha`` (canonical frame)."""
        s = self._canonical(theta)
        x = np.clip((theta - self.mid) / self.half, -1.0, 1.0)
        x = x + 0 * rho
        for _ in range(60):
            h, psi = self.support(x)
            beta = psi + s - alpha
            g = rho * np.cos(beta) - h
            dg = -rho * np.sin(beta) * cheb.chebval(x, self._dpsi) - cheb.chebval(x, self._dh)
            step = g / dg
            x = x - step
            if np.all(np.abs(step) < 1e-11):   # converging quadratically: x is now exact to round-off
                break
        return x

    def path_from(self, theta, anchor) -> np.ndarray:
        """The cable's path (m) at link angles ``theta`` (rad) from eyelets ``anchor`` other than the design's.

        The built part with its eyelet misplaced: ``anchor`` (world frame relative to the pivot, m,
        shape ``(..., 2)``) broadcasts with ``theta``; the profile, the clamp and the cable are the
        design's. A misplaced eyelet moves the tangent point; where it would move past one of the
        profile's ends the cable bends over that end instead (straight from the eyelet to the end
        point, then wrapped from there, or straight to the clamp).

        Raises
        ------
        ProfileError
            Where the tangency cannot be solved (the eyelet far off).

        Examples
        --------
        >>> psi0 = math.pi / 2 + math.acos(0.02 / 0.3)
        >>> p = NoncircularProfile([0.02], [psi0, -1.0], (-1.0, 1.0), (0.0, 0.3), (0.0, 0.0), 1, 0.0)
        >>> bool(np.isclose(p.path_from(0.5, [0.0, 0.3]), p.cable(0.5).path))
        True
        """
        theta = np.asarray(theta, dtype=float)
        anchor = np.asarray(anchor, dtype=float)
        ax, ay = anchor[..., 0], self.turn * anchor[..., 1]
        rho, alpha = np.hypot(ax, ay), np.arctan2(ay, ax)
        x = self._tangent(theta, rho, alpha)
        if not np.all(np.isfinite(x)):
            self._refuse(np.broadcast_to(theta, x.shape)[~np.isfinite(x)])
        inside = np.abs(x) <= 1.0
        x = np.clip(x, -1.0, 1.0)
        h, psi = self.support(x)
        straight = rho * np.sin(psi + self._canonical(theta) - alpha) + self._h_psi(x)
        if not np.all(inside):     # over an end of the profile: straight from the eyelet to that end
            ends = self.world(np.broadcast_to(theta, x.shape), self.local_points(x))
            gap_x = ends[..., 0] - (self.pivot[0] + anchor[..., 0])
            gap_y = ends[..., 1] - (self.pivot[1] + anchor[..., 1])
            straight = np.where(inside, straight, np.hypot(gap_x, gap_y))
        return straight + self.arc_length(self.end_parameter) - self.arc_length(x)

    def _refuse(self, where) -> None:
        lo, hi = np.degrees(self.angle_range)
        raise ProfileError(f"the cable's tangent point leaves the profile at link angle "
                           f"{math.degrees(float(np.ravel(where)[0])):.3f}°: the profile covers "
                           f"{lo:.3f}° to {hi:.3f}° only; outside it the spring does not balance")

    def cable(self, theta) -> CableGeometry:
        """The cable's geometry at link angles ``theta`` (rad): tangent from the eyelet plus wrapped arc.

        Examples
        --------
        >>> psi0 = math.pi / 2 + math.acos(0.02 / 0.3)
        >>> p = NoncircularProfile([0.02], [psi0, -1.0], (-1.0, 1.0), (0.0, 0.3), (0.0, 0.0), 1, 0.0)
        >>> c = p.cable(0.5)
        >>> round(float(c.wrapped), 6)  # a circle: radius times the angle turned from -1 rad
        0.03
        """
        theta = np.asarray(theta, dtype=float)
        x = self.tangent_parameter(theta)
        h, psi = self.support(x)
        beta = psi + self._canonical(theta) - self.alpha
        straight = self.rho * np.sin(beta) + self._h_psi(x)
        wrapped = self.arc_length(self.end_parameter) - self.arc_length(x)
        return CableGeometry(self.world(theta, self.local_points(x)),
                             self.world(theta, self.local_points(self.end_parameter + 0 * x)),
                             np.broadcast_to(np.add(self.anchor, self.pivot), x.shape + (2,)),
                             straight, wrapped, straight + wrapped, x)

    def world(self, theta, points) -> np.ndarray:
        """Link-frame points (m) carried to the world at link angles ``theta`` (rad)."""
        theta = np.asarray(theta, dtype=float)[..., None]
        p = np.asarray(points, dtype=float)
        c, s = np.cos(theta[..., 0]), np.sin(theta[..., 0])
        return np.stack(place(self.pivot[0], self.pivot[1], c, s, (p[..., 0], p[..., 1])), -1)

    def length(self, pose_a, pose_b) -> np.ndarray:
        """The spring's length (m): the cable's path from the eyelet minus the cable's length.

        Parameters
        ----------
        pose_a, pose_b : numpy.ndarray, shape (..., 3)
            Poses of the ground and of the link (its angle is the link angle).

        Returns
        -------
        numpy.ndarray, shape (...)
        """
        return self.cable(np.asarray(pose_b)[..., 2]).path - self.cable_length
