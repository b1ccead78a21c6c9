"""Gravity-loaded four-bar linkages: counterweights, two ZFL springs, minimum preload.

* Lecture 35 (and the previous lecture): the coupler's weight is equivalent to a mass
  ``m3`` on the crank and a mass ``m3`` on the rocker (the complex-number decomposition
  ``U3 = (1 - c) Z2 + c Z4 + c Z1`` with ``c = (r_c / r3) e^{i phi}``); balance each of
  those links with a counterweight (:func:`fourbar_counterweights`) or with one ZFL
  spring each (:func:`fourbar_two_springs`).
* Singh & Ananthasuresh, Sec. III.A: relax the coupler-rocker joint, balance the
  crank-coupler 2R with three ZFL springs and the rocker as a lever, all with minimum
  preload (:func:`singh_fourbar`).

Bodies: 0 ground, 1 crank (link 2 of the lecture), 2 coupler (link 3), 3 rocker
(link 4). The coordinate is the crank angle from the global x-axis.
"""
from __future__ import annotations

import numpy as np

from .design import Design
from .elements import Joint, Load, Spring, _finite, _point, weight
from .kinematics import FourBarKinematics
from .lever import link_spring, min_preload_lever
from .serial import serial_2r_min_preload

__all__ = ["fourbar_joints", "equivalent_masses", "fourbar_counterweights", "fourbar_two_springs",
           "singh_fourbar"]

_BODIES = ("ground", "crank", "coupler", "rocker")


def fourbar_joints(kin: FourBarKinematics) -> list:
    """The four revolute joints of a :class:`FourBarKinematics` linkage.

    Parameters
    ----------
    kin : FourBarKinematics

    Returns
    -------
    list of Joint

    Examples
    --------
    >>> len(fourbar_joints(FourBarKinematics((0, 0), (0.7, 0), 0.3, 0.8, 0.6)))
    4
    """
    return [Joint(0, tuple(kin.A), 1, (0.0, 0.0)), Joint(1, (kin.r2, 0.0), 2, (0.0, 0.0)),
            Joint(2, (kin.r3, 0.0), 3, (kin.r4, 0.0)), Joint(0, tuple(kin.B), 3, (0.0, 0.0))]


def equivalent_masses(coupler: float, crank: float, rocker: float, m3: float, p3) -> dict:
    """Where the coupler's mass acts on the crank and on the rocker (lecture 35).

    With ``c = (p3_x + i p3_y) / r3`` the coupler's centre of mass is
    ``U3 = (1 - c) Z2 + c Z4 + c Z1``: a mass ``m3`` at the local point ``(1 - c) r2`` of the
    crank, a mass ``m3`` at the local point ``c r4`` of the rocker, and a constant.

    Parameters
    ----------
    coupler, crank, rocker : float
        Link lengths r3, r2, r4 (m), > 0.
    m3 : float
        Coupler mass (kg), > 0.
    p3 : (float, float)
        Coupler centre of mass in its local frame (m).

    Returns
    -------
    dict
        ``crank_point`` and ``rocker_point`` (local, m) of the two equivalent masses ``m3``.

    Examples
    --------
    >>> em = equivalent_masses(0.8, 0.3, 0.6, 2.0, (0.4, 0.0))
    >>> em["crank_point"], em["rocker_point"]
    ((0.15, 0.0), (0.3, 0.0))
    """
    r3 = _finite("coupler length (m)", coupler, positive=True)
    r2 = _finite("crank length (m)", crank, positive=True)
    r4 = _finite("rocker length (m)", rocker, positive=True)
    _finite("m3 (kg)", m3, positive=True)
    p3 = _point("p3 (coupler centre of mass, m)", p3)
    c = complex(*p3) / r3
    on_crank = (1 - c) * r2
    on_rocker = c * r4
    return {"c": c, "crank_point": (on_crank.real, on_crank.imag),
            "rocker_point": (on_rocker.real, on_rocker.imag)}


def _gravity_fourbar(A, B, crank, coupler, rocker, m, p, branch):
    kin = FourBarKinematics(A, B, crank, coupler, rocker, branch=branch, symbolic="loop")
    m2, m3, m4 = (_finite(f"m{i + 2} (kg)", v, positive=True) for i, v in enumerate(m))
    p2, p3, p4 = (_point(f"p{i + 2} (centre of mass, m)", v) for i, v in enumerate(p))
    em = equivalent_masses(coupler, crank, rocker, m3, p3)
    M2 = m2 * np.array(p2) + m3 * np.array(em["crank_point"])
    M4 = m4 * np.array(p4) + m3 * np.array(em["rocker_point"])
    loads = [weight(1, p2, m2, "m2"), weight(2, p3, m3, "m3"), weight(3, p4, m4, "m4")]
    labels = {"O2": (0, tuple(kin.A)), "O4": (0, tuple(kin.B)), "A": (1, (kin.r2, 0.0)),
              "B": (3, (kin.r4, 0.0)), "G3": (2, tuple(p3))}
    return kin, loads, labels, em, M2, M4


def fourbar_counterweights(A=(0.0, 0.0), B=(0.7, 0.0), crank: float = 0.3, coupler: float = 0.8,
                           rocker: float = 0.6, m=(1.0, 2.0, 1.5), p=((0.15, 0.0), (0.4, 0.1), (0.3, 0.0)),
                           counter_masses=(3.0, 3.0), branch: int = 1) -> Design:
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
    m : (float, float, float)
        Masses of crank, coupler and rocker (kg), > 0.
    p : three (float, float)
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
    kin, loads, labels, em, M2, M4 = _gravity_fourbar(A, B, crank, coupler, rocker, m, p, branch)
    mc2, mc4 = (_finite(f"counter_masses[{i}] (kg)", v, positive=True) for i, v in enumerate(counter_masses))
    cw2 = tuple(-M2 / mc2)
    cw4 = tuple(-M4 / mc4)
    loads += [weight(1, cw2, mc2, "cw2", kind="counterweight"),
              weight(3, cw4, mc4, "cw4", kind="counterweight")]
    return Design("four-bar with counterweights (lecture)", _BODIES, fourbar_joints(kin), kin, loads, [],
                  labels=labels, parameters={"cw2_x": cw2[0], "cw2_y": cw2[1], "cw4_x": cw4[0],
                                             "cw4_y": cw4[1], "m3_on_crank_x": em["crank_point"][0],
                                             "m3_on_crank_y": em["crank_point"][1],
                                             "m3_on_rocker_x": em["rocker_point"][0],
                                             "m3_on_rocker_y": em["rocker_point"][1]},
                  reference="Lecture 35 (equivalent masses of the coupler on links 2 and 4)")


def fourbar_two_springs(A=(0.0, 0.0), B=(0.7, 0.0), crank: float = 0.3, coupler: float = 0.8,
                        rocker: float = 0.6, m=(1.0, 2.0, 1.5), p=((0.15, 0.0), (0.4, 0.1), (0.3, 0.0)),
                        b=(0.2, 0.2), c=(0.15, 0.3), branch: int = 1) -> Design:
    """The lecture's closing design: the four-bar balanced by two ZFL springs.

    The crank and the rocker, each carrying its own mass and the coupler's equivalent
    mass, are single links: one ZFL spring each, from an anchor a height ``b_i`` above
    its pivot to the point a distance ``c_i`` along its first moment, with
    ``k_i = g |M_i| / (b_i c_i)`` (simpler than Singh's four springs; both are in the
    course).

    Parameters
    ----------
    A, B, crank, coupler, rocker, m, p, branch : see :func:`fourbar_counterweights`.
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
    kin, loads, labels, em, M2, M4 = _gravity_fourbar(A, B, crank, coupler, rocker, m, p, branch)
    s2 = link_spring(M2, b[0], c[0], body=1, pivot=tuple(kin.A), name="k2")
    s4 = link_spring(M4, b[1], c[1], body=3, pivot=tuple(kin.B), name="k4")
    return Design("four-bar with two ZFL springs (lecture)", _BODIES, fourbar_joints(kin), kin, loads,
                  [s2, s4], labels=labels, parameters={"k2": s2.k, "k4": s4.k},
                  reference="Lecture 35 (springs on links 2 and 4)")


def singh_fourbar(W=(10.0, 20.0, 10.0), p1=(1.0, 0.5), p_x2: float = 2.0, p_x3: float = 0.5,
                  crank: float = 1.5, coupler: float = 4.0, rocker: float = 1.0, ground: float = 4.0,
                  a_x=(1.0, 2.0, -2.0), a4=(0.5, 0.0), branch: int = 1) -> Design:
    """Singh & Ananthasuresh's four-bar balanced with minimum preload (Sec. III.A).

    Relaxing the joint between the coupler (body 2) and the rocker (body 3) leaves a 2R
    (crank and coupler), balanced by three ZFL springs from the ground with minimum
    preload (:func:`balancelab.serial_2r_min_preload`), and a lever (the rocker),
    balanced by one ZFL spring with minimum preload (:func:`balancelab.min_preload_lever`).
    Each part's energy is constant for *every* pair of its angles, so the re-assembled
    four-bar is balanced too, with four springs.

    With the defaults the paper's numbers follow: ``b_x1 = 0.124 m``, ``b_y1 = 0.9923 m``,
    ``b_x2 = b_x3 = 0.1861 m``, ``b_y2 = 3.4884 m``, ``b_y3 = -0.5116 m``, ``k1 = 17.81 N/m``,
    ``k2 = k3 = 5 N/m``; ``b_x4 = 0``, ``b_y4 = 0.5 m``, ``k4 = 20 N/m``. The paper's Fig. 6
    is not in the text: the crank length ``1.5 m`` is the one for which ``b_x1`` and ``b_y1``
    come out as printed; coupler ``4 m`` and rocker ``1 m`` put the centres of mass at
    their midpoints (``p_x2 = 2``, ``p_x3 = 0.5``); the ground length ``4 m`` is assumed
    (the balance holds for any).

    Parameters
    ----------
    W : (float, float, float)
        Weights of crank, coupler and rocker (N).
    p1 : (float, float)
        Centre of mass of the crank (m).
    p_x2, p_x3 : float
        Centres of mass along coupler and rocker (m).
    crank, coupler, rocker, ground : float
        Link lengths (m); the rocker is pivoted at ``(ground, 0)``.
    a_x : (float, float, float)
        Free choices of the 2R (m).
    a4 : (float, float)
        Attachment of the lever spring on the rocker (m).
    branch : {1, -1}

    Returns
    -------
    Design

    Examples
    --------
    >>> d = singh_fourbar()
    >>> round(d.parameters["k1"], 2), d.parameters["k4"], d.balance_report().balanced
    (17.81, 20.0, True)
    """
    ground = _finite("ground (m)", ground, positive=True)
    W1, W2, W3 = (_finite(f"W{i + 1} (N)", v, positive=True) for i, v in enumerate(W))
    kin = FourBarKinematics((0.0, 0.0), (ground, 0.0), crank, coupler, rocker, branch=branch,
                            symbolic="relaxed")
    arm = serial_2r_min_preload(W1, W2, p1, p_x2, crank, a_x)
    lever = min_preload_lever(W3, p_x3, a4[0], a4[1])
    B = np.array([ground, 0.0])
    lever_spring = lever.springs[0]
    s4 = Spring(lever_spring.k, 0.0, (0, tuple(B + lever_spring.a.point)), (3, lever_spring.b.point),
                name="k4")
    loads = [Load(1, tuple(p1), (0.0, -W1), "W1", kind="weight"),
             Load(2, (p_x2, 0.0), (0.0, -W2), "W2", kind="weight"),
             Load(3, (p_x3, 0.0), (0.0, -W3), "W3", kind="weight")]
    params = {k: v for k, v in arm.parameters.items()}
    params.update({"k4": lever.parameters["k"], "b_x4": lever.parameters["b_x"],
                   "b_y4": lever.parameters["b_y"], "a_x4": a4[0], "a_y4": a4[1],
                   "PE_min": arm.parameters["PE_min"] + lever.parameters["PE"]})
    labels = {"A": (0, (0.0, 0.0)), "B": (0, tuple(B))}
    for s in list(arm.springs) + [s4]:
        labels[s.name.replace("k", "b")] = s.a
        labels[s.name.replace("k", "a")] = s.b
    return Design("Singh's four-bar with minimum preload", ("ground", "body 1", "body 2", "body 3"),
                  fourbar_joints(kin), kin, loads, list(arm.springs) + [s4], labels=labels,
                  parameters=params, reference="Singh & Ananthasuresh, Sec. III.A (eqs 18-20, 42-49)")
