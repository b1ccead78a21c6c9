"""Sphinx extension: the ``.ipynb`` a reader downloads is a plain Jupyter notebook, without solutions.

Jupyter Book offers every executed page as ``_sources/<page>.ipynb``: the MyST source with its
outputs, which Jupyter shows as raw directives (```` ```{exercise} ````, ``{cite:p}`...```) with
every solution in plain view. After the build this extension rewrites each of those files from
the page's MyST source (:func:`reader_notebook`):

* exercise solutions (``solution-start`` ... ``solution-end`` with their code cells, and
  ``solution`` blocks) are left out: the site keeps them behind a click;
* directives become Markdown Jupyter understands (a bold heading and a quotation), roles become
  their text (``{cite:p}`lecture35``` -> ``[lecture35]``), labels of targets and equations go;
  a cross-reference becomes what the site shows ("(4.3)", "Figure 4.1", the section's title),
  never the raw label;
* the first cell names the course (``html_title``; Jupyter Book 1 never sets ``project``);
* outputs are left out (the notebook is for running): the file is a few kB, not a few MB.
"""
from __future__ import annotations

import re
from pathlib import Path

__all__ = ["reader_notebook", "setup"]

_FENCE = re.compile(r"^(?P<fence>`{3,}|:{3,})\{(?P<name>[\w:-]+)\}[ \t]*(?P<arg>[^\n]*)\n(?P<body>.*?)^(?P=fence)[ \t]*$\n?",
                    re.MULTILINE | re.DOTALL)
_ROLE = re.compile(r"\{(?P<role>[\w:-]+)\}`(?P<text>[^`]*)`")
_TARGET = re.compile(r"^\([\w:.-]+\)=[ \t]*\n", re.MULTILINE)
_EQ_LABEL = re.compile(r"(\$\$)[ \t]*\([\w:.-]+\)[ \t]*$", re.MULTILINE)
_DROP = {"solution", "tableofcontents", "bibliography", "glue:figure", "code-cell"}
_TITLES = {"exercise": "Exercise", "prf:theorem": "Theorem", "prf:proof": "Proof", "prf:lemma": "Lemma",
           "prf:definition": "Definition", "prf:example": "Example", "prf:remark": "Remark", "note": "Note",
           "tip": "Tip", "warning": "Warning", "important": "Important", "hint": "Hint", "figure": "Figure"}
_CITE = ("cite", "cite:p", "cite:t", "cite:ps", "cite:ts", "cite:alp")


#: What a cross-reference names when the site's number or title is not known, by label prefix.
_KINDS = {"fig": "the figure", "tab": "the table", "thm": "the theorem", "eq": "the equation",
          "ex": "the exercise", "sol": "the solution", "notes": "the notes on the sources",
          "lem": "the lemma", "def": "the definition"}


def _role(m: re.Match, resolve=None) -> str:
    role, text = m.group("role"), m.group("text")
    shown = re.match(r"^(.*?)\s*<([^>]*)>$", text, re.S)
    if shown and shown.group(1):
        return shown.group(1)
    target = shown.group(2) if shown else text
    if role in _CITE:
        return "[" + ", ".join(k.strip() for k in target.split(",")) + "]"
    if role in ("eq", "numref", "ref", "prf:ref"):
        found = resolve(role, target) if resolve is not None else None
        if found:
            return found
        return _KINDS.get(target.split("-")[0], "the section") + " on the course site"
    if role == "doc":
        found = resolve(role, target) if resolve is not None else None
        return f"*{found}*" if found else f"the page *{target.split('/')[-1].replace('_', ' ')}*"
    if role == "math":
        return f"${target}$"
    return target


def _directive(m: re.Match) -> str:
    name, arg, body = m.group("name"), m.group("arg").strip(), m.group("body")
    if name in _DROP:
        return ""
    if body.startswith("---\n") and "\n---\n" in body[3:]:
        body = body[body.index("\n---\n", 3) + 5:]
    lines = body.splitlines()
    while lines and lines[0].startswith(":"):
        lines.pop(0)
    body = _FENCE.sub(_directive, "\n".join(lines).strip() + "\n").strip()
    if name == "math":
        return f"$$\n{body}\n$$\n"
    head = _TITLES.get(name, "")
    title = " — ".join(t for t in (head, arg) if t)
    quoted = "\n".join(">" if not ln.strip() else f"> {ln}" for ln in body.splitlines())
    return (f"> **{title}**\n>\n" if title else "") + quoted + "\n"


def _markdown(text: str, resolve=None) -> str:
    text = _FENCE.sub(_directive, text)
    text = _TARGET.sub("", text)
    text = _EQ_LABEL.sub(r"\1", text)
    return _ROLE.sub(lambda m: _role(m, resolve), text).strip()


def reader_notebook(myst: str, title: str = "", resolve=None):
    """A MyST notebook page as a plain Jupyter notebook without solutions or outputs.

    Parameters
    ----------
    myst : str
        The page's MyST Markdown (jupytext ``md:myst``).
    title : str
        Where the notebook comes from, for its first cell.
    resolve : callable, optional
        ``resolve(role, label)``: what the site shows for a cross-reference ("(4.3)",
        "Figure 4.1", a section's title), or None; without it a reference reads "the figure on
        the course site".

    Returns
    -------
    nbformat.NotebookNode

    Examples
    --------
    >>> page = ("---\\njupytext:\\n  text_representation:\\n    format_name: myst\\nkernelspec:\\n"
    ...         "  name: python3\\n  display_name: Python 3\\n  language: python\\n---\\n"
    ...         "# A page\\n\\nSee {cite:p}`lecture35`.\\n\\n```{exercise} Try\\n:label: ex\\n"
    ...         "Balance it.\\n```\\n\\n```{solution-start} ex\\n```\\n\\nThe answer.\\n\\n"
    ...         "```{code-cell} ipython3\\nk = 5\\n```\\n\\n```{solution-end}\\n```\\n\\nEnd.\\n")
    >>> nb = reader_notebook(page)
    >>> text = "\\n".join(c.source for c in nb.cells)
    >>> {c.cell_type for c in nb.cells}, "k = 5" in text, "The answer" in text, "[lecture35]" in text
    ({'markdown'}, False, False, True)
    >>> "> **Exercise — Try**" in text and "End." in text and "{" not in text
    True
    >>> cells = reader_notebook("# P\\n\\nSee {eq}`eq-a` and {numref}`fig-b`.\\n",
    ...                         resolve=lambda role, label: "(1.2)" if role == "eq" else None).cells
    >>> cells[0].source
    '# P\\n\\nSee (1.2) and the figure on the course site.'

    """
    import jupytext
    import nbformat

    nb = jupytext.reads(myst, fmt="md:myst")
    cells, hiding = [], False
    for cell in nb.cells:
        if cell.cell_type == "markdown":
            kept, text = [], cell.source
            while text:
                marker = "```{solution-end}" if hiding else "```{solution-start}"
                at = text.find(marker)
                if at < 0:
                    kept.append("" if hiding else text)
                    break
                if not hiding:
                    kept.append(text[:at])
                end = text.find("```", at + len(marker))
                text = text[end + 3:] if end >= 0 else ""
                hiding = not hiding
            source = _markdown("".join(kept), resolve)
            if source:
                cells.append(nbformat.v4.new_markdown_cell(source))
        elif not hiding:
            code = nbformat.v4.new_code_cell(cell.source)
            tags = cell.metadata.get("tags", [])
            if tags:
                code.metadata["tags"] = list(tags)
            cells.append(code)
    if title:
        cells.insert(0, nbformat.v4.new_markdown_cell(
            f"*{title}*: a notebook to run. The exercises' solutions, the figures and the numbered "
            "cross-references are on the course site."))
    out = nbformat.v4.new_notebook(cells=cells)
    out.metadata["kernelspec"] = dict(nb.metadata.get("kernelspec", {"name": "python3",
                                                                      "display_name": "Python 3",
                                                                      "language": "python"}))
    return out


def _rewrite(app, exception) -> None:
    if exception is not None or app.builder.format != "html":
        return
    import nbformat

    sources = Path(app.outdir) / "_sources"
    for ipynb in sorted(sources.rglob("*.ipynb")):
        docname = ipynb.relative_to(sources).with_suffix("").as_posix()
        src = Path(app.srcdir) / f"{docname}.md"
        if not src.is_file():
            continue
        title = f"{course_title(app)}: {app.env.titles[docname].astext()}" if docname in app.env.titles else ""
        nbformat.write(reader_notebook(src.read_text(encoding="utf-8"), title, resolver(app)), str(ipynb))


def course_title(app) -> str:
    """The course's name: ``html_title`` (``_config.yml``'s ``title``; Jupyter Book 1 leaves
    ``project`` at "Project name not set")."""
    title = (app.config.html_title or "").strip()
    if not title or title.lower().startswith("project name not set"):
        title = app.config.project or "The course"
    return title


def resolver(app):
    """``resolve(role, label)`` for :func:`reader_notebook`: the equation number, figure number or
    section title that the site shows for a cross-reference, from the Sphinx environment."""
    env = app.env
    std = env.get_domain("std")

    def number(docname, kind, node_id):
        nums = env.toc_fignumbers.get(docname, {}).get(kind, {}).get(node_id)
        return ".".join(map(str, nums)) if nums else None

    def resolve(role, label):
        if role == "doc":
            for docname, title in env.titles.items():
                if docname == label.lstrip("/") or docname.endswith("/" + label):
                    return title.astext()
            return None
        if role == "eq":
            math = env.get_domain("math")
            found = math.equations.get(label) if hasattr(math, "equations") else None
            if not found:
                return None
            docname, eqno = found
            num = number(docname, "displaymath", f"equation-{label}")
            return f"({num or eqno})"
        target = std.labels.get(label) or std.anonlabels.get(label)
        if not target:
            return None
        docname, node_id = target[0], target[1]
        if label.startswith("fig"):
            num = number(docname, "figure", node_id)
            return f"Figure {num}" if num else None
        if label.startswith("tab"):
            num = number(docname, "table", node_id)
            return f"Table {num}" if num else None
        name = target[2] if len(target) > 2 else ""
        return f"*{name}*" if name else None

    return resolve


def setup(app):
    """Register the rewrite with Sphinx."""
    app.connect("build-finished", _rewrite)
    return {"version": "1.0", "parallel_read_safe": True, "parallel_write_safe": True}
