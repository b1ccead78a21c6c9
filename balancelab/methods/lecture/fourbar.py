"""Lecture 35: a gravity-loaded four-bar balanced through the coupler's equivalent masses.

The coupler's weight is equivalent to a mass ``m3`` on the crank and a mass ``m3`` on the
rocker (the complex-number decomposition ``U3 = (1 - c) Z2 + c Z4 + c Z1`` with
``c = (r_c / r3) e^{i phi}``); each of those links is then balanced with a counterweight
(:func:`fourbar_counterweights`) or with one ZFL spring (:func:`fourbar_two_springs`).
"""
from __future__ import annotations


import numpy as np

from ..registry import example
from ...core.design import Design
from ...core.elements import gravity_load
from ...core.validation import finite_real, finite_reals, planar_point, planar_points
from ...mechanisms.fourbar import FourBarKinematics, fourbar_joints
from .lever import link_spring

__all__ = ["equivalent_masses", "fourbar_counterweights", "fourbar_two_springs"]

_BODIES = ("ground", "crank", "coupler", "rocker")


def equivalent_masses(crank: float, coupler: float, rocker: float, mass: float, com) -> dict:
    """Where the coupler's mass acts on the crank and on the rocker (lecture 35).

    With ``mass = m3``, ``com = p3`` and ``c = (p3_x + i p3_y) / r3`` the coupler's centre of mass is
    ``U3 = (1 - c) Z2 + c Z4 + c Z1``: a mass ``m3`` at the local point ``(1 - c) r2`` of the
    crank, a mass ``m3`` at the local point ``c r4`` of the rocker, and a constant.

    Parameters
    ----------
    crank, coupler, rocker : float
        Link lengths r2, r3, r4 (m), > 0.
    mass : float
        Coupler mass m3 (kg), > 0.
    com : (float, float)
        Coupler centre of mass p3 in its local frame (m).

    Returns
    -------
    dict
        ``crank_point`` and ``rocker_point`` (local, m) of the two equivalent masses ``m3``.

    Examples
    --------
    >>> em = equivalent_masses(0.3, 0.8, 0.6, 2.0, (0.4, 0.0))
    >>> em["crank_point"], em["rocker_point"]
    ((0.15, 0.0), (0.3, 0.0))
    """
    r3 = finite_real("coupler length (m)", coupler, positive=True)
    r2 = finite_real("crank length (m)", crank, positive=True)
    r4 = finite_real("rocker length (m)", rocker, positive=True)
    finite_real("mass (coupler, kg)", mass, positive=True)
    p3 = planar_point("com (coupler centre of mass, m)", com)
    c = complex(*p3) / r3
    on_crank = (1 - c) * r2
    on_rocker = c * r4
    return {"c": c, "crank_point": (on_crank.real, on_crank.imag),
            "rocker_point": (on_rocker.real, on_rocker.imag)}


def _gravity_fourbar(A, B, crank, coupler, rocker, masses, coms, branch):
    kin = FourBarKinematics(A, B, crank, coupler, rocker, branch=branch, symbolic="loop")
    m2, m3, m4 = finite_reals("masses (crank, coupler, rocker; kg)", masses, 3, positive=True)
    p2, p3, p4 = planar_points("coms (crank, coupler, rocker; m)", coms, 3)
    em = equivalent_masses(crank, coupler, rocker, m3, p3)
    M2 = m2 * np.array(p2) + m3 * np.array(em["crank_point"])
    M4 = m4 * np.array(p4) + m3 * np.array(em["rocker_point"])
    loads = [gravity_load(1, p2, m2, "m2"), gravity_load(2, p3, m3, "m3"), gravity_load(3, p4, m4, "m4")]
    labels = {"A": (0, tuple(kin.A)), "B": (0, tuple(kin.B)), "D": (1, (kin.r2, 0.0)),
              "C": (3, (kin.r4, 0.0)), "G3": (2, tuple(p3))}
    return kin, loads, labels, em, M2, M4


@example("fourbar_counterweights", "Four-bar with counterweights on links 2 and 4 (lecture 35)", chapter=5)
def fourbar_counterweights(A=(0.0, 0.0), B=(0.7, 0.0), crank: float = 0.3, coupler: float = 0.8,
                           rocker: float = 0.6, masses=(1.0, 2.0, 1.5),
                           coms=((0.15, 0.0), (0.4, 0.1), (0.3, 0.0)), counter_masses=(3.0, 3.0), branch: int = 1) -> Design:
    """A four-bar whose total centre of mass is stationary: counterweights on crank and rocker.

    The coupler's mass is replaced by its equivalent masses on the crank and the rocker
    (:func:`equivalent_masses`); each of those two links then carries a first moment
    ``M = m_link p_link + m3 p_equiv`` about its pivot, cancelled by a counterweight of
    mass ``m_cw`` at ``-M / m_cw``. The total gravity energy is then constant.

    Parameters
    ----------
    A, B : (float, float)
        Ground pivots of crank and rocker (m).
    crank, coupler, rocker : float
        Link lengths (m), > 0.
    masses : (float, float, float)
        Masses of crank, coupler and rocker (kg), > 0.
    coms : three (float, float)
        Their centres of mass in the local frames (m).
    counter_masses : (float, float)
        Counterweight masses on crank and rocker (kg), > 0.
    branch : {1, -1}
        Assembly branch.

    Returns
    -------
    Design

    Examples
    --------
    >>> fourbar_counterweights().balance_report().balanced
    True
    """
    kin, loads, labels, em, M2, M4 = _gravity_fourbar(A, B, crank, coupler, rocker, masses, coms, branch)
    mc2, mc4 = finite_reals("counter_masses (kg)", counter_masses, 2, positive=True)
    cw2 = tuple(-M2 / mc2)
    cw4 = tuple(-M4 / mc4)
    loads += [gravity_load(1, cw2, mc2, "cw2", kind="counterweight"),
              gravity_load(3, cw4, mc4, "cw4", kind="counterweight")]
    return Design("four-bar with counterweights (lecture)", _BODIES, fourbar_joints(kin), kin, loads, [],
                  labels=labels, parameters={"cw2_x": cw2[0], "cw2_y": cw2[1], "cw4_x": cw4[0],
                                             "cw4_y": cw4[1], "m3_on_crank_x": em["crank_point"][0],
                                             "m3_on_crank_y": em["crank_point"][1],
                                             "m3_on_rocker_x": em["rocker_point"][0],
                                             "m3_on_rocker_y": em["rocker_point"][1]},
                  reference="Lecture 35 (equivalent masses of the coupler on links 2 and 4)")


@example("fourbar_two_springs", "Four-bar with two ZFL springs on links 2 and 4 (lecture 35)", chapter=5)
def fourbar_two_springs(A=(0.0, 0.0), B=(0.7, 0.0), crank: float = 0.3, coupler: float = 0.8,
                        rocker: float = 0.6, masses=(1.0, 2.0, 1.5),
                        coms=((0.15, 0.0), (0.4, 0.1), (0.3, 0.0)), b=(0.2, 0.2), c=(0.15, 0.3), branch: int = 1) -> Design:
    """The lecture's closing design: the four-bar balanced by two ZFL springs.

    The crank and the rocker, each carrying its own mass and the coupler's equivalent
    mass, are single links: one ZFL spring each, from an anchor a height ``b_i`` above
    its pivot to the point a distance ``c_i`` along its first moment, with
    ``k_i = g |M_i| / (b_i c_i)`` (simpler than Singh's four springs; both are in the
    course).

    Parameters
    ----------
    A, B, crank, coupler, rocker, masses, coms, branch : see :func:`fourbar_counterweights`.
    b : (float, float)
        Anchor heights above the crank and rocker pivots (m), > 0.
    c : (float, float)
        Attachment distances along the first moments (m), > 0.

    Returns
    -------
    Design

    Examples
    --------
    >>> d = fourbar_two_springs()
    >>> len(d.springs), d.balance_report().balanced
    (2, True)
    """
    kin, loads, labels, em, M2, M4 = _gravity_fourbar(A, B, crank, coupler, rocker, masses, coms, branch)
    b = finite_reals("b (anchor heights, m)", b, 2, positive=True)
    c = finite_reals("c (attachment distances, m)", c, 2, positive=True)
    s2 = link_spring(M2, b[0], c[0], body=1, pivot_on_anchor=tuple(kin.A), name="k2")
    s4 = link_spring(M4, b[1], c[1], body=3, pivot_on_anchor=tuple(kin.B), name="k4")
    return Design("four-bar with two ZFL springs (lecture)", _BODIES, fourbar_joints(kin), kin, loads,
                  [s2, s4], labels=labels, parameters={"k2": s2.k, "k4": s4.k},
                  reference="Lecture 35 (springs on links 2 and 4)")
