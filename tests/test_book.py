"""The course book: it builds with every chapter executed and warnings as errors, fails when a
cell raises or a reference is broken, and works offline in a real browser.

Slow: the module builds the whole site once (forced execution). Set
``BALANCELAB_BOOK_PREBUILT=1`` to test an existing ``_build/html`` instead (for working on the
tests themselves). The browser part needs Debian's ``chromium`` (installed by
``scripts/setup_extras.sh``) and drives it through Python playwright.
"""
from __future__ import annotations

import functools
import http.server
import os
import re
import shutil
import subprocess
import sys
import threading
from pathlib import Path
from urllib.parse import unquote, urljoin, urlsplit

import pytest
import yaml

from conftest import build_mini_book

ROOT = Path(__file__).resolve().parents[1]
SITE = ROOT / "_build" / "html"
SHOTS = ROOT / "_build" / "screenshots"
pytestmark = pytest.mark.slow

CHAPTERS = ["intro", "notation", "ch1_counterweights", "ch2_zfl_springs", "ch3_building_zfl",
            "ch4_serial", "ch5_fourbar", "ch6_scissors_peaucellier", "ch7_your_own_linkage",
            "ch8_ideal_to_real", "labs", "notes_on_sources", "references"]
NOTEBOOKS = [c for c in CHAPTERS if c.startswith("ch")] + ["labs"]
REMOTE = re.compile(r"""<(?:script|img|iframe|link)\b[^>]*?\b(?:src|href)\s*=\s*["'](?:https?:)?//[^"']*""",
                    re.IGNORECASE)


def _toc_files() -> list[str]:
    toc = yaml.safe_load((ROOT / "_toc.yml").read_text())
    files = [toc["root"]]
    for part in toc.get("parts", []):
        files += [c["file"] for c in part.get("chapters", [])]
    return files


@pytest.fixture(scope="module")
def site() -> Path:
    """The site, built with every notebook re-executed and warnings as errors."""
    if os.environ.get("BALANCELAB_BOOK_PREBUILT") == "1" and (SITE / "index.html").is_file():
        return SITE
    r = subprocess.run([sys.executable, "scripts/build_book.py", "--force", "--quiet"], cwd=ROOT,
                       capture_output=True, text=True, timeout=1800)
    assert r.returncode == 0, f"book build failed:\n{r.stdout[-6000:]}\n{r.stderr[-6000:]}"
    return SITE


# --------------------------------------------------------------------------- the build
def test_toc_lists_every_chapter_in_order():
    files = _toc_files()
    assert [f.split("/")[-1] for f in files] == CHAPTERS
    for f in files:
        assert (ROOT / f"{f}.md").is_file(), f"{f}.md is in _toc.yml but missing"


def test_config_is_offline_and_strict():
    cfg = yaml.safe_load((ROOT / "_config.yml").read_text())
    assert cfg["only_build_toc_files"] is True
    assert cfg["execute"]["execute_notebooks"] == "cache"
    assert cfg["execute"]["allow_errors"] is False
    sc = cfg["sphinx"]["config"]
    assert not re.match(r"https?://", sc["mathjax_path"])
    assert all(not re.match(r"https?://", k) for k in sc["nb_ipywidgets_js"])
    assert "book/_vendor" in sc["html_extra_path"]
    assert {"sphinx_exercise", "sphinx_proof", "sphinx_togglebutton"} <= set(cfg["sphinx"]["extra_extensions"])
    for nb in NOTEBOOKS:
        head = (ROOT / "book" / f"{nb}.md").read_text().split("---")[1]
        meta = yaml.safe_load(head)
        assert meta["kernelspec"]["name"] == "python3", nb
        assert meta["jupytext"]["text_representation"]["format_name"] == "myst", nb


def test_site_has_every_page_and_its_notebook(site):
    for name in CHAPTERS:
        assert (site / "book" / f"{name}.html").is_file(), name
    for nb in NOTEBOOKS:
        assert (site / "_sources" / "book" / f"{nb}.ipynb").is_file(), f"no .ipynb download for {nb}"
    assert (site / "vendor" / "mathjax" / "tex-chtml.js").is_file()
    assert (site / "vendor" / "requirejs" / "require.js").is_file()
    assert (site / "vendor" / "html-manager" / "embed-amd.js").is_file()


def test_no_page_loads_anything_from_another_host(site):
    offenders = {}
    for page in site.rglob("*.html"):
        if page.relative_to(site).parts[0] in ("vendor", "_static"):
            continue
        hits = [m.group(0) for m in REMOTE.finditer(page.read_text(errors="replace"))
                if not re.search(r'rel="(canonical|alternate)"', m.group(0))]
        if hits:
            offenders[str(page.relative_to(site))] = hits[:3]
    assert not offenders, offenders


def test_chapters_have_exercises_with_executed_solutions(site):
    for ch in ("ch1_counterweights", "ch2_zfl_springs", "ch3_building_zfl"):
        html = (site / "book" / f"{ch}.html").read_text()
        n_ex = html.count('class="exercise admonition"')
        assert 2 <= n_ex <= 4, (ch, n_ex)
        assert html.count("solution") >= n_ex
        assert 'class="tip admonition' in html or "Learning objectives" in html, ch
        assert "Learning objectives" in html
        assert html.count('<div class="animation">') >= 1, ch
        assert re.search(r'<figure[^>]*id="fig-', html), f"{ch}: no numbered figure"


def test_a_cell_that_raises_fails_the_build(tmp_path):
    r = build_mini_book(tmp_path, """
        # Page

        ```{code-cell} ipython3
        raise RuntimeError("a broken chapter")
        ```
        """)
    assert r.returncode != 0
    out = r.stdout + r.stderr
    assert "a broken chapter" in out


def test_a_broken_reference_fails_the_build(tmp_path):
    r = build_mini_book(tmp_path, """
        # Page

        See {numref}`fig-that-does-not-exist`.

        ```{code-cell} ipython3
        1 + 1
        ```
        """)
    assert r.returncode != 0
    assert "fig-that-does-not-exist" in r.stdout + r.stderr


# -------------------------------------------------------------------------- the browser
class _Quiet(http.server.SimpleHTTPRequestHandler):
    def log_message(self, *args):  # keep the test output readable
        pass


@pytest.fixture(scope="module")
def server(site):
    handler = functools.partial(_Quiet, directory=str(site))
    httpd = http.server.ThreadingHTTPServer(("127.0.0.1", 0), handler)
    thread = threading.Thread(target=httpd.serve_forever, daemon=True)
    thread.start()
    yield f"http://127.0.0.1:{httpd.server_address[1]}/"
    httpd.shutdown()
    httpd.server_close()


@pytest.fixture(scope="module")
def browser():
    exe = shutil.which("chromium")
    if exe is None:
        pytest.skip("Debian chromium is not installed (bash scripts/setup_extras.sh installs it)")
    sync_api = pytest.importorskip("playwright.sync_api")
    with sync_api.sync_playwright() as p:
        b = p.chromium.launch(executable_path=exe, args=["--headless", "--no-sandbox", "--disable-gpu",
                                                          "--disable-background-networking"])
        yield b
        b.close()


def _pages(site: Path) -> list[str]:
    return sorted(str(p.relative_to(site)) for p in site.rglob("*.html")
                  if p.relative_to(site).parts[0] not in ("vendor", "_static", "_sources"))


_IDS: dict = {}


def _ids(path: Path) -> set:
    if path not in _IDS:
        _IDS[path] = set(re.findall(r'\sid="([^"]+)"', path.read_text(errors="replace")))
    return _IDS[path]


PAGE_CHECKS = """
async () => {
  if (window.MathJax && MathJax.startup && MathJax.startup.promise) { await MathJax.startup.promise; }
  const main = document.querySelector("main") || document.body;
  const maths = Array.from(main.querySelectorAll(".math"));
  const unrendered = maths.filter(e => !e.querySelector("mjx-container")).map(e => e.textContent.slice(0, 80));
  const errors = Array.from(main.querySelectorAll("mjx-merror")).map(e => e.textContent.slice(0, 80));
  const clone = main.cloneNode(true);
  clone.querySelectorAll("pre, code, script, style, .highlight").forEach(e => e.remove());
  const raw = (clone.textContent.match(/\\$\\$|\\\\\\[|\\\\begin\\{/g) || []).length;
  const imgs = Array.from(document.images);
  const broken = imgs.filter(i => !(i.complete && i.naturalWidth > 0)).map(i => i.id || i.src.slice(0, 80));
  const noalt = imgs.filter(i => !(i.getAttribute("alt") || "").trim()).map(i => i.id || i.src.slice(0, 80));
  const heads = Array.from(main.querySelectorAll("h1, h2, h3, h4, h5, h6")).map(h => +h.tagName[1]);
  const figures = Array.from(main.querySelectorAll("figure img")).filter(i => !(i.alt || "").trim()).length;
  const links = Array.from(document.querySelectorAll("a[href]")).map(a => a.href);
  return {maths: maths.length, unrendered, errors, raw, broken, noalt, heads, figures, links,
          animations: document.querySelectorAll("div.animation").length};
}
"""


def test_every_page_in_a_browser(site, server, browser):
    SHOTS.mkdir(parents=True, exist_ok=True)
    problems: list[str] = []
    pages = _pages(site)
    assert len(pages) >= len(CHAPTERS)
    ctx = browser.new_context(viewport={"width": 1280, "height": 900})
    external: list[str] = []

    def route(r):
        host = urlsplit(r.request.url).hostname
        if r.request.url.startswith(("data:", "blob:")) or host == "127.0.0.1":
            r.continue_()
        else:
            external.append(r.request.url)
            r.abort()

    ctx.route("**/*", route)
    n_anim = 0
    for rel in pages:
        page = ctx.new_page()
        console: list[str] = []
        bad: list[str] = []
        page.on("console", lambda m: console.append(m.text) if m.type == "error" else None)
        page.on("pageerror", lambda e: console.append(f"uncaught: {e}"))
        page.on("response", lambda r: bad.append(f"{r.status} {r.url}") if r.status >= 400 else None)
        url = urljoin(server, rel)
        resp = page.goto(url, wait_until="load")
        where = rel
        if resp is None or resp.status != 200:
            problems.append(f"{where}: status {resp and resp.status}")
            continue
        redirect = re.search(r'http-equiv="Refresh" content="0; url=([^"]+)"', (site / rel).read_text())
        if redirect:  # a redirect-only page (the site's index): check its target, then move on
            target = urljoin(url, redirect.group(1))
            page.wait_for_url(target, timeout=10000)
            page.wait_for_load_state("load")
            if not (site / urljoin(rel, redirect.group(1))).is_file():
                problems.append(f"{where}: redirects to a missing page {redirect.group(1)}")
            continue
        page.wait_for_timeout(300)
        res = page.evaluate(PAGE_CHECKS)
        for key in ("unrendered", "errors", "broken", "noalt"):
            if res[key]:
                problems.append(f"{where}: {key}: {res[key][:5]}")
        if res["raw"]:
            problems.append(f"{where}: {res['raw']} raw TeX delimiters left in the text")
        if res["figures"]:
            problems.append(f"{where}: {res['figures']} figures without alt text")
        heads = res["heads"]
        if heads and heads[0] != 1:
            problems.append(f"{where}: first heading is h{heads[0]}")
        for a, b in zip(heads, heads[1:]):
            if b > a + 1:
                problems.append(f"{where}: heading jumps from h{a} to h{b}")
                break
        for href in res["links"]:
            parts = urlsplit(href)
            if parts.hostname != "127.0.0.1" or parts.scheme not in ("http", "https"):
                continue
            target = site / unquote(parts.path.lstrip("/"))
            if target.is_dir():
                target = target / "index.html"
            if not target.is_file():
                problems.append(f"{where}: dead link {href}")
            elif parts.fragment and target.suffix == ".html" and unquote(parts.fragment) not in _ids(target):
                problems.append(f"{where}: dead anchor {href}")
        # every animation is there and advances when played
        for i in range(res["animations"]):
            anim = page.locator("div.animation").nth(i)
            anim.scroll_into_view_if_needed()
            slider = anim.locator("input[type=range]")
            seen = {slider.input_value()}
            anim.locator("button[title=Play]").click()
            for _ in range(12):  # sample the frame counter while it plays (loops may wrap around)
                page.wait_for_timeout(70)
                seen.add(slider.input_value())
            anim.locator("button[title=Pause]").click()
            n_anim += 1
            if len(seen) < 2:
                problems.append(f"{where}: animation {i} did not advance when played")
            if int(slider.get_attribute("max") or 0) < 2:
                problems.append(f"{where}: animation {i} has fewer than 3 frames")
        page.screenshot(path=str(SHOTS / (rel.replace("/", "__")[:-5] + ".png")), full_page=True)
        problems += [f"{where}: console error: {c}" for c in console]
        problems += [f"{where}: failed request: {b}" for b in bad]
        page.close()
    ctx.close()
    assert not external, f"requests to other hosts: {sorted(set(external))[:10]}"
    assert not problems, "\n".join(problems)
    assert n_anim >= 3, f"only {n_anim} animations in the whole site"


WIDGET_PAGE = """<!DOCTYPE html>
<html lang="en"><head><meta charset="utf-8"><title>widgets offline</title>
<script>window.MathJax = {{tex: {{inlineMath: [["$", "$"], ["\\\\(", "\\\\)"]]}}}};</script>
<script defer src="vendor/mathjax/tex-chtml.js"></script>
{scripts}
<script type="application/vnd.jupyter.widget-state+json">{state}</script>
</head><body><main><h1>widgets</h1>
<script type="application/vnd.jupyter.widget-view+json">{view}</script>
</main></body></html>
"""


def test_vendored_widget_manager_renders_math_offline(site, browser, tmp_path):
    """The page set-up myst-nb writes for a page with widget state, with the vendored files:
    the HTML manager renders an HTMLMath widget beside MathJax 3, without console errors
    and without asking any other host (the MathJax 2 shim at work)."""
    import json

    ipywidgets_embed = pytest.importorskip("ipywidgets.embed")
    import ipywidgets

    data = ipywidgets_embed.embed_data(views=[ipywidgets.HTMLMath(value=r"energy $V = \frac{1}{2} k a^2$")])
    cfg = yaml.safe_load((ROOT / "_config.yml").read_text())
    scripts = "\n".join(f'<script src="{path.replace("../", "")}"></script>'
                        for path in cfg["sphinx"]["config"]["nb_ipywidgets_js"])
    (tmp_path / "vendor").symlink_to(site / "vendor", target_is_directory=True)
    (tmp_path / "widgets.html").write_text(WIDGET_PAGE.format(
        scripts=scripts, state=json.dumps(data["manager_state"]), view=json.dumps(data["view_specs"][0])))
    handler = functools.partial(_Quiet, directory=str(tmp_path))
    httpd = http.server.ThreadingHTTPServer(("127.0.0.1", 0), handler)
    threading.Thread(target=httpd.serve_forever, daemon=True).start()
    try:
        ctx = browser.new_context()
        external, console, failed = [], [], []

        def route(r):
            if urlsplit(r.request.url).hostname == "127.0.0.1" or r.request.url.startswith("data:"):
                r.continue_()
            else:
                external.append(r.request.url)
                r.abort()

        ctx.route("**/*", route)
        page = ctx.new_page()
        page.on("console", lambda m: console.append(m.text) if m.type == "error" else None)
        page.on("pageerror", lambda e: console.append(f"uncaught: {e}"))
        page.on("response", lambda r: failed.append(f"{r.status} {r.url}") if r.status >= 400 else None)
        page.goto(f"http://127.0.0.1:{httpd.server_address[1]}/widgets.html", wait_until="load")
        page.wait_for_selector(".widget-htmlmath", timeout=20000)
        page.wait_for_selector(".widget-htmlmath mjx-container", timeout=20000)
        ctx.close()
    finally:
        httpd.shutdown()
        httpd.server_close()
    assert not external, external
    assert not console, console
    assert not failed, failed
