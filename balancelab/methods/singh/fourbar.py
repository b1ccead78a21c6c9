"""Singh & Ananthasuresh, Sec. III.A: a four-bar balanced with minimum preload.

Relax the coupler-rocker joint, balance the crank-coupler 2R with three ZFL springs and
the rocker as a lever, all with minimum preload.
"""
from __future__ import annotations


from ..registry import example
from ...core.design import Design
from ...core.elements import Load, Spring
from ...core.validation import finite_real, finite_reals, planar_point, planar_points
from ...mechanisms.fourbar import FourBarKinematics, fourbar_joints
from .serial import serial_2r_min_preload

__all__ = ["singh_fourbar"]

_BODIES = ("ground", "crank", "coupler", "rocker")


def _rocker_spring(W3, p_x3, a4, ground):
    """The rocker as a lever with minimum preload (eqs 18-20), for either sign of ``p_x3``.

    W3 is highest at ``theta_4* = sign(p_x3) 90 deg``; the spring has zero length there:
    ``b = R(theta_4*) a4`` relative to ``B`` and ``k4 |a4|^2 = W3 |p_x3|`` (the
    energy ``k4 |a4|^2 (1 - sin(sigma theta_4)) + W3 p_x3 sin theta_4`` is then constant).
    """
    sign = 1.0 if p_x3 > 0 else -1.0
    b = (0.0 - sign * a4[1], sign * a4[0])
    k = W3 * abs(p_x3) / (a4[0] ** 2 + a4[1] ** 2)
    return Spring(k, 0.0, (0, (ground + b[0], b[1])), (3, a4), name="k4"), b


@example("singh_fourbar", "Four-bar with minimum preload (Singh Sec. III.A: k1 = 17.81, k4 = 20 N/m)",
         chapter=5)
def singh_fourbar(weights=(10.0, 20.0, 10.0), coms=((1.0, 0.5), (2.0, 0.0), (0.5, 0.0)),
                  crank: float = 1.5, coupler: float = 4.0, rocker: float = 1.0, ground: float = 4.0,
                  a_x=(1.0, 2.0, -2.0), a4=(0.5, 0.0), branch: int = 1) -> Design:
    """Singh & Ananthasuresh's four-bar balanced with minimum preload (Sec. III.A).

    Relaxing the joint between the coupler (body 2) and the rocker (body 3) leaves a 2R
    (crank and coupler), balanced by three ZFL springs from the ground with minimum
    preload (:func:`balancelab.singh.serial_2r_min_preload`), and a lever (the rocker),
    balanced by one ZFL spring with minimum preload (:func:`balancelab.singh.min_preload_lever`).
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
    weights : (float, float, float)
        Weights ``W1, W2, W3`` of crank, coupler and rocker (N), > 0.
    coms : three (float, float)
        Their centres of mass ``p1``, ``(p_x2, 0)``, ``(p_x3, 0)`` (m); coupler's and rocker's
        on the links' axes, ``p_x2 != 0`` and ``p_x3 != 0`` of either sign (a negative one
        puts that body's spring anchors on the other side: its load is highest at -90 deg).
    crank, coupler, rocker, ground : float
        Link lengths (m); the rocker is pivoted at ``(ground, 0)``.
    a_x : (float, float, float)
        Free choices of the 2R (m).
    a4 : (float, float)
        Attachment of the lever spring on the rocker (m), not ``(0, 0)``.
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
    ground = finite_real("ground (m)", ground, positive=True)
    W1, W2, W3 = finite_reals("weights (N)", weights, 3, positive=True)
    p1, p2, p3 = planar_points("coms (m)", coms, 3)
    if p3[1] != 0:
        raise ValueError(f"coms[2] must lie on the rocker's axis, (p_x3, 0), got {p3}")
    p_x2, p_x3 = p2[0], p3[0]
    if p_x3 == 0:
        raise ValueError("coms[2]: p_x3 must be non-zero: with W3 on the rocker's pivot the rocker needs "
                         "no spring")
    a4 = planar_point("a4 (m)", a4)
    if a4 == (0.0, 0.0):
        raise ValueError("a4 must not be the rocker's pivot (0, 0): a spring there cannot balance the rocker")
    kin = FourBarKinematics((0.0, 0.0), (ground, 0.0), crank, coupler, rocker, branch=branch,
                            symbolic="relaxed")
    arm = serial_2r_min_preload((W1, W2), (p1, p2), crank, a_x)
    s4, lever = _rocker_spring(W3, p_x3, a4, ground)
    loads = [Load(1, tuple(p1), (0.0, -W1), "W1", kind="weight"),
             Load(2, (p_x2, 0.0), (0.0, -W2), "W2", kind="weight"),
             Load(3, (p_x3, 0.0), (0.0, -W3), "W3", kind="weight")]
    params = {k: v for k, v in arm.parameters.items()}
    params.update({"k4": s4.k, "b_x4": lever[0], "b_y4": lever[1], "a_x4": a4[0], "a_y4": a4[1],
                   "PE_min": arm.parameters["PE_min"] + W3 * abs(p_x3)})
    labels = {"A": (0, (0.0, 0.0)), "B": (0, (ground, 0.0))}
    for s in list(arm.springs) + [s4]:
        labels[s.name.replace("k", "b")] = s.a
        labels[s.name.replace("k", "a")] = s.b
    return Design("Singh's four-bar with minimum preload", ("ground", "body 1", "body 2", "body 3"),
                  fourbar_joints(kin), kin, loads, list(arm.springs) + [s4], labels=labels,
                  parameters=params, reference="Singh & Ananthasuresh, Sec. III.A (eqs 18-20, 42-49)")
