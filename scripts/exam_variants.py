"""Exam variants of the problem bank: the same problems, each student's own numbers.

Each :class:`Problem` draws its numbers from the labs' seeding
(:func:`balancelab.course.check.core.student_rng`, key ``exam-<name>``), states the problem with
them, and computes its answer with the library (the worked solution names the relation, the
library gives the number, so a stated answer cannot drift from the course). The student's sheet
holds the statements only; the instructor's key adds the worked solutions and answers.
"""
from __future__ import annotations

import math
import re
from dataclasses import dataclass
from pathlib import Path
from typing import Callable

import balancelab as bl
from balancelab.course.check.core import student_key, student_rng
from balancelab.methods.lecture import single_link_counterweight, single_link_spring
from balancelab.methods.realize import negative_free_length_partner
from balancelab.methods.singh import serial_2r_min_preload

G = bl.G


@dataclass(frozen=True)
class Problem:
    """One exam problem: ``numbers(rng)`` draws a student's numbers, ``statement(n)`` states it,
    ``solution(n)`` is the worked solution and ``answer(n)`` the number it arrives at (SI units)."""

    name: str
    kind: str
    numbers: Callable
    statement: Callable
    solution: Callable
    answer: Callable


def _r(rng, lo, hi, nd=3):
    return round(float(rng.uniform(lo, hi)), nd)


PROBLEMS = (
    Problem(
        "lamp-counterweight", "Compute",
        lambda rng: dict(m=_r(rng, 0.5, 2.0, 2), r=_r(rng, 0.3, 0.6), m_l=_r(rng, 0.2, 1.0, 2), m_c=_r(rng, 2.0, 5.0, 2)),
        lambda n: (f"A lamp head of {n['m']} kg sits at the end of a uniform arm of {n['m_l']} kg and length "
                   f"{n['r']} m, pivoted at its other end. How far behind the pivot (m) must a counterweight "
                   f"of {n['m_c']} kg sit so that the arm is balanced in every position?"),
        lambda n: ("The first moments about the pivot cancel: m r + m_l r / 2 = m_c r_c, so "
                   "r_c = r (m + m_l / 2) / m_c."),
        lambda n: single_link_counterweight(mass=n["m"], length=n["r"], counter_mass=n["m_c"],
                                            link_mass=n["m_l"]).parameters["r_c"]),
    Problem(
        "lamp-spring", "Compute",
        lambda rng: dict(m=_r(rng, 0.8, 2.5, 2), r=_r(rng, 0.28, 0.55), b=_r(rng, 0.18, 0.32), c=_r(rng, 0.08, 0.16)),
        lambda n: (f"A lamp of {n['m']} kg at {n['r']} m from the pivot of a massless arm is balanced by a "
                   f"zero-free-length spring from an anchor {n['b']} m straight above the pivot to a point "
                   f"{n['c']} m along the arm. What spring rate (N/m) balances it in every position?"),
        lambda n: ("The spring's energy k (b^2 + c^2 - 2 b c sin(theta)) / 2 must cancel the lamp's m g r sin(theta) "
                   "for every theta: k b c = m g r, so k = m g r / (b c)."),
        lambda n: single_link_spring(mass=n["m"], length=n["r"], b=n["b"], c=n["c"]).parameters["k"]),
    Problem(
        "partner", "Compute",
        lambda rng: dict(k=_r(rng, 200.0, 800.0, 1), l0=_r(rng, 0.025, 0.09, 4), kp=_r(rng, 120.0, 480.0, 1)),
        lambda n: (f"A spring of {n['k']} N/m with a free length of {n['l0']} m is paired, between the same two "
                   f"points, with a spring of {n['kp']} N/m. What free length (m) must the partner have for the "
                   "pair to act as one zero-free-length spring?"),
        lambda n: ("Two springs between the same points pull with k (d - l0) + k' (d - l0'); the pair has zero "
                   "free length when k l0 + k' l0' = 0, so l0' = -k l0 / k' (negative)."),
        lambda n: negative_free_length_partner(k=n["k"], free_length=n["l0"], k_partner=n["kp"])),
    Problem(
        "least-preload", "Derive",
        lambda rng: dict(W1=_r(rng, 4.0, 16.0, 1), W2=_r(rng, 8.0, 30.0, 1), px1=_r(rng, 0.5, 1.5, 2),
                         py1=_r(rng, 0.1, 0.8, 2), px2=_r(rng, 1.0, 3.0, 2), l=_r(rng, 0.8, 2.0, 2)),
        lambda n: (f"A 2R arm carries W1 = {n['W1']} N at ({n['px1']}, {n['py1']}) m on link 1 (local frame) "
                   f"and W2 = {n['W2']} N at ({n['px2']}, 0) m on link 2; link 1 is {n['l']} m long. Derive the "
                   "least constant energy (J, loads' energy measured from the base pivot's height) that any "
                   "balanced version with springs can have, and evaluate it."),
        lambda n: ("Springs store no negative energy, so the constant is at least the loads' largest energy. "
                   "Link 1 contributes a sin(theta1) + b cos(theta1) with a = W1 px1 + W2 l, b = W1 py1, link 2 "
                   "W2 px2 sin(theta1 + theta2); each sinusoid peaks at its amplitude and theta2 is free, so "
                   "PE_min = sqrt(a^2 + b^2) + W2 px2 (Singh & Ananthasuresh)."),
        lambda n: serial_2r_min_preload(weights=(n["W1"], n["W2"]), coms=((n["px1"], n["py1"]), (n["px2"], 0.0)),
                                        length=n["l"], a_x=(1.0, 6.0, -6.0)).parameters["PE_min"]),
    Problem(
        "rate-error", "Derive",
        lambda rng: dict(e=_r(rng, 0.01, 0.05, 4), m1=_r(rng, 0.6, 1.6, 2), m2=_r(rng, 0.6, 1.6, 2),
                         p1=_r(rng, 0.15, 0.3), l1=_r(rng, 0.4, 0.6), th=_r(rng, -60.0, 60.0, 1)),
        lambda n: (f"A 2R lamp arm (m1 = {n['m1']} kg at p1 = {n['p1']} m on link 1, m2 = {n['m2']} kg whose "
                   f"first moment acts at the elbow, l1 = {n['l1']} m) is balanced by a zero-free-length spring "
                   f"on link 1 from an anchor above the shoulder; theta1 is link 1's angle from the horizontal, "
                   f"counter-clockwise. The spring is {100 * n['e']:.2f} % too stiff. Derive the torque (N m) a hand "
                   "must apply to link 1 to hold the arm, dV/dtheta1 (counter-clockwise positive), as a function "
                   f"of theta1, and evaluate it, with its sign, at theta1 = {n['th']} deg."),
        lambda n: ("Only the extra rate e k1 is unbalanced: its energy e k1 (b1^2 + c1^2 - 2 b1 c1 sin(theta1)) / 2 "
                   "has derivative -e k1 b1 c1 cos(theta1), and k1 b1 c1 = g (m1 p1 + m2 l1), so the hand's torque "
                   "is dV/dtheta1 = -e g (m1 p1 + m2 l1) cos(theta1), whatever the spring's mounting: negative "
                   "(clockwise) over the whole range, since the stiff spring lifts the arm and the hand holds it down."),
        lambda n: -n["e"] * G * (n["m1"] * n["p1"] + n["m2"] * n["l1"]) * math.cos(math.radians(n["th"]))),
)


def variant(student: str) -> list[tuple[Problem, dict]]:
    """The problems with ``student``'s numbers (the same on every call and machine; ids are
    case-insensitive, as in the labs: ``Alice`` and ``alice`` get the same numbers)."""
    if not isinstance(student, str) or not re.fullmatch(r"[A-Za-z0-9][A-Za-z0-9.-]*", student.strip()):
        raise ValueError(f"student must be an id of letters, digits, '.' and '-' (as on the roster), got {student!r}")
    return [(p, p.numbers(student_rng(f"exam-{p.name}", student_key(student)))) for p in PROBLEMS]


def sheet(student: str, key: bool = False) -> str:
    """The Markdown exam of ``student``: statements only, or (``key=True``) with worked solutions."""
    title = "Answer key" if key else "Exam"
    lines = [f"# {title}: {student}", ""]
    for i, (p, n) in enumerate(variant(student), start=1):
        lines += [f"## Problem {i} ({p.kind.lower()})", "", p.statement(n), ""]
        if key:
            lines += [f"*Solution.* {p.solution(n)} Answer: {p.answer(n):.6g} (SI units).", ""]
    return "\n".join(lines)


def write_variants(students: list[str], out: Path) -> tuple[Path, Path]:
    """Write ``out/handout/<id>.md`` (for the student) and ``out/key/<id>.md`` (for the instructor)."""
    handout, key = Path(out) / "handout", Path(out) / "key"
    handout.mkdir(parents=True, exist_ok=True)
    key.mkdir(parents=True, exist_ok=True)
    for s in students:
        (handout / f"{s}.md").write_text(sheet(s))
        (key / f"{s}.md").write_text(sheet(s, key=True))
    return handout, key
