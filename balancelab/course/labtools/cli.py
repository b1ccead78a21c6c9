"""The command line ``balancelab-labs`` (``python -m balancelab.course.labtools``)."""
from __future__ import annotations

import argparse
import sys
from pathlib import Path

from .execute import execute_notebook
from .folders import default_labs
from .handout import autograder, handout
from .markers import MarkerError
from .students import generate, stale

__all__ = ["main"]


def main(argv: list[str] | None = None) -> int:
    """Command line: ``generate``, ``check``, ``execute``, ``handout`` or ``autograder`` (see the package docstring).

    Parameters
    ----------
    argv : list of str, optional
        The arguments (``sys.argv[1:]`` by default).

    Returns
    -------
    int
        The exit status: 0 on success, 1 when ``check`` finds a stale student version, 2
        on a marker error or a missing folder.

    Examples
    --------
    >>> import pathlib, tempfile
    >>> empty = pathlib.Path(tempfile.mkdtemp())
    >>> main(["check", "--solutions", str(empty)])  # prints "error: no solution notebooks ..." on stderr
    2
    """
    ap = argparse.ArgumentParser(prog="balancelab-labs", description=(
        "Student versions, hand-out and autograder of the lab notebooks. The labs folder is an argument "
        "(default: ./labs of the current folder, or the checkout's labs/); run from anywhere."))
    ap.add_argument("command", choices=("generate", "check", "execute", "handout", "autograder"))
    ap.add_argument("--labs", help="the labs folder holding solutions/ and student/ (default: ./labs)")
    ap.add_argument("--solutions", help="solution notebooks folder (default: LABS/solutions)")
    ap.add_argument("--student", help="student versions folder (default: LABS/student)")
    ap.add_argument("notebooks", nargs="*", help="for execute: the notebooks (default: all solutions); "
                    "for handout and autograder: the output folder")
    args = ap.parse_args(argv)
    labs = Path(args.labs) if args.labs else default_labs()
    solutions = Path(args.solutions) if args.solutions else labs / "solutions"
    student = Path(args.student) if args.student else labs / "student"
    try:
        return _run(ap, args.command, solutions, student, args.notebooks)
    except (MarkerError, FileNotFoundError, FileExistsError, RuntimeError, ValueError) as e:
        print(f"error: {e}", file=sys.stderr)
        return 2


def _run(ap: argparse.ArgumentParser, command: str, solutions: Path, student: Path, rest: list[str]) -> int:
    if command == "generate":
        for p in generate(solutions, student):
            print(f"wrote {p}")
    elif command == "check":
        bad = stale(solutions, student)
        for p in bad:
            print(f"stale: {p} (run: balancelab-labs generate)")
        if bad:
            return 1
        print("every student version is up to date")
    elif command in ("handout", "autograder"):
        if len(rest) != 1:
            ap.error(f"{command} needs one output folder")
        made = (handout if command == "handout" else autograder)(rest[0], solutions)
        print(f"wrote {made}")
    else:
        paths = rest or sorted(str(p) for p in solutions.glob("*.ipynb"))
        if not paths:
            raise FileNotFoundError(f"no solution notebooks (*.ipynb) in {solutions}")
        for path in paths:
            execute_notebook(path)
            print(f"executed {path}")
    return 0
