"""Benchmarks of the course book: build times and site size.

Rows (name, value, unit, target):

* cold full build, every notebook executed (no cache, fresh environment): < 5 min;
* cached rebuild after touching one chapter: < 30 s;
* slowest chapter (execution time from the jupyter-cache records): for information;
* total size of the site, the course PDF included: < 15 MB, and the size of each of its parts
  (chapter pages, animation frames, PDF, MathJax, theme ...: :func:`site_parts`);
* weight of the heaviest page: its HTML plus the images it shows: < 3 MB;
* the scripts, style sheets and fonts every page loads (downloaded once, then cached by the
  browser; MathJax's on-demand parts aside): for information;
* each chapter's first visit in Chromium (every byte the page fetches with an empty cache),
  without and with its own inline figures (:func:`first_visit_weights`); animation frames after
  the first load when the reader reaches the player (book/_ext/lazy_frames.py). The target,
  < 1.5 MB, is on what is *transferred* (issue 20): the bytes a static host sends, text files
  gzip-compressed, figures included. The raw bytes are for information: of a chapter's ~2.3 MB
  without figures, 1.16 MB is MathJax's ``tex-chtml.js`` (TeX input, HTML output, the formula
  menu that copies and zooms a formula and the assistive MathML screen readers read: both are
  documented features, book/accessibility.md) and 0.4 MB the theme's style sheet, which no
  static host sends uncompressed (gzip: 0.26 MB and 0.07 MB);
* the printable course's size, as printed by Chromium and as shipped (scripts/build_pdf.py
  stores its pictures as indexed images and drops the per-line structure tags): for information;
* the printable course's build time (Chromium printing the whole course, scripts/build_pdf.py).

The cold build re-executes everything, so this benchmark takes a few minutes.
"""
from __future__ import annotations

import re
import shutil
import subprocess
import sys
import time
from pathlib import Path
from urllib.parse import unquote, urlsplit

ROOT = Path(__file__).resolve().parents[1]
SITE = ROOT / "_build" / "html"
CACHE = ROOT / "_build" / ".jupyter_cache"
TOUCHED = ROOT / "book" / "ch2_zfl_springs.md"


def _build(*args: str) -> float:
    t0 = time.perf_counter()
    r = subprocess.run([sys.executable, str(ROOT / "scripts" / "build_book.py"), "--quiet", *args],
                       cwd=ROOT, capture_output=True, text=True)
    elapsed = time.perf_counter() - t0
    if r.returncode != 0:
        raise RuntimeError(f"book build failed:\n{r.stdout[-3000:]}\n{r.stderr[-3000:]}")
    return elapsed


def _slowest_chapter() -> tuple[str, float]:
    from jupyter_cache import get_cache

    worst = ("none", 0.0)
    for rec in get_cache(str(CACHE)).list_cache_records():
        t = float((rec.data or {}).get("execution_seconds", 0.0))
        if t > worst[1]:
            worst = (Path(rec.uri).stem, t)
    return worst


_IMAGE = (".png", ".jpg", ".jpeg", ".gif", ".svg", ".webp")


def page_weight(page: Path, site: Path = SITE, shared: bool = False) -> int:
    """Bytes of ``page``: its HTML and the images it shows, or (``shared``) the local scripts,
    style sheets and fonts it loads, which every page shares.
    """
    text = page.read_text(encoding="utf-8", errors="replace")
    refs = set(re.findall(r'\bsrc="([^"#?]+)', text))
    refs |= {m for m in re.findall(r'<link\b[^>]*\bhref="([^"#?]+)', text) if not m.endswith(".html")}
    total = 0 if shared else page.stat().st_size
    for ref in refs:
        if "://" in ref or ref.startswith("data:") or ref.lower().endswith(_IMAGE) == shared:
            continue
        target = (page.parent / ref).resolve()
        if target.is_file() and site.resolve() in target.parents:
            total += target.stat().st_size
    return total


_FIGURE = re.compile(r'src="data:image/[^"]*"')


#: Responses a static host (GitHub Pages, GitLab Pages, nginx) sends gzip-compressed.
_TEXT = (".html", ".js", ".css", ".json", ".svg", ".txt", ".map")


def _served(url: str, body: int, site: Path, gzip_text: bool) -> int:
    """Bytes of one response: as measured, or what gzip (level 6) makes of a text file."""
    import gzip

    path = site / unquote(urlsplit(url).path.lstrip("/"))
    if not gzip_text or path.suffix not in _TEXT or not path.is_file():
        return body
    return len(gzip.compress(path.read_bytes(), 6))


def first_visit_weights(site: Path = SITE, figures: bool = False, gzip_text: bool = False) -> dict:
    """Bytes each page of the book fetches on a first visit (empty cache), in Chromium, without
    the page's own figures (inline PNG data in its HTML) unless ``figures``.

    The page is loaded at a laptop's window size and left until the network is idle: an
    animation's frames after the first are fetched only when the reader scrolls to it
    (book/_ext/lazy_frames.py), so they count only for an animation in the first screen.

    With ``gzip_text`` every text file (HTML, scripts, style sheets) counts as the gzip-compressed
    bytes a static host sends; the test server sends them uncompressed. Figures are inline PNG
    data, which gzip hardly shrinks, so ``figures`` and ``gzip_text`` together leave them as they
    are inside the compressed page.

    Returns
    -------
    dict of str to int
        Page (``book/ch1_counterweights.html`` ...) to bytes.
    """
    import functools
    import http.server
    import threading

    from playwright.sync_api import sync_playwright

    class Quiet(http.server.SimpleHTTPRequestHandler):
        def log_message(self, *args):
            pass

    httpd = http.server.ThreadingHTTPServer(("127.0.0.1", 0), functools.partial(Quiet, directory=str(site)))
    threading.Thread(target=httpd.serve_forever, daemon=True).start()
    out = {}
    try:
        with sync_playwright() as p:
            browser = p.chromium.launch(executable_path=shutil.which("chromium"), args=["--headless", "--no-sandbox"])
            for page_file in sorted(p for p in (site / "book").glob("*.html") if not p.name.startswith("_")):
                rel = str(page_file.relative_to(site))
                ctx = browser.new_context()
                page = ctx.new_page()
                sizes: list[int] = []
                page.on("requestfinished", lambda r, sizes=sizes: sizes.append(
                    _served(r.url, r.sizes()["responseBodySize"], site, gzip_text)))
                page.goto(f"http://127.0.0.1:{httpd.server_address[1]}/{rel}", wait_until="networkidle")
                shown = 0 if figures else sum(len(m) for m in _FIGURE.findall(page_file.read_text(encoding="utf-8")))
                out[rel] = sum(sizes) - shown
                ctx.close()
            browser.close()
    finally:
        httpd.shutdown()
    return out


def _sizes() -> tuple[float, str, float, float]:
    files = [p for p in SITE.rglob("*") if p.is_file()]
    total = sum(p.stat().st_size for p in files) / 1e6
    pages = [p for p in files if p.suffix == ".html" and p.relative_to(SITE).parts[0] != "vendor"]
    heavy = max(pages, key=page_weight)
    shared = max(page_weight(p, shared=True) for p in pages)
    return total, str(heavy.relative_to(SITE)), page_weight(heavy) / 1e6, shared / 1e6


def weight_rows(site: Path = SITE) -> list[tuple[str, float, str, str]]:
    """Page weight per chapter (first visit, with and without its figures), the animation frames
    loaded on demand, and the site's total size (MB), from an existing build."""
    rows = []
    bare, whole = first_visit_weights(site), first_visit_weights(site, figures=True)
    served = first_visit_weights(site, figures=True, gzip_text=True)
    for name in bare:
        page = name.split("/")[-1][:-5]
        rows.append((f"book: first visit of {page} (without its figures)", bare[name] / 1e6, "MB", "info"))
        rows.append((f"book: first visit of {page} (with its figures)", whole[name] / 1e6, "MB", "info"))
        rows.append((f"book: first visit of {page} (with figures, gzip as served)", served[name] / 1e6, "MB",
                     "< 1.5 MB"))
    frames = site / "_images" / "frames"
    deferred = sum(p.stat().st_size for p in frames.iterdir()) / 1e6 if frames.is_dir() else 0.0
    rows.append(("book: animation frames loaded on demand (whole site)", deferred, "MB", "info"))
    report = site / "balancelab-course.json"
    if report.is_file():
        import json

        printed = json.loads(report.read_text())
        if "bytes" in printed:
            rows.append(("book: course PDF as Chromium printed it", printed["printed_bytes"] / 1e6, "MB", "info"))
            rows.append(("book: course PDF as shipped", printed["bytes"] / 1e6, "MB", "info"))
    for part, size in site_parts(site).items():
        rows.append((f"book: site part {part}", size / 1e6, "MB", "info"))
    total = sum(p.stat().st_size for p in site.rglob("*") if p.is_file()) / 1e6
    rows.append(("book: total site size (with the course PDF)", total, "MB", "< 15 MB"))
    return rows


#: The parts of the site whose sizes the table lists (where the total goes): a name, the start of
#: the path and its end; the first that fits a file counts it.
PARTS = (("chapter pages (their inline figures and first frames)", "book/", ".html"),
         ("animation frames after the first", "_images/frames/", ""),
         ("course PDF", "", ".pdf"), ("MathJax", "vendor/mathjax/", ""), ("widget manager", "vendor/", ""),
         ("theme (scripts, styles, fonts)", "_static/", ""), ("reader notebooks", "_sources/", ""))


def site_parts(site: Path = SITE) -> dict:
    """Bytes of each part of the site (:data:`PARTS`, then "everything else")."""
    sizes = dict.fromkeys([name for name, _, _ in PARTS] + ["everything else"], 0)
    for path in site.rglob("*"):
        if path.is_file():
            rel = path.relative_to(site).as_posix()
            part = next((name for name, start, end in PARTS if rel.startswith(start) and rel.endswith(end)),
                        "everything else")
            sizes[part] += path.stat().st_size
    return sizes


def run() -> list[tuple[str, float, str, str]]:
    """Build the book cold, then rebuild after touching one chapter; measure the site."""
    if CACHE.exists():
        shutil.rmtree(CACHE)
    cold = _build("--all")
    chapter, slowest = _slowest_chapter()
    original = TOUCHED.read_text()
    try:  # a prose edit: the page is re-read, its code comes from the execution cache
        TOUCHED.write_text(original + "\n<!-- benchmark edit -->\n")
        warm = _build()
    finally:
        TOUCHED.write_text(original)
    _, page, page_mb, shared_mb = _sizes()
    visits = weight_rows()
    report = SITE / "balancelab-course.json"
    pdf = [("book: printable course (Chromium, whole course)",
            float(__import__("json").loads(report.read_text())["seconds"]), "s", "info")] if report.is_file() else []
    return visits + pdf + [
        ("book: cold full build (all notebooks executed)", cold, "s", "< 300 s"),
        (f"book: cached rebuild after editing {TOUCHED.stem}", warm, "s", "< 30 s"),
        (f"book: slowest chapter ({chapter})", slowest, "s", "info"),
        (f"book: heaviest page, HTML and images ({page})", page_mb, "MB", "< 3 MB"),
        ("book: scripts, styles and fonts every page loads", shared_mb, "MB", "info"),
    ]


if __name__ == "__main__":
    # --weights: only the page weights of the site already built (no builds, about a minute)
    for row in (weight_rows() if "--weights" in sys.argv else run()):
        print(f"{row[0]:<60} {row[1]:10.2f} {row[2]:<3} {row[3]}")
