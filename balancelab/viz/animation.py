"""Animations that play on a static web page: a design moving, or a design parameter swept.

Both functions return a :class:`matplotlib.animation.FuncAnimation` whose
``to_jshtml()`` is a self-contained JavaScript player (frames embedded as images, a
scrubber and play buttons), so the built book plays it with no kernel and no network.
The defaults keep one embedded animation under 2 MB and at 24 frames per second
(20 for parameter sweeps). The mechanism is drawn above its energy curve (not beside it), in
the house style of :mod:`balancelab.viz.style`: a frame is narrow enough that its smallest
text stays readable when a phone shows it at the page's width.

* :func:`animate` moves a design through its configuration range beside its energy
  curve, with a marker riding on the curve.
* :func:`animate_parameter` rebuilds the design for each value of one parameter (the
  free choice ``a_x`` of a lever, a pulley radius, the position of a pivot on its
  locus ...): scrubbing the player is the static-page counterpart of a lab's slider.
* :func:`~balancelab.viz.player.player` (in :mod:`balancelab.viz.player`) turns any matplotlib
  animation into the page's player; both functions here give it a text alternative computed
  from the designs' numbers (``anim.description``) and a label per frame (``anim.frame_labels``).
"""
from __future__ import annotations

import math
from typing import Any, Callable, Mapping, Sequence

import numpy as np

from ..core.design import Design
from ..core.report import q_units
from ..core.validation import finite_real, positive_int
from .drawing import Drawing, extent
from .energy import EnergyView, energy_limits, q_symbol, report_summary
from . import style
from .style import FONT, fit_title
from .frame import Blitter, check_design, default_q
from .player import Player, offline_page, player

__all__ = ["Player", "animate", "animate_parameter", "configuration_label", "configuration_path", "player",
           "WRITER_INTERNALS", "MATPLOTLIB_RANGE"]

#: matplotlib's private names this module still leans on: the HTML writer's frame list and
#: byte count (filled with compact palette WebP frames instead of its own PNGs) and the animation's
#: per-frame redraw hook (skipped while the writer renders the frame itself). matplotlib has no
#: public way to hand its JavaScript player ready-made frames; so the supported versions are
#: pinned (:data:`MATPLOTLIB_RANGE`, the same range as ``pyproject.toml`` and
#: ``constraints.txt``) and the tests check that these names exist in the installed version.
#: Without them the writer falls back to matplotlib's own (bigger) frames.
WRITER_INTERNALS = ("_saved_frames", "_total_bytes", "_bytes_limit", "_hit_limit")
#: the matplotlib versions this module is tested with (``pyproject.toml``'s requirement)
MATPLOTLIB_RANGE = ">=3.7,<3.12"

#: Defaults chosen so that ``to_jshtml()`` of a catalog design stays well under 2 MB and a frame
#: shown 350 px wide (a phone) keeps its smallest text >= 9 px (see :mod:`balancelab.viz.style`).
FIGSIZE = (4.4, 4.6)
DPI = style.DPI


def _compact_frame(rgb: np.ndarray, colors: int = 32, dpi: float | None = None) -> bytes:
    """Pixels as a lossless WebP of at most ``colors`` colours, its resolution ``dpi`` in its EXIF.

    Line art loses nothing visible to the palette; a lossless WebP of it is about a third smaller
    than the same palette as a PNG, which pays for the four times as many pixels of a frame drawn
    for high-density screens.
    """
    from io import BytesIO

    from PIL import Image

    im = Image.fromarray(np.ascontiguousarray(rgb)).quantize(
        colors=colors, method=Image.Quantize.FASTOCTREE, dither=Image.Dither.NONE)
    exif = Image.Exif()
    if dpi:
        exif[0x011A] = exif[0x011B] = float(dpi)    # XResolution, YResolution
        exif[0x0128] = 2                            # ResolutionUnit: inch
    out = BytesIO()
    im.save(out, format="webp", lossless=True, quality=100, method=4, exif=exif)
    return out.getvalue()


def _compact_writer_class():
    from matplotlib.animation import HTMLWriter

    class CompactHTMLWriter(HTMLWriter):
        """HTMLWriter embedding palette WebP frames rendered by the animation's blitter."""

        colors = 32
        source = None
        compact_frames = 0

        def grab_frame(self, **savefig_kwargs):
            needed = WRITER_INTERNALS
            # Animation.save always passes the colours; other options need a real savefig
            plain = set(savefig_kwargs) <= {"facecolor", "edgecolor", "transparent"} and \
                not savefig_kwargs.get("transparent", False)
            if (self.source is None or not plain or not self.embed_frames
                    or self.frame_format != "png" or not all(hasattr(self, a) for a in needed)):
                return super().grab_frame(**savefig_kwargs)
            import base64

            image = _compact_frame(self.source.render_frame(), self.colors, self.source.figure.dpi)
            data = base64.encodebytes(image).decode("ascii")
            self._total_bytes += len(data)
            if self._total_bytes >= self._bytes_limit:
                raise RuntimeError("the animation is larger than matplotlib's animation.embed_limit; "
                                   "use fewer frames or a lower dpi")
            self._saved_frames.append(data)
            self.compact_frames += 1
            return None

    return CompactHTMLWriter


def _animation_class():
    from matplotlib.animation import FuncAnimation

    class BalanceAnimation(FuncAnimation):
        """A FuncAnimation whose ``to_jshtml`` embeds compact palette WebP frames.

        Frames are rendered by redrawing only the moving artists over a cached
        background (``dynamic`` lists them; ``None`` means redraw everything). The embedded
        frames have ``pixel_ratio`` device pixels per CSS pixel (drawn at that multiple of the
        figure's dpi, like the course's figures: sharp on high-density screens); ``shown_size``
        is the size (CSS px) the player shows them at, the figure's own size in pixels.
        """

        dynamic = None
        _compact_saving = False
        #: set by :func:`animate` / :func:`animate_parameter`: the figure, the function that
        #: draws frame ``i``, the number of frames, the frame rate and how the player repeats
        figure: Any = None
        frame_function: Any = None
        _blitter: Any = None
        frame_count = 0
        fps = 24.0
        default_mode = "loop"
        pixel_ratio = style.PIXEL_RATIO

        @property
        def shown_size(self) -> tuple[int, int]:
            """(width, height) in CSS px at which the player shows a frame: the figure's size."""
            w, h = self.figure.canvas.get_width_height()
            return int(w), int(h)

        def render_frame(self) -> np.ndarray:
            """Pixels (h, w, 3) of the figure as it stands (only the moving artists redrawn)."""
            if self.dynamic is None:
                self.figure.canvas.draw()
                return np.asarray(self.figure.canvas.buffer_rgba())[..., :3]
            if getattr(self, "_blitter", None) is None:
                self._blitter = Blitter(self.figure, self.dynamic)
            return self._blitter.render()

        def frame_image(self, i: int) -> np.ndarray:
            """Pixels (h, w, 3) of frame ``i``, as embedded by :meth:`to_jshtml`."""
            if not 0 <= i < self.frame_count:
                raise IndexError(f"frame {i} of an animation of {self.frame_count} frames")
            self.frame_function(i)
            return self.render_frame()

        def _post_draw(self, framedata, blit):     # one of WRITER_INTERNALS' neighbours: see the module
            if self._compact_saving:
                return  # the writer renders the frame itself, once
            super()._post_draw(framedata, blit)  # type: ignore[misc]  # private in matplotlib's stubs

        def to_jshtml(self, fps=None, embed_frames=True, default_mode=None):
            """Self-contained HTML/JavaScript player of the animation (see matplotlib's)."""
            if not embed_frames:
                return super().to_jshtml(fps, embed_frames, default_mode)
            if fps is None:
                fps = self.fps
            if default_mode is None:
                default_mode = self.default_mode
            key = (fps, default_mode)
            cache = self.__dict__.setdefault("_balancelab_html", {})
            if key not in cache:
                cache[key] = offline_page(_embedded_player(self, fps, default_mode))
            return cache[key]

        def _repr_html_(self):
            return self.to_jshtml()

    return BalanceAnimation


def _embedded_player(anim, fps: float, default_mode: str) -> str:
    """matplotlib's JavaScript player of ``anim`` (a ``BalanceAnimation``), its frames compact WebP
    images drawn at ``anim.pixel_ratio`` times the figure's dpi; the figure is left as it was."""
    import tempfile
    from pathlib import Path

    with tempfile.TemporaryDirectory() as tmp:
        path = Path(tmp, "animation.html")
        writer = _compact_writer_class()(fps=fps, embed_frames=True, default_mode=default_mode)
        writer.source = anim
        anim._compact_saving = True
        anim._blitter = None
        dpi = anim.figure.dpi
        anim.figure.set_dpi(dpi * anim.pixel_ratio)   # fonts and lines scale with it
        try:
            anim.save(str(path), writer=writer)
        finally:
            anim._compact_saving = False
            anim.figure.set_dpi(dpi)
            anim._blitter = None
        page = path.read_text()
    if writer.compact_frames:
        page = page.replace('"data:image/png;base64,', '"data:image/webp;base64,')
    return page


def _start(fig, frame: Callable, count: int, fps: float, laid_out: bool = False):
    """The animation of ``count`` frames drawn by ``frame(i)``, its figure laid out once.

    An animation starts at its figure's first draw (matplotlib draws frame 0 then): that draw is
    made here (the one that freezes the layout, or one more when ``laid_out``), so no later render
    restarts frame 0 half-way, and an animation dropped unrendered is not reported as never drawn.
    """
    anim = _animation_class()(fig, frame, frames=count, interval=1000.0 / fps, blit=False,
                              repeat=True, cache_frame_data=False)
    anim.figure, anim.frame_function, anim.frame_count, anim.fps = fig, frame, count, fps
    if laid_out:
        fig.canvas.draw()
    else:
        _freeze_layout(fig)
    return anim


def _freeze_layout(fig) -> None:
    """Lay the figure out once, then keep that layout (drawing frames gets ~2x faster)."""
    fig.canvas.draw()
    fig.set_layout_engine("none")


def _figure(figsize, dpi, panels: int):
    from matplotlib.backends.backend_agg import FigureCanvasAgg
    from matplotlib.figure import Figure

    fig = Figure(figsize=figsize, dpi=dpi, layout="constrained")
    FigureCanvasAgg(fig)
    if panels == 2:
        axes = fig.subplots(2, 1, height_ratios=(1.2, 1))
    else:
        axes = [fig.subplots(1, 1)]
    return fig, list(axes)


def configuration_path(design: Design, frames: int = 60) -> np.ndarray:
    """A smooth closed path of reachable configurations through the design's range.

    One coordinate: a full turn when the range is a whole revolution, otherwise a
    smooth sweep from one end of the range to the other and back. Several
    coordinates: a Lissajous path over 90 % of each range. Unreachable points of the
    path are dropped.

    Parameters
    ----------
    design : Design
    frames : int
        Number of configurations, >= 2.

    Returns
    -------
    numpy.ndarray, shape (m, dof)
        ``m <= frames`` configurations (rad).

    Raises
    ------
    ValueError
        If fewer than two configurations of the path can be reached.

    Examples
    --------
    >>> import balancelab as bl
    >>> configuration_path(bl.singh.lacoste_lever(10.0, 0.5, 0.2, 0.3), 8).shape
    (8, 1)
    """
    check_design(design)
    frames = positive_int("frames", frames, 2)
    lo, hi = design.q_range[:, 0], design.q_range[:, 1]
    t = np.arange(frames) / frames
    if design.dof == 1:
        if hi[0] - lo[0] >= 2 * math.pi - 1e-9:
            q = (lo[0] + (hi[0] - lo[0]) * t)[:, None]
        else:
            # a hair inside the ends, which an open range does not include
            a, b = lo[0] + 1e-6 * (hi[0] - lo[0]), hi[0] - 1e-6 * (hi[0] - lo[0])
            q = (a + (b - a) * 0.5 * (1 - np.cos(2 * math.pi * t)))[:, None]
    else:
        c, h = 0.5 * (lo + hi), 0.45 * (hi - lo)
        cols = [c[i] + h[i] * np.sin(2 * math.pi * (i + 1) * t + 0.5 * i) for i in range(design.dof)]
        q = np.stack(cols, axis=-1)
    ok = design.reachable(q)
    if ok.sum() < 2:
        raise ValueError(f"{design.name}: fewer than two configurations of the animation path "
                         "can be reached")
    return q[ok]


def _fps(fps) -> float:
    return finite_real("fps (frames per second)", fps, positive=True)


def animate(design: Design, frames: int = 60, fps: float = 24, *, path=None, figsize=FIGSIZE,
            dpi: float = DPI, labels: bool = True):
    """Animate a design through its range beside its energy curve.

    Parameters
    ----------
    design : Design
        Any design; designs with 1 or 2 coordinates also show their energy curve or
        map with a marker at the current configuration.
    frames : int
        Number of frames (>= 2) of the default path (see :func:`configuration_path`).
    fps : float
        Frames per second of playback.
    path : array_like, shape (m, dof), optional
        Configurations (rad) to show instead of the default path (shape ``(m,)`` is
        accepted for one coordinate).
    figsize : (float, float)
        Figure size (inches).
    dpi : float
        Resolution; with the defaults ``to_jshtml()`` stays under 2 MB.
    labels : bool
        Write the design's named points.

    Returns
    -------
    matplotlib.animation.FuncAnimation
        Call ``to_jshtml()`` to embed it in a page. Extra attributes: ``path`` (the
        configurations), ``drawing`` (:class:`~balancelab.viz.Drawing`) and
        ``energy`` (:class:`~balancelab.viz.EnergyView` or ``None``).

    Examples
    --------
    >>> import balancelab as bl
    >>> anim = animate(bl.singh.lacoste_lever(10.0, 0.5, 0.2, 0.3), frames=12)
    >>> len(anim.path)
    12
    """
    check_design(design)
    fps = _fps(fps)
    if path is None:
        path = configuration_path(design, frames)
    else:
        path = np.asarray(path, dtype=float)
        if design.dof == 1 and path.ndim == 1:
            path = path[:, None]
        if path.ndim != 2 or path.shape[1] != design.dof or len(path) == 0:
            raise ValueError(f"path must have shape (m, {design.dof}) (configurations in rad, m >= 1) for "
                             f"the coordinates {design.q_names}, got shape {path.shape}")
        design.poses(path)
    show_energy = design.dof <= 2
    fig, axes = _figure(figsize, dpi, 2 if show_energy else 1)
    drawing = Drawing(design, path[0], axes[0], labels=labels)
    fit_title(axes[0], design.name)
    energy = None
    if show_energy:
        energy = EnergyView(design, axes[1], q=path[0], legend=True, title=False)
        energy.ax.set_title(_verdict(energy), fontsize=FONT["title"])

    def frame(i):
        drawing.update(path[i])
        if energy is not None:
            energy.set_q(path[i])
        return drawing.artists + ([energy.marker] if energy is not None else [])

    anim = _start(fig, frame, len(path), fps)
    anim.dynamic = lambda: drawing.artists + ([energy.marker] if energy is not None else [])
    anim.path = path
    anim.drawing = drawing
    anim.energy = energy
    anim.fps = fps
    anim.frame_labels = [configuration_label(design, q) for q in path]
    anim.description = _motion_description(design, path, energy)
    return anim


def configuration_label(design: Design, q) -> str:
    """A configuration in words for a player's frame: ``"θ = 40°"``, ``"θ1 = 90°, θ2 = -10°"``.

    Parameters
    ----------
    design : Design
    q : array_like, shape (dof,)
        The configuration (rad).

    Returns
    -------
    str

    Examples
    --------
    >>> import balancelab as bl
    >>> configuration_label(bl.catalog()["lacoste_lever"](), [0.7])
    'θ = 40°'
    """
    q = np.asarray(q, dtype=float).reshape(-1)
    return ", ".join(f"{q_symbol(design, i)} = {_shown(unit, v)}" for i, (unit, v) in enumerate(zip(q_units(design), q)))


def _shown(unit: str, value: float) -> str:
    """A coordinate for a label: an angle in whole degrees, a slide in whole millimetres."""
    return f"{1000.0 * value:.0f} mm" if unit == "m" else f"{np.degrees(value):.0f}°"


def _motion_description(design: Design, path: np.ndarray, energy) -> str:
    """What :func:`animate` shows: the design, the range it moves through, and its energy finding."""
    lo, hi = path.min(axis=0), path.max(axis=0)
    moves = ", ".join(f"{q_symbol(design, i)} from {_shown(u, a)} to {_shown(u, b)}"
                      for i, (u, a, b) in enumerate(zip(q_units(design), lo, hi)))
    text = f"{design.name} moving through {moves} in {len(path)} frames"
    if energy is not None:
        return f"{text}; {energy.description}"
    rep = design.balance_report()
    return f"{text}; it is {'balanced' if rep.balanced else 'not balanced'}: {report_summary(rep)}"


def _verdict(view: EnergyView) -> str:
    rep = view.report
    if rep is None:
        return "energy"
    return "balanced: total energy constant" if rep.balanced else "not balanced"


def animate_parameter(factory: Callable, name: str, values: Sequence[float], q=None, *,
                      fixed: Mapping | None = None, fps: float = 20, figsize=FIGSIZE, dpi: float = DPI,
                      labels: bool = True, unit: str = ""):
    """A scrubbable animation over one design parameter.

    Frame ``i`` shows ``factory(**{name: values[i], **fixed})`` in configuration ``q``
    beside its energy curve. A value for which the factory raises ``ValueError``
    (including :class:`~balancelab.UnreachableConfiguration`) or an arithmetic error,
    or for which ``q`` cannot be reached, becomes a frame with the error message
    instead of the mechanism; the animation itself never fails on it.

    Parameters
    ----------
    factory : callable
        ``factory(**kwargs) -> Design``.
    name : str
        The swept keyword argument.
    values : sequence of float
        Its values, one per frame (at least one must give a design).
    q : array_like, optional
        Configuration (rad) to show; by default each design's :func:`default_q`.
    fixed : mapping, optional
        Other keyword arguments for the factory.
    fps : float
        Frames per second.
    figsize, dpi : see :func:`animate`.
    labels : bool
        Write the designs' named points.
    unit : str
        Unit of the parameter for the titles (for example ``"m"``).

    Returns
    -------
    matplotlib.animation.FuncAnimation
        With attributes ``values``, ``designs`` (a Design or ``None`` per frame),
        ``messages`` (``""`` or the error text per frame), ``drawing`` and ``energy``.

    Raises
    ------
    ValueError
        If no value gives a valid design.

    Examples
    --------
    >>> import balancelab as bl
    >>> anim = animate_parameter(lambda a_x: bl.singh.lacoste_lever(10.0, 0.5, a_x, 0.3), "a_x",
    ...                          [0.0, 0.1, 0.2], unit="m")
    >>> [m[:8] for m in anim.messages]
    ['a_x = 0 ', '', '']
    """
    if not callable(factory):
        raise TypeError("factory must be callable: factory(**{name: value}) -> Design")
    if not isinstance(name, str) or not name:
        raise TypeError(f"name must be the parameter's keyword name, got {name!r}")
    fps = _fps(fps)
    values = [float(v) for v in values]
    if not values:
        raise ValueError("values must hold at least one parameter value")
    unit_s = f" {unit}" if unit else ""
    designs, qs, messages = _sweep(factory, name, values, dict(fixed or {}), q, unit_s)
    valid = [i for i, d in enumerate(designs) if d is not None]
    if not valid:
        raise ValueError(f"no value of {name} gives a valid design; first error: {messages[0]}")
    first = designs[valid[0]]
    show_energy = len({designs[i].dof for i in valid}) == 1 and first.dof <= 2
    fig, axes = _figure(figsize, dpi, 2 if show_energy else 1)
    ax = axes[0]
    drawing = Drawing(first, qs[valid[0]], ax, labels=labels, limits=False)
    x0, x1, y0, y1 = drawing.padded(_union_box([designs[i] for i in valid]))
    ax.set_xlim(x0, x1)
    ax.set_ylim(y0, y1)
    ax.set_aspect("equal", adjustable="box")
    title = ax.set_title("", fontsize=FONT["title"], y=1.0)
    note = ax.text(0.5, 0.5, "", transform=ax.transAxes, ha="center", va="center", fontsize=FONT["note"],
                   color="#D55E00", wrap=True,
                   bbox=dict(boxstyle="round", facecolor="white", edgecolor="#D55E00"))
    energy = _sweep_energy(designs, valid, axes[1], qs[valid[0]]) if show_energy else None
    heads = [f"{name} = {v:.4g}{unit_s}" for v in values]
    frame = _sweep_frames(designs, qs, [_wrap(m) for m in messages], heads, drawing, energy, title, note)
    # lay the figure out with the title that needs the most lines, so that none overlaps the drawing
    fit_title(ax, max((f"{d.name}, {h}" if d is not None else h + ": no valid design"
                       for d, h in zip(designs, heads)), key=len), y=1.0)
    _freeze_layout(fig)
    frame(0)
    anim = _start(fig, frame, len(values), fps, laid_out=True)
    if energy is not None and first.dof == 1:  # energy is shown
        anim.dynamic = lambda: (drawing.artists + [note, title] + energy.artists
                                + [energy.ax.title])
    anim.values = values
    anim.designs = designs
    anim.messages = messages
    anim.frame_labels, anim.description = _sweep_words(designs, heads, name, unit_s)
    anim.drawing = drawing
    anim.energy = energy
    anim.fps = fps
    return anim


def _sweep(factory: Callable, name: str, values: list, fixed: dict, q, unit_s: str):
    """The design and configuration of every value, or ``None`` and the error message."""
    designs: list = []
    qs: list = []
    messages: list = []
    for v in values:
        try:
            d = check_design(factory(**{**fixed, name: v}))
            qq = default_q(d) if q is None else np.asarray(q, dtype=float).reshape(-1)
            d.poses(qq)
        except (ValueError, ArithmeticError, RuntimeError) as exc:
            designs.append(None)
            qs.append(None)
            messages.append(f"{name} = {v:.4g}{unit_s}: {exc}")
            continue
        designs.append(d)
        qs.append(qq)
        messages.append("")
    return designs, qs, messages


def _sweep_words(designs: list, heads: list, name: str, unit_s: str) -> tuple[list, str]:
    """Each frame's label and the sweep's description: for which values the design is balanced."""
    verdicts, labels = [], []
    for d, h in zip(designs, heads):
        rep = None if d is None else d.balance_report(n=200)
        verdicts.append("no valid design" if rep is None else ("balanced" if rep.balanced else "not balanced"))
        labels.append(f"{h}, {verdicts[-1]}")
    first = next(d for d in designs if d is not None)
    vals = [h.split(" = ", 1)[1].removesuffix(unit_s) for h in heads]
    groups = {v: [x for x, w in zip(vals, verdicts) if w == v] for v in dict.fromkeys(verdicts)}
    found = "; ".join(f"{v} for {name} = {', '.join(xs)}{unit_s}" for v, xs in groups.items())
    return labels, (f"{first.name} redrawn for {len(heads)} values of {name} from {vals[0]} to {vals[-1]}"
                    f"{unit_s}: {found}")


def _union_box(designs: list) -> np.ndarray:
    """Bounding box ``[xmin, xmax, ymin, ymax]`` (m) of every design over its range."""
    boxes = np.array([extent(d)[0] for d in designs])
    return np.array([boxes[:, 0].min(), boxes[:, 1].max(), boxes[:, 2].min(), boxes[:, 3].max()])


def _sweep_energy(designs: list, valid: list, ax, q) -> EnergyView:
    """The energy view of the first design, its axis fixed to hold every design's curves."""
    first = designs[valid[0]]
    energy = EnergyView(first, ax, q=q, title=False)
    energy.ax.set_title(" ", fontsize=FONT["title"], y=1.0)
    if first.dof == 1:
        lows, highs = [], []
        for i in valid:
            e = energy.update(designs[i])
            vals = np.concatenate([v[np.isfinite(v)] for v in (e.load, e.spring, e.total)])
            lows.append(vals.min())
            highs.append(vals.max())
        scale = max((d.balance_report(n=200).scale for d in designs if d is not None), default=0.0)
        energy.ylim = energy_limits(min(lows + [0.0]), max(highs + [0.0]), scale)
        energy.update(first)
    return energy


def _sweep_frames(designs, qs, notes, heads, drawing, energy, title, note) -> Callable:
    """The frame function of a parameter sweep: frame ``i`` shows design ``i`` or its error."""
    state = {"design": designs[next(i for i, d in enumerate(designs) if d is not None)]}

    def frame(i):
        d = designs[i]
        if d is None:
            drawing.set_visible(False)
            note.set_text(notes[i])
            note.set_visible(True)
            fit_title(title.axes, heads[i] + ": no valid design", y=1.0)
            if energy is not None:
                energy.set_visible(False)
                energy.ax.set_title("", fontsize=FONT["title"], y=1.0)
            return []
        note.set_visible(False)
        drawing.update(qs[i], d, rescale=False)
        drawing.set_visible(True)
        fit_title(title.axes, f"{d.name}, {heads[i]}", y=1.0)
        if energy is not None:
            if d is not state["design"]:
                energy.update(d)
            energy.set_q(qs[i])
            energy.set_visible(True)
            energy.ax.set_title(_verdict(energy), fontsize=FONT["title"], y=1.0)
        state["design"] = d
        return []

    return frame


def _wrap(text: str, width: int = 36) -> str:
    import textwrap

    return "\n".join(textwrap.wrap(text, width)[:8])
