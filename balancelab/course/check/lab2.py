"""Lab 2, ZFL springs and levers: the lecture's lamp arm, Singh's levers, an open lever design."""
from __future__ import annotations

import numpy as np

from ...core.design import Design
from ...core.elements import Load, Spring
from ...mechanisms.lever import lever_design
from ...methods.lecture import single_link_spring
from ...methods.singh import lacoste_lever
from .answers import design_balanced, numeric, spring, symbolic, personal_option
from .core import AnswerError, register_task

__all__ = ["LAMP_SPRING", "LACOSTE", "LAB2_LEVER", "LAB2_BOX", "LAB2_STOCK_RATE", "lab2_lever"]

#: Task 2.1's lamp arm (kg, m): the lecture's single link with a ZFL spring.
LAMP_SPRING = dict(mass=1.5, length=0.4, b=0.25, c=0.12)
#: Task 2.3's LaCoste lever (N, m).
LACOSTE = dict(weight=20.0, length=0.5, a_x=0.1, b_y=0.25)
#: The lever of lab 2's design task: load ``weight`` (N) at ``length`` (m) and the limits
#: (N/m, m).
LAB2_LEVER = dict(weight=30.0, length=0.6, k_max=400.0, anchor_max=0.35, attach_max=0.6)


def lab2_lever(k: float, a, b, *, W: float | None = None, l: float | None = None,
               free_length: float = 0.0) -> Design:
    """A lever with a load ``W`` at ``(l, 0)`` and one spring from ground point ``b`` to lever point ``a``.

    Parameters
    ----------
    k : float
        Spring rate (N/m), > 0.
    a : (float, float)
        Attachment on the lever, local frame (m).
    b : (float, float)
        Anchor on the ground (m).
    W, l : float, optional
        The load's weight (N) and its distance from the pivot (m); lab 2's design task
        values by default. (The labs call them ``W`` and ``l``.)
    free_length : float
        Free length of the spring (m); 0 for a ZFL spring.

    Returns
    -------
    Design

    Examples
    --------
    >>> lab2_lever(100.0, (0.3, 0.0), (0.0, 0.2)).springs[0].k
    100.0
    """
    W = LAB2_LEVER["weight"] if W is None else W
    l = LAB2_LEVER["length"] if l is None else l
    return lever_design("lab 2 lever", [Load(1, (l, 0.0), (0.0, -W), "W")],
                        [Spring(k, free_length, (0, tuple(b)), (1, tuple(a)), name="k")],
                        labels={"O": (0, (0.0, 0.0)), "a": (1, tuple(a)), "b": (0, tuple(b))}, link="lever")


def _lamp_numbers(rng) -> dict:
    """Task 2.1's lamp arm: the published numbers, or a student's (drawn from ``rng``)."""
    if rng is None:
        return dict(LAMP_SPRING)
    return dict(mass=round(rng.uniform(0.8, 2.5), 2), length=round(rng.uniform(0.28, 0.55), 3),
                b=round(rng.uniform(0.18, 0.32), 3), c=round(rng.uniform(0.08, 0.16), 3))


@register_task("2.1", "spring rate that balances the lamp arm", "k_lamp", "numeric",
               "a number in N/m (or a string like '0.2 N/mm'); accepted within 0.5 %", numbers=_lamp_numbers,
               distinct=(lambda lamp: single_link_spring(**lamp).parameters["k"], 0.015))
def _t21(answer, lamp):
    return numeric(answer, single_link_spring(**lamp).parameters["k"], "stiffness")


def _lever_variant(rng) -> dict:
    """Task 2.2's variant: the load at the fraction ``f`` of ``l`` from the pivot (SymPy text); ``"1"``
    (the load at ``l``, the book's lever) for the published problem."""
    return dict(f=personal_option(rng, "1", ("1/2", "2/3", "3/4", "4/5", "5/4", "4/3")))


@register_task("2.2", "balance conditions of the generalized lever: (a_y, k)", "lever_conditions", "symbolic",
               "a pair (a_y, k) of sympy expressions in W, l, a_x, b_x, b_y for your lever (task_numbers('2.2'): "
               "the load at f l from the pivot); any equivalent form accepted", numbers=_lever_variant)
def _t22(answer, lever):
    import sympy as sp

    if isinstance(answer, dict):
        answer = (answer.get("a_y"), answer.get("k"))
    if isinstance(answer, (str, sp.Basic)) or not hasattr(answer, "__len__") or len(answer) != 2:
        raise AnswerError("The answer should be a pair (a_y, k) of expressions.",
                          "Write it like (a_y_expr, k_expr).")
    # b_x may have either sign (the anchor on either side of the pivot): it is a real symbol
    W, l, ax, by = sp.symbols("W l a_x b_y", positive=True)
    bx = sp.Symbol("b_x", real=True)
    names, f = "W l a_x b_x b_y", sp.Rational(lever["f"])
    ok1, m1, h1 = symbolic(answer[0], -ax * bx / by, names, "your a_y", signed="b_x")
    ok2, m2, h2 = symbolic(answer[1], W * f * l * by / (ax * (bx ** 2 + by ** 2)), names, "your k", signed="b_x")
    return ok1 and ok2, f"{m1} {m2}", h1 or h2


def _lacoste_numbers(rng) -> dict:
    """Task 2.3's LaCoste lever (N, m): :data:`LACOSTE`, or a student's (from ``rng``)."""
    if rng is None:
        return dict(LACOSTE)
    u = lambda lo, hi, nd=3: round(float(rng.uniform(lo, hi)), nd)  # noqa: E731
    return dict(weight=u(10.0, 40.0, 1), length=u(0.3, 0.7), a_x=u(0.05, 0.2), b_y=u(0.15, 0.35))


def _lacoste_energy(lever: dict) -> float:
    """Task 2.3's expected value: the balanced lever's energy, from the library's design."""
    return float(lacoste_lever(**lever).potential_energy(np.zeros(1)).total)


@register_task("2.3", "constant potential energy of the balanced LaCoste lever", "lever_energy", "numeric",
               "a number in J for your lever (task_numbers('2.3'); energies measured from the pivot height, "
               "spring at zero length); accepted within 0.5 %", numbers=_lacoste_numbers,
               distinct=(_lacoste_energy, 0.015))
def _t23(answer, lever):
    return numeric(answer, _lacoste_energy(lever), "energy")


#: The mounting box of the published task 2.4 (m): ``(x_min, x_max, y_min, y_max)`` of the anchor ``b``, and
#: the rate (N/m) of the stock spring that must be used.
LAB2_BOX = (-0.10, -0.05, 0.20, 0.25)
LAB2_STOCK_RATE = 300.0


def _lever_numbers(rng) -> dict:
    """Task 2.4's load (``weight`` N at ``length`` m), the stock spring's rate ``k`` (N/m) and the anchor's
    mounting ``box`` (m): :data:`LAB2_LEVER`'s, or a student's (from ``rng``). A student's rate is that of
    a design with the anchor at the box's centre and ``a_x`` between 0.2 and 0.4 m (not near a round 0.3 m),
    rounded to 5 N/m, so a design within the limits exists, and a catalog lever called with a chosen ``a_x``
    misses the rate."""
    if rng is None:
        return dict(weight=LAB2_LEVER["weight"], length=LAB2_LEVER["length"], k=LAB2_STOCK_RATE, box=LAB2_BOX)
    weight, length = round(float(rng.uniform(20.0, 40.0)), 1), round(float(rng.uniform(0.45, 0.7)), 2)
    x0, y0 = round(float(rng.uniform(-0.15, 0.1)), 3), round(float(rng.uniform(0.15, 0.25)), 3)
    bx, by = x0 + 0.025, y0 + 0.025
    a_x = float(rng.uniform(0.2, 0.28) if rng.random() < 0.5 else rng.uniform(0.32, 0.4))  # not a round 0.3
    k = min(5.0 * round(weight * length * by / (a_x * (bx ** 2 + by ** 2)) / 5.0), LAB2_LEVER["k_max"])
    return dict(weight=weight, length=length, k=k, box=(x0, round(x0 + 0.05, 3), y0, round(y0 + 0.05, 3)))


@register_task("2.4", "a ZFL spring of your stock rate, anchored in your mounting box, that balances the lever "
               "(open design)", "lever_spring", "design",
               "a dict {'k': N/m, 'a': (x, y) on the lever, 'b': (x, y) on the ground} in SI units; k your stock "
               "spring's rate (task_numbers('2.4')['k'], within 0.5 %), b inside your mounting box "
               "(task_numbers('2.4')['box'] = (x_min, x_max, y_min, y_max)), |a| <= 0.6 m; balanced to 0.1 % "
               "with your load (task_numbers('2.4'))", points=2, numbers=_lever_numbers,
               distinct=(lambda load: load["weight"] * load["length"] / load["k"], 0.01))
def _t24(answer, load):
    k, pa, pb = spring(answer)
    p = LAB2_LEVER
    x0, x1, y0, y1 = load["box"]
    cons = [(abs(k / load["k"] - 1) <= 5e-3, f"k is not your stock spring's rate ({load['k']:g} N/m)"),
            (x0 - 1e-12 <= pb[0] <= x1 + 1e-12 and y0 - 1e-12 <= pb[1] <= y1 + 1e-12,
             "anchor b outside your mounting box"),
            (np.hypot(*pa) <= p["attach_max"] + 1e-12,
             f"attachment a farther than {p['attach_max']} m from the pivot")]
    return design_balanced(lab2_lever(k, tuple(pa), tuple(pb), W=load["weight"], l=load["length"]), cons)
