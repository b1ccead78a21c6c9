"""The course from a wheel: the instructor tools run from an installed wheel, outside any checkout.

A wheel is built from the checkout (``pip wheel --no-deps``), installed without its dependencies
in a fresh virtual environment, and the dependencies come from the test environment's own
site-packages through a ``.pth`` file (no network). From a folder outside the checkout, the
installed ``balancelab-labs`` writes the student versions of a copy of the solution notebooks,
and ``balancelab-grade`` grades a solution in the bubblewrap sandbox, which must find what it
binds (the package sits in site-packages, not in a checkout).
"""
from __future__ import annotations

import csv
import shutil
import subprocess
import sys
import sysconfig
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
LAB = "lab6_scissors_and_peaucellier.ipynb"

pytestmark = pytest.mark.slow


def _run(cmd, cwd, timeout=600, env=None):
    r = subprocess.run([str(c) for c in cmd], cwd=cwd, capture_output=True, text=True, timeout=timeout, env=env)
    assert r.returncode == 0, f"{cmd[0]} failed ({r.returncode}):\n{r.stdout[-2000:]}\n{r.stderr[-3000:]}"
    return r


@pytest.fixture(scope="module")
def fresh(tmp_path_factory):
    """``(bin folder, work folder)`` of a fresh venv holding the wheel built from this checkout."""
    tmp = tmp_path_factory.mktemp("wheel")
    src = tmp / "src"  # build from a copy: pip wheel . would leave build/ and egg-info in the checkout
    shutil.copytree(ROOT / "balancelab", src / "balancelab",
                    ignore=shutil.ignore_patterns("__pycache__", "*.pyc"))
    for name in ("pyproject.toml", "README.md", "LICENSE"):
        shutil.copy2(ROOT / name, src / name)
    _run([sys.executable, "-m", "pip", "wheel", "--no-deps", "-w", tmp / "dist", src], tmp)
    (wheel,) = (tmp / "dist").glob("balancelab-*.whl")
    venv = tmp / "venv"
    _run([sys.executable, "-m", "venv", "--without-pip", venv], tmp)
    python = venv / "bin" / "python"
    _run([sys.executable, "-m", "pip", "--python", python, "install", "--no-deps", "--no-index", wheel], tmp)
    site = Path(_run([python, "-c", "import sysconfig; print(sysconfig.get_paths()['purelib'])"], tmp).stdout.strip())
    (site / "balancelab_test_deps.pth").write_text(sysconfig.get_paths()["purelib"] + "\n", encoding="utf-8")
    work = tmp / "work"
    work.mkdir()
    return venv / "bin", work


def test_the_wheel_is_what_runs(fresh):
    bin_, work = fresh
    where = _run([bin_ / "python", "-c", "import balancelab; print(balancelab.__file__)"], work).stdout.strip()
    assert Path(where).is_relative_to(bin_.parent) and "site-packages" in where
    assert (bin_ / "balancelab-labs").exists() and (bin_ / "balancelab-grade").exists()


def test_labs_generate_from_a_wheel_outside_the_checkout(fresh):
    """``balancelab-labs generate --solutions X --student Y`` writes exactly the checkout's student
    versions (the set-up cell's address comes from the installed distribution when the course
    folder has no ``_config.yml``), and ``check`` then finds them current."""
    bin_, work = fresh
    solutions, student = work / "x" / "solutions", work / "y" / "student"
    shutil.copytree(ROOT / "labs" / "solutions", solutions)
    out = _run([bin_ / "balancelab-labs", "generate", "--solutions", solutions, "--student", student], work).stdout
    names = sorted(p.name for p in (ROOT / "labs" / "solutions").glob("*.ipynb"))
    assert sorted(p.name for p in student.glob("*.ipynb")) == names and out.count("wrote") == len(names)
    for name in names:
        assert (student / name).read_text(encoding="utf-8") == (ROOT / "labs" / "student" / name).read_text(
            encoding="utf-8"), name
    r = _run([bin_ / "balancelab-labs", "check", "--solutions", solutions, "--student", student], work)
    assert "up to date" in r.stdout
    # no labs folder here and none in a checkout: a clear message naming the folder, exit status 2
    r = subprocess.run([bin_ / "balancelab-labs", "generate"], cwd=work, capture_output=True, text=True, timeout=120)
    assert r.returncode == 2 and str(work / "labs" / "solutions") in r.stderr


def test_handout_from_a_wheel_is_installable(fresh):
    """The hand-out built from a wheel carries a package pip can build (its pyproject.toml written from
    the installed metadata) and leaves out the grader's modules."""
    bin_, work = fresh
    course = work / "course"
    shutil.copytree(ROOT / "labs" / "solutions", course / "labs" / "solutions")
    _run([bin_ / "balancelab-labs", "handout", work / "handout"], course)
    package = work / "handout" / "package"
    text = (package / "pyproject.toml").read_text(encoding="utf-8")
    assert 'name = "balancelab"' in text and "labs = [" in text and "numpy" in text
    assert not (package / "balancelab" / "course" / "sandbox.py").exists()
    _run([sys.executable, "-m", "pip", "wheel", "--no-deps", "-w", work / "again", package],
         work)
    assert list((work / "again").glob("balancelab-*.whl"))


@pytest.mark.skipif(shutil.which("bwrap") is None, reason="bubblewrap (the grader's sandbox) is not installed")
def test_grade_from_a_wheel_in_the_sandbox(fresh):
    """``balancelab-grade`` from the wheel gives a solution full marks, its kernel in the sandbox."""
    bin_, work = fresh
    subs = work / "submissions"
    subs.mkdir()
    text = (ROOT / "labs" / "solutions" / LAB).read_text(encoding="utf-8")
    (subs / f"s1_{LAB}").write_text(text.replace('STUDENT_ID = \\"\\"', 'STUDENT_ID = \\"s1\\"'), encoding="utf-8")
    _run([bin_ / "balancelab-grade", subs, "--out", work / "grades.csv", "--cell-timeout", "180"], work, timeout=900)
    with open(work / "grades.csv", newline="", encoding="utf-8") as f:
        (row,) = list(csv.DictReader(f))
    assert row["status"] == "graded", row
    assert float(row["total"]) == float(row["max"]) > 0, row
