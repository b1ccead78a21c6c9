"""The four-bar linkage: closed-form position analysis, circuits, joints, named points.

Points (the notation page of the book): ground pivots ``A`` (crank) and ``B``
(rocker); ``D`` joins crank and coupler, ``C`` coupler and rocker; ``E`` is a coupler
point. Bodies: 0 ground, 1 crank (frame at ``A``), 2 coupler (frame at ``D``, x-axis
towards ``C``), 3 rocker (frame at ``B``, x-axis towards ``C``). The coordinate is the
crank angle ``theta`` from the global x-axis. Links: ``crank = |AD|``,
``coupler = |DC|``, ``rocker = |BC|``, ``ground = |AB|``.

:class:`FourBarKinematics` is the position analysis (circuits, crank range, symbolic
views); :class:`FourBar` is a four-bar with its coupler point ``E``, built on it, with
its joints (:func:`fourbar_joints`), named points (:func:`fourbar_labels`), fast
vectorized positions (:func:`fourbar_positions`, :func:`loop_closure_error`) and its
coupler curve. Both check assembly with :func:`check_assembly` and place ``C`` with
:func:`balancelab.mechanisms.geometry.circle_intersection`. Layer: mechanisms.
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from functools import cached_property
from typing import Mapping, Sequence

import numpy as np
from numpy.typing import ArrayLike

from ..core.design import Design
from ..core.elements import Joint, Load, Spring
from ..core.kinematics import Kinematics
from ..core.validation import finite_real, instance_of, planar_point, positive_int, real_array
from .geometry import Point, as_complex, binary_link_point, circle_intersection, rotate

__all__ = ["PIVOTS", "check_assembly", "pivot_name", "FourBarKinematics", "FourBar", "fourbar_joints",
           "fourbar_labels", "fourbar_design", "coupler_curve", "fourbar_positions", "loop_closure_error"]

#: names of the two ground pivots: of the crank and of the rocker
PIVOTS = ("A", "B")


def check_assembly(crank: float, coupler: float, rocker: float, ground: float) -> None:
    """Raise ValueError unless a four-bar with these link lengths closes for some crank angle.

    The distance from the crank tip ``D`` to ``B`` spans ``[|ground - crank|, ground +
    crank]``; the dyad ``D-C-B`` closes over ``[|coupler - rocker|, coupler + rocker]``;
    the four-bar assembles when the two intervals overlap, i.e. when each link is at
    most the sum of the other three. When they only touch (one link as long as the other three
    together, to the round-off of the lengths) the loop closes at one crank angle alone, all four
    links on a line: a structure, not a mechanism, and it is refused too (it cannot move, so there
    is nothing to balance).

    Parameters
    ----------
    crank, coupler, rocker, ground : float
        Link lengths ``|AD|``, ``|DC|``, ``|BC|``, ``|AB|`` (m), > 0.

    Raises
    ------
    ValueError
        If the linkage cannot assemble, or only in one configuration (the message gives the four
        lengths).

    Examples
    --------
    >>> check_assembly(0.1, 0.35, 0.3, 0.4)
    >>> check_assembly(0.8, 0.3, 0.2, 0.3)  # doctest: +ELLIPSIS
    Traceback (most recent call last):
    ...
    ValueError: this four-bar cannot assemble into a mechanism that moves: with crank 0.8 m, ...
    >>> check_assembly(0.1, 0.2, 0.3, 1.0)  # doctest: +ELLIPSIS
    Traceback (most recent call last):
    ...
    ValueError: this four-bar cannot assemble: with crank 0.1 m, coupler 0.2 m, rocker 0.3 m and ...
    """
    crank, coupler, rocker, ground = (finite_real(f"{n} (m)", v, positive=True) for n, v in zip(
        ("crank", "coupler", "rocker", "ground"), (crank, coupler, rocker, ground)))
    if ground + crank < abs(coupler - rocker) or abs(ground - crank) > coupler + rocker:
        raise ValueError(_cannot_assemble(crank, coupler, rocker, ground))
    # the width of the overlap; each bound is rounded by an ulp of the lengths' sum at most, and the
    # lengths themselves (0.8 against 0.3 + 0.3 + 0.2) by an ulp each: a width within 4 ulps is a point
    width = min(ground + crank, coupler + rocker) - max(abs(ground - crank), abs(coupler - rocker))
    if width <= 4.0 * np.finfo(float).eps * (crank + coupler + rocker + ground):
        raise ValueError(f"this four-bar cannot assemble into a mechanism that moves: with crank {crank:.4g} m, "
                         f"coupler {coupler:.4g} m, rocker {rocker:.4g} m and ground {ground:.4g} m one link is "
                         "as long as the other three together, so the loop closes only with all four on one line")


def _cannot_assemble(crank, coupler, rocker, ground) -> str:
    return (f"this four-bar cannot assemble: with crank {crank:.4g} m, coupler {coupler:.4g} m, rocker {rocker:.4g} m "
            f"and ground {ground:.4g} m no crank angle closes the loop (each link must be shorter than "
            "the sum of the other three)")


def pivot_name(parameter: str, value: str) -> str:
    """Check that ``value`` names a ground pivot of the four-bar, ``"A"`` or ``"B"``.

    Parameters
    ----------
    parameter : str
        Name of the parameter, for the error message.
    value : str

    Returns
    -------
    str
        ``value``.

    Raises
    ------
    ValueError
        If ``value`` is neither ``"A"`` nor ``"B"``.

    Examples
    --------
    >>> pivot_name("base", "B")
    'B'
    """
    if value not in PIVOTS:
        raise ValueError(f"{parameter} must be 'A' or 'B' (a ground pivot of the four-bar), got {value!r}")
    return value


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

    Parameters
    ----------
    A, B : (float, float)
        Ground pivots of the crank and of the rocker (m), distinct.
    crank, coupler, rocker : float
        Link lengths ``|AD|``, ``|DC|``, ``|BC|`` (m), > 0.
    branch : {1, -1}
        Assembly branch.
    symbolic : {"loop", "relaxed"}
        Symbolic view (above).
    circuit : float, optional
        A crank angle (rad) inside the interval of crank angles wanted (see
        :class:`FourBar`).

    Raises
    ------
    ValueError
        If the linkage cannot assemble (:func:`check_assembly`) or an argument is out
        of range.

    Examples
    --------
    >>> kin = FourBarKinematics((0, 0), (0.4, 0), 0.1, 0.35, 0.3)
    >>> kin.ground, [round(float(v), 4) for v in kin.q_range[0]]
    (0.4, [-3.1416, 3.1416])
    """

    def __init__(self, A: Point, B: Point, crank: float, coupler: float, rocker: float, branch: int = 1,
                 symbolic: str = "loop", circuit: float | None = None) -> None:
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
        self.names, self.descriptions = ("theta",), ("crank angle from the x-axis",)
        self.symbol_bodies = (1, 3) if symbolic == "loop" else (1, 2, 3)
        self.independent_symbols = symbolic == "relaxed"  # the loop's crank and rocker angles are tied
        check_assembly(self.r2, self.r3, self.r4, self.r1)
        self.q_range = self._crank_range(circuit)

    # the link lengths under the names of FourBar (r2, r3, r4, r1 are the lecture's)
    crank = property(lambda self: self.r2, doc="``|AD|`` (m).")
    coupler = property(lambda self: self.r3, doc="``|DC|`` (m).")
    rocker = property(lambda self: self.r4, doc="``|BC|`` (m).")
    ground = property(lambda self: self.r1, doc="``|AB|`` (m).")

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
        if not ok.any():  # closes only at isolated crank angles (a link as long as the other three)
            raise ValueError(_cannot_assemble(self.r2, self.r3, self.r4, self.r1))
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
        full = hi - lo >= 2 * np.pi - 1e-9   # a fully rotating crank: any angle, modulo 2 pi
        ok = closes & np.isfinite(th) & (full | ((th >= lo - 1e-12) & (th <= hi + 1e-12)))
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


@dataclass(frozen=True)
class FourBar:
    """A four-bar ``A-D-C-B`` with a coupler point ``E``, on :class:`FourBarKinematics`.

    Parameters
    ----------
    A, B : (float, float)
        Ground pivots of the crank and of the rocker (m).
    crank, coupler, rocker : float
        Link lengths ``|AD|``, ``|DC|``, ``|BC|`` (m), > 0.
    coupler_point : (float, float)
        ``E`` in the coupler's frame: origin ``D``, x-axis along ``DC`` (m).
    branch : {1, -1}
        Assembly branch, as in :class:`FourBarKinematics`.
    circuit : float, optional
        A crank angle (rad) inside the interval of crank angles wanted. When the crank
        cannot turn fully its reachable angles may form two separate intervals (two
        circuits); by default the widest is used.

    Raises
    ------
    ValueError
        If the four-bar cannot assemble for any crank angle (:func:`check_assembly`).

    Examples
    --------
    >>> fb = FourBar((0, 0), (0.4, 0), 0.15, 0.35, 0.3, (0.2, 0.1))
    >>> round(abs(fb.z), 4)
    0.6389
    >>> sorted(fb.labels())
    ['A', 'B', 'C', 'D', 'E']
    """

    A: tuple
    B: tuple
    crank: float
    coupler: float
    rocker: float
    coupler_point: tuple
    branch: int = 1
    circuit: float | None = None

    def __post_init__(self) -> None:
        object.__setattr__(self, "A", planar_point("pivot A", self.A))
        object.__setattr__(self, "B", planar_point("pivot B", self.B))
        for name in ("crank", "coupler", "rocker"):
            value = finite_real(f"{name} length (m)", getattr(self, name), positive=True)
            object.__setattr__(self, name, value)
        object.__setattr__(self, "coupler_point", planar_point("coupler_point E (coupler frame, m)",
                                                               self.coupler_point))
        if isinstance(self.branch, bool) or self.branch not in (1, -1):
            raise ValueError(f"branch must be +1 or -1, got {self.branch!r}")
        object.__setattr__(self, "branch", int(self.branch))
        if self.ground == 0:
            raise ValueError("ground pivots A and B coincide; a four-bar needs two distinct pivots")
        check_assembly(self.crank, self.coupler, self.rocker, self.ground)

    @property
    def ground(self) -> float:
        """``|AB|`` (m)."""
        return math.dist(self.A, self.B)

    @cached_property
    def kinematics(self) -> FourBarKinematics:
        """The closed-form position analysis (bodies 0 ground, 1 crank, 2 coupler, 3 rocker)."""
        return FourBarKinematics(self.A, self.B, self.crank, self.coupler, self.rocker, self.branch,
                                 circuit=self.circuit)

    @property
    def z(self) -> complex:
        """Complex ratio ``(E - D) / (C - D)`` fixed by the coupler triangle."""
        return as_complex(self.coupler_point) / self.coupler

    def joints(self) -> list[Joint]:
        """The four revolute joints (A, D, C, B) of the bodies 0-3: :func:`fourbar_joints`."""
        return fourbar_joints(self)

    def labels(self) -> dict:
        """Named points A, B, D, C, E for figures: :func:`fourbar_labels`."""
        return fourbar_labels(self, self.coupler_point)

    def state(self, q: ArrayLike) -> dict:
        """Global points (complex arrays) and link angles at crank angles ``q`` (rad).

        Returns a dict with ``A, B, D, C, E`` (complex), ``th2, th3, th4`` (crank,
        coupler and rocker angles), ``ok`` (reachable mask) and ``poses`` (the
        kinematics' body poses).
        """
        q = np.asarray(q, dtype=float)
        P, ok = self.kinematics.poses(q[..., None])
        D = P[..., 2, 0] + 1j * P[..., 2, 1]
        th2, th3, th4 = P[..., 1, 2], P[..., 2, 2], P[..., 3, 2]
        C = D + self.coupler * np.exp(1j * th3)
        E = D + self.coupler * self.z * np.exp(1j * th3)
        return {"A": as_complex(self.A), "B": as_complex(self.B), "D": D, "C": C, "E": E,
                "th2": th2, "th3": th3, "th4": th4, "ok": ok, "poses": P}

    def pivot(self, name: str) -> complex:
        """Ground pivot ``"A"`` or ``"B"`` as a complex number."""
        return as_complex(self.A if pivot_name("pivot", name) == "A" else self.B)

    def check_triangle(self) -> None:
        """Raise ValueError when the coupler point coincides with ``D`` or ``C``."""
        scale = self.coupler
        if abs(self.z) * scale < 1e-12 * scale:
            raise ValueError("degenerate coupler triangle: the coupler point E coincides with the "
                             "crank-coupler joint D")
        if abs(self.z - 1) * scale < 1e-12 * scale:
            raise ValueError("degenerate coupler triangle: the coupler point E coincides with the "
                             "coupler-rocker joint C")


def fourbar_joints(linkage: FourBarKinematics | FourBar) -> list[Joint]:
    """The four revolute joints ``A, D, C, B`` of a four-bar (bodies 0 ground, 1-3 moving).

    Parameters
    ----------
    linkage : FourBarKinematics or FourBar
        Anything with pivots ``A``, ``B`` and lengths ``crank``, ``coupler``, ``rocker``.

    Returns
    -------
    list of Joint

    Examples
    --------
    >>> len(fourbar_joints(FourBarKinematics((0, 0), (0.7, 0), 0.3, 0.8, 0.6)))
    4
    """
    instance_of("linkage", linkage, (FourBarKinematics, FourBar), "a FourBarKinematics or a FourBar")
    A = (float(linkage.A[0]), float(linkage.A[1]))
    B = (float(linkage.B[0]), float(linkage.B[1]))
    return [Joint(0, A, 1, (0.0, 0.0)), Joint(1, (linkage.crank, 0.0), 2, (0.0, 0.0)),
            Joint(2, (linkage.coupler, 0.0), 3, (linkage.rocker, 0.0)), Joint(0, B, 3, (0.0, 0.0))]


def fourbar_labels(linkage: FourBarKinematics | FourBar, coupler_point: Point | None = None) -> dict:
    """The named points of a four-bar as ``{name: (body, local point)}``: A, B, D, C and E.

    Parameters
    ----------
    linkage : FourBarKinematics or FourBar
        As in :func:`fourbar_joints`.
    coupler_point : (float, float), optional
        ``E`` in the coupler's frame (m); left out when omitted.

    Returns
    -------
    dict

    Examples
    --------
    >>> fourbar_labels(FourBarKinematics((0, 0), (0.7, 0), 0.3, 0.8, 0.6))["C"]
    (2, (0.8, 0.0))
    """
    instance_of("linkage", linkage, (FourBarKinematics, FourBar), "a FourBarKinematics or a FourBar")
    labels = {"A": (0, (float(linkage.A[0]), float(linkage.A[1]))),
              "B": (0, (float(linkage.B[0]), float(linkage.B[1]))),
              "D": (1, (linkage.crank, 0.0)), "C": (2, (linkage.coupler, 0.0))}
    if coupler_point is not None:
        labels["E"] = (2, planar_point("coupler_point", coupler_point))
    return labels


def fourbar_design(name: str, fourbar: FourBar, loads: Sequence[Load], springs: Sequence[Spring], *,
                   kinematics: Kinematics | None = None, labels: Mapping | None = None,
                   parameters: Mapping[str, float] | None = None, reference: str = "") -> Design:
    """A :class:`Design` of a four-bar (bodies ground, crank, coupler, rocker) with loads and springs.

    Parameters
    ----------
    name : str
        Title of the design.
    fourbar : FourBar
    loads, springs : sequence of Load, sequence of Spring
        On bodies 0-3.
    kinematics : Kinematics, optional
        Places bodies 0-3 (by default ``fourbar.kinematics``); the cognates use one
        driven by another cognate's crank.
    labels : dict, optional
        Named points added to :func:`fourbar_labels`.
    parameters, reference
        As in :class:`Design`.

    Returns
    -------
    Design

    Examples
    --------
    >>> fb = FourBar((0, 0), (0.4, 0), 0.1, 0.35, 0.3, (0.2, 0.12))
    >>> fourbar_design("bare four-bar", fb, [], []).bodies
    ('ground', 'crank', 'coupler', 'rocker')
    """
    instance_of("fourbar", fourbar, FourBar, "a FourBar")
    lab = fourbar.labels()
    lab.update(labels or {})
    kin = fourbar.kinematics if kinematics is None else kinematics
    return Design(name, ("ground", "crank", "coupler", "rocker"), fourbar.joints(), kin,
                  loads, springs, labels=lab, parameters=parameters or {}, reference=reference)


def coupler_curve(fourbar: FourBar, n: int = 721) -> np.ndarray:
    """Points of the coupler curve over the crank's whole range, shape ``(n, 2)`` (m).

    Parameters
    ----------
    fourbar : FourBar
    n : int
        Number of points, >= 2.

    Returns
    -------
    numpy.ndarray

    Examples
    --------
    >>> coupler_curve(FourBar((0, 0), (0.4, 0), 0.1, 0.35, 0.3, (0.2, 0.12)), 5).shape
    (5, 2)
    """
    instance_of("fourbar", fourbar, FourBar, "a FourBar")
    n = positive_int("n", n, 2)
    lo, hi = fourbar.kinematics.q_range[0]
    E = fourbar.state(np.linspace(lo, hi, n))["E"]
    return np.stack([E.real, E.imag], axis=-1)


def _joint_positions(fourbar: FourBar, q):
    """``D`` and ``C`` (x and y arrays) at crank angles ``q`` and the mask of closed loops."""
    q = np.asarray(q, dtype=float)
    Dx = fourbar.A[0] + fourbar.crank * np.cos(q)
    Dy = fourbar.A[1] + fourbar.crank * np.sin(q)
    Cx, Cy, ok = circle_intersection((Dx, Dy), fourbar.coupler, fourbar.B, fourbar.rocker, fourbar.branch)
    return Dx, Dy, Cx, Cy, ok


def fourbar_positions(fourbar: FourBar, q: ArrayLike
                      ) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """Joint and coupler-point positions of a four-bar at crank angles ``q``, fast.

    The rocker tip ``C`` is the intersection of the circles ``|C - D| = coupler`` and
    ``|C - B| = rocker`` (:func:`balancelab.mechanisms.geometry.circle_intersection`, on
    the side ``branch`` as in :class:`FourBarKinematics`) and ``E`` follows from ``D``
    and ``C`` by the coupler triangle. No inverse trigonometric function is needed,
    which makes it the fastest way to place many configurations.

    Parameters
    ----------
    fourbar : FourBar
    q : array_like
        Crank angles (rad).

    Returns
    -------
    (D, C, E, ok)
        Arrays of shape ``q.shape + (2,)`` (m) and the mask of assembled configurations.

    Examples
    --------
    >>> fb = FourBar((0, 0), (0.4, 0), 0.1, 0.35, 0.3, (0.2, 0.12))
    >>> D, C, E, ok = fourbar_positions(fb, [0.0, 1.0])
    >>> bool(ok.all()), C.shape
    (True, (2, 2))
    """
    instance_of("fourbar", fourbar, FourBar, "a FourBar")
    q = real_array("q (crank angles, rad)", q)
    Dx, Dy, Cx, Cy, ok = _joint_positions(fourbar, q)
    Ex, Ey = binary_link_point((Dx, Dy), (Cx, Cy), (0.0, 0.0), (fourbar.coupler, 0.0), fourbar.coupler_point)
    return (np.stack([Dx, Dy], -1), np.stack([Cx, Cy], -1), np.stack([Ex, Ey], -1), ok)


def loop_closure_error(fourbar: FourBar, q: ArrayLike) -> np.ndarray:
    """Largest violation (m) of the four-bar's link lengths at crank angles ``q``.

    Places the joints as :func:`fourbar_positions` does and returns, per configuration,
    ``max(| |C - D| - coupler |, | |C - B| - rocker |)``: round-off for a correct
    solution, ``inf`` where the loop cannot close.

    Parameters
    ----------
    fourbar : FourBar
    q : array_like
        Crank angles (rad), inside the crank's range.

    Returns
    -------
    numpy.ndarray

    Examples
    --------
    >>> fb = FourBar((0, 0), (0.4, 0), 0.1, 0.35, 0.3, (0.2, 0.12))
    >>> float(loop_closure_error(fb, [0.0, 2.0]).max()) < 1e-15
    True
    """
    instance_of("fourbar", fourbar, FourBar, "a FourBar")
    q = real_array("q (crank angles, rad)", q)
    Dx, Dy, Cx, Cy, ok = _joint_positions(fourbar, q)
    ux, uy = Cx - Dx, Cy - Dy
    e1 = np.sqrt(ux * ux + uy * uy)
    e1 -= fourbar.coupler
    np.abs(e1, out=e1)
    Cx -= fourbar.B[0]
    Cy -= fourbar.B[1]
    e2 = np.sqrt(Cx * Cx + Cy * Cy)
    e2 -= fourbar.rocker
    np.abs(e2, out=e2)
    np.maximum(e1, e2, out=e1)
    e1[~ok] = np.inf
    return e1
