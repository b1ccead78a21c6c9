"""The linkage builder: its numeric kinematics against closed forms, its degrees of freedom, its errors."""
from __future__ import annotations

import numpy as np
import pytest

import balancelab as bl
from balancelab.mechanisms.linkage import LinkageKinematics
from balancelab.methods.general.examples import fourbar_issue11, parallelogram_lamp, watt_sixbar


def fourbar_linkage(crank, coupler, rocker, ground, guess, name="four-bar"):
    lk = bl.Linkage(name)
    lk.revolute("ground", (0.0, 0.0), "crank", (0.0, 0.0))
    lk.revolute("crank", (crank, 0.0), "coupler", (0.0, 0.0))
    lk.revolute("coupler", (coupler, 0.0), "rocker", (rocker, 0.0))
    lk.revolute("rocker", (0.0, 0.0), "ground", (ground, 0.0))
    return lk.build(guess=guess)


def wrap(a):
    return np.angle(np.exp(1j * np.asarray(a)))


def random_fourbar(rng):
    """Random assemblable four-bar lengths and a guess that assembles it (rocker up or down)."""
    while True:
        crank, coupler, rocker, ground = rng.uniform(0.2, 1.0, 4)
        try:
            bl.mechanisms.check_assembly(crank, coupler, rocker, ground)
        except ValueError:
            continue
        return crank, coupler, rocker, ground, {"crank": rng.uniform(-np.pi, np.pi),
                                                 "rocker": rng.uniform(-np.pi, np.pi)}


@pytest.mark.parametrize("seed", range(12))
def test_random_fourbars_match_the_closed_form_on_their_circuit(seed):
    rng = np.random.default_rng(seed)
    crank, coupler, rocker, ground, guess = random_fourbar(rng)
    d = fourbar_linkage(crank, coupler, rocker, ground, guess)
    kin = d.kinematics
    q0 = kin.assembled[1]
    # the closed form on the same branch and circuit
    ref = None
    for branch in (1, -1):
        fb = bl.FourBar((0.0, 0.0), (ground, 0.0), crank, coupler, rocker, (0.5 * coupler, 0.0), branch=branch,
                        circuit=float(wrap(q0)))
        if abs(wrap(fb.kinematics.poses([[q0]])[0][0, 3, 2] - kin.assembled[3])) < 1e-8:
            ref = fb.kinematics
    assert ref is not None
    lo, hi = d.q_range[0]
    rlo, rhi = ref.q_range[0]
    if kin.full_turn:
        assert rhi - rlo >= 2 * np.pi - 1e-9
    else:  # the same interval of crank angles (up to whole turns), to the bisection's precision
        shift = 2 * np.pi * np.round((lo - rlo) / (2 * np.pi))
        assert abs(lo - rlo - shift) < 1e-7 and abs(hi - rhi - shift) < 1e-7
    q = d.sample(400, seed=seed)
    mine = d.poses(q)
    theirs, ok = ref.poses(rlo + np.mod(q - rlo, 2 * np.pi))  # the same angles, inside the closed form's range
    assert ok.all()
    assert np.abs(mine[..., :2] - theirs[..., :2]).max() < 1e-12
    assert np.abs(wrap(mine[..., 2] - theirs[..., 2])).max() < 1e-11
    assert d.joint_error(q).max() < 1e-12


def test_the_issue_example_builds_a_grashof_crank_rocker():
    d = fourbar_issue11()
    assert d.bodies == ("ground", "crank", "coupler", "rocker") and d.q_names == ("theta_1",)
    assert d.kinematics.full_turn and d.kinematics.grubler == 1 and d.kinematics.redundant == 0
    assert len(d.loads) == 2 and d.loads[0].force == (0.0, -2.0 * bl.G)


def test_configurations_outside_the_circuit_are_unreachable_and_say_so():
    d = fourbar_linkage(1.0, 1.0, 0.6, 1.2, {"crank": 1.5, "rocker": 2.0})  # a non-Grashof linkage
    lo, hi = d.q_range[0]
    assert not d.kinematics.full_turn
    q = np.array([[lo - 0.05], [0.5 * (lo + hi)], [hi + 0.05]])
    assert d.reachable(q).tolist() == [False, True, False]
    err = d.kinematics.joint_error(q, d.joints)
    assert np.isinf(err[0]) and err[1] < 1e-12 and np.isinf(err[2])
    with pytest.raises(bl.UnreachableConfiguration):
        d.poses(q)


def test_the_circuit_is_followed_without_jumps():
    d = fourbar_issue11()
    lo, hi = d.q_range[0]
    sweep = np.linspace(lo, hi, 20001)
    rng = np.random.default_rng(0)
    order = rng.permutation(len(sweep))  # solved in random order, compared in sweep order
    angles = np.empty((len(sweep), 4))
    angles[order] = d.poses(sweep[order])[..., 2]
    assert np.abs(wrap(np.diff(angles, axis=0))).max() < 10 * (hi - lo) / 20000 * 3


def random_tree(rng, n):
    lengths = rng.uniform(0.2, 1.0, n)
    lk = bl.Linkage("chain")
    prev, tip = "ground", (0.0, 0.0)
    for i, length in enumerate(lengths):
        point = (0.0, 0.0) if i else tuple(rng.uniform(-0.3, 0.3, 2))
        lk.revolute(prev, tip, f"link{i + 1}", point)
        prev, tip = f"link{i + 1}", (length, rng.uniform(-0.1, 0.1))
    return lk.build(), lengths


@pytest.mark.parametrize("seed", range(6))
def test_random_chains_are_trees_with_every_angle_a_coordinate(seed):
    rng = np.random.default_rng(seed)
    n = 2 + seed % 2
    d, _ = random_tree(rng, n)
    assert d.dof == n and d.kinematics.full_turn and not d.kinematics.topology.loops
    q = rng.uniform(-10, 10, (200, n))
    assert d.reachable(q).all() and d.joint_error(q).max() < 1e-12
    np.testing.assert_allclose(d.poses(q)[..., 1:, 2], q)


def test_tree_energy_is_symbolic_too():
    import sympy as sp

    d, _ = random_tree(np.random.default_rng(3), 2)
    lk_mass = bl.Linkage("arm")
    lk_mass.revolute("ground", (0.0, 0.0), "a", (0.0, 0.0))
    lk_mass.revolute("a", (0.5, 0.0), "b", (0.0, 0.0))
    lk_mass.mass("b", 2.0, com=(0.3, 0.0))
    arm = lk_mass.build()
    t1, t2 = arm.kinematics.symbols()
    expr = arm.potential_energy_symbolic(parametric=False)
    assert sp.simplify(expr - 2.0 * bl.G * (0.5 * sp.sin(t1) + 0.3 * sp.sin(t2))) == 0
    assert d.kinematics.independent_symbols


def test_five_bar_has_two_degrees_of_freedom():
    lk = bl.Linkage("five-bar")
    lk.revolute("ground", (0.0, 0.0), "a", (0.0, 0.0))
    lk.revolute("a", (0.5, 0.0), "b", (0.0, 0.0))
    lk.revolute("b", (1.0, 0.0), "c", (1.0, 0.0))
    lk.revolute("c", (0.0, 0.0), "d", (0.5, 0.0))
    lk.revolute("d", (0.0, 0.0), "ground", (0.8, 0.0))
    d = lk.build(guess={"a": 1.2, "d": 2.0})
    assert d.dof == 2 and d.kinematics.grubler == 2 and d.q_names == ("theta_1", "theta_2")
    q = d.sample(500)
    assert d.joint_error(q).max() < 1e-11


def test_a_redundant_parallelogram_moves_although_grubler_says_it_cannot():
    lk = bl.Linkage("double parallelogram")
    lk.revolute("ground", (0.0, 0.0), "left", (0.0, 0.0))
    lk.revolute("ground", (1.0, 0.0), "right", (0.0, 0.0))
    lk.revolute("ground", (0.5, 0.0), "middle", (0.0, 0.0))
    lk.revolute("left", (0.6, 0.0), "top", (0.0, 0.0))
    lk.revolute("right", (0.6, 0.0), "top", (1.0, 0.0))
    lk.revolute("middle", (0.6, 0.0), "top", (0.5, 0.0))
    d = lk.build(guess={"left": 1.0, "right": 1.0, "middle": 1.0})
    assert d.kinematics.grubler == 0 and d.dof == 1 and d.kinematics.redundant == 1
    q = d.sample(300)
    assert d.joint_error(q).max() < 1e-11
    np.testing.assert_allclose(wrap(d.poses(q)[..., 4, 2]), 0.0, atol=1e-9)  # the top stays level


def test_driving_bodies_can_be_chosen_and_must_determine_the_rest():
    lk = bl.Linkage()
    lk.revolute("ground", (0.0, 0.0), "crank", (0.0, 0.0))
    lk.revolute("crank", (0.4, 0.0), "coupler", (0.0, 0.0))
    lk.revolute("coupler", (1.0, 0.0), "rocker", (0.8, 0.0))
    lk.revolute("rocker", (0.0, 0.0), "ground", (1.0, 0.0))
    d = lk.build(driving=["rocker"], guess={"crank": 1.0, "rocker": 1.5})
    assert d.q_names == ("theta_3",) and not d.kinematics.full_turn  # the rocker only rocks
    assert d.joint_error(d.sample(300)).max() < 1e-11
    with pytest.raises(ValueError, match="driving must name 1"):
        lk.build(driving=["crank", "rocker"], guess={"crank": 1.0, "rocker": 1.5})


def test_clear_errors():
    lk = bl.Linkage()
    lk.revolute("ground", (0.0, 0.0), "a", (0.0, 0.0))
    lk.revolute("b", (0.0, 0.0), "c", (1.0, 0.0))
    with pytest.raises(ValueError, match="not connected to the ground"):
        lk.build()
    lk = bl.Linkage()
    lk.revolute("ground", (0.0, 0.0), "a", (0.0, 0.0))
    lk.mass("lonely", 1.0)
    with pytest.raises(ValueError, match=r"\['lonely'\] have no joint"):
        lk.build()
    with pytest.raises(ValueError, match="duplicate body name 'a'"):
        lk.body("a")
    with pytest.raises(ValueError, match="duplicate joint"):
        lk.revolute("a", (0.0, 0.0), "ground", (0.0, 0.0))
    with pytest.raises(ValueError, match="two different bodies"):
        lk.revolute("a", (0.0, 0.0), "a", (1.0, 0.0))
    with pytest.raises(ValueError, match="index must be in 0..2"):
        lk.revolute(7, (0.0, 0.0), "a", (1.0, 0.0))
    with pytest.raises(ValueError, match="does not assemble"):
        fourbar_linkage(0.2, 0.3, 0.3, 2.0, None)
    triangle = bl.Linkage()
    triangle.revolute("ground", (0.0, 0.0), "a", (0.0, 0.0))
    triangle.revolute("a", (1.0, 0.0), "b", (0.0, 0.0))
    triangle.revolute("b", (1.0, 0.0), "ground", (1.0, 0.0))
    with pytest.raises(ValueError, match="over-constrained"):
        triangle.build()
    with pytest.raises(ValueError, match="no moving body"):
        bl.Linkage().build()


def test_kinematics_contract_shapes():
    d = fourbar_issue11()
    kin = d.kinematics
    assert isinstance(kin, LinkageKinematics) and isinstance(kin, bl.Kinematics)
    q = d.sample(12).reshape(3, 4, 1)
    poses, ok = kin.poses(q)
    assert poses.shape == (3, 4, 4, 3) and ok.shape == (3, 4) and ok.all()


def test_a_parallelogram_stays_a_parallelogram_through_its_change_points():
    d = parallelogram_lamp()  # two dof, one loop; its flat configurations join the anti-parallelogram branch
    assert d.kinematics.full_turn  # every pair of link angles
    lo, hi = d.q_range[:, 0], d.q_range[:, 1]
    q = lo + (hi - lo) * np.random.default_rng(5).random((4000, 2))
    assert d.reachable(q).all()
    P = d.poses(q)
    assert np.abs(wrap(P[..., 3, 2] - q[:, 1])).max() < 1e-9  # the copy of link 2 is parallel to link 2
    assert np.abs(wrap(P[..., 4, 2] - q[:, 0])).max() < 1e-9
    assert d.joint_error(q).max() < 1e-12


def test_a_watt_sixbar_closes_both_loops_over_a_full_turn():
    d = watt_sixbar()
    assert d.kinematics.full_turn and d.kinematics.grubler == 1 and len(d.kinematics.topology.loops) == 2
    sweep = np.linspace(-np.pi, np.pi, 2001)
    angles = d.poses(sweep)[..., 2]
    assert d.joint_error(sweep).max() < 1e-12
    assert np.abs(wrap(np.diff(angles, axis=0))).max() < 0.1  # no jump to the other assembly


def test_a_parallelogram_four_bar_driven_by_its_crank_keeps_its_coupler_level():
    lk = bl.Linkage("parallelogram four-bar")
    lk.revolute("ground", (0.0, 0.0), "crank", (0.0, 0.0))
    lk.revolute("crank", (0.4, 0.0), "coupler", (0.0, 0.0))
    lk.revolute("coupler", (1.0, 0.0), "rocker", (0.4, 0.0))
    lk.revolute("rocker", (0.0, 0.0), "ground", (1.0, 0.0))
    d = lk.build(guess={"crank": 1.0, "rocker": 1.0})
    q = np.linspace(-np.pi, np.pi, 3601)  # through both flat configurations, where the branches cross
    assert d.kinematics.full_turn and d.reachable(q).all()
    P = d.poses(q)
    assert np.abs(wrap(P[:, 2, 2])).max() < 1e-9 and np.abs(wrap(P[:, 3, 2] - q)).max() < 1e-9


# ---- linkages that cannot move (outside attack) ----

def _flat_fourbar(crank, coupler, rocker, ground):
    lk = bl.Linkage("flat four-bar")
    lk.revolute("ground", (0, 0), "crank", (0, 0))
    lk.revolute("crank", (crank, 0), "coupler", (0, 0))
    lk.revolute("coupler", (coupler, 0), "rocker", (rocker, 0))
    lk.revolute("rocker", (0, 0), "ground", (ground, 0))
    return lk


@pytest.mark.parametrize("lengths", [(0.4, 1.0, 0.6, 2.0), (0.5, 1.0, 0.5, 2.0)])
def test_a_locked_fourbar_is_refused_as_unable_to_move(lengths):
    """crank + coupler + rocker = ground: the loop only closes stretched flat; it cannot move."""
    with pytest.raises(ValueError, match="cannot move.*crank, coupler, rocker"):
        _flat_fourbar(*lengths).build()


def test_a_stretched_fivebar_is_a_value_error():
    lk = bl.Linkage("five")
    lk.revolute("ground", (0, 0), "a", (0, 0))
    for x, y in (("a", "b"), ("b", "c"), ("c", "d")):
        lk.revolute(x, (1, 0), y, (0, 0))
    lk.revolute("d", (1, 0), "ground", (4, 0))
    with pytest.raises(ValueError, match="does not move"):
        lk.build()


def test_a_slider_with_every_point_at_the_origin_needs_a_stroke():
    lk = bl.Linkage("slide")
    lk.prismatic("ground", (0, 0), "s", (0, 0))
    with pytest.raises(ValueError, match="stroke"):
        lk.build()
    lk = bl.Linkage("slide")
    lk.prismatic("ground", (0, 0), "s", (0, 0), stroke=(-0.5, 0.5))
    assert np.allclose(lk.build().q_range, [[-0.5, 0.5]])


def test_a_too_large_force_is_reported_in_newtons():
    lk = bl.Linkage("lever")
    lk.revolute("ground", (0, 0), "arm", (0, 0))
    with pytest.raises(ValueError, match=r"force \(N\) must have coordinates of magnitude <= 1e\+12 N,"):
        lk.load("arm", (0.0, 1e13))
