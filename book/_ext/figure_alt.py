"""Sphinx extension: a figure drawn as one image per panel keeps the alt text its page wrote.

In the book's kernels ``balancelab.viz.style.install`` shows every matplotlib figure as HTML,
one image per column of panels (so that they stack on a phone), with alt text made from the
panels' titles and axis labels. A page describes its figure better: when the cell sets
``mystnb: image: alt:``, this extension gives that text to each panel image (prefixed with
"panel i of n" when there are several), followed by what the panel computed it shows, when it
did (an energy plot: "Energy plot: the total energy is flat at 2.94 J ...").
"""
from __future__ import annotations

import html
import re

from docutils import nodes

__all__ = ["panel_alts", "setup"]

_PANEL = re.compile(r'(<img [^>]*?)alt="[^"]*"([^>]*class="bl-panel")')


def panel_alts(text: str, alt: str) -> str:
    """``text`` (HTML) with the alt text of every ``bl-panel`` image replaced by ``alt``.

    Examples
    --------
    >>> page = '<img src="a" alt="Figure panel: x" class="bl-panel"><img src="b" alt="y" class="bl-panel">'
    >>> panel_alts(page, "Left, a link; right, its energy")
    '<img src="a" alt="panel 1 of 2: Left, a link; right, its energy" class="bl-panel"><img src="b" alt="panel 2 of 2: Left, a link; right, its energy (y)" class="bl-panel">'
    """
    n = len(_PANEL.findall(text))
    count = iter(range(1, n + 1))

    def swap(m: re.Match) -> str:
        label = alt if n == 1 else f"panel {next(count)} of {n}: {alt}"
        own = html.unescape(re.search(r'alt="([^"]*)"', m.group(0)).group(1))
        if own and not own.startswith("Figure panel"):  # what the panel computed it shows: keep it
            label = f"{label} ({own})"
        return f'{m.group(1)}alt="{html.escape(label)}"{m.group(2)}'

    return _PANEL.sub(swap, text)


def _doctree_read(app, doctree: nodes.document) -> None:
    for cell in doctree.findall(nodes.container):
        if cell.get("nb_element") != "cell_code":
            continue
        alt = (((cell.get("cell_metadata") or {}).get("mystnb") or {}).get("image") or {}).get("alt")
        if not alt:
            continue
        for raw in list(cell.findall(nodes.raw)):
            text = raw.astext()
            if "bl-panel" in text:
                raw.replace_self(nodes.raw("", panel_alts(text, " ".join(str(alt).split())),
                                           format=raw.get("format", "html")))


def setup(app):
    """Register the hook with Sphinx."""
    app.connect("doctree-read", _doctree_read)
    return {"version": "1.0", "parallel_read_safe": True, "parallel_write_safe": True}
