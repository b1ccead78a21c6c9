"""Sphinx extension of the balancelab course: the site's chrome as a reader needs it.

* the download menu offers the reader's notebook (``.ipynb``, without solutions, written by
  ``reader_notebooks``) and the printable course (:data:`PDF_NAME`, made by
  ``scripts/build_pdf.py``); not the MyST source, which holds every solution, and not the
  browser's print dialog presented as a PDF;
* element ids are unique on a page (sphinx-exercise gives every exercise and solution body
  the same ``exercise-content`` / ``solution-content`` id): later copies get a suffix;
* after the build the site sheds what no reader uses (:func:`slim_site`): the Font Awesome
  JavaScript (1.5 MB; the theme's style sheet draws the same icons with its web fonts), the
  MyST sources, MathJax's speech rules for languages other than English (the English rules and
  Nemeth braille stay: screen readers use them), MathJax's input bundles and all-packages file
  that no page loads, the second copies of the components ``tex-chtml.js`` holds (:data:`MATHJAX_BUNDLED`) and the
  widget manager's icon fonts in formats no browser that runs it asks for (:data:`LEGACY_FONTS`).
"""
from __future__ import annotations

import re
import shutil
from pathlib import Path

from docutils import nodes

__all__ = ["LEGACY_FONTS", "MATHJAX_BUNDLED", "PDF_NAME", "setup", "slim_site"]

#: The printable course, at the site's root.
PDF_NAME = "balancelab-course.pdf"
#: Font formats older than WOFF2 that the widget manager's style sheet lists after WOFF2 (every
#: browser that runs the manager loads the WOFF2 file): 2.8 MB no reader ever fetches.
LEGACY_FONTS = ("eot", "svg", "ttf", "woff")
#: MathJax components that ``tex-chtml.js`` already holds (its ``preLoad`` list): MathJax never
#: fetches them, since they are loaded with it (1 MB of second copies).
MATHJAX_BUNDLED = ("loader.js", "startup.js", "core.js", "output/chtml.js", "output/chtml/fonts/tex.js",
                   "ui/menu.js", "a11y/assistive-mml.js",
                   *(f"input/tex/extensions/{name}.js" for name in
                     ("ams", "newcommand", "noundefined", "require", "autoload", "configmacros")))
#: Site files (globs relative to the site root) that no page loads.
UNUSED = ("_static/scripts/fontawesome.js", "_static/scripts/fontawesome.js.LICENSE.txt",
          "_static/vendor/fontawesome/webfonts/*.ttf", "_sources/**/*.md",
          "vendor/mathjax/input/tex-full.js", "vendor/mathjax/input/tex-base.js", "vendor/mathjax/input/tex.js",
          # every TeX package in one file: only a page that asks for it by name loads it (autoload
          # fetches each package a formula uses on its own)
          "vendor/mathjax/input/tex/extensions/all-packages.js",
          "vendor/mathjax/input/asciimath.js", "vendor/mathjax/input/mml.js", "vendor/mathjax/input/mml",
          *(f"vendor/html-manager/*.{ext}" for ext in LEGACY_FONTS),
          *(f"vendor/mathjax/{name}" for name in MATHJAX_BUNDLED))
#: MathJax speech-rule files kept (English speech, Nemeth braille, the shared base).
MATHMAPS_KEPT = ("base.json", "en.json", "nemeth.json")
_FA_SCRIPT = re.compile(r'<script defer src="[^"]*_static/scripts/fontawesome\.js[^"]*"></script>\s*')


def _download_menu(app, pagename, templatename, context, doctree) -> None:
    for group in context.get("header_buttons", []):
        if group.get("label") != "download-buttons":
            continue
        kept = []
        for button in group["buttons"]:
            if button.get("label") == "download-source-button":
                continue
            if button.get("label") == "download-pdf-button":
                button = {"type": "link", "url": context["pathto"](PDF_NAME, 1), "text": "course PDF",
                          "tooltip": "The whole course, printable (PDF)", "icon": "fas fa-file-pdf",
                          "label": "download-pdf-button"}
            kept.append(button)
        group["buttons"] = kept
        group["tooltip"] = "Download"


def _unique_ids(app, doctree, docname) -> None:
    seen: dict = {}
    for node in doctree.findall(nodes.Element):
        ids = node.get("ids")
        if not ids:
            continue
        new = []
        for i in ids:
            n = seen.get(i, 0)
            seen[i] = n + 1
            new.append(i if n == 0 else f"{i}-{n + 1}")
        node["ids"] = new


def slim_site(outdir) -> int:
    """Delete from a built site what no page loads; return the bytes saved.

    Parameters
    ----------
    outdir : path
        The site's root (``_build/html``).

    Returns
    -------
    int

    Examples
    --------
    >>> import tempfile, pathlib
    >>> root = pathlib.Path(tempfile.mkdtemp())
    >>> (root / "vendor/mathjax/sre/mathmaps").mkdir(parents=True)
    >>> for name in ("en.json", "de.json"): _ = (root / "vendor/mathjax/sre/mathmaps" / name).write_text("{}")
    >>> slim_site(root), sorted(p.name for p in (root / "vendor/mathjax/sre/mathmaps").iterdir())
    (2, ['en.json'])
    """
    root = Path(outdir)
    saved = 0
    doomed = [p for pattern in UNUSED for p in root.glob(pattern)]
    maps = root / "vendor" / "mathjax" / "sre" / "mathmaps"
    if maps.is_dir():
        doomed += [p for p in maps.iterdir() if p.name not in MATHMAPS_KEPT]
    for path in doomed:
        if path.is_dir():
            saved += sum(f.stat().st_size for f in path.rglob("*") if f.is_file())
            shutil.rmtree(path)
        elif path.exists():
            saved += path.stat().st_size
            path.unlink()
    for page in root.rglob("*.html"):
        if page.relative_to(root).parts[0] == "vendor":
            continue
        text = page.read_text(encoding="utf-8")
        slim = _FA_SCRIPT.sub("", text)
        if slim != text:
            page.write_text(slim, encoding="utf-8")
    return saved


def _finished(app, exception) -> None:
    if exception is None and app.builder.format == "html":
        slim_site(app.outdir)


def setup(app):
    """Register the handlers with Sphinx."""
    app.connect("html-page-context", _download_menu, priority=900)
    app.connect("doctree-resolved", _unique_ids)
    app.connect("build-finished", _finished, priority=900)
    return {"version": "1.0", "parallel_read_safe": True, "parallel_write_safe": True}
