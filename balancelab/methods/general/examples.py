"""Worked examples of the general balancer (chapter 7): mechanisms of no source, built and balanced.

* :func:`balanced_3r_arm`: a desk-lamp-like 3R arm (three links and a lamp head) balanced
  by ZFL springs between every pair of bodies, each spring's distal end placed by the solver;
* :func:`balanced_fourbar`: the four-bar of issue 11 (a crank mass and a coupler load)
  balanced by two ZFL springs with free ends and a counterweight on the crank.

Layer: methods.
"""
from __future__ import annotations

import warnings
from typing import Sequence

from ...core.design import Design
from ...core.validation import finite_reals
from ...mechanisms.linkage import Linkage
from ..registry import example
from .balancer import balance

__all__ = ["arm_3r", "all_pairs", "balanced_3r_arm", "fourbar_issue11", "balanced_fourbar", "watt_sixbar",
           "parallelogram_lamp"]


def arm_3r(lengths: Sequence[float] = (0.5, 0.4, 0.3), masses: Sequence[float] = (2.0, 1.5, 1.0),
           lamp: float = 0.5) -> Design:
    """An unbalanced 3R arm: links ``upper``, ``fore``, ``hand`` pinned in series from the origin.

    Parameters
    ----------
    lengths : three floats
        Link lengths (m), > 0.
    masses : three floats
        Link masses (kg), > 0, at the middle of each link.
    lamp : float
        Mass of the lamp head at the tip of ``hand`` (kg), > 0.

    Returns
    -------
    Design
        Three degrees of freedom: the absolute link angles ``theta_1, theta_2, theta_3``.

    Examples
    --------
    >>> arm_3r().q_names
    ('theta_1', 'theta_2', 'theta_3')
    """
    lengths = finite_reals("lengths (m)", lengths, 3, positive=True)
    masses = finite_reals("masses (kg)", masses, 3, positive=True)
    lk = Linkage("3R lamp arm")
    prev, tip = "ground", (0.0, 0.0)
    for name, length, mass in zip(("upper", "fore", "hand"), lengths, masses):
        lk.revolute(prev, tip, name, (0.0, 0.0))
        lk.mass(name, mass, com=(length / 2, 0.0))
        prev, tip = name, (length, 0.0)
    lk.mass("hand", lamp, com=tip, name="lamp")
    return lk.build()


def all_pairs(design: Design, anchor: float = 0.1, ground_anchor=(0.0, 0.15)) -> list:
    """Candidate ZFL springs between every pair of bodies: fixed proximal end, free distal end.

    The end on the body nearer the ground sits at ``(anchor, 0)`` of that body (at
    ``ground_anchor`` on the ground); the other end is left to the solver.

    Examples
    --------
    >>> len(all_pairs(arm_3r()))
    6
    """
    names = design.bodies
    return [((names[i], tuple(ground_anchor) if i == 0 else (anchor, 0.0)), (names[j], None))
            for i in range(len(names)) for j in range(i + 1, len(names))]


@example("general_3r_arm", "A 3R lamp arm balanced by ZFL springs between all pairs of bodies (general balancer)",
         chapter=7, objective="min_stiffness")
def balanced_3r_arm(objective: str = "min_stiffness") -> Design:
    """:func:`arm_3r` balanced with the candidates :func:`all_pairs` for ``objective``.

    Examples
    --------
    >>> balanced_3r_arm().balance_report().balanced
    True
    """
    arm = arm_3r()
    return balance(arm, springs=all_pairs(arm), objective=objective)


def fourbar_issue11() -> Design:
    """The four-bar of issue 11: crank 0.4 m, coupler 1 m, rocker 0.8 m, ground pivots 1 m apart.

    A 2 kg mass at the middle of the crank and a 30 N downward load on the coupler at
    ``(0.5, 0.1)``; assembled with the crank at about 57 degrees and the rocker up.

    Examples
    --------
    >>> fourbar_issue11().dof
    1
    """
    lk = Linkage("four-bar of issue 11")
    lk.revolute("ground", (0.0, 0.0), "crank", (0.0, 0.0))
    lk.revolute("crank", (0.4, 0.0), "coupler", (0.0, 0.0))
    lk.revolute("coupler", (1.0, 0.0), "rocker", (0.8, 0.0))
    lk.revolute("rocker", (0.0, 0.0), "ground", (1.0, 0.0))
    lk.mass("crank", 2.0, com=(0.2, 0.0))
    lk.load("coupler", (0.0, -30.0), com=(0.5, 0.1))
    return lk.build(guess={"crank": 1.0, "rocker": 1.5})


@example("general_fourbar", "The four-bar of issue 11 balanced by two ZFL springs and a counterweight (general "
         "balancer)", chapter=7, objective="min_stiffness")
def balanced_fourbar(objective: str = "min_stiffness") -> Design:
    """:func:`fourbar_issue11` with a ground-crank spring (both ends free), a spring from
    ``(0, 0.5)`` to the rocker (rocker end free) and a counterweight on the crank (free point).

    The stiffness objective does not count the counterweight: its moment ``M p`` is fixed, its
    mass is a free choice (any ``M`` with ``p`` inside the box); :func:`balance`'s warning about
    it is silenced here, the entry keeps the solver's vertex (the point at the box's edge).

    Examples
    --------
    >>> balanced_fourbar().balance_report().balanced
    True
    """
    with warnings.catch_warnings():
        warnings.filterwarnings("ignore", message=".*does not select a unique design", category=UserWarning)
        return balance(fourbar_issue11(),
                       springs=[(("ground", None), ("crank", None)), (("ground", (0.0, 0.5)), ("rocker", None))],
                       counterweights=[("crank", None)], objective=objective)


def watt_sixbar() -> Design:
    """A Watt six-bar with weights: a four-bar (crank 0.3 m, coupler 1 m, rocker 0.8 m, pivots 1 m
    apart) whose coupler and rocker carry a second loop of two links (0.6 m and 0.5 m).

    Bodies: ground, crank, coupler (ternary), rocker (ternary), link4, link5; one degree of
    freedom, the crank angle ``theta_1``, which turns fully.

    Examples
    --------
    >>> d = watt_sixbar()
    >>> d.dof, d.kinematics.full_turn, len(d.joints)
    (1, True, 7)
    """
    lk = Linkage("Watt six-bar")
    lk.revolute("ground", (0.0, 0.0), "crank", (0.0, 0.0))
    lk.revolute("crank", (0.3, 0.0), "coupler", (0.0, 0.0))
    lk.revolute("coupler", (1.0, 0.0), "rocker", (0.8, 0.0))
    lk.revolute("rocker", (0.0, 0.0), "ground", (1.0, 0.0))
    lk.revolute("coupler", (0.5, 0.4), "link4", (0.0, 0.0))
    lk.revolute("link4", (0.6, 0.0), "link5", (0.0, 0.0))
    lk.revolute("link5", (0.5, 0.0), "rocker", (0.4, 0.3))
    for body, mass, at in (("coupler", 1.0, (0.5, 0.1)), ("rocker", 1.0, (0.4, 0.0)), ("link4", 0.5, (0.3, 0.0)),
                           ("link5", 0.5, (0.25, 0.0))):
        lk.mass(body, mass, com=at)
    return lk.build(guess={"crank": 1.2, "rocker": 1.6, "link4": 1.0, "link5": -0.5})


def parallelogram_lamp(length: float = 0.5, offset: float = 0.1, masses: Sequence[float] = (1.0, 1.0)) -> Design:
    """The desk lamp of lecture 35 built with the builder: a 2R arm whose second link is copied to
    the base by a parallelogram, so that both springs can sit on the base.

    Bodies: ground, ``link 1`` (pivoted at the origin), ``link 2`` (at ``(length, 0)`` of link 1),
    ``copy of link 2`` (pivoted at the origin, an arm ``offset`` long behind it) and
    ``copy of link 1`` (from that arm to ``link 2``'s point ``(-offset, 0)``). Two degrees of freedom,
    the angles of links 1 and 2 (``theta_1``, ``theta_2``); one loop, followed on its
    parallelogram branch. Masses at the middle of links 1 and 2.

    Examples
    --------
    >>> d = parallelogram_lamp()
    >>> d.q_names, d.kinematics.grubler
    (('theta_1', 'theta_2'), 2)
    """
    masses = finite_reals("masses (kg)", masses, 2, positive=True)
    lk = Linkage("desk lamp with a parallelogram")
    lk.revolute("ground", (0.0, 0.0), "link 1", (0.0, 0.0))
    lk.revolute("link 1", (length, 0.0), "link 2", (0.0, 0.0))
    lk.revolute("ground", (0.0, 0.0), "copy of link 2", (0.0, 0.0))
    lk.revolute("copy of link 2", (-offset, 0.0), "copy of link 1", (0.0, 0.0))
    lk.revolute("copy of link 1", (length, 0.0), "link 2", (-offset, 0.0))
    lk.mass("link 1", masses[0], com=(length / 2, 0.0))
    lk.mass("link 2", masses[1], com=(length / 2, 0.0))
    return lk.build(driving=["link 1", "link 2"],
                    guess={"link 1": 0.5, "link 2": -0.5, "copy of link 2": -0.5, "copy of link 1": 0.5})
