"""Exact balance with a real spring over a non-circular pulley: model, independent cable check, exports."""
from __future__ import annotations

import csv
import math
import re
import xml.etree.ElementTree as ET

import numpy as np
import pytest

import balancelab as bl
from balancelab import G
from balancelab.core.design import UnreachableConfiguration
from balancelab.methods import realize as rz
from balancelab.methods.practice.springs import ExtensionSpring

MASS, LENGTH, B, C = 2.0, 0.5, 0.3, 0.2
RANGE = (-math.pi / 3, math.pi / 3)
REAL = ExtensionSpring(3e-3, 24e-3, 60, initial_tension=40.0)


@pytest.fixture(scope="module")
def lever():
    return bl.lecture.single_link_spring(MASS, LENGTH, B, C)


@pytest.fixture(scope="module")
def design(lever):
    return rz.noncircular_pulley(lever, spring_model=REAL, angle_range=RANGE, min_tension=45.0)


def _load_torque(theta):
    """Torque (N m, counter-clockwise) of the weight at the tip: -m g r cos(theta)."""
    return -MASS * G * LENGTH * np.cos(theta)


def _cross(u, v):
    return u[..., 0] * v[..., 1] - u[..., 1] * v[..., 0]


# --------------------------------------------------------------- the library's model
def test_real_spring_and_balance_report(design):
    s = design.springs[0]
    assert s.k == pytest.approx(REAL.k) and s.free_length == pytest.approx(REAL.equivalent_free_length)
    assert s.free_length > 0 and not s.is_zfl and s.cable is s.realization
    rep = design.balance_report()
    assert rep.balanced and rep.variation < 1e-12
    assert np.allclose(design.q_range, [RANGE])


def test_spring_torque_equals_load_torque_at_1000_random_angles(design):
    theta = np.random.default_rng(7).uniform(*RANGE, 1000)
    prof = design.springs[0].cable
    cab = prof.cable(theta)
    poses = design.poses(theta)
    length = prof.length(poses[:, 0], poses[:, 1])   # the spring's length, as the design's energy uses it
    tension = REAL.k * (length - REAL.equivalent_free_length)
    assert np.all(tension >= REAL.initial_tension)
    pull = (cab.anchor - cab.tangent) / np.hypot(*(cab.anchor - cab.tangent).T)[:, None]
    spring_torque = tension * _cross(cab.tangent, pull)   # about the pivot at the origin
    scale = MASS * G * LENGTH
    assert np.max(np.abs(spring_torque + _load_torque(theta))) < 1e-9 * scale
    # and the design's own energy agrees: its derivative is zero to the differences' accuracy
    assert np.max(np.abs(design.generalized_force(theta))) < 1e-6 * scale


def test_path_changes_at_the_rate_of_the_cable_lines_distance_from_the_pivot(design):
    prof = design.springs[0].cable
    theta = np.linspace(RANGE[0] + 0.01, RANGE[1] - 0.01, 50)
    step = 1e-6
    rate = (prof.cable(theta + step).path - prof.cable(theta - step).path) / (2 * step)
    cab = prof.cable(theta)
    pull = (cab.anchor - cab.tangent) / np.hypot(*(cab.anchor - cab.tangent).T)[:, None]
    # virtual work: the pull's torque about the pivot is -T dP/dtheta
    assert np.allclose(rate, -_cross(cab.tangent, pull), atol=1e-8)
    assert np.all(cab.straight > 0) and np.all(cab.wrapped >= -1e-12)


def test_outside_the_covered_range_the_design_says_where_it_fails(design):
    with pytest.raises(UnreachableConfiguration, match=r"-60\.0+°, 60\.0+°"):
        design.potential_energy(1.3)
    with pytest.raises(rz.ProfileError, match=r"covers -60\.000° to 60\.000°"):
        design.springs[0].cable.cable(np.array([0.0, 1.4]))


def test_no_symbolic_energy_for_a_cable_path(design):
    with pytest.raises(NotImplementedError, match="cable"):
        design.potential_energy_symbolic()


def test_circle_is_a_constant_support_function():
    R, rho = 0.02, 0.3
    prof = rz.NoncircularProfile([R], [math.pi / 2 + math.acos(R / rho), -1.0], (-1.0, 1.0), (0.0, rho),
                                 (0.0, 0.0), 1, 0.0)
    x = np.linspace(-1, 1, 21)
    assert np.allclose(np.hypot(*prof.local_points(x).T), R, atol=1e-15)
    assert np.allclose(prof.radius_of_curvature(x), R, atol=1e-15)
    cab = prof.cable(np.linspace(-0.9, 0.9, 7))
    assert np.allclose(cab.straight, math.sqrt(rho ** 2 - R ** 2), atol=1e-14)
    assert np.allclose(cab.wrapped, R * (np.linspace(-0.9, 0.9, 7) + 1.0), atol=1e-14)


# ------------------------------------------------------- independent check from the export
def _read_csv(path):
    with open(path, newline="") as f:
        rows = [r for r in csv.reader(line for line in f if not line.startswith("#"))]
    assert rows[0] == ["link_angle_deg", "x_mm", "y_mm"]
    return np.array(rows[1:], dtype=float)


def _cable_from_points(points, end, anchor, theta):
    """Path length and torque arm of a taut cable from ``anchor`` round the polyline ``points``.

    Our own computation: the tangent vertex is the interior extremum of the direction seen
    from the anchor; the wrapped length is the polyline's length from there to the end ``end``.
    """
    c, s = math.cos(theta), math.sin(theta)
    world = points @ np.array([[c, s], [-s, c]])
    rel = world - anchor
    ang = np.unwrap(np.arctan2(rel[:, 1], rel[:, 0]))
    i = int(np.argmax(ang)) if 0 < np.argmax(ang) < len(ang) - 1 else int(np.argmin(ang))
    assert 0 < i < len(ang) - 1, "the cable's tangent point is off the exported profile"
    seg = np.hypot(*np.diff(world, axis=0).T)
    e = 0 if np.hypot(*(points[0] - end)) < np.hypot(*(points[-1] - end)) else len(points) - 1
    wrapped = seg[:i].sum() if e == 0 else seg[i:].sum()
    straight = float(np.hypot(*rel[i]))
    arm = float(_cross(world[i], -rel[i] / straight))
    return straight + wrapped, arm


def test_exported_points_balance_within_the_bound_their_spacing_implies(design, tmp_path):
    n = 2000
    path = rz.export_profile(design, tmp_path / "pulley.csv", n=n, tolerance=1e-6)
    pts = _read_csv(path)[:, 1:] / 1000.0
    assert len(pts) == n
    spacing = float(np.max(np.hypot(*np.diff(pts, axis=0).T)))
    a, b, c = pts[:-2], pts[1:-1], pts[2:]
    circum = (np.hypot(*(a - b).T) * np.hypot(*(b - c).T) * np.hypot(*(c - a).T)
              / (2 * np.abs(_cross(b - a, c - a))))
    r_min = float(np.min(circum))
    s = design.springs[0]
    anchor, end = np.array(s.a.point), np.array(s.b.point)
    p = design.parameters
    cable_length = p["cable_length"] - p["anchor_distance"]   # path minus spring length, from the build data
    rho = float(np.hypot(*anchor))
    arc = float(np.hypot(*np.diff(pts, axis=0).T).sum())
    # a vertex is at most `spacing` along the curve from the true tangent point: the path is
    # stationary there, so it errs by at most spacing^2 / r_min; chords fall short of the arc by
    # at most arc spacing^2 / (24 r_min^2); the line through the vertex moves by spacing^2 / (2 r_min)
    # at the profile, i.e. its distance from the pivot by that times rho / (shortest straight part)
    theta = np.random.default_rng(3).uniform(RANGE[0] + 0.02, RANGE[1] - 0.02, 200)
    straight_min = float(np.min(s.cable.cable(theta).straight))
    d_path = spacing ** 2 / r_min + arc * spacing ** 2 / (24 * r_min ** 2) + 2e-9
    d_arm = spacing ** 2 / (2 * r_min) * rho / straight_min + 2e-9
    worst, bound = 0.0, 0.0
    for th in theta:
        length, arm = _cable_from_points(pts, end, anchor, th)
        tension = s.k * (length - cable_length - s.free_length)
        residual = abs(tension * arm + _load_torque(th))
        allowed = abs(tension) * d_arm + s.k * d_path * abs(arm)
        worst, bound = max(worst, residual / allowed), max(bound, allowed)
    assert worst <= 1.0
    assert bound < 1e-4 * MASS * G * LENGTH   # 2,000 points: within 1e-4 of the load's torque


# ------------------------------------------------------------------ exports read back
def _polyline_distance(points, poly):
    """Largest distance from any of ``points`` to the closed polyline ``poly`` (its segments)."""
    a, b = poly, np.roll(poly, -1, axis=0)
    ab = b - a
    t = np.clip(np.sum((points[:, None] - a) * ab, -1) / np.sum(ab * ab, -1), 0.0, 1.0)
    d = np.hypot(*(points[:, None] - (a + t[..., None] * ab)).transpose(2, 0, 1))
    return float(np.max(np.min(d, axis=1)))


def test_dxf_reads_back_within_a_hundredth_of_a_millimetre(design, tmp_path):
    ezdxf = pytest.importorskip("ezdxf")
    part = rz.profile_part(design, n=800)
    doc = ezdxf.readfile(rz.export_profile(design, tmp_path / "pulley.dxf", n=800, tolerance=1e-5))
    assert doc.header["$INSUNITS"] == 4    # millimetres
    msp = doc.modelspace()
    got = {e.dxf.layer: e for e in msp if e.dxftype() in ("LWPOLYLINE", "CIRCLE")}
    pitch = np.array([p[:2] for p in got["PITCH"].get_points()]) / 1000
    assert np.max(np.abs(pitch - part.pitch)) < 1e-5
    for layer, model in (("GROOVE", part.groove), ("FLANGE", part.flange)):
        poly = np.array([p[:2] for p in got[layer].get_points()]) / 1000
        assert got[layer].closed and np.max(np.abs(poly - model)) < 1e-5
    assert got["AXLE"].dxf.radius / 1000 == pytest.approx(part.axle_diameter / 2, abs=1e-5)
    # the groove is the cable's radius inside the pitch curve, the flange 4 mm outside it
    prof = design.springs[0].cable
    x = np.linspace(-1, 1, 800)
    groove_arc = prof.local_points(x) - 0.00075 * prof.normals(x)
    assert _polyline_distance(groove_arc, np.array([p[:2] for p in got["GROOVE"].get_points()]) / 1000) < 1e-5


def test_svg_reads_back_within_a_hundredth_of_a_millimetre(design, tmp_path):
    part = rz.profile_part(design, n=600)
    root = ET.parse(rz.export_profile(design, tmp_path / "pulley.svg", n=600, tolerance=1e-5)).getroot()
    assert root.get("width").endswith("mm")
    ns = {"s": "http://www.w3.org/2000/svg"}
    paths = {p.get("id"): p.get("d") for p in root.findall("s:path", ns)}
    for name, model in (("pitch", part.pitch), ("groove", part.groove), ("flange", part.flange)):
        xy = np.array(re.findall(r"(-?[\d.]+),(-?[\d.]+)", paths[name]), dtype=float) / 1000
        xy[:, 1] *= -1   # SVG's y runs down
        assert np.max(np.abs(xy - model)) < 1e-5, name
    axle = root.find("s:circle", ns)
    assert float(axle.get("r")) / 1000 == pytest.approx(part.axle_diameter / 2, abs=1e-5)


def test_the_part_holds_the_pivot_and_the_outlines_are_convex(design):
    part = rz.profile_part(design)
    for outline in (part.groove, part.flange):
        nxt = np.roll(outline, -1, axis=0)
        turn = _cross(nxt - outline, np.roll(nxt, -1, axis=0) - nxt)
        assert np.all(turn >= -1e-15)          # counter-clockwise and convex
        edges = _cross(nxt - outline, -outline)   # the pivot is on the inner side of every edge
        assert np.all(edges > 0)
    with pytest.raises(ValueError, match="boss"):
        rz.profile_part(design, axle_diameter=0.05)
    with pytest.raises(ValueError, match=r"\.svg, \.dxf or \.csv"):
        rz.export_profile(design, "pulley.png")


# --------------------------------------------------------------- existence and errors
def test_default_tension_search_finds_a_wrappable_balanced_profile(lever):
    d = rz.noncircular_pulley(lever, spring_model=REAL, angle_range=RANGE)
    p = d.parameters
    assert d.balance_report().balanced
    assert p["min_radius_of_curvature"] >= 0.005 and p["min_tension"] >= REAL.initial_tension
    assert p["max_tension"] <= rz.spring_limits(REAL)["max_force"]
    assert p["stroke"] == pytest.approx((p["max_tension"] - p["min_tension"]) / REAL.k)


def test_concave_profile_is_refused_with_its_radius(lever):
    with pytest.raises(rz.ProfileError, match=r"concave at -?\d+\.\d+° \(radius of curvature -[\d.]+"):
        rz.noncircular_pulley(lever, spring_model=REAL, angle_range=RANGE, min_tension=100.0, turn=1)


def test_curvature_below_the_cables_bending_radius_is_refused(lever, design):
    rmin = design.parameters["min_radius_of_curvature"]
    with pytest.raises(rz.ProfileError, match=r"below the cable's bending radius \(cable_bend_radius\) 30 mm by [\d.]+ mm"):
        rz.noncircular_pulley(lever, spring_model=REAL, angle_range=RANGE, min_tension=45.0,
                              cable_bend_radius=0.03)
    assert rmin < 0.03


def test_overstressed_spring_and_hooks_are_refused(lever):
    weak = ExtensionSpring(1.5e-3, 12e-3, 30, initial_tension=5.0)
    with pytest.raises(rz.ProfileError, match=r"overstressed.*(body|hook).*by [\d.]+ %"):
        rz.noncircular_pulley(lever, spring_model=weak, angle_range=RANGE, min_tension=20.0)
    lim = rz.spring_limits(REAL)
    assert lim["max_force"] == min(lim["body"], lim["hook_bending"], lim["hook_torsion"])


def test_slack_cable_and_close_eyelet_are_refused(lever):
    with pytest.raises(rz.ProfileError, match="below the spring's initial tension"):
        rz.noncircular_pulley(lever, spring_model=REAL, angle_range=RANGE, min_tension=30.0, turn=-1)
    with pytest.raises(rz.ProfileError, match="eyelet is only 0.05 m"):
        rz.noncircular_pulley(lever, spring_model=REAL, angle_range=RANGE, min_tension=45.0, eyelet=(0.0, 0.05))


def test_bad_input_names_the_parameter(lever):
    with pytest.raises(ValueError, match="angle_range"):
        rz.noncircular_pulley(lever, spring_model=REAL, angle_range=(1.0, -1.0))
    with pytest.raises(ValueError, match="180"):
        rz.noncircular_pulley(lever, spring_model=REAL, angle_range=(-2.0, 2.0))
    with pytest.raises(TypeError, match="spring_model"):
        rz.noncircular_pulley(lever, spring_model=100.0)
    with pytest.raises(ValueError, match=r"spring must be an integer in 0\.\.0, got 3"):
        rz.noncircular_pulley(lever, 3, spring_model=REAL)
    with pytest.raises(TypeError, match=r"spring must be an integer in 0\.\.0, got 0\.0"):
        rz.noncircular_pulley(lever, 0.0, spring_model=REAL)
    with pytest.raises(ValueError, match="turn"):
        rz.noncircular_pulley(lever, spring_model=REAL, angle_range=RANGE, min_tension=45.0, turn=2)
    with pytest.raises(ValueError, match=r"it must join the ground \(body 0\) to the body it pulls"):
        rz.noncircular_pulley(bl.singh.scissors_lift(), spring_model=REAL, angle_range=(0.3, 0.9))


def test_lamp_arm_two_pulleys_one_per_joint():
    """The lecture's 2R lamp arm with springs at the base: link 1 and the base copy of link 2 each get a
    real spring on its own profile (the parallelogram carries link 2's angle to the base)."""
    lamp = bl.lecture.serial_2r_base_springs(masses=(1.0, 1.0), length=0.5, coms=((0.25, 0.0), (0.25, 0.0)),
                                             b=(0.3, 0.25), c=(0.15, 0.1))
    real = ExtensionSpring(2.5e-3, 20e-3, 60, initial_tension=20.0)
    one = rz.noncircular_pulley(lamp, 0, spring_model=real, angle_range=RANGE)
    both = rz.noncircular_pulley(one, 1, spring_model=real, angle_range=RANGE)
    assert all(s.cable is not None and s.free_length > 0 for s in both.springs)
    assert np.allclose(both.q_range, [RANGE, RANGE]) and both.name.endswith("non-circular pulleys")
    rep = both.balance_report()
    assert rep.balanced and rep.variation < 1e-12
    # each cable's torque balances the generalized force of the loads on its own coordinate
    q = both.sample(300, seed=5)
    loads = both.replace(springs=[]).generalized_force(q)
    for j, s in enumerate(both.springs):
        cab = s.cable.cable(q[:, j])
        tension = s.k * (cab.path - s.cable.cable_length - s.free_length)
        pull = (cab.anchor - cab.tangent) / np.hypot(*(cab.anchor - cab.tangent).T)[:, None]
        assert np.max(np.abs(tension * _cross(cab.tangent, pull) - loads[:, j])) < 1e-6 * np.max(np.abs(loads))


# ------------------------------------------------------------------ drawing
def test_drawing_follows_the_design_cable(design):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from balancelab.viz.springs import cable_angle, cable_path, profile_outline

    s = design.springs[0]
    for q in (-0.9, 0.0, 0.8):
        end = design.world_points(q, [s.b])[0]
        assert cable_angle(s, end) == pytest.approx(q, abs=1e-12)
        x, y = cable_path(s, q, 1.0)
        cab = s.cable.cable(q)
        path = np.column_stack([x, y])
        assert np.allclose(path[-1], end, atol=1e-12)                     # ends at the clamp
        assert np.min(np.hypot(*(path - cab.tangent).T)) < 1e-12           # passes the tangent point
        eyelet = np.add(s.cable.pivot, s.cable.anchor)
        assert np.min(np.hypot(*(path - eyelet).T)) < 1e-12                # and the eyelet
        # the coil starts at the spring's fixed anchor (the design's build data), runs towards the eyelet
        # at the spring's true length to its hook end, and the cable goes on from the hook to the eyelet
        anchor = np.array(design.parameters["spring_anchor"])
        assert np.allclose(path[0], anchor, rtol=0, atol=1e-12)
        at_eyelet = int(np.argmin(np.hypot(*(path - eyelet).T)))
        hook = path[at_eyelet - 1]
        assert np.hypot(*(hook - anchor)) == pytest.approx(cab.path - s.cable.cable_length, rel=1e-12)
        assert abs(_cross(hook - anchor, eyelet - anchor)) < 1e-12    # on the line from the anchor to the eyelet
        assert np.hypot(*(hook - anchor)) < np.hypot(*(eyelet - anchor))
        ox, oy = profile_outline(s, q)
        assert np.allclose(np.column_stack([ox, oy])[0], s.cable.world(q, s.cable.local_points(-1.0)))
    fig = bl.draw(design, 0.3).figure
    assert any(line.get_gid() == f"spring:{s.name}" for line in fig.axes[0].lines)
    plt.close(fig)
    anim = bl.animate(design, frames=6)
    assert anim is not None
    plt.close("all")


# ------------------------------------------------------------------ properties
from hypothesis import HealthCheck, given, settings  # noqa: E402
from hypothesis import strategies as st  # noqa: E402


@settings(max_examples=25, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(mass=st.floats(0.5, 4.0), length=st.floats(0.2, 0.8), eyelet_r=st.floats(0.1, 0.6),
       eyelet_a=st.floats(-math.pi, math.pi), lo=st.floats(-1.2, 0.3), span=st.floats(0.3, 1.6),
       tension=st.floats(1.0, 4.0), turn=st.sampled_from([1, -1, None]))
def test_every_profile_it_builds_balances_and_every_refusal_is_a_profile_error(mass, length, eyelet_r, eyelet_a,
                                                                                lo, span, tension, turn):
    lever = bl.lecture.single_link_spring(mass, length, 0.3, 0.2)
    eyelet = (eyelet_r * math.cos(eyelet_a), eyelet_r * math.sin(eyelet_a))
    try:
        d = rz.noncircular_pulley(lever, spring_model=REAL, angle_range=(lo, lo + span), eyelet=eyelet,
                                  min_tension=tension * REAL.initial_tension, turn=turn)
    except rz.ProfileError as err:
        assert "°" in str(err) or " N" in str(err)   # it says where or by how much
        return
    theta = np.random.default_rng(0).uniform(lo, lo + span, 200)
    cab = d.springs[0].cable.cable(theta)
    p = d.parameters
    tension_now = REAL.k * (p["anchor_distance"] + cab.path - p["cable_length"] - REAL.equivalent_free_length)
    pull = (cab.anchor - cab.tangent) / np.hypot(*(cab.anchor - cab.tangent).T)[:, None]
    residual = tension_now * _cross(cab.tangent, pull) - mass * G * length * np.cos(theta)
    assert np.max(np.abs(residual)) < 1e-9 * mass * G * length
    assert np.all(tension_now >= REAL.initial_tension * (1 - 1e-12))
    assert d.parameters["min_radius_of_curvature"] >= 0.005 and d.balance_report().balanced


def test_spring_limits_follow_the_hook_and_body_formulas():
    # Shigley's hook stresses, written out here: bending at the loop (C1 = C), torsion at the bend (C2 = 4)
    d, D = REAL.wire_diameter, REAL.coil_diameter
    C1, C2 = D / d, 4.0
    sut = 2211e6 / (d * 1000) ** 0.145                      # music wire, A / d^m
    per_newton_bending = (4 * C1 ** 2 - C1 - 1) / (4 * C1 * (C1 - 1)) * 16 * D / (math.pi * d ** 3) \
        + 4 / (math.pi * d ** 2)
    per_newton_torsion = (4 * C2 - 1) / (4 * C2 - 4) * 8 * D / (math.pi * d ** 3)
    lim = rz.spring_limits(REAL)
    assert lim["hook_bending"] == pytest.approx(0.75 * sut / per_newton_bending, rel=1e-12)
    assert lim["hook_torsion"] == pytest.approx(0.40 * sut / per_newton_torsion, rel=1e-12)
    assert lim["body"] == pytest.approx(REAL.max_forces()["body"], rel=1e-12)
    assert REAL.stress(lim["body"]) == pytest.approx(0.45 * sut, rel=1e-9)


def test_a_full_turn_default_range_asks_for_angle_range(lever):
    with pytest.raises(ValueError, match=r"pass angle_range=\(lo, hi\)"):
        rz.noncircular_pulley(lever, spring_model=REAL)


# ---------------------------------------------------------------- regressions of the outside attack (issue 25)
def test_spring_limits_credit_the_part_that_governs(lever, design):
    bare = ExtensionSpring(3e-3, 24e-3, 60, initial_tension=40.0, hooks=False)
    assert rz.spring_limits(bare) == {"body": bare.max_forces()["body"], "max_force": bare.max_forces()["body"]}
    # 270 N is within the bare body's 316.6 N: the spring check passes, whatever else refuses the profile
    try:
        d = rz.noncircular_pulley(lever, spring_model=bare, angle_range=(0.0, 0.3), min_tension=270.0)
        assert d.parameters["limiting_part"] == "body"
    except rz.ProfileError as err:
        assert "hook" not in str(err) and "overstressed" not in str(err)
    lim = rz.spring_limits(REAL)
    weakest = min(("body", "hook_bending", "hook_torsion"), key=lim.get)
    with pytest.raises(rz.ProfileError, match=rf"exceeds what its {weakest.replace('_', ' ')} allows, "
                                              rf"{lim[weakest]:.4g} N"):
        rz.noncircular_pulley(lever, spring_model=REAL, angle_range=(0.0, 0.3), min_tension=270.0)
    p = design.parameters
    assert p["limiting_part"] == weakest and p["allowable_force"] == lim[weakest]
    # the reported stress is that of the governing part at the largest tension, at or below its allowable
    assert p["max_stress"] == pytest.approx(float(REAL.stresses(p["max_tension"])[weakest]), rel=1e-12)
    assert p["max_stress"] / float(REAL.stresses(lim[weakest])[weakest]) == pytest.approx(p["max_tension"] / lim[weakest])


def test_a_lever_built_with_linkage_is_accepted_and_balanced():
    lk = bl.Linkage("lever")
    lk.revolute("ground", (0.0, 0.0), "arm", (0.0, 0.0))
    lk.mass("arm", MASS, com=(LENGTH, 0.0))
    lk.spring("ground", (0.0, B), "arm", (C, 0.0), MASS * G * LENGTH / (B * C))
    d = lk.build()
    assert d.balance_report().balanced
    real = rz.noncircular_pulley(d, spring_model=REAL, angle_range=RANGE, min_tension=45.0)
    assert real.balance_report().balanced
    assert real.q_range[0].tolist() == pytest.approx(list(RANGE))
    q = np.linspace(*RANGE, 41)[:, None]
    e = real.potential_energy(q).total
    assert np.ptp(e) <= 1e-6 * MASS * G * LENGTH


def test_a_spring_that_does_not_join_the_ground_or_a_pivoted_body_is_refused_with_the_reason():
    lk = bl.Linkage("offset lever")
    lk.revolute("ground", (0.1, 0.0), "arm", (0.0, 0.0))
    lk.mass("arm", MASS, com=(LENGTH, 0.0))
    lk.spring("ground", (0.1, B), "arm", (C, 0.0), MASS * G * LENGTH / (B * C))
    with pytest.raises(ValueError, match=r"turn about a ground pivot at the world origin"):
        rz.noncircular_pulley(lk.build(), spring_model=REAL, angle_range=RANGE, min_tension=45.0)
    none = bl.lecture.single_link_spring(MASS, LENGTH, B, C).replace(springs=[])
    with pytest.raises(ValueError, match="has no spring"):
        rz.noncircular_pulley(none, spring_model=REAL, angle_range=RANGE)


@pytest.mark.parametrize("theta", [3.0, -3.0, RANGE[1] + 1e-3, RANGE[0] - 1e-3, 2 * math.pi, float("nan")])
def test_every_angle_outside_the_covered_range_is_refused(design, theta):
    profile = design.springs[0].cable
    with pytest.raises(rz.ProfileError, match="the profile covers"):
        profile.cable(theta)
    with pytest.raises(rz.ProfileError, match="the profile covers"):
        profile.tangent_parameter(np.array([0.0, theta]))
    with pytest.raises(rz.ProfileError, match="the profile covers"):
        profile.length(np.zeros(3), np.array([0.0, 0.0, theta]))
    assert np.all(np.isfinite(profile.cable(np.linspace(*RANGE, 9)).path))


def test_build_data_reassemble_to_the_models_spring_lengths(design):
    p, s = design.parameters, design.springs[0]
    eyelet, anchor = np.array(p["eyelet"]), np.array(p["spring_anchor"])
    assert eyelet.tolist() == pytest.approx(list(s.a.point)) and list(p["clamp"]) == pytest.approx(list(s.b.point))
    assert np.hypot(*(anchor - eyelet)) == pytest.approx(p["anchor_distance"], rel=1e-12)
    # the anchor lies on the line from the pivot through the eyelet, beyond the eyelet
    assert _cross(eyelet, anchor - eyelet) == pytest.approx(0.0, abs=1e-12) and np.dot(eyelet, anchor - eyelet) > 0
    theta = np.linspace(*RANGE, 13)
    cab = s.cable.cable(theta)
    q = theta[:, None]
    poses = design.poses(q)
    model = s.cable.length(poses[:, 0], poses[:, 1])              # the spring's length in the model
    # cable = (spring's hook end -> eyelet) + (eyelet -> tangent -> clamp E)
    rebuilt = p["anchor_distance"] - model + cab.path
    assert np.allclose(rebuilt, p["cable_length"], rtol=0, atol=1e-12)
    # the clamp is where the cable ends, carried by the link
    assert np.allclose(cab.end, s.cable.world(theta, np.array(p["clamp"])), atol=1e-12)
    # the spring is never shorter than its body, and its hook end never reaches the eyelet
    assert np.all(model >= REAL.body_length * (1 - 1e-12)) and np.all(model < p["anchor_distance"])
    tension = REAL.k * (model - REAL.equivalent_free_length)
    assert p["min_tension"] * (1 - 1e-6) <= tension.min() and tension.max() <= p["max_tension"] * (1 + 1e-6)


EDGE_RANGE = (math.radians(-80), math.radians(-10))


def test_a_profile_too_near_the_axle_is_refused_with_a_min_tension_that_works(lever):
    d = rz.noncircular_pulley(lever, spring_model=REAL, angle_range=EDGE_RANGE, min_tension=149.2)
    with pytest.raises(ValueError, match=r"reach [\d.]+ mm into the cable's groove.*min_tension at most") as err:
        rz.profile_part(d)
    suggested = float(re.search(r"min_tension at most ([\d.]+) N", str(err.value)).group(1))
    assert REAL.initial_tension < suggested < 149.2
    fixed = rz.noncircular_pulley(lever, spring_model=REAL, angle_range=EDGE_RANGE, min_tension=suggested)
    part = rz.profile_part(fixed)
    hub = 0.008 / 2 + 0.004
    prof = fixed.springs[0].cable
    h = np.sum(part.pitch * prof.normals((part.link_angle - prof.mid) / prof.half), -1)
    assert h.min() > hub + 0.0015 / 2 and fixed.balance_report().balanced


def test_a_pivot_outside_the_profile_warns_at_synthesis_and_is_named_at_export(lever):
    with pytest.warns(UserWarning, match="the pivot lies outside the profile"):
        d = rz.noncircular_pulley(lever, spring_model=REAL, angle_range=(-math.pi / 6, math.pi / 4),
                                  eyelet=(0.0, 0.1))
    assert d.balance_report().balanced and d.parameters["min_lever_arm"] < 0
    h = np.polynomial.chebyshev.chebval(np.linspace(-1, 1, 201), d.springs[0].cable.h)
    assert d.parameters["min_lever_arm"] == pytest.approx(h.min(), abs=1e-6)
    with pytest.raises(ValueError, match="the pivot lies outside the profile"):
        rz.profile_part(d)


def test_the_tension_search_finds_a_narrow_feasible_band(lever):
    # with a 21 mm cable bend only a narrow band of tensions just above the envelope's limit is wrappable
    # (those profiles are metres across: allowed explicitly by max_size)
    d = rz.noncircular_pulley(lever, spring_model=REAL, angle_range=EDGE_RANGE, cable_bend_radius=0.021,
                              max_size=50.0)
    assert d.balance_report().balanced and d.parameters["min_radius_of_curvature"] >= 0.021
    with pytest.raises(rz.ProfileError, match="none found"):
        rz.noncircular_pulley(lever, spring_model=REAL, angle_range=EDGE_RANGE, cable_bend_radius=0.021)
    assert REAL.initial_tension <= d.parameters["min_tension"]


def test_search_refusals_say_what_was_searched_and_never_advise_below_the_floor(lever):
    with pytest.raises(rz.ProfileError, match=r"none found: no wrappable profile among \d+ values of min_tension") as err:
        rz.noncircular_pulley(lever, spring_model=REAL, angle_range=EDGE_RANGE, cable_bend_radius=0.5)
    assert "lower min_tension" not in str(err.value)
    for tension in (REAL.initial_tension, 200.0):
        try:
            rz.noncircular_pulley(lever, spring_model=REAL, angle_range=RANGE, min_tension=tension, turn=1)
        except rz.ProfileError as refusal:
            assert tension > REAL.initial_tension or "lower min_tension" not in str(refusal)


def test_absurdly_large_profiles_are_refused_unless_allowed(lever):
    with pytest.raises(rz.ProfileError, match=r"reach [\d.]+ m from the pivot \(.*°\), more than max_size 2 m"):
        rz.noncircular_pulley(lever, spring_model=REAL, angle_range=EDGE_RANGE, min_tension=73.0)
    big = rz.noncircular_pulley(lever, spring_model=REAL, angle_range=EDGE_RANGE, min_tension=73.0, max_size=20.0)
    size = np.max(np.hypot(*big.springs[0].cable.local_points(np.linspace(-1, 1, 2001)).T))
    assert 2.0 < size <= 20.0 and big.parameters["size"] == pytest.approx(size, rel=1e-3)
    with pytest.raises(ValueError, match="max_size"):
        rz.noncircular_pulley(lever, spring_model=REAL, angle_range=RANGE, max_size=-1.0)


def test_the_flange_covers_the_whole_groove_and_the_core_plate(design):
    from matplotlib.path import Path as MplPath

    part = rz.profile_part(design, n=400)
    outline = MplPath(part.flange)
    assert np.all(outline.contains_points(part.pitch, radius=-1e-9) | outline.contains_points(part.pitch, radius=1e-9))
    # every point of the cable's pitch curve, the clamped end included, lies inside the flange by >= 1 mm
    edges = np.concatenate([part.flange, part.flange[:1]])
    d = np.min([np.abs(_cross(b - a, part.pitch - a)) / np.hypot(*(b - a))
                for a, b in zip(edges[:-1], edges[1:])], axis=0)
    assert np.all(outline.contains_points(part.pitch)) and d.min() >= 1e-3 - 1e-12
    assert np.all(outline.contains_points(part.groove, radius=1e-9) | outline.contains_points(part.groove, radius=-1e-9))


def test_each_cable_spring_of_the_lamp_keeps_its_own_build_data_and_its_coil_is_drawn_from_its_anchor():
    """Two different real springs on the lamp arm: ``pulleys[i]`` holds each one's own numbers, which
    reassemble that spring's model length, and the drawn coil of each starts at its own anchor."""
    from balancelab.viz.springs import cable_coil_ends, cable_path

    lamp = bl.lecture.serial_2r_base_springs(masses=(1.0, 1.0), length=0.5, coms=((0.25, 0.0), (0.25, 0.0)),
                                             b=(0.3, 0.25), c=(0.15, 0.1))
    springs = (ExtensionSpring(2.5e-3, 20e-3, 60, initial_tension=20.0),
               ExtensionSpring(2.2e-3, 18e-3, 50, initial_tension=12.0))
    one = rz.noncircular_pulley(lamp, 0, spring_model=springs[0], angle_range=RANGE)
    both = rz.noncircular_pulley(one, 1, spring_model=springs[1], angle_range=RANGE)
    pulleys = both.parameters["pulleys"]
    assert sorted(pulleys) == [0, 1]
    with pytest.raises(TypeError):
        pulleys[0]["k"] = 1.0                  # a design is a value: its build data are read-only
    q = both.sample(50, seed=2)
    for i, real in enumerate(springs):
        p, s = pulleys[i], both.springs[i]
        assert p["k"] == pytest.approx(real.k) and p["free_length"] == pytest.approx(real.equivalent_free_length)
        assert p["initial_tension"] == real.initial_tension
        assert s.k == p["k"] and s.free_length == p["free_length"]
        assert p["eyelet"] == pytest.approx(list(s.a.point)) and p["clamp"] == pytest.approx(list(s.b.point))
        cab = s.cable.cable(q[:, i])
        length = p["anchor_distance"] + cab.path - p["cable_length"]        # from this spring's own build data
        poses = both.poses(q)
        assert np.allclose(length, s.cable.length(poses[:, 0], poses[:, s.b.body]), rtol=0, atol=1e-12)
        tension = s.k * (length - s.free_length)
        assert p["min_tension"] * (1 - 1e-6) <= tension.min() and tension.max() <= p["max_tension"] * (1 + 1e-6)
        fixed, hook = cable_coil_ends(s, q[:, i])
        assert np.allclose(fixed, p["spring_anchor"], rtol=0, atol=1e-12)
        assert np.allclose(np.hypot(*(hook - fixed).T), length, rtol=1e-12)
        x, y = cable_path(s, float(q[0, i]), 1.0)
        assert np.allclose([x[0], y[0]], p["spring_anchor"], rtol=0, atol=1e-12)
    # the springs differ, and so do their numbers; the flat keys are the spring replaced last
    assert pulleys[0]["k"] != pulleys[1]["k"] and pulleys[0]["spring_anchor"] != pulleys[1]["spring_anchor"]
    assert all(both.parameters[key] == pulleys[1][key] for key in pulleys[1])
    assert one.parameters["pulleys"][0]["k"] == pulleys[0]["k"] and 1 not in one.parameters["pulleys"]


# ------------------------------------------------------------------ practice: forces and tolerances
def _energy_slope(d, theta, step=1e-4):
    """dV/dtheta (N m per rad) of a one-coordinate design by the five-point difference of its energy."""
    e = [d.potential_energy(theta + j * step).total for j in (-2, -1, 1, 2)]
    return (e[0] - 8 * e[1] + 8 * e[2] - e[3]) / (12 * step)


def _rebuilt(design, *, anchor_shift=(0.0, 0.0), cable_shift=0.0, free_length=None):
    """The design with its cable spring built off the drawing: eyelet moved, cable longer, free length off."""
    import dataclasses

    s = design.springs[0]
    p = s.cable
    anchor = tuple(np.add(p.anchor, anchor_shift))
    prof = rz.NoncircularProfile(p.h, p.psi, p.angle_range, anchor, p.pivot, p.turn, p.cable_length + cable_shift,
                                 anchor_distance=p.anchor_distance)
    built = dataclasses.replace(s, a=bl.Attachment(0, anchor), realization=prof,
                                free_length=s.free_length if free_length is None else free_length)
    return design.replace(springs=[built])


def test_forces_include_the_cable_and_agree_with_the_energys_derivative(design):
    import dataclasses

    from balancelab.methods.practice import forces

    theta = np.linspace(RANGE[0] + 0.05, RANGE[1] - 0.05, 15)
    s, p = design.springs[0], design.parameters
    # the tension from the build data: spring length = anchor distance + path - cable length
    cab = s.cable.cable(theta)
    expected = s.k * (p["anchor_distance"] + cab.path - p["cable_length"] - s.free_length)
    assert np.allclose(forces.spring_forces(design, theta[:, None])[:, 0], expected, rtol=1e-12)
    # balanced: the joint holds no torque; heavier by 10 %: both routes give the energy's slope
    assert np.max(np.abs(forces.joint_loads(design, theta[:, None]).torque)) < 1e-9 * MASS * G * LENGTH
    heavy = design.replace(loads=[dataclasses.replace(ld, force=tuple(1.1 * f for f in ld.force))
                                  for ld in design.loads])
    slope = _energy_slope(heavy, theta)
    assert np.max(np.abs(slope)) > 0.05 * MASS * G * LENGTH
    _, Q = forces.generalized_force(heavy, theta[:, None])
    assert np.allclose(Q[:, 0], slope, rtol=0, atol=1e-7 * MASS * G * LENGTH)
    jl = forces.joint_loads(heavy, theta[:, None])
    assert np.allclose(jl.torque[:, 0], slope, rtol=0, atol=1e-7 * MASS * G * LENGTH)
    # the joint carries the weight and the cable's pull: the link's forces and moments sum to zero
    pull = (cab.anchor - cab.tangent) / np.hypot(*(cab.anchor - cab.tangent).T)[:, None]
    weight = np.array(heavy.loads[0].force)
    assert np.allclose(jl.force[:, 0], -(weight + expected[:, None] * pull), rtol=0, atol=1e-9)


def test_tolerance_of_a_cable_spring_follows_its_built_errors(design):
    from balancelab.methods.practice import forces, tolerance

    # a rate error e: the tension is (1 + e) times the one that balances, the residual e m g r cos(theta)
    r = tolerance.monte_carlo(design, tolerance.Tolerances(k=0.05), n=300, grid=25)
    e = r.samples["k"][:, 0] / design.springs[0].k - 1
    assert np.allclose(r.worst, np.abs(e) * MASS * G * LENGTH, rtol=1e-6)
    # a misplaced eyelet, a cable too long at the clamp, a wrong free length: the batch's residual is the
    # derivative of the energy of the design rebuilt with that error
    theta = np.linspace(RANGE[0] + 0.1, RANGE[1] - 0.1, 9)
    s = design.springs[0]
    tangent = s.cable.local_points(s.cable.end_parameter) - s.cable.local_points(s.cable.end_parameter * (1 - 1e-6))
    tangent /= np.hypot(*tangent)
    shift = np.array([0.002, -0.0015])
    cases = [({"a_points": [[np.add(s.a.point, shift)]]}, _rebuilt(design, anchor_shift=shift)),
             ({"b_points": [[np.add(s.b.point, 0.001 * tangent)]]}, _rebuilt(design, cable_shift=-0.001)),
             ({"free_length": [[s.free_length + 0.001]]}, _rebuilt(design, free_length=s.free_length + 0.001))]
    for values, built in cases:
        Q = forces.batch_generalized_force(design, theta[:, None], **values)[0, :, 0]
        slope = _energy_slope(built, theta)
        assert np.max(np.abs(slope)) > 1e-3 * MASS * G * LENGTH
        assert np.allclose(Q, slope, rtol=0, atol=1e-7 * MASS * G * LENGTH), values
    sens = tolerance.sensitivities(design, tolerance.Tolerances(k=0.02, attachment=1e-3, free_length=1e-3), n=200)
    assert set(sens) == {"all", "k", "attachment", "free_length"} and all(v > 0 for v in sens.values())


# ------------------------------------------------------------------ the export keeps the balance bound
def test_the_export_refuses_a_polyline_too_coarse_for_the_bound_and_names_n(design, tmp_path):
    with pytest.raises(ValueError, match=r"n=600 points .* varies the energy by [\d.e-]+ .* above the bound "
                                         r"tolerance=1e-09; about \d+ points would"):
        rz.export_profile(design, tmp_path / "coarse.csv", n=600)
    assert not (tmp_path / "coarse.csv").exists()
    for bad in (0.0, 1.0, -1e-6, float("nan"), "tight"):
        with pytest.raises((TypeError, ValueError), match="tolerance"):
            rz.export_profile(design, tmp_path / "bad.csv", n=600, tolerance=bad)
    for bad in (-7, 5, 600.5, "600", float("nan")):     # n=None chooses; any other n must be a count >= 10
        with pytest.raises((TypeError, ValueError), match=r"\bn\b"):
            rz.export_profile(design, tmp_path / "bad.csv", n=bad, tolerance=1e-3)


def test_the_default_export_raises_n_until_the_cut_part_balances_to_the_bound(design, tmp_path):
    """Recomputed here from the written points alone (our own cable wrap): the energy of the weight plus
    the spring's energy varies by at most 1e-9 of what the weight exchanges."""
    pts = _read_csv(rz.export_profile(design, tmp_path / "pulley.csv"))[:, 1:] / 1000.0
    assert len(pts) > 2000
    s, p = design.springs[0], design.parameters
    cable_length = p["cable_length"] - p["anchor_distance"]
    theta = np.concatenate([np.linspace(RANGE[0] + 0.02, RANGE[1] - 0.02, 120),
                            np.random.default_rng(11).uniform(RANGE[0] + 0.02, RANGE[1] - 0.02, 60)])
    paths = np.array([_cable_from_points(pts, np.array(s.b.point), np.array(s.a.point), th)[0] for th in theta])
    weight = MASS * G * LENGTH * np.sin(theta)                    # the tip's weight: m g r sin(theta)
    total = weight + 0.5 * s.k * (paths - cable_length - s.free_length) ** 2
    assert np.ptp(total) <= 1e-9 * (MASS * G * LENGTH * (math.sin(RANGE[1] - 0.02) - math.sin(RANGE[0] + 0.02)))
    # and the polyline of 2,000 points, written with a looser bound, does not keep 1e-9
    coarse = _read_csv(rz.export_profile(design, tmp_path / "coarse.csv", n=2000, tolerance=1e-6))[:, 1:] / 1000.0
    paths = np.array([_cable_from_points(coarse, np.array(s.b.point), np.array(s.a.point), th)[0] for th in theta])
    total = weight + 0.5 * s.k * (paths - cable_length - s.free_length) ** 2
    assert 1e-9 < np.ptp(total) / np.ptp(weight) <= 1e-6


def test_a_misplaced_eyelet_gives_the_cable_path_of_the_cut_part_even_past_the_profiles_ends(design):
    """path_from agrees with the cable wound on a fine polyline of the profile (profile_check's own
    computation), also at the range's ends where the shifted eyelet pulls the cable over the part's end."""
    from balancelab.methods.realize.profile_check import polyline_path

    prof, s = design.springs[0].cable, design.springs[0]
    pts = prof.local_points(np.linspace(-1.0, 1.0, 40001))
    theta = np.array([RANGE[0], RANGE[0] + 0.01, 0.0, RANGE[1] - 0.01, RANGE[1]])
    for shift in ((0.0, 0.0), (0.01, 0.0), (-0.01, 0.0), (0.0, 0.01), (0.0, -0.01)):
        anchor = np.add(prof.anchor, shift)
        got = prof.path_from(theta, anchor)
        want = polyline_path(pts, theta, anchor, s.b.point, prof.turn)
        assert np.allclose(got, want, rtol=0, atol=1e-7), shift


# --- issue 25, A25: the narrowest range the synthesis resolves ----------------------------------------------------

def _circumradii(profile, x, step=1e-3):
    """Radius (m) of the circle through the profile's points at parameters x - step, x, x + step: geometry
    of the curve itself, independent of the support function's derivatives."""
    a, b, c = (profile.local_points(x + d) for d in (-step, 0.0, step))
    ab, bc, ca = (np.hypot(*(q - p).T) for p, q in ((a, b), (b, c), (c, a)))
    twice_area = (b[:, 0] - a[:, 0]) * (c[:, 1] - a[:, 1]) - (b[:, 1] - a[:, 1]) * (c[:, 0] - a[:, 0])
    return ab * bc * ca / (2 * np.abs(twice_area))


@pytest.mark.parametrize("centre", [-0.5, 0.0, 0.5])
def test_just_above_the_narrowest_range_the_curvature_is_the_curves(lever, centre):
    from balancelab.methods.realize.noncircular import MIN_ANGLE_RANGE

    spring = ExtensionSpring(3e-3, 24e-3, 60, initial_tension=40.0)
    d = bl.realize.noncircular_pulley(lever, spring_model=spring, eyelet=(0.0, 0.3),
                                      angle_range=(centre, centre + 1.001 * MIN_ANGLE_RANGE))
    assert d.balance_report().balanced
    profile = d.springs[0].cable
    x = np.linspace(-0.999, 0.999, 41)
    np.testing.assert_allclose(profile.radius_of_curvature(x), _circumradii(profile, x), rtol=1e-3)


@pytest.mark.parametrize("width", [0.999, 0.5, 0.0573, 1e-4])   # in units of the narrowest range; 0.0573 = 1 mrad
def test_below_the_narrowest_range_a_named_error(lever, width):
    from balancelab.methods.realize.noncircular import MIN_ANGLE_RANGE

    spring = ExtensionSpring(3e-3, 24e-3, 60, initial_tension=40.0)
    with pytest.raises(ValueError, match=r"angle_range must span at least 1° \(0\.01745 rad\)"):
        bl.realize.noncircular_pulley(lever, spring_model=spring, eyelet=(0.0, 0.3),
                                      angle_range=(0.5, 0.5 + width * MIN_ANGLE_RANGE))
