"""Taking in submissions: which files are graded, how they are read, whose they are, which lab.

* :func:`find_submissions` lists every ``*.ipynb`` under a folder without following links;
* :func:`read_regular` opens one without following a link, only if it is a regular file, and
  reads at most a size cap (a FIFO, a device or a link to ``/dev/zero`` is refused, not read);
* :func:`identity` says whose a submission is: from the roster (``--roster``: a CSV with the
  columns ``file`` and ``student_id``) or from the file name (:data:`ID_PATTERN`), never from
  the notebook;
* :func:`resolve_lab` says which lab it is, :func:`cheat_notes` what its code replaces.
"""
from __future__ import annotations

import ast
import csv
import os
import re
import stat
from pathlib import Path

from .check.core import student_key
from .sanitize import excerpt

__all__ = ["MAX_NOTEBOOK", "ID_PATTERN", "find_submissions", "read_regular", "read_roster", "roster_problems",
           "identity", "resolve_lab", "lab_sources", "cheat_notes"]

#: Largest notebook file read (bytes).
MAX_NOTEBOOK = 20 * 2 ** 20
#: The student id in a file name: ``ID_labN.ipynb`` or ``ID/labN....ipynb`` (letters, digits, ``.-``).
ID_PATTERN = re.compile(r"^(?P<id>[A-Za-z0-9][A-Za-z0-9.\-]{0,62})_(?i:lab)\d+(?:_[^/]*)?\.ipynb$")
_DIR_ID = re.compile(r"^[A-Za-z0-9][A-Za-z0-9.\-_]{0,62}$")


def find_submissions(folder: str | Path) -> list[Path]:
    """Every ``*.ipynb`` under ``folder`` (checkpoints skipped), links included but never followed.

    Parameters
    ----------
    folder : str or Path

    Returns
    -------
    list of Path
        Sorted; a link (to a file or a folder) is listed as itself so that it gets a row.

    Examples
    --------
    >>> find_submissions("/nonexistent-folder")
    []
    """
    found = []
    for root, dirs, files in os.walk(folder, followlinks=False):
        keep = []
        for d in dirs:
            if os.path.islink(os.path.join(root, d)):   # listed (a row says it is refused), never entered
                files.append(d)
            elif d != ".ipynb_checkpoints":
                keep.append(d)
        dirs[:] = keep
        found += [Path(root) / f for f in files if f.endswith(".ipynb")]
    return sorted(found)


def read_regular(path: str | Path, cap: int = MAX_NOTEBOOK) -> bytes:
    """The bytes of a regular file, opened without following a link and without blocking.

    Parameters
    ----------
    path : str or Path
    cap : int
        Largest size read (bytes).

    Returns
    -------
    bytes

    Raises
    ------
    PermissionError
        If ``path`` is a link, or not a regular file (a FIFO, a device, a folder), or larger than ``cap``.

    Examples
    --------
    >>> read_regular("/dev/zero")
    Traceback (most recent call last):
    ...
    PermissionError: not a regular file (a character device)
    """
    try:
        fd = os.open(path, os.O_RDONLY | os.O_NOFOLLOW | os.O_NONBLOCK | os.O_CLOEXEC)
    except OSError as e:
        if os.path.islink(path):
            raise PermissionError("a symbolic link (only regular files are graded)") from e
        raise
    try:
        st = os.fstat(fd)
        if not stat.S_ISREG(st.st_mode):
            kinds = {stat.S_ISCHR: "a character device", stat.S_ISBLK: "a block device",
                     stat.S_ISFIFO: "a FIFO", stat.S_ISSOCK: "a socket", stat.S_ISDIR: "a folder"}
            kind = next((v for k, v in kinds.items() if k(st.st_mode)), "not a file")
            raise PermissionError(f"not a regular file ({kind})")
        if st.st_size > cap:
            raise PermissionError(f"larger than {cap // 2 ** 20} MB")
        data = os.read(fd, cap + 1)
        chunks = [data]
        while data and sum(map(len, chunks)) <= cap:
            data = os.read(fd, cap + 1)
            chunks.append(data)
        out = b"".join(chunks)
        if len(out) > cap:
            raise PermissionError(f"larger than {cap // 2 ** 20} MB")
        return out
    finally:
        os.close(fd)


def read_roster(path: str | Path) -> dict[str, str]:
    """A roster: submission file (its path in the folder, or its name) -> student id.

    Parameters
    ----------
    path : str or Path
        CSV with the columns ``file`` and ``student_id``.

    Returns
    -------
    dict

    Raises
    ------
    ValueError
        If a column is missing or a file is listed twice.

    Examples
    --------
    >>> import pathlib, tempfile
    >>> p = pathlib.Path(tempfile.mkdtemp()) / "roster.csv"
    >>> _ = p.write_text("file,student_id\\nalice_lab2.ipynb,s1001\\n")
    >>> read_roster(p)
    {'alice_lab2.ipynb': 's1001'}

    A spreadsheet's byte-order mark and ``./`` before a path are read as nothing:

    >>> _ = p.write_bytes(b"\\xef\\xbb\\xbffile,student_id\\r\\n./bob/lab2.ipynb,s1002\\r\\n")
    >>> read_roster(p)
    {'bob/lab2.ipynb': 's1002'}
    """
    out: dict[str, str] = {}
    with Path(path).open(newline="", encoding="utf-8-sig") as f:  # -sig: Excel's "CSV UTF-8" starts with a BOM
        reader = csv.DictReader(f)
        if not reader.fieldnames or not {"file", "student_id"} <= set(reader.fieldnames):
            raise ValueError(f"roster {path} must have the columns 'file' and 'student_id'")
        for rec in reader:
            name, sid = (rec.get("file") or "").strip(), (rec.get("student_id") or "").strip()
            while name.startswith("./"):
                name = name[2:]
            if not name or not sid:
                continue
            if name in out:
                raise ValueError(f"roster {path} lists {name!r} twice")
            out[name] = sid
    return out


def roster_problems(rels: list[str], roster: dict[str, str]) -> list[str]:
    """What is wrong with a roster for the submitted files: rows that match no file, rows that
    match several files, ids given to several files of one lab.

    A row matches a file by its path in the graded folder, or by its bare name when no row names
    that path (as :func:`identity` looks rows up).

    Parameters
    ----------
    rels : list of str
        Every submission's path in the graded folder (all of them, not one shard's).
    roster : dict
        :func:`read_roster`'s result.

    Returns
    -------
    list of str
        One sentence per problem (empty when the roster fits the folder).

    Examples
    --------
    >>> roster = {"alice_lab1.ipynb": "s1", "gone_lab1.ipynb": "s2", "a/bob_lab1.ipynb": "s3",
    ...           "b/bob_lab1.ipynb": "s3", "carol_lab1.ipynb": "s4"}
    >>> for p in roster_problems(["x/alice_lab1.ipynb", "y/alice_lab1.ipynb", "a/bob_lab1.ipynb",
    ...                           "b/bob_lab1.ipynb", "carol_lab1.ipynb"], roster):
    ...     print(p)
    roster: 'alice_lab1.ipynb' matches 2 submitted files (x/alice_lab1.ipynb, y/alice_lab1.ipynb): give their paths
    roster: 'gone_lab1.ipynb' matches no submitted file
    roster: the id 's3' is given to 2 files of lab1 (a/bob_lab1.ipynb, b/bob_lab1.ipynb)
    """
    rels = [r.replace(os.sep, "/") for r in rels]
    out = []
    for name in roster:
        found = [r for r in rels if r == name or (r.rsplit("/", 1)[-1] == name and r not in roster)]
        if not found:
            out.append(f"roster: {excerpt(name, 80)!r} matches no submitted file")
        elif len(found) > 1:
            out.append(f"roster: {excerpt(name, 80)!r} matches {len(found)} submitted files "
                       f"({excerpt(', '.join(found), 200)}): give their paths")
    groups: dict[tuple[str, str], list[str]] = {}
    for name, sid in roster.items():
        groups.setdefault((student_key(sid), lab_sources({}, Path(name))[0] or "no lab"), []).append(name)
    for (sid, lab), names in groups.items():
        if len(names) > 1:
            out.append(f"roster: the id {excerpt(sid, 40)!r} is given to {len(names)} files of {lab} "
                       f"({excerpt(', '.join(names), 200)})")
    return out


def identity(rel: str, roster: dict[str, str] | None) -> tuple[str, str]:
    """Whose a submission is, and how that was found: from the roster, else from the file name.

    Parameters
    ----------
    rel : str
        The submission's path in the graded folder (``"alice_lab2.ipynb"``, ``"s12/lab2.ipynb"``).
    roster : dict or None
        :func:`read_roster`'s result.

    Returns
    -------
    (str, str)
        The id (``""`` when unknown) and its source (``"roster"``, ``"file name"`` or a note).

    Examples
    --------
    >>> identity("alice_lab2.ipynb", None)
    ('alice', 'file name')

    Ids are case-insensitive (:func:`~balancelab.course.check.core.student_key`):

    >>> identity("Alice_lab2.ipynb", None)[0] == identity("ALICE/lab2.ipynb", None)[0] == "alice"
    True
    >>> [identity(name, None)[0] for name in ("Alice_Lab2.ipynb", "ALICE_LAB2.ipynb", "Kim/Lab2.ipynb")]
    ['alice', 'alice', 'kim']
    >>> identity("s1234/lab2.ipynb", None)
    ('s1234', 'folder name')

    An id in the file name comes first; a folder of another name is said (the row notes it):

    >>> identity("mallory/alice_lab1.ipynb", None)
    ('alice', "file name; the folder 'mallory' names another id: check whose it is")
    >>> identity("malice_lab1.ipynb", {"malice_lab1.ipynb": "M77"})
    ('m77', 'roster')
    >>> identity("lab1.ipynb", None)[0]
    ''
    """
    sid, how = _identity(rel.replace(os.sep, "/"), roster)
    return student_key(sid), how


def _identity(rel: str, roster: dict[str, str] | None) -> tuple[str, str]:
    if roster is not None:
        sid = roster.get(rel) or roster.get(rel.rsplit("/", 1)[-1])
        return (sid, "roster") if sid else ("", "not in the roster")
    parts = rel.split("/")
    m = ID_PATTERN.match(parts[-1])
    folder = parts[-2] if len(parts) >= 2 and _DIR_ID.match(parts[-2]) else None
    if m and folder is not None and student_key(m.group("id")) != student_key(folder):
        # ID_labN.ipynb in a folder of another name: a folder that groups files, or someone's upload
        # folder holding a file named for a classmate; the file name's id is used, and the row says so
        return m.group("id"), (f"file name; the folder {excerpt(folder, 40)!r} names another id: "
                               "check whose it is")
    if m:
        return m.group("id"), "file name"
    if folder is not None and re.match(r"^lab\d+", parts[-1], re.IGNORECASE):
        return folder, "folder name"
    return "", "the file name does not match ID_labN.ipynb or ID/labN.ipynb"


def _norm_lab(lab) -> str | None:
    """``labN``; None for no tag (absent or blank); ``unreadable (...)`` for any other tag (a float, a
    list, a table, a name of no lab), so that a tag that cannot be read is still reported."""
    if lab is None or (isinstance(lab, str) and lab.strip() == ""):
        return None
    if not isinstance(lab, (str, int)) or isinstance(lab, bool):
        return f"unreadable ({excerpt(lab, 20)})"
    m = re.fullmatch(r"(?:lab)?\s*(\d{1,3})", str(lab).strip(), re.IGNORECASE)
    return f"lab{int(m.group(1))}" if m else f"unreadable ({excerpt(lab, 20)})"


def resolve_lab(nb: dict, path: Path, lab: str | None = None) -> tuple[str | None, str]:
    """The lab of a notebook and what disagrees about it.

    ``--lab`` wins, then ``labN`` in the file name (the instructor's name for the file, or the
    roster's), and only then the notebook's ``balancelab.lab`` metadata, which the notebook's
    author can edit; every source that names another lab is reported.

    Parameters
    ----------
    nb : dict
        The notebook.
    path : Path
        Its file.
    lab : str, optional
        The lab forced on the command line.

    Returns
    -------
    (str or None, str)
        The lab (None if unknown) and the mismatch text (empty if all sources agree).

    Examples
    --------
    >>> from pathlib import Path
    >>> resolve_lab({"metadata": {"balancelab": {"lab": "lab5"}}}, Path("ann_lab1.ipynb"))
    ('lab1', 'file name says lab1, metadata says lab5')
    >>> resolve_lab({"metadata": {"balancelab": {"lab": "lab5"}}}, Path("ann.ipynb"))
    ('lab5', '')
    """
    from_name, from_meta, forced = lab_sources(nb, path, lab)
    sources = [("file name", from_name), ("metadata", from_meta), ("--lab", forced)]
    named = {v for _, v in sources if v}
    mismatch = ", ".join(f"{k} says {v}" for k, v in sources if v) if len(named) > 1 else ""
    return forced or from_name or from_meta, mismatch


def lab_sources(nb: dict, path: Path, lab: str | None = None) -> tuple[str | None, str | None, str | None]:
    """What the file name, the notebook's metadata and ``--lab`` each say the lab is (None: nothing).

    Parameters
    ----------
    nb : dict
        The notebook.
    path : Path
        Its file.
    lab : str, optional
        The lab forced on the command line.

    Returns
    -------
    (str or None, str or None, str or None)
        ``labN`` (or ``"unreadable (...)"`` for a tag that names no lab) from the file name,
        the metadata and ``--lab``.

    Examples
    --------
    >>> from pathlib import Path
    >>> lab_sources({"metadata": {"balancelab": {"lab": "Lab 07"}}}, Path("Ann_LAB2.ipynb"))
    ('lab2', 'lab7', None)
    >>> lab_sources({}, Path("slab3_lab1.ipynb"))[0]
    'lab1'

    A tag that is no lab name is reported as unreadable, never read as no tag:

    >>> lab_sources({"metadata": {"balancelab": {"lab": [5]}}}, Path("ann_lab2.ipynb"))
    ('lab2', 'unreadable ([5])', None)
    """
    meta = nb.get("metadata", {}) if isinstance(nb, dict) else {}
    meta = meta.get("balancelab", {}) if isinstance(meta, dict) else {}
    from_meta = _norm_lab(meta.get("lab")) if isinstance(meta, dict) else None
    # the ``labN`` of ``ID_labN`` or ``labN...`` first: an id may itself hold "lab3" (``slab3_lab1``)
    m = (re.search(r"(?:^|_)lab[_\-]?(\d+)", path.name, re.IGNORECASE)
         or re.search(r"lab[_\-]?(\d+)", path.name, re.IGNORECASE))
    return (f"lab{int(m.group(1))}" if m else None), from_meta, _norm_lab(lab)


#: IPython's hooks on what a cell's source becomes (they see and rewrite every later cell the runner sends).
_HOOK_NAMES = {"input_transformers_post", "input_transformers_cleanup", "input_transformer_manager", "transform_cell",
               "ast_transformers", "register_transformer"}
_PATCH_NAMES = {"check", "check_data", "grade_answers", "grade_namespace", "balance_report", "judge", "Verdict",
                "print", "dumps"}


def cheat_notes(nb) -> list[str]:
    """What the notebook's code replaces that the grader ignores anyway (reported, never trusted).

    Parameters
    ----------
    nb : dict
        The notebook.

    Returns
    -------
    list of str

    Examples
    --------
    >>> cheat_notes({"cells": [{"cell_type": "code", "source": "import json\\njson.dumps = str"}]})
    ['the notebook replaces `dumps`: ignored (the grader checks the exported answers itself)']
    """
    found = set()
    for cell in nb.get("cells", []):
        if cell.get("cell_type") != "code":
            continue
        src = cell.get("source", "")
        src = src if isinstance(src, str) else "".join(src)
        try:
            tree = ast.parse("\n".join(ln for ln in src.splitlines() if not ln.lstrip().startswith(("%", "!"))))
        except (SyntaxError, ValueError):  # ValueError: a lone surrogate or NUL that cannot be compiled
            continue
        for node in ast.walk(tree):
            targets = (node.targets if isinstance(node, ast.Assign) else [node.target]
                       if isinstance(node, (ast.AugAssign, ast.AnnAssign)) else [])
            for t in targets:
                name = t.id if isinstance(t, ast.Name) else t.attr if isinstance(t, ast.Attribute) else None
                if name in _PATCH_NAMES:
                    found.add(f"replaces `{name}`")
            hook = (node.attr if isinstance(node, ast.Attribute) else node.id if isinstance(node, ast.Name) else
                    node.value if isinstance(node, ast.Constant) and isinstance(node.value, str) else None)
            if hook in _HOOK_NAMES:
                found.add("hooks IPython's input transformers")
            if isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef)) and node.name in _PATCH_NAMES:
                found.add(f"redefines `{node.name}`")
            if isinstance(node, ast.ClassDef) and any("Design" in ast.unparse(b) or "Verdict" in ast.unparse(b)
                                                      for b in node.bases):
                found.add(f"subclasses {excerpt(', '.join(ast.unparse(b) for b in node.bases), 40)}")
    if not found:
        return []
    return [f"the notebook {', '.join(sorted(found))}: ignored (the grader checks the exported answers itself)"]
