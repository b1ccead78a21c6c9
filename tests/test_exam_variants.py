"""Exam variants (issue 21, item 4): each student's numbers from the labs' seeding, solutions only in the key."""
import math
import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT / "scripts"))
import exam_variants as ev  # noqa: E402

G = 9.81


def _by_hand(name, n):
    """Each problem's answer from its numbers, by hand (not through the library call of the key)."""
    if name == "lamp-counterweight":
        return n["r"] * (n["m"] + n["m_l"] / 2) / n["m_c"]
    if name == "lamp-spring":
        return n["m"] * G * n["r"] / (n["b"] * n["c"])
    if name == "partner":
        return -n["k"] * n["l0"] / n["kp"]
    if name == "least-preload":
        return math.hypot(n["W1"] * n["px1"] + n["W2"] * n["l"], n["W1"] * n["py1"]) + n["W2"] * n["px2"]
    if name == "rate-error":  # central difference of the extra spring energy e k1 (b^2 + c^2 - 2 b c sin t) / 2
        k_bc = G * (n["m1"] * n["p1"] + n["m2"] * n["l1"])
        energy = lambda t: n["e"] * k_bc * (-math.sin(t))  # noqa: E731  (the b c-free part, per unit b c)
        t, h = math.radians(n["th"]), 1e-6
        return (energy(t + h) - energy(t - h)) / (2 * h)
    raise KeyError(name)


def _formats(v):
    return {f.format(v) for f in ("{:.4g}", "{:.5g}", "{:.6g}", "{:.4f}")}


@pytest.mark.parametrize("student", ["s001", "alice", "s199"])
def test_every_variant_answer_is_right_and_only_in_the_key(student):
    handout, key = ev.sheet(student), ev.sheet(student, key=True)
    assert "Solution" not in handout and "Answer" not in handout
    for p, n in ev.variant(student):
        value = p.answer(n)
        assert math.isclose(value, _by_hand(p.name, n), rel_tol=1e-6), p.name
        assert f"{value:.6g}" in key
        assert not any(s in handout for s in _formats(value) if len(s.strip("-0.").replace(".", "")) >= 4), (p.name, value)
        assert p.statement(n) in handout and p.solution(n) in key


def test_variants_are_personal_and_reproducible():
    ids = [f"s{i:03d}" for i in range(200)]
    answers = {s: [p.answer(n) for p, n in ev.variant(s)] for s in ids}
    assert answers["s001"] == [p.answer(n) for p, n in ev.variant("s001")]
    for k in range(len(ev.PROBLEMS)):  # few classmates share an answer to within 0.5 %
        close = sum(abs(answers[a][k] / answers[b][k] - 1) <= 0.005 for a in ids for b in ids if a != b)
        assert close / (len(ids) * (len(ids) - 1)) < 0.01, ev.PROBLEMS[k].name
    from balancelab.course.check import task_numbers

    lab = task_numbers("2.1", "s001")  # the exam does not repeat the lab's numbers of the same student
    lamp = dict(ev.variant("s001"))[ev.PROBLEMS[1]]
    assert (lamp["m"], lamp["r"]) != (lab["mass"], lab["length"])


@pytest.mark.parametrize("bad", ["", "  ", "../x", "a/b", 3])
def test_variant_refuses_ids_that_are_not_file_names(bad):
    with pytest.raises(ValueError, match="student"):
        ev.variant(bad)


def test_command_writes_handouts_without_solutions_and_a_key(tmp_path):
    ids = tmp_path / "ids.txt"
    ids.write_text("s001\nalice\n")
    proc = subprocess.run([sys.executable, str(ROOT / "scripts" / "problem_bank.py"), "--variants", str(ids),
                           "--out", str(tmp_path / "exam")], capture_output=True, text=True, timeout=300)
    assert proc.returncode == 0, proc.stderr
    for s in ("s001", "alice"):
        assert (tmp_path / "exam" / "handout" / f"{s}.md").read_text() == ev.sheet(s)
        assert (tmp_path / "exam" / "key" / f"{s}.md").read_text() == ev.sheet(s, key=True)
    assert not any("Solution" in p.read_text() for p in (tmp_path / "exam" / "handout").iterdir())


def test_ids_are_case_insensitive_as_in_the_labs():
    """Attack A21: ``alice`` and ``Alice`` got different exam numbers (and two files that overwrite
    each other on a case-insensitive disk), while the labs treat them as one student."""
    from exam_variants import variant

    assert [n for _, n in variant("Alice")] == [n for _, n in variant("alice")] == [n for _, n in variant(" ALICE ")]


@pytest.mark.parametrize("student", ["s001", "alice", "s199"])
def test_rate_error_answer_is_the_hands_torque_dV_dtheta1(student):
    """Brief c21b item 5: Problem 5's answer is dV/dtheta1, the torque a hand applies to link 1
    (counter-clockwise positive), sign included: the library's generalized force of the lecture's
    lamp arm with the student's numbers and spring 1 too stiff by e, at the student's angle and at
    any elbow angle; the text and the solution say the same."""
    import numpy as np

    from balancelab.core.elements import Spring
    from balancelab.methods.lecture import serial_2r_base_springs
    from balancelab.methods.practice.forces import generalized_force

    (p, n), = [(p, n) for p, n in ev.variant(student) if p.name == "rate-error"]
    assert ev.PROBLEMS.index(p) == 4  # Problem 5 of the sheet
    arm = serial_2r_base_springs(masses=(n["m1"], n["m2"]), length=n["l1"], coms=((n["p1"], 0.0), (0.2, 0.0)),
                                 b=(0.3, 0.25), c=(0.15, 0.1))
    stiff = arm.replace(springs=[Spring(s.k * (1 + n["e"]) if s.name == "k1" else s.k, s.free_length, s.a, s.b,
                                        name=s.name) for s in arm.springs])
    for elbow in (0.0, 0.7, -1.1):
        _, Q = generalized_force(stiff, np.array([[math.radians(n["th"]), elbow]]))
        assert math.isclose(p.answer(n), float(Q[0, 0]), rel_tol=1e-6, abs_tol=1e-12), (elbow, Q)
    assert p.answer(n) < 0  # the stiff spring lifts the arm: the hand pushes clockwise
    assert "dV/dtheta1 (counter-clockwise positive)" in p.statement(n) and "with its sign" in p.statement(n)
    assert "dV/dtheta1 = -e g (m1 p1 + m2 l1) cos(theta1)" in p.solution(n)
