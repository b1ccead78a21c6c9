"""The core of the answer checks: verdicts and the task registry.

:func:`register_task` is how a lab module (``lab1`` ... ``lab9``) declares a task and its
judge; :func:`check` runs the judge on a student's answer and turns whatever happens
(right, wrong, malformed, a crash) into a :class:`Verdict`. Reading and judging answers
is :mod:`.answers`' job.
"""
from __future__ import annotations

import functools
from dataclasses import dataclass, field
from typing import Any, Callable

from ...core.errors import AnswerError
from .data import Unreadable, decode_answer, encode_answer
from .derive import shortcuts

__all__ = ["Verdict", "AnswerError", "Task", "SKILLS", "register_task", "tasks", "lab_tasks", "explain", "check", "check_data", "set_student",
           "task_numbers", "student_key", "student_rng"]


@dataclass(frozen=True)
class Verdict:
    """The outcome of one check.

    Attributes
    ----------
    task : str
        Task id, e.g. ``"2.1"``.
    correct : bool
        Whether the answer is accepted.
    message : str
        What was found (never the expected value).
    hint : str
        What to look at next (empty when correct).
    score : float
        Points earned (0 or the task's points).
    points : float
        Points the task is worth.

    Examples
    --------
    >>> v = Verdict("2.1", False, "Not within 0.5 % of the expected value.", "Did you forget g?")
    >>> bool(v), v.score
    (False, 0.0)
    """

    task: str
    correct: bool
    message: str
    hint: str = ""
    score: float = 0.0
    points: float = 1.0

    def __bool__(self) -> bool:
        return self.correct

    def __str__(self) -> str:
        head = "✔ correct" if self.correct else "✘ not yet"
        text = f"Task {self.task}: {head}. {self.message}"
        if self.hint and not self.correct:
            text += f"\n  Hint: {self.hint}"
        return text

    __repr__ = __str__


@dataclass(frozen=True)
class Task:
    """One task of a lab.

    Attributes
    ----------
    id : str
        ``"<lab>.<n>"``, e.g. ``"1.3"``.
    lab : str
        ``"lab1"`` ... ``"lab8"``.
    title : str
        One line saying what is asked.
    variable : str
        Name of the notebook variable holding the answer (what the grader reads).
    kind : str
        The answer's form: ``"numeric"``, ``"symbolic"`` or ``"design"``.
    expects : str
        What an answer looks like, with units and tolerance.
    judge : callable
        ``judge(answer) -> (correct, message, hint)``; may raise :class:`AnswerError`.
    points : float
        Points the task is worth.
    numbers : callable, optional
        For a task with personal numbers: ``numbers(rng)`` draws a student's numbers (a dict)
        from a seeded generator, ``numbers(None)`` gives the published ones; the judge is
        then called as ``judge(answer, numbers)``.
    skill : str
        The work the task asks for (:data:`SKILLS`): ``"compute"`` (a number the chapter's relations
        or the library give), ``"derive"`` (reasoning no single library call gives: a symbolic
        result, a prediction, a sign with its reason) or ``"design"`` (choose free parameters
        under constraints; many right answers). By default ``"derive"`` for a symbolic answer,
        ``"design"`` for a design and ``"compute"`` for a number.
    distinct : (callable, float), optional
        ``(value, rel)``: a student's numbers are drawn again (up to 50 times) until ``value(numbers)``
        differs from ``value`` of the published numbers by more than ``rel`` (relative), so that the
        published answer is wrong for every student.

    Examples
    --------
    >>> t = tasks("lab2")[0]
    >>> t.id, t.variable, t.kind, t.skill
    ('2.1', 'k_lamp', 'numeric', 'compute')
    """

    id: str
    lab: str
    title: str
    variable: str
    kind: str
    expects: str
    judge: Callable[..., tuple[bool, str, str]] = field(repr=False, compare=False)  # (answer[, numbers])
    points: float = 1.0
    numbers: Callable | None = field(default=None, repr=False, compare=False)
    distinct: tuple | None = field(default=None, repr=False, compare=False)
    skill: str = "compute"


#: The kinds of work a task asks for (:attr:`Task.skill`).
SKILLS = ("compute", "derive", "design")
_DEFAULT_SKILL = {"numeric": "compute", "symbolic": "derive", "design": "design"}

_TASKS: dict[str, Task] = {}


def register_task(id: str, title: str, variable: str, kind: str, expects: str,
                  points: float = 1.0, numbers: Callable | None = None, distinct: tuple | None = None,
                  skill: str | None = None) -> Callable:
    """Decorator declaring a task: the decorated function is its judge.

    A judge takes the student's answer and returns ``(correct, message, hint)`` (the
    helpers of :mod:`.answers` build those) or raises :class:`AnswerError` for a malformed answer.

    Parameters
    ----------
    id : str
        ``"<lab>.<n>"``, e.g. ``"2.4"``; registering an id again replaces the task.
    title, variable, kind, expects, points, numbers, distinct, skill
        As in :class:`Task` (``skill`` follows from ``kind`` when omitted).

    Returns
    -------
    callable
        The decorator; it returns the judge unchanged.

    Examples
    --------
    >>> @register_task("99.1", "the answer to everything", "x", "numeric", "the number 42")
    ... def _judge(answer):
    ...     return answer == 42, "Checked.", "Try 42."
    >>> check("99.1", 42).correct, check("99.1", 41).hint
    (True, 'Try 42.')
    >>> _ = _TASKS.pop("99.1")
    """
    if kind not in ("numeric", "symbolic", "design"):
        raise ValueError(f"kind must be 'numeric', 'symbolic' or 'design', got {kind!r}")
    skill = _DEFAULT_SKILL[kind] if skill is None else skill
    if skill not in SKILLS:
        raise ValueError(f"skill must be one of {', '.join(map(repr, SKILLS))}, got {skill!r}")

    def register(fn):
        _TASKS[id] = Task(id, "lab" + id.split(".")[0], title, variable, kind, expects, fn, points, numbers, distinct,
                          skill)
        return fn

    return register


def tasks(lab: str | int | None = None) -> list[Task]:
    """The registered tasks, in order, optionally of one lab.

    Parameters
    ----------
    lab : str or int, optional
        ``"lab2"``, ``"2"`` or ``2``; all labs when omitted.

    Returns
    -------
    list of Task

    Examples
    --------
    >>> [t.id for t in tasks(2)][:2]
    ['2.1', '2.2']
    """
    order = sorted(_TASKS.values(), key=lambda t: tuple(int(x) for x in t.id.split(".")))
    if lab is None:
        return order
    key = str(lab)
    key = key if key.startswith("lab") else "lab" + key
    return [t for t in order if t.lab == key]


lab_tasks = tasks


_STUDENT = {"id": ""}
#: How many times :func:`check` ran on each task in this kernel (exported with the answers; the
#: grade table reports it per task, as the notebook's kernel counted it).
ATTEMPTS: dict[str, int] = {}


def student_key(student_id: str) -> str:
    """The one normal form of a student id: surrounding spaces dropped, letters in lower case.

    Ids are case-insensitive everywhere: personal numbers are drawn for this form, and the
    grader compares ids (file name, roster, the notebook's ``STUDENT_ID``) in this form, so
    ``Alice_lab1.ipynb`` and ``alice_lab1.ipynb`` are the same student.

    Parameters
    ----------
    student_id : str
        An id as written anywhere (file name, roster, notebook).

    Returns
    -------
    str

    Examples
    --------
    >>> student_key("  Alice ") == student_key("alice") == "alice"
    True
    """
    if not isinstance(student_id, str):
        raise TypeError(f"student_id must be a string, got {type(student_id).__name__}")
    return student_id.strip().lower()


def set_student(student_id: str) -> None:
    """Set the student whose personal numbers :func:`task_numbers` and :func:`check` use.

    Parameters
    ----------
    student_id : str
        The id the instructor gave (as in the submission's file name); ``""`` for the
        published numbers.

    Examples
    --------
    >>> set_student("")
    >>> task_numbers("2.1")["mass"]
    1.5
    """
    if not isinstance(student_id, str):
        raise TypeError(f"student_id must be a string, got {type(student_id).__name__}")
    _STUDENT["id"] = student_key(student_id)


def task_numbers(task_id: str, student: str | None = None) -> dict:
    """The numbers of a task: the published ones, or a student's personal ones (seeded by the id).

    Parameters
    ----------
    task_id : str
        E.g. ``"2.1"``.
    student : str, optional
        The student id; the one of :func:`set_student` by default. ``""``: published numbers.

    Returns
    -------
    dict
        Empty for a task without numbers of its own.

    Examples
    --------
    >>> task_numbers("2.1", "") == task_numbers("2.1", "")
    True
    >>> task_numbers("2.1", "s1234") == task_numbers("2.1", "s1234") != task_numbers("2.1", "s9876")
    True
    """
    t = _TASKS.get(str(task_id))
    if t is None or t.numbers is None:
        return {}
    student = _STUDENT["id"] if student is None else student_key(str(student))
    return dict(_drawn(t.id, student))


def student_rng(key: str, student: str) -> Any:
    """The random generator of one student for one key: the seeding of every personal number.

    Parameters
    ----------
    key : str
        What the numbers are for: a task id (``"3.1"``) or, for an exam variant, its own key
        (``"exam-lamp"``), so that no two keys share numbers.
    student : str
        The student id.

    Returns
    -------
    numpy.random.Generator
        Seeded by the SHA-256 of ``"balancelab:<key>:<student>"``: the same for the same pair,
        on every machine.

    Examples
    --------
    >>> float(student_rng("exam-lamp", "s1").uniform()) == float(student_rng("exam-lamp", "s1").uniform())
    True
    """
    import hashlib

    import numpy as np

    seed = int.from_bytes(hashlib.sha256(f"balancelab:{key}:{student}".encode()).digest()[:8], "big")
    return np.random.default_rng(seed)


@functools.lru_cache(maxsize=4096)
def _drawn(task_id: str, student: str) -> dict:
    """A task's numbers for ``student`` (cached: a ``distinct`` draw may compute answers)."""
    t = _TASKS[task_id]
    if t.numbers is None:
        raise ValueError(f"task_id: task {task_id} has no personal numbers")
    draw = t.numbers
    if not student:
        return dict(draw(None))
    rng = student_rng(t.id, student)
    mine = dict(draw(rng))
    if t.distinct is not None:
        value, rel = t.distinct
        published = value(draw(None))
        for _ in range(50):
            if abs(value(mine) / published - 1) > rel:
                break
            mine = dict(draw(rng))
    return mine


def explain(task_id: str) -> str:
    """What a task asks and what an answer looks like (units, tolerance).

    Parameters
    ----------
    task_id : str
        E.g. ``"2.1"``.

    Returns
    -------
    str

    Examples
    --------
    >>> print(explain("1.1").splitlines()[0])
    Task 1.1 (compute): distance of the counterweight from the pivot
    """
    t = _TASKS.get(str(task_id))
    if t is None:
        raise KeyError(f"no task {task_id!r}; tasks are {', '.join(t.id for t in tasks())}")
    return f"Task {t.id} ({t.skill}): {t.title}\n  store your answer in `{t.variable}`: {t.expects}"


def check(task_id: str, answer: Any) -> Verdict:
    """Check a student's answer to one task.

    Parameters
    ----------
    task_id : str
        The task, e.g. ``"2.1"`` (see :func:`tasks`).
    answer : object
        The answer in the form the task states (:func:`explain`).

    Returns
    -------
    Verdict
        Prints as a one-line verdict with a hint; ``bool(verdict)`` is whether it is right.
        Never raises for a malformed answer. A derive task's answer is refused when the cell
        that checks it calls a library shortcut (:mod:`.derive`). Each call is counted (:data:`ATTEMPTS`): the
        grade table shows how many checks a notebook ran per task.

    Examples
    --------
    >>> check("2.1", "12 apples").correct
    False
    >>> print(check("1.1", float("nan")))
    Task 1.1: ✘ not yet. The answer is NaN or infinite; give a finite number.
      Hint: Store a plain number in m or a string such as '2.5 m'.
    """
    found = shortcuts(str(task_id), _cell_source())
    if found and str(task_id) in _TASKS:
        t = _TASKS[str(task_id)]
        ATTEMPTS[t.id] = ATTEMPTS.get(t.id, 0) + 1
        return Verdict(t.id, False, f"Task {t.id} is to be derived by hand, and this cell calls "
                       f"{', '.join(found)}: the library may confirm your result in another cell, not give it.",
                       t.expects, 0.0, t.points)
    try:
        data = encode_answer(answer)
    except (RecursionError, OverflowError, MemoryError, ValueError, TypeError) as err:  # never raise at a student
        data = {"other": f"answer that cannot be read ({type(err).__name__})"}
    return check_data(task_id, data)  # counted there


def _cell_source() -> str:
    """The source of the notebook cell running now (IPython's ``In[-1]``), or ``""`` outside IPython."""
    try:
        from IPython import get_ipython

        shell = get_ipython()
        history = shell.user_ns.get("In") if shell is not None else None
        return str(history[-1]) if history else ""
    except Exception:  # no IPython, or a history we cannot read: nothing to inspect
        return ""


def check_data(task_id: str, data: Any, student: str | None = None) -> Verdict:
    """Check an answer given as plain data (:func:`~.data.encode_answer`): what the grader does.

    :func:`check` is ``check_data(task_id, encode_answer(answer))``, so the formative check in
    the notebook and the trusted grader run the same judge on the same data. The score is
    never more than the task's points. Each call is counted (:data:`ATTEMPTS`), as one of
    :func:`check` is.

    Parameters
    ----------
    task_id : str
        The task, e.g. ``"2.1"``.
    data : dict
        The encoded answer (e.g. read from the JSON a notebook exported).
    student : str, optional
        Whose personal numbers to judge with (:func:`task_numbers`).

    Returns
    -------
    Verdict

    Examples
    --------
    >>> check_data("2.1", {"str": "12 N/m"}).message
    'Not within 0.5 % of the expected value.'
    >>> check_data("2.1", {"other": "Verdict"}).message
    'Your answer is a Verdict, which cannot be graded: store the answer itself.'
    """
    t = _TASKS.get(str(task_id))
    if t is not None:  # every check path is counted (check calls this)
        ATTEMPTS[t.id] = ATTEMPTS.get(t.id, 0) + 1
    if t is None:
        return Verdict(str(task_id), False, f"There is no task {task_id!r}.",
                       f"Tasks are: {', '.join(t.id for t in tasks())}.", 0.0, 0.0)
    answer = decode_answer(data)
    if answer is Ellipsis:
        return Verdict(t.id, False, "No answer yet.", f"Replace the `...` in `{t.variable} = ...`: {t.expects}.",
                       0.0, t.points)
    if isinstance(answer, Unreadable):
        return Verdict(t.id, False, f"Your answer is {_article(answer.what)}, which cannot be graded: "
                       "store the answer itself.", t.expects, 0.0, t.points)
    try:
        ok, message, hint = t.judge(answer, task_numbers(t.id, student)) if t.numbers else t.judge(answer)
    except AnswerError as e:
        ok, message, hint = False, str(e), e.hint or t.expects
    except Exception as e:  # a check must never crash the student's notebook
        ok, message, hint = (False, f"Your answer could not be checked ({type(e).__name__}).",
                             t.expects)
    return Verdict(t.id, bool(ok), message, hint, float(t.points) if bool(ok) else 0.0, float(t.points))


def _article(what: str) -> str:
    return what if " " in what else ("an " if what[:1].lower() in "aeiou" else "a ") + what
