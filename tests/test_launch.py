"""Every way into a lab: Colab (simulated), Binder (repo2docker's own build plan), JupyterHub
(nbgitpuller links), a laptop (the hand-out installed in a fresh virtual environment).

The fresh-environment tests are marked slow: each makes a virtual environment and installs
numpy, scipy, sympy, matplotlib and the Jupyter stack from pip's cache (pinned by
``constraints.txt``), so they take one to two minutes each.
"""
from __future__ import annotations

import contextlib
import importlib.util
import io
import json
import os
import re
import secrets
import subprocess
import sys
import textwrap
import time
import urllib.request
from pathlib import Path
from unittest import mock
from urllib.parse import parse_qs, unquote, urlsplit

import nbformat
import pytest
import yaml
from hypothesis import given, settings
from hypothesis import strategies as st

from balancelab.course import labtools, launch
from conftest import CHROMIUM, CHROMIUM_ARGS, NEEDS_CHROMIUM, free_port

ROOT = Path(__file__).resolve().parent.parent
SOLUTIONS = sorted((ROOT / "labs" / "solutions").glob("*.ipynb"))
STUDENT = ROOT / "labs" / "student"
CONSTRAINTS = ROOT / "constraints.txt"
BINDER = ROOT / "binder"
UPSTREAM = launch.course_repository()


def _code_cells(nb):
    return [c for c in nb.cells if c.cell_type == "code"]


def _text(cell) -> str:
    return "".join(o.get("text", "") for o in cell.outputs if o.output_type == "stream")


# ------------------------------------------------------------------ the set-up cell


@pytest.mark.parametrize("path", SOLUTIONS, ids=lambda p: p.stem)
def test_every_student_notebook_starts_with_the_setup_cell_of_the_configured_repository(path):
    student = nbformat.read(STUDENT / path.name, as_version=4)
    first = _code_cells(student)[0]
    assert first.metadata.get("tags") == [launch.SETUP_TAG]
    assert first.source == launch.setup_source(*UPSTREAM)
    cfg = yaml.safe_load((ROOT / "_config.yml").read_text())["repository"]
    assert f'source="git+{cfg["url"].rstrip("/")}@{cfg["branch"]}"' in first.source
    # only cells before it are prose: nothing runs before the set-up
    assert all(c.cell_type == "markdown" for c in student.cells[:student.cells.index(first)])
    assert "google.colab" not in "".join(c.source for c in nbformat.read(path, as_version=4).cells)


def test_a_forks_notebooks_install_the_fork(tmp_path):
    """Changing repository.url and branch in _config.yml changes what the set-up cell installs."""
    cfg = yaml.safe_load((ROOT / "_config.yml").read_text())
    cfg["repository"].update(url="https://gitlab.com/teach/our-balancelab/", branch="spring-2027")
    (tmp_path / "_config.yml").write_text(yaml.safe_dump(cfg))
    fork = launch.course_repository(tmp_path / "_config.yml")
    assert fork == ("https://gitlab.com/teach/our-balancelab", "spring-2027")
    text = labtools.student_text(SOLUTIONS[0], repository=fork)
    assert "git+https://gitlab.com/teach/our-balancelab@spring-2027" in text
    assert UPSTREAM[0] not in text
    # the committed student versions were generated from the upstream address: now stale for the fork
    assert text != (STUDENT / SOLUTIONS[0].name).read_text(encoding="utf-8")


@pytest.mark.parametrize("url, branch", [
    ("github.com/o/r", "main"), ("https://github.com/o/r", ""), ("https://github.com/o/r", "a b"),
    ('https://github.com/o/r"; import os; "', "main"), ("https://github.com/o/r", 'x"'), (None, "main"),
    ("https://github.com/o/r", "main@evil"),
    ("https://github.com/me/fork/tree/dev", "main"), ("ssh://git@github.com/me/fork", "main"),
    ("git@github.com:me/fork.git", "main"), ("https://gitlab.com/me/fork/-/tree/dev", "main"),
    ("http://github.com/o/r", "main"), ("https://github.com/me", "main"), ("https://github.com/o/r?x=1", "main"),
])
def test_unusable_repository_addresses_are_refused(url, branch):
    with pytest.raises(ValueError, match=r"repository\.(url|branch)"):
        launch.setup_source(url, branch)


@pytest.mark.parametrize("url", ["https://github.com/me/fork/tree/dev", "ssh://git@github.com/me/fork"])
def test_a_repository_page_or_ssh_address_is_refused_naming_the_accepted_form(url, tmp_path):
    cfg = yaml.safe_load((ROOT / "_config.yml").read_text())
    cfg["repository"]["url"] = url
    (tmp_path / "_config.yml").write_text(yaml.safe_dump(cfg))
    with pytest.raises(ValueError, match=r"repository\.url must be .*https://host/owner/repo"):
        launch.course_repository(tmp_path / "_config.yml")


def test_a_clone_address_ending_in_git_gives_web_links_without_it(tmp_path):
    nb = "labs/student/lab1_counterweights.ipynb"
    cfg = yaml.safe_load((ROOT / "_config.yml").read_text())
    for url, source in [("https://github.com/me/fork.git", f"https://github.com/me/fork/blob/dev/{nb}"),
                        ("https://gitlab.com/t/sub/fork.git", f"https://gitlab.com/t/sub/fork/-/blob/dev/{nb}")]:
        cfg["repository"].update(url=url, branch="dev")
        (tmp_path / "_config.yml").write_text(yaml.safe_dump(cfg))
        links = dict(launch.lab_links(nb, tmp_path / "_config.yml"))
        assert links["source"] == source
        assert ".git/" not in links.get("Colab", "") and "fork.git" not in links["Binder"]


def test_setup_cell_is_a_no_op_where_balancelab_imports():
    """Here balancelab imports: the cell runs no pip, touches no Colab module, prints one line."""
    with mock.patch("subprocess.run", side_effect=AssertionError("pip was called")):
        out = io.StringIO()
        with contextlib.redirect_stdout(out):
            exec(launch.setup_source(*UPSTREAM), {})
    assert out.getvalue() == "Set-up: balancelab is installed.\n"


def test_on_colab_with_balancelab_installed_the_cell_only_turns_on_the_widget_manager():
    calls = []
    output = type(sys)("google.colab.output")
    output.enable_custom_widget_manager = lambda: calls.append("on")
    colab = type(sys)("google.colab")
    colab.output = output
    fake = {"google.colab": colab, "google.colab.output": output}
    with mock.patch.dict(sys.modules, fake), mock.patch("subprocess.run", side_effect=AssertionError("pip")):
        out = io.StringIO()
        with contextlib.redirect_stdout(out):
            exec(launch.setup_source(*UPSTREAM), {})
    assert calls == ["on"]
    assert out.getvalue() == "Set-up: balancelab is installed and turned on Colab's widget manager.\n"


def test_without_balancelab_and_off_colab_the_cell_says_how_to_install(tmp_path):
    """A Python without the package (``-I -S``: no site-packages): no install; what is missing and the
    command that installs the package WITH its lab extras (ipywidgets) into a virtual environment."""
    proc = subprocess.run([sys.executable, "-I", "-S", "-c", launch.setup_source(*UPSTREAM)],
                          capture_output=True, text=True, cwd=tmp_path, timeout=60)
    assert proc.returncode == 0, proc.stderr
    assert proc.stdout.startswith("Set-up: balancelab and ipywidgets are not installed here")
    assert f'.venv/bin/python -m pip install "balancelab[labs] @ {launch.install_source(*UPSTREAM)}"' in proc.stdout
    assert "python3 -m venv .venv" in proc.stdout and "labs/README.md" in proc.stdout
    assert "pick the kernel you installed into" in proc.stdout and "is installed." not in proc.stdout


def _run_cell(source, missing=(), colab=False, pip=None):
    """Run a set-up cell here with the modules ``missing`` hidden and ``subprocess.run`` replaced by ``pip``."""
    real = importlib.util.find_spec
    calls = []
    output = type(sys)("google.colab.output")
    output.enable_custom_widget_manager = lambda: calls.append("widgets on")
    colab_mod = type(sys)("google.colab")
    colab_mod.output = output
    fake = {"google.colab": colab_mod, "google.colab.output": output} if colab else {}

    def run(args, **kw):
        calls.append((args, kw))
        return pip(args, **kw)

    with mock.patch.dict(sys.modules, fake), \
            mock.patch("importlib.util.find_spec", lambda name, *a: None if name in missing else real(name, *a)), \
            mock.patch("subprocess.run", run if pip else mock.Mock(side_effect=AssertionError("pip"))):
        out = io.StringIO()
        with contextlib.redirect_stdout(out):
            exec(source, {})
    return out.getvalue(), calls


def test_balancelab_without_ipywidgets_is_not_reported_installed():
    """B1: 'installed' only when ipywidgets imports too; otherwise what is missing and the [labs] command."""
    for handout, command in [(False, f'"balancelab[labs] @ {launch.install_source(*UPSTREAM)}"'),
                             (True, '"./package[labs]"')]:
        out, calls = _run_cell(launch.setup_source(*UPSTREAM, handout=handout), missing=("ipywidgets",))
        assert out.startswith("Set-up: ipywidgets is not installed here") and calls == []
        assert f".venv/bin/python -m pip install {command}" in out and "is installed." not in out


def test_on_colab_a_missing_ipywidgets_is_installed_with_a_timeout():
    def pip(args, **kw):
        return subprocess.CompletedProcess(args, 0, "", "")
    out, calls = _run_cell(launch.setup_source(*UPSTREAM), missing=("ipywidgets",), colab=True, pip=pip)
    (args, kw), on = calls
    assert args[-1] == "ipywidgets" and launch.install_source(*UPSTREAM) not in args   # balancelab is there
    assert args[args.index("--timeout") + 1] == "60" and 0 < kw["timeout"] <= 900 and on == "widgets on"


def test_on_colab_a_pip_that_hangs_stops_with_a_clear_message():
    def pip(args, **kw):
        raise subprocess.TimeoutExpired(args, kw["timeout"])
    with pytest.raises(RuntimeError, match=r"pip could not install git\+.* within 15 minutes: check the connection"):
        _run_cell(launch.setup_source(*UPSTREAM), missing=("balancelab",), colab=True, pip=pip)


def test_on_colab_pips_error_is_shown_without_colour_codes():
    def pip(args, **kw):
        return subprocess.CompletedProcess(args, 1, "", "\x1b[1;31mERROR:\x1b[0m repository \x1b[33mnot found\x1b[0m")
    with pytest.raises(RuntimeError) as err:
        _run_cell(launch.setup_source(*UPSTREAM), missing=("balancelab",), colab=True, pip=pip)
    assert str(err.value).endswith("ERROR: repository not found") and "\x1b" not in str(err.value)


def test_handout_notebooks_advise_the_handouts_own_install_line(tmp_path):
    """B1: a hand-out notebook names ./package[labs] and the hand-out's README.md, not a git install of main."""
    out = labtools.handout(tmp_path / "handout")
    readme = (out / "README.md").read_text(encoding="utf-8")
    for path in sorted((out / "labs").glob("*.ipynb")):
        cell = _code_cells(nbformat.read(path, as_version=4))[0]
        assert cell.source == launch.setup_source(*UPSTREAM, handout=True), path.name
    proc = subprocess.run([sys.executable, "-I", "-S", "-c", cell.source], capture_output=True, text=True,
                          cwd=tmp_path, timeout=60)
    command = '.venv/bin/python -m pip install "./package[labs]"'
    assert command in proc.stdout and command in readme
    assert "README.md at the top of the hand-out" in proc.stdout and "labs/README.md" not in proc.stdout
    assert "pick the kernel you installed into" in proc.stdout and "git+" not in proc.stdout


LAPTOP_TEXTS = {"hand-out README": launch.STUDENT_README, "labs page": launch.LAPTOP_STEPS,
                "labs/README.md": (ROOT / "labs" / "README.md").read_text(encoding="utf-8").split(
                    "## For students")[1].split("\n## ")[0]}


@pytest.mark.parametrize("where", LAPTOP_TEXTS)
def test_laptop_steps_work_on_a_pep668_system_without_python(where):
    """B2: a venv is required (python3, py on Windows, apt's python3-venv), pip runs as .venv's python."""
    text = LAPTOP_TEXTS[where]
    for words in ("python3 -m venv .venv", "py -m venv .venv", "apt install python3-venv",
                  '.venv/bin/python -m pip install "./package[labs]"', ".venv\\Scripts\\python -m pip install",
                  "VS Code", ".venv", "JupyterLab"):
        assert words in text, words
    commands = [ln.strip() for ln in text.splitlines() if ln.strip()]
    assert not any(ln.startswith(("pip ", "python ", "source ")) for ln in commands), commands
    assert "# optional" not in text   # the venv was marked optional


def test_jupyterhub_requirements_are_documented_for_instructors():
    """B3: the hub image needs nbgitpuller, balancelab[labs] and jupytext (README and labs README)."""
    publishing = (ROOT / "README.md").read_text(encoding="utf-8").split("## Publishing")[1].split("\n## ")[0]
    labs = (ROOT / "labs" / "README.md").read_text(encoding="utf-8").split("## For instructors")[1].split("\n## ")[0]
    for text in (publishing, labs):
        for words in ("nbgitpuller", "balancelab[labs]", "jupytext", "jupyterhub_url"):
            assert words in text, words


def test_graded_student_notebook_runs_the_setup_cell_as_a_no_op(tmp_path):
    """The grader runs the untouched student version (sandbox, no network): the set-up cell does nothing."""
    nb = nbformat.read(STUDENT / "lab1_counterweights.ipynb", as_version=4)
    nb.cells = nb.cells[:nb.cells.index(_code_cells(nb)[0]) + 1]
    path = tmp_path / "lab1.ipynb"
    nbformat.write(nb, path)
    ran = labtools.execute_notebook(path, write=False)
    assert _text(_code_cells(ran)[0]) == "Set-up: balancelab is installed.\n"


# ------------------------------------------------------------------ launch links


def _query(url):
    parts = urlsplit(url)
    return parts, {k: v[0] for k, v in parse_qs(parts.query, strict_parsing=True).items()}


def _nbgitpuller_target(repo: str) -> str:
    """nbgitpuller's default clone folder (nbgitpuller/handlers.py: ``repo.rstrip('/').split('/')[-1]``)."""
    return repo.rstrip("/").split("/")[-1]


@pytest.mark.parametrize("repo", ["https://github.com/balancelab/balancelab", "https://github.com/me/fork.git",
                                  "https://gitlab.com/teach/sub/course", "https://git.uni.edu/course"])
def test_nbgitpuller_links_pull_the_repository_and_open_the_lab_in_jupyterlab(repo):
    nb = "labs/student/lab1_counterweights.ipynb"
    url = launch.nbgitpuller_url("https://hub.uni.edu/jhub/", repo, "main", nb)
    parts, q = _query(url)
    assert (parts.scheme, parts.netloc, parts.path) == ("https", "hub.uni.edu", "/jhub/hub/user-redirect/git-pull")
    assert q == {"repo": repo, "branch": "main", "urlpath": f"lab/tree/{_nbgitpuller_target(repo)}/{nb}"}
    assert (ROOT / nb).exists()


@settings(max_examples=60, deadline=None)
@given(branch=st.from_regex(r"[A-Za-z0-9._/-]{1,30}", fullmatch=True),
       name=st.from_regex(r"[A-Za-z0-9 _+&#%?=-]{1,20}", fullmatch=True))
def test_links_carry_any_branch_and_file_name_intact(branch, name):
    """Quoting round-trips: '&', '#', '?', '%' and spaces in a file name or '/' in a branch survive."""
    repo, nb = "https://github.com/o/r", f"labs/student/{name}.ipynb"
    _, q = _query(launch.nbgitpuller_url("https://hub.example.edu", repo, branch, nb))
    assert (q["repo"], q["branch"], q["urlpath"]) == (repo, branch, f"lab/tree/r/{nb}")
    parts, q = _query(launch.binder_url("https://mybinder.org", repo, branch, nb))
    assert unquote(parts.path) == f"/v2/gh/o/r/{branch}" and q == {"urlpath": f"lab/tree/{nb}"}
    colab = urlsplit(launch.colab_url(repo, branch, nb))
    assert unquote(colab.path) == f"/github/o/r/blob/{branch}/{nb}" and not colab.query and not colab.fragment


def test_binder_links_for_github_gitlab_and_any_git_server():
    nb = "labs/student/lab2_zfl_springs_and_levers.ipynb"
    cases = {"https://github.com/o/r": "/v2/gh/o/r/main",
             "https://gitlab.com/group/sub/r": "/v2/gl/group%2Fsub%2Fr/main",
             "https://git.uni.edu/r.git": "/v2/git/https%3A%2F%2Fgit.uni.edu%2Fr.git/main"}
    for repo, path in cases.items():
        parts, q = _query(launch.binder_url("https://mybinder.org/", repo, "main", nb))
        assert parts.netloc == "mybinder.org" and parts.path == path and q == {"urlpath": f"lab/tree/{nb}"}
    assert launch.colab_url("https://gitlab.com/group/r", "main", nb) is None   # Colab opens GitHub only


def test_lab_links_follow_the_configuration(tmp_path):
    """No hub configured: no JupyterHub link; a hub configured: an nbgitpuller link per lab."""
    nb = "labs/student/lab1_counterweights.ipynb"
    assert [n for n, _ in launch.lab_links(nb)] == ["Binder", "Colab", "source"]
    cfg = yaml.safe_load((ROOT / "_config.yml").read_text())
    cfg["launch_buttons"]["jupyterhub_url"] = "https://hub.uni.edu"
    cfg["repository"].update(url="https://github.com/me/fork", branch="term2")
    (tmp_path / "_config.yml").write_text(yaml.safe_dump(cfg))
    links = dict(launch.lab_links(nb, tmp_path / "_config.yml"))
    assert list(links) == ["Binder", "Colab", "JupyterHub", "source"]
    assert links["JupyterHub"] == launch.nbgitpuller_url("https://hub.uni.edu", "https://github.com/me/fork",
                                                         "term2", nb)
    assert all("me/fork" in u or "me%2Ffork" in u for u in links.values())
    assert links["Colab"].endswith(f"/github/me/fork/blob/term2/{nb}")
    cfg["launch_buttons"]["jupyterhub_url"] = "hub.uni.edu"
    (tmp_path / "_config.yml").write_text(yaml.safe_dump(cfg))
    with pytest.raises(ValueError, match="jupyterhub_url"):
        launch.lab_links(nb, tmp_path / "_config.yml")


@pytest.mark.parametrize("hub", ["https://hub.example.edu", "https://hub.example.edu/", "https://hub.example.edu/hub",
                                 "https://hub.example.edu/hub/"])
def test_a_hub_address_ending_in_hub_gives_no_double_hub(hub):
    url = launch.nbgitpuller_url(hub, "https://github.com/o/r", "main", "labs/a.ipynb")
    assert urlsplit(url).path == "/hub/user-redirect/git-pull"


def test_labs_page_names_only_the_ways_it_links(tmp_path):
    """A GitLab fork gets no Colab link, so the page does not offer Colab (Binder is the quickest start)."""
    cfg = yaml.safe_load((ROOT / "_config.yml").read_text())
    cfg["repository"].update(url="https://gitlab.com/teach/course", branch="main")
    (tmp_path / "_config.yml").write_text(yaml.safe_dump(cfg))
    text = launch.ways_text(tmp_path / "_config.yml")
    assert "Colab" not in text and text.splitlines()[0].startswith("- **Binder**") and "quickest start" in text
    assert "JupyterHub" not in text
    cfg["launch_buttons"].update(binderhub_url="", jupyterhub_url="https://hub.uni.edu")
    (tmp_path / "_config.yml").write_text(yaml.safe_dump(cfg))
    text = launch.ways_text(tmp_path / "_config.yml")
    assert text.splitlines()[0].startswith("- **JupyterHub**") and "quickest start" in text
    assert "Binder" not in text and "Colab" not in text and "laptop" in text
    first = launch.ways_text().splitlines()[0]
    assert first.startswith("- **Colab**") and "quickest start" in first       # upstream: GitHub, Colab first


def test_labs_page_builds_its_links_from_the_library():
    """book/labs.md lists each lab's links through balancelab.course.launch (one place, tested here)."""
    page = (ROOT / "book" / "labs.md").read_text(encoding="utf-8")
    assert "from balancelab.course.launch import lab_links" in page
    assert "ways_text(CONFIG)" in page and "Markdown(LAPTOP_STEPS)" in page and "quickest" not in page
    text = page + launch.ways_text() + launch.LAPTOP_STEPS
    for word in ("Colab", "Binder", "JupyterHub", "VS Code", "JupyterLab"):
        assert word in text, word


# ------------------------------------------------------------------ Binder (repo2docker)


def test_binder_folder_follows_repo2docker_conventions():
    """repo2docker reads only binder/ (none of the root's files) and runs pip from the repository root."""
    assert BINDER.is_dir() and not (ROOT / ".binder").exists()   # both: repo2docker refuses to build
    lines = [ln.split("#", 1)[0].strip() for ln in (BINDER / "requirements.txt").read_text().splitlines()]
    lines = [ln for ln in lines if ln]
    constraints = [ln.split(None, 1)[1] for ln in lines if ln.startswith("-c ")]
    assert constraints and all((BINDER / c).resolve() == CONSTRAINTS for c in constraints)  # -c: relative to the file
    local = [ln for ln in lines if ln.startswith(".")]
    assert local == [".[book,labs]"]                     # "." : the repository root, pip's working directory
    tomllib = pytest.importorskip("tomllib")
    optional = tomllib.loads((ROOT / "pyproject.toml").read_text())["project"]["optional-dependencies"]
    extras = re.findall(r"\[(.*)\]", local[0])[0].split(",")
    assert all(e in optional for e in extras)
    assert any(r.startswith("jupytext") for e in extras for r in optional[e])   # chapters open as notebooks
    runtime = (BINDER / "runtime.txt").read_text().strip()
    assert re.fullmatch(r"python-3\.\d+", runtime)
    version = tuple(int(p) for p in runtime.split("-")[1].split("."))
    assert version >= (3, 10)                             # pyproject's requires-python
    mode = subprocess.run(["git", "ls-files", "-s", "binder/postBuild"], cwd=ROOT, capture_output=True,
                          text=True).stdout.split()
    assert os.access(BINDER / "postBuild", os.X_OK) and (not mode or mode[0] == "100755")


def test_postbuild_makes_jupyterlab_open_chapters_as_notebooks(tmp_path):
    """Run binder/postBuild as repo2docker does, then read the settings the way JupyterLab does."""
    env = {k: v for k, v in os.environ.items() if not k.startswith("JUPYTER")}
    env.update(HOME=str(tmp_path), PATH=f"{Path(sys.executable).parent}{os.pathsep}{env['PATH']}")
    proc = subprocess.run(["./binder/postBuild"], cwd=ROOT, env=env, capture_output=True, text=True, timeout=120)
    assert proc.returncode == 0, proc.stderr
    code = ("import json; from jupyterlab_server.settings_utils import _get_overrides; "
            "print(json.dumps(_get_overrides('/nonexistent')[0]))")
    read = subprocess.run([sys.executable, "-c", code], env=env, capture_output=True, text=True, timeout=120)
    viewers = json.loads(read.stdout)["@jupyterlab/docmanager-extension:plugin"]["defaultViewers"]
    assert viewers["markdown"] == viewers["myst"] == "Jupytext Notebook"
    # that viewer is the one jupytext's JupyterLab extension registers, and it reads every chapter
    ext = Path(sys.prefix, "share", "jupyter", "labextensions", "jupyterlab-jupytext")
    assert any("Jupytext Notebook" in f.read_text(errors="replace") for f in ext.rglob("*.js"))
    import jupytext

    for chapter in sorted((ROOT / "book").glob("ch*.md")):
        assert sum(c.cell_type == "code" for c in jupytext.read(chapter).cells) >= 1, chapter


@pytest.mark.slow
def test_repo2docker_plans_the_build_from_the_repository_root(tmp_path):
    """repo2docker's own code (in a throw-away venv) picks the Python build pack, Python of runtime.txt,
    installs binder/requirements.txt after copying the whole repository, then runs postBuild; and pip
    resolves that requirements file from the repository root with the pinned versions."""
    venv = _venv(tmp_path / "r2d", "jupyter-repo2docker", constrained=False)
    plan = textwrap.dedent("""
        import json
        from repo2docker.app import Repo2Docker
        app = Repo2Docker()
        for B in app.buildpacks:
            bp = B(base_image=app.base_image)
            bp.platform = "linux/amd64"
            if bp.detect():
                break
        print(json.dumps({"pack": B.__name__, "python": bp.python_version, "dockerfile": bp.render()}))
    """)
    out = subprocess.run([str(venv / "bin" / "python"), "-c", plan], cwd=ROOT, capture_output=True, text=True,
                         timeout=120)
    assert out.returncode == 0, out.stderr[-3000:]
    got = json.loads(out.stdout)
    assert got["pack"] == "PythonBuildPack"
    assert got["python"] == (BINDER / "runtime.txt").read_text().strip().split("-")[1]
    steps = [ln for ln in got["dockerfile"].splitlines() if ln.startswith(("COPY", "RUN", "WORKDIR"))]
    copy_all = steps.index("COPY --chown=1000:1000 src/ ${REPO_DIR}/")
    install = steps.index('RUN ${KERNEL_PYTHON_PREFIX}/bin/pip install --no-cache-dir -r "binder/requirements.txt"')
    post = steps.index("RUN ./binder/postBuild")
    assert "WORKDIR ${REPO_DIR}" in steps[:copy_all] and copy_all < install < post
    if f"{sys.version_info.major}.{sys.version_info.minor}" != got["python"]:
        pytest.skip(f"pip resolution checked only with Python {got['python']} (this is {sys.version.split()[0]})")
    report = tmp_path / "report.json"
    pip = subprocess.run([sys.executable, "-m", "pip", "install", "--dry-run", "--ignore-installed", "--quiet",
                          "--report", str(report), "-r", "binder/requirements.txt"],
                         cwd=ROOT, capture_output=True, text=True, timeout=600)
    assert pip.returncode == 0, pip.stderr[-3000:]
    names = {i["metadata"]["name"].lower() for i in json.loads(report.read_text())["install"]}
    assert {"balancelab", "jupytext", "ipywidgets", "jupyterlab", "jupyter-book"} <= names


# ------------------------------------------------------------------ fresh virtual environments


def _venv(where: Path, *packages: str, constrained: bool = True) -> Path:
    """A new virtual environment with ``packages`` (pinned by constraints.txt unless told)."""
    subprocess.run([sys.executable, "-m", "venv", str(where)], check=True, timeout=120)
    if packages:
        extra = ["-c", str(CONSTRAINTS)] if constrained else []
        proc = subprocess.run([str(where / "bin" / "python"), "-m", "pip", "install", "--quiet", *extra, *packages],
                              capture_output=True, text=True, timeout=900)
        assert proc.returncode == 0, proc.stderr[-3000:]
    return where


_RUN = textwrap.dedent("""
    import sys, nbformat
    from nbclient import NotebookClient
    nb = nbformat.read(sys.argv[1], as_version=4)
    NotebookClient(nb, timeout=600, kernel_name="python3").execute()
    nbformat.write(nb, sys.argv[2])
""")


def _run_in(venv: Path, nb, tmp_path: Path, env: dict, name: str):
    """Run ``nb`` top to bottom in a kernel of ``venv``; the executed notebook."""
    src, out = tmp_path / f"{name}.ipynb", tmp_path / f"{name}.out.ipynb"
    nbformat.write(nb, src)
    proc = subprocess.run([str(venv / "bin" / "python"), "-c", _RUN, str(src), str(out)], cwd=tmp_path, env=env,
                          capture_output=True, text=True, timeout=900)
    assert proc.returncode == 0, proc.stderr[-4000:]
    return nbformat.read(out, as_version=4)


def _up_to_first_explorer(nb):
    explorer = next(i for i, c in enumerate(nb.cells) if c.cell_type == "code" and c.source.rstrip().endswith(".widget"))
    nb.cells = nb.cells[:explorer + 1]
    return nb


def _clean_env(**extra) -> dict:
    env = {k: v for k, v in os.environ.items() if k not in ("PYTHONPATH", "VIRTUAL_ENV", "PYTHONHOME")}
    env.update(MPLBACKEND="Agg", PIP_CONSTRAINT=str(CONSTRAINTS), **extra)
    return env


def _snapshot_repository(where: Path) -> str:
    """A git repository holding this checkout as it is now (committed or not): a fork's stand-in."""
    files = subprocess.run(["git", "ls-files", "-z", "-co", "--exclude-standard"], cwd=ROOT, capture_output=True,
                           check=True).stdout.decode().split("\0")
    for f in filter(None, files):
        if (ROOT / f).is_file():
            (where / f).parent.mkdir(parents=True, exist_ok=True)
            (where / f).write_bytes((ROOT / f).read_bytes())
    git = ["git", "-c", "user.name=test", "-c", "user.email=test@example.org", "-c", "commit.gpgsign=false"]
    for cmd in (["init", "-q", "-b", "main"], ["add", "-A"], ["commit", "-q", "-m", "snapshot"]):
        subprocess.run(git + cmd, cwd=where, check=True, capture_output=True, timeout=120)
    return where.as_uri()


FAKE_COLAB = """\
import os
from pathlib import Path


def enable_custom_widget_manager():
    Path(os.environ["FAKE_COLAB_LOG"]).open("a").write("widget manager on\\n")
"""


@pytest.mark.slow
def test_colab_simulated_installs_the_course_and_runs_a_lab_to_its_first_explorer(tmp_path):
    """A fresh venv with Colab's preinstalled stack and a fake ``google.colab`` imported at start-up;
    the notebook's install address is a git repository of this checkout (file://)."""
    repo = _snapshot_repository(tmp_path / "fork")
    venv = _venv(tmp_path / "colab", "ipykernel", "ipywidgets", "numpy", "scipy", "sympy", "matplotlib",
                 "nbclient", "nbformat")
    fake = tmp_path / "fake"
    (fake / "google" / "colab").mkdir(parents=True)
    (fake / "google" / "colab" / "__init__.py").write_text("")
    (fake / "google" / "colab" / "output.py").write_text(FAKE_COLAB)
    (fake / "sitecustomize.py").write_text("import google.colab  # Colab's kernel has it imported\n")
    log = tmp_path / "colab.log"
    colab_env = _clean_env(PYTHONPATH=str(fake), FAKE_COLAB_LOG=str(log))
    python = str(venv / "bin" / "python")

    # 1. not on Colab, no balancelab: one line saying how to install, nothing installed
    cell = launch.setup_source(repo, "main")
    plain = subprocess.run([python, "-c", cell], env=_clean_env(), capture_output=True, text=True, timeout=60,
                           cwd=tmp_path)   # not the checkout: "python -c" imports from its working directory
    assert plain.returncode == 0 and plain.stdout.startswith("Set-up: balancelab is not installed here (")
    # 2. on Colab with an address that does not exist: the cell fails and says what pip said
    bad = subprocess.run([python, "-c", launch.setup_source(repo + "-missing", "main")], env=colab_env,
                         capture_output=True, text=True, timeout=300, cwd=tmp_path)
    assert bad.returncode != 0 and f"pip could not install git+{repo}-missing@main" in bad.stderr
    assert not log.exists()

    # 3. on Colab: the student version of lab 1 (set-up cell pointing at the fork) up to its first explorer
    nb = nbformat.reads(labtools.student_text(ROOT / "labs" / "solutions" / "lab1_counterweights.ipynb",
                                              repository=(repo, "main")), as_version=4)
    ran = _run_in(venv, _up_to_first_explorer(nb), tmp_path, colab_env, "colab")
    code = _code_cells(ran)
    assert _text(code[0]) == f"Set-up: installed balancelab from git+{repo}@main and turned on Colab's widget manager.\n"
    assert log.read_text() == "widget manager on\n"
    assert any(labtools.WIDGET_MIME in o.get("data", {}) for o in code[-1].outputs)
    where = subprocess.run([python, "-c", "import balancelab; print(balancelab.__file__)"], env=_clean_env(),
                           capture_output=True, text=True, cwd=tmp_path, timeout=60).stdout
    assert where.startswith(str(venv)), where     # installed from the fork, not imported from this checkout

    # 4. run again (a restarted Colab runtime): nothing installed, the widget manager turned on again
    again = _run_in(venv, nbformat.v4.new_notebook(cells=[code[0]]), tmp_path, colab_env, "again")
    assert _text(again.cells[0]) == "Set-up: balancelab is installed and turned on Colab's widget manager.\n"


@pytest.mark.slow
def test_handout_installs_in_a_fresh_venv_with_its_one_line_and_runs_a_lab(tmp_path):
    """The hand-out alone (no repository around it): its README's pip line, then a lab to its first explorer."""
    out = labtools.handout(tmp_path / "handout")
    readme = (out / "README.md").read_text(encoding="utf-8")
    lines = [ln.strip() for ln in readme.splitlines() if ln.strip().startswith(".venv/bin/python -m pip install ")]
    assert len(lines) == 1, lines
    for words in ("jupyter lab labs/", "VS Code", "Select Kernel", "Jupyter"):   # the venv: at tmp_path/laptop
        assert words in readme, words
    venv = _venv(tmp_path / "laptop")
    env = _clean_env(PATH=f"{venv / 'bin'}{os.pathsep}{os.environ['PATH']}", VIRTUAL_ENV=str(venv))
    proc = subprocess.run(lines[0].replace(".venv/bin/python", str(venv / "bin" / "python")), shell=True, cwd=out, env=env, capture_output=True, text=True, timeout=900)
    assert proc.returncode == 0, proc.stderr[-3000:]
    lab = subprocess.run([str(venv / "bin" / "jupyter"), "lab", "--version"], env=env, capture_output=True,
                         text=True, timeout=120)
    assert lab.returncode == 0 and lab.stdout.startswith("4."), lab.stdout + lab.stderr
    nb = nbformat.read(out / "labs" / "lab1_counterweights.ipynb", as_version=4)
    ran = _run_in(venv, _up_to_first_explorer(nb), out / "labs", env, "lab1_run")
    code = _code_cells(ran)
    assert _text(code[0]) == "Set-up: balancelab is installed.\n"
    assert any(labtools.WIDGET_MIME in o.get("data", {}) for o in code[-1].outputs)
    where = subprocess.run([str(venv / "bin" / "python"), "-c", "import balancelab; print(balancelab.__file__)"],
                           env=env, capture_output=True, text=True, cwd=tmp_path, timeout=60).stdout
    assert where.startswith(str(venv)), where


@pytest.mark.slow
@pytest.mark.browser
@NEEDS_CHROMIUM
def test_binder_opens_a_chapter_as_a_notebook_in_jupyterlab(tmp_path):
    """After binder/postBuild, JupyterLab (in Debian chromium) opens a chapter's .md, the file a
    chapter's Binder button names, as a notebook with code cells, not as text."""
    from playwright.sync_api import sync_playwright

    (tmp_path / "book").mkdir()
    chapter = "book/ch1_counterweights.md"
    (tmp_path / chapter).write_text((ROOT / chapter).read_text(encoding="utf-8"), encoding="utf-8")
    env = {k: v for k, v in os.environ.items() if not k.startswith("JUPYTER")}
    env.update(HOME=str(tmp_path), JUPYTER_CONFIG_DIR=str(tmp_path / ".jupyter"),
               JUPYTER_RUNTIME_DIR=str(tmp_path / ".runtime"),
               PATH=f"{Path(sys.executable).parent}{os.pathsep}{env['PATH']}")
    post = subprocess.run(["./binder/postBuild"], cwd=ROOT, env=env, capture_output=True, text=True, timeout=120)
    assert post.returncode == 0, post.stderr
    port, token = free_port(), secrets.token_hex(16)
    cmd = [sys.executable, "-m", "jupyter", "lab", "--no-browser", "--ServerApp.ip=127.0.0.1",
           "--ServerApp.allow_root=True", "--LabApp.extension_manager=readonly", f"--ServerApp.port={port}",
           "--ServerApp.port_retries=0", f"--IdentityProvider.token={token}", f"--ServerApp.root_dir={tmp_path}",
           "--LabApp.news_url=", "--LabApp.check_for_updates_class=jupyterlab.NeverCheckForUpdate",
           f"--LabApp.user_settings_dir={tmp_path / '.settings'}", f"--LabApp.workspaces_dir={tmp_path / '.ws'}"]
    with open(tmp_path / "server.log", "w") as log:
        proc = subprocess.Popen(cmd, cwd=tmp_path, env=env, stdout=log, stderr=subprocess.STDOUT)
        try:
            url = f"http://127.0.0.1:{port}"
            for _ in range(240):
                try:
                    with urllib.request.urlopen(f"{url}/api/status?token={token}", timeout=2):
                        break
                except OSError:
                    assert proc.poll() is None, (tmp_path / "server.log").read_text()[-2000:]
                    time.sleep(0.5)
            else:
                pytest.fail("JupyterLab did not answer within 120 s: " + (tmp_path / "server.log").read_text()[-2000:])
            with sync_playwright() as pw:
                browser = pw.chromium.launch(executable_path=CHROMIUM, headless=True, args=CHROMIUM_ARGS)
                try:
                    page = browser.new_page(viewport={"width": 1280, "height": 900})
                    page.goto(f"{url}/lab/tree/{chapter}?token={token}")
                    # one condition, read at one instant: JupyterLab may re-render the panel between two
                    # separate reads (a cell found by the wait was gone for the count under load)
                    page.wait_for_function("""() => document.querySelectorAll(
                        ".jp-NotebookPanel .jp-CodeCell").length >= 1
                        && document.querySelectorAll(".jp-FileEditor").length === 0""", timeout=120_000)
                finally:
                    browser.close()
        finally:
            proc.terminate()
            try:
                proc.wait(timeout=20)
            except subprocess.TimeoutExpired:
                proc.kill()
