"""Lab 4, serial 2R arms: the lecture's parallelogram arm, Singh's minimum-preload 2R, Lustig's method."""
from __future__ import annotations

from typing import Any

import numpy as np

from ...core.design import Design
from ...core.elements import Attachment, Load, Spring
from ...methods.lecture import serial_2r_parallelogram
from ...methods.lustig import LUSTIG_TOPOLOGY, LUSTIG_UNKNOWNS, lustig_values
from ...methods.lustig import solve as lustig_solve
from ...methods.singh import serial_2r_min_preload
from .answers import DESIGN_TOLERANCE, as_mapping, design_balanced, numeric, numeric_vector, symbolic, personal_option, vector
from .core import AnswerError, register_task
from .data import DesignData, decode_answer, encode_answer

__all__ = ["LAB4_PARALLELOGRAM", "LAB4_SINGH", "lab4_singh_arm"]

#: The 2R arm of lab 4's parallelogram task (kg, m), as :func:`serial_2r_parallelogram` takes it.
LAB4_PARALLELOGRAM: dict[str, Any] = dict(masses=(1.2, 0.8), length=0.45, coms=((0.2, 0.0), (0.3, 0.0)),
                          b=(0.15, 0.12), c=(0.1, 0.1))
#: Singh & Ananthasuresh's 2R (N, m) and the limits of lab 4's design task (N/m, m).
LAB4_SINGH: dict[str, Any] = dict(weights=(10.0, 20.0), coms=((1.0, 0.5), (2.0, 0.0)), length=1.5, k_max=9.0, anchor_max=3.2)


def lab4_singh_arm(a_x=None) -> Design:
    """Singh's 2R of lab 4 balanced with minimum preload, for the free choices ``a_x``.

    Parameters
    ----------
    a_x : (float, float, float), optional
        ``(a_x1, a_x2, a_x3)`` (m); those of :func:`~balancelab.methods.singh.serial_2r_min_preload`
        by default.

    Returns
    -------
    Design

    Examples
    --------
    >>> lab4_singh_arm().bodies
    ('ground', 'body 1', 'body 2')
    """
    s = LAB4_SINGH
    extra = {} if a_x is None else {"a_x": tuple(a_x)}
    return serial_2r_min_preload(weights=s["weights"], coms=s["coms"], length=s["length"], **extra)


def _parallelogram_numbers(rng) -> dict:
    """Task 4.1's arm (kg, m): :data:`LAB4_PARALLELOGRAM`, or a student's (masses, length, centres of mass from ``rng``)."""
    p = LAB4_PARALLELOGRAM
    if rng is None:
        return {k: (tuple(map(tuple, v)) if k == "coms" else tuple(v) if isinstance(v, tuple) else v)
                for k, v in p.items()}
    u = lambda lo, hi, nd=3: round(float(rng.uniform(lo, hi)), nd)  # noqa: E731
    length = u(0.35, 0.6)
    return dict(masses=(u(0.7, 1.8), u(0.4, 1.2)), length=length,
                coms=((round(u(0.3, 0.6) * length, 3), 0.0), (u(0.2, 0.4), 0.0)), b=p["b"], c=p["c"])


def _parallelogram_rates(arm: dict) -> tuple[float, float]:
    p = serial_2r_parallelogram(**arm).parameters
    return p["k1"], p["k2"]


@register_task("4.1", "spring rates (k1, k2) of the parallelogram 2R arm", "k_parallelogram", "numeric",
               "a pair (k1, k2) in N/m for your arm (task_numbers('4.1')); each accepted within 0.5 %",
               numbers=_parallelogram_numbers, distinct=(lambda arm: _parallelogram_rates(arm)[0], 0.015))
def _t41(answer, arm):
    return numeric_vector(answer, _parallelogram_rates(arm), "stiffness", names=("k1", "k2"))


def _singh_numbers(rng) -> dict:
    """Task 4.2's 2R (N, m): :data:`LAB4_SINGH`'s loads, or a student's (weights, centres of mass, length)."""
    s = LAB4_SINGH
    if rng is None:
        return dict(weights=tuple(s["weights"]), coms=tuple(map(tuple, s["coms"])), length=s["length"])
    scale = float(np.exp(rng.uniform(np.log(0.4), np.log(2.5))))  # spreads the answers: few classmates share one
    u = lambda lo, hi, nd=2: round(float(rng.uniform(lo, hi)), nd)  # noqa: E731
    return dict(weights=(round(scale * u(3.0, 18.0), 2), round(scale * u(8.0, 40.0), 2)), coms=((u(0.5, 1.5), u(0.1, 0.9)), (u(1.0, 3.2), 0.0)),
                length=u(0.8, 2.2))


def _pe_min(arm: dict) -> float:
    # PE_min depends on the loads only; free choices far apart keep every spring rate positive
    return float(serial_2r_min_preload(**arm, a_x=(1.0, 6.0, -6.0)).parameters["PE_min"])


@register_task("4.2", "least possible constant energy of any balanced version of Singh's 2R", "pe_min_2r",
               "numeric", "a number in J for your arm (task_numbers('4.2'); loads' energy measured from the base "
               "pivot's height); within 0.5 %", numbers=_singh_numbers, distinct=(_pe_min, 0.015))
def _t42(answer, arm):
    return numeric(answer, _pe_min(arm), "energy")


def _same_loads(design: Design, ref: Design) -> bool:
    """Whether ``design`` carries the loads of ``ref`` on the same moving links."""
    key = lambda L: sorted((ld.body, round(ld.point[0], 9), round(ld.point[1], 9),  # noqa: E731
                            round(ld.force[0], 9), round(ld.force[1], 9)) for ld in L)
    if key(design.loads) != key(ref.loads) or design.dof != ref.dof:
        return False
    q = ref.sample(20)
    try:
        return bool(np.allclose(design.poses(q), ref.poses(q), atol=1e-9))
    except Exception:
        return False


def _rebuild(data: DesignData) -> Design:
    """Task 4.3's design rebuilt from plain data on the trusted 2R of Singh's arm (never the student's object)."""
    ref = lab4_singh_arm()
    ref_joints = [(j.body_i, tuple(j.point_i), j.body_j, tuple(j.point_j)) for j in ref.joints]
    same = (data.mechanism == type(ref.kinematics).__name__ and len(data.joints) == len(ref_joints)
            and all(a[0] == b[0] and a[2] == b[2] and np.allclose(a[1], b[1], atol=1e-9)
                    and np.allclose(a[3], b[3], atol=1e-9) for a, b in zip(data.joints, ref_joints)))
    if not same:
        raise AnswerError("Your design is not a 2R arm with the links of Singh's 2R (l = 1.5 m).",
                          "Build it from serial_2r_min_preload(...) of the task.")
    if not data.springs or any(not (np.isfinite(k) and k > 0) for k, *_ in data.springs):
        raise AnswerError("Every spring of your design needs a finite rate k > 0.", "Check the springs.")
    loads = [Load(b, p, f, n, kind) for b, p, f, n, kind in data.loads]
    springs = [Spring(k, ell, Attachment(*a), Attachment(*b), name=n) for k, ell, a, b, n in data.springs]
    return ref.replace(loads=loads, springs=springs)


def _student_arm(answer) -> Design:
    """Task 4.3's design: the student's Design, or the arm built from their free choices."""
    if isinstance(answer, Design):  # only a trusted caller passes a Design; check() passes DesignData
        answer = decode_answer(encode_answer(answer))
    if isinstance(answer, DesignData):
        answer = _rebuild(answer)
        if not _same_loads(answer, lab4_singh_arm()):
            raise AnswerError("Your design does not carry the loads of Singh's 2R (W1 = 10 N at (1, 0.5) m, "
                              "W2 = 20 N at 2 m, l = 1.5 m) on the same two links.",
                              "Build it from serial_2r_min_preload(weights=(10, 20), coms=((1.0, 0.5), "
                              "(2.0, 0.0)), length=1.5, a_x=...).")
        return answer
    a = as_mapping(answer, ("a_x",), "your choice")
    ax = vector(a["a_x"], 3, "length", "a_x")
    try:
        return lab4_singh_arm(ax)
    except (ValueError, TypeError) as e:
        raise AnswerError(f"These free choices give no design: {e}", "Pick other values of a_x.") from e


@register_task("4.3", "minimum-preload 2R whose springs are soft and anchored close (open design)", "arm_design",
               "design", "a balancelab Design of Singh's 2R (or a dict {'a_x': (a_x1, a_x2, a_x3)} for "
               "serial_2r_min_preload); minimum preload (energy within 0.1 % of the least possible), every "
               "spring at most 9 N/m, every ground anchor within 3.2 m of the base pivot; balanced to 0.1 %",
               points=2)
def _t43(answer):
    s = LAB4_SINGH
    d = _student_arm(answer)
    rep = d.balance_report(n=400, tolerance=DESIGN_TOLERANCE)
    pe_min = lab4_singh_arm().parameters["PE_min"]
    anchors = [at.point for sp_ in d.springs for at in (sp_.a, sp_.b) if at.body == 0]
    cons = [(all(sp_.k <= s["k_max"] * (1 + 1e-9) for sp_ in d.springs),
             f"a spring stiffer than {s['k_max']:g} N/m"),
            (all(np.hypot(*p) <= s["anchor_max"] + 1e-9 for p in anchors),
             f"a ground anchor farther than {s['anchor_max']:g} m from the base pivot"),
            (rep.energy <= pe_min * (1 + DESIGN_TOLERANCE) + 1e-12,
             "more preload than necessary (its constant energy is above the least possible)")]
    return design_balanced(d, cons)


#: The inputs of task 4.4 a student's numbers replace (the rest are Table 3e case 1's).
_LUSTIG_PERSONAL = ("m2", "m3", "sx2", "ay1", "k2")


def _lustig_numbers(rng) -> dict:
    """Task 4.4's inputs (kg, m, N/m): case 1 of Table 3e (:func:`lustig_values` unsolved), or a student's
    masses, centre of mass ``sx2``, anchor height ``ay1`` and rate ``k2`` (from ``rng``)."""
    v = {k: float(x) for k, x in lustig_values(1, solved=False).items()}
    if rng is None:
        return v
    u = lambda lo, hi, nd=3: round(float(rng.uniform(lo, hi)), nd)  # noqa: E731
    v.update(m2=u(1.2, 3.0, 2), m3=u(1.2, 3.0, 2), sx2=u(0.06, 0.2), ay1=u(0.06, 0.16), k2=u(300.0, 900.0, 0))
    return v


def _lustig_k1(values: dict) -> float:
    """Task 4.4's expected ``k1`` (N/m): the paper's conditions solved for its six unknowns."""
    return float(lustig_solve(2, LUSTIG_TOPOLOGY, values, LUSTIG_UNKNOWNS)["k1"])


@register_task("4.4", "spring rate k1 of Lustig et al.'s case 1 by the stiffness-matrix method", "k1_lustig",
               "numeric", "a number in N/m for your inputs (task_numbers('4.4')); accepted within 0.5 %",
               numbers=_lustig_numbers, distinct=(_lustig_k1, 0.015))
def _t44(answer, values):
    return numeric(answer, _lustig_k1(values), "stiffness")


#: Task 4.5's hint: PE_min is no balance condition (no coefficient is set to zero) but the largest
#: value of the loads' energy over every pose.
PE_MIN_HINT = ("PE_min is the largest value the loads' energy takes over all poses. Write that energy with "
               "link 2's angle measured from link 1; link 1's terms in sin(theta_1) and cos(theta_1) make one "
               "sinusoid (its largest value is its amplitude; the elbow's weights act at l), and theta_2 is free, "
               "so link 2's largest value adds to it.")


def _elbow_numbers(rng) -> dict:
    """Task 4.5's variant: a motor of weight ``c W_2`` at the elbow (``c`` as SymPy text); ``"0"`` (no
    motor, the book's arm) for the published problem."""
    return dict(c=personal_option(rng, "0", ("1/4", "1/3", "1/2", "2/3", "3/4", "1")))


@register_task("4.5", "formula for the least preload energy PE_min of Singh's 2R", "pe_min_formula", "symbolic",
               "a sympy expression in W_1, W_2, p_x1, p_y1, p_x2, l (p_y2 = 0) for your arm (task_numbers('4.5'): "
               "a motor of weight c W_2 at the elbow); any equivalent form accepted; derived by hand: a cell "
               "that calls the library's solvers is refused", numbers=_elbow_numbers)
def _t45(answer, arm):
    import sympy as sp

    W1, W2, px1, py1, px2, l = sp.symbols("W_1 W_2 p_x1 p_y1 p_x2 l", positive=True)
    c = sp.Rational(arm["c"])
    expected = sp.sqrt((W1 * px1 + (1 + c) * W2 * l) ** 2 + (W1 * py1) ** 2) + W2 * px2
    return symbolic(answer, expected, "W_1 W_2 p_x1 p_y1 p_x2 l", "your PE_min", hint=PE_MIN_HINT)
