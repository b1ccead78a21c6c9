"""Animations: every catalog entry animates; embedded players are small and smooth."""
from __future__ import annotations

import base64
import io
import math
import os
import re
from pathlib import Path

os.environ.setdefault("MPLBACKEND", "Agg")

import numpy as np  # noqa: E402
import pytest  # noqa: E402
from PIL import Image  # noqa: E402

import balancelab as bl  # noqa: E402
from balancelab.viz.animation import animate, animate_parameter, configuration_path  # noqa: E402
from test_plotting import ALL, build, two_link_arm  # noqa: E402

FRAME_RE = re.compile(r'frames\[(\d+)\] = "data:image/webp;base64,([^"]*)"')


def _frames(html: str) -> list[bytes]:
    return [base64.b64decode(m.group(2).replace("\\\n", "").replace("\n", ""))
            for m in FRAME_RE.finditer(html)]


@pytest.mark.parametrize("name", ALL)
def test_every_design_animates_at_the_defaults(name):
    """Every design animates: 60 frames along its configuration path, at >= 20 frames per second,
    and the last frame shows the mechanism where the path ends. (The embedded player's size, < 2 MB
    for every catalog entry, is a target: ``bash scripts/course.sh bench``, benchmarks/bench_explore.py.)"""
    d = build(name)
    anim = animate(d)
    assert anim.fps >= 20
    assert len(anim.path) == 60
    np.testing.assert_array_equal(anim.path, configuration_path(d, 60))
    pixels = anim.frame_image(len(anim.path) - 1)
    w, h = anim._fig.canvas.get_width_height()
    assert pixels.shape == (h, w, 3) and np.ptp(pixels) > 0      # drawn, not blank
    np.testing.assert_allclose(anim.drawing.q, anim.path[-1])


@pytest.mark.parametrize("name", ["single_link_counterweight", "serial_2r_min_preload", "peaucellier_board"])
def test_the_embedded_player_is_offline_smooth_and_ends_where_the_path_ends(name):
    anim = animate(build(name))
    html = anim.to_jshtml()
    frames = _frames(html)
    assert len(frames) == len(anim.path) == 60
    # the player runs at >= 20 frames per second and needs no network
    (interval,) = re.findall(r"new Animation\(frames, img_id, slider_id, ([\d.]+),", html)
    assert 1000.0 / float(interval) >= 20
    assert "http://" not in html and "https://" not in html
    assert 'class="fa' not in html
    # the last embedded frame is the picture of the path's end, drawn with two device pixels per
    # CSS pixel of the figure (sharp on a high-density screen), its resolution recorded
    im = Image.open(io.BytesIO(frames[-1]))
    w, h = anim._fig.canvas.get_width_height()
    assert im.format == "WEBP" and im.size == (2 * w, 2 * h) == tuple(2 * s for s in anim.shown_size)
    assert im.getexif()[0x011A] == 2 * anim._fig.dpi
    np.testing.assert_allclose(anim.drawing.q, anim.path[-1])
    # the figure itself is left at its own resolution
    assert anim.frame_image(0).shape == (h, w, 3)


def test_the_player_shows_its_frames_at_half_their_pixels():
    anim = animate(build("lacoste_lever"), frames=3)
    w, h = anim.shown_size
    page = bl.viz.player(anim, "a lever turning").html
    assert re.search(rf'<img alt="a lever turning" width="{w}" height="{h}" id="_anim_img', page)
    (first,) = _frames(page)[:1]
    assert Image.open(io.BytesIO(first)).size == (2 * w, 2 * h)


def test_frame_count_and_path_of_a_full_turn():
    d = bl.singh.lacoste_lever(10.0, 0.5, 0.2, 0.3)
    anim = animate(d, frames=24, fps=30)
    np.testing.assert_allclose(anim.path[:, 0], -math.pi + 2 * math.pi * np.arange(24) / 24)
    assert len(_frames(anim.to_jshtml())) == 24
    assert anim.fps == 30


def test_limited_range_is_swept_there_and_back():
    d = bl.catalog()["scissors_lift"]()
    path = configuration_path(d, 40)[:, 0]
    lo, hi = d.q_range[0]
    assert path.min() >= lo - 1e-12 and path.max() <= hi + 1e-12
    assert path[0] == pytest.approx(lo, abs=1e-5) and path[20] == pytest.approx(hi, abs=1e-5)
    np.testing.assert_allclose(path[1:20], path[39:20:-1])


def test_two_dof_path_stays_inside_the_range_and_moves_the_marker():
    d = two_link_arm()
    anim = animate(d, frames=30)
    q = anim.path
    assert q.shape == (30, 2)
    assert np.all(q >= d.q_range[:, 0]) and np.all(q <= d.q_range[:, 1])
    anim.frame_image(7)
    x, y = anim.energy.marker.get_data()
    np.testing.assert_allclose([x[0], y[0]], np.degrees(q[7]))


def test_frames_match_a_full_redraw():
    d = bl.catalog()["fourbar_two_springs"]()
    anim = animate(d, frames=10)
    blitted = anim.frame_image(6).copy()
    anim._fig.canvas.draw()
    full = np.asarray(anim._fig.canvas.buffer_rgba())[..., :3]
    assert np.mean(np.any(blitted != full, axis=-1)) < 1e-3


def test_animate_rejects_bad_input():
    d = bl.singh.lacoste_lever(10.0, 0.5, 0.2, 0.3)
    with pytest.raises(ValueError, match="frames"):
        animate(d, frames=1)
    with pytest.raises(ValueError, match="fps"):
        animate(d, fps=0)
    with pytest.raises(TypeError, match="Design"):
        animate(None)
    scissors = bl.catalog()["scissors_lift"]()
    with pytest.raises(bl.UnreachableConfiguration):
        animate(scissors, path=[[0.1], [3.0]])
    # a path of the wrong shape is refused, not reshaped into other configurations
    for bad in (np.zeros((5, 3)), np.zeros((0, 1)), np.zeros((2, 2, 1))):
        with pytest.raises(ValueError, match="path must have shape"):
            animate(d, path=bad)
    assert animate(d, path=[0.1, 0.2, 0.3]).path.shape == (3, 1)


def test_parameter_animation_rebuilds_each_design_and_shows_invalid_values():
    values = [0.0, 0.1, 0.2, 0.3, -0.1]
    anim = animate_parameter(lambda a_x: bl.singh.lacoste_lever(10.0, 0.5, a_x, 0.3), "a_x", values, q=[0.6],
                             unit="m")
    assert [d is None for d in anim.designs] == [True, False, False, False, True]
    assert anim.messages[0] == "a_x = 0 m: a_x (m) must be > 0, got 0.0"
    html = anim.to_jshtml()
    assert len(_frames(html)) == len(values)
    assert len(html) < 2e6
    # a valid frame: the spring ends at a_x along the lever, its constant is W l / (a_x b_y)
    anim.frame_image(2)
    (spring,) = anim.drawing.springs
    np.testing.assert_allclose(spring.get_xydata()[-1], [0.2 * math.cos(0.6), 0.2 * math.sin(0.6)],
                               atol=1e-12)
    assert anim.drawing.design.springs[0].k == pytest.approx(10.0 * 0.5 / (0.2 * 0.3))
    assert all(a.get_visible() for a in anim.drawing.artists)
    # an invalid frame: the mechanism is hidden, the message shown
    anim.frame_image(4)
    assert not any(a.get_visible() for a in anim.drawing.artists)
    texts = [t.get_text() for t in anim.drawing.ax.texts if t.get_visible()]
    assert any("must be > 0" in t for t in texts)


def test_parameter_animation_of_a_two_dof_family():
    anim = animate_parameter(lambda W2: two_link_arm(W2=W2), "W2", [2.0, 5.0, 8.0])
    assert anim.energy.image is not None
    assert len(_frames(anim.to_jshtml())) == 3
    assert all(d.balance_report().balanced for d in anim.designs)


def test_parameter_animation_needs_one_valid_design():
    with pytest.raises(ValueError, match="no value of a_x gives a valid design"):
        animate_parameter(lambda a_x: bl.singh.lacoste_lever(10.0, 0.5, a_x, 0.3), "a_x", [0.0, -1.0])
    with pytest.raises(TypeError, match="callable"):
        animate_parameter(None, "a_x", [0.1])


def test_parameter_animation_frame_for_an_unreachable_configuration():
    # with a rocker of 0.3 m the crank cannot reach 0.2 rad: that frame says so
    anim = animate_parameter(bl.lecture.fourbar_two_springs, "rocker", [0.6, 0.3, 2.0], q=[0.2], unit="m")
    assert anim.designs[0] is not None and anim.messages[0] == ""
    assert anim.designs[1] is None and "cannot be reached" in anim.messages[1]
    assert anim.designs[2] is None and "cannot assemble" in anim.messages[2]
    assert len(_frames(anim.to_jshtml())) == 3


def test_animation_frames_show_the_designs_own_numbers():
    d = bl.lecture.single_link_ordinary_spring(2.0, 0.5, 0.3, 0.2, 0.05)  # not balanced: a curved energy
    anim = animate(d, frames=12)
    y = anim.energy.lines["total"].get_data()[1]
    np.testing.assert_array_equal(y, d.potential_energy(anim.energy.grid).total)
    (load,) = d.loads
    for i in (0, 5, 11):
        anim.frame_image(i)
        assert anim.energy.marker.get_data()[1][0] == float(d.potential_energy(anim.path[i]).total)
        np.testing.assert_allclose(anim.drawing.load_segments[0][0],
                                   d.world_points(anim.path[i], [(load.body, load.point)])[0], atol=1e-15)
    # a parameter sweep: each frame's energy curve is that frame's design's
    sweep = animate_parameter(lambda b_y: bl.singh.generalized_lever(10.0, 0.5, 0.2, 0.1, b_y), "b_y",
                              [0.2, 0.4], q=[0.6])
    for i, design in enumerate(sweep.designs):
        sweep.frame_image(i)
        y = sweep.energy.lines["total"].get_data()[1]
        np.testing.assert_array_equal(y, design.potential_energy(sweep.energy.grid).total)
        assert sweep.drawing.design is design


# --------------------------------------------------------------------------- accessible player
def _one_dof(name: str) -> bool:
    return build(name).dof == 1


@pytest.mark.parametrize("name", [n for n in ALL if _one_dof(n)][:4])
def test_an_animation_says_what_it_shows_from_the_designs_own_energies(name):
    d = build(name)
    anim = animate(d, frames=8)
    grid = anim.energy.grid
    e = d.potential_energy(grid[d.reachable(grid)])
    report = d.balance_report()
    if report.balanced:
        mean = float(np.mean(e.total))
        said = f"{mean:.3g}" if abs(mean) > 1e-9 * report.scale else "0"   # round-off is said as 0
        assert f"the total energy is flat at {said} J" in anim.description
    else:
        assert "the total energy is not flat" in anim.description
        assert f"from {e.total.min():.3g} to {e.total.max():.3g} J" in anim.description
    # one label per frame, naming the configuration it shows in degrees
    assert anim.frame_labels == [f"θ = {math.degrees(q[0]):.0f}°" for q in anim.path]


def test_an_unbalanced_design_is_never_described_as_flat():
    import dataclasses

    d = bl.lecture.single_link_spring(mass=2.0, length=0.5, b=0.3, c=0.2)
    off = d.replace(springs=[dataclasses.replace(d.springs[0], k=1.2 * d.springs[0].k)])
    assert not off.balance_report().balanced
    anim = animate(off, frames=4)
    assert "not flat" in anim.description and "is flat" not in anim.description
    assert "residual |dV/dq|" in anim.description


def test_player_is_named_spoken_and_fits_a_phone():
    d = bl.lecture.single_link_spring(mass=2.0, length=0.5, b=0.3, c=0.2)
    anim = animate(d, frames=6)
    labels = list(anim.frame_labels)
    p = bl.viz.player(anim)
    html = p.html
    assert p.frames == 6
    assert 'aria-label="Frame"' in html
    assert f'aria-valuetext="frame 1 of 6: {labels[0]}"' in html
    assert 'aria-live="polite"' in html and 'role="status"' in html
    # the frame labels the script speaks are the animation's, in order
    assert re.search(r"labels = (\[.*?\])", html).group(1).count("θ =") == 6
    # alt text: the computed finding, and every button keeps its name
    assert 'alt="' + d.name in html and "total energy is flat" in html
    for name in ("Play", "Pause", "Next frame", "Previous frame", "First frame", "Last frame"):
        assert f'aria-label="{name}"' in html
    # the slider is never wider than the column, the buttons never wrap
    assert "max-width: 374px" in html and "flex-wrap: nowrap" in html


def test_player_needs_words_for_an_animation_that_has_none():
    from matplotlib.animation import FuncAnimation
    from matplotlib.figure import Figure
    from matplotlib.backends.backend_agg import FigureCanvasAgg

    fig = Figure()
    FigureCanvasAgg(fig)
    ax = fig.subplots()
    line, = ax.plot([0, 1], [0, 1])
    anim = FuncAnimation(fig, lambda i: [line], frames=3)
    with pytest.raises(ValueError, match="alt"):
        bl.viz.player(anim)
    with pytest.raises(ValueError, match="alt"):
        bl.viz.player(anim, "   ")
    p = bl.viz.player(anim, 'a "quoted" <line>')
    assert 'alt="a &quot;quoted&quot; &lt;line&gt;"' in p.html
    assert 'aria-valuetext="frame 1 of 3"' in p.html


# ------------------------------------------------------------------ matplotlib: the range we support
def _declared_matplotlib() -> str:
    import tomllib

    deps = tomllib.loads((Path(__file__).parents[1] / "pyproject.toml").read_text())["project"]["dependencies"]
    (spec,) = [d for d in deps if d.replace(" ", "").startswith("matplotlib") and "inline" not in d]
    return spec.replace(" ", "")[len("matplotlib"):]


def test_matplotlib_is_inside_the_range_the_animations_are_tested_with():
    """The animations lean on a few matplotlib internals (WRITER_INTERNALS), so the supported range
    is bounded: pyproject.toml, constraints.txt and the module say the same, and the installed
    matplotlib is inside it."""
    import matplotlib
    from packaging.specifiers import SpecifierSet
    from packaging.version import Version

    from balancelab.viz import animation

    declared = _declared_matplotlib()
    assert declared == animation.MATPLOTLIB_RANGE
    spec = SpecifierSet(declared)
    assert any(s.operator == "<" for s in spec), f"matplotlib{declared} has no upper bound"
    pins = [line.split("==")[1].strip() for line in
            (Path(__file__).parents[1] / "constraints.txt").read_text().splitlines()
            if line.startswith("matplotlib==")]
    assert pins and all(Version(p) in spec for p in pins), (pins, declared)
    assert Version(matplotlib.__version__) in spec, (matplotlib.__version__, declared)


def test_the_matplotlib_internals_the_player_uses_exist_in_this_version(tmp_path):
    from matplotlib.animation import FuncAnimation, HTMLWriter
    from matplotlib.backends.backend_agg import FigureCanvasAgg
    from matplotlib.figure import Figure

    from balancelab.viz.animation import WRITER_INTERNALS

    fig = Figure()
    FigureCanvasAgg(fig)
    writer = HTMLWriter(fps=24, embed_frames=True)
    writer.setup(fig, str(tmp_path / "a.html"))
    missing = [name for name in WRITER_INTERNALS if not hasattr(writer, name)]
    assert not missing and callable(getattr(FuncAnimation, "_post_draw", None)), missing


def test_the_animation_modules_touch_no_other_private_matplotlib_name():
    """Private attributes read in viz/animation.py and viz/player.py: matplotlib's listed ones, or
    the module's own (its blitter, its saving flag, its cache)."""
    import ast
    import re

    import balancelab.viz as viz
    from balancelab.viz.animation import WRITER_INTERNALS

    own = {"_blitter", "_compact_saving", "_balancelab_html"}
    allowed = set(WRITER_INTERNALS) | {"_post_draw"} | own | {"_fig"}   # _fig: player() of a foreign animation
    for name in ("animation.py", "player.py"):
        tree = ast.parse((Path(viz.__file__).parent / name).read_text())
        used = {n.attr for n in ast.walk(tree) if isinstance(n, ast.Attribute) and re.match(r"_[a-z]", n.attr)}
        assert used <= allowed, f"{name} reads private {sorted(used - allowed)}"


def test_an_animation_knows_its_frames_and_is_dropped_without_a_warning():
    import gc
    import warnings

    import balancelab as bl

    with warnings.catch_warnings():
        warnings.simplefilter("error")
        anim = bl.animate(bl.catalog()["lacoste_lever"](), frames=5)
        assert anim.frame_count == 5 and anim.figure is not None and anim.fps == 24
        assert anim.frame_image(4).shape[-1] == 3
        with pytest.raises(IndexError, match="frame 5 of an animation of 5 frames"):
            anim.frame_image(5)
        unrendered = bl.animate(bl.catalog()["lacoste_lever"](), frames=3)
        del unrendered
        gc.collect()


def test_the_player_draws_any_matplotlib_animation_for_high_density_screens():
    """A plain FuncAnimation (a chapter's own figure): frames saved at twice the figure's dpi,
    shown at the figure's size."""
    from matplotlib.animation import FuncAnimation
    from matplotlib.figure import Figure

    fig = Figure(figsize=(4.4, 3.0), dpi=120)
    (line,) = fig.subplots().plot([0, 1], [0, 1])
    anim = FuncAnimation(fig, lambda i: line.set_ydata([0, i]), frames=3)
    page = bl.viz.player(anim, "a line turning").html
    assert re.search(r'<img alt="a line turning" width="528" height="360" id="_anim_img', page)
    # stored as the figures are: lossless WebP, the dpi in its EXIF
    (first, *_) = _frames(page)
    im = Image.open(io.BytesIO(first))
    assert im.size == (1056, 720) and round(im.getexif()[0x011A]) == 240
    assert len(_frames(page)) == 3
