"""The forge files: tests run on every merge request, and the package metadata names the repository
that ``_config.yml`` names (the one place the repository is configured). The schema linter of every
CI file is in tests/test_book.py (test_ci_files_pass_their_schema_linter)."""
from __future__ import annotations

from pathlib import Path
from urllib.parse import urlsplit

import pytest
import yaml

tomllib = pytest.importorskip("tomllib")   # Python >= 3.11

ROOT = Path(__file__).resolve().parents[1]
TEST_COMMAND = "bash scripts/course.sh test"


def _on(workflow: dict) -> dict:
    return workflow.get("on", workflow.get(True))   # YAML 1.1 reads the key `on` as True


def test_github_runs_the_test_command_on_pull_requests_and_branches():
    wf = yaml.safe_load((ROOT / ".github/workflows/tests.yml").read_text())
    on = _on(wf)
    assert "pull_request" in on
    assert on["push"]["branches-ignore"] == ["main"]       # main: pages.yml tests, then publishes
    assert wf["permissions"] == {"contents": "read"}       # a pull request's code gets no write token
    (job,) = wf["jobs"].values()
    assert job["timeout-minutes"] <= 90
    assert any(TEST_COMMAND in step.get("run", "") for step in job["steps"])
    assert TEST_COMMAND in (ROOT / "README.md").read_text()


def test_gitlab_runs_the_test_command_on_merge_requests_and_branches():
    ci = yaml.safe_load((ROOT / ".gitlab-ci.yml").read_text())
    job = ci["test"]
    assert job["script"] == [TEST_COMMAND]
    conditions = [rule["if"] for rule in job["rules"]]
    assert '$CI_PIPELINE_SOURCE == "merge_request_event"' in conditions
    assert any("$CI_COMMIT_BRANCH != $CI_DEFAULT_BRANCH" in c for c in conditions)
    assert ci["pages"]["rules"] == [{"if": "$CI_COMMIT_BRANCH == $CI_DEFAULT_BRANCH"}]


def test_package_metadata_names_the_configured_repository_and_its_site():
    project = tomllib.loads((ROOT / "pyproject.toml").read_text())["project"]
    repo = yaml.safe_load((ROOT / "_config.yml").read_text())["repository"]["url"].rstrip("/")
    owner, name = urlsplit(repo).path.strip("/").split("/")
    urls = project["urls"]
    assert urls["Source"] == repo and urls["Issues"] == f"{repo}/issues"
    assert urls["Homepage"] == urls["Documentation"] == f"https://{owner}.github.io/{name}/"
    assert project["authors"] and all(a.get("name") for a in project["authors"])
    # the classifiers say only what is tested: the Python versions requires-python allows
    assert "Programming Language :: Python :: 3" in project["classifiers"]
    assert project["requires-python"] == ">=3.10"
