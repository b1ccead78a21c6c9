"""Where a lab runs: the set-up cell of every student notebook and the links that open a lab.

One address names the course: ``repository.url`` and ``repository.branch`` in ``_config.yml``.
From it come

* the **set-up cell** that :mod:`~balancelab.course.labtools` puts before the first code cell of
  every student notebook (:func:`setup_source`, :func:`add_setup_cell`): where ``balancelab``
  imports it does nothing; on Google Colab (``google.colab`` in ``sys.modules``) it installs the
  course package from that address (``pip install git+URL@BRANCH``: a fork's notebooks install the
  fork) and turns on Colab's widget manager; it prints one line saying what it did;
* the **launch links** of the labs page (:func:`lab_links`): Binder (:func:`binder_url`), Colab
  (:func:`colab_url`, GitHub only), a JupyterHub through nbgitpuller (:func:`nbgitpuller_url`, only
  when ``launch_buttons.jupyterhub_url`` is set) and the file itself.

What it may import: nothing of the library (it is read by the book and by ``labtools``).
"""
from __future__ import annotations

from pathlib import Path
from urllib.parse import quote, urlencode, urlsplit

__all__ = ["SETUP_TAG", "STUDENT_README", "GRADER_MODULES", "LAPTOP_STEPS", "ways_text", "course_repository", "install_source", "setup_source", "add_setup_cell",
           "binder_url", "colab_url", "nbgitpuller_url", "lab_links"]

_ROOT = Path(__file__).resolve().parents[2]
#: The cell tag of the set-up cell (student notebooks only).
SETUP_TAG = "setup"
#: Path parts that make an address a web page of a repository rather than the repository.
_PAGE_PARTS = {"tree", "blob", "-", "commit", "raw", "src"}
_FORM = ("https://host/owner/repo (e.g. https://github.com/me/balancelab; a branch goes in "
         "repository.branch, not in the address)")
COLAB = "https://colab.research.google.com"

#: How to install on a laptop, in the hand-out folder: a virtual environment is required (Debian 12
#: and Ubuntu 24.04 have no ``python`` command and their system pip refuses to install, PEP 668).
LAPTOP_STEPS = """\
1. Make a virtual environment (once):

       python3 -m venv .venv

   Windows: `py -m venv .venv`. On Debian or Ubuntu, if it says *ensurepip is not available*,
   run `sudo apt install python3-venv` first.
2. Install the course package with JupyterLab and ipywidgets into it (once, with an internet
   connection; pip fetches numpy, scipy, sympy and matplotlib):

       .venv/bin/python -m pip install "./package[labs]"

   Windows: `.venv\\Scripts\\python -m pip install "./package[labs]"`.
3. Open a lab, in either of
   * **JupyterLab**: `.venv/bin/jupyter lab labs/` (Windows: `.venv\\Scripts\\jupyter lab labs`)
     opens in your browser; double-click a lab, then *Run > Run All Cells*;
   * **VS Code**: install the *Python* and *Jupyter* extensions, open this folder, open a lab,
     click *Select Kernel* (top right) and choose the `.venv` Python, then *Run All*.
"""

#: The hand-out's README (``labtools handout``): install once, then open a lab on a laptop.
STUDENT_README = f"""# balancelab labs

This folder holds the labs (`labs/`) and the course package they need (`package/`).
You need Python 3.10 or newer. In a terminal, in this folder:

{LAPTOP_STEPS}
After the install the labs need no network.

The first code cell of a lab says `Set-up: balancelab is installed.` when all is well. If it
says something is not installed, the notebook runs in another Python than the one you installed
into: pick the kernel you installed into (`.venv`), or run the install line above.

## Work on a lab

Every task ends in `check("n.m", answer)`: it says whether the answer is right and gives a
hint. `explain("n.m")` says what form an answer takes. Numbers are SI unless a unit is written
in a string (`"22 cm"`). If your instructor gave you a student id, write it in the line
`STUDENT_ID = ""` near the top. Hand in the `.ipynb` file.
"""

#: What the set-up cell tells a student who lacks the package off Colab, by where the notebook is.
_ADVICE = {
    False: ('In a terminal:  python3 -m venv .venv  then  .venv/bin/python -m pip install '
            '"balancelab[labs] @ {source}"  (Windows: py -m venv .venv, then .venv\\Scripts\\python; in a copy '
            'of the repository install ".[labs]"). See "For students" in labs/README.md.'),
    True: ('In a terminal, in the hand-out folder:  python3 -m venv .venv  then  .venv/bin/python -m pip install '
           '"./package[labs]"  (Windows: py -m venv .venv, then .venv\\Scripts\\python). '
           'See README.md at the top of the hand-out folder.'),
}

_SETUP = r'''# Set-up: on Google Colab this installs the course package; anywhere else it only checks it.
def _set_up(source="{source}"):
    import importlib.util, re, subprocess, sys
    on_colab = "google.colab" in sys.modules
    missing = [m for m in ("balancelab", "ipywidgets") if importlib.util.find_spec(m) is None]
    if not missing:
        done = "balancelab is installed"
    elif on_colab:
        wanted = [source] * ("balancelab" in missing) + ["ipywidgets"] * ("ipywidgets" in missing)
        try:
            pip = subprocess.run([sys.executable, "-m", "pip", "install", "--quiet", "--timeout", "60", *wanted],
                                 capture_output=True, text=True, timeout=900)
        except subprocess.TimeoutExpired:
            raise RuntimeError(f"pip could not install {{source}} within 15 minutes: check the connection, "
                               "then run this cell again") from None
        if pip.returncode:
            said = re.sub(r"\x1b\[[0-9;?]*[A-Za-z]", "", pip.stderr)[-3000:]
            raise RuntimeError(f"pip could not install {{source}}:\n{{said}}")
        importlib.invalidate_caches()
        done = f"installed balancelab from {{source}}"
    else:
        print(f"Set-up: {{' and '.join(missing)}} {{'is' if len(missing) == 1 else 'are'}} not installed here "
              f"(in this kernel's Python, {{sys.executable}}).\n" + {advice!r} +
              "\nThen pick the kernel you installed into (.venv) and run this cell again.")
        return
    if on_colab:
        from google.colab import output
        output.enable_custom_widget_manager()
        done += " and turned on Colab's widget manager"
    print(f"Set-up: {{done}}.")


_set_up()'''


#: The grader's own modules (in ``balancelab/course``): no notebook imports them, so the student
#: hand-out's package leaves them out (it can check answers, not grade).
GRADER_MODULES = ("grading.py", "runner.py", "sandbox.py", "workers.py", "caps.py", "intake.py", "leaks.py",
                  "gradetable.py", "sanitize.py")


def course_repository(config: str | Path = _ROOT / "_config.yml") -> tuple[str, str]:
    """The course's repository address and branch, as ``_config.yml`` gives them.

    Parameters
    ----------
    config : str or Path
        The Jupyter Book configuration (``repository.url``, ``repository.branch``; the branch
        defaults to ``main``).

    Returns
    -------
    (str, str)
        The address (no trailing ``/``) and the branch.

    Raises
    ------
    ValueError
        If ``repository.url`` is missing or not a repository's ``https://host/owner/repo``
        address (``file://`` is accepted for local tests; ``ssh://``, ``git@…`` and web pages
        such as ``…/tree/dev`` are not), or the branch is empty or holds a space.

    Examples
    --------
    >>> url, branch = course_repository()
    >>> url.startswith("https://"), bool(branch)
    (True, True)
    """
    import yaml

    cfg = yaml.safe_load(Path(config).read_text(encoding="utf-8")) or {}
    repo = cfg.get("repository") or {}
    return _checked(repo.get("url"), repo.get("branch") or "main")


def _checked(url, branch) -> tuple[str, str]:
    if not _usable(url):
        raise ValueError(f"repository.url must be a repository's address {_FORM}, got {url!r}")
    if not isinstance(branch, str) or not branch or any(c in branch for c in ' "\'\\\n@'):
        raise ValueError(f"repository.branch must be a branch name without spaces, quotes or '@', got {branch!r}")
    return url.rstrip("/"), branch


def _usable(url) -> bool:
    """An ``https://host/owner/repo`` address (or a ``file://`` one, for local tests)."""
    if not isinstance(url, str) or any(c in url for c in ' "\'\\\n?#'):
        return False
    if url.startswith("file://"):
        return len(url) > len("file://")
    parts = urlsplit(url)
    path = [p for p in parts.path.split("/") if p]
    if parts.scheme != "https" or not parts.hostname or "@" in parts.netloc or not path:
        return False
    if parts.hostname == "github.com" and len(path) != 2:
        return False
    return not _PAGE_PARTS & set(path)


def _web(url: str) -> str:
    """The repository's web page (a clone address's ``.git`` dropped)."""
    return url.removesuffix(".git")


def install_source(url: str, branch: str) -> str:
    """What ``pip install`` is given to install the course package from its repository.

    Parameters
    ----------
    url : str
        The repository address (``https://host/owner/repo``, or ``file://`` for local tests).
    branch : str
        The branch (or tag) to install.

    Returns
    -------
    str
        A pip requirement ``git+URL@BRANCH``.

    Raises
    ------
    ValueError
        If the address or the branch is not usable (see :func:`course_repository`).

    Examples
    --------
    >>> install_source("https://github.com/someone/balancelab/", "spring-2027")
    'git+https://github.com/someone/balancelab@spring-2027'
    """
    url, branch = _checked(url, branch)
    return f"git+{url}@{branch}"


def setup_source(url: str, branch: str, handout: bool = False) -> str:
    """The source of the set-up cell that installs the course package on Colab.

    Parameters
    ----------
    url, branch : str
        The repository to install from (see :func:`install_source`).
    handout : bool
        True for the notebooks of the hand-out (``labtools handout``): off Colab the cell then
        advises the hand-out's own install line (``"./package[labs]"``, its ``README.md``)
        instead of the repository's.

    Returns
    -------
    str
        Python code: a no-op (one printed line) where ``balancelab`` and ``ipywidgets`` import;
        on Colab it runs ``pip install git+URL@BRANCH`` (and ipywidgets if missing; pip's network
        timeout 60 s, 15 minutes in all) and ``google.colab.output.enable_custom_widget_manager()``;
        elsewhere it prints what is missing and how to install it into a virtual environment
        (``[labs]``: with ipywidgets and JupyterLab).

    Examples
    --------
    >>> import contextlib, io
    >>> out = io.StringIO()
    >>> with contextlib.redirect_stdout(out):
    ...     exec(setup_source("https://github.com/balancelab/balancelab", "main"), {})
    >>> out.getvalue()
    'Set-up: balancelab is installed.\\n'
    """
    source = install_source(url, branch)
    return _SETUP.format(source=source, advice=_ADVICE[bool(handout)].format(source=source))


def add_setup_cell(nb, url: str, branch: str, handout: bool = False):
    """Put the set-up cell before the first code cell of a notebook (in place).

    Parameters
    ----------
    nb : nbformat.NotebookNode
        A student notebook.
    url, branch : str
        The repository the cell installs from on Colab.
    handout : bool
        Whether the notebook goes into the hand-out (see :func:`setup_source`).

    Returns
    -------
    nbformat.NotebookNode
        ``nb`` itself, for chaining.

    Examples
    --------
    >>> import nbformat
    >>> v4 = nbformat.v4
    >>> nb = v4.new_notebook(cells=[v4.new_markdown_cell("# Lab"), v4.new_code_cell("import balancelab")])
    >>> [c.metadata.get("tags") for c in add_setup_cell(nb, "https://x.org/a/b", "main").cells]
    [None, ['setup'], None]
    """
    import nbformat

    cell = nbformat.v4.new_code_cell(setup_source(url, branch, handout), metadata={"tags": [SETUP_TAG]})
    if (nb.nbformat, nb.nbformat_minor) >= (4, 5):
        cell["id"] = "balancelab-setup"   # a fixed id: regenerating leaves no git diff
    else:
        cell.pop("id", None)
    at = next((i for i, c in enumerate(nb.cells) if c.cell_type == "code"), len(nb.cells))
    nb.cells.insert(at, cell)
    return nb


def _github(url: str) -> str | None:
    """``owner/name`` of a GitHub address, else None."""
    for prefix in ("https://github.com/", "http://github.com/"):
        if url.startswith(prefix):
            path = url[len(prefix):].removesuffix(".git").strip("/")
            if path.count("/") == 1:
                return path
    return None


def binder_url(binderhub: str, url: str, branch: str, path: str) -> str:
    """A BinderHub address that builds the repository and opens ``path`` in JupyterLab.

    Parameters
    ----------
    binderhub : str
        The BinderHub (``https://mybinder.org``).
    url, branch : str
        The repository and branch (GitHub, GitLab or any git address).
    path : str
        A file of the repository, relative to its root.

    Returns
    -------
    str

    Examples
    --------
    >>> binder_url("https://mybinder.org", "https://github.com/o/r", "main", "labs/student/lab1.ipynb")
    'https://mybinder.org/v2/gh/o/r/main?urlpath=lab%2Ftree%2Flabs%2Fstudent%2Flab1.ipynb'
    """
    url, branch = _checked(url, branch)
    gh = _github(url)
    if gh:
        spec = f"gh/{gh}"
    elif url.startswith("https://gitlab.com/"):
        spec = "gl/" + quote(_web(url)[len("https://gitlab.com/"):], safe="")
    else:
        spec = "git/" + quote(url, safe="")
    return f"{binderhub.rstrip('/')}/v2/{spec}/{quote(branch, safe='')}?" + urlencode({"urlpath": f"lab/tree/{path}"})


def colab_url(url: str, branch: str, path: str) -> str | None:
    """The Colab address that opens a notebook of a GitHub repository (None elsewhere).

    Parameters
    ----------
    url, branch : str
        The repository and branch.
    path : str
        The notebook, relative to the repository's root.

    Returns
    -------
    str or None
        None when the repository is not on GitHub (Colab opens notebooks only from GitHub).

    Examples
    --------
    >>> colab_url("https://github.com/o/r", "main", "labs/student/lab1.ipynb")
    'https://colab.research.google.com/github/o/r/blob/main/labs/student/lab1.ipynb'
    >>> colab_url("https://gitlab.com/o/r", "main", "labs/student/lab1.ipynb") is None
    True
    """
    url, branch = _checked(url, branch)
    gh = _github(url)
    return f"{COLAB}/github/{gh}/blob/{quote(branch)}/{quote(path)}" if gh else None


def nbgitpuller_url(hub: str, url: str, branch: str, path: str) -> str:
    """An nbgitpuller link: the hub pulls the repository into the user's home and opens ``path``.

    nbgitpuller clones into a folder named after the address's last part (its default
    ``targetpath``), so the file opens at ``lab/tree/<that folder>/<path>``.

    Parameters
    ----------
    hub : str
        The JupyterHub's address (``https://hub.example.edu``).
    url, branch : str
        The repository and branch to pull.
    path : str
        The file to open, relative to the repository's root.

    Returns
    -------
    str

    Raises
    ------
    ValueError
        If ``hub`` is not an ``https://`` or ``http://`` address.

    Examples
    --------
    >>> nbgitpuller_url("https://hub.example.edu/", "https://github.com/o/r", "main", "labs/a.ipynb")
    'https://hub.example.edu/hub/user-redirect/git-pull?repo=https%3A%2F%2Fgithub.com%2Fo%2Fr&branch=main&urlpath=lab%2Ftree%2Fr%2Flabs%2Fa.ipynb'
    """
    if not isinstance(hub, str) or not hub.startswith(("https://", "http://")):
        raise ValueError(f"launch_buttons.jupyterhub_url must start with https:// or http://, got {hub!r}")
    url, branch = _checked(url, branch)
    folder = url.split("/")[-1]
    query = urlencode({"repo": url, "branch": branch, "urlpath": f"lab/tree/{folder}/{path}"})
    return f"{_hub_root(hub)}/hub/user-redirect/git-pull?{query}"


def _hub_root(hub: str) -> str:
    """The hub's root address: ``https://x/hub/`` and ``https://x/hub`` both give ``https://x``."""
    root = hub.rstrip("/")
    return root[:-len("/hub")] if root.endswith("/hub") and root.count("/") > 2 else root


def lab_links(path: str, config: str | Path = _ROOT / "_config.yml") -> list[tuple[str, str]]:
    """``(name, address)`` of every place the notebook ``path`` opens, as the labs page lists them.

    Parameters
    ----------
    path : str
        The notebook, relative to the repository's root.
    config : str or Path
        The Jupyter Book configuration (``repository``, ``launch_buttons``).

    Returns
    -------
    list of (str, str)
        Binder (when ``launch_buttons.binderhub_url`` is set), Colab (GitHub repositories),
        JupyterHub (when ``launch_buttons.jupyterhub_url`` is set) and the file's source page.

    Examples
    --------
    >>> [name for name, _ in lab_links("labs/student/lab1_counterweights.ipynb")]
    ['Binder', 'Colab', 'source']
    """
    import yaml

    url, branch = course_repository(config)
    buttons = (yaml.safe_load(Path(config).read_text(encoding="utf-8")) or {}).get("launch_buttons") or {}
    links = []
    if buttons.get("binderhub_url"):
        links.append(("Binder", binder_url(buttons["binderhub_url"], url, branch, path)))
    colab = colab_url(url, branch, path)
    if colab:
        links.append(("Colab", colab))
    if buttons.get("jupyterhub_url"):
        links.append(("JupyterHub", nbgitpuller_url(buttons["jupyterhub_url"], url, branch, path)))
    if _github(url):
        links.append(("source", f"{_web(url)}/blob/{quote(branch)}/{quote(path)}"))
    elif url.startswith("https://gitlab.com/"):
        links.append(("source", f"{_web(url)}/-/blob/{quote(branch)}/{quote(path)}"))
    return links


_WAYS = {
    "Colab": ("**Colab** (a Google account, nothing to install): the lab's first cell installs the course "
              "package (about half a minute) and turns on Colab's widgets. Colab keeps nothing unless you "
              "choose *File > Save a copy in Drive*."),
    "Binder": ("**Binder** (no account, nothing to install): JupyterLab in your browser with everything "
               "installed. Starting can take a few minutes, a session that sits idle for about ten minutes "
               "is shut down and nothing is kept: *File > Download* your notebook before you leave."),
    "JupyterHub": ("**JupyterHub** (your course's hub, its links below): your work stays in your account. "
                   "The link copies the labs into your home folder the first time and later brings them up "
                   "to date without overwriting what you changed."),
}


def ways_text(config: str | Path = _ROOT / "_config.yml") -> str:
    """The labs page's list of ways into a lab: only those the configuration makes links for.

    Parameters
    ----------
    config : str or Path
        The Jupyter Book configuration (see :func:`lab_links`).

    Returns
    -------
    str
        Markdown bullets: Colab, Binder and JupyterHub when :func:`lab_links` makes such links
        (the first of them called the quickest start), then the laptop.

    Examples
    --------
    >>> "quickest start" in ways_text().splitlines()[0]
    True
    """
    made = {name for name, _ in lab_links("labs/student/lab1_counterweights.ipynb", config)}
    bullets = [f"- {text}" for name, text in _WAYS.items() if name in made]
    if bullets:
        head, rest = bullets[0].split(": ", 1)
        bullets[0] = f"{head}: the quickest start. {rest[0].upper()}{rest[1:]}"
    bullets.append("- **Your laptop** (Python 3.10 or newer): works offline once installed, and is the best "
                   "place for work you hand in; the steps are below.")
    return "\n".join(bullets)
