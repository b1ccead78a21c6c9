"""Lab 3, building a ZFL spring: a string over a pulley, a negative free length, an ordinary spring.

Task 3.4 (derive) asks for the torque error that a free length leaves on the lever designed for a
ZFL spring, as a formula, in the student's own angle convention and sign (a personal variant).
"""
from __future__ import annotations

from typing import Any

import functools
import math

import numpy as np

from ...core.design import Design
from ...core.elements import G
from ...methods.realize import negative_free_length_partner, pulley_balance_error, pulley_lever
from .answers import numeric, spring
from .core import register_task
from .variant import equivalent
from .lab2 import lab2_lever

__all__ = ["LAB3_LEVER", "PARTNER_SPRINGS", "LAB3_FREE_LENGTH_SYMBOLS", "lab3_torque_error"]

#: Lab 3's lever (kg, m) and its limits: torque errors are fractions of ``m g r`` with
#: ``r = length``; spring ends within ``reach_max`` (m) of the pivot in task 3.3.
LAB3_LEVER: dict[str, Any] = dict(mass=2.0, length=0.5, b=0.3, c=0.2, pulley_error=0.01, free_length=0.1,
                  theta_range=(-math.pi / 3, math.pi / 3), torque_error=0.03, reach_max=0.4)
#: Task 3.2: an ordinary spring (N/m, m) and the rate of its partner (N/m): the published numbers
#: (each student's are drawn by :func:`_partner_numbers`).
PARTNER_SPRINGS = dict(k=400.0, free_length=0.05, k_partner=250.0)


def lab3_torque_error(design: Design, theta_range=None, n: int = 241) -> float:
    """Largest ``|dV/dtheta|`` of a one-link design over a range, divided by ``m g r`` of lab 3's lever.

    Parameters
    ----------
    design : Design
        A lever (one degree of freedom).
    theta_range : (float, float), optional
        Range of the link angle (rad); lab 3's working range (+-60 deg) by default.
    n : int
        Number of angles.

    Returns
    -------
    float

    Examples
    --------
    >>> lab3_torque_error(lab2_lever(100.0, (0.2, 0.0), (0.0, 0.3))) > 0.01
    True
    """
    p = LAB3_LEVER
    lo, hi = p["theta_range"] if theta_range is None else theta_range
    q = np.linspace(lo, hi, n)
    torque = design.generalized_force(q)[..., 0]
    return float(np.max(np.abs(torque)) / (p["mass"] * G * p["length"]))


def _pulley_numbers(rng) -> dict:
    """Task 3.1's lever (kg, m): the published numbers of :data:`LAB3_LEVER`, or a student's (from ``rng``)."""
    p = LAB3_LEVER
    if rng is None:
        return {k: p[k] for k in ("mass", "length", "b", "c")}
    scale = float(np.exp(rng.uniform(np.log(0.4), np.log(2.5))))  # the lever's size: spreads the answers
    return dict(mass=round(rng.uniform(1.2, 3.0), 2), length=round(scale * rng.uniform(0.35, 0.65), 4),
                b=round(scale * rng.uniform(0.30, 0.44), 4), c=round(scale * rng.uniform(0.08, 0.20), 4))


@functools.lru_cache(maxsize=1024)
def _pulley_radius_limit(mass: float, length: float, b: float, c: float) -> float:
    """Pulley radius (m) at which a lever has a torque error of ``pulley_error`` (1 %) of ``m g r``.

    Private: the judge of task 3.1 calls it with the numbers it judges with. scipy's ``brentq``
    on the exact string model (:func:`balancelab.methods.realize.pulley_balance_error`).
    """
    from scipy.optimize import brentq

    scale = mass * G * length

    def excess(radius):
        lever = pulley_lever(mass=mass, length=length, b=b, c=c, radius=radius)
        return pulley_balance_error(lever).residual_torque / scale - LAB3_LEVER["pulley_error"]

    return brentq(excess, 1e-5, min(0.05, 0.9 * (b - c)), xtol=1e-8)


@register_task("3.1", "largest pulley radius for a 1 % torque error", "pulley_radius", "numeric",
               "a number in metres (or a string like '2.8 mm'); accepted within 0.5 %", numbers=_pulley_numbers,
               distinct=(lambda lever: _pulley_radius_limit(**lever), 0.015))
def _t31(answer, lever):
    return numeric(answer, _pulley_radius_limit(lever["mass"], lever["length"], lever["b"], lever["c"]),
                   "length", rtol=0.005)


def _partner_numbers(rng) -> dict:
    """Task 3.2's springs (N/m, m): :data:`PARTNER_SPRINGS`, or a student's (from ``rng``)."""
    if rng is None:
        return dict(PARTNER_SPRINGS)
    return dict(k=round(float(rng.uniform(200.0, 800.0)), 1), free_length=round(float(rng.uniform(0.025, 0.09)), 4),
                k_partner=round(float(rng.uniform(120.0, 480.0)), 1))


@register_task("3.2", "free length of the partner spring that makes a ZFL pair", "partner_free_length",
               "numeric", "a number in metres (negative!) for your springs (task_numbers('3.2')); accepted "
               "within 0.5 %", numbers=_partner_numbers,
               distinct=(lambda springs: negative_free_length_partner(**springs), 0.015))
def _t32(answer, springs):
    return numeric(answer, negative_free_length_partner(**springs), "length")


@register_task("3.3", "an ordinary spring that balances the lever within 3 % over +-60 deg (open design)",
               "ordinary_spring", "design",
               "a dict {'k': N/m, 'a': (x, y) on the link, 'b': (x, y) on the ground} for a spring of free "
               "length 0.1 m; largest torque error over -60..60 deg at most 3 % of m g r; |a|, |b| <= 0.4 m",
               points=2)
def _t33(answer):
    k, pa, pb = spring(answer)
    p = LAB3_LEVER
    d = lab2_lever(k, tuple(pa), tuple(pb), W=p["mass"] * G, l=p["length"], free_length=p["free_length"])
    err = lab3_torque_error(d)
    fits = np.hypot(*pa) <= p["reach_max"] + 1e-12 and np.hypot(*pb) <= p["reach_max"] + 1e-12
    ok = err <= p["torque_error"] and fits
    msg = f"Largest torque error over the range: {100 * err:.2g} % of m g r"
    msg += (" (at most 3 % accepted)" if err > p["torque_error"] else "")
    if not fits:
        msg += "; a spring end is farther than 0.4 m from the pivot"
    hint = "" if ok else ("Start from the ZFL design and move the anchor and the rate to absorb the "
                          "free length; plot the torque over the range.")
    return ok, msg + ".", hint


# --------------------------------------------------- 3.4: the free length's torque error, as a formula

#: Task 3.4's symbols and the ranges the judge draws them from (kg, m/s^2, m, rad).
LAB3_FREE_LENGTH_SYMBOLS: dict[str, tuple[float, float]] = dict(
    m=(0.5, 5.0), g=(5.0, 15.0), r=(0.2, 1.0), b=(0.1, 0.5), c=(0.05, 0.3), l_0=(0.01, 0.2), theta=(-1.2, 1.2))


def _free_length_numbers(rng) -> dict:
    """Task 3.4's variant: the published one (angle from the horizontal, dV/dtheta), or another (from ``rng``)."""
    if rng is None:
        return dict(angle="horizontal", torque="dV/dtheta")
    others = [("horizontal", "holding"), ("vertical", "dV/dtheta"), ("vertical", "holding")]
    angle, torque = others[int(rng.integers(len(others)))]
    return dict(angle=angle, torque=torque)


def _free_length_torque(angle: str, torque: str):
    """Task 3.4's reference: the torque error of the ZFL-designed lever built with a spring of free length ``l_0``."""
    import sympy as sp

    if angle not in ("horizontal", "vertical") or torque not in ("dV/dtheta", "holding"):
        raise ValueError(f"angle must be 'horizontal' or 'vertical' and torque 'dV/dtheta' or 'holding', "
                         f"got {angle!r}, {torque!r}")
    m, g, r, b, c, l0, th = sp.symbols("m g r b c l_0 theta")
    # k b c = m g r balances the ZFL part; the free length adds -k l_0 d(length)/dtheta
    if angle == "horizontal":  # link along (cos, sin): spring length^2 = b^2 + c^2 - 2 b c sin(theta)
        dv = m * g * r * l0 * sp.cos(th) / sp.sqrt(b ** 2 + c ** 2 - 2 * b * c * sp.sin(th))
    else:  # theta from the upward vertical, clockwise: link along (sin, cos)
        dv = -m * g * r * l0 * sp.sin(th) / sp.sqrt(b ** 2 + c ** 2 - 2 * b * c * sp.cos(th))
    return dv if torque == "dV/dtheta" else -dv


@register_task("3.4", "the torque error of the lever's spring built with a free length, as a formula",
               "free_length_torque", "symbolic",
               "a sympy expression in m, g, r, b, c, l_0 and theta for your variant (task_numbers('3.4')); any "
               "equivalent form accepted; derived by hand: a cell that calls the library's solvers is refused",
               numbers=_free_length_numbers)
def _t34(answer, variant):
    return equivalent(answer, _free_length_torque(variant["angle"], variant["torque"]), LAB3_FREE_LENGTH_SYMBOLS,
                      "your torque", hint="Write the spring's energy k (d - l_0)^2 / 2 with d its length; the ZFL part "
                                          "is balanced, so only -k l_0 d is left. Mind your angle and your sign.")
