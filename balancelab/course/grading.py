"""Grade a folder of submitted lab notebooks in one command.

::

    python -m balancelab.course.grading submissions/ --out grades.csv

Every ``*.ipynb`` under the folder is graded in its own worker process: the notebook is
copied to a scratch folder (the submission is never modified), executed top to bottom in a
fresh kernel with a per-cell time limit (a cell that loops is interrupted and execution goes
on), and then every task of its lab is checked (:func:`balancelab.course.check.check`) on the
variable that holds the task's answer. Failing cells cost nothing by themselves: a task
scores when its answer variable exists and its check passes.

The result is one row per notebook (``student`` = path relative to the folder, without
``.ipynb``): lab, status, total, the score of each task and notes. A notebook that is not
valid JSON, crashes its kernel, loops past the whole-notebook limit or belongs to no known
lab gets a row with a clear status and zero points, and never stops the batch. The table is
written as CSV and printed as a summary.
"""
from __future__ import annotations

import argparse
import csv
import json
import os
import re
import subprocess
import sys
import tempfile
from dataclasses import dataclass, field
from pathlib import Path

from . import check as _check

__all__ = ["GradeRow", "grade_namespace", "grade_notebook", "grade_folder", "write_csv",
           "summary", "main"]

RESULT_MARK = "BALANCELAB-GRADE-RESULT "


@dataclass
class GradeRow:
    """The grade of one submitted notebook.

    Attributes
    ----------
    student : str
        Submission name (path relative to the graded folder, no suffix).
    lab : str
        ``"lab1"`` ... or ``""`` when unknown.
    status : str
        ``"graded"``, ``"malformed"``, ``"unknown lab"``, ``"timeout"``, ``"kernel died"`` or
        ``"error"``.
    scores : dict
        Task id -> points earned.
    points : dict
        Task id -> points possible.
    notes : str
        Cells that failed or were interrupted, or what went wrong.

    Examples
    --------
    >>> row = GradeRow("alice", "lab2", "graded", {"2.1": 1.0, "2.4": 0.0}, {"2.1": 1.0, "2.4": 2.0})
    >>> row.total, row.max_total
    (1.0, 3.0)
    """

    student: str
    lab: str
    status: str
    scores: dict = field(default_factory=dict)
    points: dict = field(default_factory=dict)
    notes: str = ""

    @property
    def total(self) -> float:
        return float(sum(self.scores.values()))

    @property
    def max_total(self) -> float:
        return float(sum(self.points.values()))


def grade_namespace(namespace: dict, lab: str) -> dict:
    """Check every task of ``lab`` against the answer variables of a notebook's namespace.

    Runs inside the graded kernel (the grader appends a cell calling it).

    Parameters
    ----------
    namespace : dict
        The notebook's ``globals()``.
    lab : str
        E.g. ``"lab2"``.

    Returns
    -------
    dict
        Task id -> ``{"score", "points", "correct", "message"}``.

    Examples
    --------
    >>> r = grade_namespace({"k_lamp": 196.2}, "lab2")
    >>> r["2.1"]["score"], r["2.2"]["message"]
    (1.0, 'no answer: variable `lever_conditions` is not defined')
    """
    out = {}
    for t in _check.tasks(lab):
        if t.variable not in namespace:
            out[t.id] = dict(score=0.0, points=t.points, correct=False,
                             message=f"no answer: variable `{t.variable}` is not defined")
            continue
        v = _check.check(t.id, namespace[t.variable])
        out[t.id] = dict(score=float(v.score), points=float(t.points), correct=v.correct,
                         message=v.message)
    return out


def _lab_of(nb, path: Path, lab: str | None) -> str | None:
    if lab:
        return lab if str(lab).startswith("lab") else f"lab{lab}"
    meta = nb.get("metadata", {}).get("balancelab", {})
    if isinstance(meta, dict) and meta.get("lab"):
        return str(meta["lab"])
    m = re.search(r"lab[_\-]?(\d+)", path.name, re.IGNORECASE)
    return f"lab{m.group(1)}" if m else None


def _worker(path: Path, lab: str | None, cell_timeout: int) -> dict:
    """Execute one notebook (a copy) and grade it; returns a JSON-able dict."""
    import nbformat
    from nbclient import NotebookClient
    from nbclient.exceptions import CellTimeoutError, DeadKernelError

    try:
        nb = nbformat.read(path, as_version=4)
        nbformat.validate(nb)
    except Exception as e:  # not JSON, not a notebook, wrong schema
        return dict(status="malformed", lab=lab or "", notes=f"not a valid notebook: {type(e).__name__}: "
                    f"{str(e).splitlines()[0][:120] if str(e) else ''}")
    lab = _lab_of(nb, path, lab)
    known = {t.lab for t in _check.tasks()}
    if lab not in known:
        return dict(status="unknown lab", lab=lab or "",
                    notes="cannot tell which lab this is (no balancelab.lab metadata, no 'labN' in the "
                          "file name); pass --lab")
    nb.cells.append(nbformat.v4.new_code_cell(
        "import json as _bl_json, balancelab.course.grading as _bl_grading\n"
        f"print({RESULT_MARK!r} + _bl_json.dumps(_bl_grading.grade_namespace(globals(), {lab!r})))"))
    notes = []
    status = "graded"
    with tempfile.TemporaryDirectory(prefix="balancelab-grade-") as tmp:
        client = NotebookClient(nb, timeout=cell_timeout, kernel_name="python3", allow_errors=True,
                                interrupt_on_timeout=True, resources={"metadata": {"path": tmp}})
        try:
            client.execute()
        except CellTimeoutError:
            status = "timeout"
            notes.append(f"a cell ran longer than {cell_timeout} s and could not be interrupted")
        except DeadKernelError:
            status = "kernel died"
            notes.append("the kernel died while running the notebook")
        except Exception as e:
            status = "error"
            notes.append(f"execution failed: {type(e).__name__}: {str(e)[:120]}")
    result = None
    for i, cell in enumerate(nb.cells[:-1]):
        for o in cell.get("outputs", []):
            if o.get("output_type") == "error":
                notes.append(f"cell {i}: {o.get('ename')}")
    for o in nb.cells[-1].get("outputs", []):
        if o.get("output_type") == "stream" and RESULT_MARK in o.get("text", ""):
            line = o["text"].split(RESULT_MARK, 1)[1].splitlines()[0]
            result = json.loads(line)
    if result is None and status == "graded":
        status = "error"
        notes.append("the tasks could not be checked (the grading cell did not run)")
    return dict(status=status, lab=lab, results=result or {}, notes="; ".join(notes))


def grade_notebook(path: str | Path, *, lab: str | None = None, cell_timeout: int = 60,
                   notebook_timeout: int = 600, student: str | None = None) -> GradeRow:
    """Grade one submitted notebook in a separate process.

    Parameters
    ----------
    path : str or Path
        The submission (read only).
    lab : str, optional
        Force the lab (``"lab2"`` or ``"2"``); otherwise read from the notebook's
        ``balancelab.lab`` metadata or a ``labN`` in its file name.
    cell_timeout : int
        Per-cell time limit (s); a looping cell is interrupted.
    notebook_timeout : int
        Limit for the whole notebook (s); past it the worker is killed.
    student : str, optional
        Name for the row (default: the file name without suffix).

    Returns
    -------
    GradeRow

    Examples
    --------
    A file that is not a notebook gets a clear row (no kernel is started for it):

    >>> import pathlib, tempfile
    >>> bad = pathlib.Path(tempfile.mkdtemp()) / "bob_lab2.ipynb"
    >>> _ = bad.write_text("{not json")
    >>> row = grade_notebook(bad)
    >>> row.status, row.total, row.notes.split(":")[0]
    ('malformed', 0.0, 'not a valid notebook')
    """
    path = Path(path)
    student = student or path.stem
    cmd = [sys.executable, "-m", "balancelab.course.grading", "--worker", str(path),
           "--cell-timeout", str(cell_timeout)]
    if lab:
        cmd += ["--lab", str(lab)]
    tasks_of = lambda lb: {t.id: float(t.points) for t in _check.tasks(lb)} if lb else {}  # noqa: E731
    try:
        proc = subprocess.run(cmd, capture_output=True, text=True, timeout=notebook_timeout,
                              env={**os.environ, "PYTHONUNBUFFERED": "1"})
    except subprocess.TimeoutExpired:
        lb = lab if lab is None or str(lab).startswith("lab") else f"lab{lab}"
        return GradeRow(student, lb or "", "timeout", {t: 0.0 for t in tasks_of(lb)}, tasks_of(lb),
                        f"the notebook ran longer than {notebook_timeout} s in total")
    data = None
    for line in proc.stdout.splitlines():
        if line.startswith(RESULT_MARK):
            data = json.loads(line[len(RESULT_MARK):])
    if data is None:
        err = (proc.stderr.strip().splitlines() or ["no output"])[-1][:200]
        return GradeRow(student, lab or "", "error", notes=f"grader worker failed: {err}")
    lb = data.get("lab", "")
    results = data.get("results", {})
    points = tasks_of(lb) if lb in {t.lab for t in _check.tasks()} else {}
    scores = {tid: float(results.get(tid, {}).get("score", 0.0)) for tid in points}
    return GradeRow(student, lb, data["status"], scores, points, data.get("notes", ""))


def grade_folder(folder: str | Path, *, lab: str | None = None, cell_timeout: int = 60,
                 notebook_timeout: int = 600, progress: bool = False) -> list[GradeRow]:
    """Grade every ``*.ipynb`` under ``folder`` (checkpoints skipped), one row each.

    Parameters
    ----------
    folder : str or Path
        Folder of submissions (searched recursively).
    lab, cell_timeout, notebook_timeout
        As in :func:`grade_notebook`.
    progress : bool
        Print one line per notebook as it is graded.

    Returns
    -------
    list of GradeRow

    Raises
    ------
    FileNotFoundError
        If ``folder`` is not a folder.

    Examples
    --------
    >>> grade_folder("no/such/folder")
    Traceback (most recent call last):
    ...
    FileNotFoundError: no such folder: no/such/folder
    """
    folder = Path(folder)
    if not folder.is_dir():
        raise FileNotFoundError(f"no such folder: {folder}")
    files = sorted(p for p in folder.rglob("*.ipynb") if ".ipynb_checkpoints" not in p.parts)
    rows = []
    for p in files:
        name = str(p.relative_to(folder).with_suffix(""))
        row = grade_notebook(p, lab=lab, cell_timeout=cell_timeout, notebook_timeout=notebook_timeout,
                             student=name)
        if progress:
            print(f"graded {name}: {row.status}, {row.total:g}/{row.max_total:g}", flush=True)
        rows.append(row)
    return rows


def _task_columns(rows) -> list[str]:
    order = [t.id for t in _check.tasks()]
    used = {tid for r in rows for tid in r.points}
    return [t for t in order if t in used]


def write_csv(rows: list[GradeRow], path: str | Path) -> Path:
    """Write the grade table: student, lab, status, total, max, one column per task, notes.

    Parameters
    ----------
    rows : list of GradeRow
    path : str or Path

    Returns
    -------
    Path

    Examples
    --------
    >>> import pathlib, tempfile
    >>> rows = [GradeRow("alice", "lab2", "graded", {"2.1": 1.0}, {"2.1": 1.0})]
    >>> path = write_csv(rows, pathlib.Path(tempfile.mkdtemp()) / "grades.csv")
    >>> path.read_text().splitlines()
    ['student,lab,status,total,max,2.1,notes', 'alice,lab2,graded,1,1,1,']
    """
    path = Path(path)
    cols = _task_columns(rows)
    with path.open("w", newline="", encoding="utf-8") as f:
        w = csv.writer(f)
        w.writerow(["student", "lab", "status", "total", "max"] + cols + ["notes"])
        for r in rows:
            w.writerow([r.student, r.lab, r.status, f"{r.total:g}", f"{r.max_total:g}"]
                       + [f"{r.scores[c]:g}" if c in r.scores else "" for c in cols] + [r.notes])
    return path


def summary(rows: list[GradeRow]) -> str:
    """A plain-text table of the grades (what the command prints).

    Parameters
    ----------
    rows : list of GradeRow

    Returns
    -------
    str

    Examples
    --------
    >>> rows = [GradeRow("alice", "lab2", "graded", {"2.1": 1.0}, {"2.1": 1.0}),
    ...         GradeRow("bob", "", "malformed", notes="not a valid notebook")]
    >>> print("\\n".join(summary(rows).splitlines()[-2:]))
    2 notebooks, 1 graded, 1 with problems
      bob: malformed: not a valid notebook
    """
    cols = _task_columns(rows)
    head = ["student", "lab", "status", "score"] + cols
    body = [[r.student, r.lab, r.status, f"{r.total:g}/{r.max_total:g}"]
            + [f"{r.scores[c]:g}" if c in r.scores else "-" for c in cols] for r in rows]
    widths = [max(len(str(x)) for x in col) for col in zip(head, *body)] if body else [len(h) for h in head]
    fmt = lambda cells: "  ".join(str(c).ljust(w) for c, w in zip(cells, widths))  # noqa: E731
    lines = [fmt(head), fmt(["-" * w for w in widths])] + [fmt(b) for b in body]
    graded = [r for r in rows if r.status == "graded"]
    lines.append(f"{len(rows)} notebooks, {len(graded)} graded, {len(rows) - len(graded)} with problems")
    for r in rows:
        if r.status != "graded":
            lines.append(f"  {r.student}: {r.status}: {r.notes}")
    return "\n".join(lines)


def main(argv: list[str] | None = None) -> int:
    """Command line entry point (see the module docstring).

    Parameters
    ----------
    argv : list of str, optional
        The arguments (``sys.argv[1:]`` by default).

    Returns
    -------
    int
        The exit status: 0 when the folder was graded, 2 when it does not exist.

    Examples
    --------
    >>> main(["no/such/folder"])  # prints "error: no such folder: ..." on stderr
    2
    """
    ap = argparse.ArgumentParser(prog="python -m balancelab.course.grading",
                                 description="Grade a folder of submitted balancelab lab notebooks.")
    ap.add_argument("folder", nargs="?", help="folder of submitted notebooks")
    ap.add_argument("--out", default="grades.csv", help="CSV file to write (default grades.csv)")
    ap.add_argument("--lab", default=None, help="force the lab (e.g. lab2); default: from each notebook")
    ap.add_argument("--cell-timeout", type=int, default=60, help="per-cell time limit in s (default 60)")
    ap.add_argument("--notebook-timeout", type=int, default=600,
                    help="limit for a whole notebook in s (default 600)")
    ap.add_argument("--worker", default=None, help=argparse.SUPPRESS)
    args = ap.parse_args(argv)
    if args.worker:
        res = _worker(Path(args.worker), args.lab, args.cell_timeout)
        print(RESULT_MARK + json.dumps(res), flush=True)
        return 0
    if not args.folder:
        ap.error("give the folder of submissions")
    try:
        rows = grade_folder(args.folder, lab=args.lab, cell_timeout=args.cell_timeout,
                            notebook_timeout=args.notebook_timeout, progress=True)
    except FileNotFoundError as e:
        print(f"error: {e}", file=sys.stderr)
        return 2
    write_csv(rows, args.out)
    print(summary(rows))
    print(f"wrote {args.out}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
