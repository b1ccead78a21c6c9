"""The course book: it builds with every chapter executed and warnings as errors, fails when a
cell raises or a reference is broken, and works offline in a real browser.

Slow: the module builds the whole site once (forced execution). Set
``BALANCELAB_BOOK_PREBUILT=1`` to test an existing ``_build/html`` instead (for working on the
tests themselves). The browser part needs Debian's ``chromium`` (installed by
``scripts/setup_extras.sh``) and drives it through Python playwright.
"""
from __future__ import annotations

import fcntl
import functools
import html
import http.server
import os
import re
import shutil
import subprocess
import sys
import threading
from pathlib import Path
from urllib.parse import unquote, urljoin, urlsplit

import pytest
import yaml

from conftest import build_mini_book

ROOT = Path(__file__).resolve().parents[1]
SITE = ROOT / "_build" / "html"
SHOTS = ROOT / "_build" / "screenshots"
pytestmark = pytest.mark.slow

CHAPTERS = ["intro", "notation", "ch1_counterweights", "ch2_zfl_springs", "ch3_building_zfl",
            "ch4_serial", "ch5_fourbar", "ch6_scissors_peaucellier", "ch7_your_own_linkage",
            "ch8_ideal_to_real", "ch9_noncircular", "labs", "schedule", "problem_bank", "notes_on_sources", "references",
            "accessibility"]
NOTEBOOKS = [c for c in CHAPTERS if c.startswith("ch")] + ["labs"]
REMOTE = re.compile(r"""<(?:script|img|iframe|link)\b[^>]*?\b(?:src|href)\s*=\s*["'](?:https?:)?//[^"']*""",
                    re.IGNORECASE)


def _toc_files() -> list[str]:
    toc = yaml.safe_load((ROOT / "_toc.yml").read_text())
    files = [toc["root"]]
    for part in toc.get("parts", []):
        files += [c["file"] for c in part.get("chapters", [])]
    return files


@pytest.fixture(scope="module")
def site() -> Path:
    """The site, built with every notebook re-executed and warnings as errors."""
    if os.environ.get("BALANCELAB_BOOK_PREBUILT") == "1" and (SITE / "index.html").is_file():
        return SITE
    # One build per test run, whichever worker gets here first: pytest-xdist spread this module's tests
    # over both workers (the group mark did not hold), and two builds raced in _build/html (one's
    # clean-up removed the other's PDF). The others wait on the lock and reuse the build of this run.
    run = os.environ.get("PYTEST_XDIST_TESTRUNUID") or f"pid{os.getpid()}"
    stamp = SITE.parent / "site-test-run.txt"
    SITE.parent.mkdir(exist_ok=True)
    with open(SITE.parent / "site-build.lock", "w") as lock:
        fcntl.flock(lock, fcntl.LOCK_EX)
        if stamp.is_file() and stamp.read_text() == run and (SITE / "index.html").is_file():
            return SITE
        stamp.unlink(missing_ok=True)
        r = subprocess.run([sys.executable, "scripts/build_book.py", "--force", "--quiet"], cwd=ROOT,
                           capture_output=True, text=True, timeout=1800)
        assert r.returncode == 0, f"book build failed:\n{r.stdout[-6000:]}\n{r.stderr[-6000:]}"
        stamp.write_text(run)
    return SITE


# --------------------------------------------------------------------------- the build
# ------------------------------------------------------------------------- publishing
WORKFLOW = ROOT / ".github" / "workflows" / "pages.yml"
GITLAB = ROOT / ".gitlab-ci.yml"
README_COMMANDS = ("bash scripts/course.sh test", "bash scripts/course.sh book")


def test_pages_workflow_runs_the_readme_commands_and_publishes_the_site():
    wf = yaml.safe_load(WORKFLOW.read_text())
    on = wf.get("on", wf.get(True))   # YAML 1.1 reads the key `on` as True
    assert "push" in on and "workflow_dispatch" in on
    assert wf["permissions"] == {"contents": "read", "pages": "write", "id-token": "write"}
    build, deploy = wf["jobs"]["build"], wf["jobs"]["deploy"]
    runs = [step["run"] for step in build["steps"] if "run" in step]
    for command in README_COMMANDS:
        assert command in (ROOT / "README.md").read_text(), command
        assert any(command in r for r in runs), f"the workflow does not run {command!r}"
    uses = {step["uses"].split("@")[0]: step for step in build["steps"] + deploy["steps"] if "uses" in step}
    assert uses["actions/upload-pages-artifact"]["with"]["path"] == "_build/html"
    assert "actions/deploy-pages" in uses and "actions/checkout" in uses
    assert deploy["needs"] == "build" and deploy["environment"]["name"] == "github-pages"
    assert build["timeout-minutes"] <= 90
    gitlab = yaml.safe_load(GITLAB.read_text())["pages"]
    for command in README_COMMANDS:
        assert command in gitlab["script"]
    assert gitlab["artifacts"]["paths"] == ["public"] and any("_build/html public" in c for c in gitlab["script"])


@pytest.mark.parametrize("path, schema", [(".github/workflows/pages.yml", "vendor.github-workflows"),
                                          (".github/workflows/tests.yml", "vendor.github-workflows"),
                                          (".gitlab-ci.yml", "vendor.gitlab-ci")])
def test_ci_files_pass_their_schema_linter(path, schema):
    """check-jsonschema validates against the schema it bundles (offline)."""
    pytest.importorskip("check_jsonschema")
    r = subprocess.run([sys.executable, "-m", "check_jsonschema", "--builtin-schema", schema, str(ROOT / path)],
                       capture_output=True, text=True, timeout=120)
    assert r.returncode == 0, r.stdout + r.stderr


def test_toc_lists_every_chapter_in_order():
    files = _toc_files()
    assert [f.split("/")[-1] for f in files] == CHAPTERS
    for f in files:
        assert (ROOT / f"{f}.md").is_file(), f"{f}.md is in _toc.yml but missing"


def test_config_is_offline_and_strict():
    cfg = yaml.safe_load((ROOT / "_config.yml").read_text())
    assert cfg["only_build_toc_files"] is True
    assert cfg["execute"]["execute_notebooks"] == "cache"
    assert cfg["execute"]["allow_errors"] is False
    sc = cfg["sphinx"]["config"]
    assert not re.match(r"https?://", sc["mathjax_path"])
    assert all(not re.match(r"https?://", k) for k in sc["nb_ipywidgets_js"])
    assert "book/_vendor" in sc["html_extra_path"]
    assert {"sphinx_exercise", "sphinx_proof", "sphinx_togglebutton"} <= set(cfg["sphinx"]["extra_extensions"])
    for nb in NOTEBOOKS:
        head = (ROOT / "book" / f"{nb}.md").read_text().split("---")[1]
        meta = yaml.safe_load(head)
        assert meta["kernelspec"]["name"] == "python3", nb
        assert meta["jupytext"]["text_representation"]["format_name"] == "myst", nb


def test_site_has_every_page_and_its_notebook(site):
    for name in CHAPTERS:
        assert (site / "book" / f"{name}.html").is_file(), name
    for nb in NOTEBOOKS:
        assert (site / "_sources" / "book" / f"{nb}.ipynb").is_file(), f"no .ipynb download for {nb}"
    assert (site / "vendor" / "mathjax" / "tex-chtml.js").is_file()


def test_downloaded_notebooks_are_plain_jupyter_without_solutions(site):
    import nbformat

    for name in NOTEBOOKS:
        nb = nbformat.read(str(site / "_sources" / "book" / f"{name}.ipynb"), as_version=4)
        nbformat.validate(nb)
        text = "\n".join(c.source for c in nb.cells)
        for raw in ("```{", "{cite:", "{numref}`", "{eq}`", "{doc}`", "solution-start", ":::{"):
            assert raw not in text, f"{name}.ipynb still holds raw MyST {raw!r}"
        assert all(not c.get("outputs") for c in nb.cells if c.cell_type == "code"), name
        source = (ROOT / "book" / f"{name}.md").read_text()
        if "solution-start" in source:
            assert "Exercise" in text, name
        assert nb.metadata["kernelspec"]["name"] == "python3"


def test_downloaded_notebooks_have_the_course_title_and_no_raw_labels(site):
    import nbformat

    cfg = yaml.safe_load((ROOT / "_config.yml").read_text())
    labels = set()
    for name in CHAPTERS:
        labels |= set(re.findall(r"^\(([\w:.-]+)\)=", (ROOT / "book" / f"{name}.md").read_text(), re.M))
        labels |= set(re.findall(r":label: ([\w:.-]+)", (ROOT / "book" / f"{name}.md").read_text()))
    for name in NOTEBOOKS:
        nb = nbformat.read(str(site / "_sources" / "book" / f"{name}.ipynb"), as_version=4)
        first = nb.cells[0].source
        assert first.startswith(f"*{cfg['title']}: "), f"{name}.ipynb starts {first[:60]!r}"
        assert "not set" not in first.lower()
        text = "\n".join(c.source for c in nb.cells if c.cell_type == "markdown")
        raw = sorted(lab for lab in labels if re.search(r"(?<![\w-])" + re.escape(lab) + r"(?![\w-])", text))
        assert not raw, f"{name}.ipynb names raw labels: {raw[:8]}"


def test_download_menu_offers_the_notebook_and_the_course_pdf_not_the_source(site):
    assert not list((site / "_sources").rglob("*.md")), "the MyST sources (with solutions) are published"
    for name in NOTEBOOKS:
        text = (site / "book" / f"{name}.html").read_text()
        assert "download-source-button" not in text, name
        assert "window.print()" not in text, name
        assert 'href="../balancelab-course.pdf"' in text, f"{name}: no link to the printable course"
    assert not (site / "genindex.html").exists() and not (site / "prf-prf.html").exists()


def test_the_printable_course_has_every_chapter_its_figures_and_nothing_cut(site):
    """scripts/build_pdf.py (run by the book build) printed the whole course with Chromium."""
    import json

    pypdf = pytest.importorskip("pypdf")
    pdf = site / "balancelab-course.pdf"
    assert pdf.is_file(), "no printable course: scripts/build_pdf.py did not run"
    report = json.loads((site / "balancelab-course.json").read_text())
    assert report["cut"] == [], report["cut"][:10]
    assert [c["page"] for c in report["chapters"]] == CHAPTERS
    reader = pypdf.PdfReader(str(pdf))
    images = sum(len(page.images) for page in reader.pages)
    def titles(items):
        for item in items:
            yield from titles(item) if isinstance(item, list) else [" ".join(item.title.split())]

    outline = list(titles(reader.outline))   # the PDF's bookmarks: one per heading
    for chapter in report["chapters"]:
        title = re.sub(r"^\d+\.\s*", "", " ".join(chapter["title"].split()))   # the number may be a separate mark
        assert title and any(title[:30] in t for t in outline), f"the PDF lacks the chapter {title!r}"
    assert "Solutions" in outline
    for name in ("ch1_counterweights", "ch5_fourbar", "ch8_ideal_to_real"):
        shown = next(c for c in report["chapters"] if c["page"] == name)
        assert shown["images"] >= 2, name
        assert shown["solutions"] >= 1, f"{name}: no solutions at the chapter's end"
    # every figure of the site's pages is in the PDF (an animation shows one frame)
    assert images >= sum(c["images"] for c in report["chapters"]) * 0.9, (images, report["images"])
    assert len(reader.pages) > 40


def test_figures_keep_the_alt_text_their_page_wrote(site):
    for name in NOTEBOOKS:
        source = (ROOT / "book" / f"{name}.md").read_text()
        page = (site / "book" / f"{name}.html").read_text()
        for alt in re.findall(r"^\s+alt: (.+)$", source, re.MULTILINE):
            start = html.escape(" ".join(alt.split())[:40], quote=True)
            assert re.search(r'<img [^>]*alt="(?:panel \d of \d: )?' + re.escape(start), page), \
                f"{name}: no image carries the alt text {alt[:60]!r}"


def test_site_ships_only_assets_some_page_requests(site):
    pages = [p.read_text(errors="replace") for p in site.rglob("*.html") if p.relative_to(site).parts[0] != "vendor"]
    widgets = any("html-manager/embed-amd.js" in text for text in pages)
    # the widget manager and require.js go with the first page that embeds widgets
    assert (site / "vendor" / "html-manager" / "embed-amd.js").is_file() == widgets
    assert (site / "vendor" / "requirejs" / "require.js").is_file() == widgets
    assert not list((site / "_static").rglob("*.map")), "JavaScript source maps are never requested"
    assert not (site / "_static" / "locales").exists()
    # ... but the vendored copy keeps them for pages that will have widgets
    assert (ROOT / "book" / "_vendor" / "vendor" / "html-manager" / "embed-amd.js").is_file()
    # no second copy of what MathJax's combined file holds, no icon font older than WOFF2
    sys.path.insert(0, str(ROOT / "book" / "_ext"))
    import site_chrome

    bundle = (site / "vendor" / "mathjax" / "tex-chtml.js").read_text()
    preloaded = " ".join(re.findall(r"preLoad\(([^)]*)\)", bundle))
    for name in site_chrome.MATHJAX_BUNDLED:
        assert not (site / "vendor" / "mathjax" / name).exists(), name
        component = name[:-3] if not name.startswith("output/chtml/fonts") else name
        component = re.sub(r"^input/tex/extensions/", "[tex]/", component)
        assert f'"{component}"' in preloaded, f"{name} is not in tex-chtml.js: MathJax would fetch it"
    legacy = [p.name for p in (site / "vendor").rglob("*") if p.suffix[1:] in site_chrome.LEGACY_FONTS
              and "html-manager" in p.parts]
    assert not legacy, legacy


def _scripts_module(name: str):
    import importlib.util

    spec = importlib.util.spec_from_file_location(name, ROOT / "scripts" / f"{name}.py")
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def test_bookmark_titles_chromium_doubles_are_written_once():
    """The CI build's outline read "SolutionsSolutions" and "3.1. 3.1. Initial tension…Initial
    tension…" (Chromium's tagged outline repeats a heading's text runs at times)."""
    sys.path.insert(0, str(ROOT / "scripts"))
    from build_pdf import undouble

    assert undouble("SolutionsSolutions") == "Solutions"
    assert undouble("3.1. 3.1. Initial tension: how far it goesInitial tension: how far it goes") == \
        "3.1. Initial tension: how far it goes"
    for title in ("3.2. A string over a pulley", "1.1. Why balance?", "Notation and conventions", "2.6.1. eqs 4–8"):
        assert undouble(title) == title


def test_the_printed_course_is_shrunk_without_changing_a_pixel_and_keeps_its_bookmarks(tmp_path):
    """scripts/build_pdf.shrink_pdf: an RGB picture of few colours comes back pixel for pixel
    (indexed), an opaque alpha mask goes, the structure tree goes, the outline stays."""
    import numpy as np
    from matplotlib.figure import Figure
    from pypdf import PdfReader, PdfWriter
    from pypdf.generic import DictionaryObject, NameObject

    build_pdf = _scripts_module("build_pdf")
    rng = np.random.default_rng(20)
    colours = rng.integers(0, 256, size=(40, 3), dtype=np.uint8)
    pixels = colours[rng.integers(0, 40, size=(60, 90))]
    fig = Figure(figsize=(3, 2))
    fig.figimage(pixels)
    raw = tmp_path / "raw.pdf"
    fig.savefig(raw, format="pdf")
    writer = PdfWriter(clone_from=PdfReader(str(raw)))
    writer.add_outline_item(title="Chapter one", page_number=0)
    writer._root_object[NameObject("/StructTreeRoot")] = writer._add_object(
        DictionaryObject({NameObject("/Type"): NameObject("/StructTreeRoot")}))
    printed = tmp_path / "course.pdf"
    with open(printed, "wb") as f:
        writer.write(f)

    before, after = build_pdf.shrink_pdf(printed)
    reader = PdfReader(str(printed))
    assert "/StructTreeRoot" not in reader.trailer["/Root"]
    assert [item.title for item in reader.outline] == ["Chapter one"]
    (image,) = reader.pages[0].images
    assert image.indirect_reference.get_object()["/ColorSpace"][0] == "/Indexed"
    assert np.array_equal(np.asarray(image.image.convert("RGB")), pixels)
    assert after < before


def test_launch_buttons_open_only_what_they_can(site):
    cfg = yaml.safe_load((ROOT / "_config.yml").read_text())
    hub = cfg["launch_buttons"].get("jupyterhub_url") or ""
    for name in NOTEBOOKS:
        text = (site / "book" / f"{name}.html").read_text()
        assert "mybinder.org/v2/gh/" in text, f"{name}: no Binder button"
        # Colab cannot open a MyST page: no Colab button on a chapter
        assert "colab.research.google.com" not in text or name == "labs", f"{name}: a Colab button"
        assert ("hub/user-redirect" in text) == bool(hub), f"{name}: a JupyterHub button without a hub"
        assert "&amp;amp;" not in text, f"{name}: a link escaped twice"
    labs = (site / "book" / "labs.html").read_text()
    links = [html.unescape(h) for h in re.findall(r'href="([^"]*labs(?:/|%2F)student[^"]*)"', labs)]
    n = len(list((ROOT / "labs" / "student").glob("*.ipynb")))   # one link of each kind per lab
    assert n >= 8
    assert sum("mybinder.org/v2/gh/" in h for h in links) == n, links
    assert sum(h.startswith("https://colab.research.google.com/github/") for h in links) == n, links
    assert sum("hub/user-redirect" in h for h in links) == (n if hub else 0), links


def test_no_page_loads_anything_from_another_host(site):
    offenders = {}
    for page in site.rglob("*.html"):
        if page.relative_to(site).parts[0] in ("vendor", "_static"):
            continue
        hits = [m.group(0) for m in REMOTE.finditer(page.read_text(errors="replace"))
                if not re.search(r'rel="(canonical|alternate)"', m.group(0))]
        if hits:
            offenders[str(page.relative_to(site))] = hits[:3]
    assert not offenders, offenders


def test_chapters_have_exercises_with_executed_solutions(site):
    for ch in ("ch1_counterweights", "ch2_zfl_springs", "ch3_building_zfl"):
        html = (site / "book" / f"{ch}.html").read_text()
        n_ex = html.count('class="exercise admonition"')
        assert 2 <= n_ex <= 4, (ch, n_ex)
        assert html.count("solution") >= n_ex
        assert 'class="tip admonition' in html or "Learning objectives" in html, ch
        assert "Learning objectives" in html
        assert len(re.findall(r'<div class="animation(?: [\w-]+)*">', html)) >= 1, ch   # the player adds bl-player
        assert re.search(r'<figure[^>]*id="fig-', html), f"{ch}: no numbered figure"


# --------------------------------------------------------------------------- exercises (from the sources)


def _problem_bank():
    """scripts/problem_bank.py as a module (the generator of book/problem_bank.md)."""
    import importlib.util

    spec = importlib.util.spec_from_file_location("problem_bank", ROOT / "scripts" / "problem_bank.py")
    module = importlib.util.module_from_spec(spec)
    sys.modules["problem_bank"] = module          # dataclasses look their module up while the class is made
    spec.loader.exec_module(module)
    return module


def _solution(text: str, label: str) -> str:
    """The source between ``solution-start label`` and the next ``solution-end``."""
    m = re.search(r"^```\{solution-start\} " + re.escape(label) + r"\n(.*?)^```\{solution-end\}", text, re.M | re.S)
    assert m, f"{label}: no solution"
    return m[1]


CODE_CELL = re.compile(r"^```\{code-cell\} ipython3\n(.*?)^```$", re.M | re.S)


def test_every_chapter_ends_with_four_exercises_of_mixed_kinds_and_levels():
    bank = _problem_bank()
    chapters = bank.chapters()
    assert [p.stem for p in chapters] == [c for c in CHAPTERS if re.match(r"ch\d_", c)]
    for path in chapters:
        text = path.read_text()
        headings = re.findall(r"^## (.+)$", text, re.M)
        assert headings[-1] == "Exercises", f"{path.name}: the last section is {headings[-1]!r}, not Exercises"
        tail = text[text.rindex("\n## Exercises\n"):]
        exercises = bank.exercises_of(path)
        at_end = [e for e in exercises if f":label: {e.label}\n" in tail]
        assert len(at_end) >= 4, f"{path.name}: {len(at_end)} exercises under its Exercises heading"
        untagged = [e.label for e in exercises if not e.kind]
        assert not untagged, f"{path.name}: exercises without a '*Kind, level n of 3.*' line: {untagged}"
        assert len({e.kind for e in exercises}) >= 2, f"{path.name}: every exercise of one kind"
        assert len({e.level for e in exercises}) >= 2, f"{path.name}: every exercise of one level"
        assert all(e.label.startswith(f"ex-ch{e.number}-") for e in exercises), path.name
    everything = bank.all_exercises()
    assert {e.kind for e in everything} == set(bank.KINDS)
    assert len({e.label for e in everything}) == len(everything), "two exercises share a label"


def test_every_solution_argues_in_prose_and_checks_its_code_in_a_hidden_cell():
    bank = _problem_bank()
    for path in bank.chapters():
        text = path.read_text()
        for e in bank.exercises_of(path):
            solution = _solution(text, e.label)
            prose = CODE_CELL.sub("", solution).replace(":class: dropdown", "")
            words = re.findall(r"[A-Za-z]{2,}", re.sub(r"\$[^$]*\$", " ", prose))
            assert len(words) >= 15, f"{e.label}: the solution's reasoning is not written out ({len(words)} words)"
            cells = CODE_CELL.findall(solution)
            if cells:
                hidden = [c for c in cells if re.search(r"^:tags: \[remove-cell\]", c, re.M)]
                assert any(re.search(r"^assert ", c, re.M) for c in hidden), \
                    f"{e.label}: its code has no hidden cell that asserts the stated answer"


def test_problem_bank_page_is_current_and_lists_every_exercise():
    bank = _problem_bank()
    exercises = bank.all_exercises()
    page = (ROOT / "book" / "problem_bank.md").read_text()
    assert page == bank.render(exercises), "book/problem_bank.md is stale: run python scripts/problem_bank.py"
    rows = re.findall(r"^\| \{doc\}`(\d) <(\w+)>` \| \{ref\}`[^`]* <([\w-]+)>` \| (\w+) \| ([123]) \|$", page, re.M)
    assert [(int(n), ch, label, kind, int(level)) for n, ch, label, kind, level in rows] == \
        [(e.number, e.chapter, e.label, e.kind, e.level) for e in exercises]
    assert bank.main(["--check"]) == 0


def test_problem_bank_refuses_an_exercise_without_kind(tmp_path, monkeypatch):
    bank = _problem_bank()
    (tmp_path / "ch1_demo.md").write_text(
        "## Exercises\n\n```{exercise} Untagged\n:label: ex-ch1-demo\n\nCompute something.\n```\n\n"
        "```{exercise} Tagged\n:label: ex-ch1-other\n\n*Design, level 3 of 3.*\n\nDesign something.\n```\n")
    found = bank.all_exercises(tmp_path)
    assert [(e.label, e.kind, e.level) for e in found] == [("ex-ch1-demo", "", 0), ("ex-ch1-other", "Design", 3)]
    monkeypatch.setattr(bank, "BOOK", tmp_path)
    monkeypatch.setattr(bank, "all_exercises", lambda book=tmp_path: found)
    assert bank.main(["--check"]) == 1


def test_schedule_has_twelve_weeks_every_chapter_and_lab_and_only_real_exercises():
    page = (ROOT / "book" / "schedule.md").read_text()
    weeks = [int(w) for w in re.findall(r"^\*\*Week (\d+)\.", page, re.M)]
    assert weeks == list(range(1, 13))
    for ch in (c for c in CHAPTERS if re.match(r"ch\d_", c)):
        assert f"{{doc}}`{ch}`" in page, f"the schedule never assigns {ch}"
    assert [int(n) for n in re.findall(r"Lab (\d) \(", page)] == list(range(1, 9))
    labels = {e.label for e in _problem_bank().all_exercises()}
    cited = re.findall(r"\{ref\}`(ex-[\w-]+)`", page)
    assert cited and set(cited) <= labels, sorted(set(cited) - labels)
    assert len(re.findall(r"^\*Outcome:\*", page, re.M)) == 12
    assert "labs/bench/" in page and (ROOT / "labs" / "bench" / "README.md").is_file()


def test_a_cell_that_raises_fails_the_build(tmp_path):
    r = build_mini_book(tmp_path, """
        # Page

        ```{code-cell} ipython3
        raise RuntimeError("a broken chapter")
        ```
        """)
    assert r.returncode != 0
    out = r.stdout + r.stderr
    assert "a broken chapter" in out


def test_a_broken_reference_fails_the_build(tmp_path):
    r = build_mini_book(tmp_path, """
        # Page

        See {numref}`fig-that-does-not-exist`.

        ```{code-cell} ipython3
        1 + 1
        ```
        """)
    assert r.returncode != 0
    assert "fig-that-does-not-exist" in r.stdout + r.stderr


# -------------------------------------------------------------------------- the browser
class _Quiet(http.server.SimpleHTTPRequestHandler):
    def log_message(self, *args):  # keep the test output readable
        pass


@pytest.fixture(scope="module")
def server(site):
    handler = functools.partial(_Quiet, directory=str(site))
    httpd = http.server.ThreadingHTTPServer(("127.0.0.1", 0), handler)
    thread = threading.Thread(target=httpd.serve_forever, daemon=True)
    thread.start()
    yield f"http://127.0.0.1:{httpd.server_address[1]}/"
    httpd.shutdown()
    httpd.server_close()


@pytest.fixture(scope="module")
def browser():
    exe = shutil.which("chromium")
    if exe is None:
        pytest.skip("Debian chromium is not installed (bash scripts/setup_extras.sh installs it)")
    sync_api = pytest.importorskip("playwright.sync_api")
    with sync_api.sync_playwright() as p:
        b = p.chromium.launch(executable_path=exe, args=["--headless", "--no-sandbox", "--disable-gpu",
                                                          "--disable-background-networking"])
        yield b
        b.close()


def _pages(site: Path) -> list[str]:
    return sorted(str(p.relative_to(site)) for p in site.rglob("*.html")
                  if p.relative_to(site).parts[0] not in ("vendor", "_static", "_sources"))


_IDS: dict = {}


def _ids(path: Path) -> set:
    if path not in _IDS:
        _IDS[path] = set(re.findall(r'\sid="([^"]+)"', path.read_text(errors="replace")))
    return _IDS[path]


PAGE_CHECKS = """
async () => {
  if (window.MathJax && MathJax.startup && MathJax.startup.promise) { await MathJax.startup.promise; }
  const main = document.querySelector("main") || document.body;
  const maths = Array.from(main.querySelectorAll(".math"));
  const unrendered = maths.filter(e => !e.querySelector("mjx-container")).map(e => e.textContent.slice(0, 80));
  const errors = Array.from(main.querySelectorAll("mjx-merror")).map(e => e.textContent.slice(0, 80));
  const clone = main.cloneNode(true);
  clone.querySelectorAll("pre, code, script, style, .highlight").forEach(e => e.remove());
  const raw = (clone.textContent.match(/\\$\\$|\\\\\\[|\\\\begin\\{/g) || []).length;
  const imgs = Array.from(document.images);
  const broken = imgs.filter(i => !(i.complete && i.naturalWidth > 0)).map(i => i.id || i.src.slice(0, 80));
  const noalt = imgs.filter(i => !(i.getAttribute("alt") || "").trim()).map(i => i.id || i.src.slice(0, 80));
  const heads = Array.from(main.querySelectorAll("h1, h2, h3, h4, h5, h6")).map(h => +h.tagName[1]);
  const figures = Array.from(main.querySelectorAll("figure img")).filter(i => !(i.alt || "").trim()).length;
  const links = Array.from(document.querySelectorAll("a[href]")).map(a => a.href);
  // what a reader sees of the kernel's stderr or of a warning
  const stderr = Array.from(main.querySelectorAll(".output.stderr, .stderr")).map(e => e.textContent.slice(0, 80));
  const warned = Array.from(main.querySelectorAll(".cell_output"))
    .map(e => e.textContent).filter(t => /(Warning|Traceback \\(most recent)/.test(t)).map(t => t.slice(0, 80));
  // every figure and animation frame: natural and rendered width, and its image (its dpi: a
  // WebP keeps it in an EXIF chunk after the pixels)
  const pictures = Array.from(main.querySelectorAll(".cell_output img, div.animation img, .bl-figure img"))
    .filter(i => i.naturalWidth >= 150)
    .map(i => ({src: i.src, natural: i.naturalWidth,
                shown: i.getBoundingClientRect().width}));
  const article = document.querySelector("article.bd-article") || main;
  return {maths: maths.length, unrendered, errors, raw, broken, noalt, heads, figures, links, stderr, warned,
          pictures, content: article.clientWidth,
          overflow: document.documentElement.scrollWidth - window.innerWidth,
          animations: document.querySelectorAll("div.animation").length};
}
"""


#: What a reader of every page must be able to see, evaluated after the page has loaded (every
#: solution and dropdown opened first): each img, svg and formula inside the strip its scroll
#: container lets the reader reach (the window when it has none); no TeX, $…$ or literal \\n in
#: the text outside code and maths, and no Markdown table row printed as text; every matplotlib
#: figure checked for clashing texts when it was made (balancelab.viz.style.text_clashes) and
#: clean; unique element ids.
READER_CHECKS = """
async () => {
  // open every solution and dropdown first: what is cut inside them is cut for the reader too
  document.querySelectorAll(".toggle-hidden").forEach(e => e.classList.remove("toggle-hidden"));
  document.querySelectorAll("details").forEach(d => { d.open = true; });
  if (window.MathJax && MathJax.startup && MathJax.startup.promise) { await MathJax.startup.promise; }
  await new Promise(r => requestAnimationFrame(() => requestAnimationFrame(r)));
  const main = document.querySelector("main") || document.body;
  const vw = document.documentElement.clientWidth;
  const label = e => {
    if (e.tagName === "IMG") return "img " + (e.alt || "").slice(0, 50);
    if (e.tagName === "MJX-CONTAINER") return "formula " + (e.closest(".math, span, div") || e).textContent.slice(0, 50);
    return e.tagName.toLowerCase() + " " + (e.getAttribute("aria-label") || e.textContent || "").slice(0, 40);
  };
  // every img, svg and formula lies where its scroll container lets the reader reach it
  const cut = [];
  const items = Array.from(main.querySelectorAll("img, svg, mjx-container"))
    .filter(e => !(e.tagName === "svg" && (e.closest("mjx-container, button, .anim-buttons") || e.getBoundingClientRect().width < 24)))
    .filter(e => e.getClientRects().length && e.getBoundingClientRect().width > 0);
  for (const e of items) {
    const r = e.getBoundingClientRect();
    // the reachable strip: clipped by every clipping ancestor up to the first scroll container,
    // whose whole scrollable width is reachable; the window when there is none
    let reach = {left: -Infinity, right: Infinity}, why = "the window", scroller = null;
    for (let a = e.parentElement; a && a !== document.body && a !== document.documentElement; a = a.parentElement) {
      const cs = getComputedStyle(a), ox = cs.overflowX;
      if (ox === "visible" || cs.display === "inline" || cs.display === "contents") continue;   // not a box that clips
      const ar = a.getBoundingClientRect();
      const scrolls = (ox === "auto" || ox === "scroll");
      const left = ar.left + a.clientLeft - a.scrollLeft;
      const right = scrolls ? left + a.scrollWidth : ar.left + a.clientLeft + a.clientWidth;
      if (left > reach.left || right < reach.right) why = a.tagName.toLowerCase() + "." + String(a.className).split(" ")[0];
      reach = {left: Math.max(reach.left, left), right: Math.min(reach.right, right)};
      if (scrolls) { scroller = a; break; }
    }
    if (!scroller) reach = {left: Math.max(reach.left, 0), right: Math.min(reach.right, vw)};
    const lost = Math.max(reach.left - r.left, r.right - reach.right);
    if (lost > 1.5) cut.push(`${label(e)}: ${lost.toFixed(0)} px out of reach of ${why}`);
  }
  // no TeX, $…$ or literal \\n in the text a reader sees (code and rendered maths aside)
  const raw = [];
  const walker = document.createTreeWalker(main, NodeFilter.SHOW_TEXT, {acceptNode: n =>
    n.parentElement.closest("pre, code, script, style, mjx-container, .math, .highlight, .MathJax_Preview, .cell_input, textarea, mjx-assistive-mml")
      ? NodeFilter.FILTER_REJECT : NodeFilter.FILTER_ACCEPT});
  const tex = /\\\\(?:[a-zA-Z]{2,}|[()\\[\\]])|\\$[^$\\s][^$]*\\$|\\\\n\\b/;
  // a Markdown table printed as text: a line "| a | b |" or "|---|---|" (a cell's Markdown output
  // that was never made a table)
  const row = /^[ \\t]*\\|(?:[^|\\n]*\\|){2,}[ \\t]*$/m;
  for (let n = walker.nextNode(); n; n = walker.nextNode()) {
    const m = n.textContent.match(tex);
    if (m) raw.push(n.textContent.trim().slice(Math.max(0, m.index - 30), m.index + 50));
    const t = n.textContent.match(row);
    if (t) raw.push("a Markdown table row as text: " + t[0].trim().slice(0, 80));
  }
  // matplotlib text boxes (checked when the figure was made, see balancelab.viz.style.text_clashes)
  const figures = Array.from(main.querySelectorAll(".bl-figure"));
  const unchecked = figures.filter(f => !f.hasAttribute("data-texts-checked")).length;
  const clashes = figures.filter(f => f.dataset.textClashes).map(f => f.dataset.textClashes.slice(0, 160));
  // element ids are unique
  const seen = {}, dup = [];
  document.querySelectorAll("[id]").forEach(e => { if (seen[e.id]) dup.push(e.id); seen[e.id] = 1; });
  return {cut, raw, unchecked, clashes, dup: [...new Set(dup)]};
}
"""


#: What is wider than the page's content box on a phone (a reader must swipe inside it to see all
#: of it): every display formula, table, image, figure, animation and svg, at its full width
#: (its scrollWidth when it scrolls), measured from its left edge against the right edge of the
#: article's content box (a formula's drawn maths, its hidden MathML aside). Code blocks may scroll (their lines are kept short by
#: tests/test_pages.py), so what sits in code is left out. Run after READER_CHECKS opened every
#: solution and dropdown.
WIDTH_CHECKS = """
() => {
  const article = document.querySelector("article.bd-article") || document.querySelector("main") || document.body;
  const ar = article.getBoundingClientRect(), cs = getComputedStyle(article);
  const right = ar.left + article.clientLeft + article.clientWidth - parseFloat(cs.paddingRight);
  const wide = [];
  const items = article.querySelectorAll("mjx-container, table, img, .bl-figure, div.animation, svg, iframe, video");
  for (const e of items) {
    if (e.closest("pre, .highlight, .cell_input, button, .anim-buttons") || e.parentElement.closest("mjx-container")) continue;
    if (e.tagName === "svg" && e.getBoundingClientRect().width < 24) continue;
    if (!e.getClientRects().length) continue;
    // a formula is as wide as its drawn maths (its hidden MathML for screen readers aside)
    const drawn = e.tagName === "MJX-CONTAINER" ? e.querySelector(":scope > mjx-math") : null;
    const r = (drawn || e).getBoundingClientRect();
    const over = r.left + Math.max(r.width, drawn ? 0 : e.scrollWidth || 0) - right;
    if (over <= 1.5) continue;
    const what = e.tagName === "MJX-CONTAINER" ? "formula " + (e.closest(".math, span, div") || e).textContent.slice(0, 50)
      : e.tagName === "IMG" ? "img " + (e.alt || "").slice(0, 50)
      : e.tagName.toLowerCase() + "." + String(e.className).split(" ")[0] + " " + e.textContent.trim().slice(0, 40);
    wide.push(`${what}: ${over.toFixed(0)} px wider than the ${(right - ar.left).toFixed(0)} px column`);
  }
  return wide;
}
"""


def _reader_problems(page, where: str) -> list[str]:
    res = page.evaluate(READER_CHECKS)
    problems = [f"{where}: out of reach: {c}" for c in res["cut"]]
    problems += [f"{where}: raw TeX or markup in the text: {r!r}" for r in res["raw"]]
    if res["unchecked"]:
        problems.append(f"{where}: {res['unchecked']} figures made without the house style's text check")
    problems += [f"{where}: figure texts clash: {c}" for c in res["clashes"]]
    if res["dup"]:
        problems.append(f"{where}: duplicate element ids {res['dup'][:5]}")
    return problems


def _png_dpi(src: str, site: Path) -> float:
    """The dpi a PNG or WebP declares (72 when it declares none), from a data URI's start or a site file."""
    import base64
    import io

    from PIL import Image

    if src.startswith("data:"):
        head = src.split(",", 1)[1]
        data = base64.b64decode(head[: len(head) // 4 * 4])
    else:
        data = (site / unquote(urlsplit(src).path.lstrip("/"))).read_bytes()
    try:
        im = Image.open(io.BytesIO(data))
        # a PNG's pHYs chunk, or a WebP's EXIF XResolution (in dots per inch, unit 2)
        exif = im.getexif() if im.format == "WEBP" else {}
        dpi = exif[0x011A] if exif.get(0x0128) == 2 and 0x011A in exif else im.info.get("dpi", (72, 72))[0]
    except Exception:  # not an image header: the test reports it as unreadable
        return 0.0
    return float(dpi)


def _figure_problems(res: dict, site: Path, where: str) -> list[str]:
    """Figures whose smallest text (MIN_FONT_PT at their dpi, as shown) is under MIN_FONT_PX, and
    figures or animation frames with fewer than PIXEL_RATIO device pixels per CSS pixel shown
    (soft on a high-density screen)."""
    from balancelab.viz import style

    problems = []
    for pic in res["pictures"]:
        if pic["natural"] < style.PIXEL_RATIO * pic["shown"] - 1:
            problems.append(f"{where}: a picture {pic['natural']} px wide shown {pic['shown']:.0f} px wide "
                            f"(< {style.PIXEL_RATIO}x: soft on a high-density screen): {pic['src'][:60]}")
        dpi = _png_dpi(pic["src"], site)
        if dpi < 110:
            problems.append(f"{where}: a figure at {dpi:.0f} dpi (< 110): {pic['src'][:60]}")
            continue
        px = style.MIN_FONT_PT * dpi / 72 * pic["shown"] / pic["natural"]
        if px < style.MIN_FONT_PX - 0.05:
            problems.append(f"{where}: a figure's smallest text renders {px:.1f} px high "
                            f"({pic['natural']} px wide, shown {pic['shown']:.0f} px)")
    return problems


def _navigation_problems(page, width: int, where: str) -> list[str]:
    """The visible menu button opens the table of contents (a drawer on narrow screens)."""
    from playwright.sync_api import expect

    button = page.locator("button.primary-toggle").filter(visible=True)
    if button.count() != 1:
        return [f"{where}: {button.count()} visible menu buttons"]
    if width >= 992:
        nav = page.locator("#pst-primary-sidebar nav.bd-docs-nav")
        return [] if nav.is_visible() else [f"{where}: no table of contents at {width} px"]
    button.click()
    drawer = page.locator("#pst-primary-sidebar-modal")
    try:
        expect(drawer.locator("nav.bd-docs-nav")).to_be_visible(timeout=5000)
    except AssertionError:
        return [f"{where}: the menu button did not open the table of contents at {width} px"]
    page.keyboard.press("Escape")
    expect(drawer).to_be_hidden(timeout=5000)
    return []


@pytest.mark.parametrize("width", [390, 1280])
def test_every_page_in_a_browser(site, server, browser, width):
    SHOTS.mkdir(parents=True, exist_ok=True)
    problems: list[str] = []
    pages = _pages(site)
    assert len(pages) >= len(CHAPTERS)
    ctx = browser.new_context(viewport={"width": width, "height": 900})
    external: list[str] = []

    def route(r):
        host = urlsplit(r.request.url).hostname
        if r.request.url.startswith(("data:", "blob:")) or host == "127.0.0.1":
            r.continue_()
        else:
            external.append(r.request.url)
            r.abort()

    ctx.route("**/*", route)
    n_anim = 0
    for rel in pages:
        page = ctx.new_page()
        console: list[str] = []
        bad: list[str] = []
        # each handler binds this page's lists (a late event of an earlier page must not land in this one's)
        page.on("console", lambda m, console=console: console.append(m.text) if m.type == "error" else None)
        page.on("pageerror", lambda e, console=console: console.append(f"uncaught: {e}"))
        page.on("response", lambda r, bad=bad: bad.append(f"{r.status} {r.url}") if r.status >= 400 else None)
        url = urljoin(server, rel)
        resp = page.goto(url, wait_until="load")
        where = f"{rel} at {width} px"
        if resp is None or resp.status != 200:
            problems.append(f"{where}: status {resp and resp.status}")
            continue
        redirect = re.search(r'http-equiv="Refresh" content="0; url=([^"]+)"', (site / rel).read_text())
        if redirect:  # a redirect-only page (the site's index): check its target, then move on
            target = urljoin(url, redirect.group(1))
            page.wait_for_url(target, timeout=10000)
            page.wait_for_load_state("load")
            if not (site / urljoin(rel, redirect.group(1))).is_file():
                problems.append(f"{where}: redirects to a missing page {redirect.group(1)}")
            continue
        res = page.evaluate(PAGE_CHECKS)
        for key in ("unrendered", "errors", "broken", "noalt", "stderr", "warned"):
            if res[key]:
                problems.append(f"{where}: {key}: {res[key][:5]}")
        if res["raw"]:
            problems.append(f"{where}: {res['raw']} raw TeX delimiters left in the text")
        if res["figures"]:
            problems.append(f"{where}: {res['figures']} figures without alt text")
        problems += _figure_problems(res, site, where)
        if res["overflow"] > 1:
            problems.append(f"{where}: the page scrolls sideways by {res['overflow']} px")
        if res["pictures"] and width == 390 and res["content"] < 300:
            problems.append(f"{where}: the content column is only {res['content']} px wide")
        problems += _navigation_problems(page, width, where)
        heads = res["heads"]
        if heads and heads[0] != 1:
            problems.append(f"{where}: first heading is h{heads[0]}")
        for a, b in zip(heads, heads[1:]):
            if b > a + 1:
                problems.append(f"{where}: heading jumps from h{a} to h{b}")
                break
        for href in res["links"]:
            parts = urlsplit(href)
            if parts.hostname != "127.0.0.1" or parts.scheme not in ("http", "https"):
                continue
            target = site / unquote(parts.path.lstrip("/"))
            if target.is_dir():
                target = target / "index.html"
            if not target.is_file():
                problems.append(f"{where}: dead link {href}")
            elif parts.fragment and target.suffix == ".html" and unquote(parts.fragment) not in _ids(target):
                problems.append(f"{where}: dead anchor {href}")
        # every animation is there and advances when played
        for i in range(res["animations"]):
            anim = page.locator("div.animation").nth(i)
            anim.scroll_into_view_if_needed()
            slider = anim.locator("input[type=range]")
            frame = anim.locator("img").first
            seen = {slider.input_value()}
            pictures = {frame.evaluate("e => e.src.slice(-64)")}
            anim.locator("button[title=Play]").click()
            for _ in range(12):  # sample the frame counter while it plays (loops may wrap around)
                page.wait_for_timeout(70)
                seen.add(slider.input_value())
                pictures.add(frame.evaluate("e => e.src.slice(-64)"))
            anim.locator("button[title=Pause]").click()
            n_anim += 1
            if len(seen) < 2:
                problems.append(f"{where}: animation {i} did not advance when played")
            # the frames after the first arrive when the reader reaches the player (lazy_frames.py)
            if len(pictures) < 2:
                problems.append(f"{where}: animation {i} shows the same picture in every frame")
            if int(slider.get_attribute("max") or 0) < 2:
                problems.append(f"{where}: animation {i} has fewer than 3 frames")
        page.screenshot(path=str(SHOTS / (rel.replace("/", "__")[:-5] + f"_{width}.png")), full_page=True,
                        timeout=180_000)  # a long page on a loaded machine: the shot waits for fonts and layout
        problems += _reader_problems(page, where)
        if width == 390:
            problems += [f"{where}: wider than the column: {w}" for w in page.evaluate(WIDTH_CHECKS)]
        problems += [f"{where}: console error: {c}" for c in console]
        problems += [f"{where}: failed request: {b}" for b in bad]
        page.close()
    ctx.close()
    assert not external, f"requests to other hosts: {sorted(set(external))[:10]}"
    assert not problems, "\n".join(problems)
    assert n_anim >= 3, f"only {n_anim} animations in the whole site"


WIDGET_PAGE = """<!DOCTYPE html>
<html lang="en"><head><meta charset="utf-8"><title>widgets offline</title>
<script>window.MathJax = {{tex: {{inlineMath: [["$", "$"], ["\\\\(", "\\\\)"]]}}}};</script>
<script defer src="vendor/mathjax/tex-chtml.js"></script>
{scripts}
<script type="application/vnd.jupyter.widget-state+json">{state}</script>
</head><body><main><h1>widgets</h1>
<script type="application/vnd.jupyter.widget-view+json">{view}</script>
</main></body></html>
"""


def test_vendored_widget_manager_renders_math_offline(site, browser, tmp_path):
    """The page set-up myst-nb writes for a page with widget state, with the vendored files:
    the HTML manager renders an HTMLMath widget beside MathJax 3, without console errors
    and without asking any other host (the MathJax 2 shim at work)."""
    import json

    ipywidgets_embed = pytest.importorskip("ipywidgets.embed")
    import ipywidgets

    data = ipywidgets_embed.embed_data(views=[ipywidgets.HTMLMath(value=r"energy $V = \frac{1}{2} k a^2$")])
    cfg = yaml.safe_load((ROOT / "_config.yml").read_text())
    scripts = "\n".join(f'<script src="{path.replace("../", "")}"></script>'
                        for path in cfg["sphinx"]["config"]["nb_ipywidgets_js"])
    (tmp_path / "vendor").symlink_to(ROOT / "book" / "_vendor" / "vendor", target_is_directory=True)
    (tmp_path / "widgets.html").write_text(WIDGET_PAGE.format(
        scripts=scripts, state=json.dumps(data["manager_state"]), view=json.dumps(data["view_specs"][0])))
    handler = functools.partial(_Quiet, directory=str(tmp_path))
    httpd = http.server.ThreadingHTTPServer(("127.0.0.1", 0), handler)
    threading.Thread(target=httpd.serve_forever, daemon=True).start()
    try:
        ctx = browser.new_context()
        external, console, failed = [], [], []

        def route(r):
            if urlsplit(r.request.url).hostname == "127.0.0.1" or r.request.url.startswith("data:"):
                r.continue_()
            else:
                external.append(r.request.url)
                r.abort()

        ctx.route("**/*", route)
        page = ctx.new_page()
        page.on("console", lambda m: console.append(m.text) if m.type == "error" else None)
        page.on("pageerror", lambda e: console.append(f"uncaught: {e}"))
        page.on("response", lambda r: failed.append(f"{r.status} {r.url}") if r.status >= 400 else None)
        page.goto(f"http://127.0.0.1:{httpd.server_address[1]}/widgets.html", wait_until="load")
        page.wait_for_selector(".widget-htmlmath", timeout=20000)
        page.wait_for_selector(".widget-htmlmath mjx-container", timeout=20000)
        ctx.close()
    finally:
        httpd.shutdown()
        httpd.server_close()
    assert not external, external
    assert not console, console
    assert not failed, failed
