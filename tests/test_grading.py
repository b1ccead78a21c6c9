"""The grader: one command grades a folder; bad notebooks get a clear row; nothing is modified."""
import csv
import hashlib
import subprocess
import sys
from pathlib import Path

import nbformat
import pytest

from balancelab.course.check import tasks
from balancelab.course.grading import GradeRow, grade_namespace, summary, write_csv
from conftest import (personal_equivalent, personal_k_lamp, personal_lever_energy, personal_lever_spring, personal_r_c,
                      submission_notebook)

ROOT = Path(__file__).resolve().parent.parent



def _write(folder, name, nb):
    p = folder / name
    p.parent.mkdir(parents=True, exist_ok=True)
    nbformat.write(nb, p)
    return p


K_LAMP = personal_k_lamp  # the student's own numbers: the id is the file name's (alice_lab2 -> alice)
LEVER_SPRING = personal_lever_spring("alice")  # task 2.4: a design for alice's own load
ENERGY = personal_lever_energy  # task 2.3 on the student's own lever


@pytest.fixture(scope="module")
def graded(tmp_path_factory):
    sub = tmp_path_factory.mktemp("submissions")
    _write(sub, "alice_lab2.ipynb", submission_notebook("lab2", K_LAMP("alice"), ENERGY("alice"), LEVER_SPRING))
    _write(sub, "bob_lab2.ipynb", submission_notebook("lab2", "k_lamp = 12.0", "raise NotImplementedError('todo')",
                                      "lever_spring = {'k': 310.0, 'a': (0.3, 0.0), 'b': (0.0, 0.2)}"))
    _write(sub, "carol_lab2.ipynb", submission_notebook("lab2", K_LAMP("carol"), "while True:\n    pass", ENERGY("carol")))
    (sub / "dave_lab2.ipynb").write_text("{not json")
    _write(sub, "erin_lab2.ipynb", submission_notebook("lab2", K_LAMP("erin"), "import os\nos._exit(1)"))
    _write(sub, "frank_notes.ipynb", submission_notebook("", "x = 1"))
    _write(sub, "hank_lab2.ipynb", submission_notebook("lab2", "for k in (100.0, 150.0, 200.0):\n    check('2.1', k)",
                                                       "check('2.3', 1.0)\ncheck('9.9', 1.0)"))
    _write(sub, "group/gina_lab1.ipynb", submission_notebook("lab1", personal_r_c("gina"), personal_equivalent("gina")))
    before = {p: hashlib.sha256(p.read_bytes()).hexdigest() for p in sub.rglob("*") if p.is_file()}
    out = sub.parent / "grades.csv"
    proc = subprocess.run([sys.executable, "-m", "balancelab.course.grading", str(sub), "--out", str(out),
                           "--cell-timeout", "8", "--notebook-timeout", "120"],
                          capture_output=True, text=True, timeout=600, cwd=ROOT)
    after = {p: hashlib.sha256(p.read_bytes()).hexdigest() for p in sub.rglob("*") if p.is_file()}
    rows = {r["student"]: r for r in csv.DictReader(out.open())}
    return proc, rows, before, after


def test_command_succeeds_and_prints_summary(graded):
    proc, rows, _, _ = graded
    assert proc.returncode == 0, proc.stderr
    assert "student" in proc.stdout and "8 notebooks" in proc.stdout
    assert len(rows) == 8


def test_full_marks_for_right_answers(graded):
    _, rows, _, _ = graded
    a = rows["alice_lab2"]
    assert a["status"] == "graded" and a["lab"] == "lab2"
    assert (a["2.1"], a["2.2"], a["2.3"], a["2.4"]) == ("1", "0", "1", "2")
    assert a["total"] == "4" and a["max"] == str(int(sum(t.points for t in tasks(2))))


def test_wrong_and_missing_answers_score_zero_with_notes(graded):
    _, rows, _, _ = graded
    b = rows["bob_lab2"]
    assert b["status"] == "graded" and b["total"] == "0"
    assert "NotImplementedError" in b["notes"]


def test_looping_cell_is_interrupted_and_the_rest_graded(graded):
    _, rows, _, _ = graded
    c = rows["carol_lab2"]
    assert c["2.1"] == "1" and c["2.3"] == "1"
    assert "KeyboardInterrupt" in c["notes"] or "CellTimeoutError" in c["notes"] or c["status"] == "timeout"


def test_malformed_crashing_and_unknown_notebooks_get_clear_rows(graded):
    _, rows, _, _ = graded
    assert rows["dave_lab2"]["status"] == "malformed" and rows["dave_lab2"]["total"] == "0"
    assert "not a valid notebook" in rows["dave_lab2"]["notes"]
    assert rows["erin_lab2"]["status"] in ("kernel died", "error")
    # the answer given before the kernel died is graded; nothing after it
    assert rows["erin_lab2"]["total"] == "1" and rows["erin_lab2"]["2.1"] == "1"
    assert "kernel died" in rows["erin_lab2"]["notes"]
    assert rows["frank_notes"]["status"] == "unknown lab" and "--lab" in rows["frank_notes"]["notes"]


def test_subfolders_and_other_labs(graded):
    _, rows, _, _ = graded
    g = rows[str(Path("group") / "gina_lab1")]
    assert g["lab"] == "lab1" and g["1.1"] == "1" and g["1.3"] == "1" and g["1.4"] == "0"
    assert g["2.1"] == ""  # not a task of lab 1


def test_submissions_never_modified(graded):
    _, _, before, after = graded
    assert before == after


def test_grade_namespace_directly():
    r = grade_namespace({"k_lamp": "196.2 N/m", "lever_energy": float("nan")}, "lab2")
    assert r["2.1"]["correct"] and r["2.1"]["score"] == 1.0
    assert not r["2.3"]["correct"] and "NaN" in r["2.3"]["message"]
    assert "not defined" in r["2.4"]["message"]
    assert set(r) == {t.id for t in tasks(2)}


def test_csv_and_summary_from_rows(tmp_path):
    rows = [GradeRow("x", "lab2", "graded", {"2.1": 1.0, "2.2": 0.0}, {"2.1": 1.0, "2.2": 1.0}),
            GradeRow("y", "", "malformed", notes="not a valid notebook")]
    p = write_csv(rows, tmp_path / "g.csv")
    text = p.read_text()
    assert text.splitlines()[0] == ("student,student_id,lab,status,total,max,2.1,2.2,notes,mismatch,2.1 message,2.2 message,"
                                    "seconds,peak_mb,reported_attempts")
    assert "x,,lab2,graded,1,2,1,0," in text
    s = summary(rows)
    assert "1/2" in s and "y: malformed" in s


def test_missing_folder_is_a_clear_error(tmp_path):
    proc = subprocess.run([sys.executable, "-m", "balancelab.course.grading", str(tmp_path / "nope")],
                          capture_output=True, text=True, cwd=ROOT)
    assert proc.returncode == 2 and "no such folder" in proc.stderr


def test_check_attempts_are_reported_per_task(graded):
    _, rows, _, _ = graded
    assert rows["hank_lab2"]["reported_attempts"] == "2.1:3 2.3:1"  # an unknown task is not counted
    assert rows["alice_lab2"]["reported_attempts"] == ""


def test_rows_record_wall_time_and_peak_memory(graded):
    _, rows, _, _ = graded
    a = rows["alice_lab2"]
    assert 0 < float(a["seconds"]) < 600 and float(a["peak_mb"]) > 10
    assert rows["dave_lab2"]["seconds"] == ""  # nothing was run for a malformed notebook


def test_the_root_sandbox_makes_every_folder_above_a_bind_readable_also_under_its_own_tmp():
    """A checkout under a temporary folder of mode 700 (``mktemp -d``, as a CI clone may be): the
    sandbox's own /tmp is empty, so the folders between it and the bound venv must be made (755)
    for uid 65534, or its Python cannot even start (it fell back to a root kernel)."""
    from balancelab.course.sandbox import _made_readable

    binds = ["--ro-bind", "/usr", "/usr", "--ro-bind", "/tmp/ci.x/p/.venv", "/tmp/ci.x/p/.venv",
             "--ro-bind", "/tmp/ci.x/p/balancelab", "/tmp/ci.x/p/balancelab", "--ro-bind", "/usr/lib/x", "/usr/lib/x"]
    made = _made_readable(binds, ["/tmp", "/dev"])
    dirs = [made[i + 3] for i in range(0, len(made), 4)]
    assert made[:4] == ["--perms", "0755", "--dir", "/tmp/ci.x"]
    assert dirs == ["/tmp/ci.x", "/tmp/ci.x/p"]           # not /tmp itself, nothing under the bound /usr


def test_a_lab_named_in_capitals_is_still_its_students(tmp_path):
    """Attack A18b: ``Alice_Lab1.ipynb`` was `unidentified` (its personal tasks 0) although ids are
    case-insensitive; ``labN`` is too, in a file name and under a student's folder."""
    from balancelab.course.intake import identity, lab_sources

    for name in ("Alice_Lab1.ipynb", "ALICE_LAB1.ipynb", "alice/Lab1.ipynb", "Alice/LAB1.ipynb"):
        sid, how = identity(name, None)
        assert sid.lower() == "alice" and how in ("file name", "folder name"), (name, sid, how)
        assert lab_sources({}, Path(name))[0] == "lab1"


def test_a_roster_saved_by_a_spreadsheet_is_read(tmp_path):
    """Attack A22: a roster with Excel's byte-order mark and CRLF, and ``./`` before a path."""
    from balancelab.course.intake import read_roster

    p = tmp_path / "roster.csv"
    p.write_bytes(b"\xef\xbb\xbffile,student_id\r\neve_lab1.ipynb,eve\r\n./bob/lab1.ipynb,bob\r\n")
    assert read_roster(p) == {"eve_lab1.ipynb": "eve", "bob/lab1.ipynb": "bob"}


def test_a_cell_the_grader_cannot_parse_is_no_crash_and_a_failed_row_keeps_its_lab(tmp_path):
    """Attack A18b: a lone surrogate in a code cell made the grader fail with a row of no lab and
    no points (a table's percentage divided by 0)."""
    from balancelab.course.grading import _failed_row
    from balancelab.course.intake import cheat_notes

    nb = nbformat.v4.new_notebook(cells=[nbformat.v4.new_code_cell("x = '\ud800'\nprint(x)")])
    assert cheat_notes(nb) == []
    row = _failed_row("n5_lab1", tmp_path / "n5_lab1.ipynb", None, UnicodeEncodeError("utf-8", "", 0, 1, "x"))
    lab1 = {t.id: t.points for t in tasks("lab1")}
    assert row.lab == "lab1" and row.status == "error" and row.total == 0
    assert row.max_total == sum(lab1.values()) > 0


def test_the_grader_refuses_a_derive_shortcut_as_the_notebook_does():
    """Attack A21: a 2.2 or 4.5 cell that calls the library's solver was refused by the notebook's
    ``check`` but scored by the grader. Both now read the checking cell the same way; the
    solutions, derived by hand, are refused nothing."""
    from balancelab.course.check.derive import SHORTCUTS
    from balancelab.course.grading import derive_refusals

    root = Path(__file__).resolve().parents[1] / "labs"
    for sol in sorted((root / "solutions").glob("lab*.ipynb")):
        assert derive_refusals(nbformat.read(sol, as_version=4), sol.stem.split("_")[0]) == {}, sol.name
    derive = [t for t in tasks() if t.skill == "derive" and t.id in SHORTCUTS]
    assert derive, "no derive task has shortcuts"
    for t in derive:
        student = next((root / "student").glob(f"{t.lab}_*.ipynb"))
        nb = nbformat.read(student, as_version=4)
        cell = next(c for c in nb.cells if c.cell_type == "code" and f'check("{t.id}"' in c.source)
        cell.source = f"_ = {SHORTCUTS[t.id][0]}\n" + cell.source
        assert derive_refusals(nb, t.lab) == {t.id: [SHORTCUTS[t.id][0]]}


@pytest.mark.parametrize("tag, said", [("lab99", "lab99"), ("lab 7", "lab7"), (7, "lab7"), (-1, "unreadable (-1)"),
                                       (3.0, "unreadable (3.0)"), (True, "unreadable (True)"),
                                       ([1], "unreadable ([1])"), ({"n": 1}, "unreadable ({'n': 1})"),
                                       ("lab1; lab2", "unreadable (lab1; lab2)"), (None, None), ("  ", None)])
def test_a_bad_lab_tag_never_hides_the_file_names_lab(tag, said):
    """Brief g18 item 3: whatever the notebook's ``balancelab.lab`` tag holds, the file name's lab
    is graded; a tag that disagrees (a wrong lab, a name of no lab, a value that is no name) is a
    note that says what it said; no tag, or a blank one, is no note."""
    from balancelab.course.grading import _lab_mismatch_note, resolve_lab

    nb = {"metadata": {"balancelab": {"lab": tag}}}
    lab, mismatch = resolve_lab(nb, Path("sub/ann_lab1.ipynb"))
    assert lab == "lab1"
    if said is None:
        assert mismatch == ""
    else:
        assert mismatch == f"file name says lab1, metadata says {said}"
        note = _lab_mismatch_note(nb, Path("sub/ann_lab1.ipynb"), None, lab, mismatch)
        assert note.startswith(f"lab mismatch: the notebook's metadata says {said} but the file name says lab1: "
                               "graded as lab1")
    for meta in ({"balancelab": "lab5"}, {"balancelab": None}, [], "lab5"):  # no table where one is expected
        assert resolve_lab({"metadata": meta}, Path("ann_lab1.ipynb")) == ("lab1", "")
