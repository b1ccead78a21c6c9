"""What leaves the instructor's hands: the students' hand-out (no solutions) and the autograder."""
from __future__ import annotations

import shutil
from pathlib import Path

from ..launch import GRADER_MODULES, SETUP_TAG, STUDENT_README, setup_source
from .folders import course_repository_for, default_solutions, write_build_files
from .markers import solution_texts
from .students import generate

__all__ = ["handout", "autograder"]


def _copy_package(dst: Path, grader: bool = True) -> None:
    """The imported package (from a checkout or a wheel) and build files that make it installable,
    without tests, labs, book or caches (nor, unless ``grader``,
    :data:`~balancelab.course.launch.GRADER_MODULES`)."""
    caches = shutil.ignore_patterns("__pycache__", "*.pyc", ".ipynb_checkpoints")
    package = Path(__file__).resolve().parents[2]
    course = package / "course"
    ignore = lambda folder, names: set(caches(folder, names)) | (  # noqa: E731
        set() if grader or Path(folder) != course else set(GRADER_MODULES) & set(names))
    shutil.copytree(package, dst / "balancelab", ignore=ignore)
    write_build_files(dst)


def handout(out: str | Path, src: str | Path | None = None) -> Path:
    """Build the student hand-out in ``out``: student notebooks and the package, no solutions.

    ``out/labs`` holds the student versions (generated now from ``src``), ``out/package`` the
    library to install, ``out/README.md`` what to do. The hand-out is scanned afterwards:
    no solution notebook, no solution region and no ``BEGIN SOLUTION`` marker may be in it, and
    no number in a docstring of the package may pass a numeric task
    (:func:`~balancelab.course.leaks.answer_leaks`).

    Parameters
    ----------
    out : str or Path
        A folder that does not exist yet (or is empty).
    src : str or Path, optional
        The solution notebooks (default ``solutions/`` of
        :func:`~balancelab.course.labtools.folders.default_labs`).

    Returns
    -------
    Path

    Raises
    ------
    FileExistsError
        If ``out`` exists and is not empty.
    RuntimeError
        If solution text is found in the hand-out.

    Examples
    --------
    >>> import pathlib, tempfile
    >>> out = handout(pathlib.Path(tempfile.mkdtemp()) / "handout")
    >>> sorted(p.name for p in out.iterdir())
    ['README.md', 'labs', 'package']
    """
    out, src = Path(out), Path(src) if src is not None else default_solutions()
    if out.exists() and any(out.iterdir()):
        raise FileExistsError(f"{out} exists and is not empty")
    generate(src, out / "labs")
    _handout_setup_cells(out / "labs", course_repository_for(src))
    _copy_package(out / "package", grader=False)
    (out / "README.md").write_text(STUDENT_README, encoding="utf-8")
    _scan_handout(out, src)
    return out


def _handout_setup_cells(labs: Path, repository: tuple[str, str]) -> None:
    """The hand-out's set-up cells advise its own install line (``./package[labs]``, its README.md)."""
    import nbformat

    for path in sorted(labs.glob("*.ipynb")):
        nb = nbformat.read(path, as_version=4)
        for cell in nb.cells:
            if SETUP_TAG in cell.metadata.get("tags", []):
                cell.source = setup_source(*repository, handout=True)
        path.write_text(nbformat.writes(nb) + "\n", encoding="utf-8")


def _scan_handout(out: Path, src) -> None:
    import nbformat

    from ..leaks import answer_leaks

    leaks = answer_leaks(out / "package" / "balancelab")
    if leaks:
        raise RuntimeError(f"an answer is in a docstring of the hand-out's package: {leaks[0]}")

    regions = [line.strip() for s in sorted(Path(src).glob("*.ipynb"))
               for text in solution_texts(nbformat.read(s, as_version=4), s.name) for line in text.splitlines()
               if len(line.strip()) >= 12]
    for f in out.rglob("*"):
        if f.suffix not in (".ipynb", ".py", ".md"):
            continue
        text = f.read_text(encoding="utf-8", errors="replace")
        if f.suffix == ".ipynb" and ("BEGIN SOLUTION" in text or '"solution"' in text):
            raise RuntimeError(f"solution marker left in {f}")
        leaked = [r for r in regions if r in text] if f.suffix == ".ipynb" else []
        if leaked:
            raise RuntimeError(f"solution text in {f}: {leaked[0]!r}")


def autograder(out: str | Path, src: str | Path | None = None) -> Path:
    """Build the instructor's autograder in ``out``: solutions, the package and how to grade.

    Parameters
    ----------
    out : str or Path
        A folder that does not exist yet (or is empty).
    src : str or Path, optional
        The solution notebooks (default ``solutions/`` of
        :func:`~balancelab.course.labtools.folders.default_labs`).

    Returns
    -------
    Path

    Raises
    ------
    FileExistsError
        If ``out`` exists and is not empty.

    Examples
    --------
    >>> import pathlib, tempfile
    >>> out = autograder(pathlib.Path(tempfile.mkdtemp()) / "autograder")
    >>> sorted(p.name for p in out.iterdir())
    ['README.md', 'package', 'solutions']
    """
    out, src = Path(out), Path(src) if src is not None else default_solutions()
    if out.exists() and any(out.iterdir()):
        raise FileExistsError(f"{out} exists and is not empty")
    if not sorted(src.glob("*.ipynb")):
        raise FileNotFoundError(f"no solution notebooks (*.ipynb) in {src}")
    (out / "solutions").mkdir(parents=True)
    for f in sorted(src.glob("*.ipynb")):
        shutil.copy2(f, out / "solutions" / f.name)
    _copy_package(out / "package")
    (out / "README.md").write_text(
        "# balancelab autograder (instructors only: contains the solutions)\n\n"
        "1. `pip install \"./package[instructor]\"` and, on Debian, `apt-get install bubblewrap` (the sandbox).\n"
        "2. Collect the submitted `.ipynb` files in `submissions/`.\n"
        "3. `python -m balancelab.course.grading submissions/ --out grades.csv --jobs 2`\n"
        "   (on several machines: `--shard i/n`, then `python -m balancelab.course.grading merge "
        "part*.csv --out grades.csv`).\n", encoding="utf-8")
    return out
