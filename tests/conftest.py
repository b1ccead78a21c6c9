"""Shared test helpers: the physics every design must satisfy."""
from __future__ import annotations

import os
import shutil
import socket
import subprocess
import sys
import textwrap
from pathlib import Path

import numpy as np
import pytest
import yaml

os.environ.setdefault("MPLBACKEND", "Agg")

from balancelab import Design, Spring  # noqa: E402


def spring_perturbations(design: Design, rel: float = 1e-3):
    """Yield ``(label, design)`` with one non-zero spring parameter changed by ``rel`` (relative).

    (A relative change of a parameter that is zero is no change.)
    """
    for i, s in enumerate(design.springs):
        fields = {"k": s.k, "free_length": s.free_length,
                  "a_x": s.a.point[0], "a_y": s.a.point[1], "b_x": s.b.point[0], "b_y": s.b.point[1]}
        for name, value in fields.items():
            if value == 0:
                continue
            new = value * (1 + rel)
            k, l0 = s.k, s.free_length
            a, b = list(s.a.point), list(s.b.point)
            if name == "k":
                k = new
            elif name == "free_length":
                l0 = new
            else:
                (a if name[0] == "a" else b)[0 if name[2] == "x" else 1] = new
            changed = Spring(k, l0, (s.a.body, tuple(a)), (s.b.body, tuple(b)), name=s.name,
                             realization=s.realization)
            springs = list(design.springs)
            springs[i] = changed
            yield f"spring {s.name or i} {name}", design.replace(springs=springs)


def assert_exactly_balanced(design: Design, n: int = 1000) -> None:
    """Energy constant over ``n`` samples to 1e-9, and every 1e-3 spring change detected."""
    report = design.balance_report(n=n)
    assert report.n == n
    assert report.balanced, f"{design.name}: {report}"
    assert report.variation <= 1e-9
    assert report.residual < 1e-6, report
    for label, bad in spring_perturbations(design):
        r = bad.balance_report(n=200)
        assert not r.balanced, f"{design.name}: perturbing {label} went unnoticed ({r})"
        assert r.variation > 1e-7, (label, r.variation)


def independent_energy(design: Design, q) -> np.ndarray:
    """Potential energy (J) at each of ``q``, summed here from the design's poses with its own
    frame transform: every load (weights, forces) and every spring, any free length. A second
    bookkeeping, independent of ``Design.potential_energy``."""
    poses = design.poses(q)

    def world(body, p):
        x, y, a = poses[:, body, 0], poses[:, body, 1], poses[:, body, 2]
        return np.stack([x + np.cos(a) * p[0] - np.sin(a) * p[1], y + np.sin(a) * p[0] + np.cos(a) * p[1]], -1)

    V = np.zeros(len(q))
    for ld in design.loads:
        V -= (world(ld.body, ld.point) * np.asarray(ld.force)).sum(-1)
    for s in design.springs:
        stretch = np.linalg.norm(world(*s.a) - world(*s.b), axis=-1) - s.free_length
        V += 0.5 * s.k * stretch ** 2
    return V


def assert_symbolic_matches_numeric(design: Design, samples: int = 5) -> None:
    """The symbolic energy (with the design's values) equals the numeric one."""
    import sympy as sp

    expr = design.potential_energy_symbolic()
    values = design.symbolic.values if design.symbolic is not None else {}
    kin = design.kinematics
    if design.symbolic is not None and design.symbolic.kinematics is not None:
        kin = design.symbolic.kinematics
    syms = kin.symbols()
    f = sp.lambdify(syms, expr.subs(values), "numpy")
    q = design.sample(samples, seed=3)
    vals = kin.symbol_values(q)
    got = np.array([f(*v) for v in vals], dtype=float)
    want = design.potential_energy(q).total
    np.testing.assert_allclose(got, want, rtol=1e-9, atol=1e-9 * design.balance_report(n=100).scale)


# ---------------------------------------------------------------- book and browser helpers
ROOT = Path(__file__).resolve().parents[1]
#: Debian's chromium (never a browser downloaded by playwright)
CHROMIUM = shutil.which("chromium")
CHROMIUM_ARGS = ["--headless", "--no-sandbox", "--disable-gpu", "--disable-background-networking"]
NEEDS_CHROMIUM = pytest.mark.skipif(CHROMIUM is None, reason="Debian chromium is not installed (the setup "
                                                             "script installs it with apt: apt-get install chromium)")


SUBMISSION_HEADER = "import balancelab as bl\nfrom balancelab.course.check import check\n"


def submission_notebook(lab: str, *sources: str):
    """A student's submission for ``lab``: the labs' import cell, then one code cell per source."""
    import nbformat

    nb = nbformat.v4.new_notebook()
    nb.metadata = {"kernelspec": {"name": "python3", "display_name": "Python 3", "language": "python"},
                   "balancelab": {"lab": lab, "version": "student"}}
    nb.cells = [nbformat.v4.new_code_cell(s) for s in (SUBMISSION_HEADER,) + sources]
    return nb


def lab8_reference_springs() -> dict:
    """A right answer to lab 8's task 8.1: the library's spring selection for the lab's arm."""
    from balancelab.course.check import lab8
    from balancelab.methods.practice import selection

    arm = lab8.lab8_arm()
    strokes = dict(zip(("k1", "k2"), selection.spring_strokes(arm, 41)))
    out = {}
    for s in arm.springs:
        real = selection.select_spring(s.k, strokes[s.name]).spring
        out[s.name] = {"d": real.wire_diameter, "D": real.coil_diameter, "Na": real.active_coils,
                       "F_i": real.initial_tension}
    return out


def free_port() -> int:
    """A free TCP port on 127.0.0.1."""
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


def build_mini_book(tmp_path: Path, body: str, local_extensions: dict | None = None):
    """Build a one-page book with the course's execution and strictness settings.

    ``local_extensions`` maps extension names to folders (e.g. the page guard in book/_ext).
    Returns the finished ``subprocess.CompletedProcess`` of the build.
    """
    cfg = yaml.safe_load((ROOT / "_config.yml").read_text())
    sphinx = {"extra_extensions": cfg["sphinx"]["extra_extensions"]}
    if local_extensions:
        sphinx["local_extensions"] = local_extensions
    mini = {"title": "t", "only_build_toc_files": True, "execute": dict(cfg["execute"]), "sphinx": sphinx}
    mini["execute"]["cache"] = str(tmp_path / "cache")
    (tmp_path / "_config.yml").write_text(yaml.safe_dump(mini))
    (tmp_path / "_toc.yml").write_text("format: jb-book\nroot: page\n")
    header = ("---\njupytext:\n  text_representation:\n    extension: .md\n    format_name: myst\n"
              "kernelspec:\n  display_name: Python 3\n  language: python\n  name: python3\n---\n\n")
    (tmp_path / "page.md").write_text(header + textwrap.dedent(body))
    code = ("import sys; from jupyter_book.sphinx import build_sphinx; "
            f"sys.exit(build_sphinx({str(tmp_path)!r}, {str(tmp_path / '_build/html')!r}, noconfig=True, "
            f"path_config={str(tmp_path / '_config.yml')!r}, confoverrides={{'external_toc_path': "
            f"{str(tmp_path / '_toc.yml')!r}, 'latex_individualpages': False, 'nitpicky': True}}, "
            "warningiserror=True, keep_going=True, quiet=True))")
    return subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=600)


def personal_k_lamp(student_id: str) -> str:
    """Code of a right answer to task 2.1 for ``student_id`` (the grader takes the id from the file name)."""
    return ("from balancelab.course.check import task_numbers as _tn\n"
            f"k_lamp = bl.lecture.single_link_spring(**_tn('2.1', {student_id!r})).parameters['k']")


def personal_lever_spring(student_id: str) -> str:
    """Code of a right design for task 2.4 (the student's own load, stock rate and mounting box): the anchor
    at the box's centre, ``a_x`` from the rate condition k = W l b_y / (a_x |b|^2), ``a_y`` from eq. 15."""
    return ("from balancelab.course.check import task_numbers as _tn\n"
            f"_w = _tn('2.4', {student_id!r})\n"
            "_bx, _by = (_w['box'][0] + _w['box'][1]) / 2, (_w['box'][2] + _w['box'][3]) / 2\n"
            "_ax = _w['weight'] * _w['length'] * _by / (_w['k'] * (_bx ** 2 + _by ** 2))\n"
            "lever_spring = {'k': _w['k'], 'a': (_ax, -_ax * _bx / _by), 'b': (_bx, _by)}")


def personal_r_c(student_id: str) -> str:
    """Code of a right answer to task 1.1 for ``student_id``."""
    return ("from balancelab.course.check import task_numbers as _tn\n"
            f"_n = _tn('1.1', {student_id!r})\n"
            "r_c = bl.lecture.single_link_counterweight(_n['mass'], _n['length'], _n['counter_mass'], "
            "link_mass=_n['link_mass']).parameters['r_c']")


def personal_lever_energy(student_id: str) -> str:
    """Code of a right answer to task 2.3 for ``student_id`` (the library's LaCoste lever on their numbers)."""
    return ("from balancelab.course.check import task_numbers as _tn\n"
            f"lever_energy = bl.singh.lacoste_lever(**_tn('2.3', {student_id!r})).parameters['PE']")


def personal_equivalent(student_id: str) -> str:
    """Code of a right answer to task 1.3 for ``student_id`` (same mass, same first moment about D)."""
    return ("from balancelab.course.check import task_numbers as _tn\n"
            f"_c = _tn('1.3', {student_id!r})\n"
            "m_equivalent = (_c['mass'] * (1 - _c['com'] / 0.5), _c['mass'] * _c['com'] / 0.5)")


#: Modules that build the site or read it, or drive Chromium: one xdist worker runs them in this
#: order (``--dist loadgroup`` in scripts/course.sh) while the other takes everything else.
SITE_GROUP = ("test_book.py", "test_site_nav.py", "test_lab_browser.py", "test_a11y.py")


def pytest_collection_modifyitems(session, config, items):
    """Site and browser tests are meant to run on one worker, in :data:`SITE_GROUP` order (a11y last: it
    checks the site that tests/test_book.py builds).

    Measured on pytest-xdist 3.8 (session 8): the group does not hold, test_book.py's tests run on both
    workers. Its ``site`` fixture therefore builds under a file lock, once per test run, and the other
    worker reuses that build (two builds had raced in ``_build/html``). Open: find why the marks are not
    honoured, or move the site tests into one session-scoped runner."""
    site = sorted((item for item in items if item.path.name in SITE_GROUP),
                  key=lambda item: SITE_GROUP.index(item.path.name))
    for item in site:
        item.add_marker(pytest.mark.xdist_group("site"))
    items[:] = [item for item in items if item.path.name not in SITE_GROUP] + site


def scissors_lift_linkage(lam: float, stroke: bool = True):
    """The catalog's scissors lift as a ``bl.Linkage`` at scale ``lam`` (lengths x lam), every local
    point on the x-axis, with the catalog's loads and no spring; the bottom slider's stroke is
    (0.01..0.49) * lam, or the default one."""
    import balancelab as bl

    cat = bl.catalog()["scissors_lift"]()
    a, h = 0.5 * lam, 0.25 * lam
    lk = bl.Linkage(f"lift x{lam:g}")
    for name in cat.bodies[1:]:
        lk.body(name)
    lk.revolute("ground", (0.0, 0.0), "arm 2", (0.0, 0.0))
    lk.revolute("arm 2", (h, 0.0), "arm 3", (h, 0.0))
    lk.revolute("arm 3", (0.0, 0.0), "slider 4", (0.0, 0.0))
    lk.prismatic("ground", (0.0, 0.0), "slider 4", (0.0, 0.0), axis=(1.0, 0.0),
                 stroke=(0.01 * lam, 0.49 * lam) if stroke else None)
    lk.revolute("arm 3", (a, 0.0), "arm 5", (0.0, 0.0))
    lk.revolute("arm 2", (a, 0.0), "arm 6", (0.0, 0.0))
    lk.revolute("arm 5", (h, 0.0), "arm 6", (h, 0.0))
    lk.revolute("arm 6", (a, 0.0), "platform 8", (0.0, 0.0))
    lk.revolute("arm 5", (a, 0.0), "slider 7", (0.0, 0.0))
    lk.prismatic("platform 8", (0.0, 0.0), "slider 7", (0.0, 0.0), axis=(1.0, 0.0))
    for ld in cat.loads:
        lk.load(ld.body, ld.force, com=(ld.point[0] * lam, ld.point[1] * lam), name=ld.name)
    return lk
