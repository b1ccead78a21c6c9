"""The grade table: one :class:`GradeRow` per submission, written and read as CSV, merged, summarized.

Used by :mod:`balancelab.course.grading`; a CSV written on one machine (one shard of a class)
merges with the others' (:func:`merge_csv`).
"""
from __future__ import annotations

import csv
import os
import re
from dataclasses import dataclass, field
from pathlib import Path

from . import check as _check
from .intake import identity
from .sanitize import excerpt

__all__ = ["GradeRow", "write_csv", "read_csv", "merge_csv", "summary", "cell", "RowWriter"]


_FORMULA = ("=", "+", "-", "@", "\t", "\r")


def cell(value) -> str:
    """A CSV cell that a spreadsheet shows as text and a terminal prints as text.

    One that starts like a formula gets a ``'``; control characters (an escape sequence or a line
    break in a file name) are written as their escapes (``\\x1b``, ``\\n``), so ``cat grades.csv``
    runs nothing and every record stays on one line.

    Parameters
    ----------
    value : object

    Returns
    -------
    str

    Examples
    --------
    >>> cell("=1+2*3_lab1"), cell("@SUM(A1)"), cell("alice")
    ("'=1+2*3_lab1", "'@SUM(A1)", 'alice')
    >>> print(cell("x" + chr(27) + "[2J" + chr(10) + "FAKE_lab1"))
    x\\x1b[2J\\nFAKE_lab1
    """
    s = str(value)
    s = "'" + s if s.startswith(_FORMULA) else s
    return "".join(c if c.isprintable() else repr(c)[1:-1] for c in s)


def _uncell(s: str) -> str:
    return s[1:] if s[:1] == "'" and s[1:2] in _FORMULA else s


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
    messages : dict
        Task id -> the verdict (``"✔ ..."`` or ``"✘ ..."``) with its message.
    mismatch : str
        What disagrees about the lab (file name, notebook metadata, ``--lab``); empty if nothing.
    seconds : float or None
        Wall time of grading the notebook (s).
    peak_mb : float or None
        Peak memory of the submission's processes (MB).
    attempts : dict
        Task id -> number of ``check(...)`` calls the notebook made, as its kernel reported them
        (column ``reported_attempts``: the notebook's word, sanitized, never a measurement).
    student_id : str
        The id the grade was judged with (its personal numbers), from the roster or the file
        name, never from the notebook; ``""`` when none could be established. Written as the
        column after ``student``.

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
    messages: dict = field(default_factory=dict)
    mismatch: str = ""
    seconds: float | None = None
    peak_mb: float | None = None
    attempts: dict = field(default_factory=dict)
    student_id: str = ""

    @property
    def total(self) -> float:
        return float(sum(self.scores.values()))

    @property
    def max_total(self) -> float:
        return float(sum(self.points.values()))


def _task_columns(rows) -> list[str]:
    order = [t.id for t in _check.tasks()]
    used = {tid for r in rows for tid in r.points}
    extra = sorted(used - set(order))
    return [t for t in order if t in used] + extra


#: The last columns. ``seconds`` and ``peak_mb`` are the grader's own measurements; the check counts
#: are only what the notebook's kernel reported (it can reset or forge them), hence the column's name.
ATTEMPTS_COLUMN = "reported_attempts"
_EXTRA = ["seconds", "peak_mb", ATTEMPTS_COLUMN]


def _header(cols: list[str]) -> list[str]:
    return (["student", "student_id", "lab", "status", "total", "max"] + cols + ["notes", "mismatch"]
            + [f"{c} message" for c in cols] + _EXTRA)


def _attempts(counts: dict) -> dict:
    """Attempt counts as a table holds them: task ids (``N.M``) only, counts from 0 to 10**6."""
    out = {}
    for k, v in counts.items():
        try:
            v = int(v)
        except (TypeError, ValueError, OverflowError):
            continue
        if isinstance(k, str) and re.fullmatch(r"\d{1,3}\.\d{1,3}", k):
            out[k] = min(max(v, 0), 10 ** 6)
    return out


def _record(r: GradeRow, cols: list[str]) -> list[str]:
    num = lambda x: "" if x is None else f"{x:g}"  # noqa: E731
    attempts = " ".join(f"{k}:{v}" for k, v in sorted(_attempts(r.attempts).items()))
    return [cell(x) for x in [r.student, r.student_id, r.lab, r.status, f"{r.total:g}", f"{r.max_total:g}"]
            + [f"{r.scores[c]:g}" if c in r.scores else "" for c in cols] + [r.notes, r.mismatch]
            + [r.messages.get(c, "") for c in cols] + [num(r.seconds), num(r.peak_mb), attempts]]


def write_csv(rows: list[GradeRow], path: str | Path) -> Path:
    """Write the grade table: student, lab, status, total, max, a score column per task, notes,
    the lab mismatch, one verdict message column per task (``"2.1 message"``), then the wall time,
    peak memory and the check attempts the notebook reported. A cell that starts like a formula is escaped (:func:`cell`).

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
    >>> rows = [GradeRow("alice", "lab2", "graded", {"2.1": 1.0}, {"2.1": 1.0}, messages={"2.1": "✔ ok"})]
    >>> path = write_csv(rows, pathlib.Path(tempfile.mkdtemp()) / "grades.csv")
    >>> path.read_text(encoding="utf-8").splitlines()[1]
    'alice,,lab2,graded,1,1,1,,,✔ ok,,,'

    The id the row was judged with is the second column:

    >>> row = GradeRow("x/Alice_lab2", "lab2", "graded", {"2.1": 1.0}, {"2.1": 1.0}, student_id="alice")
    >>> write_csv([row], path).read_text(encoding="utf-8").splitlines()[1][:26]
    'x/Alice_lab2,alice,lab2,gr'
    """
    path = Path(path)
    cols = _task_columns(rows)
    tmp = path.with_name(path.name + ".partial")
    with tmp.open("w", newline="", encoding="utf-8") as f:
        w = csv.writer(f)
        w.writerow(_header(cols))
        for r in rows:
            w.writerow(_record(r, cols))
    os.replace(tmp, path)
    return path


class RowWriter:
    """A grade table written row by row as notebooks finish (every task column of every lab), so
    that a grader that is killed leaves the rows it had; :meth:`close` rewrites it compactly.

    Parameters
    ----------
    path : str or Path

    Examples
    --------
    >>> import pathlib, tempfile
    >>> p = pathlib.Path(tempfile.mkdtemp()) / "g.csv"
    >>> w = RowWriter(p)
    >>> w.add(GradeRow("=cmd", "lab2", "graded", {"2.1": 1.0}, {"2.1": 1.0}))
    >>> read_csv(p)[0].student
    '=cmd'
    >>> w.close()
    >>> p.read_text(encoding="utf-8").splitlines()[0]
    'student,student_id,lab,status,total,max,2.1,notes,mismatch,2.1 message,seconds,peak_mb,reported_attempts'
    """

    def __init__(self, path: str | Path) -> None:
        self.path = Path(path)
        self.rows: list[GradeRow] = []
        self.cols = [t.id for t in _check.tasks()]
        self._f = self.path.open("w", newline="", encoding="utf-8")
        self._w = csv.writer(self._f)
        self._w.writerow(_header(self.cols))
        self._f.flush()

    def add(self, row: GradeRow) -> None:
        """Append one row and flush it to disk."""
        self.rows.append(row)
        self._w.writerow(_record(row, self.cols))
        self._f.flush()
        os.fsync(self._f.fileno())

    def close(self) -> None:
        """Rewrite the table with the task columns that are used, rows in submission order."""
        self._f.close()
        write_csv(sorted(self.rows, key=lambda r: r.student), self.path)


def read_csv(path: str | Path) -> list[GradeRow]:
    """Read a table written by :func:`write_csv` back into rows.

    Parameters
    ----------
    path : str or Path

    Returns
    -------
    list of GradeRow

    Examples
    --------
    >>> import pathlib, tempfile
    >>> p = write_csv([GradeRow("a", "lab2", "graded", {"2.1": 1.0}, {"2.1": 1.0})],
    ...               pathlib.Path(tempfile.mkdtemp()) / "g.csv")
    >>> read_csv(p)[0].scores
    {'2.1': 1.0}

    The ``student_id`` column is read back (a table of an older grader has none: ``""``):

    >>> p = write_csv([GradeRow("=a_lab2", "lab2", "graded", student_id="=a")], p)
    >>> read_csv(p)[0].student_id
    '=a'
    """
    rows = []
    # a table written by an older grader may hold a huge cell (a student's text): read it, then cut it short
    csv.field_size_limit(max(csv.field_size_limit(), 2 ** 30))
    with Path(path).open(newline="", encoding="utf-8") as f:
        for rec in csv.DictReader(f):
            lab = _uncell(rec.get("lab", "") or "")
            tids = [k for k in rec if re.fullmatch(r"\d+\.\d+", k or "") and rec[k] != ""]
            points = {t.id: float(t.points) for t in _check.tasks(lab)} if lab else {}
            scores = {k: float(rec[k]) for k in tids}
            rec = {k: _uncell(v or "")[:4000] for k, v in rec.items() if isinstance(k, str)}
            num = lambda x: float(x) if x else None  # noqa: E731
            said = rec.get(ATTEMPTS_COLUMN, rec.get("attempts", ""))  # "attempts": a table of an older grader
            attempts = dict(a.split(":", 1) for a in said.split() if ":" in a)
            attempts = _attempts({k: v for k, v in attempts.items() if v.isdigit()})
            rows.append(GradeRow(rec["student"], lab, rec["status"], scores, {k: points.get(k, 0.0) for k in tids},
                                 rec.get("notes", ""), {k: rec.get(f"{k} message", "") for k in tids},
                                 rec.get("mismatch", ""), num(rec.get("seconds")), num(rec.get("peak_mb")),
                                 attempts, rec.get("student_id", "")))
    return rows


def merge_csv(paths: list[str | Path], out: str | Path, roster: dict[str, str] | None = None) -> Path:
    """Merge the CSVs of several shards into one table (rows sorted by student; duplicates refused).

    Two rows of one lab whose student ids are the same but which come from different tables (the
    same id graded on two shards) both get a ``DUPLICATE ID`` note, as within one run.

    Parameters
    ----------
    paths : list of str or Path
        The shards' tables.
    out : str or Path
        The merged table.
    roster : dict, optional
        The roster the shards were graded with (:func:`~balancelab.course.intake.read_roster`),
        for rows without a ``student_id`` (tables of an older grader); without one, their ids
        come from the file names (:func:`~balancelab.course.intake.identity`).

    Returns
    -------
    Path

    Raises
    ------
    ValueError
        If a student appears in two tables.

    Examples
    --------
    >>> import pathlib, tempfile
    >>> d = pathlib.Path(tempfile.mkdtemp())
    >>> a = write_csv([GradeRow("b", "lab2", "graded", {"2.1": 1.0}, {"2.1": 1.0})], d / "a.csv")
    >>> b = write_csv([GradeRow("a", "lab1", "graded", {"1.1": 0.0}, {"1.1": 1.0})], d / "b.csv")
    >>> [r.student for r in read_csv(merge_csv([a, b], d / "all.csv"))]
    ['a', 'b']

    Bob graded on two shards (his own file and one in another folder): both rows say so.

    >>> e = write_csv([GradeRow("bob_lab2", "lab2", "graded", {"2.1": 1.0}, {"2.1": 1.0})], d / "e.csv")
    >>> f = write_csv([GradeRow("x/bob_lab2", "lab2", "graded", {"2.1": 1.0}, {"2.1": 1.0})], d / "f.csv")
    >>> [r.notes[:12] for r in read_csv(merge_csv([e, f], d / "all.csv"))]
    ['DUPLICATE ID', 'DUPLICATE ID']
    """
    rows, seen, table = [], set(), {}
    for i, p in enumerate(paths):
        for r in read_csv(p):
            if r.student in seen:
                raise ValueError(f"student {r.student!r} appears in more than one table")
            seen.add(r.student)
            table[r.student] = i
            rows.append(r)
    return write_csv(sorted(_duplicates_across(rows, table, roster), key=lambda r: r.student), out)


def _duplicates_across(rows: list[GradeRow], table: dict[str, int], roster: dict | None) -> list[GradeRow]:
    """``rows`` with a ``DUPLICATE ID`` note on those whose id and lab another table's row shares."""
    from dataclasses import replace

    groups: dict[tuple[str, str], list[GradeRow]] = {}
    for r in rows:
        sid = r.student_id or identity(r.student + ".ipynb", roster)[0]
        if sid and r.lab:
            groups.setdefault((sid, r.lab), []).append(r)
    notes = {}
    for (sid, _), group in groups.items():
        if len({table[r.student] for r in group}) > 1:
            for r in group:
                others = ", ".join(o.student for o in group if o is not r)
                notes[r.student] = f"DUPLICATE ID {excerpt(sid, 40)!r} (another shard): also {excerpt(others, 200)}"
    return [replace(r, notes="; ".join(x for x in (notes[r.student], r.notes) if x)) if r.student in notes else r
            for r in rows]


def summary(rows: list[GradeRow], warnings: list[str] | tuple[str, ...] = ()) -> str:
    """A plain-text table of the grades (what the command prints), then the batch's warnings.

    Parameters
    ----------
    rows : list of GradeRow
    warnings : list of str
        Problems of the batch as a whole (e.g. the roster's, see
        :func:`~balancelab.course.intake.roster_problems`), one line each after the table.

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

    Student-chosen text is printed without control characters (no terminal escape sequence):

    >>> "\\x1b" in summary([GradeRow("\\x1b]0;pwned\\x07\\x1b[2Jeve", "", "malformed", notes="x\\nFAKE")])
    False
    >>> summary([], ["roster: 'gone_lab1.ipynb' matches no submitted file"]).splitlines()[-1]
    "WARNING: roster: 'gone_lab1.ipynb' matches no submitted file"
    """
    cols = _task_columns(rows)
    head = ["student", "lab", "status", "score"] + cols
    body = [[excerpt(r.student, 60), excerpt(r.lab, 20), excerpt(r.status, 20), f"{r.total:g}/{r.max_total:g}"]
            + [f"{r.scores[c]:g}" if c in r.scores else "-" for c in cols] for r in rows]
    widths = [max(len(str(x)) for x in col) for col in zip(head, *body)] if body else [len(h) for h in head]
    fmt = lambda cells: "  ".join(str(c).ljust(w) for c, w in zip(cells, widths))  # noqa: E731
    lines = [fmt(head), fmt(["-" * w for w in widths])] + [fmt(b) for b in body]
    graded = [r for r in rows if r.status == "graded"]
    lines.append(f"{len(rows)} notebooks, {len(graded)} graded, {len(rows) - len(graded)} with problems")
    for r in rows:
        if r.status != "graded":
            lines.append(f"  {excerpt(r.student, 60)}: {excerpt(r.status, 20)}: {excerpt(r.notes, 400)}")
        elif r.mismatch:
            lines.append(f"  {excerpt(r.student, 60)}: lab mismatch: {excerpt(r.mismatch, 200)}")
    lines += [f"WARNING: {excerpt(w, 300)}" for w in warnings]
    return "\n".join(lines)
