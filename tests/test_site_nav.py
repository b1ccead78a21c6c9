"""The site's navigation works at every width, in a real browser.

The visible "☰" button (article header) must open the table of contents as a drawer below
992 px and collapse / restore the sidebar above; the visible "Contents" button must open the
page's contents below 1200 px. A chapter link clicked in the drawer or sidebar must load that
chapter, and no page may log a console error.

Tests an existing ``_build/html`` (``tests/test_book.py``, which sorts first, builds it once per
session; ``python scripts/build_book.py`` builds it by hand) and skips when there is none. Needs
Debian's ``chromium``, driven through Python playwright.
"""
from __future__ import annotations

import re
import subprocess
import sys
import time
import urllib.request
from pathlib import Path

import pytest

from conftest import CHROMIUM, CHROMIUM_ARGS, NEEDS_CHROMIUM, free_port

ROOT = Path(__file__).resolve().parents[1]
SITE = ROOT / "_build" / "html"
SHOTS = ROOT / "_build" / "screenshots"
START = "book/ch1_counterweights.html"   # the page the reader is on
TARGET = "book/ch5_fourbar.html"         # the chapter picked in the table of contents
TIMEOUT_MS = 15_000

pytestmark = [
    pytest.mark.slow,
    pytest.mark.browser,
    NEEDS_CHROMIUM,
]


def _title(rel: str) -> str:
    """The ``<title>`` of a built page, as the browser shows it."""
    import html

    match = re.search(r"<title>(.*?)</title>", (SITE / rel).read_text(encoding="utf-8"), re.S)
    assert match, f"{rel} has no <title>"
    return html.unescape(match.group(1)).strip()


@pytest.fixture(scope="module")
def site() -> Path:
    if not (SITE / "index.html").is_file():
        pytest.skip("no built site in _build/html: run tests/test_book.py first (it builds the book) "
                    "or `python scripts/build_book.py`")
    for rel in (START, TARGET):
        assert (SITE / rel).is_file(), f"the built site has no {rel}"
    return SITE


@pytest.fixture(scope="module")
def server(site):
    port = free_port()
    proc = subprocess.Popen([sys.executable, "-m", "http.server", str(port), "--bind", "127.0.0.1",
                             "--directory", str(site)],
                            stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    url = f"http://127.0.0.1:{port}/"
    try:
        deadline = time.monotonic() + 30
        while True:
            try:
                with urllib.request.urlopen(url + START, timeout=2) as r:
                    assert r.status == 200
                break
            except OSError:
                if proc.poll() is not None or time.monotonic() > deadline:
                    pytest.fail(f"python -m http.server did not answer on {url}")
                time.sleep(0.2)
        yield url
    finally:
        proc.terminate()
        proc.wait(timeout=10)


@pytest.fixture(scope="module")
def browser():
    sync_api = pytest.importorskip("playwright.sync_api")
    with sync_api.sync_playwright() as p:
        b = p.chromium.launch(executable_path=CHROMIUM, args=CHROMIUM_ARGS)
        yield b
        b.close()


@pytest.fixture
def open_page(browser, server):
    """Open :data:`START` at a width; yield ``(page, errors)`` and check no console error at the end."""
    contexts, logs = [], []

    def _open(width: int):
        ctx = browser.new_context(viewport={"width": width, "height": 800})
        contexts.append(ctx)
        page = ctx.new_page()
        page.set_default_timeout(TIMEOUT_MS)
        errors: list[str] = []
        logs.append((width, errors))
        page.on("console", lambda m: errors.append(f"console: {m.text} {m.location.get('url', '')}")
                if m.type == "error" else None)
        page.on("pageerror", lambda e: errors.append(f"uncaught: {e}"))
        page.on("response", lambda r: errors.append(f"{r.status} {r.url}") if r.status >= 400 else None)
        page.goto(server + START, wait_until="load")
        return page

    yield _open
    for ctx in contexts:
        ctx.close()
    for width, errors in logs:
        assert not errors, f"at {width} px: " + "\n".join(errors)


def _visible_button(page, kind: str):
    """The one visible ``.primary-toggle`` / ``.secondary-toggle`` (the themes render hidden copies)."""
    buttons = page.locator(f"button.{kind}").filter(visible=True)
    assert buttons.count() == 1, f"{buttons.count()} visible .{kind} buttons"
    return buttons


def _follow_chapter_link(page, container) -> None:
    from playwright.sync_api import expect

    link = container.locator(f'a[href$="{TARGET.split("/")[-1]}"]').first
    expect(link).to_be_visible()
    box = link.bounding_box()
    width = page.viewport_size["width"]
    assert box is not None and 0 <= box["x"] and box["x"] + box["width"] <= width, \
        f"the chapter link is off screen: {box}"
    link.click()
    expect(page).to_have_title(_title(TARGET))
    assert page.url.endswith(TARGET)


@pytest.mark.parametrize("width", [390, 900])
def test_menu_button_opens_the_table_of_contents_as_a_drawer(open_page, width):
    from playwright.sync_api import expect

    page = open_page(width)
    sidebar = page.locator("#pst-primary-sidebar")
    drawer = page.locator("#pst-primary-sidebar-modal")
    expect(sidebar).to_be_hidden()
    expect(drawer).to_be_hidden()
    _visible_button(page, "primary-toggle").click()
    expect(drawer).to_be_visible()
    expect(drawer.locator("nav.bd-docs-nav")).to_be_visible()
    SHOTS.mkdir(parents=True, exist_ok=True)
    page.screenshot(path=str(SHOTS / f"nav_drawer_{width}.png"))
    _follow_chapter_link(page, drawer)


def test_menu_button_collapses_and_restores_the_sidebar_on_a_desktop(open_page):
    from playwright.sync_api import expect

    page = open_page(1280)
    sidebar = page.locator("#pst-primary-sidebar")
    expect(sidebar).to_be_visible()
    button = _visible_button(page, "primary-toggle")
    button.click()
    expect(sidebar).to_be_hidden()
    expect(page.locator("#pst-primary-sidebar-modal")).to_be_hidden()   # no drawer on a desktop
    button.click()
    expect(sidebar).to_be_visible()
    _follow_chapter_link(page, sidebar)


def test_contents_button_opens_the_page_contents_on_a_phone(open_page):
    from playwright.sync_api import expect

    page = open_page(390)
    drawer = page.locator("#pst-secondary-sidebar-modal")
    expect(drawer).to_be_hidden()
    _visible_button(page, "secondary-toggle").click()
    expect(drawer).to_be_visible()
    link = drawer.locator("a.nav-link[href^='#']").first
    expect(link).to_be_visible()
    anchor = link.get_attribute("href")
    link.click()
    page.wait_for_url(re.compile(re.escape(START) + re.escape(anchor) + "$"))


@pytest.mark.parametrize("width", [390, 1280])
def test_every_click_of_the_theme_button_switches_light_and_dark(open_page, width):
    from playwright.sync_api import expect

    page = open_page(width)
    root = page.locator("html")
    first = root.get_attribute("data-theme")
    assert first in ("light", "dark")
    other = "dark" if first == "light" else "light"
    button = page.locator(".theme-switch-button").filter(visible=True).first
    for want in (other, first, other):
        button.click()
        expect(root).to_have_attribute("data-theme", want)


def test_search_excerpts_quote_the_text_not_the_buttons(browser, server):
    from playwright.sync_api import expect

    ctx = browser.new_context(viewport={"width": 1280, "height": 800})
    try:
        page = ctx.new_page()
        page.set_default_timeout(TIMEOUT_MS)
        page.goto(server + "search.html?q=pulley", wait_until="load")
        excerpts = page.locator("#search-results li p.context")
        expect(excerpts.first).to_be_visible()
        # the excerpts arrive one page fetch at a time: wait until the search has finished and
        # every result has its excerpt (a result still loading would read as an empty one)
        expect(page.locator("#search-results p.search-summary")).to_contain_text("finished")
        try:
            page.wait_for_function(
                "() => { const li = [...document.querySelectorAll('#search-results li')];"
                " return li.length > 0 && li.every(x => { const p = x.querySelector('p.context');"
                " return p && p.textContent.trim().length > 0; }); }")
        except Exception:   # noqa: BLE001 - an excerpt that never comes is reported just below
            pass
        results = page.locator("#search-results li").evaluate_all(
            "items => items.map(li => [li.querySelector('a').getAttribute('href'), "
            "(li.querySelector('p.context') || {}).textContent || ''])")
        assert results, "no search results for 'pulley'"
        assert any("pulley" in text.lower() for _, text in results), results
        for href, text in results:
            assert len(text) > 80, f"{href}: an excerpt with no text of the page: {text!r}"
            if "labs" in href:   # the labs page's own text names Binder and Colab
                continue
            for chrome in ("Binder", "Colab", ".ipynb", "Print to PDF"):
                assert chrome not in text, f"{href}: the excerpt quotes the page's buttons: {text[:120]}"
    finally:
        ctx.close()


def test_search_excerpts_read_as_text_without_tex_or_code(browser, server):
    from playwright.sync_api import expect

    ctx = browser.new_context(viewport={"width": 1280, "height": 800})
    try:
        page = ctx.new_page()
        page.set_default_timeout(TIMEOUT_MS)
        page.goto(server + "search.html?q=theta", wait_until="load")
        expect(page.locator("#search-results p.search-summary")).to_contain_text("finished")
        page.wait_for_function(
            "() => { const li = [...document.querySelectorAll('#search-results li')];"
            " return li.length > 0 && li.every(x => x.querySelector('p.context')); }")
        texts = page.locator("#search-results li p.context").all_text_contents()
        assert texts, "no search results for 'theta'"
        for text in texts:
            assert not re.search(r"\\[a-zA-Z]{2,}|\\[()\[\]]|\$", text), f"TeX in an excerpt: {text[:160]}"
            assert "import balancelab" not in text and "bl.catalog()" not in text, f"code in an excerpt: {text[:160]}"
    finally:
        ctx.close()


def test_clicking_a_solution_title_opens_it_without_an_error(open_page):
    from playwright.sync_api import expect

    page = open_page(1280)
    solution = page.locator("div.solution.dropdown").first
    body = solution.locator("section, div.solution-content, .admonition-title ~ *").first
    expect(body).to_be_hidden()
    solution.locator(".admonition-title a").first.click()
    expect(body).to_be_visible()
    assert page.url.endswith(START), f"the click left the page: {page.url}"


#: The colours a reader sees on a page: the page's background and text, every figure and
#: animation frame (its filter and the background it sits on) and every text output's text on
#: its background (the first ancestor that paints one).
COLOURS = """
() => {
  const rgb = s => (s.match(/[\\d.]+/g) || []).map(Number);
  const ground = e => {
    for (let a = e; a; a = a.parentElement) {
      const c = rgb(getComputedStyle(a).backgroundColor);
      if (c.length === 3 || (c.length === 4 && c[3] > 0.5)) return c.slice(0, 3);
    }
    return [255, 255, 255];
  };
  const main = document.querySelector("main");
  const pictures = Array.from(main.querySelectorAll(".bl-figure img, div.animation img")).map(i => ({
    filter: getComputedStyle(i).filter, opacity: +getComputedStyle(i).opacity, ground: ground(i)}));
  const outputs = Array.from(main.querySelectorAll(".cell_output pre, .cell_output .text_html p"))
    .filter(e => e.textContent.trim()).map(e => ({text: e.textContent.trim().slice(0, 40),
      colour: rgb(getComputedStyle(e).color), ground: ground(e)}));
  return {theme: document.documentElement.dataset.theme, stored: localStorage.getItem("mode"),
          page: ground(document.body), text: rgb(getComputedStyle(main).color), pictures, outputs};
}
"""


@pytest.mark.parametrize("scheme", ["light", "dark"])
def test_a_first_visit_follows_the_systems_colour_scheme(browser, server, scheme):
    """No choice made yet: the page takes the system's colour scheme, and in dark mode its
    figures and animation frames stay white cards, undimmed, and every printed output stays
    readable (WCAG AA contrast 4.5:1)."""
    from test_a11y import _contrast

    ctx = browser.new_context(color_scheme=scheme, viewport={"width": 1280, "height": 900})
    page = ctx.new_page()
    page.goto(server + "book/ch2_zfl_springs.html", wait_until="load")
    c = page.evaluate(COLOURS)
    ctx.close()
    assert c["stored"] in (None, "auto") and c["theme"] == scheme, (c["stored"], c["theme"])
    dark = sum(c["page"]) / 3 < 60
    assert dark == (scheme == "dark"), f"the page's background {c['page']} in {scheme} mode"
    assert _contrast(c["text"], c["page"]) >= 4.5
    assert len(c["pictures"]) >= 3 and len(c["outputs"]) >= 3, c
    for pic in c["pictures"]:
        assert pic["filter"] == "none" and pic["opacity"] == 1, pic
        assert pic["ground"] == [255, 255, 255], pic      # drawn on white, shown on white
    for out in c["outputs"]:
        assert _contrast(out["colour"], out["ground"]) >= 4.5, out
