"""Grade a folder of submitted lab notebooks in one command, with grades the student cannot fake.

::

    python -m balancelab.course.grading submissions/ --out grades.csv --jobs 2
    python -m balancelab.course.grading submissions/ --shard 1/4 --out part1.csv   # on machine 1 of 4
    python -m balancelab.course.grading merge part*.csv --out grades.csv

Each ``*.ipynb`` under the folder is graded in two halves:

1. **untrusted**: the notebook is copied to a fresh scratch folder and run by
   :mod:`balancelab.course.runner` inside the sandbox (:mod:`balancelab.course.sandbox`:
   bubblewrap, writes only to the scratch folder, no network, the whole process group killed
   at the limits), which exports every answer variable as plain data (numbers, strings, sympy
   ``srepr``, a design as its joints, loads and springs) after every cell;
2. **trusted**: this process, which imported the grader's own ``balancelab``, decodes that
   data without evaluating code and runs each task's judge on it
   (:func:`~balancelab.course.check.check_data`, the same judge the student's ``check(...)``
   runs); designs are rebuilt on the task's own mechanism and their balance recomputed here.

Nothing else of the student's kernel reaches the grade: a patched ``check``, a forged verdict
or a ``Design`` subclass with a faked report changes nothing. A score never exceeds the
task's points. The submission is never modified.

The result is one row per notebook: lab, status, total, max, the score of each task, notes,
the lab mismatch flag and each task's verdict message. A notebook that is not valid JSON,
crashes its kernel, loops or belongs to no known lab gets a row with a clear status (the lab
and maximum kept whenever the lab is known) and never stops the batch.
"""
from __future__ import annotations

import argparse
import ast
import json
import os
import re
import shutil
import sys
import tempfile
import time
import warnings
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path

from . import check as _check
from .gradetable import GradeRow, merge_csv, read_csv, summary, write_csv
from .runner import ANSWERS_FILE, RESULT_MARK
from .sandbox import NO_SANDBOX_WARNING, run_limited, sandbox_available

__all__ = ["STUDENT_VARIABLE", "GradeRow", "grade_namespace", "grade_answers", "resolve_lab", "grade_notebook", "grade_folder",
           "shard", "write_csv", "read_csv", "merge_csv", "summary", "main"]


STUDENT_VARIABLE = "STUDENT_ID"


def grade_answers(answers: dict, lab: str, student: str = "") -> dict:
    """Check every task of ``lab`` on exported answer data (variable -> encoded value).

    Parameters
    ----------
    answers : dict
        Variable name -> data from :func:`~balancelab.course.check.data.encode_answer`.
    lab : str
        E.g. ``"lab2"``.
    student : str
        The student whose personal numbers the tasks that have them are judged with (``""``:
        the published numbers).

    Returns
    -------
    dict
        Task id -> ``{"score", "points", "correct", "message"}``; a score is at most the
        task's points.

    Examples
    --------
    >>> r = grade_answers({"k_lamp": {"num": "196.2"}}, "lab2")
    >>> r["2.1"]["score"], r["2.2"]["message"]
    (1.0, 'no answer: variable `lever_conditions` is not defined')
    """
    out = {}
    for t in _check.tasks(lab):
        if not isinstance(answers, dict) or t.variable not in answers:
            out[t.id] = dict(score=0.0, points=float(t.points), correct=False,
                             message=f"no answer: variable `{t.variable}` is not defined")
            continue
        v = _check.check_data(t.id, answers[t.variable], student)
        score = min(max(float(v.score), 0.0), float(t.points)) if v.correct else 0.0
        out[t.id] = dict(score=score, points=float(t.points), correct=bool(v.correct), message=v.message)
    return out


def grade_namespace(namespace: dict, lab: str) -> dict:
    """Check every task of ``lab`` against the answer variables of a namespace (formative use).

    Parameters
    ----------
    namespace : dict
        E.g. a notebook's ``globals()``.
    lab : str
        E.g. ``"lab2"``.

    Returns
    -------
    dict
        As :func:`grade_answers` (the answers are encoded first, as the grader does).

    Examples
    --------
    >>> r = grade_namespace({"k_lamp": 196.2}, "lab2")
    >>> r["2.1"]["score"], r["2.2"]["message"]
    (1.0, 'no answer: variable `lever_conditions` is not defined')
    """
    from .check.data import encode_answer

    variables = {t.variable for t in _check.tasks(lab)}
    sid = namespace.get(STUDENT_VARIABLE, "")
    return grade_answers({v: encode_answer(namespace[v]) for v in variables if v in namespace}, lab,
                         sid if isinstance(sid, str) else "")


def _norm_lab(lab) -> str | None:
    if lab is None or str(lab).strip() == "":
        return None
    lab = str(lab).strip()
    return lab if lab.startswith("lab") else f"lab{lab}"


def resolve_lab(nb: dict, path: Path, lab: str | None = None) -> tuple[str | None, str]:
    """The lab of a notebook and what disagrees about it.

    ``--lab`` wins, then the notebook's ``balancelab.lab`` metadata, then ``labN`` in the
    file name; every source that names another lab is reported.

    Parameters
    ----------
    nb : dict
        The notebook.
    path : Path
        Its file.
    lab : str, optional
        The lab forced on the command line.

    Returns
    -------
    (str or None, str)
        The lab (None if unknown) and the mismatch text (empty if all sources agree).

    Examples
    --------
    >>> from pathlib import Path
    >>> resolve_lab({"metadata": {"balancelab": {"lab": "lab5"}}}, Path("ann_lab1.ipynb"))
    ('lab5', 'file name says lab1, metadata says lab5')
    """
    meta = nb.get("metadata", {}).get("balancelab", {}) if isinstance(nb, dict) else {}
    from_meta = _norm_lab(meta.get("lab")) if isinstance(meta, dict) else None
    m = re.search(r"lab[_\-]?(\d+)", path.name, re.IGNORECASE)
    from_name = f"lab{m.group(1)}" if m else None
    forced = _norm_lab(lab)
    sources = [("file name", from_name), ("metadata", from_meta), ("--lab", forced)]
    named = {v for _, v in sources if v}
    mismatch = ", ".join(f"{k} says {v}" for k, v in sources if v) if len(named) > 1 else ""
    return forced or from_meta or from_name, mismatch


_PATCH_NAMES = {"check", "check_data", "grade_answers", "grade_namespace", "balance_report", "judge", "Verdict"}


def _cheat_notes(nb) -> list[str]:
    """What the notebook's code replaces that the grader ignores anyway (reported, never trusted)."""
    found = set()
    for cell in nb.get("cells", []):
        if cell.get("cell_type") != "code":
            continue
        src = cell.get("source", "")
        src = src if isinstance(src, str) else "".join(src)
        try:
            tree = ast.parse("\n".join(ln for ln in src.splitlines() if not ln.lstrip().startswith(("%", "!"))))
        except SyntaxError:
            continue
        for node in ast.walk(tree):
            targets = (node.targets if isinstance(node, ast.Assign) else [node.target]
                       if isinstance(node, (ast.AugAssign, ast.AnnAssign)) else [])
            for t in targets:
                name = t.id if isinstance(t, ast.Name) else t.attr if isinstance(t, ast.Attribute) else None
                if name in _PATCH_NAMES:
                    found.add(f"replaces `{name}`")
            if isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef)) and node.name in _PATCH_NAMES:
                found.add(f"redefines `{node.name}`")
            if isinstance(node, ast.ClassDef) and any("Design" in ast.unparse(b) or "Verdict" in ast.unparse(b)
                                                      for b in node.bases):
                found.add(f"subclasses {', '.join(ast.unparse(b) for b in node.bases)}")
    if not found:
        return []
    return [f"the notebook {', '.join(sorted(found))}: ignored (the grader checks the exported answers itself)"]


def _read_notebook(path: Path):
    import nbformat

    try:
        nb = nbformat.read(path, as_version=4)
        nbformat.validate(nb)
        return nb, ""
    except Exception as e:  # not JSON, not a notebook, wrong schema
        first = str(e).splitlines()[0][:120] if str(e) else ""
        return None, f"not a valid notebook: {type(e).__name__}: {first}"


def _run(path: Path, lab: str, cell_timeout: int, notebook_timeout: int, sandbox: bool | None):
    """Run the notebook in the sandbox; ``(status, answers, notes)`` (answers are untrusted data)."""
    variables = [t.variable for t in _check.tasks(lab)] + [STUDENT_VARIABLE]
    root = os.environ.get("BALANCELAB_SCRATCH") or None
    scratch = Path(tempfile.mkdtemp(prefix="balancelab-grade-", dir=root))
    try:
        copy = scratch / "submission.ipynb"
        shutil.copyfile(path, copy)
        env = {**os.environ, "PYTHONUNBUFFERED": "1", "HOME": str(scratch),
               "JUPYTER_RUNTIME_DIR": str(scratch / ".runtime"), "IPYTHONDIR": str(scratch / ".ipython"),
               "MPLCONFIGDIR": str(scratch / ".mpl"), "MPLBACKEND": "Agg"}
        cmd = [sys.executable, "-m", "balancelab.course.runner", str(copy), "--vars", ",".join(variables),
               "--cell-timeout", str(cell_timeout)]
        with warnings.catch_warnings():
            warnings.simplefilter("ignore", RuntimeWarning)
            res = run_limited(cmd, scratch, notebook_timeout, env=env, sandbox=sandbox)
        notes = [] if res.sandboxed else ["NO SANDBOX (bubblewrap missing): ran with resource limits only"]
        data = None
        for line in res.stdout.splitlines():
            if line.startswith(RESULT_MARK):
                try:
                    data = json.loads(line[len(RESULT_MARK):])
                except ValueError:
                    data = None
        saved = _saved_answers(scratch / ANSWERS_FILE)
        if res.timed_out:
            return "timeout", saved, notes + [f"the notebook ran longer than {notebook_timeout} s in total and "
                                              "was killed; the answers given before are graded"]
        if not isinstance(data, dict):
            err = (res.stderr.strip().splitlines() or ["no output"])[-1][:200]
            return "error", saved, notes + [f"the notebook could not be run: {err}"]
        answers = data.get("answers") if isinstance(data.get("answers"), dict) else saved
        notes += [str(x)[:300] for x in list(data.get("errors", []))[:50] + list(data.get("notes", []))[:10]]
        status = data.get("status") if data.get("status") in ("graded", "timeout", "kernel died", "error") \
            else "error"
        return status, answers, notes
    finally:
        _remove(scratch)


def _remove(folder: Path) -> None:
    """Delete a scratch folder; a process of the sandbox that is still dying may write for a moment."""
    for _ in range(50):
        shutil.rmtree(folder, ignore_errors=True)
        if not folder.exists():
            return
        time.sleep(0.1)
    print(f"WARNING: could not delete the scratch folder {folder}", file=sys.stderr, flush=True)


def _saved_answers(path: Path) -> dict:
    try:
        data = json.loads(path.read_text(encoding="utf-8")[:10 ** 7])
    except (OSError, ValueError):
        return {}
    return data if isinstance(data, dict) else {}


def _student_id(answers: dict, name: str) -> tuple[str, list[str]]:
    """The ``STUDENT_ID`` a notebook declares (for personal numbers) and a note if the file disagrees."""
    from .check.data import decode_answer

    sid = decode_answer(answers.get(STUDENT_VARIABLE, {"str": ""})) if isinstance(answers, dict) else ""
    sid = sid.strip() if isinstance(sid, str) else ""
    if sid and sid.lower() not in name.lower():
        return sid, [f"STUDENT_ID {sid!r} does not appear in the submission's name {name!r}: personal "
                     "numbers graded as declared, check who handed this in"]
    return sid, []


def grade_notebook(path: str | Path, *, lab: str | None = None, cell_timeout: int = 60,
                   notebook_timeout: int = 600, student: str | None = None,
                   sandbox: bool | None = None) -> GradeRow:
    """Grade one submitted notebook: run it in the sandbox, check its exported answers here.

    Parameters
    ----------
    path : str or Path
        The submission (read only).
    lab : str, optional
        Force the lab (``"lab2"`` or ``"2"``); otherwise read from the notebook's
        ``balancelab.lab`` metadata or a ``labN`` in its file name. Disagreements are flagged.
    cell_timeout : int
        Per-cell limit (s); a looping cell is interrupted, one that ignores the interrupt is killed.
    notebook_timeout : int
        Limit for the whole notebook (s); past it the sandbox is killed.
    student : str, optional
        Name for the row (default: the file name without suffix).
    sandbox : bool, optional
        Force the sandbox on or off (default: on when bubblewrap works).

    Returns
    -------
    GradeRow

    Examples
    --------
    A file that is not a notebook gets a clear row (nothing is run for it):

    >>> import pathlib, tempfile
    >>> bad = pathlib.Path(tempfile.mkdtemp()) / "bob_lab2.ipynb"
    >>> _ = bad.write_text("{not json")
    >>> row = grade_notebook(bad)
    >>> row.status, row.total, row.max_total, row.notes.split(":")[0]
    ('malformed', 0.0, 5.0, 'not a valid notebook')
    """
    path = Path(path)
    student = student or path.stem
    nb, problem = _read_notebook(path)
    lb, mismatch = resolve_lab(nb or {}, path, lab)
    known = {t.lab for t in _check.tasks()}
    points = {t.id: float(t.points) for t in _check.tasks(lb)} if lb in known else {}
    zero = {t: 0.0 for t in points}
    if nb is None:
        return GradeRow(student, lb if lb in known else "", "malformed", zero, points, problem, mismatch=mismatch)
    if lb not in known:
        return GradeRow(student, lb or "", "unknown lab", notes="cannot tell which lab this is (no balancelab.lab "
                        "metadata, no 'labN' in the file name); pass --lab", mismatch=mismatch)
    status, answers, notes = _run(path, lb, cell_timeout, notebook_timeout, sandbox)
    sid, id_note = _student_id(answers, student)
    results = grade_answers(answers, lb, sid)
    notes = _cheat_notes(nb) + id_note + notes
    if mismatch:
        notes.insert(0, f"lab mismatch ({mismatch}): graded as {lb}")
    messages = {tid: ("✔ " if r["correct"] else "✘ ") + r["message"] for tid, r in results.items()}
    scores = {tid: results[tid]["score"] for tid in points}
    return GradeRow(student, lb, status, scores, points, "; ".join(notes), messages, mismatch)


def shard(files: list, spec: str | None) -> list:
    """The files of shard ``i/n`` (1-based): every n-th file of the sorted list, starting at the i-th.

    Parameters
    ----------
    files : list
        All submissions, sorted.
    spec : str or None
        ``"i/n"`` with ``1 <= i <= n``; None for all files.

    Returns
    -------
    list

    Examples
    --------
    >>> shard(list("abcde"), "2/2")
    ['b', 'd']
    >>> shard(list("abc"), "3/2")
    Traceback (most recent call last):
    ...
    ValueError: shard must be 'i/n' with 1 <= i <= n, got '3/2'
    """
    if spec is None:
        return list(files)
    m = re.fullmatch(r"\s*(\d+)\s*/\s*(\d+)\s*", str(spec))
    if not m or not 1 <= int(m.group(1)) <= int(m.group(2)):
        raise ValueError(f"shard must be 'i/n' with 1 <= i <= n, got {spec!r}")
    i, n = int(m.group(1)), int(m.group(2))
    return list(files)[i - 1::n]


def grade_folder(folder: str | Path, *, lab: str | None = None, cell_timeout: int = 60,
                 notebook_timeout: int = 600, progress: bool = False, jobs: int = 1,
                 shard_spec: str | None = None, sandbox: bool | None = None) -> list[GradeRow]:
    """Grade every ``*.ipynb`` under ``folder`` (checkpoints skipped), one row each.

    Parameters
    ----------
    folder : str or Path
        Folder of submissions (searched recursively).
    lab, cell_timeout, notebook_timeout, sandbox
        As in :func:`grade_notebook`.
    progress : bool
        Print one line per notebook as it is graded.
    jobs : int
        Notebooks graded at the same time (>= 1).
    shard_spec : str, optional
        ``"i/n"``: grade only that share of the folder (see :func:`shard`).

    Returns
    -------
    list of GradeRow
        In file order.

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
    if not isinstance(jobs, int) or jobs < 1:
        raise ValueError(f"jobs must be an integer >= 1, got {jobs!r}")
    files = shard(sorted(p for p in folder.rglob("*.ipynb") if ".ipynb_checkpoints" not in p.parts), shard_spec)
    if sandbox is None and not sandbox_available():
        print(f"WARNING: {NO_SANDBOX_WARNING}", file=sys.stderr, flush=True)

    def one(p):
        name = str(p.relative_to(folder).with_suffix(""))
        row = grade_notebook(p, lab=lab, cell_timeout=cell_timeout, notebook_timeout=notebook_timeout,
                             student=name, sandbox=sandbox)
        if progress:
            print(f"graded {name}: {row.status}, {row.total:g}/{row.max_total:g}", flush=True)
        return row

    with ThreadPoolExecutor(max_workers=jobs) as pool:
        return list(pool.map(one, files))


def _parser() -> argparse.ArgumentParser:
    ap = argparse.ArgumentParser(prog="python -m balancelab.course.grading",
                                 description="Grade a folder of submitted balancelab lab notebooks "
                                             "(or: merge A.csv B.csv ... --out all.csv).")
    ap.add_argument("folder", nargs="*", help="folder of submitted notebooks (or 'merge' and CSV files)")
    ap.add_argument("--out", default="grades.csv", help="CSV file to write (default grades.csv)")
    ap.add_argument("--lab", default=None, help="force the lab (e.g. lab2); default: from each notebook")
    ap.add_argument("--cell-timeout", type=int, default=60, help="per-cell time limit in s (default 60)")
    ap.add_argument("--notebook-timeout", type=int, default=600,
                    help="limit for a whole notebook in s (default 600)")
    ap.add_argument("--jobs", type=int, default=1, help="notebooks graded in parallel (default 1)")
    ap.add_argument("--shard", default=None, help="grade only share i of n of the folder, e.g. 2/8")
    ap.add_argument("--no-sandbox", action="store_true", help="run without bubblewrap (trusted work only)")
    return ap


def main(argv: list[str] | None = None) -> int:
    """Command line entry point (see the module docstring).

    Parameters
    ----------
    argv : list of str, optional
        The arguments (``sys.argv[1:]`` by default).

    Returns
    -------
    int
        The exit status: 0 when the folder was graded, 2 when it does not exist or an
        argument is wrong.

    Examples
    --------
    >>> main(["no/such/folder"])  # prints "error: no such folder: ..." on stderr
    2
    """
    ap = _parser()
    args = ap.parse_args(argv)
    if args.folder[:1] == ["merge"]:
        try:
            merge_csv(args.folder[1:], args.out)
        except (OSError, ValueError, KeyError) as e:
            print(f"error: {e}", file=sys.stderr)
            return 2
        print(f"merged {len(args.folder) - 1} tables into {args.out}")
        return 0
    if len(args.folder) != 1:
        ap.error("give one folder of submissions")
    try:
        rows = grade_folder(args.folder[0], lab=args.lab, cell_timeout=args.cell_timeout,
                            notebook_timeout=args.notebook_timeout, progress=True, jobs=args.jobs,
                            shard_spec=args.shard, sandbox=False if args.no_sandbox else None)
    except (FileNotFoundError, ValueError) as e:
        print(f"error: {e}", file=sys.stderr)
        return 2
    write_csv(rows, args.out)
    print(summary(rows))
    print(f"wrote {args.out}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
