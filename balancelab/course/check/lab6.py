"""Lab 6, scissors and Peaucellier-Lipkin: Singh's projector lift and writing board.

Task 6.4 (derive) asks for the spring conditions of a scissors lift of the student's own number of
stages, with spring 1 spanning the student's own stages (a personal variant: Singh's lift, whose
conditions the library prints, is the published variant only).
"""
from __future__ import annotations

import math

from ...core.design import Design
from ...core.elements import Spring
from ...methods.singh import peaucellier_board, scissors_lift
from .answers import as_mapping, design_balanced, numeric, quantity
from .core import AnswerError, register_task
from .variant import equivalent_parts

__all__ = ["LAB6_SCISSORS", "LAB6_LIFT", "LAB6_BOARD", "LAB6_STAGE_SYMBOLS", "lab6_scissors"]

#: Lab 6's projector lift (m, kg) and the limits of its design task (N/m, m).
LAB6_SCISSORS = dict(length=0.5, payload_mass=8.0, k_max=600.0, l10_max=0.45)
#: Task 6.1's lift (m, kg): arm length and masses, as :func:`~balancelab.methods.singh.scissors_lift` takes them.
LAB6_LIFT = dict(length=0.5, arm_mass=1.0, slider_mass=0.2, platform_mass=2.0, payload_mass=8.0)
#: Task 6.2's Peaucellier-Lipkin board: the crank spring's attachment (m).
LAB6_BOARD = dict(a_x=0.25)


def lab6_scissors(free_length: float, k1: float | None = None, k2: float | None = None) -> Design:
    """Lab 6's projector lift with spring 1 of free length ``l10``, optionally with given rates.

    Parameters
    ----------
    free_length : float
        Free length ``l10`` of spring 1 (m), > 0.
    k1, k2 : float, optional
        Spring rates (N/m); by default those that balance the lift (Singh eqs 52-59).

    Returns
    -------
    Design

    Examples
    --------
    >>> lab6_scissors(0.3).bodies[:3]
    ('ground', 'arm 2', 'arm 3')
    """
    p = LAB6_SCISSORS
    d = scissors_lift(length=p["length"], payload_mass=p["payload_mass"], free_length=free_length)
    if k1 is None and k2 is None:
        return d
    s1, s2 = d.springs
    k1 = s1.k if k1 is None else k1
    k2 = s2.k if k2 is None else k2
    return d.replace(springs=[Spring(k1, s1.free_length, s1.a, s1.b, name=s1.name),
                              Spring(k2, s2.free_length, s2.a, s2.b, name=s2.name)])


def _lift_numbers(rng) -> dict:
    """Task 6.1's lift (m, kg): :data:`LAB6_LIFT`, or a student's (arm length, arm and payload masses)."""
    if rng is None:
        return dict(LAB6_LIFT)
    u = lambda lo, hi, nd: round(float(rng.uniform(lo, hi)), nd)  # noqa: E731
    return dict(LAB6_LIFT, length=u(0.25, 0.9, 3), arm_mass=u(0.5, 1.8, 2), payload_mass=u(1.0, 20.0, 1))


def _lift_rate(lift: dict) -> float:
    return float(scissors_lift(**lift).parameters["k1"])


@register_task("6.1", "spring rate k1 of the projector lift with l10 = a", "k1_lift", "numeric",
               "a number in N/m for your lift (task_numbers('6.1')); accepted within 0.5 %",
               numbers=_lift_numbers, distinct=(_lift_rate, 0.015))
def _t61(answer, lift):
    return numeric(answer, _lift_rate(lift), "stiffness")


def _board_numbers(rng) -> dict:
    """Task 6.2's crank attachment ``a_x`` (m): :data:`LAB6_BOARD`, or a student's (log-uniform, 0.08 to 0.4 m)."""
    if rng is None:
        return dict(LAB6_BOARD)
    return dict(a_x=round(math.exp(float(rng.uniform(math.log(0.08), math.log(0.4)))), 4))


def _board_rate(board: dict) -> float:
    return float(peaucellier_board(**board).parameters["k1"])


@register_task("6.2", "spring rate k1 on the Peaucellier-Lipkin board's crank for your a_x1", "k1_board",
               "numeric", "a number in N/m for your a_x1 (task_numbers('6.2')['a_x']); accepted within 0.5 %",
               numbers=_board_numbers, distinct=(_board_rate, 0.015))
def _t62(answer, board):
    return numeric(answer, _board_rate(board), "stiffness")


@register_task("6.3", "a projector lift with a shorter spring 1 (open design)", "lift_design", "design",
               "a dict {'l10': m, 'k1': N/m, 'k2': N/m}: spring 1's free length and both rates; "
               "k1 and k2 at most 600 N/m, l10 at most 0.45 m; balanced to 0.1 %", points=2)
def _t63(answer):
    a = as_mapping(answer, ("l10", "k1", "k2"), "your lift")
    l10 = quantity(a["l10"], "length", "l10")
    k1 = quantity(a["k1"], "stiffness", "k1")
    k2 = quantity(a["k2"], "stiffness", "k2")
    if l10 <= 0 or k1 <= 0 or k2 <= 0:
        raise AnswerError("l10, k1 and k2 must be positive.", "Free lengths and rates are > 0.")
    p = LAB6_SCISSORS
    try:
        d = lab6_scissors(l10, k1, k2)
    except (ValueError, TypeError) as e:
        raise AnswerError(f"This choice gives no lift: {e}", "Pick another l10.") from e
    cons = [(k1 <= p["k_max"] * (1 + 1e-9) and k2 <= p["k_max"] * (1 + 1e-9),
             f"a spring stiffer than {p['k_max']:g} N/m"),
            (l10 <= p["l10_max"] + 1e-12, f"l10 longer than {p['l10_max']} m")]
    return design_balanced(d, cons)


# ------------------------------------------------------------ 6.4: your scissors' spring conditions

#: Task 6.4's symbols and the ranges the judge draws them from (m, kg, m/s^2).
LAB6_STAGE_SYMBOLS: dict[str, tuple[float, float]] = dict(g=(5.0, 15.0), a=(0.2, 1.0), l_10=(0.05, 0.5),
                                                          m_a=(0.2, 3.0), M=(0.5, 30.0))


def _stages_numbers(rng) -> dict:
    """Task 6.4's lift: Singh's (2 stages, spring 1 up to stage 2), or another (from ``rng``)."""
    if rng is None:
        return dict(stages=2, upper=2)
    variants = [(n, j) for n in (2, 3, 4) for j in range(2, n + 1) if (n, j) != (2, 2)]
    stages, upper = variants[int(rng.integers(len(variants)))]
    return dict(stages=stages, upper=upper)


def _stage_rates(stages: int, upper: int) -> dict:
    """Task 6.4's reference ``{"k_1": expr, "k_2": expr}`` for ``stages`` stages, spring 1 up to stage ``upper``."""
    import sympy as sp

    if stages not in (2, 3, 4) or upper not in range(2, stages + 1):
        raise ValueError(f"stages must be 2..4 and upper 2..stages, got {stages!r}, {upper!r}")
    g, l10, ma, M = sp.symbols("g l_10 m_a M")
    # the arms' centres of mass at (i - 1/2) a sin(theta), the platform at n a sin(theta): g a sin(theta) (m_a n^2 + M n)
    k1 = g * stages * (ma * stages + M) / ((upper - 1) * l10)
    return {"k_1": k1, "k_2": (upper - 1) ** 2 * k1}


@register_task("6.4", "the spring conditions of your own scissors lift", "stage_rates", "symbolic",
               "a tuple (k_1, k_2) of sympy expressions in g, a, l_10, m_a, M for your lift (task_numbers('6.4')); "
               "any equivalent form accepted; derived by hand: a cell that calls the library's solvers is refused",
               numbers=_stages_numbers)
def _t64(answer, lift):
    return equivalent_parts(answer, _stage_rates(lift["stages"], lift["upper"]), LAB6_STAGE_SYMBOLS, "your rates",
                            hint="Write every height as a multiple of a sin(theta); the sin^2 terms fix k_2 / k_1 and "
                                 "the sin terms fix k_1 l_10.")
