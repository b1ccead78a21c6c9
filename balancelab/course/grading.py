"""Grade a folder of submitted lab notebooks in one command, with grades the student cannot fake.

::

    python -m balancelab.course.grading submissions/ --out grades.csv --jobs 2
    python -m balancelab.course.grading submissions/ --shard 1/4 --out part1.csv   # on machine 1 of 4
    python -m balancelab.course.grading merge part*.csv --out grades.csv

Each ``*.ipynb`` under the folder is graded by a child process of its own (the runner,
:mod:`balancelab.course.runner`) with a memory, CPU and wall-clock limit:

1. **untrusted**: the runner starts a fresh kernel **inside the sandbox**
   (:mod:`balancelab.course.sandbox`: bubblewrap, nothing of the host but what a kernel needs,
   no network, capped memory, processes and in-memory folders, :mod:`balancelab.course.caps`),
   runs the notebook's cells in it and, after every cell, asks the kernel for every answer
   variable as plain data (numbers, strings, sympy ``srepr``, a design as its joints, loads and
   springs);
2. **trusted**: the runner (outside the sandbox, with the grader's own ``balancelab``) decodes
   that data without evaluating code and runs each task's judge on it, each under a time limit
   (:func:`~balancelab.course.check.check_data`, the same judge the student's ``check(...)``
   runs); designs are rebuilt on the task's own mechanism and their balance recomputed.

Nothing else of the student's kernel reaches the grade: a patched ``check``, a forged verdict,
a ``Design`` subclass with a faked report, a printed fake result, a killed runner or a written
file changes nothing (the report comes on a channel the kernel cannot reach; a runner that
dies gives status ``error`` and 0). A score never exceeds the task's points. The submission is
never modified; a link or a non-regular file is refused, not read.

Whose a submission is comes from ``--roster roster.csv`` (columns ``file``, ``student_id``) or
from its file name (``ID_labN.ipynb`` or ``ID/labN.ipynb``), never from the notebook; personal
numbers are that student's. Roster rows that match no file or several files, and ids given to
several files of one lab, are warned about (stderr and the printed summary).

The result is one row per notebook (written as each notebook finishes): the student id it was
judged with (``student_id``: roster or file name), lab, status, total,
max, the score of each task, notes, the lab mismatch flag, each task's verdict message, the
wall time, the peak memory and the check attempts per task. A notebook that is not valid JSON,
crashes its kernel, loops, hits a cap or belongs to no known lab gets a row with a clear status
and never stops the batch.
"""
from __future__ import annotations

import argparse
import os
import re
import signal
import sys
import tempfile
import threading
import time
from typing import Any
from concurrent.futures import ThreadPoolExecutor, as_completed
from dataclasses import asdict, replace
from pathlib import Path

from . import check as _check
from .caps import Caps, Cgroup
from .gradetable import GradeRow, RowWriter, merge_csv, read_csv, summary, write_csv
from .sanitize import excerpt
from .check.core import student_key
from .intake import (MAX_NOTEBOOK, cheat_notes, find_submissions, identity, lab_sources, read_regular, read_roster,
                     resolve_lab, roster_problems)
from .sandbox import NO_SANDBOX_WARNING, font_list, kernel_runs_as_nobody, precompile_package, sandbox_available
from .workers import ACTIVE, SCRATCH_PREFIX, clean_stale, forked_runner, remove_tree, scratch_root, stop_on_signal  # noqa: F401

__all__ = ["STUDENT_VARIABLE", "GradeRow", "grade_namespace", "grade_answers", "resolve_lab", "grade_notebook", "derive_refusals",
           "grade_folder", "shard", "write_csv", "read_csv", "merge_csv", "summary", "main"]


STUDENT_VARIABLE = "STUDENT_ID"
#: Largest attempt count a row records for one task (the kernel reports the counts).
ATTEMPTS_CAP = 10 ** 6


def grade_answers(answers: dict, lab: str, student: str = "") -> dict:
    """Check every task of ``lab`` on exported answer data (variable -> encoded value), in this process.

    The grader itself judges in its runner process, each task under a time limit
    (:func:`~balancelab.course.runner.judge_tasks`); this is for trusted data.

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
    >>> r = grade_answers({"k_lamp": {"num": "12"}}, "lab2")
    >>> r["2.1"]["score"], r["2.2"]["message"]
    (0.0, 'no answer: variable `lever_conditions` is not defined')
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
    >>> r = grade_namespace({"k_lamp": 12.0}, "lab2")
    >>> r["2.1"]["score"], r["2.2"]["message"]
    (0.0, 'no answer: variable `lever_conditions` is not defined')
    """
    from .check.data import encode_answer

    variables = {t.variable for t in _check.tasks(lab)}
    sid = namespace.get(STUDENT_VARIABLE, "")
    return grade_answers({v: encode_answer(namespace[v]) for v in variables if v in namespace}, lab,
                         sid if isinstance(sid, str) else "")


def _parse_notebook(data: bytes):
    sys.modules.setdefault("rfc3987_syntax", None)  # type: ignore[arg-type]  # None blocks the import: jsonschema's 4 s IRI grammar: no IRI is validated here
    import nbformat

    try:
        nb = nbformat.reads(data.decode("utf-8"), as_version=4)
        nbformat.validate(nb)
        return nb, ""
    except Exception as e:  # not UTF-8, not JSON, not a notebook, wrong schema
        return None, f"not a valid notebook: {type(e).__name__}: {excerpt(str(e).splitlines()[0] if str(e) else '', 80)}"


def _runner(copy: Path, lab: str, sid: str, cell_timeout: int, wall: float, caps: Caps, sandbox: bool,
            scratch: Path, notebook_timeout: float | None = None) -> tuple[list[dict], str, Cgroup]:
    """Start the runner for one notebook; its report lines and how it ended."""
    share = scratch / "ipc"
    share.mkdir()
    cgroup = Cgroup(caps)
    job = dict(notebook=str(copy), lab=lab, student=sid, share=str(share), cell_timeout=cell_timeout,
               caps=asdict(caps), cgroup={k: str(v) for k, v in cgroup.dirs.items()}, no_sandbox=not sandbox,
               scratch=str(scratch), notebook_timeout=notebook_timeout,
               as_nobody=bool(sandbox and kernel_runs_as_nobody()),  # probed once, here
               fonts=font_list() if sandbox else None)  # built once, here
    lines, ended, _ = forked_runner(job, wall, int(wall) + 30)
    return lines, ended, cgroup


def _run(path_data: bytes, lab: str, sid: str, cell_timeout: int, notebook_timeout: int,
         sandbox: bool, caps: Caps):
    """Run and judge one notebook; ``(status, results, notes, extra)`` (results: task id -> dict)."""
    scratch = Path(tempfile.mkdtemp(prefix=f"{SCRATCH_PREFIX}{os.getpid()}-", dir=scratch_root()))
    cgroup = None
    try:
        copy = scratch / "submission.ipynb"
        copy.write_bytes(path_data)
        ntasks = len(_check.tasks(lab))
        wall = notebook_timeout + ntasks * caps.judge_seconds + 60
        wall += cell_timeout + 30  # the runner stops itself first (a cell interrupted at the limit, its export)
        lines, ended, cgroup = _runner(copy, lab, sid, cell_timeout, wall, caps, sandbox, scratch, notebook_timeout)
        run = next((x["run"] for x in lines if isinstance(x.get("run"), dict)), None)
        results = {x["task"]["id"]: x["task"] for x in lines if isinstance(x.get("task"), dict)}
        peak = cgroup.peak()
        hits = cgroup.hits()
        extra: dict[str, Any] = dict(peak=peak, attempts={})
        if run is None:
            why = ended or "the runner stopped before reporting"
            return "error", {}, [f"{why}: nothing was graded (0 points)"] + \
                ([f"{h} cap reached" for h in hits]), extra
        status = run.get("status") if run.get("status") in ("graded", "timeout", "kernel died", "error") else "error"
        notes = [str(x) for x in run.get("errors", []) + run.get("notes", [])]
        if isinstance(run.get("declared"), str):
            extra["declared"] = run["declared"]
        if run.get("peak") and not peak:
            extra["peak"] = run["peak"]
        known = {t.id for t in _check.tasks(lab)}  # the keys come from the kernel: only task ids, counts capped
        extra["attempts"] = {k: min(max(int(v), 0), ATTEMPTS_CAP) for k, v in run.get("attempts", {}).items()
                             if k in known and isinstance(v, int) and not isinstance(v, bool)}
        missing = [t.id for t in _check.tasks(lab) if t.id not in results]
        if missing:
            notes.append(f"{ended or 'the runner stopped'} while checking task {missing[0]}: "
                         f"task{'s' if len(missing) > 1 else ''} {', '.join(missing)} not graded (0 points)")
        return status, results, notes, extra
    finally:
        if cgroup is not None:
            cgroup.remove()
        remove_tree(scratch)


def _unknown_lab_note(nb, path: Path, lab: str | None) -> str:
    """Why no known lab was found, naming exactly what each source said."""
    said = [f"{k} says {excerpt(v, 40)}" for k, v in zip(("the file name", "the notebook's metadata", "--lab"),
                                                         lab_sources(nb, path, lab)) if v]
    return ("cannot tell which lab this is (" + ("; ".join(said) + ", which is no lab of this course" if said else
            "no 'labN' in the file name, no balancelab.lab metadata") + "); rename the file ID_labN.ipynb or pass --lab")


def _lab_mismatch_note(nb, path: Path, lab: str | None, graded_as: str, mismatch: str) -> str:
    """The row note of a lab that the sources disagree on: which source decided, what the others said."""
    from_name, from_meta, forced = lab_sources(nb, path, lab)
    decided = "--lab" if forced else "the file name" if from_name else "the notebook's metadata"
    if from_meta and from_meta != graded_as and decided == "the file name":
        return (f"lab mismatch: the notebook's metadata says {excerpt(from_meta, 40)} but the file name says "
                f"{graded_as}: graded as {graded_as} (the file name decides, not the notebook)")
    return f"lab mismatch ({excerpt(mismatch, 120)}): graded as {graded_as} ({decided} decides)"


def _refused(student: str, why: str, sid: str) -> GradeRow:
    return GradeRow(student, "", "refused", notes=f"not graded: {why}", student_id=sid)


def grade_notebook(path: str | Path, *, lab: str | None = None, cell_timeout: int = 60,
                   notebook_timeout: int = 600, student: str | None = None, student_id: str | None = None,
                   sandbox: bool | None = None, caps: Caps | None = None, id_source: str = "given") -> GradeRow:
    """Grade one submitted notebook: run it in the sandbox, judge its exported answers outside.

    Parameters
    ----------
    path : str or Path
        The submission (read only; a link or a non-regular file is refused).
    lab : str, optional
        Force the lab (``"lab2"`` or ``"2"``); otherwise read from the notebook's
        ``balancelab.lab`` metadata or a ``labN`` in its file name. Disagreements are flagged.
    cell_timeout : int
        Per-cell limit (s); a looping cell is interrupted, one that does not stop is killed.
    notebook_timeout : int
        Limit for running the whole notebook (s); checking the answers has its own limit.
    student : str, optional
        Name for the row (default: the file name without suffix).
    student_id : str, optional
        Whose personal numbers to judge with (default: from the file name, see
        :func:`~balancelab.course.intake.identity`); never taken from the notebook.
    sandbox : bool, optional
        Force the sandbox on or off (default: on when bubblewrap works).
    caps : Caps, optional
        The submission's caps (:class:`~balancelab.course.caps.Caps`).
    id_source : str
        Where ``student_id`` came from (for the row's note).

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
    start = time.monotonic()
    path = Path(path)
    student = student or path.stem
    sid, how = (student_key(student_id), id_source) if student_id is not None else identity(path.name, None)
    try:
        data = read_regular(path, MAX_NOTEBOOK)
    except OSError as e:
        return _refused(student, str(e) if isinstance(e, PermissionError) else f"cannot be read ({type(e).__name__})",
                        sid)
    nb, problem = _parse_notebook(data)
    lb, mismatch = resolve_lab(nb or {}, path, lab)
    known = {t.lab for t in _check.tasks()}
    points = {t.id: float(t.points) for t in _check.tasks(lb)} if lb in known else {}
    zero = {t: 0.0 for t in points}
    if nb is None:
        return GradeRow(student, lb if lb in known else "", "malformed", zero, points, problem, mismatch=mismatch,
                        student_id=sid)
    if lb not in known:
        return GradeRow(student, "", "unknown lab", notes=_unknown_lab_note(nb, path, lab), mismatch=mismatch,
                        student_id=sid)
    use = sandbox_available() if sandbox is None else sandbox
    precompile_package()  # once per grader: else every kernel compiles balancelab again
    status, results, run_notes, extra = _run(data, lb, sid, cell_timeout, notebook_timeout, use, caps or Caps())
    notes = cheat_notes(nb) + ([] if use else ["NO SANDBOX (bubblewrap missing or turned off): the kernel ran with "
                                               "resource limits only"])
    personal = {t.id for t in _check.tasks(lb) if t.numbers is not None}
    if not sid:   # never the published numbers: their answers are public (site, package, classmates)
        notes.append(f"NO STUDENT ID ({how}): the tasks with personal numbers ({', '.join(sorted(personal))}) "
                     "score 0; rename the file ID_labN.ipynb or list it in --roster, then grade it again")
        status = "unidentified" if status == "graded" else status
    elif "check whose" in how:  # the folder and the file name name different students
        notes.append(f"judged as {excerpt(repr(sid), 40)}: {how}")
    declared = extra.get("declared")
    if declared and student_key(declared) != sid:
        notes.append(f"the notebook declares STUDENT_ID {excerpt(repr(declared), 40)} but is "
                     f"{sid!r}'s ({how}): judged with {sid!r}'s numbers" if sid else
                     f"the notebook declares STUDENT_ID {excerpt(repr(declared), 40)}: ignored")
    notes += [excerpt(n, 300) for n in run_notes[:20]]
    if mismatch:
        notes.insert(0, _lab_mismatch_note(nb, path, lab, lb, mismatch))
    scores = {tid: float(results[tid]["score"]) if tid in results and (sid or tid not in personal) else 0.0
              for tid in points}
    scores = {tid: min(max(v, 0.0), points[tid]) if v == v else 0.0 for tid, v in scores.items()}
    messages = {tid: ("✔ " if results[tid].get("correct") else "✘ ") + excerpt(results[tid].get("message", ""), 200)
                for tid in points if tid in results}
    for tid, found in derive_refusals(nb, lb).items():  # as the notebook's own check refuses them
        scores[tid] = 0.0
        messages[tid] = (f"✘ Task {tid} is to be derived by hand, and the cell that checks it calls "
                         f"{', '.join(found)}")
    peak = extra.get("peak")
    return GradeRow(student, lb, status, scores, points, "; ".join(notes), messages, mismatch,
                    round(time.monotonic() - start, 2), round(peak / 2 ** 20, 1) if peak else None,
                    extra.get("attempts", {}), sid)


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


def derive_refusals(nb: dict, lab: str) -> dict[str, list[str]]:
    """The derive tasks of ``lab`` whose checking cell calls a library shortcut, and the names it calls.

    The grader applies the same rule as the notebook's :func:`~balancelab.course.check.check` (which
    reads the running cell): the code cell holding ``check("n.m", ...)`` is read with
    :func:`~balancelab.course.check.derive.shortcuts`.

    Parameters
    ----------
    nb : dict
        The submitted notebook.
    lab : str
        ``"lab1"`` ...

    Returns
    -------
    dict
        Task id -> disallowed names found (only tasks with some).

    Examples
    --------
    >>> import nbformat
    >>> cell = nbformat.v4.new_code_cell('a_y, k = d.balance_conditions()\\ncheck("2.2", (a_y, k))')
    >>> derive_refusals(nbformat.v4.new_notebook(cells=[cell]), "lab2")
    {'2.2': ['balance_conditions']}
    """
    from .check.derive import shortcuts

    out: dict[str, list[str]] = {}
    derive = [t.id for t in _check.tasks(lab) if getattr(t, "skill", None) == "derive"]
    for cell in nb.get("cells", []) if isinstance(nb, dict) else []:
        if not isinstance(cell, dict) or cell.get("cell_type") != "code":
            continue
        src = cell.get("source", "")
        src = src if isinstance(src, str) else "".join(s for s in src if isinstance(s, str))
        for tid in derive:
            if re.search(r"""\bcheck\(\s*["']""" + re.escape(tid) + r"""["']""", src):
                found = shortcuts(tid, src)
                if found:
                    out.setdefault(tid, []).extend(n for n in found if n not in out.get(tid, []))
    return out


def _failed_row(name: str, path: Path, lab: str | None, error: Exception, sid: str = "") -> GradeRow:
    """The row of a notebook the grader failed on: its lab (from ``--lab`` or the file name) and that
    lab's points, all 0, so that a table's percentages stay defined."""
    forced, from_name = lab_sources({}, path, lab)[2], lab_sources({}, path, lab)[0]
    lb = forced or from_name or ""
    points = {t.id: float(t.points) for t in _check.tasks(lb)} if lb in {t.lab for t in _check.tasks()} else {}
    return GradeRow(name, lb, "error", {t: 0.0 for t in points}, points,
                    notes=f"the grader failed on this notebook ({type(error).__name__}); scores 0", student_id=sid)


def grade_folder(folder: str | Path, *, lab: str | None = None, cell_timeout: int = 60,
                 notebook_timeout: int = 600, progress: bool = False, jobs: int = 1,
                 shard_spec: str | None = None, sandbox: bool | None = None, roster: dict | None = None,
                 out: str | Path | None = None, caps: Caps | None = None,
                 warnings: list[str] | None = None) -> list[GradeRow]:
    """Grade every ``*.ipynb`` under ``folder`` (checkpoints skipped, links refused), one row each.

    Parameters
    ----------
    folder : str or Path
        Folder of submissions (searched recursively, links never followed).
    lab, cell_timeout, notebook_timeout, sandbox, caps
        As in :func:`grade_notebook`.
    progress : bool
        Print one line per notebook as it is graded.
    jobs : int
        Notebooks graded at the same time (>= 1).
    shard_spec : str, optional
        ``"i/n"``: grade only that share of the folder (see :func:`shard`).
    roster : dict, optional
        Submission file -> student id (:func:`~balancelab.course.intake.read_roster`); without
        it the id is read from the file name (:func:`~balancelab.course.intake.identity`).
    out : str or Path, optional
        CSV written row by row as notebooks finish (then rewritten compactly at the end).
    warnings : list, optional
        Extended with the batch's problems (a roster row that matches no file or several, an id
        given to several files of one lab: :func:`~balancelab.course.intake.roster_problems`),
        which are also printed on stderr.

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
    every = find_submissions(folder)
    files = shard(every, shard_spec)
    problems = roster_problems([str(p.relative_to(folder)) for p in every], roster) if roster is not None else []
    for w in problems:
        print(f"WARNING: {excerpt(w, 300)}", file=sys.stderr, flush=True)
    if warnings is not None:
        warnings += problems
    if sandbox is None and not sandbox_available():
        print(f"WARNING: {NO_SANDBOX_WARNING}", file=sys.stderr, flush=True)
    clean_stale()
    Cgroup.clean_stale()
    writer = RowWriter(out) if out is not None else None

    def one(p):
        rel = str(p.relative_to(folder))
        name = rel[:-len(".ipynb")]
        sid, how = identity(rel, roster)
        try:
            row = grade_notebook(p, lab=lab, cell_timeout=cell_timeout, notebook_timeout=notebook_timeout,
                                 student=name, student_id=sid, sandbox=sandbox, caps=caps, id_source=how)
        except Exception as e:  # never stop the batch
            row = _failed_row(name, p, lab, e, sid)
        if progress:
            print(f"graded {excerpt(name, 80)}: {row.status}, {row.total:g}/{row.max_total:g}", flush=True)
        return row

    rows, owners = {}, _duplicate_ids(folder, files, roster)
    try:
        with ThreadPoolExecutor(max_workers=jobs) as pool:
            futures = {pool.submit(one, p): p for p in files}
            for fut in as_completed(futures):
                rows[futures[fut]] = row = fut.result()
                if futures[fut] in owners:
                    row.notes = "; ".join(x for x in (owners[futures[fut]], row.notes) if x)
                if writer is not None:
                    writer.add(row)
    finally:
        if writer is not None:
            writer.close()
    return [rows[p] for p in files if p in rows]


def _duplicate_ids(folder: Path, files: list, roster) -> dict:
    """A note for every submission whose student id another submission of the same lab also has
    (file -> note); the lab is the one the file name names (``""`` when it names none)."""
    groups: dict = {}
    for p in files:
        rel = str(p.relative_to(folder))
        sid, _ = identity(rel, roster)
        lab = lab_sources({}, p)[0] or ""
        if sid:
            groups.setdefault((sid, lab), []).append(rel)
    out = {}
    for (sid, _), rels in groups.items():
        if len(rels) > 1:
            for p in rels:
                others = ", ".join(excerpt(r, 60) for r in rels if r != p)
                out[folder / p] = f"DUPLICATE ID {excerpt(sid, 40)!r}: also {excerpt(others, 200)}"
    return out


def _parser() -> argparse.ArgumentParser:
    ap = argparse.ArgumentParser(prog="python -m balancelab.course.grading",
                                 description="Grade a folder of submitted balancelab lab notebooks "
                                             "(or: merge A.csv B.csv ... --out all.csv).")
    ap.add_argument("folder", nargs="*", help="folder of submitted notebooks (or 'merge' and CSV files)")
    ap.add_argument("--out", default="grades.csv", help="CSV file to write (default grades.csv)")
    ap.add_argument("--lab", default=None, help="force the lab (e.g. lab2); default: from each notebook")
    ap.add_argument("--roster", default=None, help="CSV with columns file,student_id (default: the id is "
                                                   "the file name's ID in ID_labN.ipynb or ID/labN.ipynb)")
    ap.add_argument("--cell-timeout", type=int, default=60, help="per-cell time limit in s (default 60)")
    ap.add_argument("--notebook-timeout", type=int, default=600,
                    help="limit for a whole notebook in s (default 600)")
    ap.add_argument("--jobs", type=int, default=1, help="notebooks graded in parallel (default 1)")
    ap.add_argument("--shard", default=None, help="grade only share i of n of the folder, e.g. 2/8")
    ap.add_argument("--memory-mb", type=int, default=None, help="memory cap of one submission's processes "
                                                                "(default 2048)")
    ap.add_argument("--judge-timeout", type=float, default=None, help="time to check one answer in s (default 20)")
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
            merge_csv(args.folder[1:], args.out, read_roster(args.roster) if args.roster else None)
        except (OSError, ValueError, KeyError) as e:
            print(f"error: {e}", file=sys.stderr)
            return 2
        print(f"merged {len(args.folder) - 1} tables into {args.out}")
        return 0
    if len(args.folder) != 1:
        ap.error("give one folder of submissions")
    caps = Caps()
    if args.memory_mb is not None:
        caps = replace(caps, memory=args.memory_mb * 2 ** 20)
    if args.judge_timeout is not None:
        caps = replace(caps, judge_seconds=args.judge_timeout)
    try:
        roster = read_roster(args.roster) if args.roster else None
        if not Path(args.folder[0]).is_dir():
            raise FileNotFoundError(f"no such folder: {args.folder[0]}")
        if threading.current_thread() is threading.main_thread():
            for sig in (signal.SIGTERM, signal.SIGINT, signal.SIGHUP):
                signal.signal(sig, stop_on_signal)
        warnings: list[str] = []
        rows = grade_folder(args.folder[0], lab=args.lab, cell_timeout=args.cell_timeout,
                            notebook_timeout=args.notebook_timeout, progress=True, jobs=args.jobs,
                            shard_spec=args.shard, sandbox=False if args.no_sandbox else None, roster=roster,
                            out=args.out, caps=caps, warnings=warnings)
    except (FileNotFoundError, ValueError, OSError) as e:
        print(f"error: {e}", file=sys.stderr)
        return 2
    print(summary(rows, warnings))
    print(f"wrote {args.out}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
