"""The smooth part of an energy sampled over configurations, and what is left: round-off noise.

A design's energy is a combination of ``cos``/``sin`` of its bodies' angles and of their
differences (every ZFL spring and weight), and of its slides ``s``, ``s^2``, ``s cos theta``,
``s sin theta``. The round-off of summing large energies and a closed loop's solving error are not:
they jump from one configuration to the next. A least-squares fit on these terms splits a sampled
energy into the two, so the verdict of :func:`balancelab.core.report.balance_report` can tell a real
variation (smooth) from noise that the round-off allowance covers. Layer: core.
"""
from __future__ import annotations

import math
from typing import Sequence

import numpy as np

__all__ = ["NOISE_SIGMAS", "smooth_split", "smooth_resolution"]

#: How many standard deviations of the noise's share of the fit :func:`smooth_resolution` allows
#: at each configuration: beyond 6, a Gaussian tail has odds below 1e-8 at each of some 1e3 rows.
NOISE_SIGMAS: float = 6.0


def _features(poses: np.ndarray, q: np.ndarray, units) -> np.ndarray:
    th = poses[..., 2]
    nb = th.shape[1]
    trig = []
    for b in range(1, nb):
        trig += [np.cos(th[:, b]), np.sin(th[:, b])]
        for c in range(b + 1, nb):
            trig += [np.cos(th[:, c] - th[:, b]), np.sin(th[:, c] - th[:, b])]
    # a term that hardly varies (two bodies of a parallelogram turning alike: the sine of their
    # difference is the loop's solving error itself) would fit the noise: a cos or sin must vary by
    # more than 1e-6, a slide's term by more than 1e-6 of its size
    keep = [f for f in trig if np.ptp(f) > 1e-6]
    for i, unit in enumerate(units):
        if unit == "m":
            s = q[:, i]
            slide = [s, s * s] + [s * f for f in trig[: 2 * (nb - 1)]]
            keep += [f for f in slide if np.ptp(f) > 1e-6 * max(float(np.abs(f).max()), 1e-300)]
    return np.stack([np.ones(len(th)) / np.sqrt(len(th))] + [f / np.linalg.norm(f) for f in keep], -1)


def smooth_split(poses: np.ndarray, q: np.ndarray, units: Sequence[str], energy: np.ndarray) -> tuple[float, float]:
    """``(spread of the smooth part, spread of the rest)`` (J) of ``energy`` sampled at ``q``.

    Parameters
    ----------
    poses : numpy.ndarray, shape (m, nbodies, 3)
        Poses ``(x, y, theta)`` (m, rad) at the configurations.
    q : numpy.ndarray, shape (m, dof)
        The configurations (rad for angles, m for slides).
    units : sequence of str
        ``"rad"`` or ``"m"`` for each coordinate.
    energy : numpy.ndarray, shape (m,)
        The energy (J) at each configuration.

    Returns
    -------
    tuple of float

    Examples
    --------
    >>> th = np.linspace(-3.0, 3.0, 200)
    >>> poses = np.zeros((200, 2, 3)); poses[:, 1, 2] = th
    >>> noise = 1e-9 * np.random.default_rng(0).standard_normal(200)
    >>> smooth, rest = smooth_split(poses, th[:, None], ("rad",), 2.0 * np.sin(th) + noise)
    >>> round(smooth, 3), rest < 1e-8     # 2 sin(theta) over (-3, 3) rad, and the noise
    (4.0, True)
    """
    F = _features(poses, np.asarray(q, dtype=float).reshape(len(energy), -1), units)
    e = np.asarray(energy, dtype=float) - float(np.mean(energy))
    fit = F @ np.linalg.lstsq(F, e, rcond=1e-10)[0]
    return float(np.ptp(fit)), float(np.ptp(e - fit))


def smooth_resolution(poses: np.ndarray, q: np.ndarray, units: Sequence[str], energy: np.ndarray) -> float:
    """How large (J) a spread of the smooth part of ``energy`` the noise alone can make.

    The fit of :func:`smooth_split` is a projection ``P e``; noise of standard deviation ``sigma``
    independent from one configuration to the next puts a share of standard deviation
    ``sigma sqrt(h_i)`` into the fit at row ``i`` (``h_i``, the leverage, is ``P``'s diagonal). With
    ``sigma`` estimated from the rest, ``|e - P e|^2 / (m - p)`` (``p`` the fit's rank), the noise's
    share of the smooth spread is at most ``2 NOISE_SIGMAS sigma sqrt(max h)``: a smooth spread
    within it cannot be told from noise.

    Parameters
    ----------
    poses, q, units, energy
        As for :func:`smooth_split`.

    Returns
    -------
    float

    Examples
    --------
    >>> th = np.linspace(-3.0, 3.0, 200)
    >>> poses = np.zeros((200, 2, 3)); poses[:, 1, 2] = th
    >>> noise = 1e-9 * np.random.default_rng(0).standard_normal(200)
    >>> r = smooth_resolution(poses, th[:, None], ("rad",), 2.0 * np.sin(th) + noise)
    >>> 1e-10 < r < 1e-8  # J: a 2 sin(theta) fit is sure to some 1e-9 J
    True
    """
    F = _features(poses, np.asarray(q, dtype=float).reshape(len(energy), -1), units)
    e = np.asarray(energy, dtype=float) - float(np.mean(energy))
    u, sv, _ = np.linalg.svd(F, full_matrices=False)
    u = u[:, sv > 1e-10 * sv[0]]
    rank = u.shape[1]
    if len(e) <= rank:
        return float("inf")
    rest = e - u @ (u.T @ e)
    sigma = float(np.linalg.norm(rest)) / math.sqrt(len(e) - rank)
    leverage = float(np.max(np.sum(u * u, axis=1)))
    return 2.0 * NOISE_SIGMAS * sigma * float(np.sqrt(leverage))
