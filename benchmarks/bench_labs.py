"""Speed of the labs: nbval of every solution notebook, one answer check of each kind, and the
grader on a class: 100 lab-1 submissions graded with ``--jobs 2`` (sandboxed, 2 cores).

``python benchmarks/bench_labs.py`` prints the table; ``python benchmarks/bench_labs.py grade``
only the class-grading row.
"""
from __future__ import annotations

import shutil
import subprocess
import sys
import tempfile
import time
from pathlib import Path

from timing import best_time

ROOT = Path(__file__).resolve().parent.parent


def run() -> list[tuple[str, float, str, str]]:
    """Rows ``(name, measured, unit, target)``."""
    from balancelab.course.check import check

    rows = [
        ("check: numeric answer (2.1)", 1e3 * best_time(lambda: check("2.1", "196.2 N/m")), "ms", "< 5 ms"),
        ("check: symbolic answer (2.2)", 1e3 * best_time(lambda: check("2.2", ("-a_x*b_x/b_y",
                                                                         "W*l*b_y/(a_x*(b_x**2+b_y**2))"))),
         "ms", "< 2000 ms"),
        ("check: open design (1.4, four-bar)", 1e3 * best_time(lambda: check("1.4", {
            "crank": (2.0, (-0.112, 0.0)), "rocker": (2.0, (-0.196, 0.0))})), "ms", "< 500 ms"),
    ]
    files = sorted(str(p) for p in (ROOT / "labs" / "solutions").glob("*.ipynb"))
    t = time.perf_counter()
    proc = subprocess.run([sys.executable, "-m", "pytest", "--nbval", "--nbval-current-env",
                           "--nbval-sanitize-with", str(ROOT / "labs" / "nbval_sanitize.cfg"),
                           "-p", "no:cacheprovider", "-q", "-o", "addopts=", *files],
                          capture_output=True, text=True, cwd=ROOT)
    elapsed = time.perf_counter() - t
    name = f"nbval of {len(files)} solution notebooks" + ("" if proc.returncode == 0 else " (FAILED)")
    rows.append((name, elapsed, "s", "< 120 s on 2 cores"))
    rows.append(grade_class())
    return rows


def grade_class(n: int = 100, jobs: int = 2) -> tuple[str, float, str, str]:
    """Grade ``n`` copies of lab 1 (half solutions, half untouched student versions); the row."""
    lab1 = sorted((ROOT / "labs" / "solutions").glob("lab1*.ipynb"))[0]
    with tempfile.TemporaryDirectory(prefix="bench-grade-") as tmp:
        sub = Path(tmp) / "submissions"
        sub.mkdir()
        for i in range(n):
            src = lab1 if i % 2 == 0 else ROOT / "labs" / "student" / lab1.name
            shutil.copy(src, sub / f"student{i:03d}_lab1.ipynb")
        t = time.perf_counter()
        proc = subprocess.run([sys.executable, "-m", "balancelab.course.grading", str(sub), "--out",
                               str(Path(tmp) / "grades.csv"), "--jobs", str(jobs)],
                              capture_output=True, text=True, cwd=ROOT)
        elapsed = time.perf_counter() - t
    name = f"grade {n} lab-1 submissions, --jobs {jobs}" + ("" if proc.returncode == 0 else " (FAILED)")
    return (name, elapsed, "s", "for information (2 cores)")


if __name__ == "__main__":
    rows = [grade_class()] if sys.argv[1:] == ["grade"] else run()
    for row in rows:
        print(f"{row[0]:45s} {row[1]:10.3g} {row[2]:3s} {row[3]}")
