"""Pages for readers: checks live in hidden cells, and the build refuses stderr and bare booleans.

The guard is ``book/_ext/page_guard.py``; the mini-book test builds a one-page book with it
(slow: it starts a kernel and Sphinx, about 20 s).
"""
from __future__ import annotations

import ast
import re
from pathlib import Path

import pytest
import yaml

from conftest import build_mini_book

ROOT = Path(__file__).resolve().parents[1]
PAGES = ["intro", "ch1_counterweights", "ch2_zfl_springs", "ch3_building_zfl", "ch4_serial",
         "ch5_fourbar", "ch6_scissors_peaucellier", "ch7_your_own_linkage", "ch8_ideal_to_real", "ch9_noncircular",
         "notes_on_sources"]
CELL = re.compile(r"^```\{code-cell\}[^\n]*\n(.*?)^```", re.MULTILINE | re.DOTALL)
HIDING = ("remove-cell", "remove_cell", "remove-input", "remove_input")


def code_cells(text: str) -> list[tuple[bool, str]]:
    """(visible, code) of every code cell of a MyST notebook page."""
    cells = []
    for m in CELL.finditer(text):
        body = m.group(1)
        options = ""
        if body.startswith("---\n"):
            end = body.index("\n---\n", 3)
            options, body = body[:end], body[end + 5:]
        else:
            head = re.match(r"(?:^:[^\n]*\n)*", body).group(0)
            options, body = head, body[len(head):]
        cells.append((not any(tag in options for tag in HIDING), body))
    return cells


def test_code_cells_are_found_with_their_visibility():
    text = ("```{code-cell} ipython3\nx = 1\n```\n\n```{code-cell} ipython3\n:tags: [remove-cell]\n"
            "assert x == 1\n```\n\n```{code-cell} ipython3\n---\ntags: [remove-input]\n---\nprint(x)\n```\n")
    assert code_cells(text) == [(True, "x = 1\n"), (False, "assert x == 1\n"), (False, "print(x)\n")]


#: The longest line of code a page shows (the chapters are formatted to 72 columns; 88 is the limit
#: past which a code block scrolls sideways even in a laptop's column).
CODE_COLUMNS = 88
FENCE = re.compile(r"^```(?:python|bash|ipython3?|sh|text|console)\n(.*?)^```", re.MULTILINE | re.DOTALL)


@pytest.mark.parametrize("page", PAGES + ["labs"])
def test_visible_code_lines_fit_the_column(page):
    """Every line of code a reader sees (visible cells and plain code blocks) is at most 88 columns."""
    text = (ROOT / "book" / f"{page}.md").read_text()
    shown = [code for visible, code in code_cells(text) if visible]
    shown += [m.group(1) for m in FENCE.finditer(text)]
    long = [line for code in shown for line in code.splitlines() if len(line) > CODE_COLUMNS]
    assert not long, f"{page}: {len(long)} visible code lines over {CODE_COLUMNS} columns:\n" + "\n".join(long[:5])


def test_the_line_check_sees_visible_cells_and_code_blocks_only():
    long = "x = " + "1 + " * 30 + "1"
    text = (f"```{{code-cell}} ipython3\n{long}\n```\n\n```{{code-cell}} ipython3\n:tags: [remove-cell]\n"
            f"{long}\n```\n\n```python\n{long}\n```\n")
    visible = [code for v, code in code_cells(text) if v] + [m.group(1) for m in FENCE.finditer(text)]
    assert [len(c.strip()) > CODE_COLUMNS for c in visible] == [True, True]


@pytest.mark.parametrize("page", PAGES)
def test_no_visible_cell_asserts(page):
    cells = code_cells((ROOT / "book" / f"{page}.md").read_text())
    assert cells or page in ("intro",), f"{page}: no code cells found"
    for visible, code in cells:
        if not visible:
            continue
        asserts = [n.lineno for n in ast.walk(ast.parse(code)) if isinstance(n, ast.Assert)]
        assert not asserts, f"{page}: a visible cell asserts (move the check into a hidden cell):\n{code}"
        assert "printed_digits" not in code, f"{page}: a visible cell compares printed digits:\n{code}"


def test_guard_is_registered():
    cfg = yaml.safe_load((ROOT / "_config.yml").read_text())
    assert cfg["sphinx"]["local_extensions"]["page_guard"] == "book/_ext"
    assert (ROOT / "book" / "_ext" / "page_guard.py").is_file()


@pytest.mark.slow
def test_a_cell_writing_to_stderr_or_showing_a_bare_boolean_fails_the_build(tmp_path):
    r = build_mini_book(tmp_path, local_extensions={"page_guard": str(ROOT / "book" / "_ext")}, body="""
        # Page

        ```{code-cell} ipython3
        print("k = 500 N/m")
        ```

        ```{code-cell} ipython3
        import sys
        print("something went wrong", file=sys.stderr)
        ```

        ```{code-cell} ipython3
        1 + 1 == 2
        ```
        """)
    out = r.stdout + r.stderr
    assert r.returncode != 0, out
    assert "page 'page', code cell 2" in out and "it writes to stderr: something went wrong" in out, out
    assert "page 'page', code cell 3" in out and "its result is a bare True" in out, out
    assert "code cell 1 " not in out, out
