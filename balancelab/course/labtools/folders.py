"""Where the course is: the labs folder, the course's ``_config.yml`` and the package to hand out.

The instructor tools work from a checkout and from an installed wheel alike. Nothing is looked up
next to the installed package: the labs folder is an argument, by default ``./labs`` of the
current folder (its ``solutions/`` and ``student/``); inside a checkout whose current folder has
no ``labs/``, the checkout's own ``labs/``. The repository address the set-up cell installs from
comes from the ``_config.yml`` of the course folder (the folder holding ``labs/``), else from the
current folder's, else from the installed distribution's ``Source`` address (branch ``main``).
"""
from __future__ import annotations

import re
import shutil
from importlib import metadata
from pathlib import Path

from ..launch import course_repository

__all__ = ["checkout", "default_labs", "default_solutions", "default_student", "course_config",
           "course_repository_for", "write_build_files"]

#: The files besides the package that make a folder pip-installable (copied from a checkout).
BUILD_FILES = ("pyproject.toml", "LICENSE", "README.md", "constraints.txt")


def checkout() -> Path | None:
    """The repository around the imported package, or ``None`` for an installed wheel.

    Returns
    -------
    Path or None

    Examples
    --------
    >>> where = checkout()
    >>> where is None or (where / "pyproject.toml").is_file()
    True
    """
    root = Path(__file__).resolve().parents[3]
    return root if (root / "pyproject.toml").is_file() and (root / "balancelab").is_dir() else None


def default_labs() -> Path:
    """The labs folder used when none is given: ``./labs``, else the checkout's ``labs``.

    Returns
    -------
    Path

    Examples
    --------
    >>> default_labs().name
    'labs'
    """
    here = Path.cwd() / "labs"
    root = checkout()
    if not (here / "solutions").is_dir() and root is not None and (root / "labs" / "solutions").is_dir():
        return root / "labs"
    return here


def default_solutions() -> Path:
    """``solutions/`` of :func:`default_labs`.

    Returns
    -------
    Path

    Examples
    --------
    >>> default_solutions().parts[-2:]
    ('labs', 'solutions')
    """
    return default_labs() / "solutions"


def default_student() -> Path:
    """``student/`` of :func:`default_labs`.

    Returns
    -------
    Path

    Examples
    --------
    >>> default_student().parts[-2:]
    ('labs', 'student')
    """
    return default_labs() / "student"


def course_config(solutions: str | Path | None = None) -> Path | None:
    """The course's ``_config.yml``: beside the labs folder of ``solutions``, else in the current folder.

    Parameters
    ----------
    solutions : str or Path, optional
        A folder of solution notebooks (``COURSE/labs/solutions``); default :func:`default_solutions`.

    Returns
    -------
    Path or None
        ``None`` when neither folder has one.

    Examples
    --------
    >>> import pathlib, tempfile
    >>> course = pathlib.Path(tempfile.mkdtemp())
    >>> (course / "labs" / "solutions").mkdir(parents=True)
    >>> _ = (course / "_config.yml").write_text("repository:\\n  url: https://example.org/me/course\\n")
    >>> course_config(course / "labs" / "solutions") == (course / "_config.yml").resolve()
    True
    """
    folder = Path(solutions if solutions is not None else default_solutions()).resolve()
    for candidate in (folder.parent.parent / "_config.yml", Path.cwd() / "_config.yml"):
        if candidate.is_file():
            return candidate.resolve()
    return None


def course_repository_for(solutions: str | Path | None = None) -> tuple[str, str]:
    """Address and branch the set-up cells install from, for the labs of ``solutions``.

    From :func:`course_config` when there is one, else the installed distribution's ``Source``
    address and the branch ``main``.

    Parameters
    ----------
    solutions : str or Path, optional
        A folder of solution notebooks.

    Returns
    -------
    (str, str)

    Raises
    ------
    ValueError
        If the address found is not a repository's ``https://host/owner/repo``, or no address is
        found at all.

    Examples
    --------
    >>> url, branch = course_repository_for()
    >>> url.startswith("https://"), bool(branch)
    (True, True)
    """
    config = course_config(solutions)
    if config is not None:
        return course_repository(config)
    try:
        urls = metadata.metadata("balancelab").get_all("Project-URL") or []
    except metadata.PackageNotFoundError:
        urls = []
    source = [u.split(",", 1)[1].strip() for u in urls if u.lower().startswith("source,")]
    if not source:
        raise ValueError("no _config.yml beside the labs folder or in the current folder, and the installed "
                         "balancelab names no Source address: run from the course folder")
    return source[0].rstrip("/"), "main"


def write_build_files(dst: str | Path) -> None:
    """Make ``dst`` (holding a copy of the package in ``dst/balancelab``) installable with pip.

    In a checkout the repository's build files are copied; from an installed wheel a
    ``pyproject.toml`` is written from the installed distribution's metadata (name, version,
    Python, dependencies and extras).

    Parameters
    ----------
    dst : str or Path
        The folder.

    Examples
    --------
    >>> import pathlib, tempfile
    >>> dst = pathlib.Path(tempfile.mkdtemp())
    >>> write_build_files(dst)
    >>> 'name = "balancelab"' in (dst / "pyproject.toml").read_text()
    True
    """
    dst = Path(dst)
    root = checkout()
    if root is not None:
        for name in BUILD_FILES:
            if (root / name).exists():
                shutil.copy2(root / name, dst / name)
        return
    (dst / "pyproject.toml").write_text(_pyproject_from_metadata(), encoding="utf-8")


def _pyproject_from_metadata() -> str:
    """A ``pyproject.toml`` that rebuilds the installed distribution (its dependencies and extras)."""
    meta = metadata.metadata("balancelab")
    plain: list[str] = []
    extras: dict[str, list[str]] = {}
    for req in meta.get_all("Requires-Dist") or []:
        spec, _, marker = req.partition(";")
        found = re.search(r"""extra\s*==\s*["']([\w.-]+)["']""", marker)
        (extras.setdefault(found.group(1), []) if found else plain).append(spec.strip())
    quoted = lambda items: "[" + ", ".join(f'"{i}"' for i in items) + "]"  # noqa: E731
    lines = ["[build-system]", 'requires = ["setuptools>=77", "wheel"]', 'build-backend = "setuptools.build_meta"',
             "", "[project]", f'name = "{meta["Name"]}"', f'version = "{meta["Version"]}"',
             f'requires-python = "{(meta.get_all("Requires-Python") or [">=3.10"])[0]}"', f"dependencies = {quoted(plain)}",
             "", "[project.optional-dependencies]"]
    lines += [f"{name} = {quoted(items)}" for name, items in sorted(extras.items())]
    lines += ["", "[tool.setuptools.packages.find]", 'include = ["balancelab*"]', ""]
    return "\n".join(lines)
