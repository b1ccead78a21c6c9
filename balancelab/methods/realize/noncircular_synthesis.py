"""Synthesis of a non-circular pulley's profile from the energy it must balance, and its checks.

The profile balancing an energy ``V(theta)`` (a Chebyshev series over the link angle) with a
spring of rate ``k`` and smallest tension ``m`` is the envelope of the cable's lines whose
distance from the pivot is ``h = -V'(theta) / T`` with ``T = sqrt(m^2 + 2 k (V_max - V))``
(:mod:`.noncircular` derives it). This module builds that profile at the smallest Chebyshev
degree whose tail is round-off, checks that a cable can wrap it (convex, not sharper than the
cable's bending radius, the eyelet on the right side, within a largest size), chooses the
wrap's sense and, when no smallest tension is given, searches for the most compact
wrappable one. Geometry only: the design's plumbing is :mod:`.noncircular`.
"""
from __future__ import annotations

import math
import re
import warnings

import numpy as np
from numpy.polynomial import chebyshev as cheb

from .profile import NoncircularProfile, ProfileError

__all__ = ["DEGREES", "at_floor", "choose_turn", "pivot_inside", "search_tension"]

#: Chebyshev degrees tried for the energy and the profile (doubling until the tail is round-off)
DEGREES = (32, 64, 128, 256)


def _synthesis(v_coef, k: float, min_tension: float, anchor, turn: int, lo: float, hi: float, n: int):
    """Support function and normal angle at ``n`` Chebyshev nodes, and the tension there."""
    half = 0.5 * (hi - lo)
    x = np.cos(np.pi * (np.arange(n) + 0.5) / n)
    theta = 0.5 * (lo + hi) + half * x
    v = cheb.chebval(x, v_coef)
    dv = turn * cheb.chebval(x, cheb.chebder(v_coef)) / half        # dV/d(canonical angle)
    fine = cheb.chebval(np.linspace(-1, 1, 4001), v_coef)
    top = max(float(fine.max()), float(v.max()))
    tension = np.sqrt(min_tension ** 2 + 2 * k * (top - v))
    h = -dv / tension
    ax, ay = anchor[0], turn * anchor[1]
    rho, alpha = math.hypot(ax, ay), math.atan2(ay, ax)
    worst = int(np.argmax(np.abs(h)))
    if abs(h[worst]) >= rho:
        raise ProfileError(
            f"the cable's line must pass {abs(h[worst]):.4g} m from the pivot at {math.degrees(theta[worst]):.2f}°, "
            f"but the eyelet is only {rho:.4g} m from it: move the eyelet at least "
            f"{abs(h[worst]) - rho:.3g} m farther, or raise min_tension (now {min_tension:.4g} N)")
    psi = alpha - turn * theta + np.arccos(h / rho)
    return x, theta, h, psi, tension


def _profile(v_coef, k, min_tension, anchor, turn, lo, hi):
    """The profile's Chebyshev series, at the smallest degree whose tail is round-off."""
    for n in DEGREES:
        x, theta, h, psi, tension = _synthesis(v_coef, k, min_tension, anchor, turn, lo, hi, n)
        ch, cp = cheb.chebfit(x, h, n - 1), cheb.chebfit(x, psi, n - 1)
        tail = max(np.max(np.abs(ch[-4:])) / np.max(np.abs(ch)), np.max(np.abs(cp[-4:])) / np.max(np.abs(cp)))
        if tail < 1e-14:
            break
    return ch, cp, (x, theta, tension)


def _check_wrappable(profile: NoncircularProfile, cable_bend_radius: float) -> dict:
    """Convexity, curvature and a cable that reaches the profile from the right side, or ProfileError."""
    x = np.linspace(-1.0, 1.0, 2001)
    theta = profile.mid + profile.half * x
    dpsi = cheb.chebval(x, cheb.chebder(profile.psi))
    if not (np.all(dpsi < 0) or np.all(dpsi > 0)):
        i = int(np.argmin(np.abs(dpsi)))
        raise ProfileError(f"the cable's line stops turning relative to the link at {math.degrees(theta[i]):.2f}°: "
                           "the lines have no envelope there (no profile); change min_tension or the eyelet")
    rc = profile.radius_of_curvature(x)
    i = int(np.argmin(rc))
    if rc[i] <= 0:
        raise ProfileError(f"the profile would be concave at {math.degrees(theta[i]):.2f}° (radius of curvature "
                           f"{1000 * rc[i]:.3g} mm): a cable cannot wrap a concave arc; lower min_tension or use "
                           "a stiffer spring (a larger change of tension over the range)")
    if rc[i] < cable_bend_radius:
        raise ProfileError(f"the profile's smallest radius of curvature, {1000 * rc[i]:.3g} mm at "
                           f"{math.degrees(theta[i]):.2f}°, is below the cable's bending radius (cable_bend_radius) "
                           f"{1000 * cable_bend_radius:.3g} mm by {1000 * (cable_bend_radius - rc[i]):.3g} mm")
    h, psi = profile.support(x)
    straight = profile.rho * np.sin(psi + profile.turn * theta - profile.alpha) + \
        cheb.chebval(x, cheb.chebder(profile.h)) / dpsi
    j = int(np.argmin(straight))
    if straight[j] <= 0:
        raise ProfileError(f"at {math.degrees(theta[j]):.2f}° the eyelet lies on the wrong side of the tangent "
                           "point (the cable would have to wrap the other way): use the other turn")
    return {"min_radius_of_curvature": float(rc[i]), "min_straight": float(straight[j])}


def _kind(err: ProfileError) -> str:
    """What failed, without the numbers: two tensions failing differently may hold a feasible one between."""
    return re.sub(r"-?[\d.]+", "#", str(err))[:48]


def at_floor(err: ProfileError, tension: float, floor: float) -> ProfileError:
    """The refusal at ``tension``; at the spring's initial tension it cannot advise a lower one."""
    if tension > floor * (1 + 1e-12):
        return err
    text = str(err).replace("lower min_tension or use a stiffer spring", "min_tension is already the spring's "
                            "initial tension (the lowest possible): use a stiffer spring")
    text = text.replace("change min_tension or the eyelet", "raise min_tension or move the eyelet")
    text = text.replace("choose a stronger spring or a lower min_tension", "choose a stronger spring (min_tension "
                        "is already its initial tension)")
    return ProfileError(text)


def search_tension(v_coef, k, spring_model, limit, eyelet, turn, lo, hi, bounds):
    """No ``min_tension`` given: the most compact wrappable profile, for tensions up to ``limit``.

    A geometric grid of tensions, then bisection between neighbours that fail for different
    reasons (a feasible band may lie between them).
    """
    start = max(spring_model.initial_tension, 0.02 * limit)
    found, failed = {}, {}

    def attempt(tension):
        try:
            built = choose_turn(v_coef, k, tension, eyelet, turn, lo, hi, bounds)
        except ProfileError as err:
            failed[tension] = err
            return False
        found[tension] = (built, built[1]["size"])
        return True

    grid = [float(t) for t in np.geomspace(start, limit, 40)] if limit > start else [start]
    for tension in grid:
        attempt(tension)
    for a, b in zip(grid, grid[1:]):
        if a in failed and b in failed and _kind(failed[a]) != _kind(failed[b]):
            ka = _kind(failed[a])
            while b - a > 1e-7 * b:
                mid = 0.5 * (a + b)
                if attempt(mid):
                    break
                a, b = (mid, b) if _kind(failed[mid]) == ka else (a, mid)
    if not found:
        err = at_floor(failed[start], start, spring_model.initial_tension)
        raise ProfileError(f"none found: no wrappable profile among {len(failed)} values of min_tension from "
                           f"{start:.4g} N to {limit:.4g} N (a geometric grid of 40, refined by bisection where "
                           f"the reason for failing changes; above {limit:.4g} N the spring is overstressed at the "
                           f"range's end); pass min_tension to try another; at {start:.4g} N: {err}")
    best = min(found, key=lambda t: found[t][1])
    return best, found[best][0]


def _build(v_coef, k, min_tension, eyelet, turn, lo, hi, bounds):
    ch, cp, (x, theta, tension) = _profile(v_coef, k, min_tension, eyelet, turn, lo, hi)
    profile = NoncircularProfile(ch, cp, (lo, hi), eyelet, (0.0, 0.0), turn, 0.0)
    checks = _check_wrappable(profile, bounds[0])
    x = np.linspace(-1.0, 1.0, 401)
    reach = np.hypot(*profile.local_points(x).T)
    far = int(np.argmax(reach))
    size = float(reach[far])
    if size > bounds[1]:
        raise ProfileError(f"the profile would reach {size:.3g} m from the pivot (where the cable leaves it at "
                           f"link angle {math.degrees(profile.mid + profile.half * x[far]):.2f}°), more than max_size "
                           f"{bounds[1]:.3g} m (by default 4 times the linkage's size); raise min_tension or move "
                           "the eyelet, or pass a larger max_size")
    checks["size"] = size
    return profile, checks, theta, tension


def choose_turn(v_coef, k, min_tension, eyelet, turn, lo, hi, bounds):
    """The profile for ``turn``, or (``turn=None``) for the wrap that holds the pivot inside, else the other."""
    if turn is not None:
        if isinstance(turn, bool) or turn not in (1, -1):
            raise ValueError(f"turn must be 1 (counter-clockwise), -1 (clockwise) or None, got {turn!r}")
        return _build(v_coef, k, min_tension, eyelet, int(turn), lo, hi, bounds)
    mean_slope = cheb.chebval(np.linspace(-1, 1, 101), cheb.chebder(v_coef)).mean()
    first = -1 if mean_slope > 0 else 1      # h = -turn V'/T > 0: the pivot inside the profile
    try:
        return _build(v_coef, k, min_tension, eyelet, first, lo, hi, bounds)
    except ProfileError as err:
        try:
            return _build(v_coef, k, min_tension, eyelet, -first, lo, hi, bounds)
        except ProfileError:
            raise err from None


def pivot_inside(profile: NoncircularProfile) -> float:
    """The cable line's smallest distance from the pivot (m); warns when the pivot lies outside the profile."""
    x = np.linspace(-1.0, 1.0, 2001)
    h = cheb.chebval(x, profile.h)
    i = int(np.argmin(h))
    if h[i] <= 0:
        warnings.warn(f"the pivot lies outside the profile (at link angle "
                      f"{math.degrees(profile.mid + profile.half * x[i]):.2f}° the cable's line passes "
                      f"{1000 * -h[i]:.3g} mm beyond it): the design balances, but the pulley needs an arm out to its "
                      "axle and profile_part cannot cut it; the other turn, another eyelet or min_tension may keep "
                      "the pivot inside", UserWarning, stacklevel=3)
    return float(h[i])
