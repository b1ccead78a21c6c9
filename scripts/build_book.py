"""Fetch the course site's offline assets and build the book (Jupyter Book 1.x).

Usage::

    python scripts/build_book.py            # cached execution, warnings are errors
    python scripts/build_book.py --force    # re-execute every chapter (what the tests do)
    python scripts/build_book.py --assets   # only fetch the offline assets (and axe-core)
    python scripts/build_book.py --no-pdf   # skip the printable course (scripts/build_pdf.py)

The site must load nothing from a CDN, so MathJax 3, require.js and
``@jupyter-widgets/html-manager`` are taken from the npm registry (``npm pack`` with
exact versions; npm checks each tarball's integrity) and unpacked into the git-ignored
``book/_vendor/vendor/``, which Sphinx publishes at ``/vendor/`` through
``html_extra_path``; ``book/_ext/offline_assets.py`` then drops from the site what no page
requests (the widget manager and require.js when no page has widgets). axe-core, which the
accessibility test injects into every page, goes to the git-ignored ``tests/_vendor/`` instead
(:func:`fetch_axe`): it is a test tool, not part of the site.

The chapters' kernels start with the course's figure style installed
(:func:`balancelab.viz.style.install`: every figure at the house resolution, one image per
column of panels so that figures stack on a phone): the build points ``IPYTHONDIR`` at
``_build/ipython``, whose kernel configuration runs that one line before the first cell.
"""
from __future__ import annotations

import argparse
import os
import shutil
import subprocess
import sys
import tarfile
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
VENDOR = ROOT / "book" / "_vendor" / "vendor"
OUT = ROOT / "_build" / "html"

#: npm packages and the exact versions vendored into the site.
PACKAGES = {
    "mathjax": "3.2.2",
    "requirejs": "2.3.8",
    "@jupyter-widgets/html-manager": "1.0.15",
}
#: Parts of mathjax/es5 that the pages load (the entry point and what it loads on demand).
MATHJAX_KEEP = ("tex-chtml.js", "core.js", "loader.js", "startup.js", "input", "output/chtml",
                "output/chtml.js", "ui", "a11y", "adaptors", "sre")
STAMP = VENDOR / "VERSIONS.txt"
IPYTHONDIR = ROOT / "_build" / "ipython"
#: IPython kernel configuration of the book's kernels (see the module docstring).
KERNEL_CONFIG = (
    "# Written by scripts/build_book.py: the course's figure style in every chapter's kernel.\n"
    "c.InteractiveShellApp.exec_lines = [\n"
    "    'import balancelab.viz.style as _bl_style; _bl_style.install(); del _bl_style',\n"
    "]\n"
)


def kernel_profile() -> Path:
    """Write the kernels' IPython configuration into :data:`IPYTHONDIR`; return that folder."""
    profile = IPYTHONDIR / "profile_default"
    profile.mkdir(parents=True, exist_ok=True)
    config = profile / "ipython_kernel_config.py"
    if not config.is_file() or config.read_text() != KERNEL_CONFIG:
        config.write_text(KERNEL_CONFIG)
    return IPYTHONDIR


def _stamp_text() -> str:
    return "".join(f"{name}@{ver}\n" for name, ver in PACKAGES.items())


def _npm_pack(spec: str, dest: Path) -> Path:
    npm = shutil.which("npm")
    if npm is None:
        raise SystemExit("npm is needed to fetch MathJax, require.js and the ipywidgets HTML manager "
                         "from the npm registry: run `bash scripts/setup_extras.sh .venv/bin/python` "
                         "(installs Debian's npm) or install Node.js")
    out = subprocess.run([npm, "pack", spec, "--silent", "--pack-destination", str(dest)],
                         check=True, capture_output=True, text=True).stdout.strip().splitlines()
    return dest / out[-1].strip()


def _extract(tgz: Path, member_prefix: str, target: Path, keep=None) -> None:
    with tarfile.open(tgz) as tar:
        for m in tar.getmembers():
            if not m.isfile() or not m.name.startswith(member_prefix):
                continue
            rel = m.name[len(member_prefix):]
            if keep is not None and not any(rel == k or rel.startswith(k + "/") for k in keep):
                continue
            path = target / rel
            path.parent.mkdir(parents=True, exist_ok=True)
            with tar.extractfile(m) as src, open(path, "wb") as dst:
                shutil.copyfileobj(src, dst)


def fetch_assets(force: bool = False) -> Path:
    """Put MathJax 3, require.js and the widgets HTML manager into ``book/_vendor/vendor``.

    Parameters
    ----------
    force : bool
        Fetch again even when the pinned versions are already there.

    Returns
    -------
    pathlib.Path
        The vendor folder.
    """
    if not force and STAMP.is_file() and STAMP.read_text() == _stamp_text() \
            and (VENDOR / "mathjax" / "tex-chtml.js").is_file():
        return VENDOR
    if VENDOR.exists():
        shutil.rmtree(VENDOR)
    VENDOR.mkdir(parents=True)
    with tempfile.TemporaryDirectory() as tmp:
        tmp = Path(tmp)
        mj = _npm_pack(f"mathjax@{PACKAGES['mathjax']}", tmp)
        _extract(mj, "package/es5/", VENDOR / "mathjax", MATHJAX_KEEP)
        _extract(mj, "package/", VENDOR / "mathjax", ("LICENSE",))
        rq = _npm_pack(f"requirejs@{PACKAGES['requirejs']}", tmp)
        _extract(rq, "package/", VENDOR / "requirejs", ("require.js", "README.md"))
        (VENDOR / "requirejs" / "README.md").unlink(missing_ok=True)
        hm = _npm_pack(f"@jupyter-widgets/html-manager@{PACKAGES['@jupyter-widgets/html-manager']}", tmp)
        fonts = []
        with tarfile.open(hm) as tar:
            fonts = [m.name[len("package/dist/"):] for m in tar.getmembers()
                     if m.name.startswith("package/dist/")
                     and m.name.rsplit(".", 1)[-1] in ("woff", "woff2", "ttf", "eot", "svg")]
        _extract(hm, "package/dist/", VENDOR / "html-manager", ["embed-amd.js", *fonts])
        _extract(hm, "package/", VENDOR / "html-manager", ("LICENSE",))
    shutil.copy(ROOT / "book" / "_ext" / "widgets-mathjax-shim.js", VENDOR / "widgets-mathjax-shim.js")
    STAMP.write_text(_stamp_text())
    return VENDOR


#: axe-core, the accessibility checker the browser tests inject into every page (tests/test_a11y.py);
#: vendored beside the tests, never published with the site.
AXE_VERSION = "4.14.1"
AXE_DIR = ROOT / "tests" / "_vendor" / "axe-core"


def fetch_axe(force: bool = False) -> Path:
    """Put axe-core's ``axe.min.js`` (npm, exact version) into the git-ignored ``tests/_vendor/``.

    Parameters
    ----------
    force : bool
        Fetch again even when the pinned version is already there.

    Returns
    -------
    pathlib.Path
        The path of ``axe.min.js``.
    """
    script, stamp = AXE_DIR / "axe.min.js", AXE_DIR / "VERSION.txt"
    if not force and script.is_file() and stamp.is_file() and stamp.read_text().strip() == AXE_VERSION:
        return script
    AXE_DIR.mkdir(parents=True, exist_ok=True)
    with tempfile.TemporaryDirectory() as tmp:
        tgz = _npm_pack(f"axe-core@{AXE_VERSION}", Path(tmp))
        _extract(tgz, "package/", AXE_DIR, ("axe.min.js", "LICENSE"))
    stamp.write_text(AXE_VERSION + "\n")
    return script


def build(force: bool = False, all_pages: bool = False, quiet: bool = False, toc=None) -> float:
    """Build the site into ``_build/html`` with warnings as errors; return the seconds it took.

    Parameters
    ----------
    force : bool
        Re-execute every notebook (``nb_execution_mode = "force"``) instead of using the cache.
    all_pages : bool
        Re-write every page (a fresh Sphinx environment).
    quiet : bool
        Print only warnings.
    toc : path, optional
        Another table of contents (default ``_toc.yml``).

    Returns
    -------
    float
        Wall time of the build (s).

    Raises
    ------
    SystemExit
        When the build fails (a cell raised, a warning was emitted ...).
    """
    fetch_assets()
    # The kernels inherit this process's environment: a non-interactive MPLBACKEND (test suites
    # set Agg) would stop matplotlib's inline backend, and every figure would vanish from the pages.
    os.environ.pop("MPLBACKEND", None)
    os.environ["IPYTHONDIR"] = str(kernel_profile())
    from jupyter_book.sphinx import build_sphinx

    # What `jb build . -W -n --keep-going` passes, plus forced execution when asked.
    overrides = {"external_toc_path": str(Path(toc).resolve() if toc else ROOT / "_toc.yml"),
                 "latex_individualpages": False, "nitpicky": True}
    if force:
        overrides["nb_execution_mode"] = "force"
    t0 = time.perf_counter()
    if (force or all_pages) and OUT.exists():
        shutil.rmtree(OUT)  # no stale pages from an earlier table of contents
    status = build_sphinx(str(ROOT), str(OUT), path_config=str(ROOT / "_config.yml"),
                          noconfig=True, confoverrides=overrides, builder="html", warningiserror=True,
                          keep_going=True, freshenv=all_pages or force, quiet=quiet)
    elapsed = time.perf_counter() - t0
    if status:
        raise SystemExit(f"book build failed (status {status}); see the messages above")
    return elapsed


def main(argv=None) -> int:
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--force", action="store_true", help="re-execute every chapter")
    p.add_argument("--all", action="store_true", help="re-write every page")
    p.add_argument("--assets", action="store_true", help="only fetch the offline assets")
    p.add_argument("--quiet", action="store_true")
    p.add_argument("--no-pdf", action="store_true", help="do not print the course into a PDF")
    p.add_argument("--toc", help="another table of contents, for working on a few pages")
    a = p.parse_args(argv)
    if a.assets:
        print(fetch_assets(force=True))
        print(fetch_axe(force=True))
        return 0
    t = build(force=a.force, all_pages=a.all, quiet=a.quiet, toc=a.toc)
    fetch_axe()  # for the accessibility test of the site just built
    print(f"\nbook built in {t:.1f} s: open {OUT / 'index.html'}")
    if not a.no_pdf and a.toc is None:
        sys.path.insert(0, str(ROOT / "scripts"))
        import build_pdf

        r = build_pdf.build_pdf(OUT)
        print(f"printable course: {OUT / build_pdf.PDF_NAME} ({r['seconds']} s)")
    return 0


if __name__ == "__main__":
    sys.exit(main())
