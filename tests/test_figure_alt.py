"""A figure of several panels gets one alt text per panel (``book/_ext/figure_alt.py``).

The panels of a figure sit side by side on a wide screen and stack on a phone, so each panel's
image describes that panel alone and never points at another by its place. The built pages are
checked by ``tests/test_a11y.py``; here the extension's rules, and that every chapter gives its
side-by-side figures one text per panel.
"""
from __future__ import annotations

import html
import re
import sys
from pathlib import Path

import pytest
import yaml
from hypothesis import given
from hypothesis import strategies as st

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT / "book" / "_ext"))
try:
    from figure_alt import panel_alts
finally:
    sys.path.pop(0)

CELL = re.compile(r"^```\{code-cell\}[^\n]*\n---\n(.*?)\n---\n(.*?)^```", re.MULTILINE | re.DOTALL)


def figure(*own: str) -> str:
    """HTML of a figure whose panels carry the alt texts ``own`` (as ``figure_html`` writes it)."""
    return '<div class="bl-figure">' + "".join(
        f'<img src="data:image/png;base64,AA" width="10" height="10" alt="{html.escape(a)}" class="bl-panel" '
        f'style="flex: 1 1 9px;">' for a in own) + "</div>"


def alts(text: str) -> list[str]:
    return [html.unescape(a) for a in re.findall(r'alt="([^"]*)"', text)]


words = st.text(alphabet=st.characters(whitelist_categories=("L", "N"), whitelist_characters=" ,.&<>'\"°-"),
                min_size=1, max_size=40).filter(lambda t: t.strip() and not re.search(r"(?i)left|right|middle", t))


@given(st.lists(words, min_size=2, max_size=5))
def test_each_panel_gets_its_own_text_numbered(texts):
    out = alts(panel_alts(figure(*["Figure panel: x"] * len(texts)), texts))
    n = len(texts)
    assert out == [f"Panel {i} of {n}: {' '.join(t.split())}" for i, t in enumerate(texts, start=1)]


@given(words)
def test_a_single_panel_gets_the_text_as_it_is(text):
    assert alts(panel_alts(figure("Figure panel: energy"), text)) == [" ".join(text.split())]
    assert alts(panel_alts(figure("Figure panel: energy"), [text])) == [" ".join(text.split())]


def test_what_a_panel_computed_it_shows_follows_its_text():
    out = alts(panel_alts(figure("Figure panel: x", "Energy plot: the total energy is flat at 2.94 J"),
                          ["A link and its spring.", "Its energies against the link angle."]))
    assert out == ["Panel 1 of 2: A link and its spring.",
                   "Panel 2 of 2: Its energies against the link angle. (Energy plot: the total energy is flat at 2.94 J)"]


@pytest.mark.parametrize("given_texts", [["only one text"], "only one text", ["a", "b", "c"]])
def test_the_wrong_number_of_texts_is_refused(given_texts):
    with pytest.raises(ValueError, match=r"alt: the figure has 2 panels but \d alt texts? w(as|ere) given"):
        panel_alts(figure("x", "y"), given_texts)


@pytest.mark.parametrize("bad", ["Left, a link with a spring", "a link; right: its energy", "On the left the lines meet",
                                 "Middle and right, residual torques", "the left panel shows a link"])
def test_a_text_that_points_left_or_right_is_refused(bad):
    with pytest.raises(ValueError, match="points at a panel by its place"):
        panel_alts(figure("x", "y"), [bad, "Energy curves with a flat total."])


@pytest.mark.parametrize("fine", ["a mass at its right end and a counterweight on its short left end",
                                  "a profile below and to the right of the pivot", "a spring on the right side of A"])
def test_where_things_are_inside_a_panel_may_be_said(fine):
    assert alts(panel_alts(figure("Figure panel: x", "y"), [fine, "Energy curves."]))[0] == f"Panel 1 of 2: {fine}"


def test_an_empty_panel_text_is_refused():
    with pytest.raises(ValueError, match="panel 2 is empty"):
        panel_alts(figure("x", "y"), ["A link.", "  "])


def test_chapters_give_side_by_side_figures_one_text_per_panel():
    """Every figure cell that draws a row of panels gives a list of that many alt texts."""
    checked = 0
    for page in sorted((ROOT / "book").glob("ch*.md")):
        for meta_text, code in CELL.findall(page.read_text(encoding="utf-8")):
            meta = yaml.safe_load(meta_text) or {}
            alt = meta.get("panel_alts")
            row = re.search(r"plt\.subplots\(\s*1,\s*(\d+)", code)
            if row is None or not (alt or (meta.get("mystnb") or {}).get("image")):
                continue
            # myst-nb checks that image: alt: is one string; several panels take panel_alts
            assert "alt" not in ((meta.get("mystnb") or {}).get("image") or {}), page.name
            n = int(row.group(1))
            assert isinstance(alt, list) and len(alt) == n, f"{page.name}: {alt!r} for {n} panels"
            assert len(set(alt)) == n, f"{page.name}: panels share a text: {alt}"
            checked += 1
    assert checked >= 15


@pytest.mark.slow
def test_a_book_gives_each_panel_its_text_and_refuses_one_text_for_two_panels(tmp_path):
    from conftest import build_mini_book

    r = build_mini_book(tmp_path, local_extensions={"figure_alt": str(ROOT / "book" / "_ext")}, body="""
        # Page

        ```{code-cell} ipython3
        from IPython.display import display
        from matplotlib.figure import Figure
        import balancelab.viz.style as style
        _ = style.install()
        ```

        ```{code-cell} ipython3
        ---
        panel_alts:
          - "A link and its spring."
          - "Its energies against the link angle."
        ---
        fig = Figure(figsize=(6, 2), layout="constrained"); a, b = fig.subplots(1, 2)
        _ = a.set_title("link"), b.set_title("energy")
        display(fig)
        ```

        ```{code-cell} ipython3
        ---
        mystnb:
          image:
            alt: Left, a link; right, its energy.
        ---
        fig = Figure(figsize=(6, 2), layout="constrained"); a, b = fig.subplots(1, 2)
        _ = a.set_title("link"), b.set_title("energy")
        display(fig)
        ```
        """)
    out = r.stdout + r.stderr
    assert r.returncode != 0, out
    assert "figure alt text: alt: the figure has 2 panels but 1 alt text was given" in out, out
    page = (tmp_path / "_build" / "html" / "page.html").read_text(encoding="utf-8")
    assert alts(page)[:2] == ["Panel 1 of 2: A link and its spring.", "Panel 2 of 2: Its energies against the link angle."]


def test_captions_name_panels_by_order_not_by_side():
    """Attack A23: on a phone the panels stack, so a caption's "left"/"right" points nowhere (WCAG
    1.3.3); captions say "first panel", "second panel" instead."""
    side = re.compile(r"\b(left|right|middle)\b(?!-)", re.IGNORECASE)
    checked, found = 0, []
    for page in sorted((ROOT / "book").glob("ch*.md")):
        for meta_text, _ in CELL.findall(page.read_text(encoding="utf-8")):
            caption = (((yaml.safe_load(meta_text) or {}).get("mystnb") or {}).get("figure") or {}).get("caption")
            if caption:
                checked += 1
                found += [f"{page.name}: {caption[:80]}" for _ in side.findall(caption.replace("left out", ""))]
    assert checked >= 20 and not found, found
