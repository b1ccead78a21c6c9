"""String over a round pulley: the exact model of a ZFL spring made with an ordinary spring.

Sources: Lecture 35 (*Theory of Mechanisms*), realizing a zero-free-length spring with a
string over a pulley; Deepak & Ananthasuresh 2012, Sec. 2.3 / Fig. 20 (the pulley-and-string
arrangement of the prototype).

**String over a pulley.** An ordinary spring hangs from the ground; a string tied to
its end comes down along a fixed line, wraps round a pulley of radius ``rho`` centred at
the virtual anchor and leaves it on the tangent towards the attachment ``C`` on the
moving link. The spring carries that geometry: ``Spring(..., realization=Pulley(rho,
spring_direction, turn))`` (:class:`balancelab.core.elements.Pulley`), read both by the
exact model here and by the drawing; the string's geometry (:func:`pulley_string`) is
:mod:`balancelab.mechanisms.geometry`'s, re-exported here. The string's passed-over length (from where it
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
from ...core.validation import finite_real, instance_of, positive_int, real_array
from ...mechanisms.geometry import PulleyString, pulley_string
from ...mechanisms.lever import lever_design
from ..registry import register

__all__ = ["PulleyString", "pulley_string", "pulley_lever", "pulley_energy", "PulleyError",
           "pulley_balance_error", "pulley_error_curve"]


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
