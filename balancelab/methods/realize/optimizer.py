"""Approximate balancing with an ordinary spring placed by an optimizer.

Source: Lecture 35 (*Theory of Mechanisms*), approximate balancing with regular (or gas)
springs: no ordinary spring balances a lever exactly, so the anchor, the attachment and the
rate are chosen to make the residual torque small over a working range (scipy.optimize).
"""
from __future__ import annotations

import math

import numpy as np

from ...core.design import Design
from ...core.elements import G, Load, Spring
from ...core.errors import ApproximationError
from ...core.frames import turn
from ...core.validation import finite_real, finite_reals, planar_points, positive_int
from ...mechanisms.lever import lever_design
from ..registry import register

__all__ = ["ApproximationError", "approximate_lever"]

def _lever_torque(x, mass, r, l0, th):
    bx, by, ax, ay, k = x
    c, s = np.cos(th), np.sin(th)
    Ax, Ay = turn(c, s, (ax, ay))
    dAx, dAy = -Ay, Ax
    dx, dy = Ax - bx, Ay - by
    d = np.hypot(dx, dy)
    f = k * (d - l0) / np.where(d > 0, d, 1e-300)
    return mass * G * r * c + f * (dx * dAx + dy * dAy)


def _lever_energy(x, mass, r, l0, th):
    bx, by, ax, ay, k = x
    c, s = np.cos(th), np.sin(th)
    Ax, Ay = turn(c, s, (ax, ay))
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


register("approximate_spring_lever", "Ordinary coil spring placed by optimization: approximately "
         "balanced over +-60 deg (lecture 35)", approximate_lever, chapter=3, expected_balanced=False)
