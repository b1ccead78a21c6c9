"""Lab 7, balance your own linkage: formative checks as pure functions on plain data.

Self-contained on purpose: the tasks are *not* entered in the shared task registry of
:mod:`.core` (the grading pipeline is being rewritten); :data:`TASKS` maps each task id to
its points, what an answer looks like and its check, a pure function ``check(answer) ->
Verdict`` that builds everything it needs from the answer (plain numbers, strings and
tuples) and the library, never prints the expected value and never raises.

* 7.1: free choices left by the all-pairs candidates on the 3R lamp arm of chapter 7;
* 7.2: the least total stiffness of that arm (the solver's ``"min_stiffness"``);
* 7.3 (open design): springs for the parallelogram desk lamp that fit the constraints of
  :data:`LAB7_LAMP` (at most three ZFL springs from the base, anchors in a box, rates
  limited), checked by building the design and running its balance report.
"""
from __future__ import annotations

import functools
from typing import Any, Callable, NamedTuple

from ...methods.general import balance, free_choices
from ...methods.general.examples import all_pairs, arm_3r, parallelogram_lamp
from .answers import design_balanced, numeric, point, quantity
from .core import AnswerError, Verdict

__all__ = ["LAB7_LAMP", "Lab7Task", "TASKS", "check_lab7", "lamp_with_springs"]

#: The open design task's constraints: anchors (on the ground) in ``box`` (m), rates up to ``k_max`` (N/m).
LAB7_LAMP = dict(box=((-0.15, 0.15), (0.0, 0.3)), k_max=300.0, max_springs=3)


class Lab7Task(NamedTuple):
    """One task: its points, what an answer looks like, and its check ``answer -> Verdict``."""

    points: float
    expects: str
    check: Callable[[Any], Verdict]


@functools.lru_cache(maxsize=None)
def _arm_numbers() -> tuple[int, float]:
    arm = arm_3r()
    cands = all_pairs(arm)
    left = free_choices(arm, springs=cands).free_choices
    stiff = balance(arm, springs=cands, objective="min_stiffness")
    return left, float(sum(s.k for s in stiff.springs))


def _verdict(task: str, judged: tuple[bool, str, str]) -> Verdict:
    correct, message, hint = judged
    points = TASKS[task].points
    return Verdict(task, bool(correct), message, "" if correct else hint, points if correct else 0.0, points)


def _guarded(task: str, judge: Callable[[Any], tuple[bool, str, str]]) -> Callable[[Any], Verdict]:
    """A check that turns a malformed answer (or a crash while building it) into a verdict."""

    def check(answer):
        try:
            return _verdict(task, judge(answer))
        except AnswerError as err:
            return _verdict(task, (False, str(err), err.hint or TASKS[task].expects))
        except (ValueError, TypeError, ArithmeticError) as err:
            return _verdict(task, (False, f"This answer could not be used: {err}", "Read what the task expects."))

    check.__name__ = f"check_{task.replace('.', '_')}"
    check.__doc__ = f"Check an answer to task {task}; returns a Verdict."
    return check


def _t71(answer):
    value = quantity(answer, "ratio", "the number of free choices")
    if value != int(value):
        raise AnswerError("A number of free choices is a whole number.", "Unknowns minus the rank.")
    expected = _arm_numbers()[0]
    if int(value) == expected:
        return True, "Right: that many independent directions keep the arm balanced.", ""
    return False, "Not the number of free choices.", "Use free_choices(arm, springs=candidates)."


def _t72(answer):
    return numeric(answer, _arm_numbers()[1], "stiffness")


def lamp_with_springs(springs) -> Any:
    """The parallelogram lamp of chapter 7 with ``springs`` as ``(k, (body, (x, y)), (body, (x, y)))`` ZFL springs.

    Examples
    --------
    >>> d = lamp_with_springs([(183.9375, ("ground", (0.0, 0.2)), ("link 1", (0.2, 0.0))),
    ...                        (122.625, ("ground", (0.0, 0.2)), ("copy of link 2", (0.1, 0.0)))])
    >>> d.balance_report().balanced
    True
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
        built.append((quantity(k, "stiffness", f"k of spring {i + 1}"), ends[0], ends[1]))
    from ...core.elements import Spring

    return lamp.replace(springs=[Spring(k, 0.0, a, b, name=f"k{i + 1}") for i, (k, a, b) in enumerate(built)])


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


TASKS: dict[str, Lab7Task] = {
    "7.1": Lab7Task(1.0, "a whole number", _guarded("7.1", _t71)),
    "7.2": Lab7Task(1.0, "a number in N/m (or with a unit); accepted within 0.5 %", _guarded("7.2", _t72)),
    "7.3": Lab7Task(3.0, "a list of up to 3 springs (k, (body, (x, y)), (body, (x, y))), each from the ground "
                    "with its anchor in -0.15 <= x <= 0.15 m, 0 <= y <= 0.3 m and k <= 300 N/m; balanced",
                    _guarded("7.3", _t73)),
}


def check_lab7(task: str, answer: Any) -> Verdict:
    """Check ``answer`` to lab 7's task ``task`` (``"7.1"`` ...); a Verdict, never an exception.

    Examples
    --------
    >>> check_lab7("7.1", "seven").correct
    False
    >>> check_lab7("7.9", 1).message
    "There is no task '7.9' in lab 7 (tasks: ['7.1', '7.2', '7.3'])."
    """
    if task not in TASKS:
        return Verdict(str(task), False, f"There is no task {task!r} in lab 7 (tasks: {sorted(TASKS)}).", "", 0.0, 0.0)
    return TASKS[task].check(answer)
