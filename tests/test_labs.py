"""The labs: eight of them, solutions pass nbval, student versions are generated, leak nothing and run."""
import copy
import re
import subprocess
import sys
from pathlib import Path

import nbformat
import pytest

from balancelab.course import labtools
from balancelab.course.check import tasks
from balancelab.course.grading import grade_notebook

ROOT = Path(__file__).resolve().parent.parent
SOLUTIONS = ROOT / "labs" / "solutions"
STUDENT = ROOT / "labs" / "student"
SOLUTION_FILES = sorted(SOLUTIONS.glob("*.ipynb"))
LABS = sorted({t.lab for t in tasks()})


def _read(p):
    return nbformat.read(p, as_version=4)


def _lab_file(lab):
    files = [p for p in SOLUTION_FILES if _read(p).metadata.get("balancelab", {}).get("lab") == lab]
    assert len(files) == 1, (lab, files)
    return files[0]


# ------------------------------------------------------------------------- structure


def test_every_registered_lab_has_a_solution_and_a_student_version():
    assert len(SOLUTION_FILES) == len(LABS) >= 5
    for lab in LABS:
        sol = _lab_file(lab)
        assert (STUDENT / sol.name).exists()
        assert _read(STUDENT / sol.name).metadata["balancelab"] == {"lab": lab, "version": "student"}


@pytest.mark.parametrize("lab", LABS)
def test_lab_shape(lab):
    """A goal, a live explorer, 3-6 tasks with checks, at least one open design task."""
    nb = _read(_lab_file(lab))
    src = "\n".join(c.source for c in nb.cells)
    assert nb.cells[0].cell_type == "markdown" and "**Goal.**" in nb.cells[0].source
    assert "explore(" in src and ".widget" in src
    ts = tasks(lab)
    assert 3 <= len(ts) <= 6
    assert any(t.kind == "design" for t in ts)
    for t in ts:
        assert re.search(rf"^{re.escape(t.variable)}\s*=", src, re.M), t.variable
        assert f'check("{t.id}", {t.variable})' in src
        assert f"## Task {t.id}" in src


# -------------------------------------------------------------------- student versions


def test_committed_student_versions_are_exactly_what_the_generator_writes():
    assert labtools.stale(SOLUTIONS, STUDENT) == []
    for s in SOLUTION_FILES:
        assert (STUDENT / s.name).read_text(encoding="utf-8") == labtools.student_text(s)
    proc = subprocess.run([sys.executable, "-m", "balancelab.course.labtools", "check"], capture_output=True,
                          text=True, cwd=ROOT)
    assert proc.returncode == 0, proc.stdout + proc.stderr


@pytest.mark.parametrize("path", SOLUTION_FILES, ids=lambda p: p.stem)
def test_no_solution_text_survives(path):
    sol = _read(path)
    regions = labtools.solution_texts(sol)
    assert len(regions) >= 2 * len(tasks(sol.metadata["balancelab"]["lab"]))  # code + prose per task
    student = _read(STUDENT / path.name)
    text = "\n".join(c.source for c in student.cells)
    assert "BEGIN SOLUTION" not in text and "END SOLUTION" not in text
    assert "**Solution.**" not in text
    for region in regions:
        for line in region.splitlines():
            line = line.strip()
            if len(line) >= 6 and re.search(r"[A-Za-z0-9]", line):
                assert line not in text, line
    for c in student.cells:
        if c.cell_type == "code":
            assert c.outputs == [] and c.execution_count is None
    n_placeholders = text.count(labtools.PLACEHOLDER) + text.count("= ...  # your answer here")
    assert n_placeholders == sum(1 for c in sol.cells if c.cell_type == "code" and "# BEGIN SOLUTION" in c.source)
    for t in tasks(sol.metadata["balancelab"]["lab"]):  # every task's placeholder names its answer variable
        assert labtools.ANSWER_PLACEHOLDER.format(variable=t.variable) in text


def test_generator_rules():
    v4 = nbformat.v4
    nb = v4.new_notebook(cells=[
        v4.new_markdown_cell("Task.\n\n<!-- BEGIN SOLUTION -->\nsecret prose\n<!-- END SOLUTION -->\n\nAfter."),
        v4.new_markdown_cell("<!-- BEGIN SOLUTION -->only secret<!-- END SOLUTION -->"),
        v4.new_code_cell("def f(x):\n    y = 1\n    # BEGIN SOLUTION\n    return x * secret\n    # END SOLUTION\n"
                         "print(f)", outputs=[v4.new_output("stream", text="old")], execution_count=3),
        v4.new_code_cell("hidden = 42", metadata={"tags": ["solution"]}),
    ])
    before = copy.deepcopy(nb)
    out = labtools.student_version(nb)
    assert nb == before  # the source is not modified
    assert [c.cell_type for c in out.cells] == ["markdown", "code"]
    assert out.cells[0].source == "Task.\n\nAfter."
    assert out.cells[1].source == f"def f(x):\n    y = 1\n    {labtools.PLACEHOLDER}\nprint(f)"
    assert out.cells[1].outputs == [] and out.cells[1].execution_count is None
    texts = labtools.solution_texts(nb)
    assert any("secret prose" in t for t in texts) and any("hidden = 42" in t for t in texts)
    ns = {}
    exec(out.cells[1].source.replace("print(f)", ""), ns)
    with pytest.raises(NotImplementedError):
        ns["f"](1)


@pytest.mark.parametrize("source", [
    "# BEGIN SOLUTION\nx = 1\n",
    "x = 1\n# END SOLUTION\n",
    "# BEGIN SOLUTION\n# BEGIN SOLUTION\nx = 1\n# END SOLUTION\n",
])
def test_generator_rejects_unbalanced_markers(source):
    nb = nbformat.v4.new_notebook(cells=[nbformat.v4.new_code_cell(source)])
    with pytest.raises(labtools.MarkerError, match="cell 0"):
        labtools.student_version(nb, "broken.ipynb")


def test_generate_and_check_commands(tmp_path):
    src = tmp_path / "sol"
    src.mkdir()
    nbformat.write(_read(SOLUTION_FILES[0]), src / "a_lab.ipynb")
    dst = tmp_path / "stu"
    r = subprocess.run([sys.executable, "-m", "balancelab.course.labtools", "check", "--solutions", str(src),
                        "--student", str(dst)], capture_output=True, text=True)
    assert r.returncode == 1 and "stale" in r.stdout
    r = subprocess.run([sys.executable, "-m", "balancelab.course.labtools", "generate", "--solutions", str(src),
                        "--student", str(dst)], capture_output=True, text=True)
    assert r.returncode == 0 and (dst / "a_lab.ipynb").exists()
    assert labtools.stale(src, dst) == []


@pytest.mark.parametrize("path", SOLUTION_FILES, ids=lambda p: p.stem)
def test_student_version_runs_all_past_unanswered_tasks(path, tmp_path):
    """Run All goes through: no cell fails, every explorer runs, every check says "No answer yet"."""
    target = tmp_path / path.name
    target.write_text((STUDENT / path.name).read_text(encoding="utf-8"), encoding="utf-8")
    nb = labtools.execute_notebook(target, timeout=120, allow_errors=True, write=False)
    errors = [(i, o.ename) for i, c in enumerate(nb.cells) if c.cell_type == "code"
              for o in c.outputs if o.output_type == "error"]
    assert errors == []
    lab = nb.metadata["balancelab"]["lab"]
    shown = "\n".join(str(o.get("text", "")) + str(o.get("data", {}).get("text/plain", ""))
                      for c in nb.cells if c.cell_type == "code" for o in c.outputs)
    for t in tasks(lab):
        assert f"Task {t.id}: ✘ not yet. No answer yet." in shown
    explorers = [c for c in nb.cells if c.cell_type == "code" and c.source.rstrip().endswith(".widget")]
    assert explorers and all(any(labtools.WIDGET_MIME in o.get("data", {}) for o in c.outputs) for c in explorers)


# ---------------------------------------------------------------------------- nbval


def test_solution_notebooks_pass_nbval():
    """``pytest --nbval`` on every solution notebook, with the documented sanitization."""
    cmd = [sys.executable, "-m", "pytest", "--nbval", "--nbval-current-env",
           "--nbval-sanitize-with", str(ROOT / "labs" / "nbval_sanitize.cfg"),
           "-p", "no:cacheprovider", "-q", "-o", "addopts=", *map(str, SOLUTION_FILES)]
    proc = subprocess.run(cmd, capture_output=True, text=True, cwd=ROOT, timeout=900)
    assert proc.returncode == 0, proc.stdout[-4000:] + proc.stderr[-2000:]
    assert re.search(r"\d+ passed", proc.stdout)
    assert "failed" not in proc.stdout.splitlines()[-1]


# ------------------------------------------------------------------------- grading


@pytest.mark.parametrize("lab", ["lab1", "lab7", "lab8", "lab9"])
def test_grading_solution_and_student_versions(lab, tmp_path):
    """The trusted grader gives a solution full marks and the untouched student version none.

    The solution is graded as student ``s1``'s (its import cell set to that id, as a student sets
    it): a file whose id cannot be told scores 0 on the tasks with personal numbers."""
    sol = _lab_file(lab)
    mine = tmp_path / f"s1_{sol.name}"
    text = sol.read_text(encoding="utf-8")
    assert ('STUDENT_ID = \\"\\"' in text) == any(t.numbers is not None for t in tasks(lab))
    mine.write_text(text.replace('STUDENT_ID = \\"\\"', 'STUDENT_ID = \\"s1\\"'), encoding="utf-8")
    full = grade_notebook(mine, cell_timeout=120, student_id="s1")
    assert full.status == "graded" and full.total == full.max_total == sum(t.points for t in tasks(lab))
    empty = grade_notebook(STUDENT / sol.name, cell_timeout=120, student_id="s1")
    assert empty.status == "graded" and empty.total == 0 and empty.max_total == full.max_total
    assert all(m == "✘ No answer yet." for m in empty.messages.values())


# ------------------------------------------------------------ hand-out and autograder


def test_handout_has_no_solutions_and_autograder_has_them(tmp_path):
    out = tmp_path / "handout"
    r = subprocess.run([sys.executable, "-m", "balancelab.course.labtools", "handout", str(out)],
                       capture_output=True, text=True, cwd=ROOT)
    assert r.returncode == 0, r.stderr
    assert sorted(p.name for p in (out / "labs").glob("*.ipynb")) == [p.name for p in SOLUTION_FILES]
    assert (out / "package" / "balancelab" / "course" / "check" / "core.py").exists()
    assert (out / "package" / "pyproject.toml").exists() and "pip install" in (out / "README.md").read_text()
    # the grader's own modules (its sandbox, runner, table) are not the students' (issue 18)
    course = out / "package" / "balancelab" / "course"
    assert labtools.GRADER_MODULES and not [m for m in labtools.GRADER_MODULES if (course / m).exists()]
    every = [p for p in out.rglob("*") if p.is_file()]
    assert not any("solutions" in p.parts or p.suffix == ".pyc" for p in every)
    notebooks = "\n".join(p.read_text(encoding="utf-8") for p in every if p.suffix == ".ipynb")
    assert "BEGIN SOLUTION" not in notebooks and "**Solution.**" not in notebooks
    for s in SOLUTION_FILES:
        for region in labtools.solution_texts(_read(s)):
            for line in region.splitlines():
                if len(line.strip()) >= 12:
                    assert line.strip() not in notebooks, line
    r = subprocess.run([sys.executable, "-m", "balancelab.course.labtools", "handout", str(out)],
                       capture_output=True, text=True, cwd=ROOT)
    assert r.returncode == 2 and "not empty" in r.stderr
    grader = tmp_path / "autograder"
    assert labtools.autograder(grader) == grader
    assert sorted(p.name for p in (grader / "solutions").glob("*.ipynb")) == [p.name for p in SOLUTION_FILES]
    assert "balancelab.course.grading" in (grader / "README.md").read_text()
    assert all((grader / "package" / "balancelab" / "course" / m).exists() for m in labtools.GRADER_MODULES)


def test_execute_keeps_widget_ids_stable(tmp_path):
    path = tmp_path / "w.ipynb"
    nbformat.write(nbformat.v4.new_notebook(cells=[nbformat.v4.new_code_cell(
        "import ipywidgets\nipywidgets.IntSlider()")]), path)
    first = labtools.execute_notebook(path)
    text = path.read_text(encoding="utf-8")
    labtools.execute_notebook(path)
    assert path.read_text(encoding="utf-8") == text
    view = first.cells[0].outputs[0]["data"][labtools.WIDGET_MIME]
    assert view["model_id"] == labtools.stable_widget_id("w.ipynb", 0, 0)


def test_committed_solutions_carry_stable_widget_ids():
    for s in SOLUTION_FILES:
        nb = _read(s)
        for i, c in enumerate(nb.cells):
            for j, o in enumerate(c.get("outputs", [])):
                view = o.get("data", {}).get(labtools.WIDGET_MIME)
                if view:
                    assert view["model_id"] == labtools.stable_widget_id(s.name, i, j)


def test_lamp_explorer_reports_the_sliders_r_c():
    nb = _read(_lab_file("lab1"))
    src = next(c.source for c in nb.cells if c.source.startswith("def lamp_arm"))
    ns = {}
    exec("import balancelab as bl\n" + src.split("lamp_explorer =")[0], ns)
    for r_c in (0.1, 0.3):
        d = ns["lamp_arm"](r_c=r_c)
        assert d.parameters["r_c"] == r_c
        assert d.balance_report().balanced == (abs(r_c - 0.225) < 1e-12)


@pytest.mark.parametrize("lab, task", [("lab5", "5.1"), ("lab6", "6.1")])
def test_default_explorers_do_not_show_answers(lab, task):
    """The explorer's starting design is not the task's: its parameters do not hold the answer."""
    from balancelab.course.check import check

    nb = _read(_lab_file(lab))
    src = next(c.source for c in nb.cells if c.cell_type == "code" and "explore(" in c.source)
    ns = {}
    exec("import balancelab as bl\nfrom balancelab.methods.lecture import fourbar_two_springs\n"
         + src.split("_explorer =")[0].rsplit("\n", 1)[0], ns)
    fn = next(v for k, v in ns.items() if callable(v) and not k.startswith("_") and k not in ("bl",)
              and getattr(v, "__module__", None) is None)
    design = fn()
    shown = [v for v in design.parameters.values() if isinstance(v, (int, float))]
    assert not any(check(task, float(v)).correct for v in shown)


# ------------------------------------------------------- kinds of work, and derive tasks' shortcuts


def test_every_task_is_labelled_compute_derive_or_design_in_its_heading():
    """Issue 21, item 1: each task carries its kind of work, and the notebook's heading says the same."""
    from balancelab.course.check.core import SKILLS

    for lab in LABS:
        src = "\n".join(c.source for c in _read(_lab_file(lab)).cells if c.cell_type == "markdown")
        for t in tasks(lab):
            assert t.skill in SKILLS, t.id
            assert t.kind != "symbolic" or t.skill == "derive", t.id
            assert re.search(rf"^## Task {re.escape(t.id)} \({t.skill}[,)]", src, re.M), (t.id, t.skill)


def _run_cell(source):
    """Run ``source`` as one cell of a real IPython shell (history stored, as in a notebook)."""
    from IPython.core.interactiveshell import InteractiveShell

    shell = InteractiveShell.instance()
    result = shell.run_cell(source, store_history=True)
    assert result.error_in_exec is None, result.error_in_exec
    return shell.user_ns


#: For each derive task, what a student who reads the docstrings tries: the library call that
#: computes the answer (for the published numbers, or fed the task's symbols), in the graded cell.
SHORTCUT_CELLS = {
    "1.2": ['import balancelab as bl\nfrom balancelab.course.check import check\n'
            'r_c_formula = bl.lecture.single_link_counterweight(mass=1.2, length=0.45, counter_mass=3.0, '
            'link_mass=0.6).parameters["r_c"]\nverdict = check("1.2", r_c_formula)'],
    "2.2": ['import sympy as sp\nimport balancelab as bl\nfrom balancelab.course.check import check\n'
            'd = bl.singh.generalized_lever(weight=10.0, length=0.5, a_x=0.2, b_x=0.1, b_y=0.3)\n'
            'eqs = [e.lhs for e in d.balance_conditions()]\n'
            'syms = {str(s): s for e in eqs for s in e.free_symbols}\n'
            'sol = sp.solve(eqs, [syms["a_y"], syms["k"]], dict=True)\n'
            'sol = [s for s in sol if s[syms["k"]] != 0][0]\n'
            'lever_conditions = (sol[syms["a_y"]], sol[syms["k"]])\nverdict = check("2.2", lever_conditions)'],
    # the library's symbolic energy of the lever with a free length, differentiated
    "3.4": ['import sympy as sp\nfrom balancelab.course.check import check, lab2_lever\n'
            'V = lab2_lever(196.2, (0.2, 0.0), (0.0, 0.3), W=19.62, l=0.5, free_length=0.1).potential_energy_symbolic()\n'
            'free_length_torque = sp.diff(V, *[s for s in V.free_symbols if "theta" in str(s)])\n'
            'verdict = check("3.4", free_length_torque)'],
    "4.5": ['from balancelab.methods.singh import serial_2r_min_preload\nfrom balancelab.course.check import check\n'
            'pe_min_formula = serial_2r_min_preload().parameters["PE_min"]\nverdict = check("4.5", pe_min_formula)'],
    # the library's two-spring four-bar, its numeric rates handed in as the formulas
    "5.4": ['from balancelab.methods.lecture import fourbar_two_springs\nfrom balancelab.course.check import check\n'
            'd = fourbar_two_springs(coms=((0.15, 0.0), (0.4, 0.0), (0.3, 0.0)))\n'
            'fourbar_rates = (d.parameters["k2"], d.parameters["k4"])\nverdict = check("5.4", fourbar_rates)'],
    # the library's symbolic conditions of Singh's lift, solved for the rates
    "6.4": ['import sympy as sp\nimport balancelab as bl\nfrom balancelab.course.check import check\n'
            'eqs = [e.lhs for e in bl.singh.scissors_lift().balance_conditions()]\n'
            'syms = {str(s): s for e in eqs for s in e.free_symbols}\n'
            'sol = sp.solve(eqs[:2], [syms["k_1"], syms["k_2"]], dict=True)[0]\n'
            'stage_rates = (sol[syms["k_1"]], sol[syms["k_2"]])\nverdict = check("6.4", stage_rates)'],
    # the solver of chapter 7 on the published arm, its numeric rates handed in as the formulas
    "7.5": ['import balancelab as bl\n'
            'from balancelab.course.check import check\n'
            'from balancelab.course.check.lab7 import lab7_own_arm\n'
            'values = dict(g=9.81, m_1=1.5, p_1=0.2, l_1=0.4, m_2=1.0, p_2=0.15, m_L=0.5, l_2=0.35, a=0.2, s_1=0.15,\n'
            '              s_2=0.25, s_3=0.1, c=0.05)\n'
            'arm = lab7_own_arm("above", True, values)\n'
            'candidates = [((s.a.body, s.a.point), (s.b.body, s.b.point)) for s in arm.springs]\n'
            'own_rates = tuple(s.k for s in bl.balance(arm.replace(springs=[]), springs=candidates).springs)\n'
            'verdict = check("7.5", own_rates)\n'],
    "8.4": ['import numpy as np\nfrom balancelab.course.check import check, lab8\n'
            'from balancelab.methods.practice import forces\n'
            'torque_formula = float(forces.generalized_force(lab8.rate_error_arm(0.02), np.array([[0.0, 0.0]]))[1][0, 0])\n'
            'verdict = check("8.4", torque_formula)'],
    # the library's symbolic energy of the lecture's link, handed in as the arm (attack A21: 9.3 had none)
    "9.3": ['import balancelab as bl\nfrom balancelab.course.check import check\n'
            'arm_formula = bl.lecture.single_link_spring(2.0, 0.5, 0.3, 0.2).potential_energy_symbolic()\n'
            'verdict = check("9.3", arm_formula)'],
}


@pytest.mark.parametrize("tid", [t.id for t in tasks() if t.skill == "derive"])
def test_derive_tasks_refuse_the_obvious_library_call(tid):
    """Issue 21, item 2: the library call that gives a derive task's answer, made in the graded cell,
    is refused by the notebook's check (which names it); its value, as the grader reads it, scores 0."""
    from balancelab.course.check import core, data

    assert tid in SHORTCUT_CELLS, f"no shortcut tried for derive task {tid}"
    for cell in SHORTCUT_CELLS[tid]:
        ns = _run_cell(cell)
        verdict = ns["verdict"]
        assert not verdict.correct and verdict.score == 0, str(verdict)
        assert "derived by hand" in verdict.message and "calls" in verdict.message
        answer = ns[{t.id: t for t in tasks()}[tid].variable]
        if not isinstance(answer, tuple):  # a number where a formula is asked: the grader's judge refuses it
            assert not core.check_data(tid, data.encode_answer(answer)).correct


@pytest.mark.parametrize("call", [
    lambda s: __import__("balancelab").lecture.single_link_counterweight(
        mass=s("m"), length=s("r"), counter_mass=s("m_c"), link_mass=s("m_l")).parameters["r_c"],
    lambda s: __import__("balancelab").methods.singh.serial_2r_min_preload(
        weights=(s("W_1"), s("W_2")), coms=((s("p_x1"), s("p_y1")), (s("p_x2"), 0.0)), length=s("l")).parameters["PE_min"],
    lambda s: __import__("balancelab").course.check.lab8.rate_error_arm(s("epsilon")),
    lambda s: __import__("balancelab").lecture.fourbar_two_springs(masses=(s("m_2"), s("m_3"), s("m_4"))),
    lambda s: __import__("balancelab").singh.scissors_lift(length=s("a"), arm_mass=s("m_a"), payload_mass=s("M")),
    lambda s: __import__("balancelab").course.check.lab7.lab7_own_arm(
        "above", True, {n: s(n) for n in __import__("balancelab").course.check.lab7.LAB7_OWN_SYMBOLS}),
])
def test_the_library_does_not_derive_formulas_from_symbols(call):
    """The solvers a derive task disallows take numbers only: fed the task's sympy symbols, they refuse
    (so the formula cannot be had from them in any cell)."""
    import sympy as sp

    with pytest.raises((TypeError, ValueError)):
        call(lambda name: sp.Symbol(name, positive=True))


@pytest.mark.parametrize("lab", LABS)
def test_at_least_half_of_every_labs_points_are_derive_or_design(lab):
    ts = tasks(lab)
    assert 2 * sum(t.points for t in ts if t.skill != "compute") >= sum(t.points for t in ts), lab
    assert sum(t.points for t in ts if t.skill == "compute") <= sum(t.points for t in ts) / 2
