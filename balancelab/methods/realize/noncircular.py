"""Exact balance with a real spring: a cable wound on a non-circular pulley.

A real extension spring (rate ``k``, body length ``L_b``, initial tension ``F_i``, so
equivalent free length ``l = L_b - F_i/k > 0``, chapter 8) pulls a cable through a fixed
eyelet ``A``; the cable runs to a profile fixed to the link and wraps on it. Whatever the
free length, the link is balanced when the spring's energy makes up the rest of the
energy:

    k/2 u(theta)^2 + V(theta) = C,     u = spring length - l   (the stretch),

so the tension is ``T = k u = sqrt(2 k (C - V))``. The cable's path ``P`` from the eyelet
(tangent plus wrapped arc, :mod:`.profile`) changes with the link angle at the rate
``dP/dtheta = h``, the distance of the cable's line from the pivot, so its torque is
``-T h`` and balance needs ``h = -V'(theta) / T(theta)`` (canonical, counter-clockwise
wrap). The line through the eyelet at that distance has its normal at
``psi = alpha - theta + acos(h / rho)``; the profile is the envelope of these lines
(support-function form). ``C`` is set by the smallest tension, ``min_tension``.

The resulting :class:`~balancelab.core.design.Design` computes the spring's length from the
cable (:class:`.profile.NoncircularProfile`, a :class:`~balancelab.core.elements.CablePath`):
the tangent point is found from the tangency condition and the wrapped length from the
profile's arc length, not from the formula above.
"""
from __future__ import annotations

import copy
import math
from types import MappingProxyType

import numpy as np
from numpy.polynomial import chebyshev as cheb

from ...core.design import Design
from ...core.elements import Spring
from ...core.validation import finite_real, finite_reals, instance_of, planar_point, positive_int
from ...mechanisms.base import TreeKinematics
from ..practice.springs import ExtensionSpring
from .noncircular_synthesis import DEGREES, at_floor, choose_turn, pivot_inside, search_tension
from .profile import NoncircularProfile, ProfileError

__all__ = ["MIN_ANGLE_RANGE", "noncircular_pulley", "spring_limits", "ProfileError"]



def spring_limits(spring_model: ExtensionSpring, cycles: float | None = None) -> dict:
    """The largest pull (N) of a real extension spring: its body and its hooks.

    Body: the allowable shear stress of :mod:`balancelab.methods.practice.springs`. Hooks
    (a full loop of mean radius ``D/2`` bent up with a bend radius ``2 d``): bending at the
    loop, ``sigma = F (16 D K_A / (pi d^3) + 4 / (pi d^2))`` with
    ``K_A = (4 C^2 - C - 1) / (4 C (C - 1))``, at most 75 % of ``S_ut``; torsion at the bend,
    ``tau = 8 F D K_B / (pi d^3)`` with ``K_B = (4 C_2 - 1) / (4 C_2 - 4)``, ``C_2 = 4``, at
    most 40 % of ``S_ut`` (Shigley's static limits for extension springs; in cyclic service
    the fatigue fractions). A spring made without hooks has only its body's limit.

    Parameters
    ----------
    spring_model : ExtensionSpring
        The real spring.
    cycles : float, optional
        Number of load cycles for the body's allowable stress (static when omitted).

    Returns
    -------
    dict
        ``body`` and, for a spring with hooks, ``hook_bending`` and ``hook_torsion``, and
        ``max_force`` (the smallest), in N (:meth:`ExtensionSpring.max_forces`).

    Examples
    --------
    >>> from balancelab.methods.practice.springs import ExtensionSpring
    >>> lim = spring_limits(ExtensionSpring(3e-3, 24e-3, 60, initial_tension=20.0))
    >>> lim["max_force"] == min(lim["body"], lim["hook_bending"], lim["hook_torsion"])
    True
    """
    instance_of("spring_model", spring_model, ExtensionSpring, "a practice.springs.ExtensionSpring")
    out = dict(spring_model.max_forces(cycles))     # body, and the hooks when the spring has them
    out["max_force"] = min(out.values())
    return out


def _pivoted_link(design: Design, spring) -> tuple[int, int]:
    """``(spring, coordinate)``: the spring's moving body turns about the origin, its angle one coordinate."""
    instance_of("design", design, Design, "a balancelab Design")
    if not design.springs:
        raise ValueError(f"{design.name} has no spring: noncircular_pulley replaces one of its springs")
    spring = positive_int("spring", spring, 0, len(design.springs) - 1)
    s = design.springs[int(spring)]
    if s.a.body != 0 and s.b.body != 0:
        raise ValueError(f"{design.name}: spring {spring} joins {design.bodies[s.a.body]} to "
                         f"{design.bodies[s.b.body]}; it must join the ground (body 0) to the body it pulls")
    body = s.b.body if s.a.body == 0 else s.a.body
    q = design.sample(16, seed=3)
    poses = np.asarray(design.poses(q))
    if float(np.max(np.abs(poses[:, body, :2]))) > 1e-9:
        raise ValueError(f"{design.name}: spring {spring} pulls {design.bodies[body]}, whose frame's origin "
                         "moves: the body must turn about a ground pivot at the world origin (0, 0)")
    for coordinate in range(design.dof):
        if np.allclose(poses[:, body, 2], q[:, coordinate], rtol=0.0, atol=1e-9):
            return int(spring), coordinate
    raise ValueError(f"{design.name}: the angle of {design.bodies[body]} (pulled by spring {spring}) must equal "
                     "one of the coordinates (its absolute angle, no offset), e.g. a driving body of a Linkage")


def _linkage_size(design: Design, eyelet) -> float:
    """The linkage's size (m): its farthest joint, load or spring point from its body's origin, or the eyelet."""
    points = [j.point_i for j in design.joints] + [j.point_j for j in design.joints]
    points += [ld.point for ld in design.loads] + [p.point for s in design.springs for p in (s.a, s.b)]
    return max([math.hypot(*eyelet)] + [math.hypot(*p) for p in points])


#: Narrowest ``angle_range`` (rad) a profile is synthesized for, 1°: the radius of curvature divides
#: round-off by the square of the range, and below about 1 mrad it is wrong by tens of millimetres.
MIN_ANGLE_RANGE = math.radians(1.0)


def _angle_range(design: Design, angle_range, coordinate: int) -> tuple[float, float]:
    lo, hi = design.q_range[coordinate] if angle_range is None else finite_reals("angle_range (lo, hi, rad)", angle_range, 2)
    if not lo < hi:
        raise ValueError(f"angle_range must have lo < hi (rad), got ({lo}, {hi})")
    if hi - lo < MIN_ANGLE_RANGE:
        raise ValueError(f"angle_range must span at least {math.degrees(MIN_ANGLE_RANGE):.0f}° ({MIN_ANGLE_RANGE:.4g} rad) "
                         f"and less than 180°, got {hi - lo:.3g} rad: over a narrower range the profile's curvature "
                         "(second derivatives in the link angle) drowns in round-off")
    if hi - lo >= math.pi:
        raise ValueError(f"angle_range must span less than 180° (the cable's line turns with the link), "
                         f"got {math.degrees(hi - lo):.1f}°" + (" (the design's whole range: pass angle_range=(lo, hi))"
                                                                if angle_range is None else ""))
    return float(lo), float(hi)


def _restricted(design: Design, coordinate: int, lo: float, hi: float):
    """The design's kinematics with the range of one coordinate narrowed to ``(lo, hi)``."""
    kin = design.kinematics
    q_range = np.array(kin.q_range, dtype=float)
    q_range[coordinate] = (lo, hi)
    if isinstance(kin, TreeKinematics):
        return TreeKinematics(kin.nbodies, design.joints, kin.angle_matrix, kin.names, q_range,
                              angle_offset=kin.angle_offset)
    narrowed = copy.copy(kin)          # any other kinematics (a Linkage's): same solver, narrower range
    narrowed.q_range = q_range
    return narrowed


def _energy_series(design: Design, spring: int, coordinate: int, lo: float, hi: float):
    """Chebyshev series (in x in [-1, 1]) of the energy of everything but the spring, along one coordinate.

    The other coordinates are held at two places in their ranges; the energy must differ between
    them by a constant only (the rest depends on this coordinate alone), or no profile on this
    body can balance it.
    """
    rest = design.replace(springs=[s for i, s in enumerate(design.springs) if i != spring],
                          kinematics=_restricted(design, coordinate, lo, hi))
    span = rest.q_range
    for n in DEGREES:
        x = np.cos(np.pi * (np.arange(n) + 0.5) / n)
        q = np.repeat([span[:, 0] + 0.5 * (span[:, 1] - span[:, 0])], n, axis=0)
        q[:, coordinate] = 0.5 * (lo + hi) + 0.5 * (hi - lo) * x
        v = rest.potential_energy(q).total
        coef = cheb.chebfit(x, v, n - 1)
        if np.max(np.abs(coef[-4:])) <= 1e-14 * max(np.max(np.abs(coef[1:])), 1e-300):
            break
    if np.max(np.abs(coef[1:])) == 0.0:
        raise ValueError(f"{design.name}: without the spring nothing exchanges energy; nothing to balance")
    q2 = np.repeat([span[:, 0] + 0.3 * (span[:, 1] - span[:, 0])], n, axis=0)
    q2[:, coordinate] = q[:, coordinate]
    drift = np.ptp(rest.potential_energy(q2).total - v)
    if drift > 1e-9 * np.ptp(v):
        raise ValueError(f"{design.name}: without spring {spring} the energy along {design.q_names[coordinate]} "
                         f"also depends on the other coordinates (by {drift:.3g} J): one profile cannot balance it")
    return coef


def _check_spring(spring_model, k, min_tension, max_tension, cycles) -> dict:
    limits = spring_limits(spring_model, cycles)
    if min_tension < spring_model.initial_tension:
        raise ProfileError(f"min_tension {min_tension:.4g} N is below the spring's initial tension "
                           f"{spring_model.initial_tension:.4g} N: the coils would close and the cable go slack")
    part = min((p for p in limits if p != "max_force"), key=lambda where: limits[where])
    if max_tension > limits["max_force"]:
        raise ProfileError(
            f"the spring is overstressed: its largest tension {max_tension:.4g} N exceeds what its "
            f"{part.replace('_', ' ')} allows, {limits['max_force']:.4g} N, by "
            f"{100 * (max_tension / limits['max_force'] - 1):.3g} %; choose a stronger spring"
            + (" or a lower min_tension" if min_tension > spring_model.initial_tension * (1 + 1e-12) else
               " (min_tension is already its initial tension)"))
    stroke = (max_tension - min_tension) / k
    return {"max_tension": max_tension, "stroke": stroke, "allowable_force": limits["max_force"],
            "limiting_part": part, "max_stress": float(spring_model.stresses(max_tension)[part]),
            "max_length": spring_model.equivalent_free_length + max_tension / k}


def noncircular_pulley(design: Design, spring: int = 0, *, spring_model: ExtensionSpring, angle_range=None,
                       min_tension: float | None = None, eyelet=None, turn: int | None = None,
                       cable_bend_radius: float = 0.005, cycles: float | None = None,
                       max_size: float | None = None) -> Design:
    """Replace a spring by a real spring whose cable wraps a non-circular pulley on the body it pulls.

    The profile is synthesized so that the real spring balances everything else of the
    design exactly over ``angle_range`` (see the module docstring); the returned design's
    spring energy comes from the cable's path (tangent from the eyelet plus wrapped arc),
    and its range is ``angle_range``: outside it the cable leaves the profile and the
    energy refuses to evaluate (:class:`ProfileError` names the covered range).

    Parameters
    ----------
    design : Design
        A design whose spring ``spring`` joins the ground to a body that turns about the origin by
        one coordinate: a lever (e.g. :func:`balancelab.lecture.single_link_spring`), or link 1 or
        the base copy of link 2 of the lecture's 2R arm with springs at the base
        (:func:`balancelab.lecture.serial_2r_base_springs`), where each spring balances its own
        coordinate; call once per spring. Without the spring, the energy must depend on that
        coordinate alone.
    spring : int
        Index of the spring to replace; its ground attachment is the default eyelet.
    spring_model : ExtensionSpring
        The real spring (:mod:`balancelab.methods.practice.springs`): its rate, initial
        tension and body length; ``free_length`` of the result is its equivalent free length.
    angle_range : (float, float), optional
        Angles of the body (its coordinate, rad) covered, ``lo < hi``, at least 1°
        (:data:`MIN_ANGLE_RANGE`) and less than 180° apart;
        default that coordinate's range in the design.
    min_tension : float, optional
        Smallest cable tension over the range (N), at least the initial tension; by default
        the tension between ``F_i`` and the spring's allowable pull (40 values tried) whose
        profile is wrappable and most compact (nearest the pivot at its farthest point).
    eyelet : (float, float), optional
        Where the cable leaves the ground (m), world frame; default the spring's ground attachment.
    turn : {1, -1}, optional
        Wrap counter-clockwise (1) or clockwise (-1); default: the wrap that keeps the pivot
        inside the profile, else the other one.
    cable_bend_radius : float
        Smallest radius (m) the cable may be bent to, > 0; the profile must not be sharper.
    cycles : float, optional
        Load cycles for the spring's allowable stress (static when omitted).
    max_size : float, optional
        Largest distance (m) of the profile from the pivot, > 0; default 4 times the
        linkage's size (the farthest joint, load or spring attachment point from its body's
        origin, or the eyelet from the pivot). Larger profiles are refused.

    Returns
    -------
    Design
        ``parameters`` hold ``k``, ``free_length``, ``initial_tension``, ``min_tension``,
        ``max_tension`` (N), ``stroke`` (m), ``max_stress`` (Pa), ``allowable_force`` (N) and
        ``limiting_part`` (the part that fails first: ``body``, ``hook_torsion`` or
        ``hook_bending``; ``max_stress`` is its stress), ``min_radius_of_curvature`` (m),
        ``min_lever_arm`` (m, the cable line's smallest distance from the pivot; not positive
        when the pivot lies outside the profile, which also warns), ``size`` (m, the
        profile's farthest point from the pivot), ``lo``, ``hi`` (rad), and the build data:
        ``eyelet`` (world, m), ``spring_anchor`` (world, m: where the spring's far end is fixed, on the line from the pivot through
        the eyelet, ``anchor_distance`` beyond the eyelet: the longest spring plus a coil
        diameter), ``clamp`` (the cable's end ``E`` in the link's frame, m) and
        ``cable_length`` (m, the cable from the spring's hook end through the eyelet to
        ``E``), so that the spring's length is
        ``anchor_distance + path - cable_length`` with ``path`` the cable's path from the
        eyelet to ``E`` (:meth:`.NoncircularProfile.cable`). These flat keys describe the
        spring just replaced; ``pulleys`` maps the index of *every* spring replaced so far
        (the two springs of the 2R lamp arm, say) to a read-only mapping of its own keys
        above, so that each cable spring keeps its rate, free length, anchor and limits.
        The design's range of that coordinate is ``(lo, hi)``.

    Raises
    ------
    ProfileError
        When no wrappable profile exists or the spring cannot carry it: the message names what
        fails (eyelet too close, concave profile, curvature below the cable's bending radius,
        overstressed spring or hook, slack cable) and by how much.

    Examples
    --------
    >>> import math, balancelab as bl
    >>> from balancelab.methods.practice.springs import ExtensionSpring
    >>> lever = bl.lecture.single_link_spring(2.0, 0.5, 0.3, 0.2)
    >>> real = ExtensionSpring(3e-3, 24e-3, 60, initial_tension=20.0)
    >>> d = noncircular_pulley(lever, spring_model=real, angle_range=(-math.pi / 3, math.pi / 3))
    >>> d.balance_report().balanced, d.springs[0].free_length > 0
    (True, True)
    """
    spring, coordinate = _pivoted_link(design, spring)
    instance_of("spring_model", spring_model, ExtensionSpring, "a practice.springs.ExtensionSpring")
    lo, hi = _angle_range(design, angle_range, coordinate)
    old = design.springs[spring]
    ground = old.a if old.a.body == 0 else old.b
    eyelet = ground.point if eyelet is None else planar_point("eyelet (m)", eyelet)
    cable_bend_radius = finite_real("cable_bend_radius (m)", cable_bend_radius, positive=True)
    max_size = 4 * _linkage_size(design, eyelet) if max_size is None else \
        finite_real("max_size (m)", max_size, positive=True)
    bounds = (cable_bend_radius, max_size)
    k = spring_model.k
    limit = spring_limits(spring_model, cycles)["max_force"]
    v_coef = _energy_series(design, spring, coordinate, lo, hi)
    fine = cheb.chebval(np.linspace(-1, 1, 4001), v_coef)
    exchange = float(np.ptp(fine))         # the energy the spring must store and give back (J)
    if min_tension is None:
        top = math.sqrt(max(limit ** 2 - 2 * k * exchange, 0.0))   # highest smallest tension within the limit
        _check_spring(spring_model, k, spring_model.initial_tension, math.hypot(spring_model.initial_tension,
                      math.sqrt(2 * k * exchange)), cycles)
        min_tension, found = search_tension(v_coef, k, spring_model, top, eyelet, turn, lo, hi, bounds)
    else:
        min_tension = finite_real("min_tension (N)", min_tension, positive=True)
        _check_spring(spring_model, k, min_tension, math.hypot(min_tension, math.sqrt(2 * k * exchange)), cycles)
        try:
            found = choose_turn(v_coef, k, min_tension, eyelet, turn, lo, hi, bounds)
        except ProfileError as err:
            raise at_floor(err, min_tension, spring_model.initial_tension) from None
    profile, checks, theta, tension = found
    checks["min_lever_arm"] = pivot_inside(profile)
    # the largest tension is where the rest's energy is lowest (the range's ends included, not only the nodes)
    largest = max(math.hypot(min_tension, math.sqrt(2 * k * exchange)), float(np.max(tension)))
    sp_checks = _check_spring(spring_model, k, min_tension, largest, cycles)
    return _assemble(design, (spring, coordinate), old, spring_model, profile, theta, tension,
                     {**checks, **sp_checks, "min_tension": min_tension, "lo": lo, "hi": hi})


def _assemble(design, which, old, spring_model, profile, theta, tension, numbers) -> Design:
    """The design with the real spring on its profile (cable length fixed by the stretch)."""
    k, l_eq = spring_model.k, spring_model.equivalent_free_length
    path = profile.cable(theta).path
    cable_length = float(np.mean(path - (tension / k + l_eq)))
    # the spring hangs from a ground anchor on the line pivot -> eyelet, beyond the eyelet by the longest
    # spring plus a coil diameter; its hook end pulls the cable through the eyelet to the clamp E
    reach = numbers["max_length"] + spring_model.coil_diameter
    profile = NoncircularProfile(profile.h, profile.psi, profile.angle_range, profile.anchor, profile.pivot,
                                 profile.turn, cable_length, anchor_distance=reach)
    end = tuple(float(v) for v in profile.local_points(profile.end_parameter))
    spring, coordinate = which
    body = old.b.body if old.a.body == 0 else old.a.body
    new = Spring(k, l_eq, (0, profile.anchor), (body, end), name=old.name or f"k{spring + 1}",
                 realization=profile)
    springs = list(design.springs)
    springs[spring] = new
    lo, hi = profile.angle_range
    own = {"k": k, "free_length": l_eq, "initial_tension": spring_model.initial_tension, **numbers,
           "cable_length": reach + cable_length, "spring_anchor": profile.spring_anchor,
           "eyelet": tuple(float(v) for v in np.add(profile.pivot, profile.anchor)),
           "anchor_distance": reach, "clamp": end}
    pulleys = dict(design.parameters.get("pulleys", {}))
    pulleys[spring] = MappingProxyType(own)
    params = {**design.parameters, **own, "pulleys": MappingProxyType(dict(sorted(pulleys.items())))}
    labels = dict(design.labels)
    if not any(b == 0 and np.allclose(p, profile.anchor) for b, p in labels.values()):
        labels["eyelet"] = (0, profile.anchor)
    several = sum(s.cable is not None for s in springs) > 1
    name = design.name.split(": real spring")[0] + (": real springs on non-circular pulleys" if several
                                                    else ": real spring on a non-circular pulley")
    return design.replace(name=name, springs=springs,
                          kinematics=_restricted(design, coordinate, lo, hi), labels=labels,
                          parameters=params, reference=(design.reference + "; " if design.reference else "")
                          + "non-circular pulley synthesized by balancelab.realize.noncircular_pulley")
