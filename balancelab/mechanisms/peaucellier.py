"""The Peaucellier-Lipkin straight-line linkage, driven by a crank (Singh & Ananthasuresh, Sec. III.B).

``O`` is the origin and the fixed pivot of the long arms; the crank turns about
``A = (d, 0)`` and carries ``C`` around a circle through ``O``, so the rhombus tip ``P``
moves on a straight line. Bodies: 0 ground, 1 crank, 2 and 3 long arms, 4-7 rhombus
sides. Layer: mechanisms.
"""
from __future__ import annotations

import math

import numpy as np

from ..core.validation import finite_real
from ..core.kinematics import Kinematics
from .geometry import binary_link_point, circle_intersection, rotate

__all__ = ["PEAUCELLIER_BODIES", "PeaucellierKinematics"]


PEAUCELLIER_BODIES = ("ground", "crank 1", "arm 2", "arm 3", "side 4", "side 5", "side 6", "side 7")


class PeaucellierKinematics(Kinematics):
    """Closed-form poses of a Peaucellier-Lipkin linkage, driven by the crank angle ``phi``.

    ``O`` is the origin, ``A = (d, 0)``; ``D`` is on the upper side of the line ``OP``.
    Symbolically the linkage is relaxed (Singh's construction): crank, arms 2, 3 and
    sides 6, 7 each get an angle, and sides 4 and 5 are written through their end joints.

    Parameters
    ----------
    crank : float
        Crank length ``d`` = distance ``OA`` (m), > 0.
    arm : float
        Length ``l`` of the long arms ``OD = OE`` (m), > 0.
    side : float
        Rhombus side ``s`` (m), ``0 < s < l``.

    The paper's symbols are kept as attributes: ``d``, ``l``, ``s``.

    Reach: ``|OC| = 2 d cos(phi/2)`` must lie in ``[l - s, l + s]`` for the loop to close.
    ``phi_max`` bounds ``|phi|`` from ``|OC| >= l - s``. A crank longer than ``(l + s)/2``
    puts ``C`` out of reach near ``phi = 0``: the poses with ``|phi| < phi_min`` (``phi_min > 0``
    only then) are unreachable and ``reachable`` is false there, so the working range is
    ``phi_min <= |phi| <= phi_max`` (two intervals, and ``P`` cannot cross the x-axis).

    Examples
    --------
    >>> kin = PeaucellierKinematics(0.22326, 0.7505, 0.363)
    >>> round(kin.line_x, 4)
    0.9663
    """

    def __init__(self, crank: float, arm: float, side: float) -> None:
        self.d = finite_real("crank (length d, m)", crank, positive=True)
        self.l = finite_real("arm (long-arm length l, m)", arm, positive=True)
        self.s = finite_real("side (rhombus side s, m)", side, positive=True)
        if self.s >= self.l:
            raise ValueError(f"the rhombus side = {side} m must be shorter than the long arms arm = {arm} m")
        if 2 * self.d <= self.l - self.s:
            raise ValueError(f"the crank = {crank} m is too short: C must reach a distance arm - side = "
                             f"{self.l - self.s:.4g} m from O, so crank > (arm - side)/2")
        self.nbodies = 8
        self.names = ("phi",)
        self.descriptions = ("crank angle from the x-axis",)
        self.symbol_bodies = (1, 2, 3, 6, 7)
        self.phi_max = 2 * math.acos((self.l - self.s) / (2 * self.d))
        self.phi_min = 2 * math.acos(min(1.0, (self.l + self.s) / (2 * self.d)))
        self.q_range = np.array([[-self.phi_max, self.phi_max]])
        self.line_x = (self.l ** 2 - self.s ** 2) / (2 * self.d)

    #: whether the sympy symbols (crank, arms 2 and 3, sides 6 and 7) are independent coordinates
    #: of the relaxed linkage (see :func:`balancelab.core.symbolic.symbols_are_independent`)
    independent_symbols = True

    @property
    def travel(self) -> float:
        """Length (m) of the part of the line ``x = line_x`` that ``P`` reaches.

        ``|OP| = (l^2 - s^2)/|OC|`` runs over ``[l - s, l + s]``; when the line passes closer
        to ``O`` than ``l - s`` (a long crank) the points near the x-axis are out of reach.

        Examples
        --------
        >>> round(PeaucellierKinematics(0.22326, 0.7505, 0.363).travel, 4)
        1.1065
        """
        outer = math.sqrt((self.l + self.s) ** 2 - self.line_x ** 2)
        inner = math.sqrt(max((self.l - self.s) ** 2 - self.line_x ** 2, 0.0))
        return 2 * (outer - inner)

    def poses(self, q):
        q = np.asarray(q, dtype=float)
        phi = q[..., 0]
        d, l, s = self.d, self.l, self.s
        cx, cy = d + d * np.cos(phi), d * np.sin(phi)
        oc = np.hypot(cx, cy)
        # the loop closes only for l - s <= |OC| <= l + s (|phi| <= phi_max and |phi| >= phi_min)
        ok = (np.abs(phi) < self.phi_max) & (oc > 0) & (oc <= (l + s) * (1 + 1e-12))
        oc_safe = np.where(oc > 0, oc, 1.0)
        op = (l * l - s * s) / oc_safe
        px, py = op * cx / oc_safe, op * cy / oc_safe
        dx, dy, meets = circle_intersection((0.0, 0.0), l, (cx, cy), s, +1)
        ok = ok & meets
        ex, ey, _ = circle_intersection((0.0, 0.0), l, (cx, cy), s, -1)
        out = np.zeros(phi.shape + (8, 3))

        def put(b, x, y, tx, ty):
            out[..., b, 0], out[..., b, 1] = x, y
            out[..., b, 2] = np.arctan2(ty - y, tx - x)

        put(1, d, 0.0, cx, cy)
        put(2, 0.0, 0.0, dx, dy)
        put(3, 0.0, 0.0, ex, ey)
        put(4, cx, cy, dx, dy)
        put(5, cx, cy, ex, ey)
        put(6, dx, dy, px, py)
        put(7, ex, ey, px, py)
        return out, ok

    def symbols(self):
        import sympy as sp

        return sp.symbols("phi_1 theta_2 theta_3 theta_6 theta_7", real=True)

    def symbolic_point(self, body, point, syms):
        import sympy as sp

        f1, t2, t3, t6, t7 = syms
        d, l, s = (sp.Float(v) for v in (self.d, self.l, self.s))
        A = (d, sp.S.Zero)
        C = (A[0] + d * sp.cos(f1), d * sp.sin(f1))
        D = (l * sp.cos(t2), l * sp.sin(t2))
        E = (l * sp.cos(t3), l * sp.sin(t3))

        def on(origin, angle):
            x, y = rotate(sp, angle, point)
            return (origin[0] + x, origin[1] + y)

        if body == 0:
            return tuple(point)
        if body == 1:
            return on(A, f1)
        if body == 2:
            return on((0, 0), t2)
        if body == 3:
            return on((0, 0), t3)
        if body == 4:
            return binary_link_point(C, D, (0, 0), (s, 0), point)
        if body == 5:
            return binary_link_point(C, E, (0, 0), (s, 0), point)
        if body == 6:
            return on(D, t6)
        return on(E, t7)
