"""Figures of designs: the artists sit where the physics says, for every catalog entry."""
from __future__ import annotations

import math
import os

os.environ.setdefault("MPLBACKEND", "Agg")

import matplotlib  # noqa: E402

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
import pytest  # noqa: E402

import balancelab as bl  # noqa: E402
from balancelab.core.elements import G, Joint, Pulley, Spring, gravity_load  # noqa: E402
from balancelab.methods import realize as rz  # noqa: E402
from balancelab.viz import drawing as D, energy as E, frame as F, spaces as S  # noqa: E402


# ----------------------------------------------------------------- test designs
def two_link_arm(W1: float = 10.0, W2: float = 5.0, l1: float = 0.6, p1: float = 0.3, p2: float = 0.4,
                 a1: float = 0.2, b1: float = 0.25, b2: float = 0.3, c2: float = 0.1) -> bl.Design:
    """A 2R arm (absolute link angles) balanced by three ZFL springs, derived here.

    Loads: ``W1`` at ``(p1, 0)`` on link 1, ``W2`` at ``(p2, 0)`` on link 2, whose joint is
    at ``(l1, 0)`` on link 1. Spring 2 runs from the ground anchor ``(0, b2)`` to
    ``(p2, 0)`` on link 2; its energy has ``-k2 b2 (l1 sin q1 + p2 sin q2)`` and a cross
    term ``k2 l1 p2 cos(q1 - q2)``. Spring 3 joins ``(l1/2, 0)`` on link 1 to ``(-c2, 0)``
    on link 2, adding ``-k3 (l1/2) c2 cos(q1 - q2)``: ``k3 = 2 k2 p2 / c2`` cancels the
    cross term. ``k2 = W2 / b2`` cancels ``sin q2`` and leaves ``W2 l1 sin q1`` cancelled
    too, so spring 1 from ``(0, b1)`` to ``(a1, 0)`` on link 1 needs ``k1 = W1 p1 / (a1 b1)``
    (the lecture's single-link rule).
    """
    k2 = W2 / b2
    k3 = 2 * k2 * p2 / c2
    k1 = W1 * p1 / (a1 * b1)
    joints = [Joint(0, (0.0, 0.0), 1, (0.0, 0.0)), Joint(1, (l1, 0.0), 2, (0.0, 0.0))]
    kin = bl.TreeKinematics(3, joints, [[0, 0], [1, 0], [0, 1]], ("theta_1", "theta_2"),
                            [(-math.pi, math.pi), (-math.pi, math.pi)])
    loads = [gravity_load(1, (p1, 0.0), W1 / G, "W1"), gravity_load(2, (p2, 0.0), W2 / G, "W2")]
    springs = [Spring(k1, 0.0, (0, (0.0, b1)), (1, (a1, 0.0)), "k1"),
               Spring(k2, 0.0, (0, (0.0, b2)), (2, (p2, 0.0)), "k2"),
               Spring(k3, 0.0, (1, (l1 / 2, 0.0)), (2, (-c2, 0.0)), "k3")]
    labels = {"O": (0, (0.0, 0.0)), "J": (1, (l1, 0.0)), "b1": (0, (0.0, b1)), "b2": (0, (0.0, b2))}
    return bl.Design("2R arm, three ZFL springs", ("ground", "link 1", "link 2"), joints, kin, loads,
                     springs, labels=labels, parameters={"k1": k1, "k2": k2, "k3": k3})


def pulley_lever() -> bl.Design:
    """The lecture's single link whose ZFL spring is a string over a pulley at the anchor."""
    d = bl.lecture.single_link_spring(2.0, 0.5, 0.3, 0.2)
    s = d.springs[0]
    return d.replace(name="single link, string over a pulley",
                     springs=[Spring(s.k, 0.0, s.a, s.b, name="k", realization="pulley")])


EXTRA = {"extra_two_link_arm": two_link_arm, "extra_pulley_lever": pulley_lever}
ALL = list(bl.catalog()) + list(EXTRA)


def build(name: str) -> bl.Design:
    return EXTRA[name]() if name in EXTRA else bl.catalog()[name]()


@pytest.fixture(autouse=True)
def _close_figures():
    yield
    plt.close("all")


# ----------------------------------------------------------------- the designs
def test_draw_titles_each_design_with_its_own_name():
    cat = bl.catalog()
    assert len(cat) >= 10
    for name in list(cat)[:3]:
        d = cat[name]()
        assert D.draw(d).get_title() == d.name
    d = bl.singh.lacoste_lever(10.0, 0.5, 0.2, 0.3)
    assert D.draw(d, title="mine").get_title() == "mine"
    assert D.draw(d, title=False).get_title() == ""


def test_two_link_arm_is_balanced_and_breaks_when_perturbed():
    d = two_link_arm()
    assert d.dof == 2
    assert d.balance_report().balanced
    s = d.springs[2]
    worse = d.replace(springs=[*d.springs[:2], Spring(s.k * 1.001, 0.0, s.a, s.b, "k3")])
    assert not worse.balance_report().balanced


# ------------------------------------------------------------------------ draw
def _q(d):
    return F.default_q(d)


@pytest.mark.parametrize("name", ALL)
def test_draw_places_every_artist(name):
    d = build(name)
    q = _q(d)
    ax = D.draw(d, q)
    dr = ax.drawing
    assert dr.ax is ax
    # one artist per moving body, spring and load
    assert sorted(dr.links) == list(range(1, len(d.bodies)))
    assert len(dr.springs) == len(d.springs)
    assert len(dr.loads) == len(d.loads)
    for a in list(dr.links.values()) + dr.springs + dr.loads:
        assert a in ax.patches or a in ax.lines
    # joints at their world positions (both sides of a joint coincide)
    if d.joints:
        want = d.world_points(q, [(j.body_i, j.point_i) for j in d.joints])
        np.testing.assert_allclose(dr.joints.get_offsets(), want, atol=1e-9)
    # each link's outline passes through its joints and spring attachments
    for b, poly in dr.links.items():
        outline = poly.get_xy()
        pts = [j.point_i for j in d.joints if j.body_i == b] + [j.point_j for j in d.joints if j.body_j == b]
        pts += [s.a.point for s in d.springs if s.a.body == b] + [s.b.point for s in d.springs if s.b.body == b]
        for p in d.world_points(q, [(b, p) for p in pts]):
            inside = poly.get_path().contains_point(p, radius=1e-9) or poly.get_path().contains_point(p, radius=-1e-9)
            on_vertex = np.min(np.hypot(*(outline - p).T)) < 1e-9
            on_edge = _on_polyline(outline, p)
            assert inside or on_vertex or on_edge, (b, p)
    # springs run between their two attachments
    for s, line in zip(d.springs, dr.springs):
        pa, pb = d.world_points(q, [s.a, s.b])
        xy = line.get_xydata()
        if s.pulley is not None:
            np.testing.assert_allclose(xy[0], pb, atol=1e-12)
        else:
            np.testing.assert_allclose(xy[0], pa, atol=1e-12)
            np.testing.assert_allclose(xy[-1], pb, atol=1e-12)
    # loads: arrows start at the point of action and point along the force; discs centred
    for ld, art, (tail, head) in zip(d.loads, dr.loads, dr.load_segments):
        (p,) = d.world_points(q, [(ld.body, ld.point)])
        if ld.kind == "counterweight":
            np.testing.assert_allclose(art.center, p, atol=1e-12)
        else:
            np.testing.assert_allclose(tail, p, atol=1e-12)
            u = (head - tail) / np.hypot(*(head - tail))
            f = np.array(ld.force) / np.hypot(*ld.force)
            np.testing.assert_allclose(u, f, atol=1e-12)
    # labels at their named points
    for lab, text in dr.labels.items():
        np.testing.assert_allclose(text.xy, d.world_points(q, [d.labels[lab]])[0], atol=1e-12)
    if d.labels:
        np.testing.assert_allclose(dr.label_dots.get_offsets(),
                                   d.world_points(q, list(d.labels.values())), atol=1e-12)
    # ground: one hatched block per ground pivot or anchor
    assert all(r.get_hatch() for r in dr.ground)
    assert ax.get_aspect() == 1.0


def _on_polyline(xy, p, tol=1e-9):
    for a, b in zip(xy[:-1], xy[1:]):
        ab = b - a
        t = np.clip(np.dot(p - a, ab) / max(np.dot(ab, ab), 1e-300), 0, 1)
        if np.hypot(*(a + t * ab - p)) < tol:
            return True
    return False


def test_update_moves_artists_like_a_fresh_drawing():
    d = bl.catalog()["fourbar_two_springs"]()
    lo, hi = d.q_range[0]
    q1, q2 = [lo + 0.3 * (hi - lo)], [lo + 0.7 * (hi - lo)]
    moved = D.draw(d, q1).drawing.update(q2)
    fresh = D.draw(d, q2).drawing
    for b in fresh.links:
        np.testing.assert_allclose(moved.links[b].get_xy(), fresh.links[b].get_xy(), atol=1e-12)
    for a, b in zip(moved.springs, fresh.springs):
        np.testing.assert_allclose(a.get_xydata(), b.get_xydata(), atol=1e-12)
    np.testing.assert_allclose(moved.joints.get_offsets(), fresh.joints.get_offsets(), atol=1e-12)


def test_update_with_a_new_design_of_another_structure_rebuilds():
    ax = D.draw(bl.singh.lacoste_lever(10.0, 0.5, 0.2, 0.3), [0.4])
    dr = ax.drawing
    arm = two_link_arm()
    dr.update([0.1, 0.5], arm)
    assert len(dr.links) == 2 and len(dr.springs) == 3 and len(dr.loads) == 2
    assert len(ax.patches) == len(dr.links) + len(dr.loads) + len(dr.ground) + len(dr.extras)


def test_ternary_link_is_a_plate_through_its_three_points():
    d = bl.singh.generalized_lever(10.0, 0.5, 0.2, 0.1, 0.3)  # a = (0.2, -0.0667) is off the lever's axis
    q = [0.3]
    poly = D.draw(d, q).drawing.links[1]
    outline = poly.get_xy()[:-1]
    want = d.world_points(q, [(1, (0.0, 0.0)), (1, d.springs[0].b.point), (1, (0.5, 0.0))])
    assert len(outline) == 3
    for p in want:
        assert np.min(np.hypot(*(outline - p).T)) < 1e-12


def test_zfl_finite_and_pulley_springs_look_different():
    zfl = D.draw(bl.lecture.single_link_spring(2.0, 0.5, 0.3, 0.2)).drawing.springs[0]
    ordinary = D.draw(bl.lecture.single_link_ordinary_spring(2.0, 0.5, 0.3, 0.2, 0.05)).drawing.springs[0]
    assert zfl.get_linestyle() == "-"
    assert ordinary.get_linestyle() != "-"
    assert zfl.get_color() != ordinary.get_color()
    d = pulley_lever()
    dr = D.draw(d, [0.4]).drawing
    (pulley,) = dr.extras
    np.testing.assert_allclose(pulley.center, d.world_points([0.4], [d.springs[0].a])[0], atol=1e-12)
    assert dr.springs[0].get_color() not in (zfl.get_color(), ordinary.get_color())


PULLEYS = [Pulley(0.05), Pulley(0.05, (1.0, 0.0), -1), Pulley(0.06, (-1.0, -1.0), 1), Pulley(0.05, (0.0, -1.0), -1),
           "pulley"]


@pytest.mark.parametrize("pulley", PULLEYS, ids=str)
def test_the_drawn_pulley_spring_lies_where_the_model_puts_it(pulley):
    """The string leaves on the model's tangent, wraps by the model's angle, and the coil is on its side."""
    base = rz.pulley_lever(radius=0.0)
    s = base.springs[0]
    d = base.replace(springs=[Spring(s.k, 0.0, s.a, s.b, name="k", realization=pulley)])
    p = d.springs[0].pulley
    u = np.array(p.spring_direction) / np.hypot(*p.spring_direction)
    dr = D.draw(d, [0.3]).drawing
    (circle,) = dr.extras
    for q in ([0.3], [-1.2], [1.4]):
        dr.update(q)
        pa, pb = d.world_points(q, [s.a, s.b])
        radius = max(p.radius, 0.03 * dr.size)
        np.testing.assert_allclose(circle.center, pa, atol=1e-12)
        assert circle.get_radius() == pytest.approx(radius)
        model = rz.pulley_string(pa, radius, pb, p.spring_direction, p.turn)
        xy = dr.springs[0].get_xydata()
        np.testing.assert_allclose(xy[0], pb, atol=1e-12)
        np.testing.assert_allclose(xy[1], model.tangent_out, atol=1e-12)
        dist = np.hypot(*(xy - pa).T)
        on_pulley = np.flatnonzero(np.abs(dist - radius) < 1e-9)
        arc = xy[1:on_pulley[-1] + 1]
        np.testing.assert_allclose(arc[-1], model.tangent_in, atol=1e-12)
        arc_length = np.sum(np.hypot(*np.diff(arc, axis=0).T))
        assert arc_length == pytest.approx(radius * float(model.wrap), rel=0.01, abs=1e-12)
        coil = xy[on_pulley[-1] + 1:]
        assert len(coil) >= 10
        side = (coil - pa) @ u
        assert np.all(side > 0.02 * dr.size), "the coil must lie on the spring's side of the pulley"
        assert side.max() > 0.12 * dr.size
        if p.radius > 0:
            assert radius == p.radius  # drawn at its own radius when it is visible


def test_counterweights_are_discs_and_weights_arrows():
    d = bl.lecture.single_link_counterweight(2.0, 0.5, 4.0)
    dr = D.draw(d, [0.0]).drawing
    kinds = [type(a).__name__ for a in dr.loads]
    assert kinds == ["FancyArrowPatch", "Circle"]


def test_palette_is_okabe_ito():
    assert F.PALETTE["vermillion"] == "#D55E00" and F.PALETTE["blue"] == "#0072B2"
    assert set(F.STYLE.values()) <= set(F.PALETTE.values())


def test_draw_rejects_bad_input():
    d = bl.singh.lacoste_lever(10.0, 0.5, 0.2, 0.3)
    with pytest.raises(TypeError, match="balancelab.Design"):
        D.draw("lever")
    with pytest.raises(ValueError, match="q must hold 1 angle"):
        D.draw(d, [0.1, 0.2])
    scissors = bl.catalog()["scissors_lift"]()
    with pytest.raises(bl.UnreachableConfiguration):
        D.draw(scissors, [scissors.q_range[0, 1] + 0.5])


# ---------------------------------------------------------------------- energy
@pytest.mark.parametrize("name", ALL)
def test_energy_plot_shows_the_designs_energy(name):
    d = build(name)
    ax = E.energy_plot(d)
    view = ax.energy
    rep = d.balance_report()
    assert view.report.balanced == rep.balanced
    assert ("not balanced" in ax.get_title()) == (not rep.balanced)
    ok = np.isfinite(view.total)
    e = d.potential_energy(view.grid[ok])
    if d.dof != 2:  # three or more: the curves along a closed path through every coordinate (issue 19)
        x, y = view.lines["total"].get_data()
        np.testing.assert_allclose(x, 100 * view.t if d.dof > 2 else np.degrees(view.grid[:, 0]))
        if d.dof > 2:
            assert np.all(np.ptp(view.grid, axis=0) >= 0.9 * np.ptp(d.q_range, axis=1))  # each swept
        np.testing.assert_allclose(np.asarray(y)[ok], e.total, rtol=1e-12, atol=1e-12)
        np.testing.assert_allclose(np.asarray(view.lines["load"].get_data()[1])[ok], e.load, atol=1e-12)
        np.testing.assert_allclose(np.asarray(view.lines["spring"].get_data()[1])[ok], e.spring, atol=1e-12)
        ylo, yhi = ax.get_ylim()
        assert ylo <= np.nanmin(view.load) and yhi >= np.nanmax(view.spring)
    else:
        Z = np.asarray(view.image.get_array()).ravel()
        assert view.scale == pytest.approx(rep.scale)
        np.testing.assert_allclose(view.mean + view.scale * Z[ok], e.total, atol=1e-9 * rep.scale)
        assert view.mean == pytest.approx(np.mean(e.total))
        assert view.image.get_clim() == (-0.5, 0.5)
        assert view.residual_image is not None
    if rep.balanced:
        assert view.note.get_text().startswith("balanced")
        assert len(view.worst.get_xdata()) == 0
    else:
        assert view.note.get_text().startswith("not balanced")
        assert view.worst.get_xdata()[0] == pytest.approx(np.degrees(np.atleast_1d(rep.worst_q)[0]))


def test_energy_plot_marks_a_configuration():
    d = bl.singh.lacoste_lever(10.0, 0.5, 0.2, 0.3)
    ax = E.energy_plot(d, q=[0.5])
    x, y = ax.energy.marker.get_data()
    assert x[0] == pytest.approx(np.degrees(0.5))
    assert y[0] == pytest.approx(float(d.potential_energy([0.5]).total))


def test_counts_and_energy_limits_refuse_nonsense():
    d = bl.singh.lacoste_lever(10.0, 0.5, 0.2, 0.3)
    for n, error in ((0, ValueError), (1, ValueError), (2.5, TypeError), (True, TypeError)):
        with pytest.raises(error, match="n must be an integer >= 2"):     # the one integer check
            E.energy_plot(d, n=n)
        with pytest.raises(error, match="n must be an integer >= 2"):
            S.lever_valley(n=n)
        with pytest.raises(error, match="n must be an integer >= 2"):
            S.cognates_plot([d], point="p", n=n)
    with pytest.raises(ValueError, match="lo"):
        E.energy_limits(float("nan"), 1.0)
    with pytest.raises(ValueError, match="lo <= hi"):
        E.energy_limits(2.0, 1.0)
    with pytest.raises(ValueError, match="scale"):
        E.energy_limits(0.0, 1.0, -1.0)
    with pytest.raises(TypeError, match="BalanceReport"):
        E.report_summary(3)


def test_report_summary_names_verdict_and_residual():
    rep = bl.lecture.single_link_ordinary_spring(2.0, 0.5, 0.3, 0.2, 0.05).balance_report()
    text = E.report_summary(rep)
    assert text.startswith("NOT balanced")
    assert f"{rep.residual * rep.scale:.3g} J/rad" in text
    assert E.report_summary(bl.singh.lacoste_lever(10.0, 0.5, 0.2, 0.3).balance_report()).startswith("balanced")


# ---------------------------------------------------------------- design spaces
def test_lever_valley_is_the_balanced_energy_of_the_lever():
    W, l = 10.0, 0.5
    ax = S.lever_valley(W, l, (0.1, 0.6), (0.1, 0.6), n=26)
    A, B, PE = ax.valley
    for i, j in [(0, 0), (3, 17), (25, 4), (12, 12)]:
        d = bl.singh.lacoste_lever(W, l, A[i, j], B[i, j])
        assert d.balance_report().balanced
        assert float(d.potential_energy([0.7]).total) == pytest.approx(PE[i, j], rel=1e-12)
    diag = np.diag(PE)  # a_x = b_y: the valley of minima, PE = W l (Singh eq. 9)
    np.testing.assert_allclose(diag, W * l, rtol=1e-12)
    assert PE.min() == pytest.approx(W * l)
    assert np.all(PE >= W * l - 1e-12)


def test_every_figure_reads_its_numbers_from_the_design():
    # the valley: every grid value is the energy of the lever built there
    ax = S.lever_valley(10.0, 0.5, (0.1, 0.5), (0.2, 0.6), n=5)
    A, B, PE = ax.valley
    for idx in np.ndindex(A.shape):
        d = bl.singh.lacoste_lever(10.0, 0.5, A[idx], B[idx])
        np.testing.assert_allclose(d.potential_energy(np.linspace(-3, 3, 7)).total, PE[idx], rtol=1e-12)
    # a family: the constants are the springs' and the loci the labels' positions
    def factory(b_y):
        return bl.singh.generalized_lever(10.0, 0.5, 0.2, 0.1, b_y)

    values = [0.2, 0.3, 0.4]
    ax1, _ = S.family_plot(factory, "b_y", values, q=[0.7])
    designs = [factory(v) for v in values]
    np.testing.assert_array_equal(ax1.family["constants"]["k"], [d.springs[0].k for d in designs])
    for lab, pts in ax1.family["loci"].items():
        np.testing.assert_array_equal(pts, [d.world_points([0.7], [d.labels[lab]])[0] for d in designs])
    # cognates: the curve is the named point over the design's reachable range
    d = bl.catalog()["fourbar_two_springs"]()
    ax = S.cognates_plot([d], point=list(d.labels)[-1], n=50)
    grid = F.range_grid(d, 50)
    want = d.world_points(grid[d.reachable(grid)], [list(d.labels.values())[-1]])[:, 0, :]
    np.testing.assert_array_equal(ax.curves[0], want)
    # the energy curve and its marker
    view = E.energy_plot(d, q=F.default_q(d)).energy
    x, y = view.lines["total"].get_data()
    ok = np.isfinite(y)
    np.testing.assert_array_equal(x, np.degrees(view.grid[:, 0]))
    np.testing.assert_array_equal(np.asarray(y)[ok], d.potential_energy(view.grid[ok]).total)
    mx, my = view.marker.get_data()
    assert my[0] == float(d.potential_energy(F.default_q(d)).total)


def test_lever_valley_surface_and_bad_input():
    ax = S.lever_valley(kind="surface", n=20)
    assert ax.name == "3d"
    with pytest.raises(ValueError, match="a_range must be increasing"):
        S.lever_valley(a_range=(0.5, 0.1))
    with pytest.raises(ValueError, match="kind"):
        S.lever_valley(kind="bars")
    with pytest.raises(ValueError, match="> 0"):
        S.lever_valley(weight=-1.0)


def test_family_plot_of_designs():
    values = [0.0, 0.1, 0.2, 0.3, 0.4]  # 0 is invalid (a_x must be > 0)
    ax1, ax2 = S.family_plot(lambda a_x: bl.singh.lacoste_lever(10.0, 0.5, a_x, 0.3), "a_x", values,
                             q=[0.4], points=["a"])
    fam = ax1.family
    np.testing.assert_allclose(fam["values"], values[1:])
    np.testing.assert_allclose(fam["constants"]["k"], [10.0 * 0.5 / (v * 0.3) for v in values[1:]])
    want = np.array([[v * math.cos(0.4), v * math.sin(0.4)] for v in values[1:]])
    np.testing.assert_allclose(fam["loci"]["a"], want, atol=1e-12)
    assert "1 invalid values skipped" in ax2.get_title()
    assert len(ax2.lines) == 1


def test_family_plot_with_springs_that_come_and_go():
    def factory(n):
        d = bl.lecture.single_link_spring(2.0, 0.5, 0.3, 0.2)
        if n < 1:
            return d.replace(springs=[])  # a bare link: nothing named k
        return d

    ax1, ax2 = S.family_plot(lambda n: factory(n), "n", [0, 1], q=[0.3])
    k = ax1.family["constants"]["k"]
    assert np.isnan(k[0]) and k[1] == pytest.approx(2.0 * G * 0.5 / (0.3 * 0.2))


def test_family_plot_of_dicts_and_errors():
    def family(h):
        if h <= 0:
            raise ValueError("h must be > 0")
        return {"H": (h, 2 * h), "k_b": 3 * h, "k_t": 1 / h}

    ax1, ax2 = S.family_plot(family, "h", [-1.0, 1.0, 2.0, 4.0])
    np.testing.assert_allclose(ax1.family["loci"]["H"], [[1, 2], [2, 4], [4, 8]])
    np.testing.assert_allclose(ax1.family["constants"]["k_t"], [1.0, 0.5, 0.25])
    with pytest.raises(ValueError, match="failed for every value"):
        S.family_plot(family, "h", [-1.0, 0.0])
    with pytest.raises(TypeError, match="callable"):
        S.family_plot(3, "h", [1.0])


def test_cognates_plot_traces_the_named_point():
    # two levers with different spring attachments carry the load on one and the same circle
    a = bl.singh.lacoste_lever(10.0, 0.5, 0.2, 0.3)
    b = bl.singh.lacoste_lever(10.0, 0.5, 0.4, 0.1)
    ax = S.cognates_plot([a, b], point="p", n=91)
    for curve in ax.curves:
        np.testing.assert_allclose(np.hypot(*curve.T), 0.5, rtol=1e-12)
    np.testing.assert_allclose(ax.curves[0], ax.curves[1], atol=1e-12)
    assert len(ax.patches) >= 4  # both mechanisms drawn
    with pytest.raises(ValueError, match="no point named 'E'"):
        S.cognates_plot([a], point="E")


def test_two_dof_residual_map_is_the_generalized_force():
    d = two_link_arm(W2=6.0).replace(name="unbalanced arm")  # same springs, other weights below
    k = d.springs[0]
    d = d.replace(springs=[Spring(k.k * 1.2, 0.0, k.a, k.b, "k1"), *d.springs[1:]])
    fig, (ax1, ax2) = plt.subplots(1, 2)
    ax = E.energy_plot(d, ax=ax1, residual=ax2, n=21)
    view = ax.energy
    R = np.asarray(view.residual_image.get_array()).ravel()
    want = np.max(np.abs(d.generalized_force(view.grid)), axis=-1) / view.report.scale
    np.testing.assert_allclose(R, want, rtol=1e-9)
    assert not view.report.balanced and view.note.get_text().startswith("not balanced")
    with pytest.raises(ValueError, match="residual="):
        E.energy_plot(d, ax=ax1, residual=True)


def test_the_three_catalog_cognates_trace_one_coupler_curve():
    cat = bl.catalog()
    designs = [cat[f"deepak_cognate_{i}"]() for i in (1, 2, 3)]
    ax = S.cognates_plot(designs, point="E", n=181)
    first = ax.curves[0]
    assert len(first) > 100
    for curve in ax.curves[1:]:  # driven by the same crank angle: the same points, in order
        np.testing.assert_allclose(curve, first, atol=1e-9)
    assert len(ax.get_legend().get_texts()) == 3


def test_an_alt_text_that_says_not_flat_shows_two_different_numbers():
    """Attack A23: ch3's alt text read "varies from 23 to 23 J": 3 digits hid the variation it names."""
    import re as _re

    from balancelab.viz.energy import _j_range

    for lo, delta in ((23.04, 0.004), (1.0, 1e-6), (-5.0, 1e-4), (0.0, 1e-3)):
        a, b = _j_range(lo, lo + delta, 100.0)
        assert a != b and float(a) <= float(b), (lo, delta, a, b)
        assert _re.fullmatch(r"-?[\d.e+-]+", a) and _re.fullmatch(r"-?[\d.e+-]+", b)
