"""The balance report cannot be fooled: one configuration, silly tolerances, self-cancelling springs."""
from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import HealthCheck, example, given, settings
from hypothesis import strategies as st

import balancelab as bl
from balancelab import Design, Joint, Spring, TreeKinematics, gravity_load

G = bl.G


def pivot_lever(pivot=(0.0, 0.0), mass=2.0, length=0.5, b=0.3, c=0.2, imbalance=0.0, pair=None,
                q_range=(-math.pi, math.pi)) -> Design:
    """A link turning about ``pivot`` (its kinematics takes the pivot), weight ``mass`` at
    ``length``, balanced by a ZFL spring from ``pivot + (0, b)`` to the link point ``(c, 0)``
    with ``k = m g length / (b c)`` times ``1 + imbalance``. ``pair = (k, h, d)`` adds two ZFL
    springs from ``pivot + (0, +-h)`` to the link point ``(d, 0)``: their energies sum to a
    constant."""
    px, py = pivot
    kin = TreeKinematics(2, [Joint(0, pivot, 1, (0.0, 0.0))], [[0.0], [1.0]], ("theta",), (q_range,))
    k = mass * G * length / (b * c) * (1.0 + imbalance)
    springs = [Spring(k, 0.0, (0, (px, py + b)), (1, (c, 0.0)), name="k")]
    if pair is not None:
        kp, h, d = pair
        springs += [Spring(kp, 0.0, (0, (px, py + h)), (1, (d, 0.0)), name="k+"),
                    Spring(kp, 0.0, (0, (px, py - h)), (1, (d, 0.0)), name="k-")]
    return Design("pivot lever", ("ground", "link"), [Joint(0, pivot, 1, (0.0, 0.0))], kin,
                  [gravity_load(1, (length, 0.0), mass)], springs)


# ---------------------------------------------------------------- 1. one configuration
def test_one_configuration_is_refused():
    bad = pivot_lever(imbalance=0.1)  # 10 % off: clearly not balanced
    assert not bad.balance_report().balanced
    with pytest.raises(ValueError, match=r"n \(number of configurations\) must be an integer in 10\.\.200000"):
        bad.balance_report(n=1)
    with pytest.raises(ValueError, match=r"n \(number of configurations\) must be an integer in 10\.\.200000"):
        bad.balance_report(n=9)
    with pytest.raises(ValueError, match=r"q must hold at least 10 distinct configurations .* got 1"):
        bad.balance_report(np.full((50, 1), 0.3))
    with pytest.raises(ValueError, match=r"q must hold at least 10 distinct"):
        bad.balance_report(np.linspace(0.0, 3.0, 9))
    # many distinct configurations, all near one: not a real part of the range
    with pytest.raises(ValueError, match=r"q must give configurations spanning at least 0.25 .* theta spans"):
        bad.balance_report(np.linspace(0.3, 0.31, 100))
    # a quarter of the turn is enough, and it catches the imbalance
    assert not bad.balance_report(np.linspace(0.0, math.pi / 2, 10)).balanced
    assert pivot_lever().balance_report(np.linspace(0.0, math.pi / 2, 10)).balanced


@pytest.mark.parametrize("name", ["singh_fourbar", "deepak_watt_prototype", "scissors_lift",
                                  "approximate_spring_lever"])
def test_narrow_ranges_sample_fine(name):
    """Designs with a limited range: the default sampling and small samples always qualify."""
    entry = bl.catalog()[name]
    d = entry()
    assert d.balance_report().balanced == entry.expected_balanced
    for seed in range(5):
        assert d.balance_report(n=30, seed=seed).balanced == entry.expected_balanced
    lo, hi = d.q_range[0]
    narrow = d.sample(1000)
    narrow = narrow[np.abs(narrow[:, 0] - narrow[:, 0].mean()) < 0.05 * (hi - lo)]
    with pytest.raises(ValueError, match="spanning at least"):
        d.balance_report(narrow)


def test_a_narrow_declared_range_samples_fine():
    for q_range in [(0.2, 0.4), (-1.0, -0.99)]:
        assert pivot_lever(q_range=q_range).balance_report().balanced
        assert pivot_lever(q_range=q_range).balance_report(n=10, seed=3).balanced
        assert not pivot_lever(q_range=q_range, imbalance=1e-3).balance_report().balanced


# ---------------------------------------------------------------- 2. silly tolerances
@pytest.mark.parametrize("tolerance, error", [
    (math.inf, ValueError), (-1e-3, ValueError), (math.nan, ValueError), (0.0, ValueError),
    (0, ValueError), (1.0, ValueError), (5.0, ValueError), ("1e-3", TypeError), (None, TypeError),
    (True, TypeError), ([1e-3], TypeError)])
def test_silly_tolerances_are_refused(tolerance, error):
    d = pivot_lever(imbalance=0.1)
    with pytest.raises(error, match=r"tolerance must be a real number with 0 < tolerance < 1"):
        d.balance_report(tolerance=tolerance)


def test_sensible_tolerances_are_used():
    d = pivot_lever(imbalance=1e-4)
    assert not d.balance_report().balanced
    r = d.balance_report(tolerance=1e-3)
    assert r.balanced and r.tolerance == 1e-3
    assert d.balance_report(tolerance=np.float64(1e-3)).balanced


# ---------------------------------------------------------------- 3. self-cancelling springs
def test_self_cancelling_pair_is_constant():
    d = pivot_lever(pair=(1e6, 0.4, 0.3)).replace(loads=[])
    d = d.replace(springs=d.springs[1:])
    vl, vs = d.element_energies(d.sample(200))
    assert np.ptp(vs.sum(-1)) < 1e-9 * np.ptp(vs, axis=0).sum()


@pytest.mark.parametrize("pair, tolerance", [((1e4, 0.5, 0.5), 1e-3), ((1e10, 0.5, 0.5), 1e-9)])
def test_self_cancelling_springs_do_not_hide_an_imbalance(pair, tolerance):
    bad = pivot_lever(imbalance=-0.1 / 1.1, pair=pair)  # the weight is 10 % more than the spring holds
    r = bad.balance_report(tolerance=tolerance)
    assert not r.balanced, r
    assert r.load_variation > 0.05 and r.load_scale == pytest.approx(2 * G * 0.5 * 2, rel=1e-3)
    assert str(r).startswith("NOT balanced")
    good = pivot_lever(pair=pair).balance_report(tolerance=tolerance)
    if good.resolvable:
        assert good.balanced and str(good).startswith("balanced: energy varies by")
    else:   # 1e10 N/m springs: their round-off exceeds 1e3 x 1e-9 of the loads' exchange
        assert pair[0] >= 1e10 and str(good).startswith("NOT balanced (cannot be resolved")


def test_opposite_loads_at_one_point_do_not_inflate_the_scale():
    bad = pivot_lever(imbalance=0.1)
    extra = [bl.Load(1, (0.3, 0.0), (0.0, -1e12)), bl.Load(1, (0.3, 0.0), (0.0, 1e12))]
    r = bad.replace(loads=list(bad.loads) + extra).balance_report()
    assert not r.balanced and r.load_scale == pytest.approx(bad.balance_report().load_scale, rel=1e-6)


def test_counterweight_and_spring_loaded_designs_keep_their_scale():
    cw = bl.lecture.fourbar_counterweights().balance_report()
    assert cw.balanced and cw.load_scale == pytest.approx(cw.scale, rel=1e-12)  # every weight counts
    spring_loaded = bl.catalog()["deepak_technique2_A"]()
    r = spring_loaded.balance_report()
    assert r.balanced and r.load_scale == r.scale  # no loads: the springs are the load
    k = list(spring_loaded.springs)
    k[1] = Spring(k[1].k * 1.01, 0.0, k[1].a, k[1].b)
    assert not spring_loaded.replace(springs=k).balance_report().balanced


# ---------------------------------------------------------------- every worked example
@pytest.mark.parametrize("name, entry", list(bl.catalog().items()), ids=list(bl.catalog()))
def test_catalog_verdicts_are_kept(name, entry):
    r = entry().balance_report()
    assert r.balanced == entry.expected_balanced, (name, str(r))
    assert r.variation <= r.load_variation  # the load scale is the stricter yardstick
    if not entry.expected_balanced:
        assert r.load_variation > 1e-6


# ---------------------------------------------------------------- origin independence
@pytest.mark.parametrize("imbalance", [0.0, 1e-6, 0.1])
def test_verdict_does_not_depend_on_the_origin(imbalance):
    here = pivot_lever(imbalance=imbalance, pair=(1e3, 0.4, 0.3)).balance_report()
    far = pivot_lever((37.0, -120.0), imbalance=imbalance, pair=(1e3, 0.4, 0.3)).balance_report()
    assert here.balanced == far.balanced == (imbalance == 0.0)
    assert far.load_scale == pytest.approx(here.load_scale, rel=1e-9)
    assert far.scale == pytest.approx(here.scale, rel=1e-9)
    if imbalance:
        assert far.load_variation == pytest.approx(here.load_variation, rel=1e-6)
    assert abs(far.energy - here.energy) > 100  # the energies differ, the verdict does not
    cw_here = bl.lecture.fourbar_counterweights().balance_report()
    cw_far = bl.lecture.fourbar_counterweights(A=(-50.0, 80.0), B=(-49.3, 80.0)).balance_report()
    assert cw_here.balanced and cw_far.balanced
    assert cw_far.load_scale == pytest.approx(cw_here.load_scale, rel=1e-9)


# ---------------------------------------------------------------- random imbalances
def _with_pair(design: Design, k: float, h: float, d: float) -> Design:
    """``design`` with two self-cancelling ZFL springs on body 1 (turning about a fixed pivot)."""
    px, py = design.world_points(design.sample(20), [(1, (0.0, 0.0))])[:, 0].mean(axis=0)
    pair = [Spring(k, 0.0, (0, (px, py + h)), (1, (d, 0.0))), Spring(k, 0.0, (0, (px, py - h)), (1, (d, 0.0)))]
    return design.replace(springs=list(design.springs) + pair)


GRAVITY_DESIGNS = ["lacoste_lever", "serial_2r_min_preload", "singh_fourbar", "fourbar_two_springs",
                   "deepak_gravity_fourbar"]


@settings(max_examples=40, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(name=st.sampled_from(GRAVITY_DESIGNS), which=st.integers(0, 10),
       size=st.floats(-3.0, -1.0), sign=st.sampled_from([1.0, -1.0]),
       pair=st.none() | st.tuples(st.floats(0.0, 10.0), st.floats(0.05, 1.0), st.floats(0.05, 1.0)))
# issue 19: the noise of a 10**8.5 N/m pair put 2.3e-9 of the loads' exchange into the smooth part (it can
# put up to 7e-9 there): once reported NOT balanced yet resolvable, now "cannot be resolved"
@example(name="deepak_gravity_fourbar", which=0, size=-1.0, sign=1.0, pair=(8.5, 0.5, 0.125))
def test_random_spring_rate_imbalances_are_always_caught(name, which, size, sign, pair):
    design = bl.catalog()[name]()
    springs = list(design.springs)
    i = which % len(springs)
    s = springs[i]
    springs[i] = Spring(s.k * (1.0 + sign * 10.0 ** size), s.free_length, s.a, s.b)
    bad = design.replace(springs=springs)
    if pair is not None:
        bad = _with_pair(bad, 10.0 ** pair[0], pair[1], pair[2])
        exact = _with_pair(design, 10.0 ** pair[0], pair[1], pair[2]).balance_report(n=200)
        # exact: balanced; with a pair so stiff that double precision cannot resolve 1e-9 of the
        # loads' exchange, honestly "NOT balanced (cannot be resolved)", never a false verdict either way
        assert exact.balanced or (not exact.resolvable and pair[0] > 6.0), exact
    assert not bad.balance_report(n=200).balanced
    assert not bad.balance_report(n=200, tolerance=1e-5).balanced


@settings(max_examples=30, deadline=None)
@given(pivot=st.tuples(st.floats(-100.0, 100.0), st.floats(-100.0, 100.0)),
       size=st.floats(-3.0, -1.0), sign=st.sampled_from([1.0, -1.0]),
       pair=st.tuples(st.floats(0.0, 6.0), st.floats(0.05, 1.0), st.floats(0.05, 1.0)))
def test_random_lever_imbalances_anywhere_are_caught(pivot, size, sign, pair):
    """Far from the origin, stiff springs' world coordinates lose digits: the balanced lever is
    then checked to 1e-6 only; every imbalance of 1e-3 or more is caught at any tolerance."""
    pair = (10.0 ** pair[0], pair[1], pair[2])
    assert pivot_lever(pivot, pair=pair).balance_report(n=100, tolerance=1e-6).balanced
    bad = pivot_lever(pivot, imbalance=sign * 10.0 ** size, pair=pair)
    for tolerance in (1e-4, 1e-9):
        report = bad.balance_report(n=100, tolerance=tolerance)
        assert not report.balanced
        assert report.load_variation > 4e-4
