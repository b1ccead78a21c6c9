"""Student versions written to disk: one file per solution notebook, and the check that they are current.

Where the labs are is always an argument (a folder of solution notebooks, a folder for the
student versions); :func:`~balancelab.course.labtools.folders.default_labs` gives the defaults.
"""
from __future__ import annotations

from pathlib import Path

from ..launch import add_setup_cell
from .folders import course_repository_for, default_solutions, default_student
from .markers import student_version

__all__ = ["student_text", "generate", "stale"]


def student_text(path: str | Path, repository: tuple[str, str] | None = None) -> str:
    """The exact file content of the student version of the solution notebook at ``path``.

    The student version starts with the set-up cell (:func:`~balancelab.course.launch.add_setup_cell`).

    Parameters
    ----------
    path : str or Path
        A solution notebook.
    repository : (str, str), optional
        Address and branch the set-up cell installs the package from on Colab (default:
        :func:`~balancelab.course.labtools.folders.course_repository_for` the notebook's folder:
        ``repository.url`` and ``repository.branch`` of the course's ``_config.yml``).

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
    add_setup_cell(nb, *(repository or course_repository_for(path.parent)))
    return nbformat.writes(nb) + "\n"


def _pairs(src: str | Path | None, dst: str | Path | None):
    src = Path(src) if src is not None else default_solutions()
    dst = Path(dst) if dst is not None else default_student()
    files = sorted(src.glob("*.ipynb"))
    if not files:
        raise FileNotFoundError(f"no solution notebooks (*.ipynb) in {src}")
    return [(f, dst / f.name) for f in files]


def generate(src: str | Path | None = None, dst: str | Path | None = None) -> list[Path]:
    """Write the student version of every solution notebook in ``src`` to ``dst``.

    Parameters
    ----------
    src : str or Path, optional
        Folder of solution notebooks (default ``solutions/`` of
        :func:`~balancelab.course.labtools.folders.default_labs`).
    dst : str or Path, optional
        Folder for the student versions (created if needed; same file names; default ``student/``).

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
    for s, d in _pairs(src, dst):
        d.parent.mkdir(parents=True, exist_ok=True)
        d.write_text(student_text(s), encoding="utf-8")
        written.append(d)
    return written


def stale(src: str | Path | None = None, dst: str | Path | None = None) -> list[Path]:
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
    return [d for s, d in _pairs(src, dst)
            if not d.exists() or d.read_text(encoding="utf-8") != student_text(s)]
