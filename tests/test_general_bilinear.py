"""Springs with both ends free: never a false "impossible", and the best over the starts is kept."""
import pytest

import balancelab as bl

G = 9.81


def _fourbar():
    lk = bl.Linkage("fb")
    lk.revolute("ground", (0, 0), "crank", (0, 0))
    lk.revolute("crank", (0.4, 0), "coupler", (0, 0))
    lk.revolute("coupler", (1, 0), "rocker", (0.8, 0))
    lk.revolute("rocker", (0, 0), "ground", (1, 0))
    lk.mass("crank", 2, com=(0.2, 0))
    lk.load("coupler", (0, -30), com=(0.5, 0.1))
    return lk.build(guess={"crank": 1, "rocker": 1.5})


def _lever():
    lk = bl.Linkage("lever")
    lk.revolute("ground", (0, 0), "arm", (0, 0))
    lk.mass("arm", 2.0, com=(0.5, 0.0))
    return lk.build()


@pytest.mark.parametrize("objective", ["min_preload", "min_stiffness", "min_mass"])
def test_both_free_spring_on_fourbar_is_not_called_impossible(objective):
    """A solution exists in the default box (one with the coupler end at (-0.5, 0) is found when
    that end is fixed): making the end free must find one too, and it must be balanced."""
    f = _fourbar()
    fixed = bl.balance(f, springs=[(("ground", None), ("coupler", (-0.5, 0.0))), (("ground", None), ("crank", (0.4, 0)))],
                       objective="min_stiffness")
    assert fixed.balance_report().balanced
    d = bl.balance(f, springs=[(("ground", None), ("coupler", None)), (("ground", None), ("crank", (0.4, 0)))],
                   objective=objective)
    assert d.balance_report().balanced


def test_free_points_are_a_superset_of_fixed_candidates():
    """Property: min stiffness with a free end is never worse than with that end fixed at any point of the box."""
    f = _fourbar()
    free = bl.balance(f, springs=[(("ground", None), ("coupler", None)), (("ground", None), ("crank", (0.4, 0)))],
                      objective="min_stiffness")
    k_free = free.parameters["k1"] + free.parameters.get("k2", 0.0)
    for pt in [(-0.5, 0.0), (-1.0, 0.0), (0.5, 0.5)]:
        try:
            d = bl.balance(f, springs=[(("ground", None), ("coupler", pt)), (("ground", None), ("crank", (0.4, 0)))],
                           objective="min_stiffness", box=((-1, 1), (-1, 1)))
        except bl.InfeasibleDesign:
            continue
        assert k_free <= (d.parameters["k1"] + d.parameters.get("k2", 0.0)) * (1 + 1e-6)


def test_min_stiffness_with_both_ends_free_beats_a_known_feasible_design():
    """Lever m g l = 9.81 J: the ZFL spring from arm (0.5, 0.5) to ground (-0.5, 0.5) balances with
    k = m g l / |a x b| = 9.81 / 0.5 = 19.62 N/m in the box +-0.5; the optimum is no stiffer."""
    lever = _lever()
    known = lever.replace(springs=[bl.Spring(2 * G * 0.5 / 0.5, 0.0, (1, (0.5, 0.5)), (0, (-0.5, 0.5)))])
    assert known.balance_report().balanced
    d = bl.balance(lever, springs=[(("arm", None), ("ground", None))], objective="min_stiffness",
                   box=((-0.5, 0.5), (-0.5, 0.5)))
    assert d.balance_report().balanced
    assert d.parameters["k1"] <= 19.62 * (1 + 1e-9)


def test_impossible_only_when_the_relaxation_fails():
    """A verdict on a both-free spring is "impossible" only when the lifted relaxation has no solution;
    otherwise it is honest about having searched (verdict "not_found")."""
    lk = bl.Linkage("slide")
    lk.revolute("ground", (0, 0), "arm", (0, 0))
    lk.load("arm", (3.0, -5.0), com=(0.5, 0.2))
    d = lk.build()
    try:
        bl.balance(d, springs=[(("arm", None), ("ground", None))], box=((-0.01, 0.01), (-0.01, 0.01)))
    except bl.InfeasibleDesign as err:
        assert err.verdict in ("box", "not_found", "negative"), str(err)


def _telescoping_arm():
    lk = bl.Linkage("telescoping arm")
    lk.revolute("ground", (0, 0), "arm", (0, 0))
    lk.prismatic("arm", (0, 0), "slide", (0, 0), axis=(1, 0), stroke=(0.2, 0.8))
    lk.mass("slide", 1.0)
    lk.mass("arm", 0.5, com=(0.3, 0))
    return lk.build()


def test_no_scipy_warning_leaks_from_an_infeasible_telescoping_arm():
    import warnings

    with warnings.catch_warnings():
        warnings.simplefilter("error")
        with pytest.raises(bl.InfeasibleDesign) as info:
            bl.balance(_telescoping_arm(), counterweights=[("arm", None), ("slide", None)])
    assert info.value.verdict in ("negative", "impossible")


def test_leftover_terms_of_a_slide_name_the_slide():
    """A counterweight on the arm cannot cancel m g s sin θ of the sliding mass (1 kg): the message
    names that term, with its coefficient m g = 9.81 J per m."""
    with pytest.raises(bl.InfeasibleDesign) as info:
        bl.balance(_telescoping_arm(), counterweights=[("arm", None)])
    assert info.value.verdict == "impossible"
    assert "9.81 J × s_1 sin θ_1" in str(info.value)


@pytest.mark.parametrize("objective, kw", [
    ("min_mass", dict(springs=[(("arm", None), ("ground", (0, 0.4)))])),
    ("min_mass", dict(springs=[(("arm", None), ("ground", None))])),
    ("min_stiffness", dict(springs=[(("arm", (0.25, 0)), ("ground", (0, 0.4)))], counterweights=[("arm", None)])),
])
def test_a_tie_break_is_never_silent(objective, kw):
    """min_mass with springs only, min_stiffness with a free counterweight: the objective ignores
    candidates (a free spring's rate can grow while its point shrinks, and so can a counterweight's
    mass): many designs share the value, and a warning says so."""
    with pytest.warns(UserWarning, match="does not select a unique design"):
        out = bl.balance(_lever(), objective=objective, **kw)
    assert out.balance_report().balanced
