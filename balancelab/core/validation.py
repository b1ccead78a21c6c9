"""The input checks every public function uses: one message style for bad input.

Each check returns the value in its canonical type or raises a ``TypeError`` (wrong
kind of value) or ``ValueError`` (outside the valid range) whose message names the
parameter and the valid range. Layer: core; imports nothing from balancelab.
"""
from __future__ import annotations

import math
from numbers import Real

import numpy as np

__all__ = ["finite_real", "planar_point", "body_index", "positive_int", "finite_reals", "planar_points"]


def finite_real(name: str, value, *, positive: bool = False, nonnegative: bool = False) -> float:
    """Return ``value`` as a float, or raise a clear error naming ``name``."""
    if isinstance(value, bool) or not isinstance(value, (Real, np.floating, np.integer)):
        raise TypeError(f"{name} must be a real number, got {type(value).__name__} {value!r}")
    value = float(value)
    if not math.isfinite(value):
        raise ValueError(f"{name} must be finite, got {value}")
    if positive and value <= 0:
        raise ValueError(f"{name} must be > 0, got {value}")
    if nonnegative and value < 0:
        raise ValueError(f"{name} must be >= 0, got {value}")
    return value


def planar_point(name: str, value) -> tuple[float, float]:
    """Return a planar point as a tuple of two floats, or raise naming ``name``."""
    try:
        arr = np.asarray(value, dtype=float)
    except (TypeError, ValueError):
        raise TypeError(f"{name} must be a pair of numbers (x, y) in metres, got {value!r}") from None
    if arr.shape != (2,):
        raise ValueError(f"{name} must have exactly two coordinates (x, y), got shape {arr.shape}")
    if not np.all(np.isfinite(arr)):
        raise ValueError(f"{name} must be finite, got {tuple(arr)}")
    return (float(arr[0]), float(arr[1]))


def body_index(name: str, value) -> int:
    if isinstance(value, bool) or not isinstance(value, (int, np.integer)):
        raise TypeError(f"{name} must be a body index (int, 0 is the ground), got {value!r}")
    if value < 0:
        raise ValueError(f"{name} must be a body index >= 0 (0 is the ground), got {value}")
    return int(value)


def positive_int(name: str, value, minimum: int = 1) -> int:
    """Return ``value`` as an int ``>= minimum``, or raise a clear error naming ``name``.

    Examples
    --------
    >>> positive_int("n", 5)
    5
    """
    if isinstance(value, bool) or not isinstance(value, (int, np.integer)):
        raise TypeError(f"{name} must be an integer >= {minimum}, got {value!r}")
    if value < minimum:
        raise ValueError(f"{name} must be an integer >= {minimum}, got {value}")
    return int(value)


def _nth(name: str, i: int) -> str:
    """``"masses (kg)"``, 0 -> ``"masses[0] (kg)"``."""
    base, sep, rest = name.partition(" (")
    return f"{base}[{i}]{sep}{rest}"


def _items(name: str, value, n: int, what: str) -> list:
    if isinstance(value, (str, bytes)):
        raise TypeError(f"{name} must be {n} {what}, got {value!r}")
    try:
        items = list(value)
    except TypeError:
        raise TypeError(f"{name} must be {n} {what}, got {value!r}") from None
    if len(items) != n:
        raise ValueError(f"{name} must be {n} {what}, got {len(items)}")
    return items


def finite_reals(name: str, value, n: int, *, positive: bool = False,
                 nonnegative: bool = False) -> tuple[float, ...]:
    """Return ``value`` as a tuple of ``n`` floats (one per body or spring), each checked.

    Examples
    --------
    >>> finite_reals("masses (kg)", [1, 2.5], 2, positive=True)
    (1.0, 2.5)
    """
    items = _items(name, value, n, "numbers")
    return tuple(finite_real(_nth(name, i), v, positive=positive, nonnegative=nonnegative)
                 for i, v in enumerate(items))


def planar_points(name: str, value, n: int) -> tuple[tuple[float, float], ...]:
    """Return ``value`` as a tuple of ``n`` points ``(x, y)``, each checked.

    Examples
    --------
    >>> planar_points("coms (m)", [(0.2, 0), (0.5, 0.1)], 2)
    ((0.2, 0.0), (0.5, 0.1))
    """
    items = _items(name, value, n, "points (x, y)")
    return tuple(planar_point(_nth(name, i), v) for i, v in enumerate(items))
