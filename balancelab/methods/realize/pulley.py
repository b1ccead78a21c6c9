"""String over a round pulley: the exact model of a ZFL spring made with an ordinary spring.

Sources: Lecture 35 (*Theory of Mechanisms*), realizing a zero-free-length spring with a
string over a pulley; Deepak & Ananthasuresh 2012, Sec. 2.3 / Fig. 20 (the pulley-and-string
arrangement of the prototype).

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

from ...core.design import Design
from ...core.elements import G, Load, Pulley, Spring
from ...core.validation import finite_real, instance_of, planar_point, positive_int, real_array
from ...mechanisms.lever import lever_design
from ..registry import register

__all__ = ["PulleyString", "pulley_string", "pulley_lever", "pulley_energy", "PulleyError",
           "pulley_balance_error", "pulley_error_curve"]


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


register("pulley_lever", "ZFL spring realized by a string over a 1 cm pulley (lecture 35)", pulley_lever,
         chapter=3)
