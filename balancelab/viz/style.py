"""The house style of the course's figures: resolution, font sizes, titles that fit, panels that stack.

A figure is read on a 1280 px screen and on a 390 px phone. An image of width ``w`` px shown
``s`` times its natural size renders a font of ``p`` points at ``p * dpi / 72 * s`` CSS px, so

* every figure is rendered at :data:`DPI` (>= 110) and no text is smaller than
  :data:`MIN_FONT_PT` (:data:`FONT` gives the size of each role);
* a figure is never shown smaller than :data:`MIN_SCALE` of its natural width (it scrolls
  sideways instead), so the smallest text stays >= :data:`MIN_FONT_PX` CSS px at any width;
* a figure of several panels side by side is shown as one image per panel
  (:func:`figure_html`), which sit side by side on a wide screen and stack on a phone;
* each image has :data:`PIXEL_RATIO` device pixels per CSS pixel (sharp on a phone's or a
  laptop's high-density screen) and is stored as a lossless palette WebP (line art: a few kB per
  panel);
* no two texts of a figure overlap and every text lies inside the canvas
  (:func:`text_clashes`; :func:`figure_html` records what it found on the page, where the
  browser test reads it).

:func:`use` applies the style to matplotlib; :func:`install` makes an IPython shell show every
figure with :func:`figure_html` (the book's kernels do this at start-up, see
``scripts/build_book.py``); :func:`fit_title` wraps a title to the width of its Axes;
:func:`arrange_labels` keeps the labels of named points off each other.

Layer: viz; imports matplotlib (lazily) only.
"""
from __future__ import annotations

import base64
import html
import io
import textwrap
from typing import Any

import numpy as np

__all__ = ["DPI", "FONT", "MIN_FONT_PT", "MIN_FONT_PX", "MIN_SCALE", "PIXEL_RATIO", "RC", "arrange_labels",
           "figure_html", "fit_title", "install", "panel_columns", "text_clashes", "use", "webp_image"]

#: Resolution (dots per inch) of every figure and animation frame of the course.
DPI = 120
#: Device pixels per CSS pixel of a page's figure: the image is drawn at ``DPI * PIXEL_RATIO`` and
#: shown at the size it would have at ``DPI``.
PIXEL_RATIO = 2
#: The smallest font of any text in a figure (points).
MIN_FONT_PT = 9.0
#: The smallest rendered font the site allows (CSS px).
MIN_FONT_PX = 9.0
#: The smallest fraction of its natural width a figure is shown at: MIN_FONT_PT at DPI stays
#: MIN_FONT_PX tall.
MIN_SCALE = MIN_FONT_PX / (MIN_FONT_PT * DPI / 72.0)
#: Font size (points) of each role of text.
FONT = {"title": 10.0, "label": 10.0, "tick": 9.0, "legend": 9.0, "annotation": 9.5, "note": 9.0}

#: matplotlib rcParams of the house style.
RC: dict[str, Any] = {
    "figure.dpi": DPI,
    "savefig.dpi": DPI,
    "font.size": FONT["label"],
    "axes.titlesize": FONT["title"],
    "axes.labelsize": FONT["label"],
    "xtick.labelsize": FONT["tick"],
    "ytick.labelsize": FONT["tick"],
    "legend.fontsize": FONT["legend"],
    "legend.title_fontsize": FONT["legend"],
    "figure.titlesize": FONT["title"],
}


def use() -> None:
    """Apply :data:`RC` to matplotlib's rcParams.

    Examples
    --------
    >>> import matplotlib
    >>> use(); matplotlib.rcParams["figure.dpi"] == DPI
    True
    """
    import matplotlib

    matplotlib.rcParams.update(RC)  # type: ignore[arg-type]  # valid keys; the stubs want each as a literal


def fit_title(ax, text: str, fontsize: float | None = None, max_lines: int = 3, **kwargs):
    """Set ``text`` as the title of ``ax``, wrapped onto lines that fit the Axes' width.

    Parameters
    ----------
    ax : matplotlib.axes.Axes
    text : str
    fontsize : float, optional
        Points; :data:`FONT` ``["title"]`` by default.
    max_lines : int
        Lines kept (the last one ends with an ellipsis when the text is longer).
    **kwargs
        Passed to ``ax.set_title``.

    Returns
    -------
    matplotlib.text.Text

    Examples
    --------
    >>> from matplotlib.figure import Figure
    >>> ax = Figure(figsize=(2.0, 2.0)).subplots()
    >>> fit_title(ax, "a rather long title that cannot fit on one line").get_text().count("\\n") >= 1
    True
    """
    size = FONT["title"] if fontsize is None else float(fontsize)
    width_in = ax.get_position().width * ax.figure.get_figwidth()
    chars = max(8, int(width_in * 72.0 / (0.55 * size)))
    lines = textwrap.wrap(str(text), chars) or [""]
    if len(lines) > max_lines:
        lines = lines[:max_lines]
        lines[-1] = lines[-1][: chars - 1].rstrip() + "…"
    return ax.set_title("\n".join(lines), fontsize=size, **kwargs)


#: Directions (x, y signs) a point's label may take, the first preferred.
LABEL_DIRECTIONS = ((1, 1), (1, -1), (-1, 1), (-1, -1), (1, 0), (-1, 0), (0, 1), (0, -1))


def arrange_labels(labels: dict, points: dict, texts: dict, obstacles=(), previous: dict | None = None) -> dict:
    """Place point labels so that they avoid each other; points that coincide share one label.

    Of eight directions around its point, a label takes the one whose estimated text box is
    farthest from the other labelled points, the ``obstacles`` and the labels already placed,
    among those whose box stays inside the Axes (else the least outside); its ``previous``
    direction wins a near tie, so labels do not jump between animation frames.
    Distances are measured on the page (points), not in data units.

    Parameters
    ----------
    labels : dict of str to matplotlib.text.Annotation
        The labels (``textcoords="offset points"``), by name, all on one Axes.
    points : dict of str to (float, float)
        Each label's point (data coordinates).
    texts : dict of str to str
        Each label's text.
    obstacles : array_like, shape (m, 2)
        Other points to keep clear of (data coordinates), for example the joints.
    previous : dict, optional
        The directions this function returned for the previous frame.

    Returns
    -------
    dict of str to (int, int)
        The direction taken by each shown label.

    Examples
    --------
    >>> from matplotlib.figure import Figure
    >>> ax = Figure().subplots(); _ = ax.set_xlim(0, 1); _ = ax.set_ylim(0, 1)
    >>> lab = {n: ax.annotate(n, (0, 0), xytext=(5, 5), textcoords="offset points") for n in "AB"}
    >>> dirs = arrange_labels(lab, {"A": (0.5, 0.5), "B": (0.5, 0.5)}, {"A": "A", "B": "B"})
    >>> lab["A"].get_text(), lab["B"].get_text(), list(dirs)
    ('A, B', '', ['A'])
    """
    if not labels:
        return {}
    names = list(labels)
    ax = labels[names[0]].axes
    to_pt = 72.0 / ax.figure.dpi
    pts = ax.transData.transform(np.array([points[n] for n in names], dtype=float)) * to_pt
    obstacles = np.asarray(obstacles, dtype=float).reshape(-1, 2)
    obst = ax.transData.transform(obstacles) * to_pt if len(obstacles) else np.zeros((0, 2))
    size = float(labels[names[0]].get_fontsize())
    frame = np.asarray(ax.bbox.extents, dtype=float) * to_pt
    previous = previous or {}
    placed: list[np.ndarray] = []
    done: set[str] = set()
    dirs: dict[str, Any] = {}
    for i, name in enumerate(names):
        if name in done:
            continue
        group = [m for j, m in enumerate(names) if m not in done and np.hypot(*(pts[j] - pts[i])) < 0.4 * size]
        done.update(group)
        for m in group[1:]:
            labels[m].set_text("")
        half = np.array([0.33 * size * (sum(len(m.replace("_", "")) for m in group) + 2 * len(group) - 2),
                         0.5 * size])
        others = np.vstack([pts[[j for j, m in enumerate(names) if m not in group]].reshape(-1, 2), obst,
                            np.array(placed).reshape(-1, 2)])

        def score(d, i=i, half=half, others=others, name=name):
            centre = pts[i] + np.array(d) * (4.0 + half)
            gap = float(np.min(np.hypot(*(others - centre).T))) if len(others) else 1e9
            # a label reaching out of the Axes would sit on the tick labels: the frame comes first
            out = np.maximum(np.maximum(frame[:2] - (centre - half), (centre + half) - frame[2:]), 0.0)
            return -round(float(out.sum())), gap * (1.15 if d == previous.get(name, LABEL_DIRECTIONS[0]) else 1.0)

        d = max(LABEL_DIRECTIONS, key=score)
        dirs[name] = d
        placed.append(pts[i] + np.array(d) * (4.0 + half))
        t = labels[name]
        t.set_text(", ".join(texts[m] for m in group))
        t.set_position((4.0 * d[0], 4.0 * d[1]))
        t.set_horizontalalignment({1: "left", 0: "center", -1: "right"}[d[0]])
        t.set_verticalalignment({1: "bottom", 0: "center", -1: "top"}[d[1]])
    return dirs


def panel_columns(fig, renderer=None) -> list[tuple[float, float]]:
    """Horizontal pixel ranges ``(x0, x1)`` of the figure's columns of panels, left to right.

    Axes whose drawn extents (with their labels) overlap horizontally form one column; a
    colour bar belongs to the column of its Axes. The ranges split the gaps between columns
    in the middle. One range covering the figure is returned when it cannot be split
    (one column, figure-level texts or legends, or columns whose labels overlap).

    Parameters
    ----------
    fig : matplotlib.figure.Figure
    renderer : optional
        The renderer of the figure's last draw.

    Returns
    -------
    list of (float, float)

    Examples
    --------
    >>> from matplotlib.figure import Figure
    >>> from matplotlib.backends.backend_agg import FigureCanvasAgg
    >>> fig = Figure(figsize=(6, 2), dpi=100, layout="constrained"); _ = FigureCanvasAgg(fig)
    >>> _ = fig.subplots(1, 2); fig.canvas.draw()
    >>> len(panel_columns(fig))
    2
    """
    width = fig.bbox.width
    whole = [(0.0, float(width))]
    if fig.texts or fig.legends or getattr(fig, "_suptitle", None) is not None:
        return whole
    if renderer is None:
        if not hasattr(fig.canvas, "get_renderer"):   # a figure never drawn by an Agg canvas
            from matplotlib.backends.backend_agg import FigureCanvasAgg

            old = fig.canvas
            canvas = FigureCanvasAgg(fig)
            canvas.draw()
            renderer = canvas.get_renderer()
            fig.set_canvas(old)
        else:
            renderer = fig.canvas.get_renderer()
    spans = []
    for ax in fig.axes:
        box = ax.get_tightbbox(renderer) if ax.get_visible() else None
        if box is None:
            continue
        bar = getattr(ax, "_colorbar", None)   # a colour bar: one span with the Axes of its image
        owner = getattr(getattr(bar, "mappable", None), "axes", None)
        if owner is not None and owner.get_visible():
            other = owner.get_tightbbox(renderer)
            box = box if other is None else type(box).union([box, other])
        spans.append((box.x0, box.x1))
    spans.sort()
    if not spans:
        return whole
    cols = [list(spans[0])]
    for x0, x1 in spans[1:]:
        if x0 < cols[-1][1]:
            cols[-1][1] = max(cols[-1][1], x1)
        else:
            cols.append([x0, x1])
    if len(cols) < 2:
        return whole
    cuts = [0.0] + [0.5 * (a[1] + b[0]) for a, b in zip(cols, cols[1:])] + [float(width)]
    return list(zip(cuts[:-1], cuts[1:]))


def webp_image(rgba: np.ndarray, dpi: float) -> bytes:
    """Pixels as a lossless WebP, its resolution in its EXIF: a 256-colour palette when that is
    smaller (line art), else RGB. (A lossless WebP of line art is about a quarter smaller than
    the same pixels as an optimized PNG.) The encoder of every figure of the course.

    Parameters
    ----------
    rgba : numpy.ndarray
        Pixels, shape (h, w, 3) or (h, w, 4) (alpha ignored), uint8.
    dpi : float
        Resolution recorded in the image (dots per inch).

    Returns
    -------
    bytes

    Examples
    --------
    >>> import io; from PIL import Image
    >>> im = Image.open(io.BytesIO(webp_image(np.full((4, 6, 3), 255, np.uint8), 240)))
    >>> im.format, im.size, im.getexif()[0x011A]
    ('WEBP', (6, 4), 240.0)
    """
    from PIL import Image

    im = Image.fromarray(np.ascontiguousarray(rgba[..., :3]))
    exif = Image.Exif()
    exif[0x011A] = exif[0x011B] = float(dpi)     # XResolution, YResolution
    exif[0x0128] = 2                             # ResolutionUnit: inch
    best = b""
    for candidate in (im.quantize(256, method=Image.Quantize.MEDIANCUT, dither=Image.Dither.NONE), im):
        out = io.BytesIO()
        candidate.save(out, format="webp", lossless=True, quality=100, method=4, exif=exif)
        if not best or len(out.getvalue()) < len(best):
            best = out.getvalue()
    return best


def _figure_texts(fig, renderer) -> list:
    """(name, bbox) of every text the reader sees: titles, axis labels, tick labels in view,
    annotations, figure texts; a legend counts as one box."""
    from matplotlib.text import Text

    found = []

    def add(t, name=None):
        if isinstance(t, Text) and t.get_visible() and t.get_text().strip():
            found.append((name or t.get_text().strip(), t.get_window_extent(renderer)))

    for t in fig.texts:
        add(t)
    sup = getattr(fig, "_suptitle", None)
    if sup is not None:
        add(sup)
    for ax in fig.axes:
        if not ax.get_visible():
            continue
        for t in (ax.title, ax._left_title, ax._right_title, ax.xaxis.label, ax.yaxis.label):
            add(t)
        for axis, lo_hi in ((ax.xaxis, ax.get_xlim()), (ax.yaxis, ax.get_ylim())):
            lo, hi = min(lo_hi), max(lo_hi)
            span = (hi - lo) or 1.0
            for tick in axis.get_major_ticks():
                if lo - 1e-9 * span <= tick.get_loc() <= hi + 1e-9 * span:
                    add(tick.label1)
                    add(tick.label2)
        for t in ax.texts:
            add(t)
        legend = ax.get_legend()
        if legend is not None and legend.get_visible():
            found.append(("legend", legend.get_window_extent(renderer)))
    for legend in fig.legends:
        found.append(("legend", legend.get_window_extent(renderer)))
    return found


def text_clashes(fig, renderer=None, tolerance: float = 1.0) -> list[str]:
    """Texts of a drawn figure that overlap another text or stick out of the canvas.

    Parameters
    ----------
    fig : matplotlib.figure.Figure
    renderer : optional
        The renderer of the figure's last draw (the figure is drawn with Agg when not given).
    tolerance : float
        Pixels of overlap (in both directions) or of overhang forgiven.

    Returns
    -------
    list of str
        One line per problem ("'A' × 'B'", "'label' outside the canvas"); empty when none.

    Examples
    --------
    >>> from matplotlib.figure import Figure
    >>> fig = Figure(figsize=(3, 2), layout="constrained"); ax = fig.subplots()
    >>> _ = ax.set_xlabel("time (s)"); text_clashes(fig)
    []
    >>> _ = ax.text(0.5, 0.5, "one"); _ = ax.text(0.5, 0.5, "two"); text_clashes(fig)
    ["'one' × 'two'"]
    """
    if renderer is None:
        from matplotlib.backends.backend_agg import FigureCanvasAgg

        old = fig.canvas
        canvas = FigureCanvasAgg(fig)
        canvas.draw()
        renderer = canvas.get_renderer()
        fig.set_canvas(old)
    texts = _figure_texts(fig, renderer)
    width, height = fig.bbox.width, fig.bbox.height
    problems = []
    for name, box in texts:
        if box.x0 < -tolerance or box.y0 < -tolerance or box.x1 > width + tolerance or box.y1 > height + tolerance:
            problems.append(f"{name!r} outside the canvas")
    for i, (a, ba) in enumerate(texts):
        for b, bb in texts[i + 1:]:
            w = min(ba.x1, bb.x1) - max(ba.x0, bb.x0)
            h = min(ba.y1, bb.y1) - max(ba.y0, bb.y0)
            if w > tolerance and h > tolerance:
                problems.append(f"{a!r} × {b!r}")
    return problems


def _crop(rgba: np.ndarray, background) -> np.ndarray:
    """``rgba`` without its margins of plain background colour (keeping 4 px)."""
    ink = np.any(np.abs(rgba[..., :3].astype(int) - np.asarray(background[:3], dtype=int)) > 8, axis=-1)
    rows, cols = np.flatnonzero(ink.any(axis=1)), np.flatnonzero(ink.any(axis=0))
    if rows.size == 0:
        return rgba
    r0, r1 = max(rows[0] - 4, 0), min(rows[-1] + 5, rgba.shape[0])
    c0, c1 = max(cols[0] - 4, 0), min(cols[-1] + 5, rgba.shape[1])
    return rgba[r0:r1, c0:c1]


def _alt(fig, axes) -> str:
    # a plot that can say what it shows (an energy plot: is the total flat, at what energy) says it
    found = [d for d in (getattr(getattr(ax, "energy", None), "description", None) for ax in axes)
             if isinstance(d, str)]
    if found:
        return "Energy plot: " + "; ".join(found)
    parts = []
    for ax in axes:
        bits = [t for t in (ax.get_title(), ax.get_title("left"), ax.get_title("right")) if t]
        if ax.get_xlabel() or ax.get_ylabel():
            bits.append(f"{ax.get_ylabel() or 'value'} against {ax.get_xlabel() or 'position'}")
        if bits:
            parts.append("; ".join(bits))
    return ("Figure panel: " + " | ".join(parts)) if parts else "Figure panel drawn with balancelab"


def figure_html(fig, dpi: float = DPI) -> str:
    """The figure as HTML: one image per column of panels (:func:`panel_columns`), at ``dpi``.

    Each image (a lossless WebP) has :data:`PIXEL_RATIO` times the pixels of its shown size (sharp on high-density
    screens). A figure without a layout engine whose texts stick out of the canvas is laid out
    with ``tight_layout`` first. The ``<div>`` records :func:`text_clashes`: its
    ``data-texts-checked`` counts the texts checked, ``data-text-clashes`` lists the problems.

    The images sit side by side while the page is wide enough to show each at
    :data:`MIN_SCALE` of its natural width or more, and stack otherwise; an image wider than
    the page then scrolls sideways instead of shrinking. Each image carries alt text made of
    its panels' titles and axis labels.

    Parameters
    ----------
    fig : matplotlib.figure.Figure
    dpi : float
        Resolution of the images.

    Returns
    -------
    str

    Examples
    --------
    >>> from matplotlib.figure import Figure
    >>> fig = Figure(figsize=(6, 2), layout="constrained")
    >>> a, b = fig.subplots(1, 2); _ = a.set_title("energy"); _ = b.set_title("torque")
    >>> page = figure_html(fig)
    >>> page.count("<img"), 'alt="Figure panel: energy"' in page, 'data-text-clashes' in page
    (2, True, False)
    """
    import warnings

    from matplotlib.backends.backend_agg import FigureCanvasAgg

    old_dpi, old_canvas = fig.dpi, fig.canvas
    canvas = FigureCanvasAgg(fig)
    try:
        fig.set_dpi(dpi * PIXEL_RATIO)
        canvas.draw()
        renderer = canvas.get_renderer()
        clashes = text_clashes(fig, renderer)
        if fig.get_layout_engine() is None and any("outside the canvas" in c for c in clashes):
            with warnings.catch_warnings():
                warnings.simplefilter("ignore")
                fig.tight_layout()
            canvas.draw()
            clashes = text_clashes(fig, renderer)
        checked = len(_figure_texts(fig, renderer))
        rgba = np.asarray(canvas.buffer_rgba()).copy()
        columns = panel_columns(fig, renderer)
        groups = [[ax for ax in fig.axes if x0 <= 0.5 * (ax.bbox.x0 + ax.bbox.x1) < x1] for x0, x1 in columns]
    finally:
        fig.set_dpi(old_dpi)
        fig.set_canvas(old_canvas)
    background = (np.array(fig.get_facecolor()) * 255).round().astype(int)
    imgs = []
    for (x0, x1), axes in zip(columns, groups):
        part = _crop(rgba[:, int(round(x0)):int(round(x1))], background)
        data = base64.b64encode(webp_image(part, dpi * PIXEL_RATIO)).decode("ascii")
        w, h = part.shape[1] / PIXEL_RATIO, part.shape[0] / PIXEL_RATIO
        imgs.append(f'<img src="data:image/webp;base64,{data}" width="{w:.0f}" height="{h:.0f}" '
                    f'alt="{html.escape(_alt(fig, axes))}" class="bl-panel" '
                    f'style="flex: 1 1 {MIN_SCALE * w:.0f}px; min-width: {MIN_SCALE * w:.0f}px; '
                    f'max-width: {w:.0f}px; height: auto;">')
    found = f' data-text-clashes="{html.escape("; ".join(clashes))}"' if clashes else ""
    return f'<div class="bl-figure" data-texts-checked="{checked}"{found}>' + "".join(imgs) + "</div>"


def install(shell=None) -> bool:
    """Make an IPython shell show matplotlib figures with :func:`figure_html` and the house style.

    Parameters
    ----------
    shell : IPython.core.interactiveshell.InteractiveShell, optional
        The running shell by default.

    Returns
    -------
    bool
        False when there is no IPython shell (nothing is changed).

    Examples
    --------
    It reports whether there was a shell to set up (a plain Python session has none):

    >>> from IPython import get_ipython
    >>> install() == (get_ipython() is not None)
    True
    """
    if shell is None:
        try:
            from IPython import get_ipython
        except ImportError:
            return False
        shell = get_ipython()
    if shell is None:
        return False
    # the backend first: loading the inline backend (on the first figure) clears every formatter
    # registered for Figure
    import matplotlib.pyplot as plt
    from matplotlib.figure import Figure

    plt.close(plt.figure())

    use()
    shell.display_formatter.formatters["text/html"].for_type(Figure, figure_html)
    return True
