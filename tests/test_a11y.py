"""Accessibility of the built site: WCAG 2.0/2.1 A and AA by axe-core, and a keyboard-only player.

* axe-core (vendored from the npm registry into the git-ignored ``tests/_vendor/axe-core/`` by
  ``scripts/build_book.py``, see :func:`build_book.fetch_axe`) runs in Chromium on every page of
  ``_build/html`` at 390 px and 1280 px, in the theme's light and dark colour modes, with the
  tags ``wcag2a``, ``wcag2aa``, ``wcag21a`` and ``wcag21aa``; any violation fails the test, which
  prints the rule, the element, the page and the mode. The per-rule counts are written to
  ``_build/a11y/axe_<mode>_<width>.json``. On the same pages every formula must carry MathJax's
  assistive MathML (what a screen reader reads).
* Formulas are not tab stops (chapter 2: Tab never lands on an inline formula), and each panel of
  a figure made of several panels has its own alt text, which never points at another panel by
  its place (the panels stack on a phone).
* An animation player is walked through with the keyboard alone: tab to its slider, scrub with
  the arrow keys, Home and End, step with the "Next frame" button, play and pause; the slider's
  spoken value and the live region say which frame and configuration are shown.
* With ``prefers-reduced-motion: reduce`` nothing moves by itself and nothing transitions.

Tests an existing ``_build/html``; ``tests/conftest.py`` runs this module after
``tests/test_book.py`` (which builds the site). Needs Debian's ``chromium`` and npm.
"""
from __future__ import annotations

import functools
import http.server
import json
import re
import sys
import threading
from collections import Counter
from html.parser import HTMLParser
from pathlib import Path
from urllib.parse import urljoin

import pytest

from conftest import CHROMIUM, CHROMIUM_ARGS, NEEDS_CHROMIUM

ROOT = Path(__file__).resolve().parents[1]
SITE = ROOT / "_build" / "html"
REPORTS = ROOT / "_build" / "a11y"
PLAYER_PAGE = "book/ch2_zfl_springs.html"   # a chapter with an animation of one coordinate θ
TAGS = ["wcag2a", "wcag2aa", "wcag21a", "wcag21aa"]

pytestmark = [pytest.mark.slow, pytest.mark.browser, NEEDS_CHROMIUM]

AXE_RUN = """async (tags) => {
  if (window.MathJax && MathJax.startup && MathJax.startup.promise) { await MathJax.startup.promise; }
  const r = await axe.run(document, {runOnly: {type: "tag", values: tags}, resultTypes: ["violations"]});
  return r.violations.map(v => ({id: v.id, impact: v.impact,
    nodes: v.nodes.map(n => ({target: n.target.join(" "), html: n.html.slice(0, 160),
                              why: (n.failureSummary || "").replace(/\\s+/g, " ").slice(0, 220)}))}));
}"""


@pytest.fixture(scope="module")
def axe_js() -> Path:
    sys.path.insert(0, str(ROOT / "scripts"))
    try:
        import build_book
    finally:
        sys.path.pop(0)
    return build_book.fetch_axe()


@pytest.fixture(scope="module")
def site() -> Path:
    if not (SITE / "index.html").is_file():
        pytest.skip("no built site in _build/html: run tests/test_book.py first (it builds the book) "
                    "or `python scripts/build_book.py`")
    return SITE


class _Quiet(http.server.SimpleHTTPRequestHandler):
    def log_message(self, *args):
        pass


@pytest.fixture(scope="module")
def server(site):
    httpd = http.server.ThreadingHTTPServer(("127.0.0.1", 0), functools.partial(_Quiet, directory=str(site)))
    threading.Thread(target=httpd.serve_forever, daemon=True).start()
    yield f"http://127.0.0.1:{httpd.server_address[1]}/"
    httpd.shutdown()
    httpd.server_close()


@pytest.fixture(scope="module")
def browser():
    from playwright.sync_api import sync_playwright

    with sync_playwright() as p:
        b = p.chromium.launch(executable_path=CHROMIUM, args=CHROMIUM_ARGS)
        yield b
        b.close()


def _pages(site: Path) -> list[str]:
    pages = []
    for p in sorted(site.rglob("*.html")):
        rel = p.relative_to(site)
        if rel.parts[0] in ("vendor", "_static", "_sources", "_images"):
            continue
        if re.search(r'http-equiv="Refresh" content="0;', p.read_text(errors="replace")):
            continue  # a redirect-only page (the site's index) shows nothing
        pages.append(str(rel))
    return pages


def colour_context(browser, mode: str, **options):
    """A browser context whose pages show the site in colour ``mode`` ("light" or "dark").

    Dark is what a reader gets who chose it with the theme's colour-mode button (the theme keeps
    the choice in ``localStorage``) on a system that prefers dark colours too.
    """
    if mode not in ("light", "dark"):
        raise ValueError(f"mode must be 'light' or 'dark', not {mode!r}")
    ctx = browser.new_context(color_scheme=mode, **options)
    ctx.add_init_script(f"try {{ localStorage.setItem('mode', '{mode}'); }} catch (e) {{}}")
    return ctx


@pytest.mark.parametrize("mode", ["light", "dark"])
@pytest.mark.parametrize("width", [390, 1280])
def test_axe_finds_no_wcag_21_aa_violation_on_any_page(site, server, browser, axe_js, width, mode):
    pages = _pages(site)
    assert len(pages) >= 13, pages
    ctx = colour_context(browser, mode, viewport={"width": width, "height": 900})
    found: list[str] = []
    per_rule: Counter = Counter()
    per_rule_pages: dict = {}
    for rel in pages:
        page = ctx.new_page()
        page.goto(urljoin(server, rel), wait_until="load")
        shown = page.evaluate("() => document.documentElement.dataset.theme")
        assert shown == mode, f"{rel} is shown in {shown!r} mode, not {mode!r}"
        page.add_script_tag(path=str(axe_js))
        for v in page.evaluate(AXE_RUN, TAGS):
            per_rule[v["id"]] += len(v["nodes"])
            per_rule_pages.setdefault(v["id"], set()).add(rel)
            for n in v["nodes"]:
                found.append(f"{v['id']} ({v['impact']}) on {rel} at {width} px, {mode}: {n['target']}\n"
                             f"    {n['html']}\n    {n['why']}")
        # MathJax's assistive MathML: a screen reader reads each formula from it
        bare = page.evaluate("() => document.querySelectorAll('mjx-container:not(:has(> mjx-assistive-mml))').length")
        if bare:
            found.append(f"assistive-mathml on {rel} at {width} px: {bare} formulas without MathML for screen readers")
        page.close()
    ctx.close()
    REPORTS.mkdir(parents=True, exist_ok=True)
    (REPORTS / f"axe_{mode}_{width}.json").write_text(json.dumps(
        {"axe": "axe-core " + (axe_js.parent / "VERSION.txt").read_text().strip(), "tags": TAGS, "pages": len(pages),
         "mode": mode, "rules": {k: {"elements": n, "pages": sorted(per_rule_pages[k])} for k, n in per_rule.items()},
         "violations": found},
        indent=1))
    summary = ", ".join(f"{k}: {n} elements on {len(per_rule_pages[k])} pages" for k, n in per_rule.most_common())
    assert not found, f"{len(found)} axe-core violations at {width} px in {mode} mode ({summary}):\n" + "\n".join(found[:60])


# ------------------------------------------------------------------- the animation player
STATE = """(el) => {
  const p = el.closest("div.animation");
  const s = p.querySelector("input.anim-slider");
  return {value: +s.value, text: s.getAttribute("aria-valuetext") || "", name: s.getAttribute("aria-label") || "",
          said: p.querySelector("[aria-live]").textContent, shown: p.querySelector(".bl-anim-status > span:first-child").textContent,
          max: +s.max};
}"""
FOCUSED = """() => { const e = document.activeElement;
  return e ? (e.matches("input.anim-slider") ? "slider" : (e.getAttribute("title") || e.tagName)) : ""; }"""


def _tab_to(page, what: str, limit: int, back: bool = False) -> int:
    """Press Tab (or Shift+Tab) until the focused element is ``what``; return how many presses."""
    for n in range(1, limit + 1):
        page.keyboard.press("Shift+Tab" if back else "Tab")
        if page.evaluate(FOCUSED) == what:
            return n
    pytest.fail(f"{what!r} not reached with {limit} presses of {'Shift+' if back else ''}Tab; "
                f"focus is on {page.evaluate(FOCUSED)!r}")


def _frame_text(state: dict, frame: int) -> None:
    assert state["value"] == frame, state
    assert re.fullmatch(rf"frame {frame + 1} of {state['max'] + 1}: θ = -?\d+°", state["text"]), state
    assert state["shown"] == state["text"], state


def test_animation_player_by_keyboard_alone(site, server, browser):
    ctx = browser.new_context(viewport={"width": 390, "height": 844})
    page = ctx.new_page()
    page.goto(urljoin(server, PLAYER_PAGE), wait_until="load")
    page.wait_for_function("() => document.querySelector('div.animation .bl-anim-status span') "
                           "&& /θ =/.test(document.querySelector('div.animation input.anim-slider')"
                           ".getAttribute('aria-valuetext'))")
    slider = page.locator("div.animation input.anim-slider").first
    frames = int(slider.get_attribute("max")) + 1
    # the page's first slider, reached from the top of the page with Tab alone
    _tab_to(page, "slider", 400)
    slider_handle = slider.element_handle()
    state = page.evaluate(STATE, slider_handle)
    assert state["name"] == "Frame"
    _frame_text(state, 0)
    page.keyboard.press("ArrowRight")
    page.keyboard.press("ArrowRight")
    _frame_text(page.evaluate(STATE, slider_handle), 2)
    page.keyboard.press("End")
    _frame_text(page.evaluate(STATE, slider_handle), frames - 1)
    page.keyboard.press("Home")
    _frame_text(page.evaluate(STATE, slider_handle), 0)
    # step forward with the "Next frame" button: the live region says where it is
    assert _tab_to(page, "Next frame", 10) <= 8
    page.keyboard.press("Enter")
    state = page.evaluate(STATE, slider_handle)
    _frame_text(state, 1)
    assert state["said"] == state["text"], state
    # play (Space on "Play"), then pause (Enter on "Pause"): the frame advances, then stops
    _tab_to(page, "Play", 3, back=True)
    page.keyboard.press("Space")
    page.wait_for_function("s => +s.value > 3", arg=slider_handle, timeout=10_000)
    assert page.evaluate(STATE, slider_handle)["said"] == "playing"
    _tab_to(page, "Pause", 3, back=True)
    page.keyboard.press("Enter")
    page.wait_for_function("s => s.closest('div.animation').querySelector('[aria-live]').textContent"
                           ".startsWith('paused at frame')", arg=slider_handle, timeout=5_000)
    state = page.evaluate(STATE, slider_handle)
    assert state["said"] == f"paused at {state['text']}", state
    stopped = state["value"]
    # the focused button shows where the keyboard is
    ring = page.evaluate("() => { const s = getComputedStyle(document.activeElement);"
                         " return s.outlineStyle !== 'none' && parseFloat(s.outlineWidth) > 0 || s.boxShadow !== 'none'; }")
    assert ring, "the focused player button has no visible focus indicator"
    page.keyboard.press("Tab")   # the frame stays where it was paused
    assert page.evaluate(STATE, slider_handle)["value"] == stopped
    ctx.close()


def test_player_fits_a_phone_column(site, server, browser):
    ctx = browser.new_context(viewport={"width": 390, "height": 844})
    page = ctx.new_page()
    page.goto(urljoin(server, PLAYER_PAGE), wait_until="load")
    boxes = page.evaluate("""() => Array.from(document.querySelectorAll("div.animation")).map(p => {
        const col = p.closest("article") || document.body, c = col.getBoundingClientRect();
        const s = p.querySelector("input.anim-slider").getBoundingClientRect();
        const b = Array.from(p.querySelectorAll(".anim-buttons button")).map(x => x.getBoundingClientRect());
        return {left: c.left, right: c.right, slider: [s.left, s.right],
                tops: b.map(r => Math.round(r.top)), ends: [Math.min(...b.map(r => r.left)), Math.max(...b.map(r => r.right))]};
    })""")
    assert boxes
    for i, b in enumerate(boxes):
        assert b["left"] - 0.5 <= b["slider"][0] and b["slider"][1] <= b["right"] + 0.5, (i, b)
        assert b["left"] - 0.5 <= b["ends"][0] and b["ends"][1] <= b["right"] + 0.5, (i, b)
        assert len(set(b["tops"])) == 1, f"player {i}: its buttons wrap onto {len(set(b['tops']))} lines"
    ctx.close()


def test_reduced_motion_nothing_moves_by_itself(site, server, browser):
    ctx = browser.new_context(viewport={"width": 1280, "height": 900}, reduced_motion="reduce")
    page = ctx.new_page()
    page.goto(urljoin(server, PLAYER_PAGE), wait_until="load")
    page.wait_for_function("() => Object.keys(window).some(k => /^anim[0-9a-f]{8,}/.test(k))")
    timers = page.evaluate("() => Object.keys(window).filter(k => /^anim[0-9a-f]{8,}/.test(k))"
                           ".filter(k => window[k] && window[k].timer)")
    assert timers == [], f"animations that play by themselves: {timers}"
    moving = page.evaluate("""() => Array.from(document.querySelectorAll("a, button, .bl-panel, img"))
        .map(e => getComputedStyle(e)).filter(s => s.transitionDuration.split(",").some(d => parseFloat(d) > 0.02)
            || s.animationName !== "none" && s.animationDuration.split(",").some(d => parseFloat(d) > 0.02)).length""")
    assert moving == 0, f"{moving} elements still transition or animate with reduced motion"
    ctx.close()


# ------------------------------------------------------------------- formulas and the keyboard
MATH_PAGE = "book/ch2_zfl_springs.html"   # a chapter with many inline formulas (~70 of them)
INLINE = "mjx-container:not([display='true'])"


def test_inline_formulas_are_not_tab_stops_and_stay_readable(site, server, browser):
    ctx = browser.new_context(viewport={"width": 390, "height": 844})   # some display formulas scroll
    page = ctx.new_page()
    page.goto(urljoin(server, MATH_PAGE), wait_until="load")
    page.wait_for_function("() => window.MathJax && MathJax.startup && MathJax.startup.promise")
    page.evaluate("() => MathJax.startup.promise")
    math = page.evaluate(f"""() => {{
      const inline = Array.from(document.querySelectorAll("{INLINE}"));
      const stop = e => e.tabIndex >= 0 && !e.closest("[inert]");
      return {{inline: inline.length,
              stops: inline.filter(m => stop(m) || Array.from(m.querySelectorAll("*")).some(stop)).length,
              mml: inline.filter(m => {{ const a = m.querySelector(":scope > mjx-assistive-mml");
                  return a && a.querySelector("math") && !a.closest("[aria-hidden='true']"); }}).length}};
    }}""")
    assert math["inline"] >= 30, math
    assert math["stops"] == 0, f"{math['stops']} inline formulas are tab stops"
    assert math["mml"] == math["inline"], f"formulas without MathML a screen reader reads: {math}"
    # once the fonts are in, the formulas' boxes take the focus exactly when they scroll
    page.wait_for_function("""() => document.fonts.status === "loaded" && Array.from(document.querySelectorAll(
        "mjx-container[display='true'], .math-wrapper, .bd-content span.math")).every(d =>
        (d.tabIndex >= 0) === (d.scrollWidth > d.clientWidth + 1))""", timeout=15_000)
    # from the top of the page to its end with Tab alone: the focus never lands on MathJax's
    # inline formula itself (only, on a phone, on the box around a formula too long to fit)
    seen, inside, still = [], 0, 0
    for _ in range(800):
        page.keyboard.press("Tab")
        where = page.evaluate(f"""() => {{ const e = document.activeElement;
            if (!e || e === document.body) return null;
            const box = e.closest(".bd-content span.math");
            return {{id: e.outerHTML.slice(0, 120), inline: !!e.closest("{INLINE}"),
                    still: !!box && box.scrollWidth <= box.clientWidth + 1}}; }}""")
        if where is None or (seen and where["id"] == seen[0]):
            break
        seen.append(where["id"])
        inside += where["inline"]
        still += where["still"]
    else:
        pytest.fail("Tab never came back to the start of the page in 800 presses")
    assert len(seen) > 20, seen   # the walk went through the page's links and controls
    assert inside == 0, f"Tab stopped {inside} times in an inline formula"
    # nor on the box of an inline formula that fits its line (attack A23: Chromium makes any scroll
    # container a tab stop; a box 2 px too short for its glyphs was one, silent, 66 times in ch2)
    assert still == 0, f"Tab stopped {still} times on the box of an inline formula that does not scroll"
    wide = page.evaluate("""() => Array.from(document.querySelectorAll(".bd-content span.math, mjx-container[display='true']"))
        .filter(d => d.scrollWidth > d.clientWidth + 1).length""")
    assert wide >= 1, "no formula scrolls at 390 px: the check below tests nothing"
    # and every formula that scrolls sideways can be reached (the box that scrolls takes the focus)
    unreachable = page.evaluate("""() => Array.from(document.querySelectorAll(
        "mjx-container[display='true'], .math-wrapper, .bd-content .math"))
        .filter(d => /(auto|scroll)/.test(getComputedStyle(d).overflowX) && d.scrollWidth > d.clientWidth + 1
                     && d.tabIndex < 0).map(d => d.outerHTML.slice(0, 80))""")
    assert not unreachable, f"formulas that scroll but take no focus: {unreachable}"
    ctx.close()


# ------------------------------------------------------------------- figures made of panels
class _Figures(HTMLParser):
    """The alt texts of the panel images of every ``.bl-figure`` of a page, figure by figure."""

    def __init__(self):
        super().__init__()
        self.figures: list[list[str]] = []
        self._depth = 0   # depth of <div> inside the current .bl-figure, 0 outside one

    def handle_starttag(self, tag, attrs):
        a = dict(attrs)
        if tag == "div":
            if self._depth:
                self._depth += 1
            elif "bl-figure" in (a.get("class") or "").split():
                self._depth = 1
                self.figures.append([])
        elif tag == "img" and self._depth and "bl-panel" in (a.get("class") or "").split():
            self.figures[-1].append(a.get("alt") or "")

    def handle_endtag(self, tag):
        if tag == "div" and self._depth:
            self._depth -= 1


PLACE_WORDS = re.compile(r"\b(left|right|middle)\s*[,:;]|\b(left|right|middle) (panel|drawing|plot|and (left|right))"
                         r"|\bon the (left|right)\b(?! (of|end|side of))", re.IGNORECASE)


def test_each_panel_of_a_figure_has_its_own_alt_text(site):
    figures = {}
    for page in sorted((site / "book").glob("ch*.html")):
        parser = _Figures()
        parser.feed(page.read_text(encoding="utf-8"))
        for i, alts in enumerate(parser.figures):
            if len(alts) > 1:
                figures[f"{page.name} figure {i + 1}"] = alts
    assert len(figures) >= 15, sorted(figures)   # the chapters draw many side-by-side figures
    for where, alts in figures.items():
        n = len(alts)
        assert len(set(alts)) == n, f"{where}: panels share an alt text: {alts}"
        for i, alt in enumerate(alts, start=1):
            assert alt.startswith(f"Panel {i} of {n}: "), (where, alt)
            own = alt[len(f"Panel {i} of {n}: "):]
            assert len(own) >= 20, (where, alt)
            assert not PLACE_WORDS.search(alt), f"{where}, panel {i} points at a panel by its place: {alt}"
        # no panel repeats the others' descriptions (each describes itself, not the whole figure)
        for i, alt in enumerate(alts):
            body = alt.split(": ", 1)[1].split(" (Energy plot:")[0]
            for j, other in enumerate(alts):
                if i != j:
                    assert body not in other, f"{where}: panel {j + 1} repeats panel {i + 1}'s text"


# ------------------------------------------------------------------- text on gradients
HERO_COLOURS = """() => {
  const rgb = s => (s.match(/rgba?\\([^)]*\\)/g) || []).map(c => c.match(/[\\d.]+/g).map(Number));
  const hero = document.querySelector(".bl-hero");
  const page = rgb(getComputedStyle(document.body).backgroundColor)[0];
  const texts = Array.from(hero.querySelectorAll(".bl-hero-kicker, .bl-hero-promise, .bl-button")).map(e => {
    const s = getComputedStyle(e);
    return {what: e.className + ": " + e.textContent.trim().slice(0, 30), colour: rgb(s.color)[0],
            own: rgb(s.backgroundColor)[0]};
  });
  return {page, stops: rgb(getComputedStyle(hero).backgroundImage), texts};
}"""


def _over(colour, under):
    """``colour`` (r, g, b[, alpha]) drawn over the opaque ``under``."""
    a = colour[3] if len(colour) > 3 else 1.0
    return [a * c + (1 - a) * u for c, u in zip(colour[:3], under[:3])]


def _contrast(fg, bg) -> float:
    def lum(c):
        c = [x / 255 for x in c[:3]]
        c = [x / 12.92 if x <= 0.03928 else ((x + 0.055) / 1.055) ** 2.4 for x in c]
        return 0.2126 * c[0] + 0.7152 * c[1] + 0.0722 * c[2]
    hi, lo = sorted((lum(fg), lum(bg)), reverse=True)
    return (hi + 0.05) / (lo + 0.05)


@pytest.mark.parametrize("mode", ["light", "dark"])
def test_landing_page_text_on_its_gradient_contrasts(site, server, browser, mode):
    """axe-core cannot tell the contrast of text on a gradient: every stop is checked here."""
    ctx = colour_context(browser, mode, viewport={"width": 1280, "height": 900})
    page = ctx.new_page()
    page.goto(urljoin(server, "book/intro.html"), wait_until="load")
    assert page.evaluate("() => document.documentElement.dataset.theme") == mode
    c = page.evaluate(HERO_COLOURS)
    assert len(c["stops"]) >= 2 and len(c["texts"]) >= 4, c
    for t in c["texts"]:
        own = t["own"] if t["own"] and (len(t["own"]) < 4 or t["own"][3] > 0) else None
        grounds = [_over(own, c["page"])] if own else [_over(s, c["page"]) for s in c["stops"]]
        for g in grounds:
            ratio = _contrast(_over(t["colour"], g), g)
            assert ratio >= 4.5, f"{t['what']} in {mode} mode: {ratio:.2f}:1 on {g}"
    ctx.close()
