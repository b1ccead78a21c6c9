"""Lab 5, four-bars: the lecture's two-spring four-bar, Singh's four-bar, Deepak's technique 2."""
from __future__ import annotations

from typing import Any

import numpy as np

from ...core.design import Design
from ...methods.deepak import example_fourbar, technique2
from ...methods.lecture import fourbar_two_springs
from ...methods.singh import singh_fourbar
from .answers import as_mapping, design_balanced, numeric, quantity
from .core import AnswerError, register_task

__all__ = ["LAB5_TECHNIQUE2", "lab5_technique2"]

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
