"""Lecture 35: 2R arms kept balanced by parallelograms of auxiliary links.

A parallelogram keeps a link vertical at the elbow, and one ZFL spring per link balances
it as a single link (``k_i = g M_i / (b_i c_i)``); or a second parallelogram brings the
elbow's angle to the base so both springs are anchored on the base, like a desk lamp.
"""
from __future__ import annotations

import math

import numpy as np

from ..registry import example
from ...core.design import Design
from ...core.elements import Joint, gravity_load
from ...core.validation import finite_real, finite_reals, planar_points
from ...mechanisms.base import TreeKinematics
from ...mechanisms.chain import TWO_TURNS
from .lever import link_spring

__all__ = ["serial_2r_parallelogram", "serial_2r_base_springs"]


def _arm(masses, length, coms, b, c):
    """Checked inputs of the lecture's 2R arms and the links' first moments about their joints."""
    m1, m2 = finite_reals("masses (kg)", masses, 2, positive=True)
    l1 = finite_real("length (of link 1, m)", length, positive=True)
    p1, p2 = (np.asarray(p) for p in planar_points("coms (centres of mass of links 1 and 2, m)", coms, 2))
    b = finite_reals("b (anchor heights, m)", b, 2, positive=True)
    c = finite_reals("c (attachment distances, m)", c, 2, positive=True)
    M1 = m1 * p1 + m2 * np.array([l1, 0.0])   # first moment of link 1 with link 2's mass at the elbow
    M2 = m2 * p2
    return (m1, m2), l1, (p1, p2), b, c, (M1, M2)


@example("serial_2r_parallelogram", "2R arm with a parallelogram of auxiliary links (lecture 35)", chapter=4)
def serial_2r_parallelogram(masses=(1.0, 1.0), length: float = 0.5, coms=((0.25, 0.0), (0.25, 0.0)),
                            b=(0.2, 0.2), c=(0.2, 0.2), h: float = 0.25) -> Design:
    """The lecture's 2R arm: auxiliary parallelogram and one ZFL spring per link.

    An auxiliary link (body 3) pivoted a height ``h`` above the base, parallel to link 1,
    and a coupler (body 4) from the elbow form a parallelogram, so body 4 stays vertical
    and serves as a moving "ground" for link 2. Spring 1 runs from the base, a height
    ``b1`` above the shoulder, to link 1 at ``c1``; spring 2 from body 4, a height ``b2``
    above the elbow, to link 2 at ``c2``. Each link is then a single link with a ZFL
    spring: ``k_i = g |M_i| / (b_i c_i)`` with ``M_1 = m1 p1 + m2 (l1, 0)`` and
    ``M_2 = m2 p2`` the first moments about the joints (the lecture's
    ``F_i = m g r_i a_i / (b_i c_i)``). The auxiliary links are massless.

    Parameters
    ----------
    masses : (float, float)
        Masses ``m1``, ``m2`` of links 1 and 2 (kg), > 0.
    length : float
        Length ``l1`` of link 1 (m), > 0.
    coms : two (float, float)
        Centres of mass ``p1``, ``p2`` in the links' local frames (m).
    b, c : (float, float)
        Anchor heights ``b1``, ``b2`` above the joints and attachment distances ``c1``,
        ``c2`` along the first moments (m), > 0.
    h : float
        Height of the parallelogram (m), > 0.

    Returns
    -------
    Design
        Bodies ground, link 1, link 2, auxiliary link, vertical link.

    Examples
    --------
    >>> d = serial_2r_parallelogram()
    >>> round(d.parameters["k1"], 2), round(d.parameters["k2"], 2)
    (183.94, 61.31)
    """
    (m1, m2), l1, (p1, p2), (b1, b2), (c1, c2), (M1, M2) = _arm(masses, length, coms, b, c)
    h = finite_real("h (m)", h, positive=True)
    joints = [Joint(0, (0.0, 0.0), 1, (0.0, 0.0)), Joint(1, (l1, 0.0), 2, (0.0, 0.0)),
              Joint(0, (0.0, h), 3, (0.0, 0.0)), Joint(1, (l1, 0.0), 4, (0.0, 0.0)),
              Joint(3, (l1, 0.0), 4, (h, 0.0))]
    kin = TreeKinematics(5, joints, [[0, 0], [1, 0], [0, 1], [1, 0], [0, 0]], ("theta_1", "theta_2"),
                         TWO_TURNS, angle_offset=[0, 0, 0, 0, math.pi / 2])
    s1 = link_spring(M1, b1, c1, body=1, name="k1")
    # body 4 stays vertical with its local x-axis pointing up: "b2 above the elbow" is (b2, 0)
    s2 = link_spring(M2, b2, c2, body=2, anchor_body=4, anchor_up=(1.0, 0.0), name="k2")
    loads = [gravity_load(1, tuple(p1), m1, "m1"), gravity_load(2, tuple(p2), m2, "m2")]
    return Design("2R arm with a parallelogram (lecture)",
                  ("ground", "link 1", "link 2", "auxiliary link", "vertical link"), joints, kin,
                  loads, [s1, s2], labels={"A1": (0, (0.0, 0.0)), "A2": (1, (l1, 0.0))},
                  parameters={"k1": s1.k, "k2": s2.k, "b1": b1, "c1": c1, "b2": b2, "c2": c2},
                  reference="Lecture 35: k_i = m g r_i / (b_i c_i) with auxiliary links")


@example("serial_2r_base_springs", "2R desk-lamp arm with both springs on the base (lecture 35)", chapter=4)
def serial_2r_base_springs(masses=(1.0, 1.0), length: float = 0.5, coms=((0.25, 0.0), (0.25, 0.0)),
                           b=(0.2, 0.2), c=(0.2, 0.1), e: float = 0.1) -> Design:
    """The lecture's desk-lamp arm: both ZFL springs anchored on the base.

    A parallelogram (body 3 pivoted at the shoulder and parallel to link 2, body 4
    parallel to link 1 joining the tip of body 3 to link 2's extension a distance ``e``
    behind the elbow) copies link 2's angle down to the base. Spring 1 balances link 1
    as before; spring 2 runs from a base anchor a height ``b2`` above the shoulder to
    body 3 at ``c2`` and balances link 2: ``k_i = g |M_i| / (b_i c_i)``. The auxiliary
    links are massless.

    Parameters
    ----------
    masses, length, coms, b, c : see :func:`serial_2r_parallelogram`.
    e : float
        Side of the parallelogram along link 2 (m), > 0.

    Returns
    -------
    Design

    Examples
    --------
    >>> serial_2r_base_springs().balance_report().balanced
    True
    """
    (m1, m2), l1, (p1, p2), (b1, b2), (c1, c2), (M1, M2) = _arm(masses, length, coms, b, c)
    e = finite_real("e (m)", e, positive=True)
    joints = [Joint(0, (0.0, 0.0), 1, (0.0, 0.0)), Joint(1, (l1, 0.0), 2, (0.0, 0.0)),
              Joint(0, (0.0, 0.0), 3, (0.0, 0.0)), Joint(3, (-e, 0.0), 4, (0.0, 0.0)),
              Joint(4, (l1, 0.0), 2, (-e, 0.0))]
    kin = TreeKinematics(5, joints, [[0, 0], [1, 0], [0, 1], [0, 1], [1, 0]], ("theta_1", "theta_2"),
                         TWO_TURNS)
    s1 = link_spring(M1, b1, c1, body=1, name="k1")
    s2 = link_spring(M2, b2, c2, body=3, name="k2")
    loads = [gravity_load(1, tuple(p1), m1, "m1"), gravity_load(2, tuple(p2), m2, "m2")]
    return Design("2R arm with both springs on the base (lecture)",
                  ("ground", "link 1", "link 2", "copy of link 2", "copy of link 1"), joints, kin,
                  loads, [s1, s2], labels={"A": (0, (0.0, 0.0)), "J": (1, (l1, 0.0))},
                  parameters={"k1": s1.k, "k2": s2.k},
                  reference="Lecture 35: desk-lamp arm, both springs on the base")
