"""Figures made for reading: resolution, font sizes, panels that stack, labels that avoid each other.

The library part (fast) checks the house style of ``balancelab.viz.style`` on real figures: every
text of every kind of figure is at least ``MIN_FONT_PT``, animation frames are narrow enough for a
phone, multi-panel figures become one image per panel, the player needs no icon font, labels do
not overlap. The browser part (slow, needs the built site and Debian's chromium) measures, on
every page at 390 px and 1280 px, how large the smallest text of each figure is rendered:
``MIN_FONT_PT`` at the image's dpi, scaled by its rendered / natural width, must be >= 9 CSS px.
"""
from __future__ import annotations

import base64
import io
import os
import re
from pathlib import Path

os.environ.setdefault("MPLBACKEND", "Agg")

import numpy as np  # noqa: E402
import pytest  # noqa: E402
from matplotlib.figure import Figure  # noqa: E402
from matplotlib.text import Text  # noqa: E402
from PIL import Image  # noqa: E402

import balancelab as bl  # noqa: E402
from balancelab.viz import style  # noqa: E402
from balancelab.viz.animation import animate, animate_parameter  # noqa: E402

ROOT = Path(__file__).resolve().parents[1]
SITE = ROOT / "_build" / "html"
#: Width (CSS px) of the page's content column on a 390 px phone, measured in the built site
#: (the browser test below checks it is not narrower).
PHONE_CONTENT = 340
IMG_RE = re.compile(r'<img [^>]*src="data:image/webp;base64,([^"]+)"[^>]*>')


def _texts(fig) -> list[Text]:
    return [t for t in fig.findobj(Text) if t.get_visible() and t.get_text().strip()]


def _small_texts(fig) -> list[str]:
    fig.canvas.draw()
    return [f"{t.get_text()!r}: {t.get_fontsize()} pt" for t in _texts(fig)
            if t.get_fontsize() < style.MIN_FONT_PT - 1e-9]


# ----------------------------------------------------------------------------- house style
def test_the_house_style_keeps_the_smallest_text_readable():
    assert style.DPI >= 110
    # the smallest text, shown at the smallest allowed scale, is MIN_FONT_PX tall
    assert style.MIN_FONT_PT * style.DPI / 72 * style.MIN_SCALE == pytest.approx(style.MIN_FONT_PX)
    assert style.MIN_FONT_PX >= 9
    assert min(style.FONT.values()) >= style.MIN_FONT_PT
    assert style.RC["figure.dpi"] == style.DPI and style.RC["savefig.dpi"] == style.DPI


@pytest.mark.parametrize("name", ["singh_fourbar", "serial_2r_min_preload", "scissors_lift", "pulley_lever",
                                  "deepak_technique2_A"])
def test_library_figures_write_no_text_below_the_minimum(name):
    import matplotlib.pyplot as plt

    style.use()
    d = bl.catalog()[name]()
    ax = bl.draw(d)
    assert not _small_texts(ax.figure), name
    ax = bl.energy_plot(d)
    assert not _small_texts(ax.figure), name
    anim = animate(d, frames=4)
    assert not _small_texts(anim._fig), name
    plt.close("all")


def test_animation_frames_fit_a_phone_and_titles_fit_their_axes():
    d = bl.catalog()["deepak_technique2_A"]()
    anim = animate(d, frames=4)
    h, w, _ = anim.frame_image(0).shape
    # shown at the phone's content width, the smallest text is still >= MIN_FONT_PX
    assert style.MIN_FONT_PT * anim._fig.dpi / 72 * min(1.0, PHONE_CONTENT / w) >= style.MIN_FONT_PX - 1e-9
    assert anim._fig.dpi >= 110
    renderer = anim._fig.canvas.get_renderer()
    for ax in anim._fig.axes:
        title, box = ax.title, anim._fig.bbox
        ext = title.get_window_extent(renderer)
        assert box.x0 - 0.5 <= ext.x0 and ext.x1 <= box.x1 + 0.5, (title.get_text(), ext, box)
    # the sweep: every frame's title stays inside the figure and above its drawing
    sweep = animate_parameter(lambda a_x: bl.singh.lacoste_lever(10.0, 0.5, a_x, 0.3), "a_x",
                              [0.0, 0.1, 0.2], unit="m")
    for i in range(3):
        sweep.frame_image(i)
        ax = sweep.drawing.ax
        ext = ax.title.get_window_extent(sweep._fig.canvas.get_renderer())
        assert ext.x0 >= -0.5 and ext.x1 <= sweep._fig.bbox.x1 + 0.5
        assert ext.y0 >= ax.get_window_extent().y1 - 1, f"frame {i}: the title overlaps the drawing"


def test_fit_title_wraps_long_titles_and_keeps_short_ones():
    fig = Figure(figsize=(3.0, 3.0))
    ax = fig.subplots()
    assert style.fit_title(ax, "short").get_text() == "short"
    long = "a title much longer than the axes is wide, with many words in it " * 3
    text = style.fit_title(ax, long, max_lines=2).get_text()
    assert text.count("\n") == 1 and text.endswith("…")
    fig.canvas.draw()
    ext = ax.title.get_window_extent()
    assert ext.x0 >= 0 and ext.x1 <= fig.bbox.x1


def test_the_player_draws_its_icons_without_an_icon_font():
    html = animate(bl.singh.lacoste_lever(10.0, 0.5, 0.2, 0.3), frames=3).to_jshtml()
    buttons = re.findall(r"<button[^>]*>(.*?)</button>", html, re.S)
    assert len(buttons) >= 8
    for b in buttons:
        assert "<svg" in b and "<i " not in b, b
    # no character that needs a symbol font (the old ⏮ ⏭ showed as empty boxes)
    assert not re.search("[\u2300-\u23ff\u25a0-\u25ff\u2700-\u27bf]", html)


# ------------------------------------------------------------------------------- panels
def _decode(html: str) -> list[Image.Image]:
    return [Image.open(io.BytesIO(base64.b64decode(m))) for m in IMG_RE.findall(html)]


def test_a_row_of_panels_becomes_one_image_per_panel_at_the_house_resolution():
    fig = Figure(figsize=(12, 3.4), dpi=80, layout="constrained")   # a chapter's dpi does not matter
    axes = fig.subplots(1, 3)
    for i, ax in enumerate(axes):
        ax.plot([0, 1], [0, i])
        ax.set_title(f"panel {i}")
        ax.set_xlabel("θ₁, crank angle from the x-axis (deg)")
    html = style.figure_html(fig)
    images = _decode(html)
    assert len(images) == 3
    widths = [int(w) for w in re.findall(r'\bwidth="(\d+)"', html)]
    for i, im in enumerate(images):
        # PIXEL_RATIO device pixels per CSS pixel: sharp on a high-density screen
        assert style.PIXEL_RATIO >= 2
        assert im.format == "WEBP" and round(im.getexif()[0x011A]) == style.DPI * style.PIXEL_RATIO
        assert abs(im.size[0] - style.PIXEL_RATIO * widths[i]) <= style.PIXEL_RATIO
        # each panel is about a third of the figure, shown at the house resolution
        assert 0.2 * 12 * style.DPI < widths[i] < 0.4 * 12 * style.DPI
        assert f'alt="Figure panel: panel {i}' in html
    mins = [float(m) for m in re.findall(r"min-width: (\d+)px", html)]
    assert mins == pytest.approx([style.MIN_SCALE * w for w in widths], abs=1)
    assert fig.dpi == 80   # the figure itself is left as it was


def test_a_figure_with_a_figure_title_or_one_panel_stays_whole():
    fig = Figure(figsize=(8, 3), layout="constrained")
    fig.subplots(1, 2)
    fig.suptitle("one title over both")
    assert len(_decode(style.figure_html(fig))) == 1
    single = Figure(figsize=(5, 3), layout="constrained")
    single.subplots().plot([0, 1], [1, 0])
    (im,) = _decode(style.figure_html(single))
    assert im.size[0] <= 5 * style.DPI * style.PIXEL_RATIO


def test_a_colour_bar_stays_with_its_panel():
    fig = Figure(figsize=(10, 3.5), layout="constrained")
    a, b = fig.subplots(1, 2)
    m = a.imshow(np.arange(12).reshape(3, 4))
    fig.colorbar(m, ax=a)
    b.plot([0, 1], [0, 1])
    assert len(style.panel_columns(fig)) == 2
    assert len(_decode(style.figure_html(fig))) == 2


def test_install_registers_the_html_figure_formatter():
    pytest.importorskip("IPython")
    from IPython.core.interactiveshell import InteractiveShell

    shell = InteractiveShell.instance()
    try:
        assert style.install(shell)
        fig = Figure(figsize=(8, 3))
        fig.subplots(1, 2)
        data, _ = shell.display_formatter.format(fig)
        assert data["text/html"].count("<img") == 2
    finally:
        shell.display_formatter.formatters["text/html"].pop(Figure, None)
        InteractiveShell.clear_instance()


# ------------------------------------------------------------------------------- labels
def _overlaps(boxes) -> list:
    out = []
    for i in range(len(boxes)):
        for j in range(i + 1, len(boxes)):
            a, b = boxes[i], boxes[j]
            w = min(a.x1, b.x1) - max(a.x0, b.x0)
            h = min(a.y1, b.y1) - max(a.y0, b.y0)
            if w > 1 and h > 1:
                out.append((i, j, w * h))
    return out


@pytest.mark.parametrize("name", ["singh_fourbar", "deepak_technique2_A", "serial_2r_min_preload",
                                  "peaucellier_board"])
def test_point_labels_do_not_sit_on_each_other(name):
    import matplotlib.pyplot as plt

    d = bl.catalog()[name]()
    ax = bl.draw(d)
    fig = ax.figure
    fig.canvas.draw()
    r = fig.canvas.get_renderer()
    shown = [t for t in ax.drawing.labels.values() if t.get_text()]
    boxes = [t.get_window_extent(r) for t in shown]
    assert not _overlaps(boxes), [(shown[i].get_text(), shown[j].get_text()) for i, j, _ in _overlaps(boxes)]
    # every named point is still written somewhere (coincident points share one label)
    written = ",".join(t.get_text() for t in shown)
    for n in ax.drawing.labels:
        assert bl.viz.frame.tex_label(n) in written, n
    plt.close(fig)


def test_coincident_points_share_one_label():
    fig = Figure()
    ax = fig.subplots()
    ax.set_xlim(0, 1)
    ax.set_ylim(0, 1)
    lab = {n: ax.annotate(n, (0, 0), xytext=(5, 5), textcoords="offset points") for n in ("A", "D", "C")}
    dirs = style.arrange_labels(lab, {"A": (0.2, 0.2), "D": (0.2, 0.2), "C": (0.8, 0.8)},
                                {"A": "A", "D": "D", "C": "C"}, obstacles=[(0.25, 0.25)])
    assert lab["A"].get_text() == "A, D" and lab["D"].get_text() == "" and lab["C"].get_text() == "C"
    assert set(dirs) == {"A", "C"}
    # the obstacle up and to the right of A pushes A's label elsewhere
    assert dirs["A"] != (1, 1)


# ---------------------------------------------------------------- texts that clash
def test_text_clashes_finds_overlapping_titles_and_text_outside_the_canvas():
    fig = Figure(figsize=(4, 2))
    a, b = fig.subplots(1, 2)
    a.set_title("a long title that runs into the next panel's title")
    b.set_title("the next panel's own long title")
    a.set_xlabel("a label under the bottom edge")
    found = style.text_clashes(fig)
    assert any("×" in c and "next panel" in c for c in found), found
    assert any("outside the canvas" in c for c in found), found
    # the same figure with wrapped titles and a layout engine has none
    good = Figure(figsize=(4, 2), layout="constrained")
    a, b = good.subplots(1, 2)
    style.fit_title(a, "a long title that runs into the next panel's title")
    style.fit_title(b, "the next panel's own long title")
    a.set_xlabel("a label")
    assert style.text_clashes(good) == []


def test_figure_html_records_the_check_and_fixes_a_label_below_the_canvas():
    fig = Figure(figsize=(3, 2))   # no layout engine: the x-label falls off the bottom
    ax = fig.subplots()
    ax.plot([0, 1], [0, 1])
    ax.set_xlabel("θ, angle of link 1 from the x-axis (deg)")
    assert any("outside the canvas" in c for c in style.text_clashes(fig))
    html = style.figure_html(fig)
    assert re.search(r'data-texts-checked="\d+"', html) and "data-text-clashes" not in html
    crowded = Figure(figsize=(3, 2), layout="constrained")
    ax = crowded.subplots()
    ax.text(0.5, 0.5, "one")
    ax.text(0.5, 0.5, "two")
    assert 'data-text-clashes="&#x27;one&#x27; × &#x27;two&#x27;"' in style.figure_html(crowded)


@pytest.mark.parametrize("name", ["fourbar_two_springs", "deepak_technique2_A", "deepak_technique3_AB", "pulley_lever",
                                  "singh_fourbar"])
def test_library_figures_have_no_clashing_texts(name):
    """Titles wrap to their Axes, the verdict sits in the legend (never on a curve or under the
    legend), and every text lies inside the canvas, for drawings, energy plots and animations."""
    import matplotlib.pyplot as plt

    style.use()
    d = bl.catalog()[name]()
    for fig in (bl.draw(d).figure, bl.energy_plot(d).figure):
        assert style.text_clashes(fig) == [], name
    anim = animate(d, frames=3)
    anim.frame_image(0)
    assert style.text_clashes(anim._fig, anim._fig.canvas.get_renderer()) == [], name
    plt.close("all")


# ---------------------------------------------------------------- every plot says which angle
def _catalog_designs():
    return [(name, factory()) for name, factory in bl.catalog().items()]


@pytest.mark.parametrize("name, design", _catalog_designs(), ids=lambda x: x if isinstance(x, str) else "")
def test_every_coordinate_says_what_angle_it_is(name, design):
    """Each axis label names its angle, and the words are true of the poses: an angle "of link b
    from the x-axis" is body b's angle, one "relative to link p" is the difference of the two."""
    from balancelab.viz.frame import angle_label

    q = design.sample(40, seed=3)
    poses = design.poses(q)
    for i, words in enumerate(design.kinematics.describe()):
        assert words, f"{name}: coordinate {design.q_names[i]} has no description"
        assert words in angle_label(design, i)
        m = re.fullmatch(r"angle of link (\d+) (?:from the x-axis|relative to link (\d+))", words)
        if m:
            b = int(m.group(1))
            angle = poses[..., b, 2] - (poses[..., int(m.group(2)), 2] if m.group(2) else 0.0)
            assert np.allclose(np.angle(np.exp(1j * (angle - q[..., i]))), 0.0, atol=1e-9), (name, words)
        elif words == "crank angle from the x-axis":
            assert np.allclose(np.angle(np.exp(1j * (poses[..., 1, 2] - q[..., i]))), 0.0, atol=1e-9), name
