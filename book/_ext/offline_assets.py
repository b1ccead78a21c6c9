"""Sphinx extension of the balancelab course: keep the built site self-contained.

* checks at start-up that the vendored MathJax 3, require.js and ipywidgets HTML manager
  are in ``book/_vendor/vendor/`` (``scripts/build_book.sh`` fetches them from the npm
  registry) and fails with a clear message otherwise;
* removes the second copy of sphinx-thebe 0.3.1's inline ``const THEBE_JS_URL`` script
  (declaring a ``const`` twice is a console error on every page);
* drops the Font Awesome 4 CDN link that matplotlib's ``to_jshtml()`` puts in every
  animation (the theme's own Font Awesome draws the player's icons);
* after the build, ships only what some page uses (:func:`prune_unused`): the ipywidgets HTML
  manager, require.js and their shim only when a page embeds widgets, and never the themes'
  JavaScript source maps or their translation catalogues (read by Sphinx at build time);
* after the build, warns (an error under ``-W``) about any page that still loads a script,
  style sheet or font from another host.
"""
from __future__ import annotations

import re
import shutil
from pathlib import Path

from sphinx.application import Sphinx
from sphinx.errors import ExtensionError
from sphinx.util import logging

logger = logging.getLogger(__name__)

#: Files that must be vendored, relative to the site root.
REQUIRED = ("vendor/mathjax/tex-chtml.js", "vendor/requirejs/require.js",
            "vendor/html-manager/embed-amd.js", "vendor/widgets-mathjax-shim.js")

_REMOTE = re.compile(r"""<(?:script|link|img|iframe)\b[^>]*?\b(?:src|href)\s*=\s*["'](?:https?:)?//""",
                     re.IGNORECASE)


def _check_vendor(app: Sphinx) -> None:
    if app.builder.format != "html":
        return
    missing = []
    for extra in app.config.html_extra_path:
        root = Path(app.confdir, extra)
        missing = [f for f in REQUIRED if not (root / f).is_file()]
        if not missing:
            return
    raise ExtensionError(
        "offline assets missing (" + ", ".join(missing) + "): run `bash scripts/build_book.sh "
        ".venv/bin/python`, which fetches MathJax 3, require.js and @jupyter-widgets/html-manager "
        "from the npm registry into book/_vendor/")


def _dedupe_scripts(app, pagename, templatename, context, doctree) -> None:
    files = context.get("script_files")
    if not files:
        return
    seen: set = set()
    kept = []
    for js in files:
        body = getattr(js, "attributes", {}).get("body", "") if hasattr(js, "attributes") else ""
        key = (str(js), body)
        if key in seen:
            continue
        if body and "THEBE_JS_URL" in body:
            if "thebe" in seen:
                continue
            seen.add("thebe")
        seen.add(key)
        kept.append(js)
    files[:] = kept


#: matplotlib's ``to_jshtml()`` links Font Awesome 4 from a CDN for its player buttons; the
#: theme already ships Font Awesome (``_static/scripts/fontawesome.js``), which draws the same
#: ``fa fa-play``-style icons, so the link is dropped.
_FA_LINK = re.compile(r"""<link\s+rel="stylesheet"\s+href="https://maxcdn\.bootstrapcdn\.com/font-awesome/[^"]*"\s*/?>""")


def _strip_cdn_links(app, pagename, templatename, context, doctree) -> None:
    body = context.get("body")
    if body and "maxcdn.bootstrapcdn.com" in body:
        context["body"] = _FA_LINK.sub("", body)


def _check_remote(app: Sphinx, exception) -> None:
    if exception is not None or app.builder.format != "html":
        return
    outdir = Path(app.outdir)
    for page in sorted(outdir.rglob("*.html")):
        if "vendor" in page.relative_to(outdir).parts[:1]:
            continue
        text = page.read_text(encoding="utf-8", errors="replace")
        for m in _REMOTE.finditer(text):
            # links (<a>) are fine; only loaded resources are reported. <link rel=...> of the
            # kind "canonical"/"alternate" load nothing either.
            tag = text[m.start(): text.find(">", m.start()) + 1]
            if tag.lower().startswith("<link") and not re.search(r'rel="(stylesheet|preload|icon)', tag):
                continue
            logger.warning("%s loads a resource from another host: %s",
                           page.relative_to(outdir), tag[:160], type="offline", subtype="remote")


#: Vendored files a page asks for only when it embeds widgets (myst-nb adds ``nb_ipywidgets_js``
#: to such pages only).
WIDGET_ASSETS = ("vendor/html-manager", "vendor/requirejs", "vendor/widgets-mathjax-shim.js")
#: Files of the built site that no page requests.
NEVER_REQUESTED = ("_static/**/*.map", "_static/locales")


def prune_unused(outdir) -> list[str]:
    """Delete from a built site the assets no page requests; return their paths (relative).

    Parameters
    ----------
    outdir : path
        The HTML output folder.

    Returns
    -------
    list of str

    Examples
    --------
    >>> import tempfile
    >>> root = Path(tempfile.mkdtemp())
    >>> (root / "vendor" / "requirejs").mkdir(parents=True)
    >>> _ = (root / "index.html").write_text("<html>no widgets</html>")
    >>> prune_unused(root)
    ['vendor/requirejs']
    """
    outdir = Path(outdir)
    pages = [p for p in outdir.rglob("*.html") if p.relative_to(outdir).parts[0] != "vendor"]
    uses_widgets = any("html-manager/embed-amd.js" in p.read_text(encoding="utf-8", errors="replace")
                       for p in pages)
    doomed = [] if uses_widgets else [outdir / w for w in WIDGET_ASSETS]
    for pattern in NEVER_REQUESTED:
        doomed += sorted(outdir.glob(pattern))
    removed = []
    for path in doomed:
        if path.is_dir():
            shutil.rmtree(path)
        elif path.is_file():
            path.unlink()
        else:
            continue
        removed.append(path.relative_to(outdir).as_posix())
    return removed


def _prune(app: Sphinx, exception) -> None:
    if exception is None and app.builder.format == "html":
        removed = prune_unused(app.outdir)
        logger.info("offline_assets: not shipped (no page requests them): %s", ", ".join(removed) or "nothing")


def setup(app: Sphinx) -> dict:
    app.connect("builder-inited", _check_vendor)
    app.connect("build-finished", _prune)
    app.connect("html-page-context", _dedupe_scripts, priority=900)
    app.connect("html-page-context", _strip_cdn_links)
    app.connect("build-finished", _check_remote)
    return {"version": "1.0", "parallel_read_safe": True, "parallel_write_safe": True}
