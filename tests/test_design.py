"""The Design contract: shapes, vectorization, reachability, reports, symbolic energy."""
from __future__ import annotations

import numpy as np
import pytest

import balancelab as bl
from balancelab import Joint, Load, Spring


def test_poses_vectorized_over_any_leading_shape():
    d = bl.singh.serial_2r_min_preload()
    q = d.sample(12).reshape(3, 4, 2)
    poses = d.poses(q)
    assert poses.shape == (3, 4, 3, 3)
    # body 2's origin is the tip of body 1
    tip = np.stack([1.5 * np.cos(q[..., 0]), 1.5 * np.sin(q[..., 0])], -1)
    np.testing.assert_allclose(poses[..., 2, :2], tip, atol=1e-15)
    np.testing.assert_allclose(poses[..., 2, 2], q[..., 1])
    e = d.potential_energy(q)
    assert e.total.shape == (3, 4)
    np.testing.assert_allclose(e.total, e.load + e.spring)


def test_one_dof_accepts_plain_angles():
    d = bl.singh.lacoste_lever(weight=10.0, length=0.5, a_x=0.2, b_y=0.3)
    assert d.poses(np.linspace(0, 1, 7)).shape == (7, 2, 3)
    assert d.poses(0.3).shape == (2, 3)
    assert d.potential_energy(np.zeros((2, 5, 1))).total.shape == (2, 5)


def test_energy_of_a_load_and_a_spring_by_hand():
    d = bl.Design("hand", ("ground", "bar"), [Joint(0, (0, 0), 1, (0, 0))], bl.lever_kinematics(),
                  [Load(1, (2.0, 0.0), (0.0, -3.0))], [Spring(4.0, 0.5, (0, (0.0, 1.0)), (1, (1.0, 0.0)))])
    th = 0.7
    y = 2 * np.sin(th)
    length = np.hypot(np.cos(th), np.sin(th) - 1.0)
    e = d.potential_energy(th)
    assert e.load == pytest.approx(3.0 * y, rel=1e-15)
    assert e.spring == pytest.approx(0.5 * 4.0 * (length - 0.5) ** 2, rel=1e-14)


def test_unreachable_configuration_is_reported_not_wrong():
    d = bl.singh.singh_fourbar()
    lo, hi = d.q_range[0]
    with pytest.raises(bl.UnreachableConfiguration, match="cannot be reached; valid range"):
        d.poses(hi + 0.1)
    mask = d.reachable([lo + 0.01, hi + 0.1])
    assert mask.tolist() == [True, False]
    with pytest.raises(bl.UnreachableConfiguration):
        bl.singh.scissors_lift().potential_energy(np.pi / 2 + 0.2)


def test_sample_is_reachable_spread_and_seeded():
    d = bl.singh.peaucellier_board()
    q = d.sample(1000, seed=5)
    assert q.shape == (1000, 1)
    assert d.reachable(q).all()
    lo, hi = d.q_range[0]
    assert q.min() < lo + 0.05 * (hi - lo) and q.max() > hi - 0.05 * (hi - lo)
    np.testing.assert_array_equal(q, d.sample(1000, seed=5))
    with pytest.raises(ValueError, match=r"integer >= 1"):
        d.sample(0)


def test_report_flags_an_unbalanced_design_and_names_the_worst_configuration():
    r = bl.lecture.single_link_ordinary_spring(2.0, 0.5, 0.3, 0.2, 0.05).balance_report()
    assert not r.balanced and r.variation > 1e-3 and r.residual > 1e-3
    assert "NOT balanced" in str(r)
    assert r.worst_q.shape == (1,)


def test_report_scale_does_not_depend_on_the_origin():
    here = bl.lecture.fourbar_counterweights()
    far = bl.lecture.fourbar_counterweights(A=(10.0, 100.0), B=(10.7, 100.0))
    r1, r2 = here.balance_report(), far.balance_report()
    assert r2.scale == pytest.approx(r1.scale, rel=1e-9)
    assert r1.balanced and r2.balanced
    assert abs(r2.energy - r1.energy) > 100  # the energies differ, the verdict and scale do not


def test_generalized_force_matches_the_analytic_torque():
    d = bl.lecture.single_link_ordinary_spring(2.0, 0.5, 0.3, 0.2, 0.05)
    q = np.linspace(-2, 2, 9)
    h = 1e-7
    num = (d.potential_energy(q + h).total - d.potential_energy(q - h).total) / (2 * h)
    np.testing.assert_allclose(d.generalized_force(q)[:, 0], num, rtol=1e-5, atol=1e-8)


def test_nothing_to_balance_is_an_error():
    d = bl.Design("empty", ("ground", "bar"), [Joint(0, (0, 0), 1, (0, 0))], bl.lever_kinematics())
    with pytest.raises(ValueError, match="nothing in this design stores energy"):
        d.balance_report()


def test_bad_q_shapes_and_types():
    d = bl.singh.serial_2r_min_preload()
    with pytest.raises(ValueError, match=r"shape \(\.\.\., 2\)"):
        d.poses([0.1, 0.2, 0.3])
    with pytest.raises(TypeError, match="radians"):
        d.poses("north")
    with pytest.raises(ValueError, match="finite"):
        d.poses([np.nan, 0.0])


@pytest.mark.parametrize("bad, message", [
    (dict(k=0.0), "stiffness k"), (dict(k=-3.0), "stiffness k"), (dict(k=np.inf), "finite"),
    (dict(k="stiff"), "real number"), (dict(a=(0, (0.0,))), "two coordinates"),
    (dict(b=(0, (0.0, 0.0))), "two different bodies"), (dict(realization="rubber"), "realization"),
])
def test_spring_validation(bad, message):
    args = dict(k=1.0, free_length=0.0, a=(0, (0.0, 1.0)), b=(1, (1.0, 0.0)))
    args.update(bad)
    with pytest.raises((ValueError, TypeError), match=message):
        Spring(**args)


def test_weight_and_load_validation():
    with pytest.raises(ValueError, match="mass must be > 0"):
        bl.gravity_load(1, (0, 0), 0.0)
    with pytest.raises(ValueError, match="body index >= 0"):
        Load(-1, (0, 0), (0, -1))
    with pytest.raises(ValueError, match="load kind"):
        Load(1, (0, 0), (0, -1), kind="magnet")
    assert bl.gravity_load(1, (0, 0), 2.0).mass == pytest.approx(2.0)


def test_design_validation_names_the_bad_body():
    with pytest.raises(ValueError, match="acts on body 5"):
        bl.Design("x", ("ground", "bar"), [Joint(0, (0, 0), 1, (0, 0))], bl.lever_kinematics(),
                  [Load(5, (0, 0), (0, -1))])
    with pytest.raises(ValueError, match="kinematics describes 2 bodies"):
        bl.Design("x", ("ground", "bar", "other"), [], bl.lever_kinematics())


def test_symbolic_energy_of_the_lever_is_the_papers_eq1():
    import sympy as sp

    d = bl.singh.lacoste_lever(weight=10.0, length=0.5, a_x=0.2, b_y=0.3)
    W, l, ax, by, k = sp.symbols("W l a_x b_y k", positive=True)
    th = sp.Symbol("theta", real=True)
    eq1 = k / 2 * (ax ** 2 + by ** 2) + (W * l - k * ax * by) * sp.sin(th)
    assert sp.simplify(d.potential_energy_symbolic() - eq1) == 0
    assert d.balance_conditions() == [sp.Eq(W * l - ax * by * k, 0)]


def test_trig_coefficients_vanish_for_balanced_and_not_for_unbalanced():
    good = bl.singh.serial_2r_simplified()
    assert good.conditions_residual() < 1e-12
    bad = good.replace(springs=[Spring(s.k * 1.01, 0.0, s.a, s.b, s.name) for s in good.springs])
    assert bad.conditions_residual() > 1e-4


def test_symbolic_derivation_is_cached():
    d = bl.singh.serial_2r_min_preload()
    first = d.balance_conditions()
    assert d.balance_conditions() == first
    assert ("coeffs", True) in d._sym_cache


def test_four_bar_with_two_circuits_picks_the_one_asked_for():
    from balancelab.mechanisms.fourbar import FourBarKinematics

    args = ((0.0, 0.0), (1.0, 0.0), 0.8, 0.5, 0.2)  # the crank tip must stay 0.3-0.7 m from B
    widest = FourBarKinematics(*args).q_range[0]
    upper = FourBarKinematics(*args, circuit=0.6).q_range[0]
    lower = FourBarKinematics(*args, circuit=-0.6).q_range[0]
    assert upper[0] > 0 and lower[1] < 0
    np.testing.assert_allclose(upper, -lower[::-1], atol=1e-9)
    assert any(np.allclose(widest, r, atol=1e-9) for r in (upper, lower))
    for lo, hi in (upper, lower):  # the ends are where the tip is 0.3 or 0.7 m from B
        for t in (lo, hi):
            D = np.hypot(0.8 * np.cos(t) - 1.0, 0.8 * np.sin(t))
            assert min(abs(D - 0.3), abs(D - 0.7)) < 1e-9
    with pytest.raises(ValueError, match="cannot assemble at the crank angle"):
        FourBarKinematics(*args, circuit=0.0)


# ---------------------------------------------------------------- 0.2 core contracts
def test_a_design_is_immutable_and_changed_with_replace():
    d = bl.lecture.single_link_spring(2.0, 0.5, 0.3, 0.2)
    for field, value in (("springs", ()), ("loads", ()), ("name", "x"), ("kinematics", None)):
        with pytest.raises(AttributeError, match=r"immutable: use design.replace\(" + field):
            setattr(d, field, value)
    with pytest.raises(TypeError):
        d.parameters["k"] = 1.0
    with pytest.raises(TypeError):
        d.labels["A"] = (0, (1.0, 1.0))
    assert d.balance_report().balanced  # nothing above changed it
    heavier = d.replace(loads=[bl.gravity_load(1, (0.5, 0.0), 2.2)])
    assert not heavier.balance_report().balanced and d.balance_report().balanced
    with pytest.raises(TypeError, match="unknown fields"):
        d.replace(prismatic=[])


def test_joints_that_disagree_with_the_kinematics_are_refused():
    kin = bl.serial_2r_kinematics(1.0)
    good = [Joint(0, (0.0, 0.0), 1, (0.0, 0.0)), Joint(1, (1.0, 0.0), 2, (0.0, 0.0))]
    bl.Design("2R", ("ground", "a", "b"), good, kin, [bl.gravity_load(2, (0.5, 0.0), 1.0)])
    gap = [good[0], Joint(1, (1.2, 0.0), 2, (0.0, 0.0))]  # a 0.2 m joint gap
    with pytest.raises(ValueError, match=r"joint 1 .* opens by 0.2 m"):
        bl.Design("2R", ("ground", "a", "b"), gap, kin, [bl.gravity_load(2, (0.5, 0.0), 1.0)])
    with pytest.raises(TypeError, match="must be a balancelab Kinematics"):
        bl.Design("2R", ("ground", "a", "b"), good, object())


@pytest.mark.parametrize("end", [0, 1])
def test_generalized_force_at_the_range_limits_is_the_one_sided_derivative(end):
    """At an end of the range only one side is reachable: the derivative must not be halved."""
    d = bl.lecture.single_link_spring(2.0, 0.5, 0.3, 0.2).replace(
        loads=[bl.gravity_load(1, (0.5, 0.0), 2.5)],
        kinematics=bl.lever_kinematics(q_range=(-1.0, 1.0)))
    q = d.q_range[0, end]
    h = 1e-6
    inside = q + h if end == 0 else q - h
    one_sided = (d.potential_energy(inside).total - d.potential_energy(q).total) / (inside - q)
    # the analytic torque: spring + weight, dV/dtheta
    k, b, c = d.parameters["k"], 0.3, 0.2
    exact = k * b * c * -np.cos(q) + 2.5 * bl.G * 0.5 * np.cos(q)
    assert d.generalized_force(q)[0] == pytest.approx(exact, rel=1e-5)
    assert one_sided == pytest.approx(exact, rel=1e-4)
    assert not d.reachable(q - h if end == 0 else q + h)


def test_every_mechanism_implements_the_kinematics_contract():
    import inspect

    from balancelab.core import Kinematics

    kinematics = [bl.lever_kinematics(), bl.serial_2r_kinematics(1.0), bl.scissors_kinematics(0.5),
                  bl.FourBarKinematics((0, 0), (0.7, 0), 0.3, 0.8, 0.6),
                  bl.PeaucellierKinematics(0.22326, 0.7505, 0.363)]
    for kin in kinematics:
        assert isinstance(kin, Kinematics)
        q = np.linspace(*kin.q_range[0], 11)[1:-1, None]
        if kin.dof == 2:
            q = np.hstack([q, q[::-1]])
        poses, ok = kin.poses(q)
        assert poses.shape == (len(q), kin.nbodies, 3) and ok.all()
        assert np.array_equal(kin.reachable(q), ok)
    assert inspect.isabstract(Kinematics)
    with pytest.raises(TypeError):
        Kinematics()


def test_kinematics_joint_error_is_honest_where_the_loop_does_not_close():
    # a crank that cannot turn fully (Singh's four-bar): beyond its limit the loop does not close
    kin = bl.FourBarKinematics((0, 0), (4.0, 0), 1.5, 4.0, 1.0)
    joints = bl.fourbar_joints(kin)
    lo, hi = kin.q_range[0]
    assert hi - lo < 2 * np.pi
    err = kin.joint_error(np.array([[0.5 * (lo + hi)], [hi + 0.1], [lo - 0.1]]), joints)
    assert err[0] < 1e-12 and np.isinf(err[1]) and np.isinf(err[2])
    # a fully rotating crank closes at every angle: one more turn is the same configuration
    kin = bl.FourBarKinematics((0, 0), (0.7, 0), 0.3, 0.8, 0.6)
    lo, hi = kin.q_range[0]
    err = kin.joint_error(np.array([[0.5 * (lo + hi)], [hi + 1.0]]), bl.fourbar_joints(kin))
    assert err.max() < 1e-12


def test_validation_of_sequences_names_the_item():
    from balancelab.core.validation import finite_reals, planar_points

    with pytest.raises(ValueError, match=r"masses\[1\] \(kg\) must be > 0"):
        finite_reals("masses (kg)", (1.0, -2.0), 2, positive=True)
    with pytest.raises(ValueError, match="must be 3 numbers, got 2"):
        finite_reals("a_x (m)", (1.0, 2.0), 3)
    with pytest.raises(TypeError, match="must be 2 points"):
        planar_points("coms (m)", 5.0, 2)
