"""Benchmarks of the site's accessibility: what MathJax's assistive MathML costs.

MathJax puts a hidden MathML copy (``<mjx-assistive-mml>``) beside every formula it draws, which
screen readers read out; the site keeps it (see book/accessibility.md). Rows (name, value, unit,
target), measured in headless Chromium on the built ``_build/html``:

* the time MathJax takes to typeset the page with the most formulas, with assistive MathML and
  without (median of three loads): for information, the difference is its cost (on a loaded
  machine it is within the noise of a few hundred ms);
* the size of the MathML it adds to that page's DOM: for information;
* the size of MathJax's assistive-MathML component (inside ``tex-chtml.js``, not a separate
  download): for information.

Needs a built site (``python scripts/build_book.py``) and Debian's chromium.
"""
from __future__ import annotations

import functools
import http.server
import re
import shutil
import statistics
import threading
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
SITE = ROOT / "_build" / "html"
RUNS = 3

#: wraps the page's own MathJax configuration: times the first typeset, optionally without
#: assistive MathML (MathJax 3's ``options.enableAssistiveMml``)
INIT = """(() => {
  const off = %s;
  let cfg;
  Object.defineProperty(window, "MathJax", {configurable: true, get() { return cfg; }, set(v) {
    if (v && !v.startup?.document && !window.__blWrapped) {
      window.__blWrapped = true;
      v.options = Object.assign({}, v.options || {}, off ? {enableAssistiveMml: false} : {});
      v.startup = Object.assign({}, v.startup || {}, {pageReady() {
        const t0 = performance.now();
        return MathJax.startup.defaultPageReady().then(() => { window.__blTypeset = performance.now() - t0; });
      }});
    }
    cfg = v;
  }});
})();"""


class _Quiet(http.server.SimpleHTTPRequestHandler):
    def log_message(self, *args):
        pass


def _maths_page() -> str:
    pages = [p for p in (SITE / "book").glob("*.html")]
    return max(pages, key=lambda p: len(re.findall(r'class="math', p.read_text(errors="replace")))).name


def _measure(browser, url: str, off: bool) -> tuple[float, int, int]:
    page = browser.new_page(viewport={"width": 1280, "height": 900})
    page.add_init_script(INIT % ("true" if off else "false"))
    page.goto(url, wait_until="load")
    page.wait_for_function("() => window.__blTypeset !== undefined", timeout=60_000)
    t, n, size = page.evaluate("""() => [window.__blTypeset, document.querySelectorAll("mjx-container").length,
        Array.from(document.querySelectorAll("mjx-assistive-mml")).reduce((s, e) => s + e.outerHTML.length, 0)]""")
    page.close()
    return t, n, size


def run() -> list[tuple[str, float, str, str]]:
    from playwright.sync_api import sync_playwright

    if not (SITE / "index.html").is_file():
        raise RuntimeError("no built site in _build/html: run `python scripts/build_book.py` first")
    name = _maths_page()
    httpd = http.server.ThreadingHTTPServer(("127.0.0.1", 0), functools.partial(_Quiet, directory=str(SITE)))
    threading.Thread(target=httpd.serve_forever, daemon=True).start()
    url = f"http://127.0.0.1:{httpd.server_address[1]}/book/{name}"
    try:
        with sync_playwright() as p:
            browser = p.chromium.launch(executable_path=shutil.which("chromium"),
                                        args=["--headless", "--no-sandbox", "--disable-gpu"])
            on = [_measure(browser, url, False) for _ in range(RUNS)]
            off = [_measure(browser, url, True) for _ in range(RUNS)]
            browser.close()
    finally:
        httpd.shutdown()
        httpd.server_close()
    if any(r[2] for r in off) or not all(r[2] for r in on):
        raise RuntimeError("enableAssistiveMml did not switch MathJax's assistive MathML on and off")
    t_on, t_off = statistics.median(r[0] for r in on), statistics.median(r[0] for r in off)
    formulas, added = on[0][1], on[0][2]
    component = (SITE / "vendor" / "mathjax" / "a11y" / "assistive-mml.js")
    rows = [
        (f"MathJax typeset of {name} ({formulas} formulas), assistive MathML on", t_on, "ms", "for information"),
        (f"MathJax typeset of {name}, assistive MathML off", t_off, "ms", "for information"),
        ("assistive MathML: its share of that typeset time", t_on - t_off, "ms", "for information"),
        (f"assistive MathML added to {name}'s DOM", added / 1024, "KiB", "for information"),
    ]
    if component.is_file():
        rows.append(("assistive MathML component (inside tex-chtml.js)", component.stat().st_size / 1024, "KiB",
                     "for information"))
    return rows
