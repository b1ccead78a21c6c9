"""The page's animation player: self-contained, usable by keyboard and by screen reader.

:func:`player` turns an animation (from :func:`~balancelab.viz.animate`,
:func:`~balancelab.viz.animate_parameter` or any matplotlib ``FuncAnimation``) into a block
of HTML that plays with no kernel and no network. On top of matplotlib's JavaScript player it

* draws the buttons as inline SVG (no icon font from a CDN);
* names the frame slider ("Frame") and gives it a spoken value that says which frame and which
  configuration it shows ("frame 3 of 24: θ = 30°"), the same text written under the slider;
* tells a screen reader where the player stopped after a step, a scrub or a pause (a polite live
  region that stays quiet while the animation plays);
* fits a phone's column: the slider and the row of buttons shrink with the page (390 px wide
  screens) instead of sticking out;
* never starts by itself, and has no transitions for readers who ask for reduced motion;
* shows the frames of balancelab's animations (drawn with ``pixel_ratio`` device pixels per CSS
  pixel) at the figure's own size: sharp on high-density screens.

The text alternative of the frames (the image's ``alt``) says what the animation shows; by
default it is the finding :func:`~balancelab.viz.animate` computes from the design's numbers
(``anim.description``). Layer: viz.
"""
from __future__ import annotations

import json
import re
from html import escape

__all__ = ["Player", "player"]


def _svg(path: str, flip: bool = False) -> str:
    """An inline 16x16 icon drawn in the text colour (no icon font, no network)."""
    turn = ' transform="matrix(-1 0 0 1 16 0)"' if flip else ""
    return (f'<svg aria-hidden="true" focusable="false" class="bl-icon" viewBox="0 0 16 16" width="1em" '
            f'height="1em"><path fill="currentColor"{turn} d="{path}"/></svg>')


_PLAY = "M4 2.5v11l9-5.5z"
_STEP = "M3 2.5v11l8-5.5zM12 2.5h2v11h-2z"
_FAST = "M1 2.5v11l7-5.5zM8 2.5v11l7-5.5z"
#: matplotlib's Font Awesome 4 player icons as inline SVG paths.
_ICONS = {
    "fa fa-play fa-flip-horizontal": _svg(_PLAY, flip=True),
    "fa fa-minus": _svg("M2 7h12v2H2z"),
    "fa fa-fast-backward": _svg(_FAST + "M13 2.5h2v11h-2z", flip=True),
    "fa fa-step-backward": _svg(_STEP, flip=True),
    "fa fa-pause": _svg("M3 2.5h3.5v11H3zM9.5 2.5H13v11H9.5z"),
    "fa fa-play": _svg(_PLAY),
    "fa fa-step-forward": _svg(_STEP),
    "fa fa-fast-forward": _svg(_FAST + "M13 2.5h2v11h-2z"),
    "fa fa-plus": _svg("M7 2h2v5h5v2H9v5H7V9H2V7h5z"),
}

#: The player's own styles: it fits a 358 px column (a 390 px phone) and moves only when asked.
_STYLE = """<style>
div.animation.bl-player { display: block; max-width: 100%; text-align: center; }
div.animation.bl-player input[type=range].anim-slider { width: 100%; max-width: 374px; box-sizing: border-box;
  margin: 0 auto; }
div.animation.bl-player .anim-buttons { display: flex; flex-wrap: nowrap; justify-content: center; gap: 2px;
  margin: 6px 0; }
div.animation.bl-player .anim-buttons button { flex: 0 1 36px; width: auto; min-width: 24px; margin: 0;
  padding: 0; }
div.animation.bl-player .bl-anim-status { margin: 0.2em 0; font-size: 0.9em; }
div.animation.bl-player .bl-sr-only { position: absolute; width: 1px; height: 1px; padding: 0; margin: -1px;
  overflow: hidden; clip: rect(0, 0, 0, 0); white-space: nowrap; border: 0; }
@media (prefers-reduced-motion: reduce) {
  div.animation.bl-player, div.animation.bl-player * { transition: none !important; animation: none !important; }
}
</style>
"""

#: Hooks the frame labels into matplotlib's ``Animation`` object once the page has made it.
_SCRIPT = """<script>
(function () {
  var id = "%(id)s", labels = %(labels)s, tries = 0;
  function hook() {
    var a = window["anim" + id];
    if (!a) { if (++tries < 200) { setTimeout(hook, 10); } return; }
    var slider = document.getElementById("_anim_slider" + id);
    var shown = document.getElementById("_anim_now" + id);
    var say = document.getElementById("_anim_say" + id);
    function text(f) { return "frame " + (f + 1) + " of " + labels.length + (labels[f] ? ": " + labels[f] : ""); }
    var setFrame = a.set_frame, pause = a.pause_animation, play = a.play_animation,
        reverse = a.reverse_animation;
    a.set_frame = function (f) {
      setFrame.call(this, f);
      var t = text(this.current_frame);
      slider.setAttribute("aria-valuetext", t);
      shown.textContent = t;
      /* the slider speaks its own value; a step or a jump is told here, never each frame of playback */
      if (!this.timer && document.activeElement !== slider) { say.textContent = t; }
    };
    a.pause_animation = function () {
      var was = !!this.timer;
      pause.call(this);
      if (was) { say.textContent = "paused at " + text(this.current_frame); }
    };
    a.play_animation = function () { play.call(this); say.textContent = "playing"; };
    a.reverse_animation = function () { reverse.call(this); say.textContent = "playing backwards"; };
    var t0 = text(a.current_frame);
    slider.setAttribute("aria-valuetext", t0);
    shown.textContent = t0;
  }
  setTimeout(hook, 0);
})();
</script>
"""


def offline_page(page: str) -> str:
    """Make matplotlib's player self-contained: no icon font fetched from a CDN.

    The buttons' Font Awesome icons become inline SVG drawings, so the player looks and
    works the same on a page opened with no network and with any system fonts.
    """
    page = re.sub(r'<link rel="stylesheet"\s*href="https?://[^"]*font-awesome[^"]*">\s*', "", page)
    for cls, icon in _ICONS.items():
        page = page.replace(f'<i class="{cls}"></i>', icon)
    return page


#: One frame of matplotlib's player saved as a PNG (its base64 text split by backslash-newlines).
_PNG_FRAME = re.compile(r'(frames\[\d+\] = ")data:image/png;base64,([^"]*)"')


def _compact_frames(page: str, dpi: float) -> str:
    """matplotlib's PNG frames of a player as the house style's lossless WebP (line art: a few
    times smaller than the full-colour PNGs), ``dpi`` recorded in each."""
    import base64
    import io

    import numpy as np
    from PIL import Image

    from .style import webp_image

    def one(m: re.Match) -> str:
        png = base64.b64decode(m.group(2).replace("\\\n", "").replace("\n", ""))
        rgb = np.asarray(Image.open(io.BytesIO(png)).convert("RGB"))
        data = base64.encodebytes(webp_image(rgb, dpi)).decode("ascii").replace("\n", "\\\n")
        return f'{m.group(1)}data:image/webp;base64,{data}"'

    return _PNG_FRAME.sub(one, page)


def _accessible(page: str, alt: str, labels: list[str], size: tuple[int, int] | None = None) -> str:
    """matplotlib's player HTML with a named slider, spoken frame labels and a phone-width layout;
    its frames shown at ``size`` (CSS px) when given (frames drawn for high-density screens)."""
    m = re.search(r'id="_anim_slider(\w+)"', page)
    if m is None:
        raise ValueError("not a matplotlib JavaScript player: its frame slider is missing")
    uid = m.group(1)
    first = f"frame 1 of {len(labels)}" + (f": {labels[0]}" if labels and labels[0] else "")
    page = page.replace('<div class="animation">', '<div class="animation bl-player">', 1)
    shown = f'width="{size[0]}" height="{size[1]}" ' if size else ""
    page = page.replace("<img id=", f'<img alt="{escape(alt, quote=True)}" {shown}id=', 1)
    page = page.replace(f'<input id="_anim_slider{uid}"',
                        f'<input aria-label="Frame" aria-valuetext="{escape(first, quote=True)}" '
                        f'id="_anim_slider{uid}"', 1)
    status = (f'<p class="bl-anim-status"><span id="_anim_now{uid}">{escape(first)}</span>'
              f'<span class="bl-sr-only" id="_anim_say{uid}" role="status" aria-live="polite"></span></p>')
    page = re.sub(r'(<input [^>]*id="_anim_slider' + uid + r'"[^>]*>)', lambda s: s.group(1) + status, page,
                  count=1)
    # inline-block images and buttons leave gaps that push the last button to a new line
    page = page.replace("</style>", "</style>\n" + _STYLE, 1) if "</style>" in page else _STYLE + page
    script = _SCRIPT % {"id": uid, "labels": json.dumps(labels, ensure_ascii=False).replace("</", "<\\/")}
    return page + script


class Player:
    """A self-contained HTML animation player; Jupyter shows it through ``_repr_html_``.

    Parameters
    ----------
    html : str
        The player's HTML (from :func:`player`).
    frames : int
        Number of frames it holds.
    """

    def __init__(self, html: str, frames: int) -> None:
        self.html, self.frames = html, int(frames)

    def _repr_html_(self) -> str:
        return self.html

    def __repr__(self) -> str:
        return f"<animation player, {self.frames} frames>"


def _labels(anim, frames: int) -> list[str]:
    labels = getattr(anim, "frame_labels", None)
    if labels is None or len(labels) != frames:
        return [""] * frames
    return [str(s) for s in labels]


def player(anim, alt: str | None = None, default_mode: str = "loop") -> Player:
    """The page's player of an animation, its frames described by ``alt``; the figure is closed.

    Parameters
    ----------
    anim : matplotlib.animation.Animation
        From :func:`~balancelab.viz.animate`, :func:`~balancelab.viz.animate_parameter` or any
        ``FuncAnimation``. When it has ``frame_labels`` (one string per frame, as those two
        functions set), the slider and the line under it say which configuration each frame shows.
    alt : str, optional
        What the animation shows, in words (the text alternative of its frames). By default the
        finding the animation computed from its design (``anim.description``); required for an
        animation that has none.
    default_mode : {"loop", "once", "reflect"}
        What the player does at the last frame.

    Returns
    -------
    Player
        Displayed as the player in a notebook or a built page.

    Raises
    ------
    ValueError
        If ``alt`` is empty, or missing for an animation without a description.

    Examples
    --------
    >>> import balancelab as bl
    >>> p = player(bl.animate(bl.catalog()["lacoste_lever"](), frames=4), "a lever turning")
    >>> p, 'alt="a lever turning"' in p.html, 'aria-label="Frame"' in p.html
    (<animation player, 4 frames>, True, True)
    """
    import matplotlib
    import matplotlib.pyplot as plt
    from matplotlib.animation import Animation

    from .style import PIXEL_RATIO

    if not isinstance(anim, Animation):
        raise TypeError(f"anim must be a matplotlib Animation (from animate), got {type(anim).__name__}")
    if alt is None:
        alt = getattr(anim, "description", None)
        if alt is None:
            raise ValueError("alt must describe the animation in words: this animation has no description "
                             "of its own (anim.description)")
    if not isinstance(alt, str) or not alt.strip():
        raise ValueError("alt must describe the animation in words (a non-empty string)")
    if default_mode not in ("loop", "once", "reflect"):
        raise ValueError(f"default_mode must be 'loop', 'once' or 'reflect', got {default_mode!r}")
    ratio = getattr(anim, "pixel_ratio", None)
    if ratio is not None:
        # balancelab's animations draw their frames at pixel_ratio times the size they are shown at
        html = offline_page(anim.to_jshtml(default_mode=default_mode))
        size = getattr(anim, "shown_size", None) if ratio != 1 else None
    else:
        # any other matplotlib animation: its frames saved at PIXEL_RATIO times its figure's dpi
        own = anim._fig  # type: ignore[attr-defined]  # matplotlib's only name for the figure
        with matplotlib.rc_context({"savefig.dpi": own.dpi * PIXEL_RATIO}):
            html = offline_page(anim.to_jshtml(default_mode=default_mode))
        html = _compact_frames(html, own.dpi * PIXEL_RATIO)
        w, h = own.get_size_inches() * own.dpi
        size = (int(round(w)), int(round(h)))
    frames = len(set(re.findall(r"frames\[(\d+)\]", html)))
    fig = getattr(anim, "figure", None)      # balancelab's animations name their figure
    plt.close(fig if fig is not None else anim._fig)  # type: ignore[attr-defined]  # any other matplotlib animation: its only name
    return Player(_accessible(html, " ".join(alt.split()), _labels(anim, frames), size), frames)
