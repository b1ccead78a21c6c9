"""Sphinx extension: a figure drawn as one image per panel keeps the alt text its page wrote.

In the book's kernels ``balancelab.viz.style.install`` shows every matplotlib figure as HTML,
one image per column of panels (so that they stack on a phone), with alt text made from the
panels' titles and axis labels. A page describes its figure better: when the cell sets
``mystnb: image: alt:``, this extension gives that text to the figure's image. A figure of
several panels needs one text per panel instead, the cell's ``panel_alts``, a list in the order
of the panels (a key of its own: myst-nb wants ``image: alt:`` to be a single string)::

    panel_alts:
      - A link pivoted at A with a spring from B above A to C on the link.
      - Three energy curves against the link angle; the total is flat.

Each panel's image then reads "Panel i of n: " and its own text, followed by what the panel
computed it shows, when it did (an energy plot: "Energy plot: the total energy is flat at
2.94 J ..."). The panels sit side by side on a wide screen but stack on a phone, so a panel's
text describes that panel alone and never points at another by its place ("left", "right"):
a single text for several panels, a list of the wrong length or a text that points left or
right is a build warning (an error in the course's build).
"""
from __future__ import annotations

import html
import re
from collections.abc import Sequence

from docutils import nodes
from sphinx.util import logging

__all__ = ["panel_alts", "setup"]

_PANEL = re.compile(r'(<img [^>]*?)alt="[^"]*"([^>]*class="bl-panel")')
#: words that point at a panel by where it sits beside the others (true only on a wide screen)
_PLACE = re.compile(r"\b(?:(?:left|right|middle)\s*(?:[,:;]|panels?\b|drawings?\b|plots?\b|and (?:left|right)\b)"
                    r"|on the (?:left|right)\b(?! (?:of|end|side of))"
                    r"|(?:left|right)-hand (?:panel|plot|drawing|side)\b)", re.IGNORECASE)

logger = logging.getLogger(__name__)


def panel_alts(text: str, alt: str | Sequence[str]) -> str:
    """``text`` (HTML) with the alt text of each ``bl-panel`` image replaced by its own text.

    Parameters
    ----------
    text : str
        HTML of one figure, as ``balancelab.viz.style.figure_html`` writes it.
    alt : str or sequence of str
        The figure's alt text: one string for a figure of one panel, else one string per
        panel, in the order of the panels.

    Returns
    -------
    str

    Raises
    ------
    ValueError
        When ``alt`` does not give exactly one text per panel, or a text points at a panel by
        its place ("left", "right", "middle"), which a phone's stacked panels make wrong.

    Examples
    --------
    >>> page = '<img src="a" alt="Figure panel: x" class="bl-panel"><img src="b" alt="y" class="bl-panel">'
    >>> panel_alts(page, ["A link and its spring", "Its energy curves"])
    '<img src="a" alt="Panel 1 of 2: A link and its spring" class="bl-panel"><img src="b" alt="Panel 2 of 2: Its energy curves (y)" class="bl-panel">'
    >>> panel_alts(page, "Left, a link; right, its energy")
    Traceback (most recent call last):
    ...
    ValueError: alt: the figure has 2 panels but 1 alt text was given; give a list of 2 texts, one per panel
    """
    texts = [alt] if isinstance(alt, str) else [str(a) for a in alt]
    texts = [" ".join(t.split()) for t in texts]
    n = len(_PANEL.findall(text))
    if len(texts) != n:
        given = f"{len(texts)} alt text{'s' if len(texts) != 1 else ''} {'was' if len(texts) == 1 else 'were'}"
        raise ValueError(f"alt: the figure has {n} panel{'s' if n != 1 else ''} but {given} given; "
                         f"give a list of {n} texts, one per panel")
    for i, t in enumerate(texts, start=1):
        if not t:
            raise ValueError(f"alt: the text of panel {i} is empty")
        if n > 1 and (m := _PLACE.search(t)):
            raise ValueError(f"alt: the text of panel {i} points at a panel by its place ({m.group(0)!r}); "
                             "panels stack on a phone: describe this panel alone")
    labels = iter(texts if n == 1 else [f"Panel {i} of {n}: {t}" for i, t in enumerate(texts, start=1)])

    def swap(m: re.Match) -> str:
        label = next(labels)
        own = html.unescape(re.search(r'alt="([^"]*)"', m.group(0)).group(1))
        if own and not own.startswith("Figure panel"):  # what the panel computed it shows: keep it
            label = f"{label} ({own})"
        return f'{m.group(1)}alt="{html.escape(label)}"{m.group(2)}'

    return _PANEL.sub(swap, text)


def _doctree_read(app, doctree: nodes.document) -> None:
    for cell in doctree.findall(nodes.container):
        if cell.get("nb_element") != "cell_code":
            continue
        meta = cell.get("cell_metadata") or {}
        alt = meta.get("panel_alts") or ((meta.get("mystnb") or {}).get("image") or {}).get("alt")
        if not alt:
            continue
        if not isinstance(alt, str) and not (isinstance(alt, list) and all(isinstance(a, str) for a in alt)):
            logger.warning(f"figure alt text: panel_alts must be a list of strings, not {alt!r}", location=cell)
            continue
        for raw in list(cell.findall(nodes.raw)):
            text = raw.astext()
            if "bl-panel" not in text:
                continue
            try:
                fixed = panel_alts(text, alt)
            except ValueError as exc:
                logger.warning(f"figure alt text: {exc}", location=cell)
                continue
            raw.replace_self(nodes.raw("", fixed, format=raw.get("format", "html")))


def setup(app):
    """Register the hook with Sphinx."""
    app.connect("doctree-read", _doctree_read)
    return {"version": "1.0", "parallel_read_safe": True, "parallel_write_safe": True}
