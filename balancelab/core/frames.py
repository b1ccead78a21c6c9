"""The one transform kernel: a body's local point or vector carried to the world frame, and back.

A body's pose is ``(x, y, angle)``: its frame's origin (m) and the angle (rad) of its x-axis
from the global x-axis. A local point ``p`` sits at ``X + R p`` in the world, with the rotation
``R = [[c, -s], [s, c]]`` (``c = cos angle``, ``s = sin angle``); a world vector ``v`` reads
``R^T v`` in the body's frame; the point moves at ``dR/dangle p`` as the body turns. Every
module of balancelab writes these through this module (a test greps the package for rotations
written anywhere else). The functions take numbers, numpy arrays (any shape, broadcasting) or
sympy expressions; those given ``c`` and ``s`` let a caller reuse cosines it has computed once.
Layer: core; imports numpy only.
"""
from __future__ import annotations

from types import ModuleType
from typing import Any, Sequence

from numpy.typing import ArrayLike

import numpy as np

__all__ = ["rotate", "turn", "turn_back", "turn_rate", "place", "body_to_world"]


def turn(c: Any, s: Any, point: Sequence[Any]) -> tuple:
    """``R p``: the local vector ``point`` turned by the angle whose cosine and sine are ``c``, ``s``.

    Parameters
    ----------
    c, s : float, numpy.ndarray or sympy expression
        Cosine and sine of the body's angle.
    point : (x, y)
        Local coordinates (m); numbers, arrays or sympy expressions.

    Returns
    -------
    (x, y)
        World components (m), ``(c x - s y, s x + c y)``.

    Examples
    --------
    >>> turn(0.0, 1.0, (2.0, 1.0))   # a quarter turn
    (-1.0, 2.0)
    """
    return (c * point[0] - s * point[1], s * point[0] + c * point[1])


def rotate(lib: ModuleType, angle: Any, point: Sequence[Any]) -> tuple:
    """``R(angle) p`` with the math library ``lib`` (numpy, math or sympy) computing cosine and sine.

    Parameters
    ----------
    lib : module
        ``numpy``, ``math`` or ``sympy``: whatever has the ``cos`` and ``sin`` for ``angle``.
    angle : float, numpy.ndarray or sympy expression
        The body's angle (rad).
    point : (x, y)
        Local coordinates (m).

    Returns
    -------
    (x, y)
        The turned vector (m).

    Examples
    --------
    >>> import sympy as sp
    >>> t = sp.Symbol("t")
    >>> rotate(sp, t, (1, 0))
    (cos(t), sin(t))
    """
    return turn(lib.cos(angle), lib.sin(angle), point)


def turn_back(c: Any, s: Any, vector: Sequence[Any]) -> tuple:
    """``R^T v``: a world vector read in the frame of a body with cosine ``c`` and sine ``s``.

    Parameters
    ----------
    c, s : float, numpy.ndarray or sympy expression
        Cosine and sine of the body's angle.
    vector : (x, y)
        World components (m, or N for a force).

    Returns
    -------
    (x, y)
        Local components, ``(c x + s y, -s x + c y)``.

    Examples
    --------
    >>> turn_back(0.0, 1.0, turn(0.0, 1.0, (2.0, 1.0)))
    (2.0, 1.0)
    """
    return (c * vector[0] + s * vector[1], -s * vector[0] + c * vector[1])


def turn_rate(c: Any, s: Any, point: Sequence[Any]) -> tuple:
    """``dR/dangle p``: how fast (m/rad) the local point ``point`` moves as its body turns.

    Parameters
    ----------
    c, s : float, numpy.ndarray or sympy expression
        Cosine and sine of the body's angle.
    point : (x, y)
        Local coordinates (m).

    Returns
    -------
    (x, y)
        ``(-s x - c y, c x - s y)``: the turned point turned once more by a quarter turn.

    Examples
    --------
    >>> turn_rate(1.0, 0.0, (2.0, 0.0))   # a point on the x-axis moves straight up
    (-0.0, 2.0)
    """
    return (-s * point[0] - c * point[1], c * point[0] - s * point[1])


def place(x: Any, y: Any, c: Any, s: Any, point: Sequence[Any]) -> tuple:
    """``X + R p``: the world position of the local ``point`` of a body at ``(x, y)`` turned by (c, s).

    A point on the body's x-axis (a plain number ``0`` as its ``y``) skips the terms that
    would multiply zero; the result is the same.

    Parameters
    ----------
    x, y : float, numpy.ndarray or sympy expression
        The body frame's origin (m).
    c, s : float, numpy.ndarray or sympy expression
        Cosine and sine of the body's angle.
    point : (x, y)
        Local coordinates (m).

    Returns
    -------
    (x, y)
        World coordinates (m), ``(x + c p_x - s p_y, y + s p_x + c p_y)``.

    Examples
    --------
    >>> place(1.0, 0.0, 0.0, 1.0, (2.0, 0.0))   # body at (1, 0) pointing up
    (1.0, 2.0)
    """
    px, py = point[0], point[1]
    if isinstance(py, (int, float)) and py == 0:
        return (x + c * px, y + s * px)
    return (x + c * px - s * py, y + s * px + c * py)


def body_to_world(poses: np.ndarray, bodies: ArrayLike, points: ArrayLike) -> tuple[np.ndarray, np.ndarray]:
    """Global coordinates of local body points, for every configuration.

    Parameters
    ----------
    poses : numpy.ndarray, shape (..., nbodies, 3)
        Body poses ``(x, y, angle)`` (m, m, rad).
    bodies : array_like of int, shape (n,)
        Body index of each point.
    points : array_like, shape (n, 2)
        Points in their bodies' local frames (m).

    Returns
    -------
    (numpy.ndarray, numpy.ndarray)
        ``x`` and ``y`` (m), each of shape ``(..., n)``.

    Examples
    --------
    >>> poses = np.array([[0.0, 0.0, 0.0], [1.0, 0.0, np.pi / 2]])
    >>> x, y = body_to_world(poses, [1], [(2.0, 0.0)])
    >>> round(float(x[0]), 12), round(float(y[0]), 12)
    (1.0, 2.0)
    """
    bodies = np.asarray(bodies, dtype=int)
    points = np.asarray(points, dtype=float).reshape(-1, 2)
    P = poses[..., bodies, :]
    return place(P[..., 0], P[..., 1], np.cos(P[..., 2]), np.sin(P[..., 2]), (points[:, 0], points[:, 1]))
