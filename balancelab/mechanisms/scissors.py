"""The two-stage scissors lift (Singh & Ananthasuresh, Sec. IV).

Bodies (Singh's numbers in brackets; ours are one less): 0 ground [1]; 1 lower arm from
the fixed pivot [2]; 2 lower arm from the bottom slider [3]; 3 bottom slider [4]; 4 upper
arm [5]; 5 upper arm [6]; 6 top slider [7]; 7 platform [8]. Every arm has length ``a``
and the arms of a stage cross at their midpoints. Layer: mechanisms.
"""
from __future__ import annotations

import math

from ..core.elements import Joint
from ..core.validation import length_or_symbol
from .base import ExplicitKinematics

__all__ = ["SCISSORS_BODIES", "scissors_kinematics", "scissors_joints"]


SCISSORS_BODIES = ("ground", "arm 2", "arm 3", "slider 4", "arm 5", "arm 6", "slider 7", "platform 8")


def scissors_kinematics(length: float) -> ExplicitKinematics:
    """Poses of the two-stage scissors for ``0 < theta < pi/2``.

    Parameters
    ----------
    length : float
        Arm length ``a`` (m), > 0 (a number, or a sympy symbol for the symbolic energy).

    Returns
    -------
    ExplicitKinematics

    Examples
    --------
    >>> scissors_kinematics(0.5).nbodies
    8
    """
    a = length_or_symbol("length (arm length a, m)", length)

    def pose_fn(q, lib):
        th = q[0]
        c, s = lib.cos(th), lib.sin(th)
        back = lib.pi - th
        zero = 0 * th
        return [(zero, zero, zero), (zero, zero, th), (a * c, zero, back), (a * c, zero, zero),
                (zero, a * s, th), (a * c, a * s, back), (a * c, 2 * a * s, zero),
                (zero, 2 * a * s, zero)]

    return ExplicitKinematics(8, ("theta",), ((0.0, math.pi / 2),), pose_fn, open_range=True,
                              descriptions=("angle of the arms from the floor",))


def scissors_joints(length: float) -> list:
    """The revolute joints of the scissors with arms of ``length`` (m, or a sympy symbol).

    Examples
    --------
    >>> len(scissors_joints(0.5))
    8
    """
    a = length_or_symbol("length (arm length a, m)", length)
    h = a / 2
    return [Joint(0, (0.0, 0.0), 1, (0.0, 0.0)), Joint(1, (h, 0.0), 2, (h, 0.0)),
            Joint(2, (0.0, 0.0), 3, (0.0, 0.0)), Joint(2, (a, 0.0), 4, (0.0, 0.0)),
            Joint(1, (a, 0.0), 5, (0.0, 0.0)), Joint(4, (h, 0.0), 5, (h, 0.0)),
            Joint(5, (a, 0.0), 7, (0.0, 0.0)), Joint(4, (a, 0.0), 6, (0.0, 0.0))]
