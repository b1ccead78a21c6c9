"""The four-bar linkage: closed-form position analysis, circuits and joints.

Points (the notation page of the book): ground pivots ``A`` (crank) and ``B``
(rocker); ``D`` joins crank and coupler, ``C`` coupler and rocker; ``E`` is a coupler
point. Bodies: 0 ground, 1 crank (frame at ``A``), 2 coupler (frame at ``D``, x-axis
towards ``C``), 3 rocker (frame at ``B``, x-axis towards ``C``). The coordinate is the
crank angle ``theta`` from the global x-axis. Layer: mechanisms.
"""
from __future__ import annotations

import numpy as np

from ..core.elements import Joint
from ..core.kinematics import Kinematics
from ..core.validation import finite_real, planar_point
from .geometry import binary_link_point, circle_intersection, rotate

__all__ = ["FourBarKinematics", "fourbar_joints"]


class FourBarKinematics(Kinematics):
    """Closed-form position analysis of a four-bar linkage.

    Bodies: 0 ground, 1 crank (from pivot ``A``), 2 coupler (from the crank tip), 3
    rocker (from pivot ``B``). The coordinate is the crank angle ``theta`` measured
    from the global x-axis. ``branch`` (+1 or -1) picks the assembly: the coupler
    direction is the direction from the crank tip to ``B`` turned by ``+-`` the
    triangle angle.

    Symbolically the design can be seen two ways (``symbolic``):

    * ``"loop"``: crank and rocker angles are the symbols ``theta_2``, ``theta_4`` and
      every coupler point is written through the two moving joints (the lecture's
      equivalent-mass decomposition). Constant energy in these symbols means
      constant energy of the four-bar.
    * ``"relaxed"``: the coupler-rocker joint is released and crank, coupler and rocker
      each get their own angle (Singh & Ananthasuresh, Sec. III.A). Constant energy
      of the relaxed chain is sufficient for the four-bar.
    """

    def __init__(self, A, B, crank: float, coupler: float, rocker: float, branch: int = 1,
                 symbolic: str = "loop", circuit: float | None = None):
        self.A = np.array(planar_point("pivot A", A))
        self.B = np.array(planar_point("pivot B", B))
        self.r2 = finite_real("crank length (m)", crank, positive=True)
        self.r3 = finite_real("coupler length (m)", coupler, positive=True)
        self.r4 = finite_real("rocker length (m)", rocker, positive=True)
        if branch not in (1, -1):
            raise ValueError(f"branch must be +1 or -1, got {branch!r}")
        if symbolic not in ("loop", "relaxed"):
            raise ValueError(f"symbolic must be 'loop' or 'relaxed', got {symbolic!r}")
        self.branch = branch
        self.symbolic = symbolic
        self.r1 = float(np.hypot(*(self.B - self.A)))
        if self.r1 == 0:
            raise ValueError("ground pivots A and B coincide; a four-bar needs two distinct pivots")
        self.nbodies = 4
        self.names = ("theta",)
        self.symbol_bodies = (1, 3) if symbolic == "loop" else (1, 2, 3)
        self.q_range = self._crank_range(circuit)

    def _assembles(self, theta):
        jx = self.A[0] + self.r2 * np.cos(theta)
        jy = self.A[1] + self.r2 * np.sin(theta)
        D = np.hypot(self.B[0] - jx, self.B[1] - jy)
        return (D <= self.r3 + self.r4) & (D >= abs(self.r3 - self.r4)) & (D > 0)

    def _crank_range(self, circuit: float | None = None) -> np.ndarray:
        """Interval of crank angles over which the linkage assembles.

        With ``circuit`` (a crank angle, rad) the interval containing it; otherwise the
        widest one (a crank that cannot turn fully may have two).
        """
        base = np.arctan2(*(self.B - self.A)[::-1])
        t = base + np.linspace(-np.pi, np.pi, 7201)
        ok = self._assembles(t)
        if circuit is not None:
            c = finite_real("circuit (crank angle, rad)", circuit)
            if not self._assembles(np.array(c)):
                raise ValueError(f"the four-bar cannot assemble at the crank angle circuit = {c} rad")
            if ok.all():
                return np.array([[c - np.pi, c + np.pi]])
            t = c + np.linspace(-2 * np.pi, 2 * np.pi, 14401)
            ok = self._assembles(t)
            bad = np.flatnonzero(~ok)
            left, right = bad[bad < 7200].max(), bad[bad > 7200].min()
            return np.array([[self._refine(t[left + 1], -1), self._refine(t[right - 1], +1)]])
        if ok.all():
            return np.array([[base - np.pi, base + np.pi]])
        if not ok.any():
            raise ValueError(
                "this four-bar cannot assemble: with crank {:.4g} m, coupler {:.4g} m, rocker {:.4g} m "
                "and ground {:.4g} m no crank angle closes the loop (each link must be shorter than "
                "the sum of the other three)".format(self.r2, self.r3, self.r4, self.r1))
        # ok is False at the ends (opposite side of B) or True there; roll so runs are contiguous
        idx = np.flatnonzero(ok)
        runs = np.split(idx, np.flatnonzero(np.diff(idx) > 1) + 1)
        if ok[0] and ok[-1] and len(runs) > 1:
            first, last = runs[0], runs[-1]
            runs = runs[1:-1] + [np.concatenate([last, first + len(t) - 1])]
            t = np.concatenate([t, t[1:] + 2 * np.pi])
        best = max(runs, key=len)
        lo, hi = t[best[0]], t[best[-1]]
        lo, hi = self._refine(lo, -1), self._refine(hi, +1)
        return np.array([[lo, hi]])

    def _refine(self, t0, direction):
        """Bisect the crank limit near ``t0`` to machine precision."""
        step = 2 * np.pi / 7200
        a, b = t0, t0 + direction * step
        for _ in range(60):
            m = 0.5 * (a + b)
            if self._assembles(np.array(m)):
                a = m
            else:
                b = m
        return a

    def poses(self, q):
        q = np.asarray(q, dtype=float)
        th = q[..., 0]
        A, B = self.A, self.B
        jx = A[0] + self.r2 * np.cos(th)
        jy = A[1] + self.r2 * np.sin(th)
        kx, ky, closes = circle_intersection((jx, jy), self.r3, B, self.r4, self.branch)
        lo, hi = self.q_range[0]
        ok = closes & (th >= lo - 1e-12) & (th <= hi + 1e-12)
        phi = np.arctan2(ky - jy, kx - jx)
        psi = np.arctan2(ky - B[1], kx - B[0])
        out = np.zeros(th.shape + (4, 3))
        out[..., 1, 0], out[..., 1, 1], out[..., 1, 2] = A[0], A[1], th
        out[..., 2, 0], out[..., 2, 1], out[..., 2, 2] = jx, jy, phi
        out[..., 3, 0], out[..., 3, 1], out[..., 3, 2] = B[0], B[1], psi
        return out, ok

    def symbols(self):
        import sympy as sp

       
        if self.symbolic == "loop":
            return sp.symbols("theta_2 theta_4", real=True)
        return sp.symbols("theta_1 theta_2 theta_3", real=True)

    def symbolic_point(self, body, point, syms):
        import sympy as sp

       
        A = [sp.nsimplify(v) if v == int(v) else sp.Float(v) for v in self.A]
        B = [sp.nsimplify(v) if v == int(v) else sp.Float(v) for v in self.B]
        if body == 0:
            return tuple(point)
        if self.symbolic == "loop":
            t2, t4 = syms
            J2 = (A[0] + self.r2 * sp.cos(t2), A[1] + self.r2 * sp.sin(t2))
            J3 = (B[0] + self.r4 * sp.cos(t4), B[1] + self.r4 * sp.sin(t4))
            if body == 1:
                px, py = rotate(sp, t2, point)
                return (A[0] + px, A[1] + py)
            if body == 3:
                px, py = rotate(sp, t4, point)
                return (B[0] + px, B[1] + py)
            return binary_link_point(J2, J3, (0, 0), (self.r3, 0), point)
        t1, t2, t3 = syms
        if body == 1:
            px, py = rotate(sp, t1, point)
            return (A[0] + px, A[1] + py)
        if body == 2:
            jx, jy = rotate(sp, t1, (self.r2, 0))
            px, py = rotate(sp, t2, point)
            return (A[0] + jx + px, A[1] + jy + py)
        px, py = rotate(sp, t3, point)
        return (B[0] + px, B[1] + py)


def fourbar_joints(kin: FourBarKinematics) -> list:
    """The four revolute joints of a :class:`FourBarKinematics` linkage.

    Parameters
    ----------
    kin : FourBarKinematics

    Returns
    -------
    list of Joint

    Examples
    --------
    >>> len(fourbar_joints(FourBarKinematics((0, 0), (0.7, 0), 0.3, 0.8, 0.6)))
    4
    """
    return [Joint(0, tuple(kin.A), 1, (0.0, 0.0)), Joint(1, (kin.r2, 0.0), 2, (0.0, 0.0)),
            Joint(2, (kin.r3, 0.0), 3, (kin.r4, 0.0)), Joint(0, tuple(kin.B), 3, (0.0, 0.0))]
