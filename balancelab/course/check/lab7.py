"""Lab 7, balance your own linkage: the linkage builder and the general solver of chapter 7.

The tasks are registered with :func:`~.core.register_task`, so the notebook's ``check`` and
the trusted grader run the same judges on the same plain data; each judge builds everything
it needs from the answer (plain numbers, strings and tuples) and the library:

* 7.1: free choices left on the lab's 3R lamp arm (:data:`LAB7_ARM`, not the chapter's) by
  the all-pairs candidates of chapter 7 without the ground-to-``upper`` spring;
* 7.2: the least total stiffness of that arm with those candidates (``"min_stiffness"``);
* 7.3 (open design): springs for the parallelogram desk lamp that fit the constraints of
  :data:`LAB7_LAMP` (at most three ZFL springs from the base, anchors in a box, rates
  limited), given as numbers; the judge rebuilds the lamp with them and runs its balance
  report;
* 7.4 (sliders): the least counter mass that balances lab 7's slider-crank
  (:func:`lab7_slider_crank`, :data:`LAB7_SLIDER`) with one counterweight on the crank inside
  the lab's box;
* 7.5 (derive, personal variant): the three ZFL spring rates that balance a 2R arm
  (:func:`lab7_own_arm`) as formulas, for the student's own arrangement of the springs and with or
  without the lamp, judged by equivalence on random instances (:mod:`.variant`).
"""
from __future__ import annotations

from typing import Any

import functools

import numpy as np

from ...core.design import Design
from ...core.elements import Spring
from ...methods.general import balance, free_choices
from ...mechanisms.linkage import Linkage
from ...methods.general.examples import all_pairs, arm_3r, parallelogram_lamp
from .answers import design_balanced, numeric, point, quantity
from .core import AnswerError, register_task
from .variant import equivalent_parts

__all__ = ["LAB7_ARM", "LAB7_LAMP", "LAB7_SLIDER", "LAB7_OWN_SYMBOLS", "LAB7_OWN_ARRANGEMENTS", "lab7_arm",
           "lab7_candidates", "lab7_slider_crank", "lamp_with_springs", "lab7_own_arm"]

#: Lab 7's 3R arm (m, kg): other numbers than chapter 7's, so the chapter does not print the answers.
LAB7_ARM: dict[str, Any] = dict(lengths=(0.45, 0.35, 0.25), masses=(1.8, 1.2, 0.8), lamp=0.4)

#: Lab 7's slider-crank (m, kg; the rod's mass at ``rod_com`` along it) and the box of its counterweight (m).
LAB7_SLIDER: dict[str, Any] = dict(crank=0.25, rod=0.7, crank_mass=1.2, rod_mass=0.8, rod_com=0.3, slider_mass=1.5,
                   box=((-0.5, 0.5), (-0.5, 0.5)))

#: The open design task's constraints: anchors (on the ground) in ``box`` (m), rates up to ``k_max`` (N/m).
LAB7_LAMP: dict[str, Any] = dict(box=((-0.15, 0.15), (0.0, 0.3)), k_max=300.0, max_springs=3)


def lab7_arm(numbers: dict | None = None) -> Design:
    """Lab 7's unbalanced 3R lamp arm (:func:`~balancelab.methods.general.examples.arm_3r` with :data:`LAB7_ARM`).

    Parameters
    ----------
    numbers : dict, optional
        ``lengths`` (m), ``masses`` (kg) and ``lamp`` (kg) instead of :data:`LAB7_ARM`'s, e.g. a
        student's personal numbers of task 7.2 (``task_numbers("7.2")``).

    Returns
    -------
    Design

    Examples
    --------
    >>> lab7_arm().bodies
    ('ground', 'upper', 'fore', 'hand')
    """
    return arm_3r(**(LAB7_ARM if numbers is None else numbers))


def lab7_candidates(arm: Design) -> list:
    """Chapter 7's all-pairs candidate springs of ``arm`` without the one from the ground to ``upper``.

    Parameters
    ----------
    arm : Design
        A 3R arm such as :func:`lab7_arm`.

    Returns
    -------
    list
        Candidates for :func:`~balancelab.balance`.

    Examples
    --------
    >>> len(lab7_candidates(lab7_arm()))
    5
    """
    return [c for c in all_pairs(arm) if {c[0][0], c[1][0]} != {"ground", "upper"}]


def _arm_personal(rng) -> dict:
    """Task 7.2's arm (m, kg): :data:`LAB7_ARM`, or a student's (lengths, masses and lamp from ``rng``)."""
    if rng is None:
        return {k: tuple(v) if isinstance(v, tuple) else v for k, v in LAB7_ARM.items()}
    lengths = tuple(round(float(x), 3) for x in (rng.uniform(0.34, 0.6), rng.uniform(0.25, 0.45),
                                                 rng.uniform(0.18, 0.32)))
    scale = float(np.exp(rng.uniform(np.log(0.4), np.log(2.5))))  # spreads the answers: few classmates share one
    masses = tuple(round(scale * float(x), 3) for x in (rng.uniform(1.0, 3.0), rng.uniform(0.6, 2.2), rng.uniform(0.4, 1.4)))
    return dict(lengths=lengths, masses=masses, lamp=round(scale * float(rng.uniform(0.2, 0.8)), 3))


def _key(numbers: dict) -> tuple:
    return (tuple(numbers["lengths"]), tuple(numbers["masses"]), float(numbers["lamp"]))


@functools.lru_cache(maxsize=64)
def _free_choices_left(key: tuple) -> int:
    arm = lab7_arm(dict(zip(("lengths", "masses", "lamp"), key)))
    return free_choices(arm, springs=lab7_candidates(arm)).free_choices


@functools.lru_cache(maxsize=1024)
def _least_stiffness(key: tuple) -> float:
    arm = lab7_arm(dict(zip(("lengths", "masses", "lamp"), key)))
    stiff = balance(arm, springs=lab7_candidates(arm), objective="min_stiffness")
    return float(sum(s.k for s in stiff.springs))


@register_task("7.1", "free choices left on lab 7's 3R arm without the ground-to-upper spring", "n_free", "numeric",
               "a whole number; accepted within 0.5 %")
def _t71(answer):
    # a count of the structure (springs and joints), the same for any lengths and masses: no personal numbers
    return numeric(answer, float(_free_choices_left(_key(_arm_personal(None)))), "ratio")


@register_task("7.2", "least total stiffness of lab 7's 3R arm with those candidates", "k_total_min",
               "numeric", "a number in N/m (or with a unit); accepted within 0.5 %", numbers=_arm_personal,
               distinct=(lambda arm: _least_stiffness(_key(arm)), 0.015))
def _t72(answer, arm):
    return numeric(answer, _least_stiffness(_key(arm)), "stiffness")


def lab7_slider_crank() -> Design:
    """Lab 7's slider-crank (:data:`LAB7_SLIDER`): crank, rod and a slider on a level guide through
    the crank's pivot (a prismatic joint); the crank's mass at its middle.

    Returns
    -------
    Design

    Examples
    --------
    >>> d = lab7_slider_crank()
    >>> d.bodies, d.q_names
    (('ground', 'crank', 'rod', 'slider'), ('theta_1',))
    """
    v = LAB7_SLIDER
    lk = Linkage("lab 7 slider-crank")
    lk.revolute("ground", (0.0, 0.0), "crank", (0.0, 0.0))
    lk.revolute("crank", (v["crank"], 0.0), "rod", (0.0, 0.0))
    lk.revolute("rod", (v["rod"], 0.0), "slider", (0.0, 0.0))
    lk.prismatic("ground", (0.0, 0.0), "slider", (0.0, 0.0), axis=(1.0, 0.0))
    lk.mass("crank", v["crank_mass"], com=(v["crank"] / 2, 0.0))
    lk.mass("rod", v["rod_mass"], com=(v["rod_com"], 0.0))
    lk.mass("slider", v["slider_mass"])
    return lk.build(guess={"crank": 1.0})


@functools.cache
def _slider_mass() -> float:
    d = balance(lab7_slider_crank(), counterweights=[("crank", None)], objective="min_mass", box=LAB7_SLIDER["box"])
    return float(d.parameters["counter_mass1"])


@register_task("7.4", "least counter mass on the crank that balances lab 7's slider-crank", "counter_mass_min",
               "numeric", "a mass in kg (or with a unit); accepted within 0.5 %")
def _t74(answer):
    return numeric(answer, _slider_mass(), "mass")


def lamp_with_springs(springs) -> Design:
    """The parallelogram lamp of chapter 7 with ``springs`` as ``(k, (body, (x, y)), (body, (x, y)))`` ZFL springs.

    Parameters
    ----------
    springs : sequence
        Each spring as its rate (N/m, or a string with a unit) and its two ends, each a body
        (name or index) and a local point (m).

    Returns
    -------
    Design

    Raises
    ------
    AnswerError
        When a spring is not of that form or names a body the lamp has not.

    Examples
    --------
    >>> d = lamp_with_springs([(100.0, ("ground", (0.0, 0.2)), ("link 1", (0.2, 0.0)))])
    >>> len(d.springs), d.balance_report().balanced
    (1, False)
    """
    lamp = parallelogram_lamp()
    built = []
    for i, item in enumerate(springs):
        try:
            k, (ba, pa), (bb, pb) = item
        except (TypeError, ValueError):
            raise AnswerError(f"Spring {i + 1} is not (k, (body, (x, y)), (body, (x, y))).",
                              "Write each spring as (k, (body, (x, y)), (body, (x, y))).") from None
        ends = []
        for body, p in ((ba, pa), (bb, pb)):
            if body not in lamp.bodies and body not in range(len(lamp.bodies)):
                raise AnswerError(f"Spring {i + 1} names the body {body!r}, which the lamp has not.",
                                  f"The bodies are {lamp.bodies}.")
            ends.append((lamp.bodies.index(body) if isinstance(body, str) else int(body), tuple(point(p, "a point"))))
        rate = quantity(k, "stiffness", f"k of spring {i + 1}")
        if rate <= 0:
            raise AnswerError(f"k of spring {i + 1} must be positive.", "A spring rate is > 0 N/m.")
        built.append((rate, ends[0], ends[1]))
    return lamp.replace(springs=[Spring(k, 0.0, a, b, name=f"k{i + 1}") for i, (k, a, b) in enumerate(built)])


@register_task("7.3", "ZFL springs for the parallelogram lamp within the limits (open design)", "lamp_springs",
               "design", "a list of up to 3 springs (k, (body, (x, y)), (body, (x, y))) in N/m and m, each from the "
               "ground with its anchor in -0.15 <= x <= 0.15 m, 0 <= y <= 0.3 m and k <= 300 N/m; balanced "
               "to 0.1 %", points=3)
def _t73(answer):
    if isinstance(answer, (str, bytes)) or not hasattr(answer, "__len__"):
        raise AnswerError("Give a list of springs.", "A list of (k, (body, (x, y)), (body, (x, y))).")
    lim = LAB7_LAMP
    design = lamp_with_springs(list(answer))
    (x0, x1), (y0, y1) = lim["box"]
    anchors = [s.a.point if s.a.body == 0 else s.b.point for s in design.springs]
    on_ground = [(s.a.body == 0) != (s.b.body == 0) for s in design.springs]
    inside = [x0 - 1e-9 <= x <= x1 + 1e-9 and y0 - 1e-9 <= y <= y1 + 1e-9 for x, y in anchors]
    cons = [(0 < len(design.springs) <= lim["max_springs"], f"one to {lim['max_springs']} springs"),
            (all(on_ground), "every spring runs from the base (ground) to a moving body"),
            (all(on_ground) and all(inside), "every anchor inside the box"),
            (all(s.k <= lim["k_max"] * (1 + 1e-9) for s in design.springs), f"k at most {lim['k_max']:g} N/m")]
    return design_balanced(design, cons)


# ------------------------------------------------------------------ 7.5: derive the conditions of your own arm

#: Task 7.5's symbols and the ranges the judge draws them from (SI units: m, kg, m/s^2).
LAB7_OWN_SYMBOLS: dict[str, tuple[float, float]] = dict(
    g=(5.0, 15.0), m_1=(0.3, 4.0), p_1=(0.05, 0.4), l_1=(0.2, 0.6), m_2=(0.3, 4.0), p_2=(0.05, 0.4),
    m_L=(0.1, 2.0), l_2=(0.2, 0.6), a=(0.05, 0.4), s_1=(0.05, 0.4), s_2=(0.05, 0.4), s_3=(0.05, 0.4),
    c=(0.02, 0.2))
#: The arrangements of task 7.5: where spring 2 runs and where spring 3 starts on the upper link.
LAB7_OWN_ARRANGEMENTS = ("above", "below")


def _own_numbers(rng) -> dict:
    """Task 7.5's personal variant: the published one, or one of the other three (from ``rng``)."""
    if rng is None:
        return dict(arrangement="above", lamp=True)
    others = [(arr, lamp) for arr in LAB7_OWN_ARRANGEMENTS for lamp in (True, False) if (arr, lamp) != ("above", True)]
    arrangement, lamp = others[int(rng.integers(len(others)))]
    return dict(arrangement=arrangement, lamp=lamp)


def _own_variant(arrangement: str, lamp: bool) -> tuple[str, bool]:
    if arrangement not in LAB7_OWN_ARRANGEMENTS:
        raise ValueError(f"arrangement must be one of {LAB7_OWN_ARRANGEMENTS}, got {arrangement!r}")
    if not isinstance(lamp, (bool, np.bool_)):
        raise TypeError(f"lamp must be True or False, got {lamp!r}")
    return arrangement, bool(lamp)


def lab7_own_arm(arrangement: str, lamp: bool, values: dict, rates: tuple = (1.0, 1.0, 1.0)) -> Design:
    """Task 7.5's 2R arm with three ZFL springs, for numbers of its symbols (to test a derived formula).

    The upper link turns about the ground pivot at the origin (length ``l_1``, mass ``m_1`` at
    ``p_1`` along it); the forearm turns about the elbow (mass ``m_2`` at ``p_2``; with ``lamp``,
    a lamp ``m_L`` at ``l_2``). Spring 1 runs from the ground point ``(0, a)`` to ``(s_1, 0)`` on
    the upper link. ``"above"``: spring 2 from ``(0, a)`` to ``(s_2, 0)`` on the forearm, spring 3
    from ``(l_1 + c, 0)`` on the upper link (past the elbow) to ``(s_3, 0)`` on the forearm.
    ``"below"``: spring 2 from ``(0, -a)`` to ``(-s_2, 0)`` on the forearm (behind the elbow),
    spring 3 from ``(l_1 - c, 0)`` on the upper link to ``(s_3, 0)`` on the forearm.

    Parameters
    ----------
    arrangement : {"above", "below"}
        Where springs 2 and 3 run (``task_numbers("7.5")["arrangement"]``).
    lamp : bool
        Whether the forearm carries the lamp (``task_numbers("7.5")["lamp"]``).
    values : dict
        A number for each symbol of :data:`LAB7_OWN_SYMBOLS` (m, kg, m/s^2; ``m_L`` and ``l_2``
        only with a lamp).
    rates : (float, float, float)
        The rates ``k_1, k_2, k_3`` of the springs (N/m), > 0.

    Returns
    -------
    Design
        Coordinates: the absolute angles of the upper link and the forearm.

    Examples
    --------
    >>> v = dict(g=9.81, m_1=1.5, p_1=0.2, l_1=0.4, m_2=1.0, p_2=0.15, m_L=0.5, l_2=0.35, a=0.2,
    ...          s_1=0.15, s_2=0.25, s_3=0.1, c=0.05)
    >>> lab7_own_arm("above", True, v).q_names
    ('theta_1', 'theta_2')
    """
    arrangement, lamp = _own_variant(arrangement, lamp)
    v = {k: float(values[k]) for k in LAB7_OWN_SYMBOLS if lamp or k not in ("m_L", "l_2")}
    lk = Linkage("lab 7 own arm")
    lk.revolute("ground", (0.0, 0.0), "upper", (0.0, 0.0))
    lk.revolute("upper", (v["l_1"], 0.0), "fore", (0.0, 0.0))
    lk.mass("upper", v["m_1"], com=(v["p_1"], 0.0))
    lk.mass("fore", v["m_2"], com=(v["p_2"], 0.0))
    if lamp:
        lk.mass("fore", v["m_L"], com=(v["l_2"], 0.0), name="lamp")
    k1, k2, k3 = (float(k) for k in rates)
    side = 1.0 if arrangement == "above" else -1.0
    lk.spring("ground", (0.0, v["a"]), "upper", (v["s_1"], 0.0), k=k1, name="k_1")
    lk.spring("ground", (0.0, side * v["a"]), "fore", (side * v["s_2"], 0.0), k=k2, name="k_2")
    lk.spring("upper", (v["l_1"] + side * v["c"], 0.0), "fore", (v["s_3"], 0.0), k=k3, name="k_3")
    return lk.build(name=f"lab 7 own arm ({arrangement}, {'with' if lamp else 'without'} lamp)")


def _own_rates(arrangement: str, lamp: bool) -> dict:
    """Task 7.5's reference rates ``{"k_1": expr, "k_2": expr, "k_3": expr}`` in the symbols of :data:`LAB7_OWN_SYMBOLS`."""
    import sympy as sp

    arrangement, lamp = _own_variant(arrangement, lamp)
    s = {n: sp.Symbol(n) for n in LAB7_OWN_SYMBOLS}
    m_lamp = s["m_L"] if lamp else 0
    upper = s["g"] * (s["m_1"] * s["p_1"] + (s["m_2"] + m_lamp) * s["l_1"])  # the sin(theta_1) coefficient of gravity
    fore = s["g"] * (s["m_2"] * s["p_2"] + m_lamp * s["l_2"])  # that of sin(theta_2)
    k2 = fore / (s["a"] * s["s_2"])
    sign = -1 if arrangement == "above" else 1  # spring 2 pulls the upper link up (above) or down (below)
    return {"k_1": (upper + sign * k2 * s["a"] * s["l_1"]) / (s["a"] * s["s_1"]), "k_2": k2,
            "k_3": k2 * s["l_1"] * s["s_2"] / (s["c"] * s["s_3"])}


@register_task("7.5", "the three spring rates that balance your own 2R arm, from its energy", "own_rates", "symbolic",
               "a tuple (k_1, k_2, k_3) of sympy expressions in the symbols of your arrangement "
               "(task_numbers('7.5')): g, m_1, p_1, l_1, m_2, p_2, a, s_1, s_2, s_3, c, and m_L, l_2 with the "
               "lamp; any equivalent form accepted; derived by hand: a cell that calls the library's solvers "
               "is refused", points=2, numbers=_own_numbers)
def _t75(answer, own):
    names = {n: span for n, span in LAB7_OWN_SYMBOLS.items() if own["lamp"] or n not in ("m_L", "l_2")}
    return equivalent_parts(answer, _own_rates(own["arrangement"], own["lamp"]), names, "your rates",
                            hint="Write the energy of gravity and of the three springs, expand the squared lengths, "
                                 "and set the coefficients of sin(theta_1), sin(theta_2) and cos(theta_2 - theta_1) "
                                 "to zero.")
