"""The input checks every public function uses: one message style for bad input.

Each check returns the value in its canonical type or raises a ``TypeError`` (wrong
kind of value) or ``ValueError`` (outside the valid range) whose message names the
parameter and the valid range. Layer: core; imports nothing from balancelab.
"""
from __future__ import annotations

import math
from numbers import Real
from typing import Any

import numpy as np

__all__ = ["finite_real", "planar_point", "body_index", "positive_int", "finite_reals", "planar_points",
           "length_or_symbol", "step_size", "sequence_of", "instance_of", "real_array", "option", "MAX_MAGNITUDE", "MIN_POSITIVE"]

#: largest magnitude of any input quantity (SI units): beyond it products overflow
MAX_MAGNITUDE = 1e12
#: smallest value of a quantity that must be > 0 (a length, a mass, a stiffness); also the smallest
#: magnitude a builder accepts where it divides by a signed quantity (below it quotients overflow)
MIN_POSITIVE = 1e-12


def finite_real(name: str, value: Any, *, positive: bool = False, nonnegative: bool = False) -> float:
    """Return ``value`` as a float, or raise a clear error naming ``name``."""
    if isinstance(value, bool) or not isinstance(value, (Real, np.floating, np.integer)):
        raise TypeError(f"{name} must be a real number, got {type(value).__name__} {value!r}")
    try:
        value = float(value)
    except OverflowError:
        raise ValueError(f"{name} must be finite and of magnitude <= {MAX_MAGNITUDE:g}, got {value!r}") from None
    if not math.isfinite(value):
        raise ValueError(f"{name} must be finite, got {value}")
    if abs(value) > MAX_MAGNITUDE:
        raise ValueError(f"{name} must be of magnitude <= {MAX_MAGNITUDE:g} (SI units), got {value:g}")
    if positive and value <= 0:
        raise ValueError(f"{name} must be > 0, got {value}")
    if positive and value < MIN_POSITIVE:
        raise ValueError(f"{name} must be >= {MIN_POSITIVE:g} (SI units: smaller makes quotients overflow), "
                         f"got {value:g}")
    if nonnegative and value < 0:
        raise ValueError(f"{name} must be >= 0, got {value}")
    return value


def planar_point(name: str, value: Any, unit: str = "m") -> tuple[float, float]:
    """Return a planar point (or a planar vector of ``unit``, e.g. a force in N) as a tuple of two
    floats, or raise naming ``name``.

    Examples
    --------
    >>> planar_point("force (N)", (0.0, 2e12), unit="N")
    Traceback (most recent call last):
    ...
    ValueError: force (N) must have coordinates of magnitude <= 1e+12 N, got (0, 2e+12)
    """
    if isinstance(value, (str, bytes)) or value is None or isinstance(value, dict) or (
            isinstance(value, (tuple, list)) and any(isinstance(c, (bool, np.bool_)) for c in value)):
        # a True or False among the coordinates is not a number, though numpy would make it one
        raise TypeError(f"{name} must be a pair of numbers (x, y) in {'metres' if unit == 'm' else unit}, got {value!r}")
    try:
        arr = np.asarray(value)
    except (TypeError, ValueError):
        raise TypeError(f"{name} must be a pair of numbers (x, y) in {'metres' if unit == 'm' else unit}, got {value!r}") from None
    if arr.dtype.kind not in "iuf" or arr.dtype == bool:
        if arr.ndim == 1 and all(isinstance(v, (Real, np.floating, np.integer)) and not isinstance(v, bool)
                                 for v in arr.tolist()):
            arr = arr.astype(float)
        else:
            raise TypeError(f"{name} must be a pair of numbers (x, y) in {'metres' if unit == 'm' else unit}, got {value!r}")
    arr = arr.astype(float)
    if arr.shape != (2,):
        raise ValueError(f"{name} must have exactly two coordinates (x, y), got shape {arr.shape}")
    if not np.all(np.isfinite(arr)):
        raise ValueError(f"{name} must be finite, got {tuple(arr)}")
    if np.abs(arr).max() > MAX_MAGNITUDE:
        raise ValueError(f"{name} must have coordinates of magnitude <= {MAX_MAGNITUDE:g} {unit}, got ({arr[0]:g}, {arr[1]:g})")
    return (float(arr[0]), float(arr[1]))


def body_index(name: str, value: Any, nbodies: int | None = None, *, moving: bool = False) -> int:
    """Return ``value`` as a body index (an int >= 0, 0 the ground), or raise naming ``name``.

    With ``nbodies`` the index must also name one of that many bodies, and with ``moving``
    one of the moving bodies ``1..nbodies - 1``.

    Examples
    --------
    >>> body_index("body", 2), body_index("body", 2, 3, moving=True)
    (2, 2)
    """
    if isinstance(value, bool) or not isinstance(value, (int, np.integer)):
        raise TypeError(f"{name} must be a body index (int, 0 is the ground), got {value!r}")
    if value < 0:
        raise ValueError(f"{name} must be a body index >= 0 (0 is the ground), got {value}")
    if nbodies is not None and moving and not 0 < value < nbodies:
        raise ValueError(f"{name} must be a moving body 1..{nbodies - 1}, got {value!r}")
    if nbodies is not None and value >= nbodies:
        raise ValueError(f"{name} must be a body index 0..{nbodies - 1}, got {value!r}")
    return int(value)


def positive_int(name: str, value: Any, minimum: int = 1, maximum: int | None = None) -> int:
    """Return ``value`` as an int in ``minimum..maximum``, or raise a clear error naming ``name``.

    The one integer check of the package: a value that is not an integer (``2.5``, ``"3"``,
    ``True``) is a ``TypeError``, an integer out of range a ``ValueError``; both name the range.

    Examples
    --------
    >>> positive_int("n", 5)
    5
    >>> positive_int("index", 4, 1, 3)
    Traceback (most recent call last):
    ...
    ValueError: index must be an integer in 1..3, got 4
    """
    want = f"an integer >= {minimum}" if maximum is None else f"an integer in {minimum}..{maximum}"
    if isinstance(value, bool) or not isinstance(value, (int, np.integer)):
        raise TypeError(f"{name} must be {want}, got {value!r}")
    if value < minimum or (maximum is not None and value > maximum):
        raise ValueError(f"{name} must be {want}, got {value}")
    return int(value)


def _nth(name: str, i: int) -> str:
    """``"masses (kg)"``, 0 -> ``"masses[0] (kg)"``."""
    base, sep, rest = name.partition(" (")
    return f"{base}[{i}]{sep}{rest}"


def _items(name: str, value, n: int | None, what: str) -> list:
    want = f"{n} {what}" if n is not None else f"a sequence of {what}"
    if isinstance(value, (str, bytes)) or value is None or isinstance(value, dict):
        raise TypeError(f"{name} must be {want}, got {value!r}")
    try:
        items = list(value)
    except TypeError:
        raise TypeError(f"{name} must be {want}, got {value!r}") from None
    if n is not None and len(items) != n:
        raise ValueError(f"{name} must be {want}, got {len(items)}")
    if n is None and not items:
        raise ValueError(f"{name} must be {want}, got none")
    return items


def finite_reals(name: str, value: Any, n: int | None, *, positive: bool = False,
                 nonnegative: bool = False) -> tuple[float, ...]:
    """Return ``value`` as a tuple of ``n`` floats (one per body or spring), each checked.

    ``n=None`` accepts any non-empty number of items.

    Examples
    --------
    >>> finite_reals("masses (kg)", [1, 2.5], 2, positive=True)
    (1.0, 2.5)
    """
    items = _items(name, value, n, "numbers")
    return tuple(finite_real(_nth(name, i), v, positive=positive, nonnegative=nonnegative)
                 for i, v in enumerate(items))


def planar_points(name: str, value: Any, n: int | None) -> tuple[tuple[float, float], ...]:
    """Return ``value`` as a tuple of ``n`` points ``(x, y)``, each checked.

    ``n=None`` accepts any non-empty number of points.

    Examples
    --------
    >>> planar_points("coms (m)", [(0.2, 0), (0.5, 0.1)], 2)
    ((0.2, 0.0), (0.5, 0.1))
    """
    items = _items(name, value, n, "points (x, y)")
    return tuple(planar_point(_nth(name, i), v) for i, v in enumerate(items))


def length_or_symbol(name: str, value: Any) -> Any:
    """A length (m, a float > 0, checked) or a sympy expression (for a symbolic energy), unchanged.

    Examples
    --------
    >>> length_or_symbol("length (m)", 2)
    2.0
    """
    if hasattr(value, "free_symbols") and not isinstance(value, (Real, np.floating, np.integer)):
        return value
    return finite_real(name, value, positive=True)


def step_size(name: str, value: Any, maximum: float) -> float:
    """Return a finite-difference step in ``(0, maximum]``, or raise naming ``name`` (0 is no step).

    Examples
    --------
    >>> step_size("h (step, rad)", 1e-6, 0.1)
    1e-06
    """
    value = finite_real(name, value, positive=True)
    if value > maximum:
        raise ValueError(f"{name} must be a small step in (0, {maximum:g}], got {value:g}")
    return value


def sequence_of(name: str, value: Any, kind: type) -> tuple:
    """Return ``value`` as a tuple of ``kind`` instances, or raise a ``TypeError`` naming ``name``.

    Examples
    --------
    >>> sequence_of("weights", [1.0, 2.0], float)
    (1.0, 2.0)
    """
    if isinstance(value, (str, bytes, dict, kind)) or not hasattr(value, "__iter__"):
        raise TypeError(f"{name} must be a sequence of {kind.__name__} objects, got {value!r}"[:300])
    items = tuple(value)
    for i, item in enumerate(items):
        if not isinstance(item, kind):
            raise TypeError(f"{name}[{i}] must be a {kind.__name__}, got {type(item).__name__}")
    return items


def instance_of(name: str, value: Any, kind: type | tuple, what: str) -> Any:
    """Return ``value`` if it is an instance of ``kind``, else raise a ``TypeError`` naming ``name``.

    Examples
    --------
    >>> instance_of("weights", (1.0, 2.0), tuple, "a tuple")
    (1.0, 2.0)
    """
    if not isinstance(value, kind):
        raise TypeError(f"{name} must be {what}, got {type(value).__name__} {value!r}"[:300])
    return value


def real_array(name: str, value: Any, *, ndim_min: int = 0) -> np.ndarray:
    """Return ``value`` as a float array of finite numbers, or raise naming ``name``.

    Strings, ``None`` and non-numeric items are refused (no silent ``float("0.1")``).

    Examples
    --------
    >>> real_array("q", [0.1, 0.2]).tolist()
    [0.1, 0.2]
    """
    if isinstance(value, (str, bytes)) or value is None or isinstance(value, dict):
        raise TypeError(f"{name} must be an array of numbers, got {value!r}"[:300])
    try:
        arr = np.asarray(value)
    except (TypeError, ValueError):
        raise TypeError(f"{name} must be an array of numbers, got {value!r}"[:300]) from None
    if arr.dtype.kind not in "iuf":
        raise TypeError(f"{name} must be an array of numbers, got {value!r}"[:300])
    arr = arr.astype(float)
    if arr.ndim < ndim_min:
        raise ValueError(f"{name} must have at least {ndim_min} dimension(s), got shape {arr.shape}")
    if not np.all(np.isfinite(arr)):
        raise ValueError(f"{name} must be finite numbers, got {value!r}"[:300])
    if arr.size and np.abs(arr).max() > MAX_MAGNITUDE:
        raise ValueError(f"{name} must be of magnitude <= {MAX_MAGNITUDE:g}, got {value!r}"[:300])
    return arr


def option(name: str, value: Any, choices: tuple) -> Any:
    """Return ``value`` if it is one of ``choices``, else raise a ``ValueError`` naming ``name``.

    Examples
    --------
    >>> option("base", "A", ("A", "B"))
    'A'
    """
    if isinstance(value, bool) or not any(value == c and type(value) is type(c) for c in choices):
        raise ValueError(f"{name} must be one of {choices}, got {value!r}")
    return value
