"""Run one submitted notebook inside the sandbox and export its answers as plain data.

This is the untrusted half of grading (:mod:`balancelab.course.grading` is the trusted half):
``python -m balancelab.course.runner NOTEBOOK --lab lab2 --vars k_lamp,... --cell-timeout 60``
runs in the sandbox (:mod:`balancelab.course.sandbox`), executes the notebook cell by cell in
a fresh kernel and, after every code cell, asks the kernel for the current value of each
answer variable, encoded by :func:`~balancelab.course.check.data.encode_answer` (whose source
is sent to the kernel). The answers are written to ``answers.json`` in the scratch folder
after every cell, so a notebook killed later still keeps the answers it had; the last line
of the output is a JSON summary (cells that failed or timed out).

Nothing here judges an answer: the output is data that the grader checks on its own.
A cell that passes its time limit is interrupted (SIGINT); if it is still running two
seconds later (a cell that ignores SIGINT) the kernel is killed and the run stops there.
"""
from __future__ import annotations

import argparse
import inspect
import json
import sys
from pathlib import Path

from .check.data import encode_answer

__all__ = ["RESULT_MARK", "ANSWER_MARK", "ANSWERS_FILE", "export_source", "run_notebook", "main"]

RESULT_MARK = "BALANCELAB-RUN-RESULT "
ANSWER_MARK = "BALANCELAB-ANSWERS "
ANSWERS_FILE = "answers.json"
#: Seconds a cell may keep running after the interrupt at its time limit.
INTERRUPT_GRACE = 2.0
#: The encoder's source, read once when this module is imported (the code that is running).
_ENCODER_SOURCE = inspect.getsource(encode_answer).replace("encode_answer", "_bl_encode_answer")


def export_source(variables: list[str]) -> str:
    """The code the kernel runs after each cell: print the answer variables as encoded data.

    Parameters
    ----------
    variables : list of str
        The answer variables of the lab.

    Returns
    -------
    str

    Examples
    --------
    >>> ns = {"k_lamp": 196.2}
    >>> import contextlib, io
    >>> buf = io.StringIO()
    >>> with contextlib.redirect_stdout(buf):
    ...     exec(export_source(["k_lamp", "r_c"]), ns)
    >>> buf.getvalue().split(" ", 1)[1].strip()
    '{"k_lamp": {"num": "196.2"}}'
    """
    return (_ENCODER_SOURCE + "\nimport json as _bl_json\n"
            f"print({ANSWER_MARK!r} + _bl_json.dumps({{_v: _bl_encode_answer(globals()[_v]) "
            f"for _v in {list(variables)!r} if _v in globals()}}))\n"
            "del _bl_encode_answer, _bl_json\n")


def _client_class():
    from nbclient import NotebookClient
    from nbclient.exceptions import CellTimeoutError

    class _Client(NotebookClient):
        """Interrupt at the cell limit; if the cell ignores it, give up after a short grace."""

        async def _async_handle_timeout(self, timeout, cell=None):
            import asyncio
            from queue import Empty

            from jupyter_core.utils import ensure_async

            await ensure_async(self.km.interrupt_kernel())
            loop_end = asyncio.get_event_loop().time() + INTERRUPT_GRACE
            while (left := loop_end - asyncio.get_event_loop().time()) > 0:
                try:
                    msg = await ensure_async(self.kc.shell_channel.get_msg(timeout=left))
                except Empty:
                    break
                if msg.get("msg_type") == "execute_reply":
                    return msg
            raise CellTimeoutError.error_from_timeout_and_cell("Cell ignored the interrupt", timeout, cell)

    return _Client


def _answers_of(cell) -> dict | None:
    for o in cell.get("outputs", []):
        if o.get("output_type") == "stream" and ANSWER_MARK in o.get("text", ""):
            line = o["text"].rsplit(ANSWER_MARK, 1)[1].splitlines()[0]
            try:
                data = json.loads(line)
            except ValueError:
                return None
            return data if isinstance(data, dict) else None
    return None


def run_notebook(path: str | Path, variables: list[str], cell_timeout: int = 60,
                 answers_file: str | Path | None = None) -> dict:
    """Execute a notebook cell by cell, exporting the answer variables after each code cell.

    Parameters
    ----------
    path : str or Path
        The notebook (a copy in the scratch folder).
    variables : list of str
        The answer variables to export.
    cell_timeout : int
        Per-cell limit (s).
    answers_file : str or Path, optional
        Where the answers are written after every cell (``answers.json`` beside the notebook).

    Returns
    -------
    dict
        ``{"status", "answers", "errors", "notes"}``; ``answers`` maps a variable to its
        encoded value.
    """
    import nbformat
    from nbclient.exceptions import CellTimeoutError, DeadKernelError

    path = Path(path)
    answers_file = Path(answers_file or path.with_name(ANSWERS_FILE))
    nb = nbformat.read(path, as_version=4)
    client = _client_class()(nb, timeout=cell_timeout, kernel_name="python3", allow_errors=True,
                             interrupt_on_timeout=True, shutdown_kernel="immediate",
                             resources={"metadata": {"path": str(path.parent)}})
    answers, errors, notes, status = {}, [], [], "graded"
    cells = list(nb.cells)
    probe = nbformat.v4.new_code_cell(export_source(variables))
    nb.cells.append(probe)
    with client.setup_kernel():
        for i, cell in enumerate(cells):
            if cell.cell_type != "code":
                continue
            try:
                client.execute_cell(cell, i)
                errors += [f"cell {i}: {o.get('ename')}" for o in cell.get("outputs", [])
                           if o.get("output_type") == "error"]
                probe.outputs = []
                client.execute_cell(probe, len(cells))
            except CellTimeoutError:
                status = "timeout"
                notes.append(f"cell {i} ran past the {cell_timeout} s cell limit and ignored the interrupt: "
                             "its kernel was killed; the answers given before it are graded")
                break
            except DeadKernelError:
                status = "kernel died"
                notes.append(f"the kernel died in cell {i}; the answers given before it are graded")
                break
            found = _answers_of(probe)
            if found is not None:
                answers = found
                answers_file.write_text(json.dumps(answers), encoding="utf-8")
    return dict(status=status, answers=answers, errors=errors, notes=notes)


def main(argv: list[str] | None = None) -> int:
    """Command line (see the module docstring); prints the JSON summary after :data:`RESULT_MARK`.

    Parameters
    ----------
    argv : list of str, optional

    Returns
    -------
    int
        0 when the notebook ran (whatever its cells did), 1 when it could not be run.
    """
    ap = argparse.ArgumentParser(prog="python -m balancelab.course.runner")
    ap.add_argument("notebook")
    ap.add_argument("--vars", default="")
    ap.add_argument("--cell-timeout", type=int, default=60)
    args = ap.parse_args(argv)
    variables = [v for v in args.vars.split(",") if v]
    try:
        res = run_notebook(args.notebook, variables, args.cell_timeout)
    except Exception as e:  # the kernel could not start, the notebook could not be read
        res = dict(status="error", answers={}, errors=[], notes=[f"execution failed: {type(e).__name__}: "
                                                                   f"{str(e)[:160]}"])
    print(RESULT_MARK + json.dumps(res), flush=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())
