"""Joint friction: why a slightly unbalanced lamp still stays where it is left.

Model: Coulomb friction in every revolute joint, a torque of at most ``tau_j`` (N m)
resisting relative rotation. A design *stays where it is left* in a configuration when
the holding torque each joint would have to supply (the statics of
:func:`balancelab.methods.practice.forces.joint_loads`) is within its friction:
``|t_j| <= tau_j`` for every joint. Friction therefore hides a band of imbalance: for an
extra mass ``dm`` at a point, the holding torques are ``t = t_0 + dm t_1`` (``t_1`` those of
a 1 kg mass there), and the design stays put over the whole range for every ``dm`` in an
interval (:func:`friction_band`). For the lecture's balanced link with friction ``tau``
and the extra mass at the distance ``r`` from the pivot, the band is ``|dm| <= tau / (g r)``.

To move the design along a direction ``v`` of its coordinates, a hand at a point ``P``
must supply the generalized force ``Q . v`` plus friction
``sum_j tau_j |d phi_j/dq . v|``; pushing along the point's own velocity (the most
effective direction) that takes a force ``(Q . v + friction) / |dP/dq . v|``
(:func:`hand_force`). Over a full turn of a single link, ``+direction`` is counter-clockwise
and ``-direction`` clockwise: whether that lifts or lowers the tip depends on the angle.

Pin friction is not a constant: a pin of radius ``r_pin`` with friction coefficient
``mu`` resists with about ``mu r_pin |F_j|``, ``F_j`` the joint's load
(:func:`pin_friction`); its largest value over the range is a safe constant ``tau_j`` for
the functions above. Layer: methods.
"""
from __future__ import annotations

from typing import NamedTuple

import numpy as np

from ...core.design import Design
from ...core.elements import gravity_load
from ...core.frames import turn_rate
from ...core.validation import body_index, finite_real, planar_point
from . import forces  # noqa: F401 (the doctests use the module by name)
from .forces import configurations, generalized_force, joint_loads, joint_tree, pose_jacobian

__all__ = ["joint_friction", "pin_friction", "holding_torques", "stays_put", "FrictionBand", "friction_band",
           "hand_force"]


def joint_friction(design: Design, friction) -> np.ndarray:
    """Friction torque (N m) of every joint: one number for all, or one per joint, each >= 0.

    Examples
    --------
    >>> import balancelab as bl
    >>> joint_friction(bl.singh.serial_2r_min_preload(), 0.2).tolist()
    [0.2, 0.2]
    """
    nj = len(design.joints)
    if np.ndim(friction) == 0:
        return np.full(nj, finite_real("friction (N m)", friction, nonnegative=True))
    values = [finite_real(f"friction[{j}] (N m)", v, nonnegative=True) for j, v in enumerate(friction)]
    if len(values) != nj:
        raise ValueError(f"friction must be one torque (N m) or one per joint ({nj}), got {len(values)}")
    return np.array(values)


def pin_friction(design: Design, mu: float, pin_radius: float, q=None, n: int = 61) -> tuple[np.ndarray, np.ndarray]:
    """Configurations ``(m, dof)`` and the friction torque ``mu r_pin |F_j|`` (N m) of every joint ``(m, n_joints)``.

    ``F_j`` is the joint's load from :func:`balancelab.methods.practice.forces.joint_loads`
    (springs, weights and reactions of the part beyond the joint).

    Parameters
    ----------
    design : Design
        A tree design.
    mu : float
        Friction coefficient of the pin in its bore, >= 0.
    pin_radius : float
        Radius of the pin (m), >= 0.
    q, n
        Configurations, as in :func:`stays_put`.

    Examples
    --------
    >>> import balancelab as bl
    >>> d = bl.lecture.single_link_spring(2.0, 0.5, 0.3, 0.2)
    >>> q, t = pin_friction(d, 0.2, 0.005, n=5)
    >>> bool(np.allclose(t[:, 0], 0.2 * 0.005 * np.linalg.norm(forces.joint_loads(d, q).force[:, 0], axis=-1)))
    True
    """
    mu = finite_real("mu", mu, nonnegative=True)
    pin_radius = finite_real("pin_radius (m)", pin_radius, nonnegative=True)
    q = configurations(design, q, n)
    return q, mu * pin_radius * np.linalg.norm(joint_loads(design, q).force, axis=-1)


def holding_torques(design: Design, q=None, n: int = 61) -> tuple[np.ndarray, np.ndarray]:
    """Configurations ``(m, dof)`` and the torque ``(m, n_joints)`` (N m) each joint must supply there.

    Examples
    --------
    >>> import balancelab as bl
    >>> d = bl.lecture.single_link_spring(2.0, 0.5, 0.3, 0.2)
    >>> q, t = holding_torques(d, n=9)
    >>> bool(np.abs(t).max() < 1e-9)
    True
    """
    q = configurations(design, q, n)
    return q, joint_loads(design, q).torque


def stays_put(design: Design, friction, q=None, n: int = 61) -> tuple[np.ndarray, np.ndarray]:
    """Configurations and a mask: does the design stay where it is left there?

    Parameters
    ----------
    design : Design
        A tree design (levers, serial arms).
    friction : float or sequence of float
        Coulomb friction torque of every joint (N m), >= 0.
    q : array_like, optional
        Configurations (rad); by default ``n`` per coordinate over the range.
    n : int

    Returns
    -------
    (numpy.ndarray, numpy.ndarray of bool)

    Examples
    --------
    >>> import balancelab as bl
    >>> d = bl.realize.approximate_lever()
    >>> q, ok = stays_put(d, 0.5, n=25)
    >>> bool(ok.all())
    True
    """
    tau = joint_friction(design, friction)
    q, t = holding_torques(design, q, n)
    return q, np.all(np.abs(t) <= tau + 1e-12, axis=-1)


class FrictionBand(NamedTuple):
    """Extra mass (kg) at a point that friction hides: the design stays put for ``low <= dm <= high``.

    ``empty`` is True when even ``dm = 0`` is not held everywhere.
    """

    low: float
    high: float
    empty: bool


def friction_band(design: Design, friction, body: int, point, q=None, n: int = 61) -> FrictionBand:
    """The band of extra mass at ``point`` of ``body`` that joint friction hides over the range.

    Parameters
    ----------
    design : Design
        A tree design.
    friction : float or sequence of float
        Friction torque of every joint (N m), >= 0.
    body : int
        Body carrying the extra mass (> 0).
    point : (float, float)
        Where, in the body's local frame (m).
    q, n
        Configurations, as in :func:`stays_put`.

    Returns
    -------
    FrictionBand

    Examples
    --------
    >>> import balancelab as bl
    >>> d = bl.lecture.single_link_spring(2.0, 0.5, 0.3, 0.2)
    >>> band = friction_band(d, 0.1, 1, (0.5, 0.0))
    >>> round(band.low, 5), round(band.high, 5)   # +- tau / (g r)
    (-0.02039, 0.02039)
    """
    tau = joint_friction(design, friction)
    point = planar_point("point (m)", point)
    body = body_index("body", body, len(design.bodies), moving=True)
    q, t0 = holding_torques(design, q, n)
    t1 = joint_loads(design.replace(loads=[gravity_load(int(body), point, 1.0)], springs=()), q).torque
    lo, hi = -np.inf, np.inf
    small = np.abs(t1) <= 1e-12 * max(1.0, float(np.abs(t1).max()))
    if np.any(np.abs(t0[small]) > np.broadcast_to(tau, t0.shape)[small] + 1e-12):
        return FrictionBand(float("nan"), float("nan"), True)
    tt = np.broadcast_to(tau, t0.shape)[~small]
    a, b = (-tt - t0[~small]) / t1[~small], (tt - t0[~small]) / t1[~small]
    if a.size:
        lo, hi = float(np.max(np.minimum(a, b))), float(np.min(np.maximum(a, b)))
    if lo > hi:
        return FrictionBand(float("nan"), float("nan"), True)
    return FrictionBand(lo, hi, not lo <= 0 <= hi)


def hand_force(design: Design, friction, body: int, point, q=None, n: int = 61,
               direction=None) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Force (N) a hand at ``point`` of ``body`` needs to start moving the design, both ways.

    Parameters
    ----------
    design : Design
        A tree design.
    friction : float or sequence of float
        Friction torque of every joint (N m), >= 0.
    body : int
        Body the hand holds.
    point : (float, float)
        Where, in its local frame (m).
    q, n
        Configurations, as in :func:`stays_put`.
    direction : array_like, shape (dof,), optional
        Direction of motion in the coordinates; required when ``dof > 1``.

    Returns
    -------
    (numpy.ndarray, numpy.ndarray, numpy.ndarray)
        Configurations ``(m, dof)``, the force to move along ``+direction`` and along
        ``-direction`` (N), pushing along the point's velocity.

    Examples
    --------
    >>> import balancelab as bl
    >>> d = bl.lecture.single_link_spring(2.0, 0.5, 0.3, 0.2)
    >>> q, up, down = hand_force(d, 0.1, 1, (0.5, 0.0), n=5)
    >>> np.round(up, 6).tolist()   # friction / r everywhere
    [0.2, 0.2, 0.2, 0.2, 0.2]
    """
    tau = joint_friction(design, friction)
    point = planar_point("point (m)", point)
    v = np.ones(1) if direction is None and design.dof == 1 else np.asarray(direction, dtype=float)
    if direction is None and design.dof > 1:
        raise ValueError(f"direction (of motion, {design.dof} coordinates) is required when dof > 1")
    if v.shape != (design.dof,) or not np.all(np.isfinite(v)) or not np.any(v):
        raise ValueError(f"direction must be a non-zero vector of {design.dof} finite numbers, got {direction!r}")
    q, Q = generalized_force(design, q, n)
    P, J = pose_jacobian(design, q)
    parts = joint_tree(design)
    fric = np.zeros(len(q))
    for j, part in enumerate(parts):
        jt = design.joints[j]
        child, parent = (jt.body_j, jt.body_i) if jt.body_j in part else (jt.body_i, jt.body_j)
        rate = (J[:, child, 2, :] - J[:, parent, 2, :]) @ v
        fric += tau[j] * np.abs(rate)
    rx, ry = turn_rate(np.cos(P[:, body, 2]), np.sin(P[:, body, 2]), point)     # dR/dangle p
    dx = J[:, body, 0, :] + rx[:, None] * J[:, body, 2, :]
    dy = J[:, body, 1, :] + ry[:, None] * J[:, body, 2, :]
    speed = np.hypot(dx @ v, dy @ v)
    if np.any(speed <= 1e-12):
        raise ValueError("the hand's point does not move along this direction somewhere in the range")
    Qv = Q @ v
    return q, np.maximum(Qv + fric, 0.0) / speed, np.maximum(-Qv + fric, 0.0) / speed
