"""Sphinx extension: the site meets WCAG 2.1 AA where the themes' own markup does not.

Checked by ``tests/test_a11y.py`` (axe-core on every page at 390 and 1280 px). This extension

* loads ``book/_static/accessibility.css`` (contrast of links and figure references,
  visible keyboard focus, no motion for readers who ask for reduced motion) and
  ``book/_static/accessibility.js`` (scrolling figures reachable by keyboard) on every page;
* after the build, fixes the themes' and docutils' markup in every page (:func:`fix_markup`):
  controls whose accessible name left out their visible text (the search button's "Ctrl+K",
  the hide-input toggles' "Show code cell source", the colour-mode icons' titles), and the
  bibliography's deprecated ARIA role ``doc-biblioentry`` inside a ``role="list"``.
"""
from __future__ import annotations

import re
from pathlib import Path

__all__ = ["fix_markup", "setup"]

_FIXES = (
    # the search field's name is its visible text, "Search Ctrl+K", and it says its shortcut
    (re.compile(r'(<button class="btn search-button-field[^"]*" title="Search") aria-label="Search"'),
     r'\1 aria-keyshortcuts="Control+K"'),
    # myst-nb's hide-input toggles: named by the visible "Show code cell source"
    (re.compile(r'<summary aria-label="Toggle hidden content">'), "<summary>"),
    # the colour-mode button is named "Color mode"; its icons are pictures, not text
    (re.compile(r'(<i class="theme-switch [^"]*" data-mode="\w+")\s+title="[^"]*"'), r'\1 aria-hidden="true"'),
    # docutils' citations: a list of list items (doc-biblioentry is deprecated in ARIA 1.3)
    (re.compile(r'(<div class="citation" id="[^"]+") role="doc-biblioentry"'), r'\1 role="listitem"'),
)


def fix_markup(text: str) -> str:
    """A built page's HTML with the accessibility fixes of this extension applied.

    Examples
    --------
    >>> fix_markup('<summary aria-label="Toggle hidden content"><p>Show code cell source</p>')
    '<summary><p>Show code cell source</p>'
    >>> fix_markup('<div class="citation" id="id7" role="doc-biblioentry">')
    '<div class="citation" id="id7" role="listitem">'
    """
    for pattern, repl in _FIXES:
        text = pattern.sub(repl, text)
    return text


def _build_finished(app, exception) -> None:
    if exception is not None or app.builder.format != "html":
        return
    out = Path(app.outdir)
    for page in out.rglob("*.html"):
        if page.relative_to(out).parts[0] in ("vendor", "_static", "_sources"):
            continue
        text = page.read_text(encoding="utf-8")
        fixed = fix_markup(text)
        if fixed != text:
            page.write_text(fixed, encoding="utf-8")


def setup(app):
    """Register the style sheet, the script and the post-build fixes with Sphinx."""
    app.add_css_file("accessibility.css")
    app.add_js_file("accessibility.js")
    app.connect("build-finished", _build_finished)
    return {"version": "1.0", "parallel_read_safe": True, "parallel_write_safe": True}
