"""Lab answers in a package's docstrings: the scan the hand-out runs before it is given to students.

A number (3 or more significant digits) in a docstring of the package that a numeric task accepts
as its answer with the published numbers is a leak (:func:`answer_leaks`).
"""
from __future__ import annotations

from pathlib import Path

__all__ = ["docstring_numbers", "answer_leaks"]


def docstring_numbers(package: str | Path) -> dict[float, str]:
    """Numbers (3 or more significant digits) in the docstrings of a package's modules: value -> where.

    Parameters
    ----------
    package : str or Path
        A package folder.

    Returns
    -------
    dict

    Examples
    --------
    >>> import pathlib, tempfile
    >>> d = pathlib.Path(tempfile.mkdtemp())
    >>> _ = (d / "m.py").write_text("def f():\\n    'Returns 123.25 and 2.5.'\\n")
    >>> docstring_numbers(d)
    {123.25: 'm.py: f'}
    """
    import ast
    import re

    found: dict[float, str] = {}
    for f in sorted(Path(package).rglob("*.py")):
        try:
            tree = ast.parse(f.read_text(encoding="utf-8"))
        except (SyntaxError, UnicodeDecodeError):
            continue
        for node in ast.walk(tree):
            if not isinstance(node, (ast.Module, ast.ClassDef, ast.FunctionDef, ast.AsyncFunctionDef)):
                continue
            doc = ast.get_docstring(node, clean=False) or ""
            for m in re.finditer(r"(?<![\w.])-?\d+\.\d+(?:e-?\d+)?", doc):
                digits = m.group().lstrip("-").split("e")[0].replace(".", "").lstrip("0")
                if len(digits) >= 3:
                    found.setdefault(float(m.group()), f"{f.relative_to(package)}: {getattr(node, 'name', 'module')}")
    return found


def answer_leaks(package: str | Path) -> list[str]:
    """Numbers in the package's docstrings that a numeric task accepts as its answer (published numbers).

    Parameters
    ----------
    package : str or Path
        A package folder (e.g. the hand-out's copy of ``balancelab``).

    Returns
    -------
    list of str
        ``"task n.m: <value> in <file>: <function>"`` per leak.
    """
    from .check import check_data, tasks

    numeric = [t for t in tasks() if t.kind == "numeric"]
    leaks = []
    for value, where in docstring_numbers(package).items():
        for t in numeric:
            if check_data(t.id, {"num": repr(value)}, "").correct:
                leaks.append(f"task {t.id}: {value!r} in {where}")
    return leaks
