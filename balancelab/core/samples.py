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

__all__ = ["harmonic_features", "check_spread", "fill_dimension"]

#: The configurations must give the harmonics a matrix of at least this reciprocal condition number
#: (lax: harmonics over a short range are nearly dependent, yet tell a constant energy apart).
MIN_CONDITION: float = 1e-12

#: Least share of its coordinates' count a set's measured dimension must reach (a level set of the
#: energy, a curve among two coordinates or a surface among three, falls short of it).
MIN_FILL: float = 0.75

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


def fill_dimension(q: np.ndarray) -> float:
    """The dimension the configurations ``q`` (rad or m) fill, measured by counting occupied cells.

    Each coordinate is scaled to its own span and cut into cells at two scales, the finer one as fine
    as the set can fill (about two configurations a cell, never finer than the coordinate's distinct
    values); the growth of the occupied cells from the coarse to the fine scale, against the growth
    a set filling every coordinate would show, gives the dimension: about ``q.shape[1]`` for a grid or
    a random sample, about one less for configurations on a curve or surface (a level set of an energy).
    Independent of any energy.

    Examples
    --------
    >>> t = np.linspace(0.0, 1.0, 20)
    >>> float(round(fill_dimension(np.stack(np.meshgrid(t, t), -1).reshape(-1, 2)), 2))  # a grid
    2.0
    >>> s = np.linspace(0.0, 6.0, 400)
    >>> fill_dimension(np.c_[s, np.sin(3 * s)]) < 1.5  # a curve
    True
    """
    q = np.asarray(q, dtype=float)
    n, d = q.shape
    u = (q - q.min(0)) / np.maximum(np.ptp(q, axis=0), 1e-300)
    fine = max(2, int((n / 4) ** (1 / d)))
    distinct = [len(np.unique(np.round(u[:, i], 9))) for i in range(d)]
    m2 = np.array([min(fine, v) for v in distinct])
    m1 = np.maximum(1, np.ceil(m2 / 2)).astype(int)

    def occupied(m: np.ndarray) -> int:
        cells = np.minimum((u * m).astype(int), m - 1)
        return len(np.unique(cells, axis=0))

    full = float(np.sum(np.log(m2 / m1)))
    if full <= 0.0:
        return float(d)
    return d * float(np.log(occupied(m2) / occupied(m1))) / full


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
    >>> s = np.linspace(-3.0, 3.0, 200)
    >>> check_spread(np.c_[s, 2.5 * np.sin(3 * s)], ("rad", "rad"), ("theta_1", "theta_2"))  # a curve
    Traceback (most recent call last):
    ...
    ValueError: q must fill the configuration space, not lie on a curve or surface (a level set of the energy is constant on any design): these 200 configurations fill 1.3 of the 2 dimensions of ('theta_1', 'theta_2'), at least 1.5 are needed; use design.sample(n) or a grid
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
            _check_fill(q, names)
            return
        dead = np.array([int(np.argmax(np.abs(vt[-1])))])
    raise ValueError(message + f"on these {len(q)} configurations {labels[dead[0]]} does not vary independently; "
                     f"coordinates {tuple(names)}; use design.sample(n) or a grid")


def _check_fill(q: np.ndarray, names: Sequence[str]) -> None:
    """Refuse configurations ``q`` that lie on a curve or surface rather than fill their space."""
    if q.shape[1] > 1 and fill_dimension(q) < MIN_FILL * q.shape[1]:
        raise ValueError(f"q must fill the configuration space, not lie on a curve or surface (a level set of "
                         f"the energy is constant on any design): these {len(q)} configurations fill "
                         f"{fill_dimension(q):.2g} of the {q.shape[1]} dimensions of {tuple(names)}, at "
                         f"least {MIN_FILL * q.shape[1]:.3g} are needed; use design.sample(n) or a grid")
