"""Running a notebook top to bottom and storing its outputs, small and stable under git."""
from __future__ import annotations

import hashlib
from pathlib import Path

__all__ = ["WIDGET_MIME", "WIDGET_TEXT", "execute_notebook", "stable_widget_id"]

WIDGET_MIME = "application/vnd.jupyter.widget-view+json"
#: What a stored widget output says where no widget manager can show it.
WIDGET_TEXT = "Live explorer: run the notebook to use its sliders."


def execute_notebook(path: str | Path, timeout: int = 120, kernel_name: str = "python3",
                     allow_errors: bool = False, write: bool = True):
    """Run a notebook top to bottom in a fresh kernel (in its own folder) and store the outputs.

    Parameters
    ----------
    path : str or Path
        The notebook.
    timeout : int
        Per-cell time limit (s).
    kernel_name : str
        Jupyter kernel to use.
    allow_errors : bool
        Keep going after a failing cell.
    write : bool
        Write the executed notebook back to ``path``.

    Returns
    -------
    nbformat.NotebookNode
        The executed notebook.

    Examples
    --------
    >>> import nbformat, pathlib, tempfile
    >>> path = pathlib.Path(tempfile.mkdtemp()) / "lab9.ipynb"
    >>> nbformat.write(nbformat.v4.new_notebook(cells=[nbformat.v4.new_code_cell("print(6 * 7)")]), path)
    >>> execute_notebook(path, write=False).cells[0].outputs[0].text
    '42\\n'
    """
    import nbformat
    from nbclient import NotebookClient

    path = Path(path)
    nb = nbformat.read(path, as_version=4)
    NotebookClient(nb, timeout=timeout, kernel_name=kernel_name, allow_errors=allow_errors,
                   resources={"metadata": {"path": str(path.parent)}},
                   store_widget_state=False).execute()
    for i, cell in enumerate(nb.cells):
        cell.get("metadata", {}).pop("execution", None)
        for j, out in enumerate(cell.get("outputs", [])):
            data = out.get("data", {})
            if WIDGET_MIME in data and "text/plain" in data:
                # the widget's repr holds the rendered picture's bytes: keep the file small
                data["text/plain"] = WIDGET_TEXT
            if WIDGET_MIME in data and isinstance(data[WIDGET_MIME], dict):
                # no widget state is stored, so the id names nothing: make it stable (no git diff per run)
                data[WIDGET_MIME]["model_id"] = stable_widget_id(path.name, i, j)
    if write:
        nbformat.write(nb, path)
    return nb


def stable_widget_id(name: str, cell: int, output: int) -> str:
    """A widget model id that depends only on where the widget is shown (32 hex digits).

    Parameters
    ----------
    name : str
        The notebook's file name.
    cell, output : int
        Cell index and output index.

    Returns
    -------
    str

    Examples
    --------
    >>> stable_widget_id("lab1.ipynb", 3, 0) == stable_widget_id("lab1.ipynb", 3, 0)
    True
    >>> len(stable_widget_id("lab1.ipynb", 3, 0))
    32
    """
    return hashlib.sha256(f"{name}:{cell}:{output}".encode()).hexdigest()[:32]
