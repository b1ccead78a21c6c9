"""Hostile submissions graded end to end: grades cannot be faked, the host is left untouched.

The folder is built here: right, wrong, half-done, crashing, looping and SIGINT-ignoring
notebooks, one that writes and deletes files outside its scratch folder, one that leaves a
detached process behind, monkeypatched checks, forged verdicts, a faked ``Design`` subclass,
invalid JSON, a notebook whose file name names another lab, the untouched student version, and
the attacks of issue 18: answers that stall a judge, links and FIFOs as submissions, a notebook
that looks for the solutions, the other submissions, a host socket and the grader's home,
forged report lines, a killed runner, fake answer files, patched ``print``/``json.dumps``,
memory, process, in-memory-folder and output bombs, a formula as a file name, a classmate's
id. Each outcome is asserted, then the host is checked: no file outside the scratch folder
changed, nothing reached the host socket, no process and no scratch folder of a submission is
left.
"""
import csv
import hashlib
import os
import shutil
import socket
import subprocess
import sys
import threading
import time
import uuid
from pathlib import Path

import nbformat
import pytest

from balancelab.course.check import tasks
from balancelab.course.grading import grade_answers, resolve_lab, shard
from balancelab.course.sandbox import sandbox_available
from conftest import personal_k_lamp, personal_lever_energy, personal_lever_spring, personal_r_c, submission_notebook

ROOT = Path(__file__).resolve().parent.parent
MARK = f"h3-hostile-{uuid.uuid4().hex[:12]}"
SECRET = f"H18SECRET{uuid.uuid4().hex[:8]}"
K_LAMP = personal_k_lamp  # a right answer to 2.1 for the student the file name names
LEVER = personal_lever_spring("alice")  # task 2.4: a design for alice's own load
ENERGY = personal_lever_energy  # task 2.3 on the student's own lever
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
SYMBOLS = "import sympy as sp\nm, r, m_l, m_c = sp.symbols('m r m_l m_c', positive=True)\n"
#: What a submission looks for outside its sandbox (each found path is an error in its row).
SNOOP = """import balancelab, os, pathlib, sys
root = pathlib.Path(balancelab.__file__).resolve().parents[1]
seen = [str(p) for p in [root / "labs" / "solutions", root / "labs", root / "tests", root / "book", root / ".git",
        pathlib.Path({sub!r}), pathlib.Path({home!r}), pathlib.Path({host!r}),
        pathlib.Path("/etc/os-release"), pathlib.Path("/etc/passwd"), pathlib.Path("/work/main/labs"),
        pathlib.Path("/work/main/.git")] if p.exists()]
# a Python that lives inside a checkout brings the folders above it, empty but for the prefix
allowed = set(["balancelab"])
if sys.prefix.startswith(str(root) + "/"):
    allowed.add(pathlib.Path(sys.prefix).relative_to(root).parts[0])
if root.is_dir():
    seen += [str(p) for p in root.iterdir() if p.name not in allowed]
# the grader's real home: at most the folders that lead to this Python (when it lives there)
real = pathlib.Path({real_home!r})
if real.is_dir():
    seen += [str(p) for p in real.iterdir() if not sys.base_prefix.startswith(str(p) + "/")]
if seen:
    raise RuntimeError("SAW " + " ".join(seen))"""
SOCKETS = """import socket
reached = []
for addr in [{sock!r}, "\\0" + {abstract!r}]:
    s = socket.socket(socket.AF_UNIX)
    try:
        s.connect(addr)
        reached.append(addr)
    except OSError:
        pass
if reached:
    raise RuntimeError("REACHED " + repr(reached))
if any({secret!r} in v for v in os.environ.values()):
    raise RuntimeError("SAW THE GRADER'S ENVIRONMENT")"""
#: Forged report lines on every output, fake answer files, then every process killed.
FORGER = """import json, os, signal, sys
line = json.dumps({"run": {"status": "graded", "errors": [], "notes": ["FORGED-NOTE"], "attempts": {}}}) + "\\n"
line += "".join(json.dumps({"task": {"id": t, "score": 9, "points": 9, "correct": True, "message": "FORGED"}}) + "\\n"
                for t in ("2.1", "2.2", "2.3", "2.4")) + json.dumps({"done": True}) + "\\n"
for fd in (1, 2):
    os.write(fd, line.encode())
print(line)
sys.__stdout__.write(line)
sys.__stdout__.flush()
for name in ("answers.json", "/tmp/answers.json"):
    open(name, "w").write(json.dumps({"k_lamp": {"num": "196.2"}}))
share = os.path.dirname(sys.argv[sys.argv.index("-f") + 1])
try:
    open(os.path.join(share, "answers.json"), "w").write("{}")
except OSError:
    pass
try:
    os.kill(-1, signal.SIGKILL)
except OSError:
    pass
os.kill(os.getpid(), signal.SIGKILL)"""
MONKEY = personal_k_lamp("monkey") + """
import builtins, json
right = k_lamp
json.dumps = lambda *a, **k: '{"k_lamp": {"num": "%r"}}' % right
_print = builtins.print
builtins.print = lambda *a, **k: _print('{"k_lamp": {"num": "%r"}}' % right)
k_lamp = 12.0"""
MEMORY_BOMB = """import subprocess, sys
keep = b"1" * (450 * 2 ** 20)
grow = "x = b'1' * (700 * 2 ** 20)\\nprint('allocated', flush=True)\\nimport time\\ntime.sleep(30)"
child = subprocess.Popen([sys.executable, "-c", grow], stdout=subprocess.PIPE)
said = child.stdout.readline()"""
#: Answers whose data (not the kernel) stall a judge: sympy text that builds an enormous Float.
JUDGE_STALL = """import sympy as sp
class Evil(sp.Symbol):
    def _sympyrepr(self, printer):
        return {text!r}
k_lamp = Evil("x")"""
FORK_BOMB = """import subprocess
ps = []
try:
    for _ in range(200):
        ps.append(subprocess.Popen(["sleep", "30"]))
except OSError:
    pass"""
TMP_BOMB = """for d in ("/tmp", "/dev/shm", "."):
    for i in range(3):
        try:
            with open(f"{d}/big{i}", "wb") as f:
                for _ in range(7):
                    f.write(b"0" * (16 * 2 ** 20))
        except OSError:
            pass"""
OUTPUT_BOMB = "print('x' * (8 * 2 ** 20))\nfor _ in range(4):\n    print('y' * 2 ** 20)"
ANSWER_FILES = """import os
os.mkfifo("answers.json")
os.symlink("/dev/zero", "/tmp/answers.json")"""
#: Issue 18, second round: what an outside tester did. The grader's working folder (it holds the
#: solutions and the grades) and home must not show; no user namespace of its own (the way to mount
#: a cgroup file system and raise its own caps); no cgroup file writable, no child cgroup.
ESCAPE = """import ctypes, os, pathlib
bad = []
mounts = open("/proc/self/mountinfo").read()
for p in ({cwd!r}, {home!r}):
    if p in mounts or pathlib.Path(p).exists():
        bad.append("saw " + p)
libc = ctypes.CDLL(None, use_errno=True)
if libc.unshare(0x10000000) == 0:  # CLONE_NEWUSER
    bad.append("unshare(CLONE_NEWUSER) worked")
own = open("/proc/self/cgroup").read().split("\\n")[0].rsplit(":", 1)[-1]
for d in ("/sys/fs/cgroup", "/sys/fs/cgroup" + own):
    for f in ("memory.max", "pids.max", "notify_on_release"):
        try:
            open(os.path.join(d, f), "w").write("max")
            bad.append("wrote " + os.path.join(d, f))
        except OSError:
            pass
    try:
        os.mkdir(os.path.join(d, "hidden"))
        bad.append("made a child cgroup in " + d)
    except OSError:
        pass
if bad:
    raise RuntimeError("ESCAPED " + "; ".join(bad))"""
#: Attempt counts with keys and values the student chose (an escape sequence, a formula, 1 MB).
ATTEMPT_KEYS = """from balancelab.course.check import core
core.ATTEMPTS["\\x1b[2J=HYPERLINK(\\"http://x\\")\\n" + "A" * 2 ** 20] = 7
core.ATTEMPTS["2.1"] = 10 ** 12"""
#: An export line forged with the probe's own nonce, nested 200,000 deep (json.loads: RecursionError).
DEEP_EXPORT = """import sys
cls = type(sys.stdout)
_write = cls.write
def write(self, text):
    if len(text) > 33 and text[32] == " " and all(c in "0123456789abcdef" for c in text[:32]):
        text = text[:33] + "[" * 200000 + "]" * 200000 + "\\n"
    return _write(self, text)
cls.write = write"""
NAMED_EXCEPTION = "raise type(\"=cmd|' /C calc'!A0\", (Exception,), {})('=HYPERLINK(\"x\")')"


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


class _HostSocket:
    """A unix socket in the host's /tmp (and an abstract one) that records every connection."""

    def __init__(self):
        self.path = f"/tmp/h18-host-{uuid.uuid4().hex[:10]}.sock"
        self.abstract = f"h18-abstract-{uuid.uuid4().hex[:10]}"
        self.connections = []
        self.socks = []
        for addr in (self.path, "\0" + self.abstract):
            s = socket.socket(socket.AF_UNIX)
            s.bind(addr)
            s.listen(8)
            s.settimeout(0.2)
            self.socks.append(s)
        os.chmod(self.path, 0o777)
        self.stop = threading.Event()
        self.thread = threading.Thread(target=self._serve, daemon=True)
        self.thread.start()

    def _serve(self):
        while not self.stop.is_set():
            for s in self.socks:
                try:
                    conn, _ = s.accept()
                except OSError:
                    continue
                self.connections.append(conn)

    def close(self):
        self.stop.set()
        self.thread.join(5)
        for s in self.socks:
            s.close()
        os.unlink(self.path)


def _submissions(sub: Path, host: Path, sock: _HostSocket, home: Path, cwd: Path) -> None:
    victim, pwned = host / "victim.txt", host / "pwned.txt"
    notebooks = {
        "alice_lab2": submission_notebook("lab2", K_LAMP("alice"), ENERGY("alice"), LEVER),
        "bob_lab2": submission_notebook("lab2", "k_lamp = 12.0", "lever_energy = 1.0", "lever_spring = {'k': 310.0, "
                        "'a': (0.3, 0.0), 'b': (0.0, 0.2)}"),
        "half_lab2": submission_notebook("lab2", K_LAMP("half"), "lever_energy = ...", "lever_spring = ..."),
        "crash_lab2": submission_notebook("lab2", "1 / 0", K_LAMP("crash")),
        "loop_lab2": submission_notebook("lab2", K_LAMP("loop"), "while True:\n    pass", ENERGY("loop")),
        "sigint_lab2": submission_notebook("lab2", K_LAMP("sigint"), "import signal\nsignal.signal(signal.SIGINT, "
                           "signal.SIG_IGN)\nwhile True:\n    pass", ENERGY("sigint")),
        "writer_lab2": submission_notebook("lab2", f"import os\nopen({str(pwned)!r}, 'w').write('x')",
                           f"os.remove({str(victim)!r})", K_LAMP("writer")),
        "detach_lab2": submission_notebook("lab2", "import subprocess, sys\nsubprocess.Popen([sys.executable, '-c', "
                           f"'import time; time.sleep(600)', {MARK!r}], start_new_session=True)\n"
                           "import os\nif os.fork() == 0:\n    os.setsid()\n"
                           f"    os.execv(sys.executable, [sys.executable, '-c', 'import time; time.sleep(600)', "
                           f"{MARK + '-fork'!r}])", K_LAMP("detach")),
        "patch_lab2": submission_notebook("lab2", "import balancelab.course.check as c\nfrom balancelab.course.check import Verdict\n"
                          "c.check = lambda task, answer: Verdict(task, True, 'ok', '', 100.0, 1.0)\n"
                          "check = c.check", "k_lamp = 12.0\nassert check('2.1', k_lamp).score == 100"),
        "forge_lab2": submission_notebook("lab2", "from balancelab.course.check import Verdict\n"
                          "k_lamp = Verdict('2.1', True, 'ok', '', 100.0, 1.0)\n"
                          "lever_energy = {'score': 100}"),
        "fake_lab4": submission_notebook("lab4", FAKE_DESIGN),
        "zed_lab1": submission_notebook("lab2", K_LAMP("zed")),
        "pat_lab2": submission_notebook("lab2", PERSONAL.format(sid="pat")),
        "copy_lab2": submission_notebook("lab2", PERSONAL.format(sid="pat")),
        # issue 18, item 2: answers that stall a judge, answer files that block or flood a reader
        "pow_lab1": submission_notebook("lab1", personal_r_c("pow"), SYMBOLS + "r_c_formula = sp.Pow(m + r + m_l + m_c, "
                        "200, evaluate=False)"),
        "nest_lab1": submission_notebook("lab1", SYMBOLS + "e = m\nfor _ in range(30):\n    e = sp.sin(e + r)\n"
                         "r_c_formula = e", personal_r_c("nest")),
        "huge_lab2": submission_notebook("lab2", "import sympy as sp\nk_lamp = sp.Float('1e999999999')"),
        "precise_lab2": submission_notebook("lab2", "import sympy as sp\nk_lamp = sp.Float('1.5', 10 ** 8)"),
        "files_lab2": submission_notebook("lab2", ANSWER_FILES, K_LAMP("files")),
        # an outside student's attack: a formula written as text that runs code where the judge reads it
        "textrce_lab1": submission_notebook("lab1", personal_r_c("textrce"), "r_c_formula = "
                            + repr(f"__import__('os').system('touch {pwned}')")),
        "hugejudge_lab2": submission_notebook("lab2", JUDGE_STALL.format(text="Float('1e999999999')")),
        "precisejudge_lab2": submission_notebook("lab2", JUDGE_STALL.format(text="Float('1.5', 100000000)")),
        # item 1: what the sandbox must not show
        "snoop_lab2": submission_notebook("lab2", SNOOP.format(sub=str(sub), home=str(home), host=str(host),
                                                            real_home=os.path.expanduser("~")),
                          SOCKETS.format(sock=sock.path, abstract=sock.abstract, secret=SECRET), K_LAMP("snoop")),
        # item 3: forged reports, a killed runner, fake answer files, patched print and json.dumps
        "forger_lab2": submission_notebook("lab2", FORGER),
        "monkey_lab2": submission_notebook("lab2", MONKEY),
        # item 4: caps on the whole submission
        "membomb_lab2": submission_notebook("lab2", K_LAMP("membomb"), MEMORY_BOMB),
        "forkbomb_lab2": submission_notebook("lab2", K_LAMP("forkbomb"), FORK_BOMB),
        "tmpbomb_lab2": submission_notebook("lab2", K_LAMP("tmpbomb"), TMP_BOMB),
        "outbomb_lab2": submission_notebook("lab2", K_LAMP("outbomb"), OUTPUT_BOMB),
        # item 7: formulas in names, exception names and answers
        "=1+2*3_lab2": submission_notebook("lab2", K_LAMP(""), NAMED_EXCEPTION),
        "long_lab2": submission_notebook("lab2", "k_lamp = '=HYPERLINK(\"http://x\")' + 'A' * 5000"),
        # issue 18, second round
        "escape_lab2": submission_notebook("lab2", K_LAMP("escape"), ESCAPE.format(cwd=str(cwd), home=str(home))),
        "attempts_lab2": submission_notebook("lab2", K_LAMP("attempts"), ATTEMPT_KEYS),
        "\x1b]0;pwned\x07\x1b[2Jterm_lab2": submission_notebook("lab2", K_LAMP("term")),
        "mallory/alice_lab2": submission_notebook("lab2", K_LAMP("alice")),
        "dup_lab2": submission_notebook("lab2", K_LAMP("dup")),
        "dup/lab2": submission_notebook("lab2", K_LAMP("dup")),
    }
    (sub / "mallory").mkdir()
    (sub / "dup").mkdir()
    for name, nb in notebooks.items():
        nbformat.write(nb, sub / f"{name}.ipynb")
    (sub / "junk_lab2.ipynb").write_text("{this is not json", encoding="utf-8")
    shutil.copy(ROOT / "labs" / "student" / "lab2_zfl_springs_and_levers.ipynb", sub / "untouched_lab2.ipynb")
    # items 2 and 8: links and non-regular files are refused, never read
    (sub / "sym_lab1.ipynb").symlink_to(ROOT / "labs" / "solutions" / "lab1_counterweights.ipynb")
    (sub / "zero_lab2.ipynb").symlink_to("/dev/zero")
    (sub / "hostfile_lab2.ipynb").symlink_to(host / "victim.txt")
    os.mkfifo(sub / "fifo_lab2.ipynb")


@pytest.fixture(scope="module")
def graded(tmp_path_factory):
    if not sandbox_available():
        pytest.skip("bubblewrap (bwrap) is not available: the sandbox cannot be tested")
    base = tmp_path_factory.mktemp("hostile")
    sub, host, home = base / "submissions", base / "host", base / "home"
    cwd = base / "autograder"  # the instructor's working folder: the solutions and the grades are there
    for d in (sub, host, home, cwd, cwd / "solutions"):
        d.mkdir()
    (cwd / "solutions" / "lab2_solution.ipynb").write_text(SECRET, encoding="utf-8")
    (host / "victim.txt").write_text("keep me", encoding="utf-8")
    (home / "secret.txt").write_text(SECRET, encoding="utf-8")
    sock = _HostSocket()
    try:
        _submissions(sub, host, sock, home, cwd)
        before_sub, before_host = _digest(sub), _digest(host)
        out = base / "grades.csv"
        scratch = base / "scratch"
        scratch.mkdir()
        env = {**os.environ, "HOME": str(home), "H18_SECRET": SECRET, "BALANCELAB_SCRATCH": str(scratch)}
        started = time.monotonic()
        proc = subprocess.run([sys.executable, "-m", "balancelab.course.grading", str(sub), "--out", str(out),
                               "--cell-timeout", "10", "--notebook-timeout", "120", "--jobs", "2",
                               "--memory-mb", "1000", "--judge-timeout", "5"],
                              capture_output=True, text=True, timeout=1500, cwd=cwd, env=env)
        elapsed = time.monotonic() - started
    finally:
        sock.close()
    raw = list(csv.reader(out.open(encoding="utf-8"))) if out.exists() else []
    rows = {r["student"].lstrip("'"): r for r in csv.DictReader(out.open(encoding="utf-8"))} if out.exists() else {}
    return dict(proc=proc, rows=rows, raw=raw, size=out.stat().st_size if out.exists() else 0, sub=sub, host=host, before_sub=before_sub, before_host=before_host,
                connections=len(sock.connections), elapsed=elapsed, started=started, scratch=scratch)


def _scores(row, lab):
    return tuple(row[t.id] for t in tasks(lab))


def test_the_batch_runs(graded):
    assert graded["proc"].returncode == 0, graded["proc"].stderr[-2000:]
    assert len(graded["rows"]) == 43


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
    assert sig["2.1"] == "1" and sig["2.3"] == "0" and "did not stop within 2 s of the interrupt" in sig["notes"]


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
    zed = rows["zed_lab1"]  # lab 2's metadata in a file named lab 1: the file name decides (issue 18, G18 item 3)
    assert zed["lab"] == "lab1" and zed["max"] == str(int(sum(t.points for t in tasks(1)))) and zed["total"] == "0"
    assert zed["mismatch"] == "file name says lab1, metadata says lab2"
    assert "the notebook's metadata says lab2 but the file name says lab1: graded as lab1" in zed["notes"]
    untouched = rows["untouched_lab2"]
    assert untouched["lab"] == "lab2" and untouched["total"] == "0" and untouched["max"] == LAB2_MAX


def test_the_host_is_untouched(graded):
    assert _digest(graded["sub"]) == graded["before_sub"]
    assert _digest(graded["host"]) == graded["before_host"]
    assert not (graded["host"] / "pwned.txt").exists() and (graded["host"] / "victim.txt").exists()
    assert graded["rows"]["writer_lab2"]["2.1"] == "1"
    assert _marked_processes() == []
    assert graded["rows"]["detach_lab2"]["2.1"] == "1"


def test_a_formula_written_as_text_is_read_not_run(graded):
    row = graded["rows"]["textrce_lab1"]
    assert row["status"] == "graded" and row["1.2"] == "0"
    assert not (graded["host"] / "pwned.txt").exists()


def test_no_scratch_folder_is_left(graded):
    assert list(graded["scratch"].iterdir()) == []


def test_lab_sources_are_compared():
    nb = {"metadata": {"balancelab": {"lab": "lab5"}}}
    assert resolve_lab(nb, Path("x_lab5.ipynb"), "lab1") == ("lab1", "file name says lab5, metadata says lab5, "
                                                                     "--lab says lab1")
    assert resolve_lab(nb, Path("x.ipynb")) == ("lab5", "")
    assert resolve_lab({}, Path("x.ipynb")) == (None, "")
    # the file name decides over the notebook's tag; an id holding "lab3" does not name the lab
    assert resolve_lab(nb, Path("slab3_lab1.ipynb")) == ("lab1", "file name says lab1, metadata says lab5")
    assert resolve_lab({}, Path("Ann_LAB2.ipynb"))[0] == "lab2"


def test_ids_are_case_insensitive_everywhere():
    """G18 item 2: file name, folder, roster and personal numbers agree on one normal form."""
    from balancelab.course.check import task_numbers
    from balancelab.course.intake import identity

    assert identity("Alice_lab1.ipynb", None)[0] == identity("alice_lab1.ipynb", None)[0] == "alice"
    assert identity("ALICE/lab1.ipynb", None)[0] == "alice"
    assert identity("Alice/alice_lab1.ipynb", None) == ("alice", "file name")  # no "another id" note
    assert identity("x_lab1.ipynb", {"x_lab1.ipynb": " S1001 "})[0] == "s1001"
    for tid in ("1.1", "2.1", "3.1", "7.2"):
        assert task_numbers(tid, "Alice") == task_numbers(tid, "alice") == task_numbers(tid, " ALICE ")


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


def test_personal_numbers_are_those_of_the_file_name_not_of_the_notebook(graded):
    rows = graded["rows"]
    assert rows["pat_lab2"]["2.1"] == "1" and "STUDENT_ID" not in rows["pat_lab2"]["notes"]
    copy = rows["copy_lab2"]
    # a classmate's id and a classmate's answer: judged with copy's own numbers, and said so
    assert copy["2.1"] == "0"
    assert "declares STUDENT_ID 'pat' but is 'copy''s (file name): judged with 'copy''s numbers" in copy["notes"]
    # the published numbers' answer is wrong for a student with personal numbers
    assert rows["bob_lab2"]["2.1"] == "0" and rows["alice_lab2"]["2.1"] == "1"


def test_without_the_sandbox_the_grader_warns_and_still_grades(tmp_path):
    import warnings

    from balancelab.course.grading import grade_notebook
    from balancelab.course.sandbox import NO_SANDBOX_WARNING, run_limited

    with pytest.warns(RuntimeWarning, match="no sandbox"):
        r = run_limited([sys.executable, "-c", "print(7)"], tmp_path, 60, sandbox=False)
    assert r.stdout == "7\n" and not r.sandboxed
    path = tmp_path / "amy_lab2.ipynb"
    nbformat.write(submission_notebook("lab2", K_LAMP("amy")), path)
    with warnings.catch_warnings():
        warnings.simplefilter("error")  # grade_notebook notes it in the row instead of warning per notebook
        row = grade_notebook(path, sandbox=False, cell_timeout=30, notebook_timeout=120)
    assert row.scores["2.1"] == 1.0 and "NO SANDBOX" in row.notes
    assert "bubblewrap" in NO_SANDBOX_WARNING


def test_a_grader_installed_under_tmp_still_runs_inside_the_sandbox(tmp_path, monkeypatch):
    """The sandbox gives submissions an empty /tmp of their own; a grader whose checkout or
    virtual environment lives under /tmp (a CI runner's clone) must still find its own Python
    and package inside (a clean clone under /tmp once graded every notebook as an error). Only
    the Python's own folders are bound: a folder that is merely on ``sys.path`` (``python -m``
    puts the working folder there) stays out (issue 18, second round)."""
    import tempfile

    from balancelab.course.sandbox import run_limited

    if not sandbox_available():
        pytest.skip("bubblewrap is not available here")
    pkg = Path(tempfile.mkdtemp(dir="/tmp", prefix="grader_pkg_"))
    probe = [sys.executable, "-c", "import probe_mod; print(probe_mod.X)"]
    try:
        (pkg / "probe_mod.py").write_text("X = 'the grader is visible'\n")
        monkeypatch.syspath_prepend(str(pkg))
        env = {**os.environ, "PYTHONPATH": str(pkg)}
        on_path = run_limited(probe, tmp_path, 60, env=env, sandbox=True)
        monkeypatch.setattr(sys, "exec_prefix", str(pkg))  # a Python installed under /tmp
        r = run_limited(probe, tmp_path, 60, env=env, sandbox=True)
    finally:
        shutil.rmtree(pkg)
    assert r.sandboxed and r.stdout == "the grader is visible\n", (r.stdout, r.stderr[-500:])
    assert on_path.stdout == "" and "No module named 'probe_mod'" in on_path.stderr


# ------------------------------------------------------------------ issue 18

def test_answers_that_stall_a_judge_are_stopped_and_the_batch_goes_on(graded):
    """Item 2: each judge runs in the notebook's runner process with a time and memory limit."""
    rows = graded["rows"]
    for name, task in (("pow_lab1", "1.2"), ("nest_lab1", "1.2"), ("huge_lab2", "2.1"), ("precise_lab2", "2.1"),
                       ("hugejudge_lab2", "2.1"), ("precisejudge_lab2", "2.1")):
        row = rows[name]
        assert row[task] == "0", (name, row)
        assert row["status"] in ("graded", "timeout"), (name, row["status"], row["notes"])
        assert float(row["seconds"]) < 150, (name, row["seconds"])
        assert row["peak_mb"] != ""
    # the data reached the judge, which judged it (at random instances, no simplify: 1.2's judge no longer
    # stalls on these) or was stopped at its limit (5 s here) with a clear message
    for name in ("pow_lab1", "nest_lab1"):
        assert rows[name]["1.1"] == "1" and rows[name]["status"] == "graded"
        message = rows[name]["1.2 message"]
        assert ("took more than 5 s to check" in message or message.startswith("✘ Your r_c is not equivalent")
                or message.startswith("✘ Your r_c is too large or too deeply nested to be checked")), message
    for name in ("hugejudge_lab2", "precisejudge_lab2"):
        assert rows[name]["status"] == "graded" and rows[name]["2.1 message"].startswith("✘"), rows[name]


def test_answer_files_made_fifos_or_links_change_nothing(graded):
    """Item 2: no answer file is read; the export comes over the kernel protocol."""
    row = graded["rows"]["files_lab2"]
    assert row["status"] == "graded" and row["2.1"] == "1"


def test_links_fifos_and_devices_are_refused_not_read(graded):
    """Items 2 and 8: only regular files are graded; a link is a row with status `refused`."""
    rows = graded["rows"]
    for name, why in (("sym_lab1", "symbolic link"), ("zero_lab2", "symbolic link"),
                      ("hostfile_lab2", "symbolic link"), ("fifo_lab2", "FIFO")):
        assert rows[name]["status"] == "refused" and rows[name]["total"] == "0", name
        assert why in rows[name]["notes"], (name, rows[name]["notes"])


def test_the_sandbox_shows_no_solutions_submissions_home_socket_or_environment(graded):
    """Item 1: the notebook looked for them; any it found would be an error in its row."""
    row = graded["rows"]["snoop_lab2"]
    assert row["status"] == "graded" and row["2.1"] == "1", row
    assert "RuntimeError" not in row["notes"], row["notes"]
    assert graded["connections"] == 0


def test_forged_reports_and_a_killed_kernel_give_no_points(graded):
    """Item 3: report lines printed on every output, fake answer files, every process killed."""
    row = graded["rows"]["forger_lab2"]
    assert row["status"] == "kernel died" and row["total"] == "0", row
    text = " ".join(row.values())
    assert "FORGED" not in text
    assert "Kernel is running" not in row["notes"] and "the kernel died in cell 1" in row["notes"]


def test_patched_print_and_json_dumps_do_not_change_the_exported_answer(graded):
    """The right value is printed by every patched function, the variable holds a wrong one."""
    row = graded["rows"]["monkey_lab2"]
    assert row["2.1"] == "0", row
    assert "replaces `dumps`" in row["notes"] and "replaces `print`" in row["notes"]


def test_caps_hold_for_the_whole_submission_and_are_noted(graded):
    """Item 4: the answers given before a bomb still count; the row says which cap was hit."""
    rows = graded["rows"]
    for name in ("membomb_lab2", "forkbomb_lab2", "tmpbomb_lab2", "outbomb_lab2"):
        assert rows[name]["2.1"] == "1", (name, rows[name]["status"], rows[name]["notes"])
    assert "memory cap" in rows["membomb_lab2"]["notes"]
    assert float(rows["membomb_lab2"]["peak_mb"]) <= 1000 + 1
    assert "process cap (64 at once)" in rows["forkbomb_lab2"]["notes"]
    for folder in ("/tmp", "/dev/shm", "/home/student"):
        assert f"in-memory folder {folder} reached its cap" in rows["tmpbomb_lab2"]["notes"], folder
    assert "output cap" in rows["outbomb_lab2"]["notes"]


def test_no_cell_of_the_table_is_a_formula_and_student_text_is_short(graded):
    """Item 7: names, exception names and echoed answers are escaped and cut short."""
    raw = graded["raw"]
    for record in raw:
        for cell in record:
            assert not cell.startswith(("=", "+", "-", "@", "\t", "\r")), cell
    row = graded["rows"]["=1+2*3_lab2"]
    # no id in that name: the published numbers' answer scores 0 (attack A18: a renamed file got 5/5)
    assert row["student"] == "'=1+2*3_lab2" and row["2.1"] == "0" and row["status"] == "unidentified"
    assert "NO STUDENT ID" in row["notes"]
    long = graded["rows"]["long_lab2"]
    assert len(long["2.1 message"]) <= 202 and "A" * 50 not in long["2.1 message"]
    assert all(len(v) < 4000 for r in graded["rows"].values() for v in r.values())


def test_every_row_records_wall_time_and_memory(graded):
    for name, row in graded["rows"].items():
        if row["status"] in ("refused", "malformed", "unknown lab"):
            continue
        assert 0 < float(row["seconds"]) < graded["elapsed"], name
        assert float(row["peak_mb"]) > 10, name


def test_a_runner_that_dies_gives_error_and_zero(tmp_path):
    """Item 3: a runner killed before it reports (here by the test, as the kernel cannot) gives no grade."""
    import signal

    from balancelab.course import grading

    if not sandbox_available():
        pytest.skip("bubblewrap is not available here")
    path = tmp_path / "amy_lab2.ipynb"
    nbformat.write(submission_notebook("lab2", K_LAMP("amy"), "import time\ntime.sleep(120)"), path)
    rows = []
    worker = threading.Thread(target=lambda: rows.append(grading.grade_notebook(path, cell_timeout=200,
                                                                                 notebook_timeout=300)))
    worker.start()
    assert _wait(lambda: bool(grading.ACTIVE), 120)
    time.sleep(15)  # the first answer has been exported by now (the kernel sleeps in the next cell)
    for pid in list(grading.ACTIVE):
        os.kill(pid, signal.SIGKILL)
    worker.join(120)
    row = rows[0]
    assert row.status == "error" and row.total == 0.0, (row.status, row.notes)
    assert "the runner was killed by signal 9: nothing was graded (0 points)" in row.notes
    assert "Kernel" not in row.notes


def _wait(condition, timeout: float) -> bool:
    end = time.monotonic() + timeout
    while time.monotonic() < end:
        if condition():
            return True
        time.sleep(0.2)
    return False


def _scratch_of(pid: int, root: Path) -> list[Path]:
    return list(root.glob(f"balancelab-grade-{pid}-*"))


@pytest.mark.parametrize("how", ["SIGTERM", "SIGKILL"])
def test_a_killed_grader_keeps_its_rows_and_leaves_no_scratch_or_process(tmp_path, how):
    """Items 2 and 10: rows are written as notebooks finish; scratch folders and processes go."""
    import signal

    if not sandbox_available():
        pytest.skip("bubblewrap is not available here")
    sub, scratch = tmp_path / "sub", tmp_path / "scratch"
    sub.mkdir()
    scratch.mkdir()
    mark = f"{MARK}-{how}"
    nbformat.write(submission_notebook("lab2", K_LAMP("quick")), sub / "quick_lab2.ipynb")
    nbformat.write(submission_notebook("lab2", K_LAMP("slow"), f"import time\n_ = {mark!r}\ntime.sleep(300)"),
                   sub / "slow_lab2.ipynb")
    out = tmp_path / "grades.csv"
    env = {**os.environ, "BALANCELAB_SCRATCH": str(scratch)}
    proc = subprocess.Popen([sys.executable, "-m", "balancelab.course.grading", str(sub), "--out", str(out),
                             "--cell-timeout", "200", "--notebook-timeout", "250", "--jobs", "2"],
                            cwd=ROOT, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, env=env)
    try:
        assert _wait(lambda: out.exists() and "quick_lab2" in out.read_text(encoding="utf-8"), 240)
        assert _scratch_of(proc.pid, scratch)  # the slow one is still running
        proc.send_signal(getattr(signal, how))
        proc.wait(30)
    finally:
        proc.kill()
    rows = {r["student"]: r for r in csv.DictReader(out.open(encoding="utf-8"))}
    assert rows["quick_lab2"]["2.1"] == "1" and "slow_lab2" not in rows
    # the runner dies with the grader (and the kernel with the runner)
    assert _wait(lambda: not [p for p in _marked_processes() if mark in p], 30)
    if how == "SIGKILL":  # nothing can run at SIGKILL: the next grader deletes what is left
        from balancelab.course.caps import Cgroup
        from balancelab.course.grading import clean_stale

        clean_stale(scratch)
        Cgroup.clean_stale()
    assert _scratch_of(proc.pid, scratch) == []
    from balancelab.course.caps import _parents

    assert [d for p in (_parents() or {}).values() for d in p.glob(f"balancelab-{proc.pid}-*")] == []


def test_identity_comes_from_the_roster(tmp_path):
    """Item 5: the roster says whose a file is; the notebook's own STUDENT_ID is only compared."""
    if not sandbox_available():
        pytest.skip("bubblewrap is not available here")
    sub = tmp_path / "sub"
    sub.mkdir()
    claims_alice = "STUDENT_ID = 'alice'\n" + personal_r_c("alice")
    nbformat.write(submission_notebook("lab1", claims_alice), sub / "malice_lab1.ipynb")
    nbformat.write(submission_notebook("lab1", personal_r_c("s2002")), sub / "ben_lab1.ipynb")
    nbformat.write(submission_notebook("lab1", personal_r_c("")), sub / "nobody_lab1.ipynb")
    roster = tmp_path / "roster.csv"
    roster.write_text("file,student_id\nmalice_lab1.ipynb,m77\nben_lab1.ipynb,s2002\n", encoding="utf-8")
    out = tmp_path / "grades.csv"
    proc = subprocess.run([sys.executable, "-m", "balancelab.course.grading", str(sub), "--out", str(out),
                           "--roster", str(roster), "--jobs", "2", "--cell-timeout", "30"],
                          capture_output=True, text=True, timeout=600, cwd=ROOT)
    assert proc.returncode == 0, proc.stderr[-2000:]
    rows = {r["student"]: r for r in csv.DictReader(out.open(encoding="utf-8"))}
    assert rows["ben_lab1"]["1.1"] == "1"
    malice = rows["malice_lab1"]
    assert malice["1.1"] == "0" and "declares STUDENT_ID 'alice' but is 'm77''s (roster)" in malice["notes"]
    nobody = rows["nobody_lab1"]
    assert "NO STUDENT ID (not in the roster)" in nobody["notes"] and nobody["1.1"] == "0"
    assert nobody["status"] == "unidentified"


def test_no_lab_answer_in_a_docstring_of_the_package(tmp_path):
    """Item 6: no number in a docstring of the installed package passes a numeric task; the scan
    the hand-out runs finds one that does."""
    import balancelab
    from balancelab.course.leaks import answer_leaks
    from balancelab.methods.lecture import single_link_spring

    assert answer_leaks(Path(balancelab.__file__).parent) == []
    right = round(single_link_spring(1.5, 0.4, 0.25, 0.12).parameters["k"], 3)
    (tmp_path / "leaky.py").write_text(f"def f():\n    '''>>> f()\n    {right}\n    '''\n", encoding="utf-8")
    assert [x.split(":")[0] for x in answer_leaks(tmp_path)] == ["task 2.1"]


def test_the_graders_working_folder_and_home_are_not_in_the_sandbox(graded):
    """Second round, break 1: the grader ran inside the folder with the solutions (``python -m`` puts
    it on ``sys.path``); break 2: no user namespace of its own, no cgroup file, no child cgroup."""
    row = graded["rows"]["escape_lab2"]
    assert row["status"] == "graded" and row["2.1"] == "1", row
    assert "RuntimeError" not in row["notes"], row["notes"]


def test_attempt_keys_are_task_ids_and_counts_are_capped(graded):
    """Break 5: keys the student chose never reach the table; the table stays small."""
    row = graded["rows"]["attempts_lab2"]
    assert row["2.1"] == "1" and row["reported_attempts"] == "2.1:1000000", row["reported_attempts"][:200]
    assert graded["size"] < 200_000


def test_the_printed_summary_has_no_control_characters(graded):
    """Break 5: a file name with terminal escape sequences is printed without them."""
    out = graded["proc"].stdout
    assert "term_lab2" in out
    assert not any(c in out for c in "\x1b\x07\r"), repr(out[-500:])


def test_the_folder_names_the_student_and_duplicate_ids_are_flagged(graded):
    """Break 4: an id in the file name comes first; a folder that names another id is said in the
    row, and two submissions of one lab with one id are flagged on both rows (mallory's copy of
    alice's file and alice's own)."""
    rows = graded["rows"]
    mallory = rows["mallory/alice_lab2"]
    assert "the folder 'mallory' names another id: check whose it is" in mallory["notes"], mallory["notes"]
    assert "DUPLICATE ID 'alice': also alice_lab2.ipynb" in mallory["notes"]
    assert "DUPLICATE ID 'alice': also mallory/alice_lab2.ipynb" in rows["alice_lab2"]["notes"]
    for name, other in (("dup_lab2", "dup/lab2.ipynb"), ("dup/lab2", "dup_lab2.ipynb")):
        assert f"DUPLICATE ID 'dup': also {other}" in rows[name]["notes"], rows[name]["notes"]
        assert rows[name]["2.1"] == "1"
    assert "DUPLICATE" not in rows["bob_lab2"]["notes"]


def test_merge_reads_huge_cells_and_keeps_only_task_attempts(tmp_path):
    """Break 5: a table with a 1 MB cell (an older grader's) merges; the attempts are sanitised."""
    from balancelab.course.grading import main

    header = "student,lab,status,total,max,2.1,notes,mismatch,2.1 message,seconds,peak_mb,attempts\n"
    big = "=HYPERLINK(1)" + "A" * 2 ** 20
    (tmp_path / "a.csv").write_text(header + f'eve,lab2,graded,1,1,1,,,ok,1,1,"2.1:3 {big}:5"\n', encoding="utf-8")
    (tmp_path / "b.csv").write_text(header + "bob,lab2,graded,0,1,0,,,no,1,1,2.1:2\n", encoding="utf-8")
    assert main(["merge", str(tmp_path / "a.csv"), str(tmp_path / "b.csv"), "--out", str(tmp_path / "all.csv")]) == 0
    rows = {r["student"]: r for r in csv.DictReader((tmp_path / "all.csv").open(encoding="utf-8"))}
    # an older grader's column "attempts" is read; the merged table says whose count it is
    assert rows["eve"]["reported_attempts"] == "2.1:3" and rows["bob"]["reported_attempts"] == "2.1:2"
    assert (tmp_path / "all.csv").stat().st_size < 10_000


def test_the_notebook_limit_stops_the_run_and_keeps_earlier_answers(tmp_path):
    """Break 6: cells that each stay under the cell limit run past the notebook limit: the status
    is ``timeout``, the answers given before count; a forged export line nested 200,000 deep is
    no export (the answers before it stay)."""
    if not sandbox_available():
        pytest.skip("bubblewrap is not available here")
    from balancelab.course.grading import grade_notebook

    nb = submission_notebook("lab2", K_LAMP("slow"), DEEP_EXPORT, *["import time\ntime.sleep(6)"] * 8)
    path = tmp_path / "slow_lab2.ipynb"
    nbformat.write(nb, path)
    started = time.monotonic()
    row = grade_notebook(path, cell_timeout=10, notebook_timeout=15)
    assert row.status == "timeout" and row.scores["2.1"] == 1.0, (row.status, row.notes)
    assert "ran past its 15 s limit" in row.notes
    assert time.monotonic() - started < 15 + 10 + 120  # at most one cell limit past the budget, plus start-up


def test_cgroup_cleanup_reaches_child_cgroups():
    """Break 3: a process moved into a child cgroup ("hidden") is killed and the whole tree removed,
    by :meth:`Cgroup.remove` and by :meth:`Cgroup.clean_stale` (the kernel itself cannot make one:
    ``test_the_graders_working_folder_and_home_are_not_in_the_sandbox``)."""
    from balancelab.course.caps import Caps, Cgroup

    for stale in (False, True):
        cg = Cgroup(Caps())
        if not cg.dirs:
            pytest.skip("no cgroup can be made here")
        proc = subprocess.Popen(["sleep", "600"])
        try:
            hidden = []
            for d in cg.dirs.values():
                (d / "hidden").mkdir()
                (d / "hidden" / "cgroup.procs").write_text(str(proc.pid))
                hidden.append(d / "hidden")
            if stale:  # a grader killed with SIGKILL: its cgroup is named after a pid that is gone
                dead = subprocess.Popen(["true"])
                dead.wait()
                renamed = [d.rename(d.with_name(f"balancelab-{dead.pid}-{uuid.uuid4().hex[:12]}"))
                           for d in cg.dirs.values()]
                assert Cgroup.clean_stale() >= 1
                gone = renamed
            else:
                cg.remove()
                gone = hidden
            assert proc.wait(timeout=10) == -9
            assert not any(p.exists() for p in gone + hidden)
        finally:
            proc.kill()
            proc.wait()


#: Issue 18, item 3: who the kernel is on the host. The cell reports its uid and the host uid its
#: user namespace maps it to, tries to read root-only files (mode 600) the grader put in bound folders
#: (the Python's prefix, the package folder) and to append to those and to world-readable ones.
WHO = """import os
inside = os.getuid()
outside = next(int(line.split()[1]) for line in open("/proc/self/uid_map") if int(line.split()[0]) == inside)
found = []
for path in {paths!r}:
    try:
        if path.endswith("_600.txt"):
            found.append("read " + open(path).read())
    except OSError:
        pass
    try:
        open(path, "a").write("x")
        found.append("wrote " + path)
    except OSError:
        pass
print("WHO", inside, outside, found)
if (inside, outside) != (65534, 65534) or found:
    raise RuntimeError(f"KERNEL IS {{inside}} (host {{outside}}): {{found}}")"""


def test_a_root_grader_runs_the_kernel_as_nobody(tmp_path):
    """Issue 18, item 3: a grader run by root gives the kernel the host's uid 65534, not root
    without capabilities: a root-only file in a folder the sandbox binds cannot be read, a
    root-owned one cannot be written, and the submission is still graded."""
    from balancelab.course.sandbox import kernel_runs_as_nobody

    if not sandbox_available():
        pytest.skip("bubblewrap is not available here")
    if os.geteuid() != 0:
        pytest.skip("the grader is not root here: the kernel is the grader's own unprivileged user")
    assert kernel_runs_as_nobody(), "as root the kernel must run as uid 65534 (setpriv and user namespaces work here)"
    import balancelab

    planted = []
    for folder in (Path(sys.prefix), Path(balancelab.__file__).resolve().parent):
        for mode in (0o600, 0o644):
            p = folder / f"h18_root_{uuid.uuid4().hex[:6]}_{mode:o}.txt"
            p.write_text(SECRET)
            p.chmod(mode)
            planted.append(p)
    sub, out = tmp_path / "sub", tmp_path / "grades.csv"
    sub.mkdir()
    who = WHO.format(paths=[str(p) for p in planted])
    nbformat.write(submission_notebook("lab2", who, K_LAMP("who")), sub / "who_lab2.ipynb")
    try:
        proc = subprocess.run([sys.executable, "-m", "balancelab.course.grading", str(sub), "--out", str(out)],
                              capture_output=True, text=True, timeout=600, cwd=tmp_path)
        after = {p: p.read_text() for p in planted}
    finally:
        for p in planted:
            p.unlink()
    row = next(csv.DictReader(out.open(encoding="utf-8")))
    assert proc.returncode == 0, proc.stderr[-2000:]
    assert row["status"] == "graded" and row["2.1"] == "1", row
    assert "RuntimeError" not in row["notes"], row["notes"]
    assert all(text == SECRET for text in after.values())


def _pulley_code(sid: str) -> str:
    """Code of task 3.1's answer for ``sid``'s lever (bisection on the exact string model)."""
    return ("from balancelab.course.check import task_numbers as _tn\n"
            "from balancelab.methods.realize import pulley_balance_error, pulley_lever\n"
            f"_n = _tn('3.1', {sid!r})\n"
            "_lo, _hi = 1e-5, 0.05\n"
            "for _ in range(40):\n"
            "    _mid = (_lo + _hi) / 2\n"
            "    _e = pulley_balance_error(pulley_lever(radius=_mid, **_n)).residual_torque / "
            "(_n['mass'] * bl.G * _n['length'])\n"
            "    _lo, _hi = (_mid, _hi) if _e < 0.01 else (_lo, _mid)\n"
            "pulley_radius = (_lo + _hi) / 2")


def _stiffness_code(sid: str) -> str:
    """Code of task 7.2's answer for ``sid``'s arm."""
    return ("from balancelab.course.check import task_numbers as _tn\n"
            "from balancelab.course.check.lab7 import lab7_arm, lab7_candidates\n"
            f"_arm = lab7_arm(_tn('7.2', {sid!r}))\n"
            "k_total_min = sum(s.k for s in bl.balance(_arm, springs=lab7_candidates(_arm), "
            "objective='min_stiffness').springs)")


def _counterweights_code(sid: str) -> str:
    """Code of a right design for task 1.4 for ``sid``'s link masses (each link as a lever on its pivot)."""
    return ("from balancelab.course.check import task_numbers as _tn\n"
            f"_m1, _m3, _m4 = _tn('1.4', {sid!r})['masses']\n"
            "_mc = bl.lecture.equivalent_masses(crank=0.2, coupler=0.5, rocker=0.4, mass=_m3, com=(0.2, 0.0))['c'].real * _m3\n"
            "counterweights = {'crank': (3.0, (-(_m1 * 0.1 + (_m3 - _mc) * 0.2) / 3.0, 0.0)),\n"
            "                  'rocker': (3.0, (-(_m4 * 0.2 + _mc * 0.4) / 3.0, 0.0))}")


def test_a_friends_or_the_published_answer_scores_nothing(tmp_path):
    """Issue 18, item 6: tasks 3.1, 7.2 and the design tasks 2.4 and 1.4 use personal numbers. Alice's own
    answers score; the same answers in bob's file (even declaring alice's id) and the answers for the
    published numbers in dan's file score 0, graded end to end with the id of the file name."""
    from balancelab.course.check import task_numbers

    if not sandbox_available():
        pytest.skip("bubblewrap is not available here")
    from balancelab.course.check import lab3, lab7

    answer = {"3.1": lambda n: lab3._pulley_radius_limit(**n), "7.2": lambda n: lab7._least_stiffness(lab7._key(n)),
              "2.4": lambda n: n["weight"] * n["length"],  # a design balances the load with this moment
              "1.4": lambda n: n["masses"][0] + 10 * n["masses"][1] + 100 * n["masses"][2]}  # any mass differs
    tol = {"3.1": 0.02, "7.2": 0.005, "2.4": 0.001, "1.4": 0.0001}
    mine = {t: answer[t](task_numbers(t, "alice")) for t in answer}
    for t in answer:  # the published answer is far from every student's (numbers are drawn so)
        assert abs(answer[t](task_numbers(t, "")) / mine[t] - 1) > 2 * tol[t]
    # a friend whose right answers differ from alice's (two students may, rarely, share an answer)
    friend = next(f for f in (f"bob{i}" for i in range(20))
                  if all(abs(answer[t](task_numbers(t, f)) / mine[t] - 1) > 2 * tol[t] for t in answer))
    sub, out = tmp_path / "sub", tmp_path / "grades.csv"
    sub.mkdir()
    lab3_rest = ["partner_free_length = ...", "ordinary_spring = ..."]
    books = {"alice_lab3": [_pulley_code("alice")], f"{friend}_lab3": ["STUDENT_ID = 'alice'\n" + _pulley_code("alice")],
             "dan_lab3": [_pulley_code("")], "alice_lab7": [_stiffness_code("alice")],
             f"{friend}_lab7": [_stiffness_code("alice")], "dan_lab7": [_stiffness_code("")],
             "alice_lab2": [LEVER], f"{friend}_lab2": [LEVER], "dan_lab2": [personal_lever_spring("")],
             "alice_lab1": [_counterweights_code("alice")], f"{friend}_lab1": [_counterweights_code("alice")],
             "dan_lab1": [_counterweights_code("")]}
    for name, cells in books.items():
        lab = name.split("_")[1]
        nbformat.write(submission_notebook(lab, *cells, *(lab3_rest if lab == "lab3" else [])), sub / f"{name}.ipynb")
    proc = subprocess.run([sys.executable, "-m", "balancelab.course.grading", str(sub), "--out", str(out),
                           "--jobs", "2"], capture_output=True, text=True, timeout=900, cwd=tmp_path)
    assert proc.returncode == 0, proc.stderr[-2000:]
    rows = {r["student"]: r for r in csv.DictReader(out.open(encoding="utf-8"))}
    for lab, task, points in (("lab3", "3.1", "1"), ("lab7", "7.2", "1"), ("lab2", "2.4", "2"), ("lab1", "1.4", "2")):
        assert rows[f"alice_{lab}"][task] == points, rows[f"alice_{lab}"]
        assert rows[f"{friend}_{lab}"][task] == "0", rows[f"{friend}_{lab}"]
        assert rows[f"dan_{lab}"][task] == "0", rows[f"dan_{lab}"]
    assert "declares STUDENT_ID" in rows[f"{friend}_lab3"]["notes"]


def test_duplicate_ids_across_shards_are_flagged_at_merge(tmp_path):
    """Issue 18, item 5: one id graded on two shards (alice's own file on one, a copy in mallory's
    folder on another; two roster files naming one student) is flagged in both rows of the merged
    table; other labs of that id, and other students, are not."""
    from balancelab.course.gradetable import GradeRow, read_csv, write_csv

    def row(student, lab="lab2"):
        task = "1.1" if lab == "lab1" else "2.1"
        return GradeRow(student, lab, "graded", {task: 1.0}, {task: 1.0})

    one = write_csv([row("alice_lab2"), row("bob_lab2"), row("alice_lab1", "lab1"), row("a")], tmp_path / "p1.csv")
    two = write_csv([row("mallory/alice_lab2"), row("carol_lab2"), row("b")], tmp_path / "p2.csv")
    out = tmp_path / "all.csv"
    roster = tmp_path / "roster.csv"
    roster.write_text("file,student_id\na.ipynb,s77\nb.ipynb,s77\nalice_lab2.ipynb,alice\n"
                      "mallory/alice_lab2.ipynb,alice\nbob_lab2.ipynb,bob\ncarol_lab2.ipynb,carol\n"
                      "alice_lab1.ipynb,alice\n", encoding="utf-8")
    for extra, flagged in (([], {"alice_lab2", "mallory/alice_lab2"}),
                           (["--roster", str(roster)], {"alice_lab2", "mallory/alice_lab2", "a", "b"})):
        proc = subprocess.run([sys.executable, "-m", "balancelab.course.grading", "merge", str(one), str(two),
                               "--out", str(out), *extra], capture_output=True, text=True, timeout=120)
        assert proc.returncode == 0, proc.stderr
        notes = {r.student: r.notes for r in read_csv(out)}
        assert {s for s, n in notes.items() if n.startswith("DUPLICATE ID")} == flagged, notes
        assert "mallory/alice_lab2" in notes["alice_lab2"] and "alice_lab2" in notes["mallory/alice_lab2"]


def test_a_renamed_file_gets_no_published_answers_and_no_control_characters_reach_the_csv(tmp_path):
    """Outside-view attack A18: ``mallory_lab1 (1).ipynb`` (a browser's re-download) and
    ``Mallory_Lab1.ipynb`` holding the published answers scored 5/5 with a note; file names with an
    escape sequence or a line break reached the CSV raw. Now: ids are case-insensitive, so
    ``Mallory_Lab1`` is mallory's lab 1 and judged with mallory's numbers (the published answers
    score 0 on the personal tasks); the others are ``unidentified`` with the personal tasks 0; and the
    CSV holds printable text only, one record a line."""
    if not sandbox_available():
        pytest.skip("bubblewrap is not available here")
    sub, out = tmp_path / "sub", tmp_path / "grades.csv"
    sub.mkdir()
    names = ["mallory_lab1 (1)", "Mallory_Lab1", "x\x1b[2J\x1b[31mFAKE_lab1", "evil\nalice,lab1,graded_lab1"]
    for name in names:
        nbformat.write(submission_notebook("lab1", personal_r_c("")), sub / f"{name}.ipynb")
    nbformat.write(submission_notebook("lab1", personal_r_c("carol")), sub / "carol_lab1.ipynb")
    proc = subprocess.run([sys.executable, "-m", "balancelab.course.grading", str(sub), "--out", str(out),
                           "--jobs", "2", "--lab", "lab1"], capture_output=True, text=True, timeout=900, cwd=tmp_path)
    assert proc.returncode == 0, proc.stderr[-2000:]
    text = out.read_text(encoding="utf-8")
    assert all(c.isprintable() or c in "\n\r" for c in text) and "\x1b" not in text
    rows = list(csv.DictReader(out.open(encoding="utf-8")))
    assert len(rows) == len(names) + 1                      # one record per submission, none forged
    by_name = {r["student"]: r for r in rows}
    assert by_name["carol_lab1"]["1.1"] == "1" and by_name["carol_lab1"]["status"] == "graded"
    mallory = by_name["Mallory_Lab1"]
    assert mallory["status"] == "graded" and mallory["1.1"] == "0" and "NO STUDENT ID" not in mallory["notes"]
    for r in rows:
        if r["student"] not in ("carol_lab1", "Mallory_Lab1"):
            assert r["status"] == "unidentified" and r["1.1"] == "0", r
            assert "NO STUDENT ID" in r["notes"]


#: Issue 18, G18 item 4: a cell hooks IPython's input transformers, so that every later cell the
#: runner sends (its export probe included) is rewritten: the probe then prints a line of the
#: notebook's choosing with the probe's own nonce: full in-memory folders, one check attempt.
TRANSFORM_HOOK = """import re, subprocess, sys
from balancelab.course.check import check
for _ in range(40):
    check("2.1", 1.0)
def _forge(lines):
    src = "".join(lines)
    found = re.search(r"'([0-9a-f]{{32}})' \\+ ' '", src)
    if not found:
        return lines
    line = found.group(1) + ' {{"k_lamp": {{"num": "%r"}}, "__attempts__": {{"2.1": 1}}, ' % k_lamp
    line += '"__fs__": {{"/tmp": 1.0, "/dev/shm": 1.0, "/home/student": 1.0}}}}'
    return ["import sys as _x\\n", "type(_x.stdout).write(_x.stdout, %r + chr(10))\\n" % line]
get_ipython().input_transformers_post.append(_forge)
subprocess.Popen([sys.executable, "-c", "import time; time.sleep(600)", {mark!r}], start_new_session=True)"""


def test_ids_lab_tags_and_transformer_hooks(tmp_path):
    """G18, items 2-4, each an end-to-end graded notebook, then the host checked.

    * ids are case-insensitive: ``Alice_lab1`` and ``alice_lab1`` are one student (a duplicate),
      a ``STUDENT_ID`` differing only in case is the same id, and personal numbers drawn for
      ``"Carol"`` in the notebook are those the grader judges ``CAROL_lab1`` with;
    * the file name decides the lab; a metadata tag that disagrees (or names no lab) is a note
      that says so, never a false "cannot tell which lab";
    * a notebook that hooks IPython's input transformers to rewrite the runner's export gets no
      note about a cap it did not hit (the runner measures the folders itself), and the attempt
      count it forged is in the column of what the notebook reported.
    """
    if not sandbox_available():
        pytest.skip("bubblewrap is not available here")
    sub, scratch = tmp_path / "sub", tmp_path / "scratch"
    sub.mkdir()
    scratch.mkdir()
    notebooks = {
        "Alice_lab1": submission_notebook("lab1", personal_r_c("alice")),
        "alice_lab1": submission_notebook("lab1", personal_r_c("ALICE")),
        "Bob_lab1": submission_notebook("lab1", "STUDENT_ID = 'bob'\n" + personal_r_c("bob")),
        "CAROL_lab1": submission_notebook("lab1", "from balancelab.course.check import set_student\n"
                                          "STUDENT_ID = 'Carol'\nset_student(STUDENT_ID)\n"
                                          + personal_r_c("Carol").replace(", 'Carol')", ")")),
        "meta_lab1": submission_notebook("lab7", personal_r_c("meta")),
        "bogus_lab1": submission_notebook("lab99", personal_r_c("bogus")),
        "nameless": submission_notebook("lab99", personal_r_c("")),
        "hook_lab2": submission_notebook("lab2", K_LAMP("hook"), TRANSFORM_HOOK.format(mark=MARK + "-g18")),
    }
    for name, nb in notebooks.items():
        nbformat.write(nb, sub / f"{name}.ipynb")
    out = tmp_path / "grades.csv"
    proc = subprocess.run([sys.executable, "-m", "balancelab.course.grading", str(sub), "--out", str(out),
                           "--jobs", "2", "--cell-timeout", "30"], capture_output=True, text=True, timeout=900,
                          cwd=ROOT, env={**os.environ, "BALANCELAB_SCRATCH": str(scratch)})
    assert proc.returncode == 0, proc.stderr[-2000:]
    rows = {r["student"]: r for r in csv.DictReader(out.open(encoding="utf-8"))}
    assert set(rows) == set(notebooks)
    # item 2: one student, whatever the case
    for name in ("Alice_lab1", "alice_lab1"):
        assert rows[name]["1.1"] == "1", rows[name]["notes"]
        assert "DUPLICATE ID 'alice'" in rows[name]["notes"], rows[name]["notes"]
    assert rows["Bob_lab1"]["1.1"] == "1" and "declares" not in rows["Bob_lab1"]["notes"]
    assert "DUPLICATE" not in rows["Bob_lab1"]["notes"]
    assert rows["CAROL_lab1"]["1.1"] == "1" and "declares" not in rows["CAROL_lab1"]["notes"]
    # item 3: the file name decides; the metadata's disagreement is said as it is
    for name, tag in (("meta_lab1", "lab7"), ("bogus_lab1", "lab99")):
        row = rows[name]
        assert row["lab"] == "lab1" and row["status"] == "graded" and row["1.1"] == "1", (name, row["notes"])
        assert f"the notebook's metadata says {tag} but the file name says lab1: graded as lab1" in row["notes"]
        assert row["mismatch"] == f"file name says lab1, metadata says {tag}"
    nameless = rows["nameless"]
    assert nameless["status"] == "unknown lab"
    assert "the notebook's metadata says lab99, which is no lab of this course" in nameless["notes"]
    assert "no balancelab.lab metadata" not in nameless["notes"]
    # item 4: the forged export changes the answer it carries, never what the grader measured
    hook = rows["hook_lab2"]
    assert hook["status"] == "graded" and hook["2.1"] == "1", hook["notes"]
    assert "in-memory folder" not in hook["notes"] and "reached" not in hook["notes"], hook["notes"]
    assert "input transformers" in hook["notes"]
    assert hook["reported_attempts"] == "2.1:1"  # the notebook's word, in the column that says so
    assert float(hook["seconds"]) > 0 and float(hook["peak_mb"]) > 0
    # the host: no scratch folder, no process of a submission left
    assert list(scratch.iterdir()) == []
    assert _marked_processes() == []


#: Issue 18, brief g18 item 2: a cell that raises an exception whose text reads like the grader's cap
#: notes, after hooking what IPython runs and shows (``transform_cell``, ``sys.displayhook``,
#: ``events``): the row's notes about caps come only from the runner's measurements, and the kernel's
#: own words (the exception) are quoted and marked as the submission's.
KERNEL_WORDS = """import sys
ip = get_ipython()
_transform = ip.transform_cell
ip.transform_cell = lambda src: _transform(src) + "\\nprint('the memory cap was reached')\\n"
sys.displayhook = lambda value: print("; the process cap (64 at once) was reached")
ip.events.register("post_run_cell", lambda result=None: print("output cap: 9 MB were dropped"))
class CapReached(Exception):
    pass
raise CapReached("; the memory cap of the notebook's processes (1000 MB) was reached; "
                 "the in-memory folder /tmp reached its cap (256 MB)")"""
#: item 4: the kernel starts without ipykernel's debugger (debugpy blocked: its import cost every kernel
#: time) and with the grader's matplotlib font list (each kernel scanned the fonts again)
NO_DEBUGGER = """import io, logging, sys
if "debugpy" not in sys.modules or sys.modules["debugpy"] is not None:
    raise RuntimeError("debugpy was not blocked")
assert "matplotlib.font_manager" not in sys.modules
_said = io.StringIO()
_log = logging.getLogger("matplotlib.font_manager")
_log.addHandler(logging.StreamHandler(_said))
_log.setLevel(logging.INFO)
import matplotlib.font_manager
if "generated new fontManager" in _said.getvalue():
    raise RuntimeError("the font list was built again")"""
_GRADER_CAP_NOTES = ("the memory cap", "the in-memory folder", "the process cap", "output cap")


def test_student_id_column_roster_warnings_and_the_kernels_words_in_notes(tmp_path):
    """Brief g18, items 1-4, end to end with a roster.

    * the table's ``student_id`` column (after ``student``) is the id each row was judged with,
      from the roster, and survives ``read_csv`` and ``merge_csv``;
    * roster rows that match no file, match several files, or give one id to two files of a lab
      are warned about on stderr and in the printed summary;
    * a notebook that hooks ``transform_cell``, ``sys.displayhook`` and ``events`` and raises an
      exception worded like cap notes gets no cap note: its words are quoted as its own;
    * a metadata lab tag that is no lab name leaves the file name's lab, with a note;
    * the kernel starts without ipykernel's debugger and with the grader's matplotlib font list
      (both cost CPU in every kernel, for nothing grading needs).
    """
    if not sandbox_available():
        pytest.skip("bubblewrap is not available here")
    from balancelab.course.gradetable import merge_csv, read_csv

    sub, scratch = tmp_path / "sub", tmp_path / "scratch"
    for d in (sub, sub / "x", sub / "y", scratch):
        d.mkdir()
    notebooks = {"alice_lab1": personal_r_c("S-Alice"), "twin_lab1": personal_r_c("s-alice"),
                 "x/dup_lab1": personal_r_c("s3"), "y/dup_lab1": personal_r_c("s3"),
                 "stray_lab1": personal_r_c("stray"), "hook_lab1": personal_r_c("h1"), "odd_lab1": personal_r_c("o1")}
    for name, code in notebooks.items():
        cells = (code, KERNEL_WORDS) if name == "hook_lab1" else (code, NO_DEBUGGER) if name == "alice_lab1" else (code,)
        nb = submission_notebook("lab1", *cells)
        if name == "odd_lab1":  # item 3: a tag that is no lab name
            nb.metadata["balancelab"]["lab"] = [5]
        nbformat.write(nb, sub / f"{name}.ipynb")
    roster = tmp_path / "roster.csv"
    roster.write_text("file,student_id\nalice_lab1.ipynb,S-Alice\ntwin_lab1.ipynb,s-alice\ndup_lab1.ipynb,s3\n"
                      "gone_lab1.ipynb,s2\nhook_lab1.ipynb,h1\nodd_lab1.ipynb,o1\n", encoding="utf-8")
    out = tmp_path / "grades.csv"
    proc = subprocess.run([sys.executable, "-m", "balancelab.course.grading", str(sub), "--out", str(out),
                           "--roster", str(roster), "--jobs", "2", "--cell-timeout", "30"], capture_output=True,
                          text=True, timeout=900, cwd=ROOT, env={**os.environ, "BALANCELAB_SCRATCH": str(scratch)})
    assert proc.returncode == 0, proc.stderr[-2000:]
    header = out.read_text(encoding="utf-8").splitlines()[0].split(",")
    assert header[:3] == ["student", "student_id", "lab"]
    rows = {r["student"]: r for r in csv.DictReader(out.open(encoding="utf-8"))}
    assert set(rows) == set(notebooks)
    ids = {name: r["student_id"] for name, r in rows.items()}
    assert ids == {"alice_lab1": "s-alice", "twin_lab1": "s-alice", "x/dup_lab1": "s3", "y/dup_lab1": "s3",
                   "stray_lab1": "", "hook_lab1": "h1", "odd_lab1": "o1"}
    for name in ("alice_lab1", "twin_lab1", "x/dup_lab1", "y/dup_lab1", "hook_lab1", "odd_lab1"):
        assert rows[name]["1.1"] == "1", (name, rows[name]["notes"])
    assert "raised" not in rows["alice_lab1"]["notes"], rows["alice_lab1"]["notes"]
    assert rows["stray_lab1"]["status"] == "unidentified" and rows["stray_lab1"]["1.1"] == "0"
    odd = rows["odd_lab1"]
    assert odd["lab"] == "lab1" and odd["mismatch"] == "file name says lab1, metadata says unreadable ([5])"
    assert "the notebook's metadata says unreadable ([5]) but the file name says lab1: graded as lab1" in odd["notes"]
    # the roster's problems, on stderr and in the summary
    for said in ("roster: 'gone_lab1.ipynb' matches no submitted file",
                 "roster: 'dup_lab1.ipynb' matches 2 submitted files (x/dup_lab1.ipynb, y/dup_lab1.ipynb)",
                 "roster: the id 's-alice' is given to 2 files of lab1 (alice_lab1.ipynb, twin_lab1.ipynb)"):
        assert said in proc.stderr and f"WARNING: {said}" in proc.stdout, (said, proc.stderr[-1500:])
    assert "hook_lab1.ipynb" not in proc.stderr
    # the kernel's words are quoted and marked; no note about a cap it did not hit
    hook = rows["hook_lab1"]
    assert hook["status"] == "graded", hook["notes"]
    parts = hook["notes"].split("; ")
    assert not [p for p in parts if p.startswith(_GRADER_CAP_NOTES)], hook["notes"]
    assert 'cell 2 raised an error (reported by the submission: "CapReached: , the memory cap' in hook["notes"]
    assert all(p.count('"') % 2 == 0 for p in parts), parts  # every quote closes inside its own note
    # the column round-trips through read_csv and merge_csv
    assert {r.student: r.student_id for r in read_csv(out)} == ids
    merged = merge_csv([out], tmp_path / "merged.csv")
    assert {r.student: r.student_id for r in read_csv(merged)} == ids
    assert list(scratch.iterdir()) == []
