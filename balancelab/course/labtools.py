"""Student versions of the labs, generated from the solution notebooks (the single source).

A solution notebook marks what students must not see:

* in a code cell, the lines between ``# BEGIN SOLUTION`` and ``# END SOLUTION`` (each
  on a line of its own, any indentation) are replaced by one line: ``variable = ...`` when
  the region is at the top level of a cell that checks one task (``check("n.m", variable)``),
  so that Run All goes on past an unanswered task and its check says "No answer yet";
  otherwise ``raise NotImplementedError("...")`` at the indentation of the ``BEGIN`` marker;
* in a markdown cell, everything between ``<!-- BEGIN SOLUTION -->`` and
  ``<!-- END SOLUTION -->`` is removed (a cell left empty is dropped);
* a cell tagged ``solution`` is dropped entirely.

The student version has no outputs and no execution counts. One command regenerates
every student version::

    python -m balancelab.course.labtools generate            # labs/solutions -> labs/student
    python -m balancelab.course.labtools check               # exit 1 if a student version is stale
    python -m balancelab.course.labtools execute             # re-run the solutions, store outputs
    python -m balancelab.course.labtools handout OUT         # what students get (no solutions)
    python -m balancelab.course.labtools autograder OUT      # what the instructor grades with
"""
from __future__ import annotations

import argparse
import copy
import hashlib
import re
import shutil
import sys
from pathlib import Path

from ..core.errors import MarkerError
from .launch import (GRADER_MODULES, SETUP_TAG, STUDENT_README, add_setup_cell, course_repository,
                     setup_source)

__all__ = ["PLACEHOLDER", "ANSWER_PLACEHOLDER", "student_version", "student_text", "solution_texts", "generate",
           "stale", "execute_notebook", "stable_widget_id", "handout", "autograder", "main"]

CODE_BEGIN = re.compile(r"^(\s*)# BEGIN SOLUTION\s*$")
CODE_END = re.compile(r"^\s*# END SOLUTION\s*$")
MD_BEGIN = "<!-- BEGIN SOLUTION -->"
MD_END = "<!-- END SOLUTION -->"
SOLUTION_TAG = "solution"
#: The line that replaces a solution region in a code cell.
PLACEHOLDER = 'raise NotImplementedError("your answer here: replace this line")'
#: The line that replaces a top-level solution region in a cell that checks one task.
ANSWER_PLACEHOLDER = "{variable} = ...  # your answer here: replace the ..."
CHECK_CALL = re.compile(r"""^check\(["'][\d.]+["'],\s*(\w+)\)""", re.M)

WIDGET_MIME = "application/vnd.jupyter.widget-view+json"
#: What a stored widget output says where no widget manager can show it.
WIDGET_TEXT = "Live explorer: run the notebook to use its sliders."

_ROOT = Path(__file__).resolve().parents[2]  # the repository: balancelab/course/labtools.py
DEFAULT_SOLUTIONS = _ROOT / "labs" / "solutions"
DEFAULT_STUDENT = _ROOT / "labs" / "student"


def _strip_code(src: str, where: str) -> tuple[str, list[str]]:
    checked = CHECK_CALL.findall(src)
    out, removed, inside, indent = [], [], False, ""
    for n, line in enumerate(src.split("\n"), 1):
        m = CODE_BEGIN.match(line)
        if m:
            if inside:
                raise MarkerError(f"{where}, line {n}: '# BEGIN SOLUTION' inside another solution region")
            inside, indent = True, m.group(1)
            removed.append("")
            continue
        if CODE_END.match(line):
            if not inside:
                raise MarkerError(f"{where}, line {n}: '# END SOLUTION' without a BEGIN")
            inside = False
            one = len(checked) == 1 and indent == ""
            out.append(ANSWER_PLACEHOLDER.format(variable=checked[0]) if one else indent + PLACEHOLDER)
            continue
        if inside:
            removed[-1] += line + "\n"
        else:
            out.append(line)
    if inside:
        raise MarkerError(f"{where}: '# BEGIN SOLUTION' is never closed by '# END SOLUTION'")
    return "\n".join(out), removed


def _strip_markdown(src: str, where: str) -> tuple[str, list[str]]:
    out, removed, pos = [], [], 0
    while True:
        b = src.find(MD_BEGIN, pos)
        e = src.find(MD_END, pos)
        if b < 0:
            if e >= 0:
                raise MarkerError(f"{where}: '{MD_END}' without a BEGIN")
            out.append(src[pos:])
            break
        if e < b:
            raise MarkerError(f"{where}: '{MD_END}' without a BEGIN")
        nb = src.find(MD_BEGIN, b + len(MD_BEGIN))
        if nb >= 0 and nb < e:
            raise MarkerError(f"{where}: nested '{MD_BEGIN}'")
        out.append(src[pos:b])
        removed.append(src[b + len(MD_BEGIN):e])
        pos = e + len(MD_END)
    text = "".join(out)
    text = re.sub(r"\n{3,}", "\n\n", text).strip("\n")
    return text, removed


def _cell_where(name: str, i: int) -> str:
    return f"{name}: cell {i}"


def _split(nb, name: str = "notebook"):
    """(student cells, removed texts) of a notebook."""
    cells, removed = [], []
    for i, cell in enumerate(nb.cells):
        src = cell.source if isinstance(cell.source, str) else "".join(cell.source)
        if SOLUTION_TAG in cell.get("metadata", {}).get("tags", []):
            removed.append(src)
            continue
        where = _cell_where(name, i)
        new = copy.deepcopy(cell)
        if cell.cell_type == "code":
            text, gone = _strip_code(src, where)
            new.outputs = []
            new.execution_count = None
        elif cell.cell_type == "markdown":
            text, gone = _strip_markdown(src, where)
            if gone and not text.strip():
                removed.extend(gone)
                continue
        else:
            text, gone = src, []
        new.source = text
        md = dict(new.get("metadata", {}))
        md.pop("execution", None)
        new.metadata = md
        cells.append(new)
        removed.extend(gone)
    return cells, removed


def student_version(nb, name: str = "notebook"):
    """The student version of a solution notebook (a new notebook; the input is untouched).

    Parameters
    ----------
    nb : nbformat.NotebookNode
        The solution notebook.
    name : str
        Name used in error messages.

    Returns
    -------
    nbformat.NotebookNode

    Raises
    ------
    MarkerError
        If a solution marker is unbalanced or nested.

    Examples
    --------
    >>> import nbformat
    >>> nb = nbformat.v4.new_notebook(cells=[nbformat.v4.new_code_cell(
    ...     "x = 1\\n# BEGIN SOLUTION\\nk = 2\\n# END SOLUTION")])
    >>> print(student_version(nb).cells[0].source)
    x = 1
    raise NotImplementedError("your answer here: replace this line")
    """
    import nbformat

    cells, _ = _split(nb, name)
    out = nbformat.v4.new_notebook()
    out.nbformat, out.nbformat_minor = nb.nbformat, nb.nbformat_minor
    md = copy.deepcopy(dict(nb.metadata))
    md.pop("widgets", None)
    bl = dict(md.get("balancelab", {}))
    bl["version"] = "student"
    md["balancelab"] = bl
    out.metadata = md
    out.cells = cells
    return out


def solution_texts(nb, name: str = "notebook") -> list[str]:
    """The text of every solution region (code, prose and tagged cells) of a notebook.

    Parameters
    ----------
    nb : nbformat.NotebookNode
        The solution notebook.
    name : str
        Name used in error messages.

    Returns
    -------
    list of str

    Examples
    --------
    >>> import nbformat
    >>> nb = nbformat.v4.new_notebook(cells=[nbformat.v4.new_code_cell(
    ...     "x = 1\\n# BEGIN SOLUTION\\nk = 2\\n# END SOLUTION")])
    >>> solution_texts(nb)
    ['k = 2\\n']
    """
    return [t for t in _split(nb, name)[1] if t.strip()]


def student_text(path: str | Path, repository: tuple[str, str] | None = None) -> str:
    """The exact file content of the student version of the solution notebook at ``path``.

    The student version starts with the set-up cell (:func:`~balancelab.course.launch.add_setup_cell`).

    Parameters
    ----------
    path : str or Path
        A solution notebook.
    repository : (str, str), optional
        Address and branch the set-up cell installs the package from on Colab (default:
        ``repository.url`` and ``repository.branch`` of ``_config.yml``).

    Returns
    -------
    str
        JSON text, as :func:`generate` writes it.

    Examples
    --------
    >>> import nbformat, pathlib, tempfile
    >>> path = pathlib.Path(tempfile.mkdtemp()) / "lab9.ipynb"
    >>> nbformat.write(nbformat.v4.new_notebook(cells=[nbformat.v4.new_code_cell(
    ...     "# BEGIN SOLUTION\\nk = 2\\n# END SOLUTION")]), path)
    >>> text = student_text(path)
    >>> "NotImplementedError" in text, "k = 2" in text
    (True, False)
    """
    import nbformat

    path = Path(path)
    nb = student_version(nbformat.read(path, as_version=4), path.name)
    add_setup_cell(nb, *(repository or course_repository()))
    return nbformat.writes(nb) + "\n"


def _pairs(src: Path, dst: Path):
    src, dst = Path(src), Path(dst)
    files = sorted(src.glob("*.ipynb"))
    if not files:
        raise FileNotFoundError(f"no solution notebooks (*.ipynb) in {src}")
    return [(f, dst / f.name) for f in files]


def generate(src: str | Path = DEFAULT_SOLUTIONS, dst: str | Path = DEFAULT_STUDENT) -> list[Path]:
    """Write the student version of every solution notebook in ``src`` to ``dst``.

    Parameters
    ----------
    src : str or Path
        Folder of solution notebooks.
    dst : str or Path
        Folder for the student versions (created if needed; same file names).

    Returns
    -------
    list of Path
        The files written.

    Examples
    --------
    >>> import nbformat, pathlib, tempfile
    >>> root = pathlib.Path(tempfile.mkdtemp())
    >>> (root / "solutions").mkdir()
    >>> nbformat.write(nbformat.v4.new_notebook(), root / "solutions" / "lab9.ipynb")
    >>> [p.name for p in generate(root / "solutions", root / "student")]
    ['lab9.ipynb']
    """
    written = []
    Path(dst).mkdir(parents=True, exist_ok=True)
    for s, d in _pairs(Path(src), Path(dst)):
        d.write_text(student_text(s), encoding="utf-8")
        written.append(d)
    return written


def stale(src: str | Path = DEFAULT_SOLUTIONS, dst: str | Path = DEFAULT_STUDENT) -> list[Path]:
    """Student versions that differ from what :func:`generate` would write (or are missing).

    Parameters
    ----------
    src, dst : str or Path
        As in :func:`generate`.

    Returns
    -------
    list of Path

    Examples
    --------
    >>> import nbformat, pathlib, tempfile
    >>> root = pathlib.Path(tempfile.mkdtemp())
    >>> (root / "solutions").mkdir()
    >>> nbformat.write(nbformat.v4.new_notebook(), root / "solutions" / "lab9.ipynb")
    >>> [p.name for p in stale(root / "solutions", root / "student")]
    ['lab9.ipynb']
    >>> _ = generate(root / "solutions", root / "student")
    >>> stale(root / "solutions", root / "student")
    []
    """
    return [d for s, d in _pairs(Path(src), Path(dst))
            if not d.exists() or d.read_text(encoding="utf-8") != student_text(s)]


def execute_notebook(path: str | Path, timeout: int = 120, kernel_name: str = "python3",
                     allow_errors: bool = False, write: bool = True):
    """Run a notebook top to bottom in a fresh kernel (in its own folder) and store the outputs.

    Parameters
    ----------
    path : str or Path
        The notebook.
    timeout : int
        Per-cell time limit (s).
    kernel_name : str
        Jupyter kernel to use.
    allow_errors : bool
        Keep going after a failing cell.
    write : bool
        Write the executed notebook back to ``path``.

    Returns
    -------
    nbformat.NotebookNode
        The executed notebook.

    Examples
    --------
    >>> import nbformat, pathlib, tempfile
    >>> path = pathlib.Path(tempfile.mkdtemp()) / "lab9.ipynb"
    >>> nbformat.write(nbformat.v4.new_notebook(cells=[nbformat.v4.new_code_cell("print(6 * 7)")]), path)
    >>> execute_notebook(path, write=False).cells[0].outputs[0].text
    '42\\n'
    """
    import nbformat
    from nbclient import NotebookClient

    path = Path(path)
    nb = nbformat.read(path, as_version=4)
    NotebookClient(nb, timeout=timeout, kernel_name=kernel_name, allow_errors=allow_errors,
                   resources={"metadata": {"path": str(path.parent)}},
                   store_widget_state=False).execute()
    for i, cell in enumerate(nb.cells):
        cell.get("metadata", {}).pop("execution", None)
        for j, out in enumerate(cell.get("outputs", [])):
            data = out.get("data", {})
            if WIDGET_MIME in data and "text/plain" in data:
                # the widget's repr holds the rendered picture's bytes: keep the file small
                data["text/plain"] = WIDGET_TEXT
            if WIDGET_MIME in data and isinstance(data[WIDGET_MIME], dict):
                # no widget state is stored, so the id names nothing: make it stable (no git diff per run)
                data[WIDGET_MIME]["model_id"] = stable_widget_id(path.name, i, j)
    if write:
        nbformat.write(nb, path)
    return nb


def stable_widget_id(name: str, cell: int, output: int) -> str:
    """A widget model id that depends only on where the widget is shown (32 hex digits).

    Parameters
    ----------
    name : str
        The notebook's file name.
    cell, output : int
        Cell index and output index.

    Returns
    -------
    str

    Examples
    --------
    >>> stable_widget_id("lab1.ipynb", 3, 0) == stable_widget_id("lab1.ipynb", 3, 0)
    True
    >>> len(stable_widget_id("lab1.ipynb", 3, 0))
    32
    """
    return hashlib.sha256(f"{name}:{cell}:{output}".encode()).hexdigest()[:32]


def _copy_package(dst: Path, grader: bool = True) -> None:
    """The library and its build files, without tests, labs, book or caches (nor, unless
    ``grader``, :data:`~balancelab.course.launch.GRADER_MODULES`)."""
    caches = shutil.ignore_patterns("__pycache__", "*.pyc", ".ipynb_checkpoints")
    course = _ROOT / "balancelab" / "course"
    ignore = lambda folder, names: set(caches(folder, names)) | (  # noqa: E731
        set() if grader or Path(folder) != course else set(GRADER_MODULES) & set(names))
    shutil.copytree(_ROOT / "balancelab", dst / "balancelab", ignore=ignore)
    for name in ("pyproject.toml", "LICENSE", "README.md", "constraints.txt"):
        if (_ROOT / name).exists():
            shutil.copy2(_ROOT / name, dst / name)


def handout(out: str | Path, src: str | Path = DEFAULT_SOLUTIONS) -> Path:
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
    src : str or Path
        The solution notebooks.

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
    out = Path(out)
    if out.exists() and any(out.iterdir()):
        raise FileExistsError(f"{out} exists and is not empty")
    generate(src, out / "labs")
    _handout_setup_cells(out / "labs")
    _copy_package(out / "package", grader=False)
    (out / "README.md").write_text(STUDENT_README, encoding="utf-8")
    _scan_handout(out, src)
    return out


def _handout_setup_cells(labs: Path) -> None:
    """The hand-out's set-up cells advise its own install line (``./package[labs]``, its README.md)."""
    import nbformat

    repository = course_repository()
    for path in sorted(labs.glob("*.ipynb")):
        nb = nbformat.read(path, as_version=4)
        for cell in nb.cells:
            if SETUP_TAG in cell.metadata.get("tags", []):
                cell.source = setup_source(*repository, handout=True)
        path.write_text(nbformat.writes(nb) + "\n", encoding="utf-8")


def _scan_handout(out: Path, src) -> None:
    import nbformat

    from .leaks import answer_leaks

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


def autograder(out: str | Path, src: str | Path = DEFAULT_SOLUTIONS) -> Path:
    """Build the instructor's autograder in ``out``: solutions, the package and how to grade.

    Parameters
    ----------
    out : str or Path
        A folder that does not exist yet (or is empty).
    src : str or Path
        The solution notebooks.

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
    out = Path(out)
    if out.exists() and any(out.iterdir()):
        raise FileExistsError(f"{out} exists and is not empty")
    (out / "solutions").mkdir(parents=True)
    for f in sorted(Path(src).glob("*.ipynb")):
        shutil.copy2(f, out / "solutions" / f.name)
    _copy_package(out / "package")
    (out / "README.md").write_text(
        "# balancelab autograder (instructors only: contains the solutions)\n\n"
        "1. `pip install \"./package[labs]\"` and, on Debian, `apt-get install bubblewrap` (the sandbox).\n"
        "2. Collect the submitted `.ipynb` files in `submissions/`.\n"
        "3. `python -m balancelab.course.grading submissions/ --out grades.csv --jobs 2`\n"
        "   (on several machines: `--shard i/n`, then `python -m balancelab.course.grading merge "
        "part*.csv --out grades.csv`).\n", encoding="utf-8")
    return out


def main(argv: list[str] | None = None) -> int:
    """Command line: ``generate``, ``check`` or ``execute`` (see the module docstring).

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
    ap = argparse.ArgumentParser(prog="python -m balancelab.course.labtools",
                                 description="Generate student versions of the lab notebooks.")
    ap.add_argument("command", choices=("generate", "check", "execute", "handout", "autograder"))
    ap.add_argument("--solutions", default=str(DEFAULT_SOLUTIONS), help="solution notebooks folder")
    ap.add_argument("--student", default=str(DEFAULT_STUDENT), help="student versions folder")
    ap.add_argument("notebooks", nargs="*", help="for execute: the notebooks (default: all solutions); "
                    "for handout and autograder: the output folder")
    args = ap.parse_args(argv)
    try:
        if args.command == "generate":
            for p in generate(args.solutions, args.student):
                print(f"wrote {p}")
        elif args.command == "check":
            bad = stale(args.solutions, args.student)
            for p in bad:
                print(f"stale: {p} (run: python -m balancelab.course.labtools generate)")
            if bad:
                return 1
            print("every student version is up to date")
        elif args.command in ("handout", "autograder"):
            if len(args.notebooks) != 1:
                ap.error(f"{args.command} needs one output folder")
            made = (handout if args.command == "handout" else autograder)(args.notebooks[0], args.solutions)
            print(f"wrote {made}")
        else:
            paths = args.notebooks or sorted(str(p) for p in Path(args.solutions).glob("*.ipynb"))
            for p in paths:
                execute_notebook(p)
                print(f"executed {p}")
    except (MarkerError, FileNotFoundError, FileExistsError, RuntimeError) as e:
        print(f"error: {e}", file=sys.stderr)
        return 2
    return 0


if __name__ == "__main__":
    sys.exit(main())
