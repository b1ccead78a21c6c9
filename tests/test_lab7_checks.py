"""Lab 7's checks: pure functions of plain answers, judged by the physics of the submitted design."""
from __future__ import annotations

import numpy as np
import pytest

import balancelab as bl
from balancelab.course.check.lab7 import LAB7_LAMP, TASKS, check_lab7, lamp_with_springs
from balancelab.methods.general import free_choices
from balancelab.methods.general.examples import all_pairs, arm_3r, parallelogram_lamp


def test_every_task_has_points_an_answer_form_and_a_check():
    assert sum(t.points for t in TASKS.values()) == 5.0
    for task_id, task in TASKS.items():
        verdict = task.check(None)  # a malformed answer is a verdict, not an exception
        assert verdict.task == task_id and not verdict.correct and verdict.score == 0.0 and verdict.hint


def test_free_choices_and_least_stiffness_of_the_arm():
    arm = arm_3r()
    right = free_choices(arm, springs=all_pairs(arm)).free_choices
    assert check_lab7("7.1", right).correct and check_lab7("7.1", right).score == 1.0
    assert not check_lab7("7.1", right + 1).correct
    assert not check_lab7("7.1", 2.5).correct
    stiff = bl.balance(arm, springs=all_pairs(arm), objective="min_stiffness")
    total = sum(s.k for s in stiff.springs)
    assert check_lab7("7.2", total * 1.002).correct
    assert check_lab7("7.2", f"{total / 1000} kN/m").correct
    assert not check_lab7("7.2", total * 1.05).correct
    verdict = check_lab7("7.2", total * 1.05)
    assert f"{total:.1f}" not in verdict.message + verdict.hint  # never reveals the value


def lecture_springs():
    recipe = bl.lecture.serial_2r_base_springs()
    return [(s.k, (recipe.bodies[s.a.body], s.a.point), (recipe.bodies[s.b.body], s.b.point)) for s in recipe.springs]


def test_the_lectures_springs_and_a_solver_design_pass_the_open_task():
    assert check_lab7("7.3", lecture_springs()).correct
    lamp = parallelogram_lamp()
    box = LAB7_LAMP["box"]
    cands = [(("ground", None), ("link 1", (0.3, 0.0))), (("ground", None), ("copy of link 2", (0.1, 0.0)))]
    mine = bl.balance(lamp, springs=cands, objective="min_stiffness", box=box)
    answer = [(s.k, (lamp.bodies[s.a.body], s.a.point), (lamp.bodies[s.b.body], s.b.point)) for s in mine.springs]
    verdict = check_lab7("7.3", answer)
    assert verdict.correct and verdict.score == TASKS["7.3"].points, verdict


def test_the_open_task_refuses_what_breaks_a_constraint_or_the_balance():
    good = lecture_springs()
    soft = [(k * 1.01, a, b) for k, a, b in good]
    assert not check_lab7("7.3", soft).correct  # not balanced
    stiff = [(k * 2, a, (b[0], (b[1][0] / 2, b[1][1]))) for k, a, b in good]  # balanced, but k > 300 N/m
    assert lamp_with_springs(stiff).balance_report().balanced
    verdict = check_lab7("7.3", stiff)
    assert not verdict.correct and "300" in verdict.message
    high = [(k / 2, ("ground", (0.0, 0.4)), b) for k, a, b in good]  # balanced, anchor outside the box
    assert lamp_with_springs(high).balance_report().balanced
    assert not check_lab7("7.3", high).correct
    assert not check_lab7("7.3", [(100.0, ("ground", (0.0, 0.1)), ("hand", (0.1, 0.0)))]).correct
    assert not check_lab7("7.3", "two springs").correct
    assert not check_lab7("7.3", []).correct
    assert np.isfinite(TASKS["7.3"].points)
