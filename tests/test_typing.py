"""Types and lint, from a user's seat: the package ships its hints (PEP 561), its public functions say
what they take and return, and the test command's mypy and ruff steps fail on a finding."""
from __future__ import annotations

import ast
import shutil
import subprocess
import sys
import tomllib
import zipfile
from pathlib import Path

import pytest

import balancelab as bl

ROOT = Path(__file__).resolve().parents[1]
PACKAGE = Path(bl.__file__).parent
#: public functions not fully annotated yet, ``module:qualname`` a line: this list may only shrink
TODO = Path(__file__).with_name("typing_todo.txt")


def _public_modules():
    for path in sorted(PACKAGE.rglob("*.py")):
        parts = path.relative_to(PACKAGE.parent).with_suffix("").parts
        if any(p.startswith("_") and p != "__init__" for p in parts):
            continue
        yield ".".join(parts[:-1] if parts[-1] == "__init__" else parts), path


def _signatures():
    """``(module:qualname, fully annotated?)`` of every public function and public class's method."""
    def visit(module, body, owner=""):
        for node in body:
            if isinstance(node, ast.ClassDef) and not node.name.startswith("_"):
                yield from visit(module, node.body, f"{owner}{node.name}.")
            elif isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef)):
                if node.name.startswith("_") and not (owner and node.name == "__init__"):
                    continue
                a = node.args
                params = a.posonlyargs + a.args + a.kwonlyargs + [p for p in (a.vararg, a.kwarg) if p]
                if owner and params and params[0].arg in ("self", "cls"):
                    params = params[1:]
                done = node.returns is not None and all(p.annotation is not None for p in params)
                yield f"{module}:{owner}{node.name}", done

    for module, path in _public_modules():
        yield from visit(module, ast.parse(path.read_text(encoding="utf-8")).body)


def _todo() -> set[str]:
    return {line.strip() for line in TODO.read_text(encoding="utf-8").splitlines()
            if line.strip() and not line.startswith("#")}


def test_every_new_public_function_is_fully_annotated():
    missing = sorted({name for name, done in _signatures() if not done} - _todo())
    assert not missing, ("public functions need a return annotation and an annotation on every "
                         f"parameter: {missing}")


def test_the_list_of_unannotated_functions_only_shrinks():
    now = dict(_signatures())
    stale = sorted(name for name in _todo() if now.get(name, True))
    assert not stale, f"annotated or gone: remove them from {TODO.name}: {stale}"


def test_the_core_is_fully_annotated():
    names = [name for name, _ in _signatures() if name.startswith("balancelab.core")]
    assert len(names) > 60  # the walk found the core's functions and methods
    assert not [n for n in _todo() if n.startswith("balancelab.core")]


def test_the_counting_sees_a_missing_annotation(tmp_path, monkeypatch):
    """The walk itself: a public function without hints is caught, a private one is not."""
    (tmp_path / "balancelab").mkdir()
    (tmp_path / "balancelab" / "mod.py").write_text(
        "def f(x) -> int: ...\ndef g(x: int): ...\ndef h(x: int) -> int: ...\ndef _p(x): ...\n"
        "class C:\n    def m(self, y: float) -> float: ...\n    def n(self, y): ...\n")
    monkeypatch.setattr(sys.modules[__name__], "PACKAGE", tmp_path / "balancelab")
    assert dict(_signatures()) == {"balancelab.mod:f": False, "balancelab.mod:g": False,
                                   "balancelab.mod:h": True, "balancelab.mod:C.m": True,
                                   "balancelab.mod:C.n": False}


def test_the_package_ships_py_typed_in_its_wheel(tmp_path):
    """PEP 561: type checkers read an installed balancelab's hints only when py.typed is in the wheel."""
    assert (PACKAGE / "py.typed").is_file()
    subprocess.run([sys.executable, "-m", "pip", "wheel", "--no-deps", "-q", "-w", str(tmp_path), str(ROOT)],
                   check=True, capture_output=True, timeout=600)
    wheel = next(tmp_path.glob("balancelab-*.whl"))
    assert "balancelab/py.typed" in zipfile.ZipFile(wheel).namelist()


def test_the_test_command_runs_the_linter_and_the_type_checker_and_installs_them():
    script = (ROOT / "scripts" / "course.sh").read_text()
    assert "set -euo pipefail" in script  # a failing step fails the command
    test_block = script[script.index("    test)"):script.index(";;", script.index("    test)"))]
    assert '"$PY" -m ruff check' in test_block and '"$PY" -m mypy' in test_block
    assert test_block.index("ruff") < test_block.index("pytest")  # before the tests
    config = tomllib.loads((ROOT / "pyproject.toml").read_text())
    extra = " ".join(config["project"]["optional-dependencies"]["test"])
    assert "ruff" in extra and "mypy" in extra
    assert config["tool"]["mypy"]["files"] == ["balancelab"]
    assert not config["tool"]["mypy"].get("ignore_errors")


def _project_tool(tool: str, target: Path) -> subprocess.CompletedProcess:
    exe = shutil.which(tool, path=str(Path(sys.executable).parent))
    if exe is None:
        pytest.fail(f"{tool} is not installed in this environment: install the test extra")
    args = [exe, "check", "--config", str(ROOT / "pyproject.toml"), str(target)] if tool == "ruff" else \
        [exe, "--config-file", str(ROOT / "pyproject.toml"), "--no-incremental", str(target)]
    return subprocess.run(args, capture_output=True, text=True, timeout=300, cwd=target.parent)


def test_ruff_fails_on_a_finding_and_passes_clean_code(tmp_path):
    bad = tmp_path / "bad.py"
    bad.write_text("import os\n\n\ndef f(x):\n    return x == None\n")
    run = _project_tool("ruff", bad)
    assert run.returncode != 0 and "F401" in run.stdout and "E711" in run.stdout, run.stdout
    good = tmp_path / "good.py"
    good.write_text("def f(x: int) -> int:\n    return x + 1\n")
    assert _project_tool("ruff", good).returncode == 0


def test_mypy_fails_on_a_type_error(tmp_path):
    bad = tmp_path / "bad.py"
    bad.write_text("def f(x: int) -> str:\n    return x\n\n\ndef g():\n    y: int = 'no'\n    return y\n")
    run = _project_tool("mypy", bad)
    assert run.returncode != 0, run.stdout
    assert "bad.py:2" in run.stdout and "bad.py:6" in run.stdout, run.stdout  # untyped bodies are checked too
