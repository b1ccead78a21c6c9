"""Notebook surgery: the student version of a solution notebook, and the text of its solutions.

A solution notebook marks what students must not see:

* in a code cell, the lines between ``# BEGIN SOLUTION`` and ``# END SOLUTION`` (each
  on a line of its own, any indentation) are replaced by one line: ``variable = ...`` when
  the region is at the top level of a cell that checks one task (``check("n.m", variable)``),
  so that Run All goes on past an unanswered task and its check says "No answer yet";
  otherwise ``raise NotImplementedError("...")`` at the indentation of the ``BEGIN`` marker;
* in a markdown cell, everything between ``<!-- BEGIN SOLUTION -->`` and
  ``<!-- END SOLUTION -->`` is removed (a cell left empty is dropped);
* a cell tagged ``solution`` is dropped entirely.

The student version has no outputs and no execution counts.
"""
from __future__ import annotations

import copy
import re

from ...core.errors import MarkerError

__all__ = ["PLACEHOLDER", "ANSWER_PLACEHOLDER", "MarkerError", "student_version", "solution_texts"]

CODE_BEGIN = re.compile(r"^(\s*)# BEGIN SOLUTION\s*$")
CODE_END = re.compile(r"^\s*# END SOLUTION\s*$")
MD_BEGIN = "<!-- BEGIN SOLUTION -->"
MD_END = "<!-- END SOLUTION -->"
SOLUTION_TAG = "solution"
#: The line that replaces a solution region in a code cell.
PLACEHOLDER = 'raise NotImplementedError("your answer here: replace this line")'
#: The line that replaces a top-level solution region in a cell that checks one task.
ANSWER_PLACEHOLDER = "{variable} = ...  # your answer here: replace the ..."
CHECK_CALL = re.compile(r"""^check\(["'][\d.]+["'],\s*(\w+)\)""", re.M)


def _strip_code(src: str, where: str) -> tuple[str, list[str]]:
    checked = CHECK_CALL.findall(src)
    out, removed, inside, indent = [], [], False, ""
    for n, line in enumerate(src.split("\n"), 1):
        m = CODE_BEGIN.match(line)
        if m:
            if inside:
                raise MarkerError(f"{where}, line {n}: '# BEGIN SOLUTION' inside another solution region")
            inside, indent = True, m.group(1)
            removed.append("")
            continue
        if CODE_END.match(line):
            if not inside:
                raise MarkerError(f"{where}, line {n}: '# END SOLUTION' without a BEGIN")
            inside = False
            one = len(checked) == 1 and indent == ""
            out.append(ANSWER_PLACEHOLDER.format(variable=checked[0]) if one else indent + PLACEHOLDER)
            continue
        if inside:
            removed[-1] += line + "\n"
        else:
            out.append(line)
    if inside:
        raise MarkerError(f"{where}: '# BEGIN SOLUTION' is never closed by '# END SOLUTION'")
    return "\n".join(out), removed


def _strip_markdown(src: str, where: str) -> tuple[str, list[str]]:
    out, removed, pos = [], [], 0
    while True:
        b = src.find(MD_BEGIN, pos)
        e = src.find(MD_END, pos)
        if b < 0:
            if e >= 0:
                raise MarkerError(f"{where}: '{MD_END}' without a BEGIN")
            out.append(src[pos:])
            break
        if e < b:
            raise MarkerError(f"{where}: '{MD_END}' without a BEGIN")
        nb = src.find(MD_BEGIN, b + len(MD_BEGIN))
        if nb >= 0 and nb < e:
            raise MarkerError(f"{where}: nested '{MD_BEGIN}'")
        out.append(src[pos:b])
        removed.append(src[b + len(MD_BEGIN):e])
        pos = e + len(MD_END)
    text = "".join(out)
    text = re.sub(r"\n{3,}", "\n\n", text).strip("\n")
    return text, removed


def _cell_where(name: str, i: int) -> str:
    return f"{name}: cell {i}"


def _split(nb, name: str = "notebook"):
    """(student cells, removed texts) of a notebook."""
    cells, removed = [], []
    for i, cell in enumerate(nb.cells):
        src = cell.source if isinstance(cell.source, str) else "".join(cell.source)
        if SOLUTION_TAG in cell.get("metadata", {}).get("tags", []):
            removed.append(src)
            continue
        where = _cell_where(name, i)
        new = copy.deepcopy(cell)
        if cell.cell_type == "code":
            text, gone = _strip_code(src, where)
            new.outputs = []
            new.execution_count = None
        elif cell.cell_type == "markdown":
            text, gone = _strip_markdown(src, where)
            if gone and not text.strip():
                removed.extend(gone)
                continue
        else:
            text, gone = src, []
        new.source = text
        md = dict(new.get("metadata", {}))
        md.pop("execution", None)
        new.metadata = md
        cells.append(new)
        removed.extend(gone)
    return cells, removed


def student_version(nb, name: str = "notebook"):
    """The student version of a solution notebook (a new notebook; the input is untouched).

    Parameters
    ----------
    nb : nbformat.NotebookNode
        The solution notebook.
    name : str
        Name used in error messages.

    Returns
    -------
    nbformat.NotebookNode

    Raises
    ------
    MarkerError
        If a solution marker is unbalanced or nested.

    Examples
    --------
    >>> import nbformat
    >>> nb = nbformat.v4.new_notebook(cells=[nbformat.v4.new_code_cell(
    ...     "x = 1\\n# BEGIN SOLUTION\\nk = 2\\n# END SOLUTION")])
    >>> print(student_version(nb).cells[0].source)
    x = 1
    raise NotImplementedError("your answer here: replace this line")
    """
    import nbformat

    cells, _ = _split(nb, name)
    out = nbformat.v4.new_notebook()
    out.nbformat, out.nbformat_minor = nb.nbformat, nb.nbformat_minor
    md = copy.deepcopy(dict(nb.metadata))
    md.pop("widgets", None)
    bl = dict(md.get("balancelab", {}))
    bl["version"] = "student"
    md["balancelab"] = bl
    out.metadata = md
    out.cells = cells
    return out


def solution_texts(nb, name: str = "notebook") -> list[str]:
    """The text of every solution region (code, prose and tagged cells) of a notebook.

    Parameters
    ----------
    nb : nbformat.NotebookNode
        The solution notebook.
    name : str
        Name used in error messages.

    Returns
    -------
    list of str

    Examples
    --------
    >>> import nbformat
    >>> nb = nbformat.v4.new_notebook(cells=[nbformat.v4.new_code_cell(
    ...     "x = 1\\n# BEGIN SOLUTION\\nk = 2\\n# END SOLUTION")])
    >>> solution_texts(nb)
    ['k = 2\\n']
    """
    return [t for t in _split(nb, name)[1] if t.strip()]
