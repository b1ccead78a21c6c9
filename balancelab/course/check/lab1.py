"""Lab 1, balancing with counterweights: a lamp arm and a four-bar.

The four-bar uses the library's vocabulary (:mod:`balancelab.mechanisms.fourbar`): ground
pivots ``A`` (crank) and ``B`` (rocker), ``D`` the crank-coupler joint, ``C`` the
coupler-rocker joint; the lab's text, the drawing's labels and the task texts use the same
names (crank ``AD``, coupler ``DC``, rocker ``BC``).
"""
from __future__ import annotations

from typing import Any

import numpy as np

from ...core.design import Design
from ...core.elements import gravity_load
from ...mechanisms.fourbar import FourBarKinematics, fourbar_joints, fourbar_labels
from ...methods.lecture import equivalent_masses, single_link_counterweight
from .answers import as_mapping, design_balanced, numeric, numeric_vector, point, quantity, symbolic, personal_option
from .core import AnswerError, register_task

__all__ = ["LAMP_ARM", "LAB1_FOURBAR", "lab1_fourbar"]

#: Task 1.1's lamp arm (kg, m): a lamp head ``mass`` at ``length`` on a uniform arm of
#: ``link_mass``, balanced by ``counter_mass``.
LAMP_ARM = dict(mass=1.2, length=0.45, link_mass=0.6, counter_mass=3.0)

#: Four-bar of lab 1 (m, kg) and the limits of its design task. Crank and rocker are
#: uniform bars; the coupler's centre of mass is on the coupler, 0.2 m from the crank joint.
#: ``masses`` and ``coms`` are of crank, coupler, rocker (local frames).
LAB1_FOURBAR: dict[str, Any] = dict(A=(0.0, 0.0), B=(0.6, 0.0), crank=0.2, coupler=0.5, rocker=0.4,
                    masses=(0.8, 1.2, 1.0), coms=((0.1, 0.0), (0.2, 0.0), (0.2, 0.0)),
                    max_mass=6.0, max_radius=0.25)

_LINKS = ("crank", "coupler", "rocker")


def lab1_fourbar(crank_cw=None, rocker_cw=None, masses=None) -> Design:
    """The four-bar of lab 1, optionally with counterweights on the crank and the rocker.

    Parameters
    ----------
    crank_cw, rocker_cw : (float, (float, float)), optional
        ``(mass kg, (x, y) m)``: a counterweight on the crank (local frame: origin at its
        ground pivot ``A``, x-axis along the crank) or on the rocker (origin at its ground
        pivot ``B`` -- ``D`` in the lab's text -- x-axis along the rocker).
    masses : (float, float, float), optional
        Masses of crank, coupler and rocker (kg), e.g. a student's of task 1.4
        (``task_numbers("1.4")["masses"]``); :data:`LAB1_FOURBAR`'s by default.

    Returns
    -------
    Design
        Bodies ground, crank, coupler, rocker; the drawing's labels are the lab's point
        names.

    Examples
    --------
    >>> lab1_fourbar().balance_report().balanced
    False
    >>> [load.name for load in lab1_fourbar((1.0, (-0.1, 0.0))).loads][-1]
    'crank counterweight'
    """
    p = LAB1_FOURBAR
    kin = FourBarKinematics(p["A"], p["B"], p["crank"], p["coupler"], p["rocker"], branch=1)
    masses = p["masses"] if masses is None else tuple(float(m) for m in masses)
    if len(masses) != 3 or not all(m > 0 for m in masses):
        raise ValueError(f"masses (kg) must be three positive numbers (crank, coupler, rocker), got {masses!r}")
    loads = [gravity_load(body, com, mass, name)
             for body, (name, mass, com) in enumerate(zip(_LINKS, masses, p["coms"]), start=1)]
    for body, cw, name in ((1, crank_cw, "crank counterweight"), (3, rocker_cw, "rocker counterweight")):
        if cw is not None:
            m, pt = cw
            loads.append(gravity_load(body, tuple(pt), float(m), name, kind="counterweight"))
    labels = fourbar_labels(kin)  # the library's names: A, B ground pivots; D, C moving joints
    return Design("lab 1 four-bar", ("ground",) + _LINKS, fourbar_joints(kin), kin, loads, labels=labels,
                  reference="Lecture 35: coupler replaced by equivalent masses at its joints")


def _lamp_numbers(rng) -> dict:
    """Task 1.1's lamp arm: the published numbers, or a student's (drawn from ``rng``)."""
    if rng is None:
        return dict(LAMP_ARM)
    return dict(mass=round(rng.uniform(0.6, 2.0), 2), length=round(rng.uniform(0.3, 0.6), 3),
                link_mass=round(rng.uniform(0.3, 1.0), 2), counter_mass=round(rng.uniform(2.0, 5.0), 2))


@register_task("1.1", "distance of the counterweight from the pivot", "r_c", "numeric",
               "a number in metres (or a string like '22 cm'); accepted within 0.5 %", numbers=_lamp_numbers,
               distinct=(lambda lamp: _r_c(lamp), 0.015))
def _t11(answer, lamp):
    return numeric(answer, _r_c(lamp), "length")


def _r_c(lamp: dict) -> float:
    return single_link_counterweight(mass=lamp["mass"], length=lamp["length"], counter_mass=lamp["counter_mass"],
                                     link_mass=lamp["link_mass"]).parameters["r_c"]


def _arm_numbers(rng) -> dict:
    """Task 1.2's variant: the arm's own centre of mass at the fraction ``f`` of ``r`` from the pivot
    (SymPy text); ``"1/2"`` (a uniform arm, the book's) for the published problem."""
    return dict(f=personal_option(rng, "1/2", ("1/3", "2/5", "3/5", "2/3", "3/4")))


@register_task("1.2", "formula for the counterweight distance r_c", "r_c_formula", "symbolic",
               "a sympy expression in m, r, m_l, m_c for your arm (task_numbers('1.2'): its own centre of mass "
               "at the fraction f of r from the pivot); any equivalent form is accepted", numbers=_arm_numbers)
def _t12(answer, arm):
    import sympy as sp

    m, r, ml, mc = sp.symbols("m r m_l m_c", positive=True)
    f = sp.Rational(arm["f"])
    return symbolic(answer, (m * r + f * ml * r) / mc, "m r m_l m_c", "your r_c",
                    hint="Write the arm's potential energy with its own centre of mass at f r, and make the "
                         "coefficient of sin(theta) vanish.")


def _coupler_numbers(rng) -> dict:
    """Task 1.3's coupler: ``mass`` (kg) and its centre of mass ``com`` (m from D along DC), published
    (:data:`LAB1_FOURBAR`'s) or a student's (from ``rng``)."""
    p = LAB1_FOURBAR
    if rng is None:
        return dict(mass=p["masses"][1], com=p["coms"][1][0])
    return dict(mass=round(float(rng.uniform(0.8, 2.0)), 3), com=round(float(rng.uniform(0.08, 0.42)), 3))


def _equivalent(numbers: dict) -> tuple[float, float]:
    """Task 1.3's expected ``(m_D, m_C)`` (kg), from the library's equivalent masses."""
    p, mass = LAB1_FOURBAR, numbers["mass"]
    c = equivalent_masses(crank=p["crank"], coupler=p["coupler"], rocker=p["rocker"], mass=mass,
                          com=(numbers["com"], 0.0))["c"].real
    return mass * (1 - c), mass * c


@register_task("1.3", "equivalent masses of the coupler at D and C", "m_equivalent", "numeric",
               "a pair (m_D, m_C) in kg for your coupler (task_numbers('1.3'): its mass and its centre of "
               "mass, m from D along DC); each accepted within 0.5 %", numbers=_coupler_numbers,
               distinct=(lambda n: _equivalent(n)[1], 0.015))
def _t13(answer, numbers):
    # D and C: the coupler's joints with the crank and with the rocker
    return numeric_vector(answer, _equivalent(numbers), "mass", names=("m_D", "m_C"))


def _counterweight(answer: dict, key: str) -> tuple[float, tuple[float, float]]:
    """``(mass kg, (x, y) m)`` of one counterweight of task 1.4's answer."""
    item = answer[key]
    if not isinstance(item, (tuple, list)) or len(item) != 2:
        raise AnswerError(f"counterweights[{key!r}] should be a pair (mass, (x, y)).", "E.g. (2.0, (-0.1, 0.0)).")
    m = quantity(item[0], "mass", f"the {key} counterweight mass")
    pt = point(item[1], f"the {key} counterweight position")
    if m < 0:
        raise AnswerError(f"The {key} counterweight mass is negative.", "Masses are >= 0.")
    return m, tuple(pt)


def _fourbar_numbers(rng) -> dict:
    """Task 1.4's link masses (kg): :data:`LAB1_FOURBAR`'s, or a student's (from ``rng``)."""
    if rng is None:
        return dict(masses=tuple(LAB1_FOURBAR["masses"]))
    return dict(masses=(round(float(rng.uniform(0.6, 1.0)), 2), round(float(rng.uniform(1.0, 1.5)), 2),
                        round(float(rng.uniform(0.8, 1.3)), 2)))


def _crank_moment(numbers: dict) -> float:
    """First moment (kg m) the crank carries about its pivot: its own mass and the coupler's share."""
    p, (m1, m3, _) = LAB1_FOURBAR, numbers["masses"]
    share = m3 * (1 - p["coms"][1][0] / p["coupler"])
    return m1 * p["coms"][0][0] + share * p["crank"]


@register_task("1.4", "counterweights that balance the four-bar (open design)", "counterweights", "design",
               "a dict {'crank': (mass, (x, y)), 'rocker': (mass, (x, y))} in kg and m, local frames; "
               "each mass at most 6 kg and at most 0.25 m from its pivot; balanced to 0.1 % with your "
               "link masses (task_numbers('1.4'))", points=2, numbers=_fourbar_numbers,
               distinct=(_crank_moment, 0.01))
def _t14(answer, fourbar):
    a = as_mapping(answer, ("crank", "rocker"), "your counterweights")
    p = LAB1_FOURBAR
    parts, cons = {}, []
    for key in ("crank", "rocker"):
        m, pt = parts[key] = _counterweight(a, key)
        cons.append((m <= p["max_mass"] + 1e-12, f"{key} counterweight heavier than {p['max_mass']} kg"))
        cons.append((float(np.hypot(*pt)) <= p["max_radius"] + 1e-12,
                     f"{key} counterweight farther than {p['max_radius']} m from its pivot"))
    d = lab1_fourbar(parts["crank"], parts["rocker"], masses=fourbar["masses"])
    return design_balanced(d, cons)
