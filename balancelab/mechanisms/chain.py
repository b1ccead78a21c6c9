"""Serial chains: the 2R arm (link 1 pivoted at the origin, link 2 at its tip).

Configuration coordinates are the *absolute* angles ``theta_1``, ``theta_2`` of the two
links from the global x-axis, as in the papers. Layer: mechanisms.
"""
from __future__ import annotations

import math

from ..core.elements import Joint
from ..core.validation import finite_real, length_or_symbol
from .base import TreeKinematics

__all__ = ["TWO_TURNS", "serial_2r_joints", "serial_2r_kinematics"]


TWO_TURNS = ((-math.pi, math.pi), (-math.pi, math.pi))


def serial_2r_joints(length: float) -> list:
    """The revolute joints of a 2R arm whose link 1 is ``length`` long (m, or a sympy symbol).

    Examples
    --------
    >>> serial_2r_joints(1.0)[1].point_i
    (1.0, 0.0)
    """
    length = length_or_symbol("length (of link 1, m)", length)
    return [Joint(0, (0.0, 0.0), 1, (0.0, 0.0)), Joint(1, (length, 0.0), 2, (0.0, 0.0))]


def serial_2r_kinematics(length: float) -> TreeKinematics:
    """Kinematics of a 2R arm: link 1 pivoted at the origin, link 2 at distance ``length`` on it.

    Parameters
    ----------
    length : float
        Length of link 1 (m), > 0.

    Returns
    -------
    TreeKinematics
        Coordinates ``theta_1``, ``theta_2``: absolute link angles (rad).

    Examples
    --------
    >>> serial_2r_kinematics(1.0).names
    ('theta_1', 'theta_2')
    """
    length = finite_real("length (of link 1, m)", length, positive=True)
    return TreeKinematics(3, serial_2r_joints(length), [[0, 0], [1, 0], [0, 1]], ("theta_1", "theta_2"), TWO_TURNS)
