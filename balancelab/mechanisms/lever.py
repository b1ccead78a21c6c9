"""One link pivoted at the origin: the lever of chapters 1-3.

Bodies: 0 ground, 1 the link (frame at the pivot). The coordinate ``theta`` is the
link's angle from the global x-axis (the lecture measures it from the vertical:
``pi/2 - theta``). Layer: mechanisms.
"""
from __future__ import annotations

import math

from ..core.design import Design
from ..core.elements import Joint
from ..core.validation import finite_real
from .base import TreeKinematics

__all__ = ["FULL_TURN", "LEVER_JOINTS", "lever_kinematics", "lever_design"]


FULL_TURN = ((-math.pi, math.pi),)


LEVER_JOINTS = (Joint(0, (0.0, 0.0), 1, (0.0, 0.0)),)


def lever_kinematics(name: str = "theta", q_range=FULL_TURN[0], *,
                     open_range: bool = False) -> TreeKinematics:
    """Kinematics of one link pivoted at the origin (bodies: ground, link).

    Parameters
    ----------
    name : str
        Name of the angle coordinate.
    q_range : (float, float)
        Lowest and highest link angle (rad); a range of a full turn (the default
        ``(-pi, pi)``) means the link turns freely.
    open_range : bool
        Exclude the two limits themselves (a link that cannot quite reach them).

    Returns
    -------
    TreeKinematics
        With the joint :data:`LEVER_JOINTS`.

    Raises
    ------
    ValueError
        If ``q_range`` is not two finite angles with ``low < high``.

    Examples
    --------
    >>> lever_kinematics().dof
    1
    >>> lever_kinematics(q_range=(-1.0, 1.0)).q_range.tolist()
    [[-1.0, 1.0]]
    """
    try:
        lo, hi = (finite_real("q_range (rad)", v) for v in q_range)
    except (TypeError, ValueError) as err:
        raise type(err)(f"q_range must be two finite angles (low, high) in rad: {err}") from None
    if not lo < hi:
        raise ValueError(f"q_range must have low < high (rad), got ({lo}, {hi})")
    return TreeKinematics(2, LEVER_JOINTS, [[0.0], [1.0]], (name,), ((lo, hi),), open_range=open_range)


def lever_design(name: str, loads, springs, *, q_range=FULL_TURN[0], symbolic=None, labels=None,
                 parameters=None, reference: str = "", link: str = "link") -> Design:
    """A :class:`Design` of one link pivoted at the origin, with the given loads and springs.

    Parameters
    ----------
    name : str
        Title of the design.
    loads, springs : sequence of Load, sequence of Spring
        On body 1 (the link) and the ground (body 0).
    q_range : (float, float)
        Range of the link angle (rad), as in :func:`lever_kinematics`.
    symbolic, labels, parameters, reference
        As in :class:`Design`.
    link : str
        Name of body 1.

    Returns
    -------
    Design

    Examples
    --------
    >>> from balancelab import gravity_load
    >>> d = lever_design("a link", [gravity_load(1, (0.5, 0.0), 2.0)], [])
    >>> d.bodies
    ('ground', 'link')
    """
    return Design(name, ("ground", link), LEVER_JOINTS, lever_kinematics(q_range=q_range), loads, springs,
                  symbolic=symbolic, labels=labels, parameters=parameters, reference=reference)
