"""Whether a set of configurations can show that an energy is constant: the check behind a report's ``q``.

A design's energy is a sum of a few harmonics of its coordinates: ``cos q_i``, ``sin q_i``, their
doubles, ``cos(q_i - q_j)``, ``sin(q_i - q_j)`` for angles; ``s``, ``s^2`` and ``s_i s_j`` for slides.
A set of configurations on which one of these (or a combination) is constant — ``theta_2`` only
``0`` or ``pi``, or ``theta_2 = theta_1`` throughout — cannot tell a balanced design from an
unbalanced one: :func:`check_spread` refuses it. Layer: core.
"""
from __future__ import annotations

from typing import Sequence

import numpy as np

__all__ = ["harmonic_features", "check_spread"]

#: The configurations must give the harmonics a matrix of at least this reciprocal condition number
#: (lax: harmonics over a short range are nearly dependent, yet tell a constant energy apart).
MIN_CONDITION: float = 1e-12

#: Fewest distinct values of each coordinate (an energy term of an angle has up to five coefficients).
MIN_VALUES: int = 5


def harmonic_features(q: np.ndarray, units: Sequence[str]) -> tuple[np.ndarray, list[str]]:
    """The harmonics of a design's energy at configurations ``q`` (rad or m): columns and their names.

    Examples
    --------
    >>> F, names = harmonic_features(np.array([[0.0, 1.0], [1.0, 2.0]]), ("rad", "m"))
    >>> F.shape, names[:2]
    ((2, 7), ['cos q1', 'sin q1'])
    """
    q = np.asarray(q, dtype=float)
    cols, names = [], []
    for i, unit in enumerate(units):
        v = q[:, i]
        if unit == "rad":
            cols += [np.cos(v), np.sin(v), np.cos(2 * v), np.sin(2 * v)]
            names += [f"{f} q{i + 1}" for f in ("cos", "sin", "cos 2", "sin 2")]
        else:
            span = max(float(np.ptp(v)), 1e-300)
            u = (v - v.mean()) / span  # dimensionless, so that slides of any length condition alike
            cols += [u, u * u]
            names += [f"s{i + 1}", f"s{i + 1}^2"]
    for i in range(len(units)):
        for j in range(i):
            a, b = q[:, i], q[:, j]
            if units[i] == units[j] == "rad":
                cols += [np.cos(a - b), np.sin(a - b)]
                names += [f"cos(q{i + 1} - q{j + 1})", f"sin(q{i + 1} - q{j + 1})"]
            else:
                cols.append(cols[_index(units, i)] * cols[_index(units, j)])
                names.append(f"q{i + 1} q{j + 1}")
    return np.stack(cols, -1), names


def _index(units, i: int) -> int:
    """Column of coordinate ``i``'s first harmonic (``cos q_i``, or the slide itself)."""
    return sum(4 if u == "rad" else 2 for u in units[:i])


def check_spread(q: np.ndarray, units: Sequence[str], names: Sequence[str]) -> None:
    """Refuse configurations ``q`` on which a harmonic of the energy cannot vary independently.

    Raises
    ------
    ValueError
        Naming ``q``, the harmonic (or combination) that stays constant, and how many
        configurations are needed.

    Examples
    --------
    >>> t = np.linspace(-3.0, 3.0, 40)
    >>> check_spread(np.c_[t, np.where(t > 0, 0.0, np.pi)], ("rad", "rad"), ("theta_1", "theta_2"))
    Traceback (most recent call last):
    ...
    ValueError: q must give each coordinate at least 5 distinct values (so that each term of the energy is seen to change): theta_2 takes 2; use design.sample(n) or a grid
    >>> check_spread(np.c_[t, t], ("rad", "rad"), ("theta_1", "theta_2"))  # theta_2 = theta_1 throughout
    Traceback (most recent call last):
    ...
    ValueError: q must vary every coordinate independently over its range (so that each term of the energy, cos and sin of every coordinate, their doubles and their differences, is seen to change): on these 40 configurations cos(q2 - q1) does not vary independently; coordinates ('theta_1', 'theta_2'); use design.sample(n) or a grid
    """
    for i, unit in enumerate(units):  # each coordinate: enough distinct values (an angle modulo a turn)
        v = np.angle(np.exp(1j * q[:, i])) if unit == "rad" else q[:, i]
        values = len(np.unique(np.round(v / max(float(np.abs(v).max()), 1e-300), 9)))
        if values < MIN_VALUES:
            raise ValueError(f"q must give each coordinate at least {MIN_VALUES} distinct values (so that each "
                             f"term of the energy is seen to change): {names[i]} takes {values}; "
                             "use design.sample(n) or a grid")
    F, labels = harmonic_features(q, units)
    F = F - F.mean(0)
    norms = np.linalg.norm(F, axis=0)
    need = F.shape[1] + 1
    message = ("q must vary every coordinate independently over its range (so that each term of the energy, "
               "cos and sin of every coordinate, their doubles and their differences, is seen to change): ")
    if len(q) < need:
        raise ValueError(message + f"{len(q)} configurations cannot, at least {need} are needed for "
                         f"{len(units)} coordinate(s) {tuple(names)}")
    dead = np.flatnonzero(norms <= 1e-9 * np.sqrt(len(q)))
    if len(dead) == 0:
        _, sv, vt = np.linalg.svd(F / norms, full_matrices=False)
        if sv[-1] >= MIN_CONDITION * sv[0]:
            return
        dead = np.array([int(np.argmax(np.abs(vt[-1])))])
    raise ValueError(message + f"on these {len(q)} configurations {labels[dead[0]]} does not vary independently; "
                     f"coordinates {tuple(names)}; use design.sample(n) or a grid")
