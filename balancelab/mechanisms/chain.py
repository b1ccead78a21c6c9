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


def serial_2r_joints(l: float) -> list:
    """The revolute joints of a 2R arm whose link 1 is ``l`` long (m, or a sympy symbol).

    Examples
    --------
    >>> serial_2r_joints(1.0)[1].point_i
    (1.0, 0.0)
    """
    l = length_or_symbol("l (length of link 1, m)", l)
    return [Joint(0, (0.0, 0.0), 1, (0.0, 0.0)), Joint(1, (l, 0.0), 2, (0.0, 0.0))]


def serial_2r_kinematics(l: float) -> TreeKinematics:
    """Kinematics of a 2R arm: link 1 pivoted at the origin, link 2 at distance ``l`` on it.

    Parameters
    ----------
    l : float
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
    l = finite_real("l (length of link 1, m)", l, positive=True)
    return TreeKinematics(3, serial_2r_joints(l), [[0, 0], [1, 0], [0, 1]], ("theta_1", "theta_2"), TWO_TURNS)
