"""One link pivoted at the origin: the lever of chapters 1-3.

Bodies: 0 ground, 1 the link (frame at the pivot). The coordinate ``theta`` is the
link's angle from the global x-axis (the lecture measures it from the vertical:
``pi/2 - theta``). Layer: mechanisms.
"""
from __future__ import annotations

import math

from ..core.design import Design
from ..core.elements import Joint
from .base import TreeKinematics

__all__ = ["FULL_TURN", "lever_kinematics", "lever_design"]


FULL_TURN = ((-math.pi, math.pi),)


def lever_kinematics(name: str = "theta") -> TreeKinematics:
    """Kinematics of one link pivoted at the origin (bodies: ground, link).

    Parameters
    ----------
    name : str
        Name of the angle coordinate.

    Returns
    -------
    TreeKinematics

    Examples
    --------
    >>> lever_kinematics().dof
    1
    """
    joints = [Joint(0, (0.0, 0.0), 1, (0.0, 0.0))]
    return TreeKinematics(2, joints, [[0.0], [1.0]], (name,), FULL_TURN)


def lever_design(name, loads, springs, *, symbolic=None, labels=None, parameters=None,
                  reference="", link="link") -> Design:
    return Design(name, ("ground", link), [Joint(0, (0.0, 0.0), 1, (0.0, 0.0))], lever_kinematics(),
                  loads, springs, symbolic=symbolic, labels=labels, parameters=parameters,
                  reference=reference)
