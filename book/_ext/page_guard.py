"""Sphinx extension: fail the build when an executed cell shows the reader something it should not.

myst-nb executes each page and writes the executed notebook to its output folder
(``<outdir>/../jupyter_execute/<docname>.ipynb``) while the page is read. On ``doctree-read``
this extension opens that notebook and emits a Sphinx warning (an error under ``-W``) for every
code cell, visible or hidden, whose outputs contain

* a ``stderr`` stream (Python warnings, logging, progress bars ...),
* a ``text/plain`` result that is just ``True`` or ``False`` (a bare boolean teaches nothing:
  print a sentence, or move the check into a hidden ``remove-cell`` cell as an ``assert``).

The message names the page, the cell (its number among the page's code cells, from 1, its line in
the page when the cell is shown, and its first line of code) and what was found.
"""
from __future__ import annotations

import json
import time
from pathlib import Path

from docutils import nodes
from sphinx.util import logging

__all__ = ["cell_problems", "setup"]

logger = logging.getLogger(__name__)

#: ``text/plain`` results that are refused.
BARE_BOOLEANS = ("True", "False")


def _text(value) -> str:
    return "".join(value) if isinstance(value, list) else str(value)


def cell_problems(cell: dict) -> list[str]:
    """What is wrong with one executed notebook cell's outputs.

    Parameters
    ----------
    cell : dict
        A code cell of an nbformat 4 notebook (``outputs`` as written by the kernel).

    Returns
    -------
    list of str
        One sentence per offending output; empty when the cell is fine.

    Examples
    --------
    >>> cell_problems({"cell_type": "code", "outputs": [
    ...     {"output_type": "stream", "name": "stderr", "text": "UserWarning: careful\\n"}]})
    ['it writes to stderr: UserWarning: careful']
    >>> cell_problems({"cell_type": "code", "outputs": [
    ...     {"output_type": "execute_result", "data": {"text/plain": "False"}}]})
    ['its result is a bare False']
    >>> cell_problems({"cell_type": "code", "outputs": [
    ...     {"output_type": "stream", "name": "stdout", "text": "k = 500 N/m\\n"}]})
    []
    """
    found = []
    for out in cell.get("outputs", []):
        kind = out.get("output_type")
        if kind == "stream" and out.get("name") == "stderr":
            first = _text(out.get("text", "")).strip().splitlines() or [""]
            found.append(f"it writes to stderr: {first[0][:160]}")
        elif kind in ("execute_result", "display_data"):
            plain = _text(out.get("data", {}).get("text/plain", "")).strip()
            if plain in BARE_BOOLEANS:
                found.append(f"its result is a bare {plain}")
    return found


def _cell_lines(doctree: nodes.document) -> dict[int, int]:
    """Line in the page of every rendered code cell, by notebook cell index."""
    lines = {}
    for node in doctree.findall(nodes.container):
        if node.get("nb_element") == "cell_code" and node.get("cell_index") is not None:
            if node.line is not None:
                lines[node["cell_index"]] = node.line
    return lines


def _source_read(app, docname: str, source: list) -> None:
    app.env.page_guard_read_start = getattr(app.env, "page_guard_read_start", {})
    app.env.page_guard_read_start[docname] = time.time() - 1.0


def _check_page(app, doctree: nodes.document) -> None:
    docname = app.env.docname
    config = getattr(app.env, "mystnb_config", None)
    if config is None or not config.output_folder:
        return
    ipynb = Path(config.output_folder).joinpath(*(docname + ".ipynb").split("/"))
    started = getattr(app.env, "page_guard_read_start", {}).get(docname)
    # Only a notebook written while this page was read (not a stale one of an earlier build).
    if not ipynb.is_file() or (started is not None and ipynb.stat().st_mtime < started):
        return
    notebook = json.loads(ipynb.read_text(encoding="utf-8"))
    lines = _cell_lines(doctree)
    number = 0
    for index, cell in enumerate(notebook.get("cells", [])):
        if cell.get("cell_type") != "code":
            continue
        number += 1
        for problem in cell_problems(cell):
            source = _text(cell.get("source", "")).strip().splitlines() or [""]
            tags = cell.get("metadata", {}).get("tags", [])
            where = f"line {lines[index]}" if index in lines else "hidden" if tags else "not shown"
            logger.warning(
                f"page {docname!r}, code cell {number} ({where}, `{source[0][:80]}`): {problem}",
                location=(docname, lines.get(index)), type="page_guard", subtype="output")


def setup(app):
    """Register the guard with Sphinx."""
    app.connect("source-read", _source_read)
    app.connect("doctree-read", _check_page)
    return {"version": "1.0", "parallel_read_safe": False, "parallel_write_safe": True}
