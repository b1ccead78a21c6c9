"""The README's commands and example stay true."""
from __future__ import annotations

import re
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
README = (ROOT / "README.md").read_text()


def test_readme_python_example_runs_and_reports_balanced(capsys):
    blocks = re.findall(r"```python\n(.*?)```", README, flags=re.S)
    assert blocks, "README has no python example"
    exec(compile(blocks[0], "README.md", "exec"), {})
    assert capsys.readouterr().out.startswith("balanced")


def test_ci_runs_the_readme_test_command():
    commands = re.findall(r"^(bash scripts/course\.sh \w+)", README, flags=re.M)
    assert "bash scripts/course.sh book" in commands and "bash scripts/course.sh test" in commands
    assert "bash scripts/course.sh test" in (ROOT / ".ci" / "run").read_text()
