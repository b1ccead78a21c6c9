"""The smooth part of an energy sampled over configurations, and what is left: round-off noise.

A design's energy is a combination of ``cos``/``sin`` of its bodies' angles and of their
differences (every ZFL spring and weight), and of its slides ``s``, ``s^2``, ``s cos theta``,
``s sin theta``. The round-off of summing large energies and a closed loop's solving error are not:
they jump from one configuration to the next. A least-squares fit on these terms splits a sampled
energy into the two, so the verdict of :func:`balancelab.core.report.balance_report` can tell a real
variation (smooth) from noise that the round-off allowance covers. Layer: core.
"""
from __future__ import annotations

from typing import Sequence

import numpy as np

__all__ = ["smooth_split"]


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
