"""Spring-loaded four-bar linkages balanced with zero-free-length springs.

Source: S. R. Deepak and G. K. Ananthasuresh, *Static balancing of a four-bar linkage
and its cognates*, Mechanism and Machine Theory 48 (2012) 62-80 (cited below as
"Deepak"). A four-bar ``A-D-C-B`` (ground pivots ``A`` and ``B``, crank ``AD``,
coupler ``DC`` carrying the coupler point ``E``, rocker ``BC``) is loaded by a ZFL spring
``k_l`` from ``E`` to a ground anchor ``K``. This module holds

* the building blocks, each balanced on its own: the basic spring force balancer
  (Fig. 4), the balanced parallelogram with one and two degrees of freedom (Figs 6,
  7), the composition of two ZFL springs into one (Sec. 2.1.1) and the plagiograph
  (Sec. 2.1.2, eq. 1);
* technique 1 (two auxiliary links, one balancing spring, free ``l1``, ``l2``),
  technique 2 (no auxiliary link, two balancing springs; parallelogram based at ``A``
  or ``B``, eqs 2-4), technique 3 (plagiograph + technique 2, four options, eqs 5-8) and
  Herder's method (the two options of technique 3 whose bases coincide);
* the one-parameter families of techniques 2 and 3 and the two-parameter family of
  technique 1, with infeasible members (negative or infinite stiffness, a linkage
  that does not assemble) reported, never returned;
* gravity as the limit of a spring load and the 2R / slider-crank remarks (Sec. 4);
* the Watt straight-line prototype balanced with technique 2 in the ratio 1:1:2
  (Sec. 2.3).

Notation in code: complex numbers stand for planar vectors. With the crank vector
``u = D - A``, the coupler vector ``v = C - D`` and the rocker vector ``w = C - B``, the
coupler point is ``E = D + z v`` where ``z = (e_x + i e_y) / |DC|`` is the complex ratio
fixed by the coupler triangle.

**Typo in the paper.** Eq. (4) is printed ``k_b = k_b + k_l``. Composing the load
spring ``k_l`` (anchor ``K``) with balancing spring 1 ``k_b`` (anchor ``H``), both on
``E``, gives one ZFL spring of stiffness ``k_l + k_b`` anchored at
``(k_l K + k_b H) / (k_l + k_b)``; eq. (2) puts that anchor at ``W``. The equivalent
spring along the diagonal ``WE`` of a parallelogram is balanced by a spring of the same
stiffness along the other diagonal, so balancing spring 2 must have
``k_t = k_b + k_l``. (Technique 3's eq. 8, ``k_t = k_b + k_l / m^2``, has the same form.)
The paper's own prototype (Sec. 2.3), said to satisfy eqs 2-4, confirms the reading: its
springs are in the ratio ``k_l : k_b : k_t = 1 : 1 : 2``, i.e. ``k_t = k_b + k_l``.
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from functools import cached_property
from typing import NamedTuple

import numpy as np

from ...core.design import Design
from ...core.elements import G, Joint, Load, Spring
from ...core.validation import finite_real, planar_point
from ..registry import register
from ...mechanisms.base import ExplicitKinematics, TreeKinematics
from ...mechanisms.fourbar import FourBarKinematics

__all__ = [
    "FourBar",
    "coupler_curve",
    "fourbar_positions",
    "loop_closure_error",
    "spring_loaded_fourbar",
    "basic_balancer",
    "balanced_parallelogram",
    "compose_zfl_springs",
    "composing_anchor",
    "composed_springs_lever",
    "plagiograph_map",
    "balanced_plagiograph",
    "Technique2Parameters",
    "technique1",
    "technique1_feasible",
    "technique1_family",
    "technique2_parameters",
    "technique2",
    "technique2_family",
    "Technique3Parameters",
    "technique3_parameters",
    "technique3",
    "technique3_family",
    "herder",
    "gravity_technique2",
    "gravity_as_spring_limit",
    "serial_2r_technique2",
    "slider_crank_technique2",
    "watt_fourbar",
    "watt_prototype",
    "example_fourbar",
]

_BASES = ("A", "B")


def _c(p) -> complex:
    return complex(p[0], p[1])


def _xy(c: complex) -> tuple[float, float]:
    """A complex number as a point; round-off below 1e-15 m is set to an exact zero."""
    x, y = float(c.real), float(c.imag)
    return (0.0 if abs(x) < 1e-15 else x, 0.0 if abs(y) < 1e-15 else y)


def _numeric_only(lib):
    if lib is not np:
        raise NotImplementedError("this design's kinematics is numeric only; its energy is checked "
                                  "numerically by balance_report()")


def _base(name: str, value: str) -> str:
    if value not in _BASES:
        raise ValueError(f"{name} must be 'A' or 'B' (a ground pivot of the four-bar), got {value!r}")
    return value


# --------------------------------------------------------------------------- four-bar
@dataclass(frozen=True)
class FourBar:
    """Geometry of a four-bar ``A-D-C-B`` with a coupler point ``E``.

    Parameters
    ----------
    A, B : (float, float)
        Ground pivots of the crank and of the rocker (m).
    crank, coupler, rocker : float
        Link lengths ``|AD|``, ``|DC|``, ``|BC|`` (m), > 0.
    coupler_point : (float, float)
        ``E`` in the coupler's frame: origin ``D``, x-axis along ``DC`` (m).
    branch : {1, -1}
        Assembly branch, as in :class:`balancelab.FourBarKinematics`.
    circuit : float, optional
        A crank angle (rad) inside the interval of crank angles wanted. When the crank
        cannot turn fully its reachable angles may form two separate intervals (two
        circuits); by default the widest is used.

    Raises
    ------
    ValueError
        If the four-bar cannot assemble for any crank angle.

    Examples
    --------
    >>> fb = FourBar((0, 0), (0.4, 0), 0.15, 0.35, 0.3, (0.2, 0.1))
    >>> round(abs(fb.z), 4)
    0.6389
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
            object.__setattr__(self, name, finite_real(f"{name} length (m)", getattr(self, name), positive=True))
        object.__setattr__(self, "coupler_point", planar_point("coupler_point E (coupler frame, m)",
                                                          self.coupler_point))
        if isinstance(self.branch, bool) or self.branch not in (1, -1):
            raise ValueError(f"branch must be +1 or -1, got {self.branch!r}")
        object.__setattr__(self, "branch", int(self.branch))
        r1 = math.dist(self.A, self.B)
        if r1 == 0:
            raise ValueError("ground pivots A and B coincide; a four-bar needs two distinct pivots")
        # the distance from the crank tip to B spans [|r1 - r2|, r1 + r2]; the dyad closes
        # over [|r3 - r4|, r3 + r4]; the four-bar assembles iff the two intervals overlap
        lo, hi = abs(r1 - self.crank), r1 + self.crank
        if hi < abs(self.coupler - self.rocker) or lo > self.coupler + self.rocker:
            raise ValueError(
                f"this four-bar cannot assemble: crank {self.crank:.4g} m, coupler {self.coupler:.4g} m, "
                f"rocker {self.rocker:.4g} m, ground {r1:.4g} m (each link must be shorter than the "
                "sum of the other three)")

    @cached_property
    def kinematics(self) -> FourBarKinematics:
        """The closed-form position analysis (bodies 0 ground, 1 crank, 2 coupler, 3 rocker)."""
        return FourBarKinematics(self.A, self.B, self.crank, self.coupler, self.rocker, self.branch,
                                 circuit=self.circuit)

    @property
    def z(self) -> complex:
        """Complex ratio ``(E - D) / (C - D)`` fixed by the coupler triangle."""
        return _c(self.coupler_point) / self.coupler

    def joints(self) -> list[Joint]:
        """The four revolute joints (A, D, C, B) of the design bodies 0-3."""
        return [Joint(0, self.A, 1, (0.0, 0.0)), Joint(1, (self.crank, 0.0), 2, (0.0, 0.0)),
                Joint(2, (self.coupler, 0.0), 3, (self.rocker, 0.0)), Joint(3, (0.0, 0.0), 0, self.B)]

    def labels(self) -> dict:
        """Named points A, B, D, C, E for figures."""
        return {"A": (0, self.A), "B": (0, self.B), "D": (1, (self.crank, 0.0)),
                "C": (2, (self.coupler, 0.0)), "E": (2, self.coupler_point)}

    def state(self, q) -> dict:
        """Global points (complex arrays) and link angles at crank angles ``q`` (rad).

        Returns a dict with ``A, B, D, C, E`` (complex), ``th2, th3, th4`` (crank,
        coupler and rocker angles) and ``ok`` (reachable mask).
        """
        q = np.asarray(q, dtype=float)
        P, ok = self.kinematics.poses(q[..., None])
        D = P[..., 2, 0] + 1j * P[..., 2, 1]
        th2, th3, th4 = P[..., 1, 2], P[..., 2, 2], P[..., 3, 2]
        C = D + self.coupler * np.exp(1j * th3)
        E = D + self.coupler * self.z * np.exp(1j * th3)
        return {"A": _c(self.A), "B": _c(self.B), "D": D, "C": C, "E": E,
                "th2": th2, "th3": th3, "th4": th4, "ok": ok, "poses": P}

    def pivot(self, name: str) -> complex:
        """Ground pivot ``"A"`` or ``"B"`` as a complex number."""
        return _c(self.A if _base("pivot", name) == "A" else self.B)

    def check_triangle(self) -> None:
        """Raise ValueError when the coupler point coincides with ``D`` or ``C``."""
        scale = self.coupler
        if abs(self.z) * scale < 1e-12 * scale:
            raise ValueError("degenerate coupler triangle: the coupler point E coincides with the "
                             "crank-coupler joint D")
        if abs(self.z - 1) * scale < 1e-12 * scale:
            raise ValueError("degenerate coupler triangle: the coupler point E coincides with the "
                             "coupler-rocker joint C")


def example_fourbar() -> FourBar:
    """A crank-rocker used by the worked examples (Grashof, crank turns fully).

    Returns
    -------
    FourBar
        ``A = (0, 0)``, ``B = (0.4, 0)``, crank 0.1 m, coupler 0.35 m, rocker 0.3 m,
        ``E = (0.2, 0.12)`` in the coupler frame (an assumed geometry: the paper's
        figures carry no dimensions).

    Examples
    --------
    >>> example_fourbar().crank
    0.1
    """
    return FourBar((0.0, 0.0), (0.4, 0.0), 0.1, 0.35, 0.3, (0.2, 0.12))


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
    >>> coupler_curve(example_fourbar(), 5).shape
    (5, 2)
    """
    if isinstance(n, bool) or not isinstance(n, (int, np.integer)) or n < 2:
        raise ValueError(f"n must be an integer >= 2, got {n!r}")
    lo, hi = fourbar.kinematics.q_range[0]
    E = fourbar.state(np.linspace(lo, hi, n))["E"]
    return np.stack([E.real, E.imag], axis=-1)


def _dc(fourbar: FourBar, q):
    q = np.asarray(q, dtype=float)
    r2, r3, r4 = fourbar.crank, fourbar.coupler, fourbar.rocker
    Ax, Ay = fourbar.A
    Bx, By = fourbar.B
    Dx = np.cos(q)
    Dx *= r2
    Dx += Ax
    Dy = np.sin(q)
    Dy *= r2
    Dy += Ay
    dx, dy = Bx - Dx, By - Dy
    L2 = dx * dx + dy * dy
    inv = 1.0 / np.sqrt(L2)
    a = (0.5 * (r3 * r3 - r4 * r4) + 0.5 * L2) * inv
    h2 = r3 * r3 - a * a
    ok = h2 >= -1e-12 * r3 * r3
    np.maximum(h2, 0.0, out=h2)
    h = np.sqrt(h2)
    if fourbar.branch < 0:
        h = -h
    a *= inv
    h *= inv
    Cx = Dx + a * dx - h * dy
    Cy = Dy + a * dy + h * dx
    return Dx, Dy, Cx, Cy, ok


def fourbar_positions(fourbar: FourBar, q) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """Joint and coupler-point positions of a four-bar at crank angles ``q``, fast.

    The rocker tip is the intersection of the circles ``|C - D| = coupler`` and
    ``|C - B| = rocker``: ``C = D + (a d + branch h d_perp) / |d|`` with ``d = B - D``,
    ``a = (coupler^2 - rocker^2 + |d|^2) / (2 |d|)`` and ``h = sqrt(coupler^2 - a^2)``. No
    inverse trigonometric function is needed, which makes it the fastest way to place
    many configurations (same branch convention as :class:`balancelab.FourBarKinematics`).

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
    >>> D, C, E, ok = fourbar_positions(example_fourbar(), [0.0, 1.0])
    >>> bool(ok.all()), C.shape
    (True, (2, 2))
    """
    Dx, Dy, Cx, Cy, ok = _dc(fourbar, q)
    r3 = fourbar.coupler
    zr, zi = fourbar.coupler_point[0] / r3, fourbar.coupler_point[1] / r3
    vx, vy = Cx - Dx, Cy - Dy
    Ex = Dx + zr * vx - zi * vy
    Ey = Dy + zi * vx + zr * vy
    return (np.stack([Dx, Dy], -1), np.stack([Cx, Cy], -1), np.stack([Ex, Ey], -1), ok)


def loop_closure_error(fourbar: FourBar, q) -> np.ndarray:
    """Largest violation (m) of the four-bar's link lengths at crank angles ``q``.

    Places the joints with :func:`fourbar_positions` and returns, per configuration,
    ``max(| |C - D| - coupler |, | |C - B| - rocker |)``: round-off for a correct solution.

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
    >>> float(loop_closure_error(example_fourbar(), [0.0, 2.0]).max()) < 1e-15
    True
    """
    Dx, Dy, Cx, Cy, ok = _dc(fourbar, q)
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


def _fourbar_design(name, fourbar: FourBar, springs, *, labels=None, parameters=None, reference="",
                    loads=(), driver=None) -> Design:
    lab = fourbar.labels()
    lab.update(labels or {})
    kin = fourbar.kinematics if driver is None else driver
    return Design(name, ("ground", "crank", "coupler", "rocker"), fourbar.joints(), kin,
                  loads, springs, labels=lab, parameters=parameters, reference=reference)


def _load_spring(fourbar: FourBar, K, k_l: float) -> Spring:
    return Spring(k_l, 0.0, (0, K), (2, fourbar.coupler_point), name="k_l")


def spring_loaded_fourbar(fourbar: FourBar, K, k_l: float) -> Design:
    """The four-bar loaded by a ZFL spring ``k_l`` from its coupler point ``E`` to ``K``.

    Without balancing springs its energy ``k_l/2 |E - K|^2`` is constant only if the
    coupler curve is a circle about ``K``, which it is not in general (Deepak Sec. 2.2,
    Fig. 10); ``parameters["distance_spread"]`` gives ``max |KE| - min |KE|``.

    Parameters
    ----------
    fourbar : FourBar
    K : (float, float)
        Ground anchor of the load spring (m).
    k_l : float
        Load spring stiffness (N/m), > 0.

    Returns
    -------
    Design

    Examples
    --------
    >>> d = spring_loaded_fourbar(example_fourbar(), (0.1, -0.2), 100.0)
    >>> d.balance_report().balanced
    False
    """
    K = planar_point("K (load spring anchor, m)", K)
    k_l = finite_real("k_l (load spring stiffness, N/m)", k_l, positive=True)
    E = coupler_curve(fourbar, 2001)
    dist = np.hypot(E[:, 0] - K[0], E[:, 1] - K[1])
    return _fourbar_design("spring-loaded four-bar (unbalanced)", fourbar, [_load_spring(fourbar, K, k_l)],
                           labels={"K": (0, K)},
                           parameters={"k_l": k_l, "distance_spread": float(np.ptp(dist))},
                           reference="Deepak & Ananthasuresh 2012, Sec. 2.2, Fig. 10")


# --------------------------------------------------------------------- building blocks
def basic_balancer(k: float, length: float, anchor_distance: float, angle: float = math.pi / 2) -> Design:
    """The basic spring force balancer (Deepak Fig. 4).

    A lever ``AD`` turns about ``A`` (the origin); two equal ZFL springs ``k`` run from
    ``D`` to the ground points ``P`` and ``N`` placed symmetrically about ``A``
    (``AN = -AP``). Their pull ``k (P - D) + k (N - D) = 2 k (A - D)`` always points at
    ``A``, so the lever is balanced: the energy is ``k (|AD|^2 + |AP|^2)``.

    Parameters
    ----------
    k : float
        Stiffness of each spring (N/m), > 0.
    length : float
        ``|AD|`` (m), > 0.
    anchor_distance : float
        ``|AP| = |AN|`` (m), > 0.
    angle : float
        Direction of ``AP`` from the x-axis (rad).

    Returns
    -------
    Design

    Examples
    --------
    >>> basic_balancer(50.0, 0.3, 0.2).balance_report().balanced
    True
    """
    k = finite_real("k (N/m)", k, positive=True)
    length = finite_real("length |AD| (m)", length, positive=True)
    a = finite_real("anchor_distance |AP| (m)", anchor_distance, positive=True)
    angle = finite_real("angle (rad)", angle)
    P = _xy(a * complex(math.cos(angle), math.sin(angle)))
    N = (-P[0], -P[1])
    kin = TreeKinematics(2, [Joint(0, (0.0, 0.0), 1, (0.0, 0.0))], [[0.0], [1.0]], ("phi",),
                         ((-math.pi, math.pi),))
    springs = [Spring(k, 0.0, (0, P), (1, (length, 0.0)), name="k_P"),
               Spring(k, 0.0, (0, N), (1, (length, 0.0)), name="k_N")]
    return Design("basic spring force balancer", ("ground", "lever"), [Joint(0, (0.0, 0.0), 1, (0.0, 0.0))],
                  kin, (), springs, labels={"A": (0, (0.0, 0.0)), "P": (0, P), "N": (0, N),
                                            "D": (1, (length, 0.0))},
                  parameters={"k": k, "energy": k * (length ** 2 + a ** 2)},
                  reference="Deepak & Ananthasuresh 2012, Sec. 2.1, Fig. 4")


def balanced_parallelogram(k: float, a: float, b: float, angle: float = 0.0, dof: int = 1) -> Design:
    """A parallelogram ``ADEN`` with equal ZFL springs on its two diagonals (Figs 6, 7).

    With ``u = D - A`` and ``w = N - A`` the diagonals are ``u + w`` and ``u - w``;
    ``|u + w|^2 + |u - w|^2 = 2 (|u|^2 + |w|^2)`` is constant, so two springs of equal
    stiffness on the diagonals balance each other whatever the shape of the
    parallelogram.

    Parameters
    ----------
    k : float
        Stiffness of each diagonal spring (N/m), > 0.
    a : float
        ``|AD|`` (m), > 0.
    b : float
        ``|AN|`` (m), > 0.
    angle : float
        With ``dof=1``, the direction of the ground side ``AN`` (rad).
    dof : {1, 2}
        1: ``AN`` is the ground, ``AD`` a crank, ``DE`` a coupler and ``NE`` a rocker
        (Fig. 6; springs ``A-E`` and ``D-N``). 2: ``AD`` and ``AN`` both turn about ``A``
        (Fig. 7; springs ``A-E`` and ``D-N``, the latter between two moving links).

    Returns
    -------
    Design

    Examples
    --------
    >>> balanced_parallelogram(40.0, 0.2, 0.3, dof=2).balance_report().balanced
    True
    """
    k = finite_real("k (N/m)", k, positive=True)
    a = finite_real("a = |AD| (m)", a, positive=True)
    b = finite_real("b = |AN| (m)", b, positive=True)
    angle = finite_real("angle (rad)", angle)
    ref = "Deepak & Ananthasuresh 2012, Sec. 2.1, Figs 6-7"
    if dof == 1:
        N = _xy(b * complex(math.cos(angle), math.sin(angle)))
        joints = [Joint(0, (0.0, 0.0), 1, (0.0, 0.0)), Joint(1, (a, 0.0), 2, (0.0, 0.0)),
                  Joint(2, (b, 0.0), 3, (a, 0.0)), Joint(3, (0.0, 0.0), 0, N)]
        kin = TreeKinematics(4, joints[:3] + [joints[3]], [[0.0], [1.0], [0.0], [1.0]], ("phi",),
                             ((-math.pi, math.pi),), angle_offset=[0.0, 0.0, angle, 0.0])
        springs = [Spring(k, 0.0, (0, (0.0, 0.0)), (2, (b, 0.0)), name="k_AE"),
                   Spring(k, 0.0, (1, (a, 0.0)), (0, N), name="k_DN")]
        return Design("balanced parallelogram (1 dof)", ("ground", "AD", "DE", "NE"), joints, kin, (),
                      springs, labels={"A": (0, (0.0, 0.0)), "N": (0, N), "D": (1, (a, 0.0)),
                                       "E": (2, (b, 0.0))},
                      parameters={"k": k, "energy": k * (a * a + b * b)}, reference=ref)
    if dof != 2:
        raise ValueError(f"dof must be 1 or 2, got {dof!r}")
    joints = [Joint(0, (0.0, 0.0), 1, (0.0, 0.0)), Joint(0, (0.0, 0.0), 2, (0.0, 0.0)),
              Joint(1, (a, 0.0), 3, (0.0, 0.0)), Joint(2, (b, 0.0), 4, (0.0, 0.0)),
              Joint(3, (b, 0.0), 4, (a, 0.0))]
    kin = TreeKinematics(5, joints, [[0, 0], [1, 0], [0, 1], [0, 1], [1, 0]], ("phi_1", "phi_2"),
                         ((-math.pi, math.pi), (-math.pi, math.pi)))
    springs = [Spring(k, 0.0, (0, (0.0, 0.0)), (3, (b, 0.0)), name="k_AE"),
               Spring(k, 0.0, (1, (a, 0.0)), (2, (b, 0.0)), name="k_DN")]
    return Design("balanced parallelogram (2 dof)", ("ground", "AD", "AN", "DE", "NE"), joints, kin, (),
                  springs, labels={"A": (0, (0.0, 0.0)), "D": (1, (a, 0.0)), "N": (2, (b, 0.0)),
                                   "E": (3, (b, 0.0))},
                  parameters={"k": k, "energy": k * (a * a + b * b)}, reference=ref)


def compose_zfl_springs(k1: float, anchor1, k2: float, anchor2) -> tuple[float, tuple[float, float], float]:
    """Compose two ZFL springs that share their moving end into one (Deepak Sec. 2.1.1).

    ``k1/2 |E - P1|^2 + k2/2 |E - P2|^2 = (k1 + k2)/2 |E - P|^2 + c`` for every ``E``, with
    ``P = (k1 P1 + k2 P2) / (k1 + k2)`` and the constant
    ``c = k1 k2 |P1 - P2|^2 / (2 (k1 + k2))``.

    Parameters
    ----------
    k1, k2 : float
        Stiffnesses (N/m), > 0.
    anchor1, anchor2 : (float, float)
        Fixed anchors (m).

    Returns
    -------
    (float, (float, float), float)
        Equivalent stiffness (N/m), equivalent anchor (m) and the constant ``c`` (J).

    Examples
    --------
    >>> compose_zfl_springs(1.0, (0, 0), 3.0, (4, 0))
    (4.0, (3.0, 0.0), 6.0)
    """
    k1 = finite_real("k1 (N/m)", k1, positive=True)
    k2 = finite_real("k2 (N/m)", k2, positive=True)
    p1, p2 = np.array(planar_point("anchor1", anchor1)), np.array(planar_point("anchor2", anchor2))
    k = k1 + k2
    P = (k1 * p1 + k2 * p2) / k
    c = k1 * k2 * float(np.sum((p1 - p2) ** 2)) / (2 * k)
    return k, (float(P[0]), float(P[1])), c


def composing_anchor(k1: float, anchor1, target, k2: float) -> tuple[float, float]:
    """Anchor of a second spring ``k2`` that moves spring ``k1``'s anchor to ``target``.

    From ``k1 (target - anchor1) = -k2 (target - anchor2)`` (Deepak Sec. 2.1.1, with
    ``D = target``): ``anchor2 = target + k1/k2 (target - anchor1)``.

    Parameters
    ----------
    k1 : float
        Stiffness of the given spring (N/m), > 0.
    anchor1 : (float, float)
        Its anchor (m).
    target : (float, float)
        Desired anchor of the equivalent spring (m).
    k2 : float
        Stiffness of the added spring (N/m), > 0.

    Returns
    -------
    (float, float)

    Examples
    --------
    >>> composing_anchor(1.0, (0, 0), (3, 0), 3.0)
    (4.0, 0.0)
    """
    k1 = finite_real("k1 (N/m)", k1, positive=True)
    k2 = finite_real("k2 (N/m)", k2, positive=True)
    a1, t = np.array(planar_point("anchor1", anchor1)), np.array(planar_point("target", target))
    p = t + k1 / k2 * (t - a1)
    return float(p[0]), float(p[1])


def composed_springs_lever(k1: float, anchor1, k2: float, length: float) -> Design:
    """A lever about the origin balanced by two unequal ZFL springs composed onto its pivot.

    Spring ``k1`` runs from ``anchor1`` to the lever's tip; spring ``k2`` from the anchor
    given by :func:`composing_anchor` (target: the pivot). Their composition is a spring
    of stiffness ``k1 + k2`` from the pivot to the tip, of constant length: the lever is
    balanced. With ``k1 = k2`` this is the basic balancer of Fig. 4.

    Parameters
    ----------
    k1 : float
        Stiffness of the first spring (N/m), > 0.
    anchor1 : (float, float)
        Its ground anchor (m), not the pivot.
    k2 : float
        Stiffness of the second spring (N/m), > 0.
    length : float
        Lever length (m), > 0.

    Returns
    -------
    Design

    Examples
    --------
    >>> composed_springs_lever(30.0, (0.0, 0.2), 10.0, 0.25).balance_report().balanced
    True
    """
    length = finite_real("length (m)", length, positive=True)
    a1 = planar_point("anchor1", anchor1)
    if a1 == (0.0, 0.0):
        raise ValueError("anchor1 is on the pivot: the spring is already balanced on its own")
    a2 = composing_anchor(k1, a1, (0.0, 0.0), k2)
    kin = TreeKinematics(2, [Joint(0, (0.0, 0.0), 1, (0.0, 0.0))], [[0.0], [1.0]], ("phi",),
                         ((-math.pi, math.pi),))
    springs = [Spring(k1, 0.0, (0, a1), (1, (length, 0.0)), name="k1"),
               Spring(k2, 0.0, (0, a2), (1, (length, 0.0)), name="k2")]
    return Design("lever balanced by a composition of two ZFL springs", ("ground", "lever"),
                  [Joint(0, (0.0, 0.0), 1, (0.0, 0.0))], kin, (), springs,
                  labels={"A": (0, (0.0, 0.0)), "P1": (0, a1), "P2": (0, a2), "E": (1, (length, 0.0))},
                  parameters={"k1": k1, "k2": k2, "k_equivalent": k1 + k2, "anchor2_x": a2[0],
                              "anchor2_y": a2[1]},
                  reference="Deepak & Ananthasuresh 2012, Sec. 2.1.1, Fig. 8")


def plagiograph_map(m: float, alpha: float, base, point) -> tuple[float, float]:
    """Image of ``point`` under a plagiograph based at ``base``: ``PN = m R_alpha(PM)`` (eq. 1).

    Parameters
    ----------
    m : float
        Scale (-), > 0.
    alpha : float
        Rotation (rad), counter-clockwise positive.
    base : (float, float)
        Base pivot ``P`` (m).
    point : (float, float)
        Input point ``M`` (m).

    Returns
    -------
    (float, float)
        Output point ``N`` (m).

    Examples
    --------
    >>> [round(v, 12) for v in plagiograph_map(2.0, math.pi / 2, (0, 0), (1, 0))]
    [0.0, 2.0]
    """
    m = finite_real("m (scale)", m, positive=True)
    alpha = finite_real("alpha (rad)", alpha)
    P, M = _c(planar_point("base", base)), _c(planar_point("point", point))
    return _xy(P + m * np.exp(1j * alpha) * (M - P))


def balanced_plagiograph(a: float, b: float, m: float, alpha: float, K, k_l: float, h: float,
                         parallelogram: str = "P") -> Design:
    """A two-degree-of-freedom plagiograph carrying a ZFL load spring, balanced (Sec. 2.1.2).

    Parallelogram ``PQRS`` (``P`` at the origin, ``PQ = a``, ``QR = b``); the input
    point ``M`` is on link ``QR`` with ``RQ / MQ = m`` and ``angle RQM = alpha``; the output
    ``N`` on link ``SR`` with ``NS / RS = m`` and ``angle NSR = alpha``, so that
    ``PN = m R_alpha(PM)`` (eq. 1). A load spring ``k_l`` from ``K`` to ``M`` has the energy
    of a spring ``k_l/m^2`` from ``L = P + m R_alpha(PK)`` to ``N``; that spring is balanced
    as in technique 2 on the two-link chain ``P-S-N``: spring 1 ``k_b`` from ``H`` to ``N`` with
    ``k_b (H - P) = k_l/m^2 (P - L)`` and spring 2 ``k_t = k_b + k_l/m^2`` from ``P`` to
    ``T = 2S - N``. Balanced for both degrees of freedom.

    Parameters
    ----------
    a, b : float
        ``|PQ|``, ``|QR|`` (m), > 0.
    m : float
        Scale (-), > 0.
    alpha : float
        Rotation (rad).
    K : (float, float)
        Anchor of the load spring (m); must not map onto ``P``.
    k_l : float
        Load spring stiffness (N/m), > 0.
    h : float
        Distance ``|PH|`` along the locus of ``H`` (m), > 0.
    parallelogram : {"P"}
        Base of the balanced parallelogram (only the base pivot ``P`` is offered).

    Returns
    -------
    Design

    Examples
    --------
    >>> d = balanced_plagiograph(0.2, 0.3, 1.5, 0.4, (0.1, -0.3), 80.0, 0.1)
    >>> d.balance_report().balanced
    True
    """
    a = finite_real("a = |PQ| (m)", a, positive=True)
    b = finite_real("b = |QR| (m)", b, positive=True)
    m = finite_real("m (scale)", m, positive=True)
    alpha = finite_real("alpha (rad)", alpha)
    K = planar_point("K (m)", K)
    k_l = finite_real("k_l (N/m)", k_l, positive=True)
    if parallelogram != "P":
        raise ValueError(f"parallelogram must be 'P', got {parallelogram!r}")
    rho = m * np.exp(1j * alpha)
    # M on link QR: (M - Q) = (R - Q) / rho   ->  local (b / rho) in QR's frame
    M_loc = _xy(b / rho)
    # N on link SR: N - S = rho (R - S)        ->  local (a rho) in SR's frame
    N_loc = _xy(a * rho)
    L = rho * _c(K)
    k_e = k_l / m ** 2
    H, k_b, k_t = _t2_core(0j, L, k_e, h)
    # bodies: 1 PQ (q1), 2 QR (q2), 3 PS (q2), 4 SR (q1)
    joints = [Joint(0, (0.0, 0.0), 1, (0.0, 0.0)), Joint(0, (0.0, 0.0), 3, (0.0, 0.0)),
              Joint(1, (a, 0.0), 2, (0.0, 0.0)), Joint(3, (b, 0.0), 4, (0.0, 0.0)),
              Joint(2, (b, 0.0), 4, (a, 0.0))]
    kin = TreeKinematics(5, joints, [[0, 0], [1, 0], [0, 1], [0, 1], [1, 0]], ("q_1", "q_2"),
                         ((-math.pi, math.pi), (-math.pi, math.pi)))
    T_loc = (-N_loc[0], -N_loc[1])
    springs = [Spring(k_l, 0.0, (0, K), (2, M_loc), name="k_l"),
               Spring(k_b, 0.0, (0, _xy(H)), (4, N_loc), name="k_b"),
               Spring(k_t, 0.0, (0, (0.0, 0.0)), (4, T_loc), name="k_t")]
    return Design("balanced plagiograph", ("ground", "PQ", "QRM", "PS", "SRN"), joints, kin, (), springs,
                  labels={"P": (0, (0.0, 0.0)), "K": (0, K), "L": (0, _xy(L)), "H": (0, _xy(H)),
                          "M": (2, M_loc), "N": (4, N_loc), "T": (4, T_loc)},
                  parameters={"m": m, "alpha": alpha, "k_l": k_l, "k_b": k_b, "k_t": k_t, "h": h,
                              "L_x": L.real, "L_y": L.imag, "H_x": H.real, "H_y": H.imag},
                  reference="Deepak & Ananthasuresh 2012, Sec. 2.1.2 (eq. 1) with eqs 5-8")


# ----------------------------------------------------------------------- technique 2
def _t2_core(W: complex, L: complex, k_e: float, h) -> tuple[complex, float, float]:
    """Balancing spring 1 anchor, k_b and k_t for an equivalent load spring k_e at L.

    ``k_b (H - W) = k_e (W - L)`` (eq. 2 / 6); ``k_b = k_e |LW| / |WH|`` (eq. 3 / 7);
    ``k_t = k_b + k_e`` (eq. 4 corrected / 8).
    """
    h = finite_real("h (distance WH along the locus of H, m)", h)
    d = W - L
    dist = abs(d)
    if dist <= 1e-12 * max(1.0, abs(W)):
        raise ValueError("the load spring's (equivalent) anchor coincides with the parallelogram's base "
                         "pivot W: the locus of H is undefined (no balancing spring 1 is needed; a single "
                         "spring k_t = k_l from W to T balances it)")
    if h == 0:
        raise ValueError("h = 0 puts H on the pivot W and needs an infinite stiffness k_b = k_l |KW| / |WH|; "
                         "choose h > 0")
    if h < 0:
        raise ValueError(f"h = {h} puts H on the wrong side of W: k_b = k_l |KW| / |WH| would be negative "
                         "(eq. 3 says H must lie along the direction from K to W); choose h > 0")
    H = W + h * d / dist
    k_b = k_e * dist / h
    if not math.isfinite(k_b) or k_b <= 0:
        raise ValueError(f"h = {h} gives a stiffness k_b = {k_b} that is not finite and positive")
    return H, k_b, k_b + k_e


class Technique2Parameters(NamedTuple):
    """Balancing parameters of technique 2 (Deepak eqs 2-4).

    ``W`` base pivot, ``H`` anchor of balancing spring 1 (on ``E``), ``k_b`` and ``k_t``
    (N/m); balancing spring 2 runs from ``W`` to ``T`` (coupler frame, m);
    ``direction`` the unit vector of the locus of ``H`` (``K`` to ``W``).
    """

    W: tuple
    H: tuple
    k_b: float
    k_t: float
    T: tuple
    direction: tuple


def technique2_parameters(fourbar: FourBar, K, k_l: float, base: str = "A", h: float = 0.1
                          ) -> Technique2Parameters:
    """Balancing parameters of technique 2, parallelogram based at ``base`` (eqs 2-4).

    ``H = W + h (W - K)/|W - K|`` (eq. 2: the locus starts at ``W`` along ``KW``),
    ``k_b = k_l |KW| / h`` (eq. 3) and ``k_t = k_b + k_l`` (eq. 4 as derived; the paper
    prints ``k_b = k_b + k_l``). Spring 2 runs from ``W`` to ``T``, the reflection of ``E``
    through ``D`` (base ``A``) or through ``C`` (base ``B``).

    Parameters
    ----------
    fourbar : FourBar
    K : (float, float)
        Load spring anchor (m); must not coincide with ``W``.
    k_l : float
        Load spring stiffness (N/m), > 0.
    base : {"A", "B"}
        Where the balanced parallelogram is based.
    h : float
        Free parameter: distance ``|WH|`` (m), > 0 (``h <= 0`` means infinite or negative
        ``k_b`` and raises ValueError).

    Returns
    -------
    Technique2Parameters

    Examples
    --------
    >>> p = technique2_parameters(example_fourbar(), (0.1, -0.2), 100.0, "A", 0.1)
    >>> round(p.k_b, 3), round(p.k_t, 3)
    (223.607, 323.607)
    """
    K = planar_point("K (load spring anchor, m)", K)
    k_l = finite_real("k_l (load spring stiffness, N/m)", k_l, positive=True)
    base = _base("base", base)
    W = fourbar.pivot(base)
    H, k_b, k_t = _t2_core(W, _c(K), k_l, h)
    ex, ey = fourbar.coupler_point
    T = (-ex, -ey) if base == "A" else (2 * fourbar.coupler - ex, -ey)
    d = (W - _c(K)) / abs(W - _c(K))
    return Technique2Parameters(_xy(W), _xy(H), k_b, k_t, T, _xy(d))


def technique2(fourbar: FourBar, K, k_l: float, base: str = "A", h: float = 0.1, *, driver=None) -> Design:
    """The spring-loaded four-bar balanced by technique 2: no auxiliary link, two springs.

    See :func:`technique2_parameters` for the equations. Springs: the load ``k_l``
    (``K`` to ``E``), balancing spring 1 ``k_b`` (``H`` to ``E``) and balancing spring 2
    ``k_t`` (``W`` to ``T`` on the coupler, Deepak Fig. 16).

    Parameters
    ----------
    fourbar, K, k_l, base, h
        As in :func:`technique2_parameters`.
    driver : Kinematics, optional
        Kinematics placing the four-bar's bodies 0-3 (by default ``fourbar.kinematics``);
        the cognates use one driven by another cognate's crank.

    Returns
    -------
    Design

    Examples
    --------
    >>> technique2(example_fourbar(), (0.1, -0.2), 100.0, "B", 0.05).balance_report().balanced
    True
    """
    p = technique2_parameters(fourbar, K, k_l, base, h)
    K = planar_point("K", K)
    springs = [_load_spring(fourbar, K, k_l),
               Spring(p.k_b, 0.0, (0, p.H), (2, fourbar.coupler_point), name="k_b"),
               Spring(p.k_t, 0.0, (0, p.W), (2, p.T), name="k_t")]
    return _fourbar_design(
        f"spring-loaded four-bar, technique 2 (parallelogram at {base})", fourbar, springs, driver=driver,
        labels={"K": (0, K), "H": (0, p.H), "W": (0, p.W), "T": (2, p.T)},
        parameters={"k_l": float(k_l), "k_b": p.k_b, "k_t": p.k_t, "h": float(h), "H_x": p.H[0],
                    "H_y": p.H[1]},
        reference="Deepak & Ananthasuresh 2012, Sec. 2.2.2, eqs 2-4 (eq. 4 corrected: k_t = k_b + k_l)")


def _family(core, h_values):
    h = np.atleast_1d(np.asarray(h_values, dtype=float))
    if h.ndim != 1:
        raise ValueError(f"h_values must be a 1-D sequence of lengths (m), got shape {h.shape}")
    if not np.all(np.isfinite(h)):
        raise ValueError(f"h_values must be finite lengths (m), got {h.tolist()}")
    H = np.full((len(h), 2), np.nan)
    kb = np.full(len(h), np.nan)
    kt = np.full(len(h), np.nan)
    ok = np.zeros(len(h), dtype=bool)
    for i, hi in enumerate(h):
        try:
            Hc, b, t = core(hi)
        except ValueError:
            continue
        H[i], kb[i], kt[i], ok[i] = _xy(Hc), b, t, True
    return {"h": h, "H": H, "k_b": kb, "k_t": kt, "feasible": ok}


def technique2_family(fourbar: FourBar, K, k_l: float, base: str, h_values) -> dict:
    """The one-parameter family of technique 2 as a function of ``h = |WH|``.

    Parameters
    ----------
    fourbar, K, k_l, base
        As in :func:`technique2_parameters`.
    h_values : array_like
        Values of the free parameter (m), finite (ValueError otherwise; values <= 0
        are reported infeasible).

    Returns
    -------
    dict
        ``h``, ``H`` (n, 2), ``k_b``, ``k_t`` (NaN where infeasible) and the boolean
        ``feasible`` (False for ``h <= 0``: negative or infinite stiffness).

    Examples
    --------
    >>> f = technique2_family(example_fourbar(), (0.1, -0.2), 100.0, "A", [-0.1, 0.0, 0.1])
    >>> f["feasible"].tolist()
    [False, False, True]
    """
    K = _c(planar_point("K", K))
    k_l = finite_real("k_l (N/m)", k_l, positive=True)
    W = fourbar.pivot(base)
    _t2_core(W, K, k_l, 1.0)  # raise now if the locus is undefined
    return _family(lambda h: _t2_core(W, K, k_l, h), h_values)


# ----------------------------------------------------------------------- technique 1
def _technique1_P(K: complex, E, l1: float, l2: float, branch: int):
    d = E - K
    dist = np.abs(d)
    safe = np.where(dist > 0, dist, 1.0)
    a = (l2 * l2 - l1 * l1 + dist * dist) / (2 * safe)
    hh = l2 * l2 - a * a
    ok = (hh >= -1e-14 * l2 * l2) & (dist > 0)
    e = d / safe
    P = K + e * (a + 1j * branch * np.sqrt(np.clip(hh, 0.0, None)))
    return P, ok


def technique1_feasible(fourbar: FourBar, K, l1: float, l2: float) -> bool:
    """True when the auxiliary dyad of technique 1 assembles over the whole crank range.

    The dyad ``K-P-E`` closes when ``|l1 - l2| <= |KE| <= l1 + l2`` for every point of the
    coupler curve.

    Parameters
    ----------
    fourbar : FourBar
    K : (float, float)
        Load spring anchor (m).
    l1, l2 : float
        ``|PE|`` and ``|PK|`` (m), > 0.

    Returns
    -------
    bool

    Raises
    ------
    ValueError
        If ``l1`` or ``l2`` is not a finite positive length.

    Examples
    --------
    >>> technique1_feasible(example_fourbar(), (0.1, -0.2), 0.3, 0.3)
    True
    """
    K = planar_point("K", K)
    l1 = finite_real("l1 = |PE| (m)", l1, positive=True)
    l2 = finite_real("l2 = |PK| (m)", l2, positive=True)
    E = coupler_curve(fourbar, 4001)
    dist = np.hypot(E[:, 0] - K[0], E[:, 1] - K[1])
    return bool(dist.min() > abs(l1 - l2) and dist.max() < l1 + l2)


def technique1_family(fourbar: FourBar, K, k_l: float, l1_values, l2_values) -> dict:
    """The two-parameter family of technique 1 over a grid of ``l1``, ``l2``.

    The balancing spring always has the load spring's stiffness ``k_l``; a member is
    feasible when the auxiliary dyad assembles along the whole coupler curve
    (``|l1 - l2| < |KE| < l1 + l2``).

    Parameters
    ----------
    fourbar : FourBar
    K : (float, float)
        Load spring anchor (m).
    k_l : float
        Load spring stiffness (N/m), > 0.
    l1_values, l2_values : array_like
        Values of ``|PE|`` and ``|PK|`` (m).

    Returns
    -------
    dict
        ``l1``, ``l2`` (1-D), ``feasible`` (bool, shape ``(len(l1), len(l2))``), ``k_b``
        (``k_l`` where feasible, NaN elsewhere) and the span ``KE_min``, ``KE_max`` (m).

    Examples
    --------
    >>> f = technique1_family(example_fourbar(), (0.1, -0.2), 100.0, [0.05, 0.3], [0.05, 0.3])
    >>> f["feasible"].tolist()
    [[False, False], [False, True]]
    """
    K = planar_point("K (load spring anchor, m)", K)
    k_l = finite_real("k_l (N/m)", k_l, positive=True)
    l1 = np.atleast_1d(np.asarray(l1_values, dtype=float))
    l2 = np.atleast_1d(np.asarray(l2_values, dtype=float))
    for name, v in (("l1_values", l1), ("l2_values", l2)):
        if v.ndim != 1 or not np.all(np.isfinite(v)):
            raise ValueError(f"{name} must be a 1-D sequence of finite lengths (m), got {v.tolist()}")
    E = coupler_curve(fourbar, 4001)
    dist = np.hypot(E[:, 0] - K[0], E[:, 1] - K[1])
    L1, L2 = np.meshgrid(l1, l2, indexing="ij")
    ok = (L1 > 0) & (L2 > 0) & (dist.min() > np.abs(L1 - L2)) & (dist.max() < L1 + L2)
    return {"l1": l1, "l2": l2, "feasible": ok, "k_b": np.where(ok, k_l, np.nan),
            "KE_min": float(dist.min()), "KE_max": float(dist.max())}


def technique1(fourbar: FourBar, K, k_l: float, l1: float, l2: float, branch: int = 1) -> Design:
    """The spring-loaded four-bar balanced by technique 1 (Deepak Sec. 2.2.1, Fig. 12).

    Two auxiliary links: ``KP`` (length ``l2``, pivoted on the ground at ``K``) and ``PET``
    (pivoted to ``KP`` at ``P`` and to the coupler at ``E``, ``|PE| = |PT| = l1``). With
    ``Q = K + E - P`` the parallelogram ``KPEQ`` has the load spring on the diagonal
    ``KE``; a spring of the same stiffness ``k_l`` on the other diagonal balances it
    (``|KE|^2 + |PQ|^2 = 2 (l1^2 + l2^2)``), and ``PQ = T - K`` lets it run from ``K`` to
    ``T`` instead. The family is two-parameter (``l1``, ``l2`` free); it is feasible when
    the dyad assembles along the whole coupler curve.

    Parameters
    ----------
    fourbar : FourBar
    K : (float, float)
        Load spring anchor (m).
    k_l : float
        Load spring stiffness (N/m), > 0; the balancing spring has the same.
    l1, l2 : float
        ``|PE|`` and ``|PK|`` (m), > 0.
    branch : {1, -1}
        Side of ``KE`` on which ``P`` lies.

    Returns
    -------
    Design

    Raises
    ------
    ValueError
        If the dyad cannot assemble over the whole crank range.

    Examples
    --------
    >>> technique1(example_fourbar(), (0.1, -0.2), 100.0, 0.3, 0.3).balance_report().balanced
    True
    """
    K = planar_point("K (load spring anchor, m)", K)
    k_l = finite_real("k_l (N/m)", k_l, positive=True)
    l1 = finite_real("l1 = |PE| (m)", l1, positive=True)
    l2 = finite_real("l2 = |PK| (m)", l2, positive=True)
    if branch not in (1, -1):
        raise ValueError(f"branch must be +1 or -1, got {branch!r}")
    if not technique1_feasible(fourbar, K, l1, l2):
        E = coupler_curve(fourbar, 4001)
        dist = np.hypot(E[:, 0] - K[0], E[:, 1] - K[1])
        raise ValueError(f"technique 1 with l1 = {l1} m, l2 = {l2} m cannot assemble: |KE| spans "
                         f"[{dist.min():.4g}, {dist.max():.4g}] m but the dyad closes only for "
                         f"|l1 - l2| < |KE| < l1 + l2 = [{abs(l1 - l2):.4g}, {l1 + l2:.4g}] m")
    Kc = _c(K)
    kin4 = fourbar.kinematics

    def pose_fn(q, lib):
        _numeric_only(lib)
        qq = np.stack(q, axis=-1)
        P4, _ = kin4.poses(qq)
        D = P4[..., 2, 0] + 1j * P4[..., 2, 1]
        E = D + fourbar.coupler * fourbar.z * np.exp(1j * P4[..., 2, 2])
        P, _ = _technique1_P(Kc, E, l1, l2, branch)
        out = [tuple(P4[..., i, j] for j in range(3)) for i in range(4)]
        out.append((np.full(P.shape, K[0]), np.full(P.shape, K[1]), np.angle(P - Kc)))
        out.append((P.real, P.imag, np.angle(E - P)))
        return out

    def valid_fn(q):
        P4, ok = kin4.poses(q)
        D = P4[..., 2, 0] + 1j * P4[..., 2, 1]
        E = D + fourbar.coupler * fourbar.z * np.exp(1j * P4[..., 2, 2])
        return ok & _technique1_P(Kc, E, l1, l2, branch)[1]

    kin = ExplicitKinematics(6, ("theta",), kin4.q_range, pose_fn, valid_fn)
    joints = fourbar.joints() + [Joint(0, K, 4, (0.0, 0.0)), Joint(4, (l2, 0.0), 5, (0.0, 0.0)),
                                 Joint(5, (l1, 0.0), 2, fourbar.coupler_point)]
    springs = [_load_spring(fourbar, K, k_l), Spring(k_l, 0.0, (0, K), (5, (-l1, 0.0)), name="k_b")]
    lab = fourbar.labels()
    lab.update({"K": (0, K), "P": (4, (l2, 0.0)), "T": (5, (-l1, 0.0))})
    return Design("spring-loaded four-bar, technique 1", ("ground", "crank", "coupler", "rocker", "KP", "PET"),
                  joints, kin, (), springs, labels=lab,
                  parameters={"k_l": k_l, "k_b": k_l, "l1": l1, "l2": l2},
                  reference="Deepak & Ananthasuresh 2012, Sec. 2.2.1, Figs 11-12")


# ----------------------------------------------------------------------- technique 3
class Technique3Parameters(NamedTuple):
    """Balancing parameters of technique 3 (Deepak eqs 5-8).

    ``U`` plagiograph base, ``W`` parallelogram base, ``m`` and ``alpha`` the
    plagiograph's scale and rotation, ``L`` the anchor of the equivalent load spring
    ``k_l/m^2``, ``H``, ``k_b``, ``k_t`` as in technique 2; ``G`` and ``T`` are the
    attachments of the two balancing springs on the auxiliary link ``SRG`` (its frame:
    origin ``S``, x-axis towards ``R``), ``R_local`` the joint with the coupler.
    """

    U: tuple
    W: tuple
    m: float
    alpha: float
    L: tuple
    H: tuple
    k_b: float
    k_t: float
    G: tuple
    T: tuple
    R_local: tuple
    direction: tuple


def _t3_setup(fourbar: FourBar, K, plagiograph_base: str):
    fourbar.check_triangle()
    U = fourbar.pivot(_base("plagiograph_base", plagiograph_base))
    rho = 1 / fourbar.z if plagiograph_base == "A" else 1 / (1 - fourbar.z)
    L = U + rho * (_c(K) - U)
    return U, rho, L


def technique3_parameters(fourbar: FourBar, K, k_l: float, plagiograph_base: str = "A",
                          parallelogram_base: str = "A", h: float = 0.1) -> Technique3Parameters:
    """Balancing parameters of technique 3 (Deepak Sec. 2.2.3, eqs 5-8).

    A plagiograph completed on the four-bar with base ``U`` makes the point ``G`` of an
    auxiliary link follow ``UG = m R_alpha(UE)`` (eq. 1). With base ``A``:
    ``m = |DC|/|DE|`` and ``alpha`` the counter-clockwise angle that turns ``DE`` onto ``DC``
    (``m e^{i alpha} = 1/z``); with base ``B``: ``m = |CD|/|CE|`` and ``alpha`` the angle that
    turns ``CE`` onto ``CD`` (``m e^{i alpha} = 1/(1 - z)``; Fig. 18 calls it angle ``ECD``,
    clockwise in its drawing). The load
    spring then has the energy of a spring ``k_l/m^2`` from ``L`` (``UL = m R_alpha(UK)``,
    eq. 5) to ``G``, which technique 2 balances with the parallelogram based at ``W``:
    ``WH = k_l/(m^2 k_b) LW`` (eq. 6), ``k_b = k_l |LW| / (m^2 |WH|)`` (eq. 7),
    ``k_t = k_b + k_l/m^2`` (eq. 8).

    Parameters
    ----------
    fourbar : FourBar
        The coupler point must not coincide with ``D`` or ``C``.
    K : (float, float)
        Load spring anchor (m).
    k_l : float
        Load spring stiffness (N/m), > 0.
    plagiograph_base, parallelogram_base : {"A", "B"}
        ``U`` and ``W``.
    h : float
        Free parameter ``|WH|`` (m), > 0.

    Returns
    -------
    Technique3Parameters

    Examples
    --------
    >>> p = technique3_parameters(example_fourbar(), (0.1, -0.2), 100.0, "A", "B", 0.1)
    >>> round(p.m, 4)
    1.5006
    """
    K = planar_point("K (load spring anchor, m)", K)
    k_l = finite_real("k_l (N/m)", k_l, positive=True)
    U, rho, L = _t3_setup(fourbar, K, plagiograph_base)
    W = fourbar.pivot(_base("parallelogram_base", parallelogram_base))
    m = abs(rho)
    k_e = k_l / m ** 2
    H, k_b, k_t = _t2_core(W, L, k_e, h)
    ell = fourbar.crank if plagiograph_base == "A" else fourbar.rocker
    g = ell * rho
    T = -g if plagiograph_base == parallelogram_base else 2 * ell - g
    d = (W - L) / abs(W - L)
    return Technique3Parameters(_xy(U), _xy(W), float(m), float(np.angle(rho)), _xy(L), _xy(H), k_b, k_t,
                                _xy(g), _xy(T), (ell, 0.0), _xy(d))


def technique3(fourbar: FourBar, K, k_l: float, plagiograph_base: str = "A",
               parallelogram_base: str = "A", h: float = 0.1, *, driver=None) -> Design:
    """The spring-loaded four-bar balanced by technique 3 (Deepak Fig. 17d / Fig. 18).

    Two auxiliary links complete a plagiograph: link 4 from ``U`` parallel to ``DC``
    (length ``|DC|``), link 5 from its tip ``S`` parallel to the crank (base ``A``) or to
    the rocker (base ``B``), jointed to the coupler at ``C`` (base ``A``) or ``D`` (base
    ``B``). Both balancing springs act on link 5. Equations: see
    :func:`technique3_parameters`.

    Parameters
    ----------
    fourbar, K, k_l, plagiograph_base, parallelogram_base, h
        As in :func:`technique3_parameters`.
    driver : Kinematics, optional
        As in :func:`technique2`.

    Returns
    -------
    Design

    Examples
    --------
    >>> d = technique3(example_fourbar(), (0.1, -0.2), 100.0, "B", "A", 0.1)
    >>> d.balance_report().balanced
    True
    """
    p = technique3_parameters(fourbar, K, k_l, plagiograph_base, parallelogram_base, h)
    K = planar_point("K", K)
    kin4 = fourbar.kinematics if driver is None else driver
    UA = plagiograph_base == "A"
    U = _c(p.U)
    r3 = fourbar.coupler

    def pose_fn(q, lib):
        _numeric_only(lib)
        P4, _ = kin4.poses(np.stack(q, axis=-1))
        th3 = P4[..., 2, 2]
        a4 = th3 if UA else th3 + math.pi
        S = U + r3 * np.exp(1j * a4)
        a5 = P4[..., 1, 2] if UA else P4[..., 3, 2]
        out = [tuple(P4[..., i, j] for j in range(3)) for i in range(4)]
        out.append((np.full(S.shape, U.real), np.full(S.shape, U.imag), a4))
        out.append((S.real, S.imag, a5))
        return out

    kin = ExplicitKinematics(6, kin4.names, kin4.q_range, pose_fn, lambda q: kin4.poses(q)[1])
    R_on_coupler = (r3, 0.0) if UA else (0.0, 0.0)
    joints = fourbar.joints() + [Joint(0, p.U, 4, (0.0, 0.0)), Joint(4, (r3, 0.0), 5, (0.0, 0.0)),
                                 Joint(5, p.R_local, 2, R_on_coupler)]
    springs = [_load_spring(fourbar, K, k_l), Spring(p.k_b, 0.0, (0, p.H), (5, p.G), name="k_b"),
               Spring(p.k_t, 0.0, (0, p.W), (5, p.T), name="k_t")]
    lab = fourbar.labels()
    lab.update({"K": (0, K), "L": (0, p.L), "H": (0, p.H), "U": (0, p.U), "W": (0, p.W),
                "S": (4, (r3, 0.0)), "G": (5, p.G), "T": (5, p.T)})
    return Design(f"spring-loaded four-bar, technique 3 (plagiograph at {plagiograph_base}, "
                  f"parallelogram at {parallelogram_base})",
                  ("ground", "crank", "coupler", "rocker", "US", "SRG"), joints, kin, (), springs, labels=lab,
                  parameters={"k_l": float(k_l), "k_b": p.k_b, "k_t": p.k_t, "m": p.m, "alpha": p.alpha,
                              "h": float(h), "H_x": p.H[0], "H_y": p.H[1], "L_x": p.L[0], "L_y": p.L[1]},
                  reference="Deepak & Ananthasuresh 2012, Sec. 2.2.3, eqs 5-8, Figs 17-18")


def technique3_family(fourbar: FourBar, K, k_l: float, plagiograph_base: str, parallelogram_base: str,
                      h_values) -> dict:
    """The one-parameter family of a technique-3 option as a function of ``h = |WH|``.

    Parameters
    ----------
    fourbar, K, k_l, plagiograph_base, parallelogram_base
        As in :func:`technique3_parameters`.
    h_values : array_like
        Values of the free parameter (m), finite (ValueError otherwise; values <= 0
        are reported infeasible).

    Returns
    -------
    dict
        As :func:`technique2_family`.

    Examples
    --------
    >>> f = technique3_family(example_fourbar(), (0.1, -0.2), 100.0, "A", "A", [0.0, 0.2])
    >>> f["feasible"].tolist()
    [False, True]
    """
    K = planar_point("K", K)
    k_l = finite_real("k_l (N/m)", k_l, positive=True)
    U, rho, L = _t3_setup(fourbar, K, plagiograph_base)
    W = fourbar.pivot(_base("parallelogram_base", parallelogram_base))
    k_e = k_l / abs(rho) ** 2
    _t2_core(W, L, k_e, 1.0)
    return _family(lambda h: _t2_core(W, L, k_e, h), h_values)


def herder(fourbar: FourBar, K, k_l: float, pivot: str = "A", h: float = 0.1) -> Design:
    """Herder's method (Herder 1998): technique 3 with coinciding bases ``U = W = pivot``.

    Herder balances a plagiograph first and then reduces it to the four-bar; the result
    is the technique-3 option whose plagiograph and balanced parallelogram share a base
    (Deepak Sec. 2.2.3), so Herder's method gives two of technique 3's four options:
    ``(A, A)`` and ``(B, B)``. The geometry of the auxiliary links and the attachments
    ``G``, ``T`` are fixed; ``H`` moves on a straight line (Fig. 2b).

    Parameters
    ----------
    fourbar, K, k_l, h
        As in :func:`technique3_parameters`.
    pivot : {"A", "B"}
        The common base.

    Returns
    -------
    Design

    Examples
    --------
    >>> herder(example_fourbar(), (0.1, -0.2), 100.0, "B", 0.1).balance_report().balanced
    True
    """
    pivot = _base("pivot", pivot)
    d = technique3(fourbar, K, k_l, pivot, pivot, h)
    return d.replace(name=f"spring-loaded four-bar, Herder's method (base {pivot})",
                     reference="Herder 1998, as technique 3 with U = W (Deepak & Ananthasuresh 2012, "
                               "Sec. 2.2.3, Fig. 2b)")


# --------------------------------------------------------------- gravity, 2R, slider
def gravity_technique2(fourbar: FourBar, mass: float, k_b: float, base: str = "A") -> Design:
    """A weight at the coupler point balanced by technique 2: the limit of a far spring (Sec. 4).

    A load spring ``k_l = m g / R`` anchored a distance ``R`` below ``W`` pulls on ``E``
    with ``k_l (K - E) -> (0, -m g)`` as ``R -> oo``: gravity is the limit of a ZFL spring
    load. Eqs 2-4 then give ``k_b (H - W) = (0, m g)``, i.e. ``H`` straight above ``W``
    at the height ``m g / k_b``, and ``k_t = k_b``.

    Parameters
    ----------
    fourbar : FourBar
    mass : float
        Mass at the coupler point (kg), > 0.
    k_b : float
        Chosen stiffness of balancing spring 1 (N/m), > 0 (the free parameter).
    base : {"A", "B"}
        Base of the balanced parallelogram.

    Returns
    -------
    Design

    Examples
    --------
    >>> gravity_technique2(example_fourbar(), 2.0, 400.0).balance_report().balanced
    True
    """
    mass = finite_real("mass (kg)", mass, positive=True)
    k_b = finite_real("k_b (N/m)", k_b, positive=True)
    base = _base("base", base)
    W = fourbar.pivot(base)
    H = W + 1j * mass * G / k_b
    ex, ey = fourbar.coupler_point
    T = (-ex, -ey) if base == "A" else (2 * fourbar.coupler - ex, -ey)
    springs = [Spring(k_b, 0.0, (0, _xy(H)), (2, fourbar.coupler_point), name="k_b"),
               Spring(k_b, 0.0, (0, _xy(W)), (2, T), name="k_t")]
    loads = [Load(2, fourbar.coupler_point, (0.0, -mass * G), "m", kind="weight")]
    return _fourbar_design(f"four-bar with a weight, technique 2 (parallelogram at {base})", fourbar,
                           springs, loads=loads, labels={"H": (0, _xy(H)), "W": (0, _xy(W)), "T": (2, T)},
                           parameters={"mass": mass, "k_b": k_b, "k_t": k_b, "H_x": H.real, "H_y": H.imag},
                           reference="Deepak & Ananthasuresh 2012, Sec. 4 (gravity as a limiting spring load)")


def gravity_as_spring_limit(fourbar: FourBar, mass: float, k_b: float, R: float, base: str = "A") -> Design:
    """Technique 2 for a load spring ``m g / R`` anchored ``R`` below ``W``.

    As ``R`` grows the springs and anchors tend to those of :func:`gravity_technique2`:
    ``H`` is the same, ``k_t = k_b + m g / R -> k_b``, and the load spring's energy differs
    from the weight's by a constant plus ``m g |E - W|^2 / (2 R)``.

    Parameters
    ----------
    fourbar : FourBar
    mass : float
        Mass whose weight the spring stands for (kg), > 0.
    k_b : float
        Balancing spring 1 stiffness (N/m), > 0.
    R : float
        Distance of the anchor below ``W`` (m), > 0.
    base : {"A", "B"}

    Returns
    -------
    Design

    Examples
    --------
    >>> d = gravity_as_spring_limit(example_fourbar(), 2.0, 400.0, 100.0)
    >>> round(d.parameters["k_t"] - 400.0, 4)
    0.1962
    """
    mass = finite_real("mass (kg)", mass, positive=True)
    k_b = finite_real("k_b (N/m)", k_b, positive=True)
    R = finite_real("R (m)", R, positive=True)
    W = fourbar.pivot(_base("base", base))
    K = W - 1j * R
    k_l = mass * G / R
    return technique2(fourbar, _xy(K), k_l, base, mass * G / k_b).replace(
        name=f"four-bar, load spring {R:g} m below {base} (gravity limit)")


def serial_2r_technique2(A, l1: float, l2: float, coupler_point, K, k_l: float, h: float) -> Design:
    """A spring-loaded 2R arm balanced by technique 2 based at its pivot (Deepak Sec. 4).

    Removing the rocker from a four-bar balanced by technique 2 based at ``A`` leaves a
    2R arm ``A-D-E`` that stays balanced for both of its angles: the rocker took no part
    in the balance.

    Parameters
    ----------
    A : (float, float)
        Ground pivot (m).
    l1 : float
        ``|AD|`` (m), > 0.
    l2 : float
        Length of link 2 (its x-axis, m), > 0.
    coupler_point : (float, float)
        ``E`` in link 2's frame (origin ``D``, m).
    K : (float, float)
        Load spring anchor (m), not ``A``.
    k_l : float
        Load spring stiffness (N/m), > 0.
    h : float
        ``|AH|`` (m), > 0.

    Returns
    -------
    Design

    Examples
    --------
    >>> serial_2r_technique2((0, 0), 0.2, 0.3, (0.2, 0.1), (0.1, -0.2), 100.0, 0.1).balance_report().balanced
    True
    """
    A = planar_point("A", A)
    l1 = finite_real("l1 (m)", l1, positive=True)
    finite_real("l2 (m)", l2, positive=True)
    E = planar_point("coupler_point", coupler_point)
    K = planar_point("K", K)
    k_l = finite_real("k_l (N/m)", k_l, positive=True)
    H, k_b, k_t = _t2_core(_c(A), _c(K), k_l, h)
    joints = [Joint(0, A, 1, (0.0, 0.0)), Joint(1, (l1, 0.0), 2, (0.0, 0.0))]
    kin = TreeKinematics(3, joints, [[0, 0], [1, 0], [0, 1]], ("theta_1", "theta_2"),
                         ((-math.pi, math.pi), (-math.pi, math.pi)))
    T = (-E[0], -E[1])
    springs = [Spring(k_l, 0.0, (0, K), (2, E), name="k_l"), Spring(k_b, 0.0, (0, _xy(H)), (2, E), name="k_b"),
               Spring(k_t, 0.0, (0, A), (2, T), name="k_t")]
    return Design("spring-loaded 2R arm, technique 2", ("ground", "link 1", "link 2"), joints, kin, (), springs,
                  labels={"A": (0, A), "K": (0, K), "H": (0, _xy(H)), "D": (1, (l1, 0.0)), "E": (2, E),
                          "T": (2, T)},
                  parameters={"k_l": k_l, "k_b": k_b, "k_t": k_t, "h": float(h)},
                  reference="Deepak & Ananthasuresh 2012, Sec. 4 (2R linkages)")


def slider_crank_technique2(crank: float, coupler: float, offset: float, coupler_point, K, k_l: float,
                            h: float) -> Design:
    """A spring-loaded slider-crank balanced by technique 2 based at the crank pivot (Sec. 4).

    The crank ``AD`` turns about the origin; the coupler ``DC`` ends at ``C`` on a slider
    moving along the line ``y = offset``. The slider is an extra constraint on a
    balanced 2R arm, so the balance survives. The crank must turn fully
    (``coupler >= crank + |offset|``).

    Parameters
    ----------
    crank, coupler : float
        ``|AD|``, ``|DC|`` (m), > 0.
    offset : float
        Height of the slider's line (m).
    coupler_point : (float, float)
        ``E`` in the coupler frame (origin ``D``, x-axis to ``C``, m).
    K : (float, float)
        Load spring anchor (m), not the origin.
    k_l : float
        Load spring stiffness (N/m), > 0.
    h : float
        ``|AH|`` (m), > 0.

    Returns
    -------
    Design
        Bodies: ground, crank, coupler, slider (its frame at ``C``, angle 0).

    Examples
    --------
    >>> slider_crank_technique2(0.1, 0.3, 0.05, (0.1, 0.05), (0.2, -0.2), 100.0, 0.1).balance_report().balanced
    True
    """
    r2 = finite_real("crank (m)", crank, positive=True)
    r3 = finite_real("coupler (m)", coupler, positive=True)
    e = finite_real("offset (m)", offset)
    E = planar_point("coupler_point", coupler_point)
    K = planar_point("K", K)
    k_l = finite_real("k_l (N/m)", k_l, positive=True)
    if r3 < r2 + abs(e):
        raise ValueError(f"the crank cannot turn fully: need coupler >= crank + |offset| "
                         f"({r3} < {r2 + abs(e)})")
    H, k_b, k_t = _t2_core(0j, _c(K), k_l, h)

    def pose_fn(q, lib):
        _numeric_only(lib)
        th = q[0]
        Dx, Dy = r2 * np.cos(th), r2 * np.sin(th)
        Cx = Dx + np.sqrt(np.clip(r3 * r3 - (e - Dy) ** 2, 0.0, None))
        phi = np.arctan2(e - Dy, Cx - Dx)
        z = np.zeros_like(th)
        return [(z, z, z), (z, z, th), (Dx, Dy, phi), (Cx, z + e, z)]

    kin = ExplicitKinematics(4, ("theta",), ((-math.pi, math.pi),), pose_fn)
    joints = [Joint(0, (0.0, 0.0), 1, (0.0, 0.0)), Joint(1, (r2, 0.0), 2, (0.0, 0.0)),
              Joint(2, (r3, 0.0), 3, (0.0, 0.0))]
    T = (-E[0], -E[1])
    springs = [Spring(k_l, 0.0, (0, K), (2, E), name="k_l"), Spring(k_b, 0.0, (0, _xy(H)), (2, E), name="k_b"),
               Spring(k_t, 0.0, (0, (0.0, 0.0)), (2, T), name="k_t")]
    return Design("spring-loaded slider-crank, technique 2", ("ground", "crank", "coupler", "slider"), joints,
                  kin, (), springs,
                  labels={"A": (0, (0.0, 0.0)), "K": (0, K), "H": (0, _xy(H)), "E": (2, E), "T": (2, T),
                          "C": (3, (0.0, 0.0))},
                  parameters={"k_l": k_l, "k_b": k_b, "k_t": k_t, "h": float(h), "offset": e},
                  reference="Deepak & Ananthasuresh 2012, Sec. 4 (slider-crank linkages)")


# ---------------------------------------------------------------------- Watt prototype
def watt_fourbar(rocker: float = 0.1, coupler: float = 0.05) -> FourBar:
    """Watt's straight-line four-bar: two equal rockers, the coupler point at mid-coupler.

    In the middle position both rockers are horizontal and point at each other's
    side, the coupler is vertical and its midpoint moves on a nearly straight vertical
    line. Pivots ``A = (0, 0)`` and ``B = (2 rocker, coupler)``.

    Parameters
    ----------
    rocker : float
        Length of each rocker (m), > 0.
    coupler : float
        Length of the coupler (m), > 0.

    Returns
    -------
    FourBar

    Examples
    --------
    >>> watt_fourbar().B
    (0.2, 0.05)
    """
    rocker = finite_real("rocker (m)", rocker, positive=True)
    coupler = finite_real("coupler (m)", coupler, positive=True)
    return FourBar((0.0, 0.0), (2 * rocker, coupler), rocker, coupler, rocker, (coupler / 2, 0.0), branch=1)


def watt_prototype(k: float = 200.0, rocker: float = 0.1, coupler: float = 0.05, K=(0.1, -0.15)) -> Design:
    """The prototype of Deepak Sec. 2.3: Watt's linkage balanced by technique 2 in the ratio 1:1:2.

    Technique 2 based at ``A`` with ``|AH| = |KA|``, i.e. ``H`` the reflection of ``K``
    through ``A``: eq. 3 gives ``k_b = k_l`` and eq. 4 (corrected) ``k_t = 2 k_l``, so three
    identical springs do, one of them used at half its length (twice the stiffness).
    Spring 1 shares the coupler point ``E`` with the load spring and spring 2's
    attachment ``T`` is the mirror of ``E`` about the joint ``D``, as in the prototype,
    and every spring is drawn as a string over a pulley (Fig. 20). The dimensions are
    assumed (the paper gives none).

    Parameters
    ----------
    k : float
        Stiffness of the load spring (N/m), > 0.
    rocker, coupler : float
        Link lengths (m) of :func:`watt_fourbar`.
    K : (float, float)
        Load spring anchor (m).

    Returns
    -------
    Design

    Examples
    --------
    >>> d = watt_prototype()
    >>> [round(d.parameters[n] / d.parameters["k_l"], 12) for n in ("k_l", "k_b", "k_t")]
    [1.0, 1.0, 2.0]
    """
    fb = watt_fourbar(rocker, coupler)
    K = planar_point("K", K)
    d = technique2(fb, K, k, "A", math.hypot(*K))
    # the prototype realized all three ZFL springs with strings over pulleys (Fig. 20)
    springs = [Spring(s.k, 0.0, s.a, s.b, name=s.name, realization="pulley") for s in d.springs]
    return d.replace(name="Watt straight-line four-bar, technique 2 (1:1:2 prototype)", springs=springs,
                     reference="Deepak & Ananthasuresh 2012, Sec. 2.3, Figs 19-20")


# ------------------------------------------------------------------- catalog
def _on_example_fourbar(method, *args) -> Design:
    """``method`` applied to :func:`example_fourbar` with the load spring ``k_l = 100 N/m`` from
    ``K = (0.1, -0.2)`` m (an assumed geometry)."""
    return method(example_fourbar(), (0.1, -0.2), 100.0, *args)


def _register_examples() -> None:
    T = "(Deepak & Ananthasuresh 2012)"
    reg = lambda name, title, fn, *args, **kw: register(name, title, fn, chapter=5, args=args, **kw)  # noqa: E731
    reg("deepak_spring_loaded_fourbar", f"A spring-loaded four-bar before balancing {T}",
        _on_example_fourbar, spring_loaded_fourbar, expected_balanced=False)
    reg("deepak_basic_balancer", "Basic spring force balancer (Deepak & Ananthasuresh, Fig. 4)",
        basic_balancer, 50.0, 0.3, 0.2)
    reg("deepak_balanced_parallelogram", "Balanced parallelogram (Deepak & Ananthasuresh, Figs 6-7)",
        balanced_parallelogram, 40.0, 0.2, 0.3, kwargs={"dof": 2})
    reg("deepak_composed_springs", "Two ZFL springs composed into one (Deepak & Ananthasuresh, Sec. 2.1.1)",
        composed_springs_lever, 30.0, (0.05, 0.2), 10.0, 0.25)
    reg("deepak_plagiograph", "Balanced plagiograph (Deepak & Ananthasuresh, Sec. 2.1.2, eq. 1)",
        balanced_plagiograph, 0.2, 0.3, 1.5, 0.4, (0.1, -0.3), 80.0, 0.1)
    reg("deepak_technique1", f"Technique 1 on the example four-bar {T}", _on_example_fourbar, technique1,
        0.3, 0.3)
    for base in _BASES:
        reg(f"deepak_technique2_{base}", f"Technique 2 based at {base} on the example four-bar {T}",
            _on_example_fourbar, technique2, base, 0.1)
    for U in _BASES:
        for W in _BASES:
            reg(f"deepak_technique3_{U}{W}", f"Technique 3 ({U}, {W}) on the example four-bar {T}",
                _on_example_fourbar, technique3, U, W, 0.1)
    for base in _BASES:
        reg(f"deepak_herder_{base}", f"Herder's design based at {base} on the example four-bar {T}",
            _on_example_fourbar, herder, base, 0.1)
    reg("deepak_watt_prototype", f"The Watt 1:1:2 prototype {T}", watt_prototype)
    reg("deepak_gravity_fourbar", "Gravity load as the limit of a spring load (Deepak & Ananthasuresh, "
        "Sec. 4)", _gravity_example)


def _gravity_example() -> Design:
    return gravity_technique2(example_fourbar(), 2.0, 400.0, "A")


_register_examples()
