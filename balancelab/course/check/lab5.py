"""Lab 5, four-bars: the lecture's two-spring four-bar, Singh's four-bar, Deepak's technique 2.

Task 5.4 (derive) asks for the lecture's two spring rates as formulas in the student's own numbering
of the links (a personal variant: a formula copied from the chapter, in its numbering, is wrong).
"""
from __future__ import annotations

import itertools

from typing import Any

import numpy as np

from ...core.design import Design
from ...methods.deepak import example_fourbar, technique2
from ...methods.lecture import fourbar_two_springs
from ...methods.singh import singh_fourbar
from .answers import as_mapping, design_balanced, numeric, quantity
from .core import AnswerError, register_task
from .variant import equivalent_parts

__all__ = ["LAB5_TECHNIQUE2", "LAB5_LINKS", "lab5_technique2", "lab5_symbol_ranges"]

#: Lab 5's spring-loaded four-bar (technique 2) and the box its springs must fit in (m, N/m).
LAB5_TECHNIQUE2: dict[str, Any] = dict(K=(0.1, -0.2), k_l=100.0, box=((-0.25, -0.35), (0.6, 0.35)), k_max=400.0)


def lab5_technique2(base: str = "A", h: float = 0.15) -> Design:
    """Lab 5's spring-loaded four-bar balanced by technique 2 (Deepak & Ananthasuresh, Sec. 2.2.2).

    Parameters
    ----------
    base : {"A", "B"}
        Ground pivot the auxiliary parallelogram is based at.
    h : float
        The free length ``|WH|`` (m), > 0.

    Returns
    -------
    Design

    Examples
    --------
    >>> lab5_technique2("B", 0.3).bodies
    ('ground', 'crank', 'coupler', 'rocker')
    """
    p = LAB5_TECHNIQUE2
    return technique2(example_fourbar(), p["K"], p["k_l"], base, h)


def _spring_extent(design: Design, n: int = 300) -> np.ndarray:
    """Bounding box ``[[xmin, ymin], [xmax, ymax]]`` (m) of every spring end over ``n`` configurations."""
    q = design.sample(n)
    pts = [design.world_points(q, [at]).reshape(-1, 2) for s in design.springs for at in (s.a, s.b)]
    P = np.concatenate(pts)
    return np.array([P.min(axis=0), P.max(axis=0)])


def _u(rng, lo: float, hi: float, nd: int = 3) -> float:
    return round(float(rng.uniform(lo, hi)), nd)


def _lecture_numbers(rng) -> dict:
    """Task 5.1's four-bar (kg, m): the lecture's masses and centres of mass, or a student's (from ``rng``)."""
    if rng is None:
        return dict(masses=(1.0, 2.0, 1.5), coms=((0.15, 0.0), (0.4, 0.1), (0.3, 0.0)))
    scale = float(np.exp(rng.uniform(np.log(0.4), np.log(2.5))))  # spreads the answers: few classmates share one
    return dict(masses=(round(scale * _u(rng, 0.4, 2.0), 3), round(scale * _u(rng, 0.8, 4.0), 3), 1.5),
                coms=((_u(rng, 0.05, 0.25), 0.0), (_u(rng, 0.25, 0.55), _u(rng, 0.0, 0.2)), (0.3, 0.0)))


def _crank_rate(numbers: dict) -> float:
    return float(fourbar_two_springs(**numbers).parameters["k2"])


@register_task("5.1", "spring rate on the crank of the lecture's four-bar with two springs", "k_crank",
               "numeric", "a number in N/m for your four-bar (task_numbers('5.1')); accepted within 0.5 %",
               numbers=_lecture_numbers, distinct=(_crank_rate, 0.015))
def _t51(answer, numbers):
    return numeric(answer, _crank_rate(numbers), "stiffness")


def _singh_numbers(rng) -> dict:
    """Task 5.2's loads (N): Singh's three weights, or a student's (from ``rng``)."""
    if rng is None:
        return dict(weights=(10.0, 20.0, 10.0))
    scale = float(np.exp(rng.uniform(np.log(0.4), np.log(2.5))))  # spreads the answers: few classmates share one
    return dict(weights=tuple(round(scale * _u(rng, lo, hi), 2) for lo, hi in ((3.0, 18.0), (8.0, 40.0), (3.0, 20.0))))


def _pe_min(numbers: dict) -> float:
    # PE_min depends on the loads only; free choices far apart keep every spring rate positive
    return float(singh_fourbar(**numbers, a_x=(1.0, 6.0, -6.0)).parameters["PE_min"])


@register_task("5.2", "constant energy of Singh's four-bar balanced with minimum preload", "pe_min_fourbar",
               "numeric", "a number in J for your weights (task_numbers('5.2')); accepted within 0.5 %",
               numbers=_singh_numbers, distinct=(_pe_min, 0.015))
def _t52(answer, numbers):
    return numeric(answer, _pe_min(numbers), "energy")


@register_task("5.3", "a technique-2 balancer whose springs fit in the box (open design)", "technique2_choice",
               "design", "a dict {'base': 'A' or 'B', 'h': metres}; every spring at most 400 N/m and every "
               "spring end inside -0.25 <= x <= 0.6 m, -0.35 <= y <= 0.35 m in every configuration; "
               "balanced to 0.1 %", points=2)
def _t53(answer):
    a = as_mapping(answer, ("base", "h"), "your choice")
    if a["base"] not in ("A", "B"):
        raise AnswerError(f"base should be 'A' or 'B', got {a['base']!r}.", "The two ground pivots are A and B.")
    h = quantity(a["h"], "length", "h")
    if h <= 0:
        raise AnswerError("h must be positive.", "h is a length |WH| > 0.")
    try:
        d = lab5_technique2(a["base"], h)
    except (ValueError, TypeError) as e:
        raise AnswerError(f"This choice gives no design: {e}", "Try another h.") from e
    p = LAB5_TECHNIQUE2
    lo, hi = np.array(p["box"][0]), np.array(p["box"][1])
    ext = _spring_extent(d)
    cons = [(all(s.k <= p["k_max"] * (1 + 1e-9) for s in d.springs), f"a spring stiffer than {p['k_max']:g} N/m"),
            (bool(np.all(ext[0] >= lo - 1e-9) and np.all(ext[1] <= hi + 1e-9)),
             "a spring end leaves the box")]
    return design_balanced(d, cons)


# ------------------------------------------------------- 5.4: the two springs' rates in your link numbering

#: Task 5.4's links, in the lecture's numbering (the ground is link 1).
LAB5_LINKS = ("crank", "coupler", "rocker")


def _numbering_numbers(rng) -> dict:
    """Task 5.4's link numbering: the lecture's (crank 2, coupler 3, rocker 4), or another (from ``rng``)."""
    if rng is None:
        return dict(numbering={"crank": 2, "coupler": 3, "rocker": 4})
    orders = [p for p in itertools.permutations((2, 3, 4)) if p != (2, 3, 4)]
    order = orders[int(rng.integers(len(orders)))]
    return dict(numbering=dict(zip(LAB5_LINKS, order)))


def lab5_symbol_ranges(numbering: dict) -> dict[str, tuple[float, float]]:
    """Task 5.4's symbols and the ranges the judge draws them from (m, kg, m/s^2); the same for every numbering.

    Parameters
    ----------
    numbering : dict
        ``{"crank": n, "coupler": n, "rocker": n}``, a permutation of 2, 3, 4
        (``task_numbers("5.4")["numbering"]``).

    Returns
    -------
    dict
        ``g``, ``m_i``, ``l_i``, ``r_i`` (i = 2, 3, 4) and ``b_A, c_A, b_B, c_B``.

    Examples
    --------
    >>> sorted(lab5_symbol_ranges({"crank": 3, "coupler": 4, "rocker": 2}))[:4]
    ['b_A', 'b_B', 'c_A', 'c_B']
    """
    if not isinstance(numbering, dict) or sorted(numbering) != sorted(LAB5_LINKS) \
            or sorted(numbering.values()) != [2, 3, 4]:
        raise ValueError(f"numbering must map crank, coupler and rocker to 2, 3, 4 (each once), got {numbering!r}")
    spans = dict(g=(5.0, 15.0), b_A=(0.05, 0.4), c_A=(0.05, 0.4), b_B=(0.05, 0.4), c_B=(0.05, 0.4))
    for i in (2, 3, 4):
        spans.update({f"m_{i}": (0.3, 4.0), f"l_{i}": (0.2, 1.0), f"r_{i}": (0.02, 0.5)})
    return spans


def _fourbar_rates(numbering: dict) -> dict:
    """Task 5.4's reference ``{"k_A": expr, "k_B": expr}`` in the student's numbering."""
    import sympy as sp

    lab5_symbol_ranges(numbering)
    m, l, r = ({link: sp.Symbol(f"{q}_{numbering[link]}") for link in LAB5_LINKS} for q in "mlr")
    g, bA, cA, bB, cB = sp.symbols("g b_A c_A b_B c_B")
    share = r["coupler"] / l["coupler"]  # the coupler's mass splits between D and C in this ratio
    crank = m["crank"] * r["crank"] + m["coupler"] * (1 - share) * l["crank"]
    rocker = m["rocker"] * r["rocker"] + m["coupler"] * share * l["rocker"]
    return {"k_A": g * crank / (bA * cA), "k_B": g * rocker / (bB * cB)}


@register_task("5.4", "the two spring rates of the lecture's four-bar as formulas, in your link numbering",
               "fourbar_rates", "symbolic",
               "a tuple (k_A, k_B) of sympy expressions in g, m_i, l_i, r_i (i = 2, 3, 4 in your numbering: "
               "task_numbers('5.4')), b_A, c_A, b_B, c_B; any equivalent form accepted; derived by hand: a cell "
               "that calls the library's solvers is refused", numbers=_numbering_numbers)
def _t54(answer, numbers):
    numbering = numbers["numbering"]
    return equivalent_parts(answer, _fourbar_rates(numbering), lab5_symbol_ranges(numbering), "your rates",
                            hint="Replace the coupler by equivalent masses at D and C; then each of crank and rocker "
                                 "is a single link balanced by one ZFL spring. Mind which number is which link.")
