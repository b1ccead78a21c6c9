"""Making a ZFL spring real: string over a pulley, negative free length, ordinary springs.

Sources: Lecture 35 (*Theory of Mechanisms*), realizing a zero-free-length spring with
a string over a pulley and approximate balancing with regular (or gas) springs;
Deepak & Ananthasuresh 2012, Sec. 1.1 (a negative-free-length spring in parallel with an
ordinary one) and Sec. 2.3 / Fig. 20 (the pulley-and-string arrangement of the prototype).

**String over a pulley.** An ordinary spring hangs from the ground; a string tied to
its end comes down along a fixed line, wraps round a pulley of radius ``rho`` centred at
the virtual anchor and leaves it on the tangent towards the attachment ``C`` on the
moving link. The spring carries that geometry: ``Spring(..., realization=Pulley(rho,
spring_direction, turn))`` (:class:`balancelab.core.elements.Pulley`), read both by the
exact model here and by the drawing. The string's passed-over length (from where it
first touches the pulley to ``C``) is ``lambda = rho phi + sqrt(d^2 - rho^2)``, with ``d = |C - centre|`` and ``phi``
the wrap angle, which changes with the configuration. The spring's extension equals
``lambda`` when the arrangement is calibrated so that the passed-over length is zero
at zero tension, and its energy is ``k/2 lambda^2``. As ``rho -> 0``, ``lambda -> d`` and the
arrangement becomes the ideal ZFL spring; :func:`pulley_balance_error` measures how far
a finite pulley is from it.
"""
from __future__ import annotations

import math
from typing import NamedTuple

import numpy as np

from ..core.design import Design
from ..core.elements import G, Load, Pulley, Spring
from ..core.validation import MIN_POSITIVE, finite_real, finite_reals, instance_of, planar_point, planar_points, positive_int, real_array
from ..mechanisms.lever import lever_design
from .registry import register

__all__ = [
    "PulleyString",
    "pulley_string",
    "pulley_lever",
    "pulley_energy",
    "PulleyError",
    "pulley_balance_error",
    "pulley_error_curve",
    "negative_free_length_partner",
    "parallel_springs_lever",
    "ApproximationError",
    "approximate_lever",
]


# ------------------------------------------------------------------------ pulley
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


def pulley_string(center, radius: float, point, spring_direction=(0.0, 1.0), turn: int = 1) -> PulleyString:
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


def pulley_lever(mass: float = 2.0, length: float = 0.5, b: float = 0.3, c: float = 0.2,
                 radius: float = 0.01) -> Design:
    """The lecture's single link balanced by a ZFL spring realized with a string over a pulley.

    Link pivoted at the origin with ``mass`` at its tip, a distance ``length`` from the
    pivot; the virtual ZFL spring ``k = m g r / (b c)`` (``r = length``) runs from
    ``B = (0, b)`` (the pulley's centre) to ``C``, at ``c`` along the link. The real
    spring hangs above the pulley and its string comes down on the pulley's left side,
    wrapping counter-clockwise: the spring's realization is
    ``Pulley(radius, spring_direction=(0, 1), turn=1)``. The design's energy is that of
    the ideal spring; the exact string model is in :func:`pulley_energy` and
    :func:`pulley_balance_error`. Working range: the link on the right of the pivot,
    ``theta`` in ``[-90 deg, 90 deg]``.

    Parameters
    ----------
    mass : float
        Mass at the tip of the link (kg), > 0.
    length : float
        Length of the link: the distance of the mass from the pivot (m), > 0.
    b : float
        Height of the pulley's centre above the pivot (m), > ``c + radius``.
    c : float
        Attachment distance on the link (m), > 0.
    radius : float
        Pulley radius (m), >= 0.

    Returns
    -------
    Design
        ``parameters`` hold ``k``, ``b``, ``c``, ``r`` (= ``length``), ``pulley_radius`` and
        ``balance_error`` (the relative energy variation of the exact string model at
        this radius).

    Examples
    --------
    >>> d = pulley_lever(radius=0.005)
    >>> d.balance_report().balanced, d.parameters["balance_error"] < 0.05
    (True, True)
    >>> d.springs[0].pulley
    Pulley(radius=0.005, spring_direction=(0.0, 1.0), turn=1)
    """
    mass = finite_real("mass (kg)", mass, positive=True)
    r = finite_real("length (m)", length, positive=True)
    b = finite_real("b (m)", b, positive=True)
    c = finite_real("c (m)", c, positive=True)
    radius = finite_real("radius (m)", radius, nonnegative=True)
    if b <= c + radius:
        raise ValueError(f"the pulley must stay above the attachment: need b > c + radius "
                         f"({b} <= {c + radius})")
    k = mass * G * r / (b * c)
    pulley = Pulley(radius, spring_direction=(0.0, 1.0), turn=1)
    spring = Spring(k, 0.0, (0, (0.0, b)), (1, (c, 0.0)), name="k", realization=pulley)
    d = lever_design("lever with a ZFL spring realized by a string over a pulley",
                     [Load(1, (r, 0.0), (0.0, -mass * G), "m", kind="weight")], [spring],
                     q_range=(-math.pi / 2, math.pi / 2),
                     labels={"A": (0, (0.0, 0.0)), "B": (0, (0.0, b)), "C": (1, (c, 0.0))},
                     parameters={"k": k, "b": b, "c": c, "r": r, "pulley_radius": radius},
                     reference="Lecture 35 (string over a pulley); Deepak & Ananthasuresh 2012, Fig. 20")
    return d.replace(parameters={**d.parameters, "balance_error": pulley_balance_error(d, radius).variation})


def _pulley_springs(design: Design) -> list:
    pulleys = [s for s in instance_of("design", design, Design, "a balancelab Design").springs if s.pulley]
    if not pulleys:
        raise ValueError(f"{design.name}: no spring is realized by a pulley "
                         "(realization=Pulley(...) or 'pulley')")
    return pulleys


def pulley_energy(design: Design, q, radius: float | None = None):
    """Potential energy (J) with every spring realized by a pulley modelled exactly.

    Each such spring (``spring.pulley`` is a :class:`~balancelab.core.elements.Pulley`)
    has its first attachment, the pulley's centre, on the ground. Its energy is
    ``k/2 (lambda - free_length)^2`` with the passed-over length ``lambda`` of
    :func:`pulley_string` for its pulley's radius, spring direction and sense of
    wrapping; everything else is as in ``design.potential_energy``.

    Parameters
    ----------
    design : Design
    q : array_like
        Configurations (rad).
    radius : float, optional
        Pulley radius (m), >= 0, used for every pulley instead of its own.

    Returns
    -------
    numpy.ndarray

    Examples
    --------
    >>> d = pulley_lever(radius=0.0)
    >>> import numpy as np
    >>> bool(np.ptp(pulley_energy(d, np.linspace(-1, 1, 5))) < 1e-12)
    True
    """
    pulleys = _pulley_springs(design)
    q = real_array("q (configurations, rad)", q)
    if radius is not None:
        radius = finite_real("radius (m)", radius, nonnegative=True)
    others = [s for s in design.springs if s.pulley is None]
    base = design.replace(springs=others).potential_energy(q).total if (others or design.loads) else 0.0
    total = np.asarray(base, dtype=float)
    for s in pulleys:
        p = s.pulley
        C = design.world_points(q, [s.b])[..., 0, :]
        lam = pulley_string(s.a.point, p.radius if radius is None else radius, C, p.spring_direction,
                            p.turn).passed_over
        total = total + 0.5 * s.k * (lam - s.free_length) ** 2
    return total


class PulleyError(NamedTuple):
    """Balance error of a pulley-realized design at one radius.

    ``variation``: ``(max V - min V) / scale`` with ``scale`` as in
    :meth:`Design.balance_report`; ``residual_torque``: largest ``|dV/dq|`` (N m);
    ``radius`` (m).
    """

    radius: float
    variation: float
    residual_torque: float
    scale: float


def pulley_balance_error(design: Design, radius: float | None = None, n: int = 2001) -> PulleyError:
    """How far the exact string-over-pulley model is from balance, at pulley radius ``radius``.

    The energy is evaluated on ``n`` evenly spaced configurations over the design's
    range (one degree of freedom); the torque is its derivative by differences.

    Parameters
    ----------
    design : Design
        A one-dof design with a spring realized by a pulley (see :func:`pulley_lever`).
    radius : float, optional
        Pulley radius (m), >= 0; by default each pulley's own.
    n : int
        Number of configurations, >= 3.

    Returns
    -------
    PulleyError
        Tends to zero as the radius tends to zero. Its ``radius`` is ``radius``, or
        the largest radius of the design's pulleys.

    Examples
    --------
    >>> d = pulley_lever()
    >>> pulley_balance_error(d, 0.0).variation < 1e-12
    True
    """
    instance_of("design", design, Design, "a balancelab Design")
    if design.dof != 1:
        raise ValueError("pulley_balance_error handles one-degree-of-freedom designs")
    n = positive_int("n (configurations, at least MIN_CONFIGURATIONS = 10)", n, minimum=10)
    lo, hi = design.q_range[0]
    q = np.linspace(lo, hi, n)
    V = pulley_energy(design, q, radius)
    scale = design.balance_report(q[:, None]).scale
    torque = np.gradient(V, q)
    r = float(radius) if radius is not None else max(s.pulley.radius for s in _pulley_springs(design))
    return PulleyError(r, float(np.ptp(V) / scale), float(np.max(np.abs(torque))), scale)


def pulley_error_curve(design: Design, radii, n: int = 2001) -> dict:
    """Balance error of a pulley-realized design as a function of the pulley radius.

    Parameters
    ----------
    design : Design
        As in :func:`pulley_balance_error`.
    radii : array_like
        Pulley radii (m), >= 0.
    n : int
        Configurations per radius.

    Returns
    -------
    dict
        ``radius`` (m), ``variation`` (relative energy variation) and
        ``residual_torque`` (N m), arrays of the length of ``radii``; both errors tend to
        zero (linearly) with the radius.

    Examples
    --------
    >>> c = pulley_error_curve(pulley_lever(), [0.02, 0.01, 0.0])
    >>> bool(c["variation"][0] > c["variation"][1] > c["variation"][2])
    True
    """
    radii = np.atleast_1d(real_array("radii (m)", radii))
    errs = []
    for i, r in enumerate(radii):
        try:
            errs.append(pulley_balance_error(design, float(r), n))
        except ValueError as err:  # name the radius that fails
            raise ValueError(f"radii[{i}] = {r} m: {err}") from None
    return {"radius": radii, "variation": np.array([e.variation for e in errs]),
            "residual_torque": np.array([e.residual_torque for e in errs])}


# ------------------------------------------------------------- negative free length
def negative_free_length_partner(k: float, free_length: float, k_partner: float) -> float:
    """Free length of a spring that, in parallel with ``(k, free_length)``, makes a ZFL pair.

    Two springs between the same points pull with ``k (d - l0) + k' (d - l0')``; the
    pair is a ZFL spring of stiffness ``k + k'`` when ``k l0 + k' l0' = 0``, i.e.
    ``l0' = -k l0 / k'`` (negative for an ordinary ``l0 > 0``; Deepak Sec. 1.1).

    Parameters
    ----------
    k : float
        Stiffness of the given spring (N/m), > 0.
    free_length : float
        Its free length (m).
    k_partner : float
        Stiffness of the partner (N/m), > 0.

    Returns
    -------
    float
        The partner's free length (m).

    Examples
    --------
    >>> negative_free_length_partner(100.0, 0.05, 50.0)
    -0.1
    """
    k = finite_real("k (N/m)", k, positive=True)
    free_length = finite_real("free_length (m)", free_length)
    k_partner = finite_real("k_partner (N/m)", k_partner, positive=True)
    return -k * free_length / k_partner


def parallel_springs_lever(mass: float = 2.0, length: float = 0.5, b: float = 0.3, c: float = 0.2,
                           free_length: float = 0.05, share: float = 0.5) -> Design:
    """The single link balanced by an ordinary spring and a negative-free-length partner in parallel.

    The lecture's ZFL stiffness ``k = m g r / (b c)`` is split: ``k1 = share k`` with
    free length ``free_length > 0`` and ``k2 = (1 - share) k`` with the free length of
    :func:`negative_free_length_partner`. Together they are exactly a ZFL spring, so
    the link is balanced.

    Parameters
    ----------
    mass, length, b, c : float
        As in :func:`balancelab.lecture.single_link_spring`: the mass (kg) at the tip of
        the link of length ``length`` (m), the anchor height ``b`` and the attachment
        distance ``c`` (m), all > 0.
    free_length : float
        Free length of the ordinary spring (m), > 0.
    share : float
        Part of ``k`` carried by the ordinary spring, in (0, 1).

    Returns
    -------
    Design

    Examples
    --------
    >>> d = parallel_springs_lever()
    >>> d.balance_report().balanced, round(d.parameters["free_length_2"], 3)
    (True, -0.05)
    """
    mass = finite_real("mass (kg)", mass, positive=True)
    r = finite_real("length (m)", length, positive=True)
    b = finite_real("b (m)", b, positive=True)
    c = finite_real("c (m)", c, positive=True)
    free_length = finite_real("free_length (m)", free_length, positive=True)
    share = finite_real("share", share)
    if not 0 < share < 1:
        raise ValueError(f"share must be in (0, 1), got {share}")
    k = mass * G * r / (b * c)
    k1, k2 = share * k, (1 - share) * k
    if min(k1, k2) < MIN_POSITIVE:
        raise ValueError(f"share = {share} leaves a spring of stiffness {min(k1, k2):g} N/m: choose share "
                         "in (0, 1) away from its ends")
    l2 = negative_free_length_partner(k1, free_length, k2)
    springs = [Spring(k1, free_length, (0, (0.0, b)), (1, (c, 0.0)), name="k1"),
               Spring(k2, l2, (0, (0.0, b)), (1, (c, 0.0)), name="k2 (negative free length)")]
    return lever_design("lever with an ordinary and a negative-free-length spring in parallel",
                        [Load(1, (r, 0.0), (0.0, -mass * G), "m", kind="weight")], springs,
                        labels={"A": (0, (0.0, 0.0)), "B": (0, (0.0, b)), "C": (1, (c, 0.0))},
                        parameters={"k": k, "k1": k1, "k2": k2, "free_length_1": free_length,
                                    "free_length_2": l2},
                        reference="Deepak & Ananthasuresh 2012, Sec. 1.1; Lecture 35, k = m g r / (b c)")


# ---------------------------------------------------------- approximate balancing
class ApproximationError(RuntimeError):
    """Raised when the optimizer of an approximate balance does not converge."""


def _lever_torque(x, mass, r, l0, th):
    bx, by, ax, ay, k = x
    c, s = np.cos(th), np.sin(th)
    Ax, Ay = c * ax - s * ay, s * ax + c * ay
    dAx, dAy = -Ay, Ax
    dx, dy = Ax - bx, Ay - by
    d = np.hypot(dx, dy)
    f = k * (d - l0) / np.where(d > 0, d, 1e-300)
    return mass * G * r * c + f * (dx * dAx + dy * dAy)


def _lever_energy(x, mass, r, l0, th):
    bx, by, ax, ay, k = x
    c, s = np.cos(th), np.sin(th)
    Ax, Ay = c * ax - s * ay, s * ax + c * ay
    d = np.hypot(Ax - bx, Ay - by)
    return mass * G * r * s + 0.5 * k * (d - l0) ** 2


def approximate_lever(mass: float = 2.0, length: float = 0.5, theta_range=(-math.pi / 3, math.pi / 3),
                      free_length: float = 0.1, *, anchor_bounds=((-0.2, 0.2), (0.05, 0.3)),
                      attachment_bounds=((0.05, 0.3), (-0.05, 0.05)), k_bounds=(1.0, 5000.0),
                      realization: str = "coil", n: int = 181, maxiter: int = 500) -> Design:
    """Best ordinary-spring balance of a lever over a working range (scipy.optimize).

    The spring has a positive free length (a catalogue extension spring, or a gas
    spring working in compression), so no choice balances the lever exactly. The
    ground anchor ``(b_x, b_y)``, the attachment ``(a_x, a_y)`` on the link and ``k`` are
    chosen within bounds to minimize the mean square of the torque ``dV/dtheta`` over
    ``n`` angles in ``theta_range`` (L-BFGS-B, started from the ZFL design with the same
    anchor height). ``parameters`` report the residual torque (N m) and the energy
    variation (J) over the range, next to the same numbers for the exact ZFL design
    (``k = m g r / (b c)`` with ``r = length``), which are zero up to rounding.

    Parameters
    ----------
    mass : float
        Mass at the tip of the link (kg), > 0.
    length : float
        Length of the link: the distance of the mass from the pivot (m), > 0.
    theta_range : (float, float)
        Working range of the link angle from the horizontal (rad), ``lo < hi``.
    free_length : float
        Free length of the spring (m), > 0.
    anchor_bounds : ((float, float), (float, float))
        Bounds on ``b_x`` and ``b_y`` (m).
    attachment_bounds : ((float, float), (float, float))
        Bounds on ``a_x`` and ``a_y`` (m, link frame).
    k_bounds : (float, float)
        Bounds on ``k`` (N/m), positive.
    realization : {"coil", "gas"}
        How the spring is drawn.
    n : int
        Number of angles in the objective, >= 10.
    maxiter : int
        Iteration limit of the optimizer, >= 1.

    Returns
    -------
    Design
        The lever with the optimized ordinary spring, its range the working range.

    Raises
    ------
    ApproximationError
        When the optimizer stops without converging (the message says why and what
        to change).

    Examples
    --------
    >>> d = approximate_lever()
    >>> d.parameters["relative_residual_torque"] < 0.05
    True
    """
    mass = finite_real("mass (kg)", mass, positive=True)
    r = finite_real("length (m)", length, positive=True)
    l0 = finite_real("free_length (m)", free_length, positive=True)
    lo, hi = _working_range(theta_range)
    if realization not in ("coil", "gas"):
        raise ValueError(f"realization must be 'coil' or 'gas', got {realization!r}")
    n, maxiter = positive_int("n", n, 10), positive_int("maxiter", maxiter)
    bounds = _design_bounds(anchor_bounds, attachment_bounds, k_bounds)
    th = np.linspace(lo, hi, n)
    res = _optimize_spring(mass, r, l0, th, bounds, maxiter)
    x = res.x
    torque = _lever_torque(x, mass, r, l0, th)
    energy = _lever_energy(x, mass, r, l0, th)
    # the exact ZFL design with the optimizer's anchor height and attachment, for comparison
    bz, cz = max(abs(x[1]), 1e-3), max(abs(x[2]), 1e-3)
    xz = np.array([0.0, bz, cz, 0.0, mass * G * r / (bz * cz)])
    tz = _lever_torque(xz, mass, r, 0.0, th)
    ez = _lever_energy(xz, mass, r, 0.0, th)
    bx, by, ax, ay, k = (float(v) for v in x)
    spring = Spring(k, l0, (0, (bx, by)), (1, (ax, ay)), name="k", realization=realization)
    return lever_design(f"lever, approximate balance with an ordinary {realization} spring",
                        [Load(1, (r, 0.0), (0.0, -mass * G), "m", kind="weight")], [spring],
                        q_range=(lo, hi),
                        labels={"A": (0, (0.0, 0.0)), "b": (0, (bx, by)), "a": (1, (ax, ay))},
                        parameters={"k": k, "free_length": l0, "b_x": bx, "b_y": by, "a_x": ax, "a_y": ay,
                                    "residual_torque": float(np.max(np.abs(torque))),
                                    "rms_residual_torque": float(np.sqrt(np.mean(torque ** 2))),
                                    "relative_residual_torque": float(np.max(np.abs(torque)) / (mass * G * r)),
                                    "energy_variation": float(np.ptp(energy)),
                                    "zfl_residual_torque": float(np.max(np.abs(tz))),
                                    "zfl_energy_variation": float(np.ptp(ez)),
                                    "iterations": int(res.nit)},
                        reference="Lecture 35 (approximate balancing with regular or gas springs)")


def _working_range(theta_range) -> tuple[float, float]:
    lo, hi = finite_reals("theta_range (lo, hi, rad)", theta_range, 2)
    if not (math.isfinite(lo) and math.isfinite(hi) and lo < hi):
        raise ValueError(f"theta_range must be finite with lo < hi, got {theta_range!r}")
    if hi - lo > 2 * math.pi:
        raise ValueError("theta_range spans more than a full turn")
    return lo, hi


def _design_bounds(anchor_bounds, attachment_bounds, k_bounds) -> list:
    """Bounds on ``(b_x, b_y, a_x, a_y, k)``, checked."""
    bounds = []
    for name, pair in (("anchor_bounds", anchor_bounds), ("attachment_bounds", attachment_bounds)):
        pair = planar_points(f"{name} (m)", pair, 2)
        for axis, bnd in zip("xy", pair):
            blo, bhi = bnd
            if not blo < bhi:
                raise ValueError(f"{name} ({axis}) must have lower < upper, got {bnd!r}")
            bounds.append((blo, bhi))
    klo, khi = finite_reals("k_bounds (N/m)", k_bounds, 2)
    if not 0 < klo < khi:
        raise ValueError(f"k_bounds must satisfy 0 < lower < upper, got {k_bounds!r}")
    bounds.append((klo, khi))
    return bounds


def _optimize_spring(mass, r, l0, th, bounds, maxiter):
    """L-BFGS-B on the mean square torque, from the ZFL design; ``res.x`` = ``(b_x, b_y, a_x, a_y, k)``."""
    from scipy.optimize import minimize

    tscale = mass * G * r

    def clip(v, i):
        return min(max(v, bounds[i][0]), bounds[i][1])

    by0 = clip(max(0.3, l0 * 3), 1)
    ax0 = clip(min(0.2, by0 / 2), 2)
    x0 = np.array([clip(0.0, 0), by0, ax0, clip(0.0, 3), clip(mass * G * r / (by0 * ax0), 4)])

    # optimize k / k0 so that every variable is of order one
    k0 = x0[4]
    sc = np.array([1.0, 1.0, 1.0, 1.0, k0])

    def objective(y):
        t = _lever_torque(y * sc, mass, r, l0, th) / tscale
        return float(np.mean(t * t))

    klo, khi = bounds[4]
    sbounds = bounds[:4] + [(klo / k0, khi / k0)]
    res = minimize(objective, x0 / sc, method="L-BFGS-B", bounds=sbounds,
                   options={"maxiter": int(maxiter), "ftol": 1e-12, "gtol": 1e-9})
    res.x = res.x * sc
    if not res.success:
        rms = math.sqrt(res.fun) * tscale
        raise ApproximationError(
            f"approximate balancing did not converge: {res.message} (after {res.nit} iterations; best RMS "
            f"residual torque {rms:.4g} N m). Try a larger maxiter, wider bounds, or a narrower working range.")
    return res


register("pulley_lever", "ZFL spring realized by a string over a 1 cm pulley (lecture 35)", pulley_lever,
         chapter=3)
register("negative_free_length_lever", "Negative free length: an ordinary spring in parallel with a "
         "partner (Deepak & Ananthasuresh, Sec. 1.1)", parallel_springs_lever, chapter=3)
register("approximate_spring_lever", "Ordinary coil spring placed by optimization: approximately "
         "balanced over +-60 deg (lecture 35)", approximate_lever, chapter=3, expected_balanced=False)
