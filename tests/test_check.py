"""Answer checks: right answers pass (from an independent route), wrong ones fail, nothing leaks."""
import math

import numpy as np
import pytest
import sympy as sp

import balancelab as bl
import balancelab.methods.lustig  # noqa: F401  (bl.lustig)
from balancelab.methods.singh.peaucellier import peaucellier_board
from balancelab.methods.singh.scissors import scissors_lift
from conftest import lab8_reference_springs
from balancelab.course import check as ck
from balancelab.course.check import Verdict, check, explain, tasks
from balancelab.course.check import core, answers, lab1, lab2, lab3, lab4, lab5, lab6, lab7, lab8, lab9
from balancelab.methods.lecture.fourbar import fourbar_counterweights

# ----------------------------------------------------------------- expected answers, derived by
# an independent route: by hand where a check asks the library, through another method of the
# library (or another quantity of the same design) where a check's answer is the library's


def _task(tid):
    return {t.id: t for t in tasks()}[tid]


def _lamp_r_c():
    # first moment about the pivot: m r + m_l r / 2 = m_c r_c
    return (1.2 * 0.45 + 0.6 * 0.45 / 2) / 3.0


def _lab1_counterweights(m_c2, m_c4):
    p = ck.LAB1_FOURBAR
    d = fourbar_counterweights(A=p["A"], B=p["B"], crank=p["crank"], coupler=p["coupler"], rocker=p["rocker"],
                               masses=p["masses"], coms=p["coms"], counter_masses=(m_c2, m_c4))
    q = d.parameters
    return {"crank": (m_c2, (q["cw2_x"], q["cw2_y"])), "rocker": (m_c4, (q["cw4_x"], q["cw4_y"]))}


def _equivalent():
    # same mass, same first moment about the coupler's joint with the crank
    p = ck.LAB1_FOURBAR
    m3, g3 = p["masses"][1], p["coms"][1][0]
    m_C = m3 * g3 / p["coupler"]
    return (m3 - m_C, m_C)


def _lever_conditions():
    """(a_y, k) of the generalized lever from Design.balance_conditions (sympy)."""
    d = bl.singh.generalized_lever(weight=10.0, length=0.5, a_x=0.2, b_x=0.1, b_y=0.3)
    W, l, ax, ay, bx, by, k = sp.symbols("W l a_x a_y b_x b_y k", positive=True)
    eqs = [sp.sympify(e.lhs).subs({s: sp.Symbol(str(s), positive=True) for s in e.lhs.free_symbols})
           for e in d.balance_conditions()]
    ay_r = sp.Symbol("a_y", real=True)
    eqs = [e.subs(sp.Symbol("a_y", positive=True), ay_r) for e in eqs]
    eqs = [e.subs({s: sp.Symbol(str(s), real=True) for s in e.free_symbols if str(s) == "a_y"}) for e in eqs]
    sol = sp.solve(eqs, [ay_r, k], dict=True)
    sol = [s for s in sol if s[k] != 0][0]
    return sol[ay_r], sol[k]


def _pulley_radius(mass=2.0, length=0.5, b=0.3, c=0.2):
    """Bisection on the exact pulley model (a route independent of the check's root finder)."""
    from balancelab.methods.realize import pulley_balance_error, pulley_lever

    lo, hi = 1e-5, min(0.05, 0.9 * (b - c))  # the pulley stays above the attachment
    for _ in range(40):
        mid = (lo + hi) / 2
        lever = pulley_lever(mass=mass, length=length, b=b, c=c, radius=mid)
        err = pulley_balance_error(lever).residual_torque / (mass * bl.G * length)
        lo, hi = (mid, hi) if err < 0.01 else (lo, mid)
    return (lo + hi) / 2


def _pulley_radius_by_ratio(mass, length, b, c):
    """The same radius by fixed-point steps r <- r * 1 % / error(r): the error grows almost in proportion
    to the radius, so a few steps converge (another route than the check's root finder, and faster
    than bisection for the 200 levers of the classmate test)."""
    from balancelab.methods.realize import pulley_balance_error, pulley_lever

    radius = 0.2 * (b - c) * 0.05
    for _ in range(30):
        lever = pulley_lever(mass=mass, length=length, b=b, c=c, radius=radius)
        ratio = pulley_balance_error(lever).residual_torque / (mass * bl.G * length) / 0.01
        if abs(ratio - 1) < 1e-6:
            break
        radius = min(radius / ratio, 0.9 * (b - c))
    return radius


def _approximate_spring(**kw):
    from balancelab.methods.realize import approximate_lever

    p = approximate_lever(mass=2.0, length=0.5, free_length=0.1, **kw).parameters
    return {"k": p["k"], "a": (p["a_x"], p["a_y"]), "b": (p["b_x"], p["b_y"])}


def _parallelogram_rates():
    g = bl.G
    return (g * (1.2 * 0.2 + 0.8 * 0.45) / (0.15 * 0.1), g * 0.8 * 0.3 / (0.12 * 0.1))


def _crank_rate():
    # lecture: M2 = m2 p2 + m3 (1 - c) r2 with c = (p3x + i p3y) / r3, k = g |M2| / (b c)
    c = complex(0.4, 0.1) / 0.8
    M2 = 1.0 * 0.15 + 2.0 * (1 - c) * 0.3
    return bl.G * abs(M2) / (0.2 * 0.15)


def _lab7_free_choices():
    """Unknowns minus the rank of the balance conditions, from the solver's own problem statement."""
    from balancelab.methods.general import free_choices

    arm = lab7.lab7_arm()
    count = free_choices(arm, springs=lab7.lab7_candidates(arm))
    return count.nvar - count.rank


def _lab7_least_stiffness(numbers=None):
    arm = lab7.lab7_arm(numbers)
    softest = bl.balance(arm, springs=lab7.lab7_candidates(arm), objective="min_stiffness")
    assert softest.balance_report().balanced
    return sum(s.k for s in softest.springs)


def _lab7_lamp_springs():
    # the lecture's own lamp arm (both springs at the base), written as plain numbers
    recipe = bl.lecture.serial_2r_base_springs()
    return [(s.k, (recipe.bodies[s.a.body], s.a.point), (recipe.bodies[s.b.body], s.b.point))
            for s in recipe.springs]



def _lab8_study():
    from balancelab.methods.practice import tolerance

    springs = lab8_reference_springs()
    study = tolerance.monte_carlo(lab8.built_arm(springs), lab8.LAB8_TOLERANCES, n=3000, grid=15, seed=2024)
    return {"springs": springs, "quantile": study.quantile(0.95)}


def _lab8_shoulder_torque():
    # 2 % of k1 b1 c1 = 2 % of g (m1 p1 + m2 l1): the spring's extra pull at theta_1 = 0, by hand
    return 0.02 * bl.G * (1.0 * 0.25 + 1.0 * 0.5)


def _lab9_pulley(min_tension=45.0):
    """The published link's pulley, made by the library; the judge winds the cable on its points itself."""
    from balancelab.methods.practice.springs import ExtensionSpring

    real = ExtensionSpring(3e-3, 24e-3, 60, initial_tension=40.0)
    link = bl.lecture.single_link_spring(2.0, 0.5, 0.3, 0.2)
    d = bl.realize.noncircular_pulley(link, spring_model=real, angle_range=(-math.pi / 3, math.pi / 3),
                                      min_tension=min_tension, eyelet=(0.0, 0.3))
    pitch, clamp = bl.realize.profile_part(d, n=400).pitch, d.springs[0].b.point
    if np.hypot(*(pitch[0] - clamp)) < np.hypot(*(pitch[-1] - clamp)):
        pitch = pitch[::-1]
    return {"spring": {"d": 3e-3, "D": 24e-3, "Na": 60, "F_i": 40.0}, "points": pitch,
            "cable_length": d.springs[0].cable.cable_length, "turn": d.springs[0].cable.turn}


def _lab9_tension_by_hand(m: float, r: float) -> float:
    from balancelab.methods.practice.springs import ExtensionSpring

    k = ExtensionSpring(3e-3, 24e-3, 60, initial_tension=40.0).k   # the rate is chapter 8's, not the task
    return math.sqrt(45.0 ** 2 + 2 * k * m * bl.G * r * math.sqrt(3))


def _lab9_largest_tension():
    # T_max^2 = T_min^2 + 2 k (V(60°) - V(-60°)), V = m g r sin(theta), by hand
    from balancelab.methods.practice.springs import ExtensionSpring

    k = ExtensionSpring(3e-3, 24e-3, 60, initial_tension=40.0).k   # the rate is chapter 8's, not the task
    return math.sqrt(45.0 ** 2 + 2 * k * 2.0 * bl.G * 0.5 * math.sqrt(3))


RIGHT = {
    "1.1": lambda: _lamp_r_c(),
    "1.2": lambda: sp.sympify("r*(2*m + m_l)/(2*m_c)"),
    "1.3": _equivalent,
    "1.4": lambda: _lab1_counterweights(2.0, 2.0),
    "2.1": lambda: 1.5 * bl.G * 0.4 / (0.25 * 0.12),  # k = m g r / (b c)
    "2.2": _lever_conditions,
    "2.3": lambda: bl.singh.lacoste_lever(weight=20.0, length=0.5, a_x=0.1, b_y=0.25).parameters["PE"],
    # the stock rate 300 N/m, the anchor at the box's centre: a_x = W l b_y / (k |b|^2), a_y = -a_x b_x / b_y
    "2.4": lambda: {"k": 300.0, "a": (0.24, 0.08), "b": (-0.075, 0.225)},
    "3.1": _pulley_radius,
    "3.2": lambda: -400.0 * 0.05 / 250.0,
    "3.3": _approximate_spring,
    # the free length's part -k l_0 d of the spring's energy, d = sqrt(b^2 + c^2 - 2 b c sin(theta)), k b c = m g r
    "3.4": lambda: sp.sympify("m*g*r*l_0*cos(theta)/sqrt(b**2 + c**2 - 2*b*c*sin(theta))"),
    "4.1": _parallelogram_rates,
    "4.2": lambda: float(np.hypot(10.0 * 1.0 + 20.0 * 1.5, 10.0 * 0.5) + 20.0 * 2.0),
    "4.3": lambda: {"a_x": (1.4, 1.5, -1.5)},
    "4.4": lambda: bl.lustig.lustig_table3e_case(1).parameters["k1"],
    # the 2R's largest load energy: amplitude of link 1's sinusoid plus link 2's, by hand
    "4.5": lambda: sp.sympify("sqrt(W_1**2*p_x1**2 + 2*W_1*W_2*l*p_x1 + W_2**2*l**2 + W_1**2*p_y1**2) + W_2*p_x2"),
    "5.1": _crank_rate,
    "5.2": lambda: float(np.hypot(40.0, 5.0) + 40.0 + 10.0 * 0.5),
    "5.3": lambda: {"base": "A", "h": 0.15},
    # the lecture's numbering (crank 2, coupler 3, rocker 4): the coupler's mass split m_3 (1 - r_3/l_3) at D
    # and m_3 r_3/l_3 at C, each link then a single link with k b c = g M
    "5.4": lambda: sp.sympify(("g*(m_2*r_2 + m_3*(1 - r_3/l_3)*l_2)/(b_A*c_A)", "g*(m_4*r_4 + m_3*r_3/l_3*l_4)/(b_B*c_B)")),
    "6.1": lambda: scissors_lift(length=0.5, payload_mass=8.0).parameters["k1"],
    "6.2": lambda: peaucellier_board().parameters["k1"] * (0.2 / 0.25) ** 2,
    "6.3": lambda: {"l10": 0.42, "k1": scissors_lift(length=0.5, payload_mass=8.0).parameters["k1_l10"] / 0.42,
                    "k2": scissors_lift(length=0.5, payload_mass=8.0).parameters["k1_l10"] / 0.42},
    # Singh's lift (2 stages, spring 1 from stage 1 to 2): gravity g a sin(theta) (4 m_a + 2 M), spring 1
    # a sin(theta) long, spring 2 a cos(theta) long: k_1 l_10 = g (4 m_a + 2 M), k_2 = k_1
    "6.4": lambda: sp.sympify(("g*(4*m_a + 2*M)/l_10", "g*(4*m_a + 2*M)/l_10")),
    "7.1": _lab7_free_choices,
    "7.2": _lab7_least_stiffness,
    "7.3": _lab7_lamp_springs,
    "7.4": lambda: (1.2 * 0.125 + 0.8 * (1 - 0.3 / 0.7) * 0.25) / 0.5,  # crank's moment, counterweight 0.5 m behind
    # the published arm (springs 2 and 3 "above", with the lamp): sin(theta_2), cos(theta_2 - theta_1) and
    # sin(theta_1) coefficients of the energy, by hand
    "7.5": lambda: sp.sympify(("(g*(m_1*p_1 + (m_2 + m_L)*l_1) - g*(m_2*p_2 + m_L*l_2)*l_1/s_2)/(a*s_1)",
                               "g*(m_2*p_2 + m_L*l_2)/(a*s_2)", "g*(m_2*p_2 + m_L*l_2)*l_1/(a*c*s_3)")),
    "8.1": lab8_reference_springs,
    "8.2": _lab8_study,
    "8.3": _lab8_shoulder_torque,
    "8.4": lambda: sp.sympify("-epsilon*g*cos(theta_1)*(m_1*p_1 + m_2*l_1)"),
    "9.1": _lab9_pulley,
    "9.2": _lab9_largest_tension,
    "9.3": lambda: sp.sympify("-m*g*r*cos(theta)/sqrt(2*k*C - 2*k*m*g*r*sin(theta))"),
}


def test_every_task_has_a_right_answer_here():
    assert set(RIGHT) == {t.id for t in tasks()}
    assert [t.id for t in tasks()] == sorted(RIGHT, key=lambda i: tuple(map(int, i.split("."))))
    for t in tasks():
        assert t.kind in ("numeric", "symbolic", "design")
        assert t.variable.isidentifier()
        assert "Task" in explain(t.id) and t.variable in explain(t.id)


@pytest.mark.parametrize("tid", sorted(RIGHT))
def test_right_answer_accepted(tid):
    v = check(tid, RIGHT[tid]())
    assert isinstance(v, Verdict)
    assert v.correct, str(v)
    assert v.score == v.points > 0
    assert "✔" in str(v)


@pytest.mark.parametrize("tid", [t for t in sorted(RIGHT) if _task(t).kind == "numeric"])
def test_numeric_tolerance_is_the_stated_one(tid):
    import re

    tol = float(re.search(r"within ([0-9.]+) %", _task(tid).expects).group(1)) / 100
    right = RIGHT[tid]()
    scale = (lambda f: tuple(f * x for x in right)) if isinstance(right, tuple) else (lambda f: f * right)
    assert check(tid, scale(1 + 0.8 * tol)).correct
    assert check(tid, scale(1 - 0.8 * tol)).correct
    for f in (1 + 1.2 * tol, 1 - 1.2 * tol, 2.0, -1.0):
        v = check(tid, scale(f))
        assert not v.correct and v.hint, str(v)


@pytest.mark.parametrize("tid", [t for t in sorted(RIGHT) if _task(t).kind == "numeric"])
def test_wrong_answers_never_reveal_the_expected_value(tid):
    right = RIGHT[tid]()
    values = right if isinstance(right, tuple) else (right,)
    wrongs = [tuple(x * f for x in values) if isinstance(right, tuple) else right * f
              for f in (0.5, 1.1, 9.81, 1 / 9.81, 1000.0)]
    for w in wrongs:
        text = str(check(tid, w))
        for x in values:
            for fmt in ("{:.2f}", "{:.3g}", "{:.4g}", "{:.6g}", "{}"):
                s = fmt.format(x)
                if len(s.strip("0.-")) >= 2:
                    assert s not in text, (s, text)


def test_hints_recognise_common_slips():
    k = RIGHT["2.1"]()
    assert "forget g" in check("2.1", k / bl.G).hint
    assert "1000" in check("1.1", RIGHT["1.1"]() * 1000).hint
    assert "sign" in check("2.3", -RIGHT["2.3"]()).hint


def test_units_are_understood():
    r = RIGHT["1.1"]()
    assert check("1.1", f"{r * 100:.4f} cm").correct
    assert check("1.1", (r * 1000, "mm")).correct
    k = RIGHT["2.1"]()
    assert check("2.1", f"{k / 1000:.6f} N/mm").correct
    assert check("2.1", f"{k / 1000:.6f} kN/m").correct
    v = check("2.1", f"{k:.3f}")
    assert not v.correct and "no unit" in v.message and "N/m" in v.hint
    v = check("1.1", f"{r:.4f} kg")
    assert not v.correct and "not a unit of length" in v.message
    assert ck.quantity("2.5 m", "length") == 2.5
    assert math.isclose(ck.quantity("90 deg", "angle"), math.pi / 2)


GARBAGE = [None, float("nan"), float("inf"), "banana", "", True, [1, 2, 3], (1,), {"x": 1},
           np.array([1.0, 2.0]), object(), sp.Symbol("x"), sp.Eq(sp.Symbol("k"), 1), {"crank": 1},
           {"k": "many", "a": 1, "b": (1, 2)}, ((1, 2), (3, 4))]


@pytest.mark.parametrize("tid", [t.id for t in tasks()])
def test_malformed_answers_get_a_friendly_verdict(tid):
    for g in GARBAGE:
        v = check(tid, g)  # must not raise
        assert isinstance(v, Verdict)
        assert not v.correct, (tid, g)
        assert v.score == 0
        assert v.message and "Traceback" not in str(v)
        assert v.hint


def test_specific_friendly_messages():
    assert "NaN" in check("1.1", float("nan")).message
    assert "should have 2 items" in check("1.3", (0.7,)).message
    assert "one number" in check("2.1", [1.0, 2.0]).message
    assert "missing" in check("1.4", {"crank": (1.0, (0.0, 0.0))}).message
    assert "equation" in check("1.2", sp.Eq(sp.Symbol("r_c"), sp.Symbol("r"))).message
    assert "not in the problem" in check("1.2", "x * r").message
    assert "pair" in check("2.2", sp.Symbol("W")).message
    v = check("7.7", 1.0)
    assert not v.correct and "no task" in v.message


def test_symbolic_answers_accepted_in_any_equivalent_form():
    m, r, ml, mc = sp.symbols("m r m_l m_c")
    for form in ((m * r + ml * r / 2) / mc, sp.expand((m * r + ml * r / 2) / mc),
                 r * (m + ml / 2) / mc, "r*(m + m_l/2)/m_c", (2 * m * r + ml * r) / (2 * mc)):
        assert check("1.2", form).correct, form
    for wrong in ((m * r + ml * r) / mc, m * r / mc, "r*(m+m_l)/(2*m_c)"):
        assert not check("1.2", wrong).correct
    ay, k = _lever_conditions()
    W, l, ax, bx, by = sp.symbols("W l a_x b_x b_y")
    assert check("2.2", {"a_y": ay, "k": k}).correct
    assert check("2.2", (sp.factor(ay), sp.apart(sp.sympify(k), sp.Symbol("W", positive=True)))).correct
    assert not check("2.2", (ax * bx / by, k)).correct
    assert not check("2.2", (ay, W * l / (ax * by))).correct


def test_symbolic_check_with_trig_identity_needs_equivalence_not_identity():
    m, r, ml, mc, t = sp.symbols("m r m_l m_c theta")
    form = (m * r + ml * r / 2) / mc * (sp.sin(t) ** 2 + sp.cos(t) ** 2)
    # theta is not a symbol of the problem: friendly refusal, not a crash
    assert "not in the problem" in check("1.2", form).message
    form = (m * r + ml * r / 2) / mc * (sp.sin(m) ** 2 + sp.cos(m) ** 2)
    assert check("1.2", form).correct


@pytest.mark.parametrize("masses", [(1.0, 2.0), (2.0, 2.0), (3.0, 5.5), (6.0, 6.0)])
def test_open_design_many_right_answers_lab1(masses):
    ans = _lab1_counterweights(*masses)
    v = check("1.4", ans)
    assert v.correct, str(v)
    assert v.score == 2


def test_open_design_checked_by_physics_lab1():
    ans = _lab1_counterweights(2.0, 2.0)
    # any direction works as long as the first moment is right: rotate both counterweights' positions
    # would unbalance; shifting one by 1 % unbalances
    m, (x, y) = ans["crank"]
    bad = dict(ans, crank=(m, (x * 1.01, y)))
    v = check("1.4", bad)
    assert not v.correct and "NOT balanced" in v.message
    too_far = _lab1_counterweights(0.5, 2.0)  # 0.224 kg m / 0.5 kg = 0.448 m from the pivot
    v = check("1.4", too_far)
    assert not v.correct and "balanced" in v.message and "farther than" in v.message
    too_heavy = _lab1_counterweights(7.0, 2.0)
    assert "heavier" in check("1.4", too_heavy).message
    # the design the check builds is a real balanced four-bar
    d = ck.lab1_fourbar(ans["crank"], ans["rocker"])
    assert d.balance_report(n=1000).balanced
    assert np.max(d.joint_error(d.sample(200))) < 1e-12


@pytest.mark.parametrize("b", [(-0.1, 0.2), (-0.05, 0.25), (-0.075, 0.225), (-0.06, 0.21)])
def test_open_design_many_right_answers_lab2(b):
    """Any anchor in the mounting box works once a_x is solved from the stock rate (the generalized lever)."""
    bx, by = b
    ax = 30.0 * 0.6 * by / (300.0 * (bx ** 2 + by ** 2))
    d = bl.singh.generalized_lever(weight=30.0, length=0.6, a_x=ax, b_x=bx, b_y=by)
    p = d.parameters
    assert p["k"] == pytest.approx(300.0)
    v = check("2.4", {"k": p["k"], "a": (p["a_x"], p["a_y"]), "b": (p["b_x"], p["b_y"])})
    assert v.correct, str(v)


def test_open_design_lab2_constraints_and_balance():
    assert (ck.task_numbers("2.4", "")["k"], ck.task_numbers("2.4", "")["box"]) == (300.0, (-0.1, -0.05, 0.2, 0.25))
    d = bl.singh.generalized_lever(weight=30.0, length=0.6, a_x=0.3, b_x=0.0, b_y=0.2)  # balanced, 300 N/m
    p = d.parameters
    v = check("2.4", {"k": p["k"], "a": (p["a_x"], p["a_y"]), "b": (p["b_x"], p["b_y"])})
    assert not v.correct and "outside your mounting box" in v.message and "balanced" in v.message
    d = bl.singh.generalized_lever(weight=30.0, length=0.6, a_x=0.2, b_x=-0.075, b_y=0.225)  # in the box, 360 N/m
    p = d.parameters
    v = check("2.4", {"k": p["k"], "a": (p["a_x"], p["a_y"]), "b": (p["b_x"], p["b_y"])})
    assert not v.correct and "stock spring's rate" in v.message and "balanced" in v.message
    v = check("2.4", {"k": 300.0 * 1.01, "a": (0.24, 0.08), "b": (-0.075, 0.225)})
    assert not v.correct and "NOT balanced" in v.message
    v = check("2.4", {"k": "300 N/m", "a": ("24 cm", 0.08), "b": (-0.075, "225 mm")})
    assert v.correct
    v = check("2.4", {"k": -5.0, "a": (0.24, 0.08), "b": (-0.075, 0.225)})
    assert not v.correct and "positive" in v.message


def test_lever_design_does_not_fall_to_one_catalog_call():
    """Brief c21b item 2: the catalog's levers, called with the load and a free choice as the chapter shows
    them (LaCoste's, the generalized lever with the anchor in the box and a round a_x), are balanced but
    miss the stock rate: the design needs the rate condition solved for a_x. Judged by physics for
    several students."""
    for sid in ("", "s1", "alice", "bob"):
        n = ck.task_numbers("2.4", sid)
        bx, by = (n["box"][0] + n["box"][1]) / 2, (n["box"][2] + n["box"][3]) / 2
        for d in (bl.singh.lacoste_lever(weight=n["weight"], length=n["length"], a_x=0.3, b_y=by),
                  bl.singh.generalized_lever(weight=n["weight"], length=n["length"], a_x=0.3, b_x=bx, b_y=by)):
            p = d.parameters
            v = core.check_data("2.4", ck.data.encode_answer(
                {"k": p["k"], "a": (p["a_x"], p.get("a_y", 0.0)), "b": (p.get("b_x", 0.0), p["b_y"])}), sid)
            assert not v.correct and "stock spring's rate" in v.message, (sid, str(v))
        ax = n["weight"] * n["length"] * by / (n["k"] * (bx ** 2 + by ** 2))
        right = {"k": n["k"], "a": (ax, -ax * bx / by), "b": (bx, by)}
        assert core.check_data("2.4", ck.data.encode_answer(right), sid).correct, sid


def test_lab_builders_balance_exactly_when_designed():
    d = ck.lab2_lever(300.0, (0.3, 0.0), (0.0, 0.2))
    rep = d.balance_report(n=1000)
    assert rep.balanced and rep.n == 1000
    for _name in ("k",):
        s = d.springs[0]
        worse = d.replace(springs=[bl.Spring(s.k * (1 + 1e-3), s.free_length, s.a, s.b)])
        assert not worse.balance_report().balanced


def test_verdict_prints_and_is_truthy():
    v = check("2.1", RIGHT["2.1"]())
    assert bool(v) and repr(v) == str(v) and str(v).startswith("Task 2.1")
    w = check("2.1", 1.0)
    assert not bool(w) and "Hint:" in str(w)


def test_open_designs_labs_3_to_6_physics():
    import balancelab.methods.singh.serial as serial

    # lab 3: several ordinary springs pass; the ZFL rate with a free length does not
    assert check("3.3", _approximate_spring()).correct
    assert check("3.3", _approximate_spring(k_bounds=(1.0, 800.0), anchor_bounds=((-0.1, 0.1), (0.05, 0.3)))).correct
    v = check("3.3", {"k": 2 * bl.G * 0.5 / 0.06, "a": (0.2, 0.0), "b": (0.0, 0.3)})
    assert not v.correct and "torque error" in v.message
    # lab 4: several free choices pass, as dicts or as designs; too much preload or stiff springs fail
    for ax in ((1.4, 1.5, -1.5), (1.6, 1.6, -1.6), (2.0, 1.5, -1.5)):
        assert check("4.3", {"a_x": ax}).correct, ax
    arm = serial.serial_2r_min_preload(weights=(10.0, 20.0), coms=((1.0, 0.5), (2.0, 0.0)), length=1.5,
                                       a_x=(1.6, 1.6, -1.6))
    assert check("4.3", arm).correct
    assert "anchor" in check("4.3", {"a_x": (1.5, 2.0, -2.0)}).message
    simplified = serial.serial_2r_simplified()
    assert not check("4.3", simplified).correct
    # lab 5: both bases have right answers; a stiff or boxed-out choice fails
    assert check("5.3", {"base": "A", "h": 0.3}).correct and check("5.3", {"base": "B", "h": 0.2}).correct
    assert "stiffer" in check("5.3", {"base": "A", "h": 0.03}).message
    assert "box" in check("5.3", {"base": "B", "h": 0.3}).message
    assert "'A' or 'B'" in check("5.3", {"base": "C", "h": 0.1}).message
    # lab 6: any l10 in the feasible window, with the matching rates
    prod = scissors_lift(length=0.5, payload_mass=8.0).parameters["k1_l10"]
    for l10 in (0.40, 0.43, 0.45):
        assert check("6.3", {"l10": l10, "k1": prod / l10, "k2": prod / l10}).correct, l10
    assert "longer" in check("6.3", {"l10": 0.48, "k1": prod / 0.48, "k2": prod / 0.48}).message
    assert "NOT balanced" in check("6.3", {"l10": 0.43, "k1": prod / 0.43, "k2": 1.01 * prod / 0.43}).message
    assert ck.lab6_scissors(0.43).balance_report().balanced


def test_docstring_examples_of_the_lab_modules_run():
    import doctest

    import balancelab.course.grading
    import balancelab.course.labtools

    import importlib
    import pkgutil

    for mod in (ck, core, answers, lab1, lab2, lab3, lab4, lab5, lab6, lab7, lab8, lab9, balancelab.course.grading):
        result = doctest.testmod(mod, optionflags=doctest.ELLIPSIS)
        assert result.attempted > 0 and result.failed == 0, mod.__name__
    # labtools is a package (split by concept): its modules' examples, together
    tools = balancelab.course.labtools
    attempted = 0
    for info in pkgutil.iter_modules(tools.__path__, tools.__name__ + "."):
        if info.name.endswith("__main__"):
            continue
        result = doctest.testmod(importlib.import_module(info.name), optionflags=doctest.ELLIPSIS)
        assert result.failed == 0, info.name
        attempted += result.attempted
    assert attempted > 0, tools.__name__


# ------------------------------------------------- trusted checking, hints, personal numbers


def test_check_and_grader_share_one_judge_on_plain_data():
    from balancelab.course.check import check_data, encode_answer

    for tid, right in RIGHT.items():
        answer = right()
        data = encode_answer(answer)
        assert check_data(tid, data).correct and check(tid, answer).correct, tid
        assert check_data(tid, data) == check(tid, answer)


def test_unreadable_and_missing_answers():
    assert check("2.1", ...).message == "No answer yet."
    forged = Verdict("2.1", True, "ok", "", 100.0, 1.0)
    v = check("2.1", forged)
    assert not v.correct and v.score == 0 and "Verdict" in v.message


def test_faked_design_subclass_is_judged_from_its_data():
    from balancelab.core.design import Design

    class Liar(Design):
        def balance_report(self, *args, **kwargs):
            raise AssertionError("the check must never call the student's object")

    honest = lab4.lab4_singh_arm((1.6, 1.6, -1.6))
    assert check("4.3", honest).correct
    half = honest.replace(springs=[bl.Spring(s.k / 2, s.free_length, s.a, s.b, name=s.name) for s in honest.springs])
    liar = Liar(half.name, half.bodies, half.joints, half.kinematics, half.loads, half.springs)
    v = check("4.3", liar)
    assert not v.correct and "NOT balanced" in v.message


def test_srepr_is_parsed_without_evaluating_code(tmp_path):
    from balancelab.course.check.data import parse_srepr

    target = tmp_path / "x"
    for text in (f"__import__('os').system('touch {target}')", "Symbol('x').__class__",
                 "Pow(Integer(10), Integer(10000000000000))", "Pow(Integer(10), Integer(1000000000))",
                 "lambda: 1"):
        with pytest.raises((ValueError, SyntaxError)):
            parse_srepr(text)
    assert not target.exists()
    m, r = sp.symbols("m r", positive=True)
    assert parse_srepr(sp.srepr(m * r / 2 + sp.sin(m) ** 2)) == m * r / 2 + sp.sin(m) ** 2


def _scaled(answer, factor):
    return tuple(float(v) * factor for v in answer) if isinstance(answer, tuple) else float(answer) * factor


@pytest.mark.parametrize("tid", [t.id for t in tasks() if t.kind == "numeric"])
def test_hints_give_bands_not_directions(tid):
    """Two wrong answers, one too small and one too large by the same factor, get the same hint."""
    right = RIGHT[tid]()
    for factor in (1.03, 1.3, 3.0):
        low, high = check(tid, _scaled(right, 1 / factor)), check(tid, _scaled(right, factor))
        assert not low.correct and not high.correct
        assert low.hint == high.hint, (low.hint, high.hint)
        assert "large" not in low.hint.replace("too large or too small", "")


def test_lever_conditions_hold_for_an_anchor_left_of_the_pivot():
    W, l, ax, by = sp.symbols("W l a_x b_y", positive=True)
    bx = sp.Symbol("b_x", real=True)
    assert check("2.2", (-ax * bx / by, W * l * by / (ax * (bx ** 2 + by ** 2)))).correct
    # |b_x| is b_x only when b_x > 0: wrong for an anchor on the other side
    assert not check("2.2", (-ax * sp.sqrt(bx ** 2) / by, W * l * by / (ax * (bx ** 2 + by ** 2)))).correct
    d = bl.singh.generalized_lever(weight=10.0, length=0.5, a_x=0.2, b_x=-0.1, b_y=0.3)
    assert d.balance_report().balanced
    assert np.isclose(d.parameters["k"], 10.0 * 0.5 * 0.3 / (0.2 * (0.01 + 0.09)))


def test_personal_numbers_are_seeded_by_the_student_and_judged_with_them():
    from balancelab.course.check import set_student, task_numbers

    assert task_numbers("2.1", "") == ck.LAMP_SPRING
    mine, other = task_numbers("2.1", "s001"), task_numbers("2.1", "s002")
    assert mine == task_numbers("2.1", "s001") and mine != other
    k = bl.lecture.single_link_spring(**mine).parameters["k"]
    assert np.isclose(k, mine["mass"] * bl.G * mine["length"] / (mine["b"] * mine["c"]))
    try:
        set_student("s001")
        assert check("2.1", k).correct
        set_student("s002")
        assert not check("2.1", k).correct
    finally:
        set_student("")
    assert check("2.1", RIGHT["2.1"]()).correct
    lamp = task_numbers("1.1", "s001")
    r_c = (lamp["mass"] * lamp["length"] + lamp["link_mass"] * lamp["length"] / 2) / lamp["counter_mass"]
    assert core.check_data("1.1", {"num": repr(r_c)}, "s001").correct


@pytest.mark.parametrize("task, right", [("3.1", lambda n: _pulley_radius(**n)),
                                         ("7.2", lambda n: _lab7_least_stiffness(n))])
def test_personal_numbers_of_pulley_and_arm_tasks(task, right):
    """Issue 18, item 6: tasks 3.1 and 7.2 are judged with the student's own numbers; the published
    answer and a friend's are wrong for a student whose right answer differs from them."""
    from balancelab.course.check import set_student, task_numbers

    tol = {"3.1": 0.02, "7.2": 0.005}[task]
    published = right(task_numbers(task, ""))
    ids = [f"s{i:03d}" for i in range(8)]
    mine = {sid: right(task_numbers(task, sid)) for sid in ids}
    assert all(task_numbers(task, sid) == task_numbers(task, sid) for sid in ids[:2])
    for sid, value in mine.items():
        assert core.check_data(task, {"num": repr(value)}, sid).correct
        if abs(published / value - 1) > 2 * tol:
            assert not core.check_data(task, {"num": repr(published)}, sid).correct
    differs = [sid for sid in ids if abs(published / mine[sid] - 1) > 2 * tol]
    assert len(differs) >= 5, "personal numbers should move the answer away from the published one"
    alice, bob = next((a, b) for a in differs for b in differs if abs(mine[a] / mine[b] - 1) > 2 * tol)
    assert not core.check_data(task, {"num": repr(mine[alice])}, bob).correct  # a friend's answer
    try:  # the notebook's check judges with the id set there
        set_student(alice)
        assert check(task, mine[alice]).correct and not check(task, published).correct
    finally:
        set_student("")
    assert check(task, published).correct


def _formats(v):
    out = set()
    for fmt in ("{:.2f}", "{:.3f}", "{:.4f}", "{:.4g}", "{:.5g}", "{}"):
        out.add(fmt.format(v))
    return {s for s in out if len(s.strip("-0.").replace(".", "")) >= 4}


def test_no_expected_value_in_student_versions_or_check_sources():
    """Every numeric expected value, in several formats, is absent from the hand-out and the checks' source."""
    from pathlib import Path

    root = Path(__file__).resolve().parent.parent
    texts = {p.name: p.read_text(encoding="utf-8") for p in (root / "labs" / "student").glob("*.ipynb")}
    texts.update({p.name: p.read_text(encoding="utf-8")
                  for p in (root / "balancelab" / "course" / "check").glob("*.py")})
    found = []
    for t in tasks():
        if t.kind != "numeric":
            continue
        right = RIGHT[t.id]()
        values = right if isinstance(right, tuple) else (right,)
        for v in values:
            for s in _formats(float(v)):
                for name, text in texts.items():
                    found.extend([(t.id, s, name)] if s in text else [])
    assert found == []


def test_every_check_path_is_counted_once():
    """A student who bisects with ``check_data`` instead of ``check`` is counted too (issue 18)."""
    from balancelab.course.check import core

    before = dict(core.ATTEMPTS)
    ck.check("2.1", 12.0)
    ck.check_data("2.1", {"num": "13.0"})
    ck.check_data("2.1", {"num": "14.0"}, "alice")
    ck.check("no such task", 1.0)
    assert core.ATTEMPTS.get("2.1", 0) - before.get("2.1", 0) == 3
    assert "no such task" not in core.ATTEMPTS


# ------------------------------------------------------- personal numbers: classmates' answers

def _singh_2r_pe(n):
    # Singh eq. 49 by hand: |W1 p1 + W2 l| (the base pivot's share, a vector) + W2 |p2|
    (w1, w2), ((p1x, p1y), (p2x, p2y)), l = n["weights"], n["coms"], n["length"]
    return float(np.hypot(w1 * p1x + w2 * l, w1 * p1y) + w2 * np.hypot(p2x, p2y))


def _singh_fourbar_pe(n):
    # the relaxed 2R (crank 1.5 m, coupler's com at 2 m) plus the rocker's weight at its com 0.5 m
    w1, w2, w3 = n["weights"]
    return float(np.hypot(w1 * 1.0 + w2 * 1.5, w1 * 0.5) + w2 * 2.0 + w3 * 0.5)


def _lecture_crank_rate(n):
    (m2, m3, _), ((p2, _y), (p3x, p3y), _r) = n["masses"], n["coms"]
    c = complex(p3x, p3y) / 0.8
    return bl.G * abs(m2 * p2 + m3 * (1 - c) * 0.3) / (0.2 * 0.15)


def _parallelogram_by_hand(n):
    (m1, m2), ((p1, _), (p2, _)), l = n["masses"], n["coms"], n["length"]
    (b1, b2), (c1, c2) = n["b"], n["c"]
    return (bl.G * (m1 * p1 + m2 * l) / (b1 * c1), bl.G * m2 * p2 / (b2 * c2))


def _lift_by_hand(n):
    # Singh eq. 55 with l10 = a: k1 a = g (m2/2 + m3/2 + 3 m5/2 + 3 m6/2 + 2 m7 + 2 m8), four arms of one
    # mass, sliders m4 = m7, the platform and its payload in m8 (the bottom slider m4 does not rise)
    ma, ms, m8 = n["arm_mass"], n["slider_mass"], n["platform_mass"] + n["payload_mass"]
    return bl.G * (4 * ma + 2 * ms + 2 * m8) / n["length"]


def _board_crank_by_hand(n):
    # Singh eqs 18-20: the crank (d = 0.22326 m) carries W1 = 6.88 N at d/2 and (W4 + W5)/2 = 4.78 N at C;
    # k1 a_x1 b_y1 equals that moment, with b_y1 = a_x1
    d = 0.22326
    return (6.88 * d / 2 + 4.78 * d) / n["a_x"] ** 2


#: each personal numeric task's right answer from its numbers, by a route independent of its judge
PERSONAL_RIGHT = {
    "1.1": lambda n: (n["mass"] * n["length"] + n["link_mass"] * n["length"] / 2) / n["counter_mass"],
    # same mass and same first moment about D (DC = 0.5 m)
    "1.3": lambda n: (n["mass"] * (1 - n["com"] / 0.5), n["mass"] * n["com"] / 0.5),
    "2.1": lambda n: n["mass"] * bl.G * n["length"] / (n["b"] * n["c"]),
    # Singh's eq. 3, V = W l / 2 (a_x / b_y + b_y / a_x)
    "2.3": lambda n: n["weight"] * n["length"] / 2 * (n["a_x"] / n["b_y"] + n["b_y"] / n["a_x"]),
    "3.1": lambda n: _pulley_radius_by_ratio(**n),
    "3.2": lambda n: -n["k"] * n["free_length"] / n["k_partner"],
    "4.1": _parallelogram_by_hand,
    "4.2": _singh_2r_pe,
    # the sin(theta_2) terms of the energy: k1 a_y1 L2 = g (m2 s_x2 + m3 L2), by hand
    "4.4": lambda n: bl.G * (n["m2"] * n["sx2"] + n["m3"] * n["L2"]) / (n["L2"] * n["ay1"]),
    "5.1": _lecture_crank_rate,
    "5.2": _singh_fourbar_pe,
    "6.1": _lift_by_hand,
    "6.2": _board_crank_by_hand,
    "7.2": lambda n: _lab7_least_stiffness(n),
    # the spring's extra pull e k1 b1 c1 cos(theta_1), with k1 b1 c1 = g (m1 p1 + m2 l1)
    "8.3": lambda n: n["rate_error"] * bl.G * (1.0 * 0.25 + 1.0 * 0.5) * math.cos(n["theta_1"]),
    # T_max^2 = T_min^2 + 2 k (V(60°) - V(-60°)) with V = m g r sin(theta) on the student's link, by hand
    "9.2": lambda n: _lab9_tension_by_hand(n["mass"], n["length"]),
}


def test_every_personal_numeric_task_has_an_independent_right_answer():
    personal = {t.id for t in tasks() if t.numbers is not None and t.kind == "numeric"}
    assert personal == set(PERSONAL_RIGHT)
    for tid, right in PERSONAL_RIGHT.items():
        assert check(tid, right(ck.task_numbers(tid, ""))).correct, tid  # published numbers
        for sid in ("s1", "alice", "s199"):
            assert core.check_data(tid, ck.data.encode_answer(right(ck.task_numbers(tid, sid))), sid).correct, (tid, sid)


def _as_answer(value):
    return tuple(float(v) for v in value) if isinstance(value, tuple) else float(value)


@pytest.mark.parametrize("tid", sorted(PERSONAL_RIGHT))
def test_few_classmates_answers_pass_each_others_check(tid):
    """Issue 21, item 3: over 200 ids, under 1 % of ordered pairs (i, j) have i's right answer pass
    j's check, and the published answer passes nobody's.

    The check is run on every pair whose (first) values are within 10 % of each other; every
    student's check is shown to refuse their own answer 10 % off either way, so the pairs farther
    apart cannot pass (the relative tolerance is a band around the right value)."""
    ids = [f"s{i:03d}" for i in range(200)]
    values = {sid: _as_answer(PERSONAL_RIGHT[tid](ck.task_numbers(tid, sid))) for sid in ids}
    first = {sid: (v[0] if isinstance(v, tuple) else v) for sid, v in values.items()}
    enc = ck.data.encode_answer
    for sid in ids:
        assert core.check_data(tid, enc(values[sid]), sid).correct
        for f in (0.9, 1.1):
            assert not core.check_data(tid, enc(_scaled(values[sid], f)), sid).correct
    near = [(i, j) for i in ids for j in ids if i != j and abs(first[i] / first[j] - 1) <= 0.1]
    passing = sum(core.check_data(tid, enc(values[i]), j).correct for i, j in near)
    rate = passing / (len(ids) * (len(ids) - 1))
    print(f"task {tid}: {100 * rate:.2f} % of classmate pairs pass each other's check")
    assert rate < 0.01, f"{tid}: {100 * rate:.2f} % of classmate pairs pass each other's check"
    published = enc(_as_answer(PERSONAL_RIGHT[tid](ck.task_numbers(tid, ""))))
    assert not any(core.check_data(tid, published, sid).correct for sid in ids)


def test_tolerance_study_uses_the_students_tolerances():
    """Brief c21b item 1: task 8.2's rate tolerance is personal. The published study (2 % rates) and a
    classmate's study whose rate tolerance is 25 % away score 0; the student's own study scores."""
    from balancelab.methods.practice import tolerance

    springs = lab8_reference_springs()
    built = lab8.built_arm(springs)
    enc = ck.data.encode_answer

    def study(sid, seed):
        tol = tolerance.Tolerances(**ck.task_numbers("8.2", sid))
        return {"springs": springs, "quantile": tolerance.monte_carlo(built, tol, n=3000, grid=15, seed=seed).quantile(0.95)}

    assert ck.task_numbers("8.2", "") == dict(k=0.02, attachment=0.0005, mass=0.01)
    published = enc(_lab8_study())
    ids = ("s1", "alice", "bob")
    rates = {sid: ck.task_numbers("8.2", sid)["k"] for sid in ids}
    assert all(abs(r / 0.02 - 1) > 0.25 for r in rates.values())
    for sid in ids:
        assert core.check_data("8.2", enc(study(sid, 7)), sid).correct, sid
        assert not core.check_data("8.2", published, sid).correct, sid
    friends = [(i, j) for i in ids for j in ids if i != j and abs(rates[i] / rates[j] - 1) > 0.25]
    assert friends
    for i, j in friends:
        assert not core.check_data("8.2", enc(study(i, 7)), j).correct, (i, j)


def test_rate_error_verdicts_say_derivative_and_sign():
    """Brief c21b item 3: task 8.4's verdicts. The hint of a wrong formula is the way to a derivative
    (not a balance condition set to zero), the symbol keeps its case, a flipped sign is named; and the
    hint's claims hold: dV/dtheta_1 itself (the library's generalized force) at link 1's angle from the
    horizontal, for any theta_2."""
    from balancelab.methods.practice.forces import generalized_force

    flipped = check("8.4", sp.sympify("epsilon*g*cos(theta_1)*(m_1*p_1 + m_2*l_1)"))
    assert not flipped.correct and "opposite sign" in flipped.hint
    assert flipped.message == "Your dV/dtheta_1 is not equivalent to the expected one."
    wrong = check("8.4", sp.sympify("-epsilon*g*sin(theta_1)*(m_1*p_1 + m_2*l_1)"))
    assert not wrong.correct and "coefficient to zero" not in wrong.hint
    assert "differentiate" in wrong.hint and "reference line" in wrong.hint and "not minus it" in wrong.hint
    right = check("8.4", RIGHT["8.4"]())
    assert right.correct and right.message == "Your dV/dtheta_1 is equivalent to the expected one."
    eps = 0.03
    for q in ((0.3, 0.0), (0.3, 1.0), (-0.9, -0.6)):
        _, Q = generalized_force(lab8.rate_error_arm(eps), np.array([q]))
        by_formula = float(RIGHT["8.4"]().subs({"epsilon": eps, "g": bl.G, "m_1": 1.0, "p_1": 0.25, "m_2": 1.0,
                                                 "l_1": 0.5, "theta_1": q[0]}))
        assert Q[0, 0] == pytest.approx(by_formula, rel=1e-6)


def test_pe_min_verdicts_say_largest_energy():
    """Brief c21b item 3: task 4.5's hint is the way to the largest load energy (no coefficient is set to
    zero), the symbol keeps its case; and the claim holds: the formula is the largest energy of the loads
    over a grid of poses (theta_2 measured from link 1), for Singh's published 2R."""
    wrong = check("4.5", sp.sympify("W_1*p_x1 + W_2*l + W_2*p_x2"))
    assert not wrong.correct and "coefficient to zero" not in wrong.hint
    assert "largest value" in wrong.hint and "amplitude" in wrong.hint
    assert wrong.message == "Your PE_min is not equivalent to the expected one."
    flipped = check("4.5", -RIGHT["4.5"]())
    assert not flipped.correct and "opposite sign" in flipped.hint
    t1, t2 = np.meshgrid(np.linspace(-np.pi, np.pi, 721), np.linspace(-np.pi, np.pi, 721))
    W1, W2, (px1, py1), px2, l = 10.0, 20.0, (1.0, 0.5), 2.0, 1.5
    energy = W1 * (px1 * np.sin(t1) + py1 * np.cos(t1)) + W2 * (l * np.sin(t1) + px2 * np.sin(t1 + t2))
    formula = float(RIGHT["4.5"]().subs({"W_1": W1, "W_2": W2, "p_x1": px1, "p_y1": py1, "p_x2": px2, "l": l}))
    assert energy.max() == pytest.approx(formula, rel=1e-4)
    assert formula == pytest.approx(lab4.lab4_singh_arm().parameters["PE_min"], rel=1e-9)


def _variant_formula(tid: str, n: dict):
    """Each derive task's right formula for a student's variant, by hand (not through the judge)."""
    if tid == "1.2":  # the arm's own centre of mass at f r
        return sp.sympify(f"(m*r + ({n['f']})*m_l*r)/m_c")
    if tid == "2.2":  # the load's moment W f l
        return (sp.sympify("-a_x*b_x/b_y"), sp.sympify(f"W*({n['f']})*l*b_y/(a_x*(b_x**2 + b_y**2))"))
    if tid == "4.5":  # the elbow carries (1 + c) W_2
        return sp.sympify(f"sqrt((W_1*p_x1 + (1 + ({n['c']}))*W_2*l)**2 + (W_1*p_y1)**2) + W_2*p_x2")
    if tid == "8.4":  # link 1 at theta_1 + alpha from the horizontal
        return sp.sympify(f"-epsilon*g*(m_1*p_1 + m_2*l_1)*cos(theta_1 + ({n['alpha']}))")
    return sp.sympify(f"-m*g*r*cos(theta + ({n['alpha']}))/sqrt(2*k*C - 2*k*m*g*r*sin(theta + ({n['alpha']})))")


@pytest.mark.parametrize("tid", ["1.2", "2.2", "4.5", "8.4", "9.3"])
def test_derive_tasks_have_personal_variants_the_book_formula_fails(tid):
    """Brief c21b item 4: the name scan cannot be complete (``getattr(bl, "bal" + "ance")``), so the
    answer's form carries the defence: each student derives a personal variant, and the book's (or a
    docstring's) formula is wrong for them. Judged by equivalence at random instances."""
    enc = ck.data.encode_answer
    book = _variant_formula(tid, ck.task_numbers(tid, ""))
    assert core.check_data(tid, enc(book), "").correct
    assert core.check_data(tid, enc(RIGHT[tid]()), "").correct  # the published problem is the book's
    ids = [f"s{i:03d}" for i in range(40)]
    assert all(ck.task_numbers(tid, sid) != ck.task_numbers(tid, "") for sid in ids)
    assert len({tuple(ck.task_numbers(tid, sid).values()) for sid in ids}) >= 4
    for sid in ids[:6]:
        mine = _variant_formula(tid, ck.task_numbers(tid, sid))
        assert core.check_data(tid, enc(mine), sid).correct, sid
        assert not core.check_data(tid, enc(book), sid).correct, sid


def test_getattr_beats_the_name_scan_but_not_the_variant():
    """The lever's balance conditions reached through ``getattr`` pass the name scan (nothing named) and
    give the book's formula: right for the published lever, wrong for a student's variant."""
    from balancelab.course.check.derive import shortcuts

    source = ('d = getattr(bl.singh, "generalized_" + "lever")(weight=10.0, length=0.5, a_x=0.2, b_x=0.1, b_y=0.3)\n'
              'eqs = [e.lhs for e in getattr(d, "balance_" + "conditions")()]')
    assert shortcuts("2.2", source) == []  # the scan does not see it
    d = getattr(bl.singh, "generalized_" + "lever")(weight=10.0, length=0.5, a_x=0.2, b_x=0.1, b_y=0.3)
    eqs = [e.lhs for e in getattr(d, "balance_" + "conditions")()]
    syms = {str(x): x for e in eqs for x in e.free_symbols}
    sol = [x for x in sp.solve(eqs, [syms["a_y"], syms["k"]], dict=True) if x[syms["k"]] != 0][0]
    answer = ck.data.encode_answer((sol[syms["a_y"]], sol[syms["k"]]))
    assert core.check_data("2.2", answer, "").correct
    student = next(sid for sid in (f"s{i}" for i in range(50)) if ck.task_numbers("2.2", sid)["f"] != "1")
    assert not core.check_data("2.2", answer, student).correct
