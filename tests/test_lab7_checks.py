"""Lab 7's checks: registered tasks judged from plain answers by the physics of the submitted design."""
from __future__ import annotations

import numpy as np

import balancelab as bl
from balancelab.course.check import check, check_data, encode_answer, tasks
from balancelab.course.check.lab7 import LAB7_LAMP, lab7_arm, lab7_candidates, lamp_with_springs
from balancelab.methods.general import free_choices
from balancelab.methods.general.examples import all_pairs, arm_3r, parallelogram_lamp


def test_every_task_is_registered_with_points_an_answer_form_and_a_variable():
    lab = tasks("lab7")
    assert [t.id for t in lab] == ["7.1", "7.2", "7.3", "7.4", "7.5"]
    assert sum(t.points for t in lab) == 8.0  # labs/README.md's points table
    assert [t.kind for t in lab] == ["numeric", "numeric", "design", "numeric", "symbolic"]
    for t in lab:
        verdict = check(t.id, None)  # a malformed answer is a verdict, not an exception
        assert verdict.task == t.id and not verdict.correct and verdict.score == 0.0 and verdict.hint
        assert t.variable.isidentifier() and t.expects


def test_the_labs_candidates_are_the_chapters_without_one_spring():
    arm = lab7_arm()
    cands = lab7_candidates(arm)
    assert len(cands) == len(all_pairs(arm)) - 1 and all(c in all_pairs(arm) for c in cands)
    assert all({a[0], b[0]} != {"ground", "upper"} for a, b in cands)


def test_free_choices_and_least_stiffness_of_the_arm():
    arm = lab7_arm()
    count = free_choices(arm, springs=lab7_candidates(arm))
    right = count.free_choices
    assert right == count.nvar - count.rank == 3 * len(lab7_candidates(arm)) - count.rank
    assert check("7.1", right).correct and check("7.1", right).score == 1.0
    assert not check("7.1", right + 1).correct
    assert not check("7.1", 2.5).correct
    stiff = bl.balance(arm, springs=lab7_candidates(arm), objective="min_stiffness")
    assert stiff.balance_report().balanced
    total = sum(s.k for s in stiff.springs)
    assert check("7.2", total * 1.002).correct
    assert check("7.2", f"{total / 1000} kN/m").correct
    assert not check("7.2", total * 1.05).correct
    verdict = check("7.2", total * 1.05)
    assert f"{total:.1f}" not in verdict.message + verdict.hint  # never reveals the value


def test_the_chapters_printed_numbers_are_not_the_labs_answers():
    """Chapter 7 prints the free choices and least stiffness of its own arm with all pairs: not accepted here."""
    book_arm = arm_3r()
    book_free = free_choices(book_arm, springs=all_pairs(book_arm)).free_choices
    book_k = sum(s.k for s in bl.balance(book_arm, springs=all_pairs(book_arm), objective="min_stiffness").springs)
    assert not check("7.1", book_free).correct
    assert not check("7.2", book_k).correct


def lecture_springs():
    recipe = bl.lecture.serial_2r_base_springs()
    return [(s.k, (recipe.bodies[s.a.body], s.a.point), (recipe.bodies[s.b.body], s.b.point)) for s in recipe.springs]


def test_the_lectures_springs_and_a_solver_design_pass_the_open_task():
    assert check("7.3", lecture_springs()).correct
    lamp = parallelogram_lamp()
    box = LAB7_LAMP["box"]
    cands = [(("ground", None), ("link 1", (0.3, 0.0))), (("ground", None), ("copy of link 2", (0.1, 0.0)))]
    mine = bl.balance(lamp, springs=cands, objective="min_stiffness", box=box)
    answer = [(s.k, (lamp.bodies[s.a.body], s.a.point), (lamp.bodies[s.b.body], s.b.point)) for s in mine.springs]
    verdict = check("7.3", answer)
    assert verdict.correct and verdict.score == verdict.points == 3.0, verdict
    # the same verdict from plain data, as the grader judges it; body indices work like names
    assert check_data("7.3", encode_answer(answer)) == verdict
    by_index = [(k, (lamp.bodies.index(a), pa), (lamp.bodies.index(b), pb)) for k, (a, pa), (b, pb) in answer]
    assert check("7.3", by_index).correct


def test_the_open_task_refuses_what_breaks_a_constraint_or_the_balance():
    good = lecture_springs()
    soft = [(k * 1.01, a, b) for k, a, b in good]
    assert not check("7.3", soft).correct  # not balanced
    stiff = [(k * 2, a, (b[0], (b[1][0] / 2, b[1][1]))) for k, a, b in good]  # balanced, but k > 300 N/m
    assert lamp_with_springs(stiff).balance_report().balanced
    verdict = check("7.3", stiff)
    assert not verdict.correct and "300" in verdict.message
    high = [(k / 2, ("ground", (0.0, 0.4)), b) for k, a, b in good]  # balanced, anchor outside the box
    assert lamp_with_springs(high).balance_report().balanced
    assert not check("7.3", high).correct
    negative = [(-k, a, b) for k, a, b in good]
    assert "positive" in check("7.3", negative).message
    assert not check("7.3", [(100.0, ("ground", (0.0, 0.1)), ("hand", (0.1, 0.0)))]).correct
    assert not check("7.3", "two springs").correct
    assert not check("7.3", []).correct
    assert np.isfinite(tasks("lab7")[2].points)


def test_the_slider_task_is_judged_by_the_mechanism_and_not_by_the_chapters_numbers():
    """7.4: the slider carries no moment (a level guide), the crank carries its own weight and the rod's
    share at its tip; the least counterweight sits at the box's edge, 0.5 m behind the pivot."""
    from balancelab.course.check.lab7 import LAB7_SLIDER, lab7_slider_crank

    v = LAB7_SLIDER
    moment = v["crank_mass"] * v["crank"] / 2 + v["rod_mass"] * (1 - v["rod_com"] / v["rod"]) * v["crank"]
    right = moment / v["box"][0][1]
    assert check("7.4", right).correct and check("7.4", f"{right * 1000:.3f} g").correct
    assert not check("7.4", moment / 0.6).correct  # the chapter's box, not the lab's
    assert not check("7.4", right * 9.81).correct
    d = lab7_slider_crank()
    out = bl.balance(d, counterweights=[("crank", (-v["box"][0][1], 0.0))])
    assert abs(out.parameters["counter_mass1"] - right) < 1e-9 * right and out.balance_report().balanced
