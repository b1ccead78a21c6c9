"""From ideal to real: real springs, selection, tolerances, friction, payloads and forces."""
from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

import balancelab as bl
from balancelab import G
from balancelab.methods.practice import forces as fo
from balancelab.methods.practice import friction as fr
from balancelab.methods.practice import payload as pl
from balancelab.methods.practice import selection as se
from balancelab.methods.practice import springs as sp
from balancelab.methods.practice import tolerance as to
from conftest import assert_exactly_balanced

INCH, LBF, PSI = 0.0254, 4.4482216152605, 6894.757293168


def lever(mass=2.0, length=0.5, b=0.3, c=0.2):
    return bl.lecture.single_link_spring(mass, length, b, c)


# ------------------------------------------------------------------ real springs
def test_shigley_example_10_7_extension_spring():
    """Budynas & Nisbett, Shigley's Mechanical Engineering Design (9th ed.), Example 10-7.

    Hard-drawn steel extension spring: d = 0.035 in, OD = 0.248 in, N_a = 12.57 (12.17 body
    turns + G/E), G = 11.6 Mpsi, F_i = 1.19 lbf. The book finds k = 17.91 lbf/in, an
    uncorrected initial stress of 15.1 kpsi and a preferred range of 14.2-21.2 kpsi.
    """
    d, D = 0.035 * INCH, (0.248 - 0.035) * INCH
    k = sp.spring_rate(d, D, 12.57, 11.6e6 * PSI)
    assert k / (LBF / INCH) == pytest.approx(17.91, abs=0.005)
    C = float(sp.spring_index(d, D))
    assert C == pytest.approx(6.086, abs=5e-4)
    tau_i = sp.shear_stress(1.19 * LBF, d, D, corrected=False) / PSI
    assert tau_i / 1000 == pytest.approx(15.1, abs=0.05)
    lo, hi = sp.initial_stress_range(C)
    assert (lo / PSI / 1000, hi / PSI / 1000) == pytest.approx((14.2, 21.2), abs=0.05)


def test_wahl_factor_formula_and_its_closeness_to_bergstrasser():
    C = np.linspace(4, 12, 33)
    kw = sp.wahl_factor(C)
    assert np.allclose(kw, (4 * C - 1) / (4 * C - 4) + 0.615 / C, rtol=0, atol=0)
    kb = (4 * C + 2) / (4 * C - 3)          # Bergstraesser's factor (Shigley eq. 10-5), a close cousin
    assert np.all(np.abs(kw / kb - 1) < 0.015) and np.all(kw > kb)
    assert np.all(np.diff(kw) < 0)          # the correction fades for gentler coils


def test_extension_spring_zfl_condition_and_error():
    s = sp.ExtensionSpring(1e-3, 8e-3, 40, initial_tension=2.0, hooks=False)
    assert s.k == pytest.approx(81.7e9 * 1e-3 / (8 * 8 ** 3 * 40), rel=1e-14)
    assert s.body_length == pytest.approx(41e-3, rel=1e-14)
    # two standard hooks add their inside diameters D - d: 2 * 7 mm between the load points; their
    # deflection counts as G/E extra active coils (Shigley eq. 10-39: N_a = N_b + G/E), so the body of a
    # hooked spring with N_a = 40 holds N_b = 40 - 81.7/196.5 coils, at the same rate
    hooked = sp.ExtensionSpring(1e-3, 8e-3, 40, initial_tension=2.0)
    n_b = 40 - 81.7 / 196.5
    assert hooked.k == s.k and hooked.body_coils == pytest.approx(n_b, rel=1e-14)
    assert hooked.body_length == pytest.approx(1e-3 * (n_b + 1) + 14e-3, rel=1e-14)
    ell = s.body_length - 2.0 / s.k
    L = np.linspace(s.body_length, 0.3, 7)
    assert np.allclose(s.force(L), 2.0 + s.k * (L - s.body_length), rtol=1e-13)
    assert np.allclose(sp.zfl_force_error(s, L), -s.k * ell, rtol=1e-12)
    assert np.isnan(s.force(0.5 * s.body_length)) and not s.is_zfl
    zfl = sp.ExtensionSpring(1e-3, 8e-3, 40, initial_tension=s.k * s.body_length, hooks=False)
    assert zfl.is_zfl and np.allclose(sp.zfl_force_error(zfl, L), 0.0, atol=1e-12)


def test_allowables_and_max_force():
    d = 1.2e-3
    sut = sp.tensile_strength(d)
    assert sut == pytest.approx(2211e6 / 1.2 ** 0.145, rel=1e-14)
    assert sp.allowable_stress(d) == pytest.approx(0.45 * sut)
    assert sp.allowable_stress(d, sp.STAINLESS_302) == pytest.approx(0.35 * sp.tensile_strength(d, sp.STAINLESS_302))
    cyc = [sp.allowable_stress(d, cycles=n) / sut for n in (1e3, 1e5, 1e6, 1e7, 1e9)]
    assert cyc == pytest.approx([0.36, 0.36, 0.33, 0.30, 0.30])
    s = sp.ExtensionSpring(d, 10e-3, 30, initial_tension=1.0, hooks=False)   # the body alone
    for cycles in (None, 1e6):
        assert s.stress(s.max_force(cycles)) == pytest.approx(sp.allowable_stress(d, cycles=cycles), rel=1e-12)
    assert s.max_deflection() == pytest.approx((s.max_force() - 1.0) / s.k)
    lo, hi = s.initial_tension_range()
    tlo, thi = sp.initial_stress_range(s.index)
    assert lo == pytest.approx(tlo * math.pi * d ** 3 / (8 * 10e-3)) and hi > lo


def test_hook_stresses_of_shigley_example_10_7_by_hand_in_inches():
    """Example 10-7's hooks: d = 0.035 in, D = 0.213 in, r1 = 0.106 in, r2 = 0.089 in (eqs. 10-34 to 10-36)."""
    d, D, r1, r2, F = 0.035, 0.213, 0.106, 0.089, 5.0            # inches, lbf
    C1, C2 = 2 * r1 / d, 2 * r2 / d
    KA = (4 * C1 ** 2 - C1 - 1) / (4 * C1 * (C1 - 1))
    KB = (4 * C2 - 1) / (4 * C2 - 4)
    assert (round(KA, 2), round(KB, 2)) == (1.14, 1.18)          # the factors the example prints
    sigma_A = F * (KA * 16 * D / (math.pi * d ** 3) + 4 / (math.pi * d ** 2))    # psi
    tau_B = KB * 8 * F * D / (math.pi * d ** 3)
    sA, tB = sp.hook_stresses(F * LBF, d * INCH, D * INCH, bend_radius=r1 * INCH, root_radius=r2 * INCH)
    assert sA / PSI == pytest.approx(sigma_A, rel=1e-12) and tB / PSI == pytest.approx(tau_B, rel=1e-12)
    # both factors fade to 1 for gentle bends, and the stresses are linear in the pull
    assert sp.hook_bending_factor(1e6) == pytest.approx(1, abs=1e-5) and sp.hook_torsion_factor(1e6) == pytest.approx(1, abs=1e-5)
    s2, t2 = sp.hook_stresses(2 * F * LBF, d * INCH, D * INCH, bend_radius=r1 * INCH, root_radius=r2 * INCH)
    assert (s2, t2) == pytest.approx((2 * sA, 2 * tB), rel=1e-14)


def test_standard_hooks_govern_the_lamps_static_spring():
    """Chapter 8's first choice for spring 1 (1.8 mm wire, D = 25.2 mm, 73.5 N at the longest stroke).

    By hand: tau = 8 F D / (pi d^3) = 808.8 MPa; C = 14: K_A = 769/728, so
    sigma_A = 2 K_A tau + 4 F / (pi d^2) = 1708.7 + 28.9 = 1737.6 MPa > 0.75 S_ut = 1523 MPa;
    tau_B = 1.25 tau = 1011 MPa > 0.40 S_ut = 812 MPa, while the body (K_W tau = 891 MPa) is within 45 %.
    """
    s = sp.ExtensionSpring(1.8e-3, 25.2e-3, 41)
    F = 808.8e6 * math.pi * 1.8e-3 ** 3 / (8 * 25.2e-3)
    st = s.stresses(F)
    assert st["hook_bending"] / 1e6 == pytest.approx(1737.6, abs=0.5)
    assert st["hook_torsion"] / 1e6 == pytest.approx(1011.0, abs=0.5)
    sut = sp.tensile_strength(1.8e-3)
    assert st["body"] < 0.45 * sut and st["hook_bending"] > 0.75 * sut and st["hook_torsion"] > 0.40 * sut
    assert s.max_force() < F < sp.ExtensionSpring(1.8e-3, 25.2e-3, 41, hooks=False).max_force()
    assert s.governing() == "hook_torsion"
    # cyclic allowables of the hooks (table 10-8), never above the static ones
    frac = [float(sp.allowable_stress(1.8e-3, cycles=n, where=w) / sut)
            for w in ("hook_torsion", "hook_bending") for n in (1e5, 1e6, 1e7)]
    assert frac == pytest.approx([0.34, 0.30, 0.28, 0.51, 0.47, 0.45])
    with pytest.raises(ValueError, match="where"):
        sp.allowable_stress(1e-3, where="coil")


def test_hooks_count_in_the_free_length():
    """1 mm wire, C = 10, N_a = 40, largest preferred F_i: bare l = 41 - F_i / k mm (25.5); with hooks the body
    holds N_b = N_a - G/E coils (Shigley eq. 10-39) and the hooks add 2 (D - d): l = 25.5 - 0.42 + 18 = 43.0 mm (to 0.1)."""
    bare = sp.ExtensionSpring(1e-3, 10e-3, 40, hooks=False)
    Fi = bare.initial_tension_range()[1]
    hooked = sp.ExtensionSpring(1e-3, 10e-3, 40, initial_tension=Fi)
    bare = sp.ExtensionSpring(1e-3, 10e-3, 40, initial_tension=Fi, hooks=False)
    assert 1000 * bare.equivalent_free_length == pytest.approx(25.5, abs=0.05)
    assert 1000 * hooked.equivalent_free_length == pytest.approx(43.0, abs=0.1)
    assert hooked.equivalent_free_length - bare.equivalent_free_length == pytest.approx(
        2 * (10e-3 - 1e-3) - 1e-3 * 81.7 / 196.5)


# -------------------------------------------------------------------- selection
def test_pulley_selection_residual_is_the_rate_error_in_closed_form():
    d = lever()
    sel = se.select_springs(d, budget=0.5, n=73)
    choice = sel.choices["k"]
    real = choice.spring
    k = d.springs[0].k
    # stroke 0.1 .. 0.5 m: taut string and allowable stress
    assert 0.1 >= real.initial_tension / real.k and real.k * 0.5 <= real.max_force()
    assert choice.error == pytest.approx(abs(real.k - k) / k)
    th = sel.q[:, 0]
    assert np.allclose(sel.residual[:, 0], (k - real.k) * 0.3 * 0.2 * np.cos(th), atol=1e-9)
    assert sel.worst == pytest.approx(np.abs(sel.residual).max()) and sel.within_budget


def test_direct_selection_matches_the_designs_own_torque():
    d = lever()
    sel = se.select_springs(d, budget=0.01, mode="direct", n=41)
    real = sel.choices["k"].spring
    s = sel.design.springs[0]
    assert s.k == real.k and s.free_length == pytest.approx(real.equivalent_free_length)
    assert np.allclose(sel.residual, sel.design.generalized_force(sel.q), atol=1e-6)
    assert not sel.within_budget   # an ordinary extension spring cannot hold 0.01 N m here


def test_retuned_real_spring_lever_is_balanced_and_realizable():
    d = se.real_spring_lever()
    assert_exactly_balanced(d)
    p = d.parameters
    assert p["k"] * p["b"] * p["c"] == pytest.approx(2.0 * G * 0.5, rel=1e-9)
    real = sp.ExtensionSpring(p["d"], p["D"], p["Na"], p["F_i"])
    assert real.k == pytest.approx(d.springs[0].k, rel=1e-14)


def test_selection_refuses_what_no_spring_can_do():
    with pytest.raises(ValueError, match="no pulley spring"):
        se.select_spring(5000.0, (0.0, 2.0))
    with pytest.raises(ValueError, match="mode"):
        se.select_spring(100.0, (0.1, 0.2), mode="magic")
    with pytest.raises(ValueError, match="stroke"):
        se.select_spring(100.0, (0.3, 0.2))
    with pytest.raises(ValueError, match="retune"):
        se.select_springs(lever(), 1.0, mode="direct", retune=True)


def test_every_selected_spring_survives_its_hooks_and_the_bare_choice_does_not():
    lamp = bl.lecture.serial_2r_base_springs(masses=(1.0, 1.0), length=0.5, coms=((0.25, 0.0), (0.25, 0.0)),
                                             b=(0.3, 0.25), c=(0.15, 0.1))
    strokes = se.spring_strokes(lamp, 41)
    for cycles in (None, 1e5):
        hooked = se.select_springs(lamp, 0.1, n=41, cycles=cycles)
        bare = se.select_springs(lamp, 0.1, n=41, cycles=cycles, family=se.spring_family(hooks=False))
        for (_name, c), (_, longest) in zip(hooked.choices.items(), strokes):
            s = c.spring
            assert s.hooks and s.k * longest <= s.max_force(cycles) * (1 + 1e-12)
            for where, stress in s.stresses(s.k * longest).items():
                assert stress <= sp.allowable_stress(s.wire_diameter, cycles=cycles, where=where) * (1 + 1e-12)
        b1 = bare.choices["k1"].spring
        with_hooks = sp.ExtensionSpring(b1.wire_diameter, b1.coil_diameter, b1.active_coils, b1.initial_tension)
        assert with_hooks.k * strokes[0][1] > with_hooks.max_force(cycles)    # it would break at a hook


def test_pulley_radius_and_friction_in_the_selection():
    d = bl.realize.pulley_lever(radius=0.0)       # the lecture's link on [-90, 90] deg, string over a pulley
    rho = 0.01
    sel = se.select_springs(d, budget=1.0, n=181, pulley_radius=rho)
    assert sel.design.springs[0].pulley.radius == rho
    # the exact string model of chapter 3, differentiated independently (np.gradient on a fine grid)
    err = bl.realize.pulley_balance_error(sel.design, rho)
    assert np.abs(sel.residual).max() == pytest.approx(err.residual_torque, rel=2e-3)
    assert se.select_springs(d, budget=1.0, n=181).worst < np.abs(sel.residual).max()
    # a pulley losing 3 % of the tension adds 3 % of the spring's own torque k b c |cos t| (point pulley)
    fr_sel = se.select_springs(d, budget=1.0, n=37, pulley_friction=0.03)
    k = fr_sel.choices["k"].spring.k
    assert np.allclose(fr_sel.friction[:, 0], 0.03 * k * 0.3 * 0.2 * np.abs(np.cos(fr_sel.q[:, 0])), atol=1e-6)
    assert fr_sel.worst == pytest.approx(np.max(np.abs(fr_sel.residual) + fr_sel.friction))
    with pytest.raises(ValueError, match="pulley_friction"):
        se.select_springs(d, 1.0, pulley_friction=1.0)
    with pytest.raises(ValueError, match="mode='pulley'"):
        se.select_springs(d, 1.0, mode="direct", pulley_radius=0.01)


def test_largest_pulley_radius_is_the_edge_of_the_budget():
    d = lever()
    rho = se.largest_pulley_radius(d, 0.15, n=37)
    assert 0 < rho < 0.05
    assert se.select_springs(d, 0.15, n=37, pulley_radius=rho).within_budget
    assert not se.select_springs(d, 0.15, n=37, pulley_radius=rho + 2e-5).within_budget
    assert se.largest_pulley_radius(d, 0.15, n=37, pulley_friction=0.02) < rho   # friction spends budget too


# -------------------------------------------------------------------- tolerances
def test_monte_carlo_matches_the_closed_form_of_a_rate_error():
    d = lever()
    th = np.linspace(-np.pi / 2, np.pi / 2, 41)[:, None]
    r = to.monte_carlo(d, to.Tolerances(k=0.05), n=3000, q=th, seed=1)
    eps = r.samples["k"][:, 0] / d.springs[0].k - 1
    assert np.allclose(r.worst, np.abs(eps) * 2.0 * G * 0.5, rtol=1e-7, atol=1e-9)
    # and the distribution is that of |N(0, 0.05)| m g r: median 0.6745 sigma m g r
    assert r.quantile(0.5) / (0.05 * 2.0 * G * 0.5) == pytest.approx(0.6745, abs=0.03)


def test_monte_carlo_mass_error_and_uniform_tolerances():
    d = lever()
    th = np.linspace(-np.pi / 2, np.pi / 2, 41)[:, None]
    r = to.monte_carlo(d, {"mass": 0.02}, n=500, q=th, distribution="uniform")
    s = r.samples["load_scale"][:, 0]
    assert np.all(np.abs(s - 1) <= 0.02)
    assert np.allclose(r.worst, np.abs(s - 1) * 2.0 * G * 0.5, rtol=1e-7, atol=1e-9)


@settings(max_examples=15, deadline=None)
@given(st.integers(0, 10_000))
def test_vectorized_generalized_force_equals_the_energy_derivative(seed):
    arm = bl.singh.serial_2r_min_preload()
    rng = np.random.default_rng(seed)
    springs = [bl.Spring(s.k * rng.uniform(0.8, 1.2), rng.uniform(-0.05, 0.05), (s.a.body, s.a.point + rng.normal(0, 0.02, 2)),
                         (s.b.body, s.b.point + rng.normal(0, 0.02, 2))) for s in arm.springs]
    loads = [bl.Load(ld.body, ld.point, tuple(np.asarray(ld.force) * rng.uniform(0.9, 1.1))) for ld in arm.loads]
    built = arm.replace(springs=springs, loads=loads)
    q = rng.uniform(-np.pi, np.pi, (20, 2))
    Q = fo.batch_generalized_force(arm, q, k=[[s.k for s in springs]], free_length=[[s.free_length for s in springs]],
                                   a_points=[[s.a.point for s in springs]], b_points=[[s.b.point for s in springs]],
                                   load_scale=[[ld.force[1] / l0.force[1] for ld, l0 in zip(loads, arm.loads)]])
    assert np.allclose(Q[0], built.generalized_force(q), atol=2e-6)


def test_sensitivities_rank_the_tolerances():
    s = to.sensitivities(lever(), to.Tolerances(k=0.05, mass=0.001, attachment=0.0), n=400, grid=21)
    assert list(s)[0] == "all" and list(s)[1] == "k" and "attachment" not in s
    assert s["k"] > 10 * s["mass"]


def test_monte_carlo_refuses_bad_input():
    with pytest.raises(ValueError, match="unknown tolerances"):
        to.monte_carlo(lever(), {"stiffness": 0.1})
    with pytest.raises(ValueError, match=">= 0"):
        to.monte_carlo(lever(), to.Tolerances(k=-0.1))
    with pytest.raises(ValueError, match="distribution"):
        to.monte_carlo(lever(), to.Tolerances(k=0.1), distribution="cauchy")


# ---------------------------------------------------------------------- friction
def test_friction_band_of_the_balanced_link_is_tau_over_g_r():
    tau, r = 0.15, 0.5
    band = fr.friction_band(lever(), tau, 1, (r, 0.0))
    assert (band.low, band.high) == pytest.approx((-tau / (G * r), tau / (G * r)), rel=1e-9)
    assert not band.empty
    # hand calculation: an extra 10 g at the tip needs 0.01 g r cos(theta) of holding torque
    heavier = pl.add_payload(lever(), 0.01, 1, (r, 0.0))
    q, ok = fr.stays_put(heavier, 0.01 * G * r * 1.001, n=41)
    assert ok.all()
    q, ok = fr.stays_put(heavier, 0.01 * G * r * 0.9, n=41)
    assert np.array_equal(ok, 0.01 * G * r * np.abs(np.cos(q[:, 0])) <= 0.01 * G * r * 0.9 + 1e-12)


def test_hand_force_on_an_unbalanced_link():
    heavier = pl.add_payload(lever(), 0.1, 1, (0.5, 0.0))
    q, up, down = fr.hand_force(heavier, 0.2, 1, (0.4, 0.0), n=37)
    imbalance = 0.1 * G * 0.5 * np.cos(q[:, 0])
    assert np.allclose(up, np.maximum(imbalance + 0.2, 0) / 0.4, atol=1e-7)
    assert np.allclose(down, np.maximum(-imbalance + 0.2, 0) / 0.4, atol=1e-7)


def test_pin_friction_grows_with_the_pin_load():
    """Lever: the pin carries the weight and the spring's pull k (B - C), so tau = mu r |m g (0, -1) + k (B - C)|."""
    d = lever()
    k = d.springs[0].k
    th = np.linspace(-np.pi, np.pi, 13)
    q, t = fr.pin_friction(d, 0.15, 0.004, q=th[:, None])
    C = 0.2 * np.stack([np.cos(th), np.sin(th)], -1)
    load = np.array([0.0, -2.0 * G]) + k * (np.array([0.0, 0.3]) - C)
    assert np.allclose(t[:, 0], 0.15 * 0.004 * np.linalg.norm(load, axis=-1), rtol=1e-9)
    assert t.min() < t.max()          # not a constant: largest where the spring pulls the pin hardest
    with pytest.raises(ValueError, match="mu"):
        fr.pin_friction(d, -0.1, 0.004)


def test_friction_refuses_bad_input():
    arm = bl.singh.serial_2r_min_preload()
    with pytest.raises(ValueError, match="one per joint"):
        fr.joint_friction(arm, [0.1, 0.1, 0.1])
    with pytest.raises(ValueError, match=">= 0"):
        fr.joint_friction(arm, -0.1)
    with pytest.raises(ValueError, match="direction"):
        fr.hand_force(arm, 0.1, 2, (1.0, 0.0))


# ------------------------------------------------------------------------ forces
def test_joint_loads_against_an_independent_statics_of_the_2r():
    arm = bl.singh.serial_2r_min_preload()
    rng = np.random.default_rng(3)
    built = arm.replace(springs=[bl.Spring(s.k * rng.uniform(0.9, 1.1), 0.0, s.a, s.b) for s in arm.springs])
    q = rng.uniform(-np.pi, np.pi, (30, 2))
    jl = fo.joint_loads(built, q)
    assert jl.children == (frozenset({1, 2}), frozenset({2}))
    # statics by hand: every force on link 2 (its weight, the pull of springs 2 and 3)
    total2 = np.zeros((30, 2))
    total12 = np.zeros((30, 2))
    for ld in built.loads:
        total12 += ld.force
        if ld.body == 2:
            total2 += ld.force
    for s in built.springs:
        a, b = built.world_points(q, [s.a, s.b]).transpose(1, 0, 2)
        pull = s.k * (a - b)            # a ZFL spring pulls its end b towards a with k |a - b|
        total12 += pull
        if s.b.body == 2:
            total2 += pull
    assert np.allclose(jl.force[:, 1], -total2, atol=1e-9)
    assert np.allclose(jl.force[:, 0], -total12, atol=1e-9)
    # virtual work: joint 1 turns both links (d theta_1 = d theta_2), joint 2 only link 2
    Q = built.generalized_force(q)
    assert np.allclose(jl.torque[:, 0], Q[:, 0] + Q[:, 1], atol=1e-6)
    assert np.allclose(jl.torque[:, 1], Q[:, 1], atol=1e-6)


def test_joint_loads_hand_case_and_balanced_torques():
    d = lever()
    th = np.linspace(-np.pi, np.pi, 13)[:, None]
    jl = fo.joint_loads(d, th)
    C = 0.2 * np.stack([np.cos(th[:, 0]), np.sin(th[:, 0])], -1)
    spring_pull = d.springs[0].k * (np.array([0.0, 0.3]) - C)
    assert np.allclose(jl.force[:, 0], -(spring_pull + [0.0, -2.0 * G]), atol=1e-9)
    assert np.abs(jl.torque).max() < 1e-9
    assert np.allclose(fo.spring_forces(d, th)[:, 0], d.springs[0].k * np.linalg.norm(np.array([0.0, 0.3]) - C, axis=-1))


def test_free_choices_trade_spring_force_not_energy():
    W, l = 10.0, 0.5
    a = [0.25, 0.5, 1.0]
    c = fo.compare_free_choices(lambda ax: bl.singh.min_preload_lever(W, l, ax), a, n=40)
    assert np.allclose(c["energy"], W * l)                                 # PE_min = W l for every choice
    assert np.allclose(c["max_spring_force"], [2 * W * l / x for x in a])  # k (2 a_x), k = W l / a_x^2
    assert np.all(np.diff(c["max_joint_load"]) < 0) and c["max_holding_torque"].max() < 1e-9


def test_joint_loads_refuse_a_closed_loop():
    with pytest.raises(ValueError, match="tree"):
        fo.joint_loads(bl.lecture.serial_2r_parallelogram(), [[0.1, 0.2]])


# ----------------------------------------------------------------------- payload
def test_rebalance_lever_by_anchor_and_by_stiffness():
    d = lever()
    heavy = pl.add_payload(d, 0.5, 1, (0.5, 0.0))
    by_anchor = pl.rebalance(heavy)
    assert by_anchor.springs[0].a.point == pytest.approx((0.0, 2.5 * G * 0.5 / (d.springs[0].k * 0.2)), abs=1e-12)
    by_k = pl.rebalance(heavy, "stiffness")
    assert by_k.springs[0].k == pytest.approx(2.5 * G * 0.5 / (0.3 * 0.2), rel=1e-9)
    for new in (by_anchor, by_k):
        assert new.balance_report().balanced


def test_adjustment_work_closed_form():
    d = lever()
    new = pl.rebalance(pl.add_payload(d, 0.5, 1, (0.5, 0.0)))
    b, b2, c, k = 0.3, new.springs[0].a.point[1], 0.2, d.springs[0].k
    th = np.linspace(-1.5, 1.5, 11)[:, None]
    q, W = pl.adjustment_work(d, new, th)
    assert np.allclose(W, 0.5 * k * (b2 - b) * (b2 + b - 2 * c * np.sin(th[:, 0])), atol=1e-10)


def test_rebalance_2r_by_anchors_and_refusals():
    arm = bl.singh.serial_2r_min_preload()
    heavy = pl.add_payload(arm, 0.5, 2, (2.0, 0.0))
    assert pl.rebalance(heavy).balance_report().balanced
    with pytest.raises(ValueError, match="cannot balance"):
        pl.rebalance(heavy, "stiffness")
    with pytest.raises(ValueError, match="adjust"):
        pl.rebalance(heavy, "colour")
    with pytest.raises(ValueError, match="ZFL"):
        pl.rebalance(bl.lecture.single_link_ordinary_spring(2.0, 0.5, 0.3, 0.2, 0.05))


def test_extension_spring_refuses_bad_input():
    with pytest.raises(ValueError, match="index"):
        sp.ExtensionSpring(1e-3, 2e-3, 10)
    with pytest.raises(ValueError, match="initial_tension"):
        sp.ExtensionSpring(1e-3, 8e-3, 10, initial_tension=-1.0)
    with pytest.raises(TypeError, match="material"):
        sp.ExtensionSpring(1e-3, 8e-3, 10, material="steel")
    with pytest.raises(ValueError, match="wire_diameter"):
        sp.spring_rate(-1e-3, 8e-3, 10)
    with pytest.raises(ValueError, match="cycles"):
        sp.allowable_stress(1e-3, cycles=0.5)
    with pytest.raises(TypeError, match="hooks"):
        sp.ExtensionSpring(1e-3, 8e-3, 10, hooks="standard")
    with pytest.raises(ValueError, match="bend_radius"):
        sp.hook_stresses(1.0, 1e-3, 8e-3, bend_radius=-1e-3)
    with pytest.raises(ValueError, match="hook index C2"):
        sp.hook_stresses(1.0, 1e-3, 8e-3, root_radius=0.4e-3)       # a bend tighter than the wire


# ------------------------------------------------- review of issue 21 (regressions)
def lamp_arm():
    return bl.lecture.serial_2r_base_springs(masses=(1.0, 1.0), length=0.5, coms=((0.25, 0.0), (0.25, 0.0)),
                                             b=(0.3, 0.25), c=(0.15, 0.1))


def test_pulley_strings_are_routed_to_stay_on_their_pulleys():
    """The lamp arm's attachments swing only asin(c/b) about straight down from the pulleys; a string
    coming down onto the pulley would have to bend the other way for half of each turn."""
    from balancelab.methods.practice import routing as ro
    from balancelab.methods.realize import pulley_string
    lamp = lamp_arm()
    sel = se.select_springs(lamp, 0.1, n=41, pulley_radius=0.001)
    q = fo.configurations(lamp, None, 41)
    for i, s in enumerate(sel.design.springs):
        p = s.pulley
        C = sel.design.world_points(q, [s.b])[..., 0, :]
        st_ = pulley_string(s.a.point, p.radius, C, p.spring_direction, p.turn)
        g = -np.asarray(p.spring_direction) / np.linalg.norm(p.spring_direction)   # incoming direction
        u = C - st_.tangent_out
        u /= np.linalg.norm(u, axis=-1, keepdims=True)                             # outgoing direction
        # the string turns by +wrap (sense turn) from g to u, and never by more than a half turn here
        assert np.allclose(p.turn * (g[0] * u[:, 1] - g[1] * u[:, 0]), np.sin(st_.wrap), atol=1e-9)
        assert np.allclose(g @ u.T, np.cos(st_.wrap), atol=1e-9)
        half = math.asin((0.15, 0.1)[i] / (0.3, 0.25)[i])      # c / b of each spring
        assert 0 < st_.wrap.min() and st_.wrap.max() < math.pi
        assert np.ptp(st_.wrap) == pytest.approx(2 * half, abs=0.02)
    assert sel.within_budget            # a 1 mm pulley fits once the strings stay on their pulleys
    # the routing that makes the string bend the wrong way is refused, naming it
    from balancelab.core.elements import Pulley, Spring
    down = lamp.replace(springs=[Spring(s.k, s.free_length, s.a, s.b, name=s.name,
                                        realization=Pulley(0.0, (0.0, 1.0), 1)) for s in lamp.springs])
    with pytest.raises(ValueError, match="bend the other way"):
        se.select_springs(down, 0.1, n=41, pulley_radius=0.001)
    assert not ro.stays_wrapped(ro.string_wrap(down, 0, down.springs[0].pulley, 0.001, 41))


def test_hooked_spring_counts_body_coils_per_shigley_10_39():
    for m in (sp.MUSIC_WIRE, sp.STAINLESS_302):
        s = sp.ExtensionSpring(1e-3, 8e-3, 30, material=m)
        assert s.active_coils - s.body_coils == pytest.approx(m.shear_modulus / m.youngs_modulus, rel=1e-14)
        assert s.k == pytest.approx(m.shear_modulus * 1e-12 / (8 * 8e-3 ** 3 * 30), rel=1e-14)   # rate from N_a
        assert s.coil_length == pytest.approx(1e-3 * (s.body_coils + 1), rel=1e-14)
    bare = sp.ExtensionSpring(1e-3, 8e-3, 30, hooks=False)
    assert bare.body_coils == 30
    with pytest.raises(ValueError, match="active_coils"):
        sp.ExtensionSpring(1e-3, 8e-3, 0.3)


def test_unwindable_or_breaking_initial_tension_is_flagged_or_refused():
    bare = sp.ExtensionSpring(1e-3, 8e-3, 40)
    zfl = sp.ExtensionSpring(1e-3, 8e-3, 40, initial_tension=bare.k * bare.body_length)
    lo, hi = zfl.initial_tension_range()
    assert zfl.is_zfl and zfl.initial_tension > hi and not zfl.windable
    assert sp.ExtensionSpring(1e-3, 8e-3, 40, initial_tension=hi).windable
    with pytest.raises(ValueError, match=r"initial_tension.*\[0, "):
        sp.ExtensionSpring(1e-3, 8e-3, 40, initial_tension=100.0)
    with pytest.raises(ValueError, match="force"):
        bare.stresses(-10.0)


def test_fits_refuse_inputs_outside_their_range():
    for d in (10e-3, 0.05e-3):
        with pytest.raises(ValueError, match=r"wire_diameter must be in \[0.0001, 0.0065\]"):
            sp.tensile_strength(d)
    with pytest.raises(ValueError, match=r"wire_diameter must be in \[0.0003, 0.0025\]"):
        sp.tensile_strength(3e-3, sp.STAINLESS_302)
    for C in (1.0, 20.0):
        with pytest.raises(ValueError, match=r"index C must be in \[3, 16\]"):
            sp.initial_stress_range(C)
    with pytest.raises(ValueError, match="tolerance k"):
        to.Tolerances(k=-0.03)
    with pytest.raises(ValueError, match="max_rate_error"):
        se.select_spring(1e7, (0.1, 0.5))
    assert se.select_spring(163.5, (0.1, 0.5), max_rate_error=0.01).error <= 0.01
    fam = se.spring_family(sp.STAINLESS_302, active_coils=[20])
    assert fam["d"].min() >= 0.3e-3 and fam["d"].max() <= 2.5e-3


def test_max_length_bounds_the_spring_in_service():
    lamp = lamp_arm()
    free = se.select_springs(lamp, 0.1, n=41)
    strokes = se.spring_strokes(lamp, 41)

    def longest(choice, stroke):           # spring length at the longest passed-over length x_max
        s = choice.spring
        return s.body_length + stroke[1] - s.initial_tension / s.k

    assert max(longest(c, st_) for c, st_ in zip(free.choices.values(), strokes)) > 0.5
    short = se.select_springs(lamp, 0.1, n=41, max_length=0.6)
    assert all(longest(c, st_) <= 0.6 for c, st_ in zip(short.choices.values(), strokes))
    # the stroke alone is 0.45 m: no spring passes it within 0.3 m
    with pytest.raises(ValueError, match="max_length"):
        se.select_springs(lamp, 0.1, n=41, max_length=0.3)
