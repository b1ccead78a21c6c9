"""Derive tasks: the library calls a cell that answers one may not make.

A *derive* task (:attr:`~.core.Task.skill`) asks for reasoning the library does not give in one
call. Its answer's form already refuses most shortcuts (a sympy expression in the student's
symbols, where the library returns numbers), and :data:`SHORTCUTS` names the library calls that
would still produce it: :func:`shortcuts` finds them in a cell's source, and
:func:`~.core.check` refuses an answer whose cell makes one (the verdict says which). A call
hidden in another cell or behind an alias is not found: the form of the answer and a person
reading the derivation remain the defence: every derive task is a personal variant of the book's
problem (:func:`~.answers.variant`), so the book's or a docstring's formula, reached by any route,
is wrong for a student with an id.
"""
from __future__ import annotations

import io
import tokenize

__all__ = ["SHORTCUTS", "shortcuts"]

#: For each derive task, the names (functions, methods, parameters) whose use in the answer's
#: cell means the library did the derivation.
SHORTCUTS: dict[str, tuple[str, ...]] = {
    "1.2": ("single_link_counterweight", "balance", "balance_conditions", "solve_counterweights"),
    "2.2": ("balance_conditions", "generalized_lever", "single_link_spring", "balance", "lacoste_lever"),
    "3.4": ("lab2_lever", "lab3_torque_error", "generalized_force", "potential_energy_symbolic",
            "balance_conditions", "approximate_lever", "_free_length_torque"),
    "4.5": ("serial_2r_min_preload", "PE_min", "balance_report", "balance", "singh_fourbar"),
    "5.4": ("fourbar_two_springs", "equivalent_masses", "link_spring", "fourbar_counterweights", "balance",
            "balance_conditions", "_fourbar_rates"),
    "6.4": ("scissors_lift", "lab6_scissors", "balance_conditions", "potential_energy_symbolic", "balance",
            "_stage_rates"),
    "7.5": ("balance", "balance_conditions", "potential_energy_symbolic", "free_choices", "_own_rates"),
    "8.4": ("rate_error_arm", "generalized_force", "balance_report", "potential_energy", "balance"),
    "9.3": ("noncircular_pulley", "potential_energy_symbolic", "balance_conditions", "balance", "_arm_expression"),
}


def shortcuts(task_id: str, source: str) -> list[str]:
    """The disallowed library names a cell's source uses for a derive task (comments and strings ignored).

    Parameters
    ----------
    task_id : str
        The task, e.g. ``"2.2"``; a task without shortcuts gives ``[]``.
    source : str
        The Python source of the cell that stores and checks the answer.

    Returns
    -------
    list of str
        The names found, in the order of :data:`SHORTCUTS`, each once.

    Examples
    --------
    >>> shortcuts("2.2", "conds = lever.balance_conditions()  # not allowed here")
    ['balance_conditions']
    >>> shortcuts("2.2", "a_y = -a_x * b_x / b_y  # no balance_conditions() here")
    []
    >>> shortcuts("2.1", "k = balance(d)")
    []
    """
    names = SHORTCUTS.get(str(task_id), ())
    if not names or not isinstance(source, str):
        return []
    used = set()
    try:
        for tok in tokenize.generate_tokens(io.StringIO(source).readline):
            if tok.type == tokenize.NAME:
                used.add(tok.string)
    except (tokenize.TokenError, IndentationError, SyntaxError):  # an unfinished cell: plain words
        used = set(source.replace(".", " ").replace("(", " ").split())
    return [n for n in names if n in used]
