"""Hostile submissions graded end to end: grades cannot be faked, the host is left untouched.

The folder is built here: right, wrong, half-done, crashing, looping and SIGINT-ignoring
notebooks, one that writes and deletes files outside its scratch folder, one that leaves a
detached process behind, monkeypatched checks, forged verdicts, a faked ``Design`` subclass,
invalid JSON, a notebook whose file name names another lab, and the untouched student
version. Each outcome is asserted, then the host is checked: no file outside the scratch
folder changed and no process of a submission is left.
"""
import csv
import hashlib
import os
import shutil
import subprocess
import sys
import uuid
from pathlib import Path

import nbformat
import pytest

from balancelab.course.check import tasks
from balancelab.course.grading import grade_answers, resolve_lab, shard
from balancelab.course.sandbox import sandbox_available
from conftest import submission_notebook

ROOT = Path(__file__).resolve().parent.parent
MARK = f"h3-hostile-{uuid.uuid4().hex[:12]}"
K_LAMP = "k_lamp = bl.lecture.single_link_spring(1.5, 0.4, 0.25, 0.12).parameters['k']"
LEVER = "lever_spring = {'k': 300.0, 'a': (0.3, 0.0), 'b': (0.0, 0.2)}"
ENERGY = "lever_energy = bl.singh.lacoste_lever(20.0, 0.5, 0.1, 0.25).parameters['PE']"
LAB2_MAX = str(int(sum(t.points for t in tasks(2))))
PERSONAL = """from balancelab.course.check import set_student, task_numbers
STUDENT_ID = {sid!r}
set_student(STUDENT_ID)
lamp = task_numbers("2.1")
k_lamp = bl.lecture.single_link_spring(**lamp).parameters["k"]
assert lamp != task_numbers("2.1", "")"""
FAKE_DESIGN = """
from balancelab.core.design import Design
from balancelab.course.check import lab4_singh_arm
class FakeDesign(Design):
    def balance_report(self, *args, **kwargs):
        class R:
            balanced, variation, energy = True, 0.0, 0.0
        return R()
honest = lab4_singh_arm((1.6, 1.6, -1.6))
half = honest.replace(springs=[bl.Spring(s.k / 2, s.free_length, s.a, s.b, name=s.name) for s in honest.springs])
arm_design = FakeDesign(half.name, half.bodies, half.joints, half.kinematics, half.loads, half.springs)
assert arm_design.balance_report().balanced
"""


def _digest(folder: Path) -> dict:
    return {p: hashlib.sha256(p.read_bytes()).hexdigest() for p in folder.rglob("*") if p.is_file()}


def _marked_processes() -> list[str]:
    found = []
    for p in Path("/proc").iterdir():
        if p.name.isdigit():
            try:
                cmd = (p / "cmdline").read_bytes().replace(b"\0", b" ").decode(errors="replace")
            except OSError:
                continue
            if MARK in cmd and "pytest" not in cmd:
                found.append(cmd)
    return found


def _submissions(sub: Path, host: Path) -> None:
    victim, pwned = host / "victim.txt", host / "pwned.txt"
    notebooks = {
        "alice_lab2": submission_notebook("lab2", K_LAMP, ENERGY, LEVER),
        "bob_lab2": submission_notebook("lab2", "k_lamp = 12.0", "lever_energy = 1.0", "lever_spring = {'k': 310.0, "
                        "'a': (0.3, 0.0), 'b': (0.0, 0.2)}"),
        "half_lab2": submission_notebook("lab2", K_LAMP, "lever_energy = ...", "lever_spring = ..."),
        "crash_lab2": submission_notebook("lab2", "1 / 0", K_LAMP),
        "loop_lab2": submission_notebook("lab2", K_LAMP, "while True:\n    pass", ENERGY),
        "sigint_lab2": submission_notebook("lab2", K_LAMP, "import signal\nsignal.signal(signal.SIGINT, signal.SIG_IGN)\n"
                           "while True:\n    pass", ENERGY),
        "writer_lab2": submission_notebook("lab2", f"import os\nopen({str(pwned)!r}, 'w').write('x')",
                           f"os.remove({str(victim)!r})", K_LAMP),
        "detach_lab2": submission_notebook("lab2", "import subprocess, sys\nsubprocess.Popen([sys.executable, '-c', "
                           f"'import time; time.sleep(600)', {MARK!r}], start_new_session=True)\n"
                           "import os\nif os.fork() == 0:\n    os.setsid()\n"
                           f"    os.execv(sys.executable, [sys.executable, '-c', 'import time; time.sleep(600)', "
                           f"{MARK + '-fork'!r}])", K_LAMP),
        "patch_lab2": submission_notebook("lab2", "import balancelab.course.check as c\nfrom balancelab.course.check import Verdict\n"
                          "c.check = lambda task, answer: Verdict(task, True, 'ok', '', 100.0, 1.0)\n"
                          "check = c.check", "k_lamp = 12.0\nassert check('2.1', k_lamp).score == 100"),
        "forge_lab2": submission_notebook("lab2", "from balancelab.course.check import Verdict\n"
                          "k_lamp = Verdict('2.1', True, 'ok', '', 100.0, 1.0)\n"
                          "lever_energy = {'score': 100}"),
        "fake_lab4": submission_notebook("lab4", FAKE_DESIGN),
        "zed_lab1": submission_notebook("lab2", K_LAMP),
        "pat_lab2": submission_notebook("lab2", PERSONAL.format(sid="pat")),
        "copy_lab2": submission_notebook("lab2", PERSONAL.format(sid="pat")),
    }
    for name, nb in notebooks.items():
        nbformat.write(nb, sub / f"{name}.ipynb")
    (sub / "junk_lab2.ipynb").write_text("{this is not json", encoding="utf-8")
    shutil.copy(ROOT / "labs" / "student" / "lab2_zfl_springs_and_levers.ipynb", sub / "untouched_lab2.ipynb")


@pytest.fixture(scope="module")
def graded(tmp_path_factory):
    if not sandbox_available():
        pytest.skip("bubblewrap (bwrap) is not available: the sandbox cannot be tested")
    base = tmp_path_factory.mktemp("hostile")
    sub, host = base / "submissions", base / "host"
    sub.mkdir()
    host.mkdir()
    (host / "victim.txt").write_text("keep me", encoding="utf-8")
    _submissions(sub, host)
    before_sub, before_host = _digest(sub), _digest(host)
    out = base / "grades.csv"
    proc = subprocess.run([sys.executable, "-m", "balancelab.course.grading", str(sub), "--out", str(out),
                           "--cell-timeout", "5", "--notebook-timeout", "90", "--jobs", "2"],
                          capture_output=True, text=True, timeout=900, cwd=ROOT)
    rows = {r["student"]: r for r in csv.DictReader(out.open(encoding="utf-8"))} if out.exists() else {}
    return dict(proc=proc, rows=rows, sub=sub, host=host, before_sub=before_sub, before_host=before_host)


def _scores(row, lab):
    return tuple(row[t.id] for t in tasks(lab))


def test_the_batch_runs(graded):
    assert graded["proc"].returncode == 0, graded["proc"].stderr[-2000:]
    assert len(graded["rows"]) == 16


def test_right_wrong_half_done_and_crashing(graded):
    rows = graded["rows"]
    assert _scores(rows["alice_lab2"], 2) == ("1", "0", "1", "2") and rows["alice_lab2"]["status"] == "graded"
    assert rows["bob_lab2"]["total"] == "0" and rows["bob_lab2"]["2.1 message"].startswith("✘ Not within")
    assert _scores(rows["half_lab2"], 2) == ("1", "0", "0", "0")
    assert rows["half_lab2"]["2.3 message"] == "✘ No answer yet."
    assert rows["crash_lab2"]["2.1"] == "1" and "ZeroDivisionError" in rows["crash_lab2"]["notes"]


def test_loops_are_stopped_and_rows_keep_lab_and_maximum(graded):
    rows = graded["rows"]
    loop = rows["loop_lab2"]
    assert loop["2.1"] == "1" and loop["2.3"] == "1" and "KeyboardInterrupt" in loop["notes"]
    sig = rows["sigint_lab2"]
    assert sig["status"] == "timeout" and sig["lab"] == "lab2" and sig["max"] == LAB2_MAX
    assert sig["2.1"] == "1" and sig["2.3"] == "0" and "ignored the interrupt" in sig["notes"]


def test_cheats_get_zero_with_a_note(graded):
    rows = graded["rows"]
    patch = rows["patch_lab2"]
    assert patch["total"] == "0" and "replaces `check`" in patch["notes"]
    forge = rows["forge_lab2"]
    assert forge["total"] == "0" and "Verdict, which cannot be graded" in forge["2.1 message"]
    assert "a dict" not in forge["2.3 message"] and forge["2.3"] == "0"
    fake = rows["fake_lab4"]
    assert fake["4.3"] == "0" and "NOT balanced" in fake["4.3 message"] and "subclasses Design" in fake["notes"]
    for row in rows.values():
        for t in tasks(row["lab"]) if row["lab"] else []:
            assert 0 <= float(row[t.id]) <= t.points


def test_invalid_json_wrong_lab_and_untouched_student_version(graded):
    rows = graded["rows"]
    junk = rows["junk_lab2"]
    assert junk["status"] == "malformed" and junk["lab"] == "lab2" and junk["max"] == LAB2_MAX
    zed = rows["zed_lab1"]
    assert zed["lab"] == "lab2" and zed["2.1"] == "1"
    assert zed["mismatch"] == "file name says lab1, metadata says lab2" and "lab mismatch" in zed["notes"]
    untouched = rows["untouched_lab2"]
    assert untouched["lab"] == "lab2" and untouched["total"] == "0" and untouched["max"] == LAB2_MAX


def test_the_host_is_untouched(graded):
    assert _digest(graded["sub"]) == graded["before_sub"]
    assert _digest(graded["host"]) == graded["before_host"]
    assert not (graded["host"] / "pwned.txt").exists() and (graded["host"] / "victim.txt").exists()
    assert graded["rows"]["writer_lab2"]["2.1"] == "1"
    assert _marked_processes() == []
    assert graded["rows"]["detach_lab2"]["2.1"] == "1"


def test_no_scratch_folder_is_left(graded):
    left = [p for p in Path(os.environ.get("TMPDIR", "/tmp")).glob("balancelab-grade-*")
            if p.stat().st_mtime >= graded["sub"].stat().st_mtime]
    assert left == []


def test_lab_sources_are_compared():
    nb = {"metadata": {"balancelab": {"lab": "lab5"}}}
    assert resolve_lab(nb, Path("x_lab5.ipynb"), "lab1") == ("lab1", "file name says lab5, metadata says lab5, "
                                                                     "--lab says lab1")
    assert resolve_lab(nb, Path("x.ipynb")) == ("lab5", "")
    assert resolve_lab({}, Path("x.ipynb")) == (None, "")


def test_exported_data_is_checked_not_trusted():
    r = grade_answers({"k_lamp": {"sympy": "__import__('os').system('touch /tmp/x')"},
                       "lever_energy": {"num": "1e999"}, "lever_spring": "not data"}, "lab2")
    assert all(v["score"] == 0 for v in r.values())
    assert grade_answers([], "lab2")["2.1"]["score"] == 0


def test_shards_cover_the_folder_once():
    files = [f"f{i}" for i in range(11)]
    parts = [shard(files, f"{i}/3") for i in (1, 2, 3)]
    assert sorted(sum(parts, [])) == sorted(files)
    with pytest.raises(ValueError, match="shard"):
        shard(files, "0/3")


def test_personal_numbers_are_graded_with_the_declared_student(graded):
    rows = graded["rows"]
    assert rows["pat_lab2"]["2.1"] == "1" and "STUDENT_ID" not in rows["pat_lab2"]["notes"]
    copy = rows["copy_lab2"]
    assert "STUDENT_ID 'pat' does not appear in the submission's name 'copy_lab2'" in copy["notes"]
    # the published numbers' answer is wrong for a student with personal numbers
    assert rows["alice_lab2"]["2.1"] == "1"


def test_without_the_sandbox_the_grader_warns_and_still_grades(tmp_path):
    import warnings

    from balancelab.course.grading import grade_notebook
    from balancelab.course.sandbox import NO_SANDBOX_WARNING, run_limited

    with pytest.warns(RuntimeWarning, match="no sandbox"):
        r = run_limited([sys.executable, "-c", "print(7)"], tmp_path, 60, sandbox=False)
    assert r.stdout == "7\n" and not r.sandboxed
    path = tmp_path / "amy_lab2.ipynb"
    nbformat.write(submission_notebook("lab2", K_LAMP), path)
    with warnings.catch_warnings():
        warnings.simplefilter("error")  # grade_notebook notes it in the row instead of warning per notebook
        row = grade_notebook(path, sandbox=False, cell_timeout=30, notebook_timeout=120)
    assert row.scores["2.1"] == 1.0 and "NO SANDBOX" in row.notes
    assert "bubblewrap" in NO_SANDBOX_WARNING


def test_a_grader_installed_under_tmp_still_runs_inside_the_sandbox(tmp_path, monkeypatch):
    """The sandbox gives submissions an empty /tmp of their own; a grader whose checkout or
    virtual environment lives under /tmp (a CI runner's clone) must still find its own Python
    and package inside (a clean clone under /tmp once graded every notebook as an error)."""
    import tempfile

    from balancelab.course.sandbox import run_limited

    if not sandbox_available():
        pytest.skip("bubblewrap is not available here")
    pkg = Path(tempfile.mkdtemp(dir="/tmp", prefix="grader_pkg_"))
    try:
        (pkg / "probe_mod.py").write_text("X = 'the grader is visible'\n")
        monkeypatch.syspath_prepend(str(pkg))
        env = {**os.environ, "PYTHONPATH": str(pkg)}
        r = run_limited([sys.executable, "-c", "import probe_mod; print(probe_mod.X)"], tmp_path, 60,
                        env=env, sandbox=True)
    finally:
        shutil.rmtree(pkg)
    assert r.sandboxed and r.stdout == "the grader is visible\n", (r.stdout, r.stderr[-500:])
