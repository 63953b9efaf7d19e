"""The GitHub action (``action.yml``): workflows using it pass ``actionlint``, and its
steps, run by bash as the runner runs them, drive the real ``moos-lint``."""

from __future__ import annotations

import json
import os
import re
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

yaml = pytest.importorskip("yaml", reason="PyYAML (a pre-commit dependency) is missing")

ROOT = Path(__file__).resolve().parent.parent
ACTION = ROOT / "action.yml"

WORKFLOW = """\
name: moos-lint
on: [push, pull_request]
permissions:
  contents: read
  security-events: write
jobs:
  lint:
    runs-on: ubuntu-latest
    steps:
      - uses: actions/checkout@v4
      - uses: ./
        id: lint
        with:
          paths: missions src
          format: github
          version: moos-lint==0.1.0
          args: --select ALL -D VNAME=abe
          sarif: "true"
          sarif-category: missions
      - run: echo "${{ steps.lint.outputs.sarif-file }}"
"""


def _actionlint() -> str:
    found = shutil.which("actionlint") or shutil.which(
        "actionlint", path=os.path.dirname(sys.executable)
    )
    if found is None:
        pytest.skip(
            "actionlint is not installed (go install github.com/rhysd/actionlint/cmd/actionlint)"
        )
    return found


def _lint_workflows(tmp_path: Path, workflows: dict[str, str]) -> subprocess.CompletedProcess:
    """``actionlint`` over ``workflows`` in a repository whose root holds ``action.yml``."""
    shutil.copy(ACTION, tmp_path / "action.yml")
    (tmp_path / ".git").mkdir()  # where actionlint finds the repository's root
    folder = tmp_path / ".github" / "workflows"
    folder.mkdir(parents=True)
    for name, text in workflows.items():
        (folder / name).write_text(text)
    proc = subprocess.run(
        [_actionlint(), "-no-color", "-shellcheck=", "-pyflakes="],
        cwd=tmp_path,
        capture_output=True,
        text=True,
        timeout=60,
    )
    if proc.returncode not in (0, 1):
        pytest.skip(f"actionlint could not run: {proc.stderr[-300:]}")
    return proc


def _readme_workflows() -> dict[str, str]:
    text = (ROOT / "README.md").read_text(encoding="utf-8")
    blocks = re.findall(r"```yaml\n(# \.github/workflows/.*?)```", text, re.S)
    assert len(blocks) >= 2  # with the action, and by hand
    return {f"readme-{i}.yml": block for i, block in enumerate(blocks)}


def test_workflows_using_the_action_pass_actionlint(tmp_path: Path):
    proc = _lint_workflows(tmp_path, {"lint.yml": WORKFLOW, **_readme_workflows()})
    assert proc.returncode == 0, proc.stdout + proc.stderr


def test_actionlint_reads_the_action_s_inputs(tmp_path: Path):
    """An input the action does not have is an error: actionlint did read action.yml."""
    proc = _lint_workflows(tmp_path, {"lint.yml": WORKFLOW.replace("format:", "formt:")})
    assert proc.returncode == 1 and "formt" in proc.stdout


def _step(name: str) -> dict:
    steps = yaml.safe_load(ACTION.read_text(encoding="utf-8"))["runs"]["steps"]
    return next(s for s in steps if s.get("name") == name)


def _run_step(name: str, tmp_path: Path, **env: str) -> subprocess.CompletedProcess:
    """A ``run:`` step of the action as the runner runs it: bash, with its env set."""
    step = _step(name)
    assert step["shell"] == "bash"
    assert "${{" not in step["run"]  # inputs reach the script through env only
    path = os.path.dirname(sys.executable) + os.pathsep + os.environ["PATH"]
    return subprocess.run(
        ["bash", "-e", "-c", step["run"]],
        cwd=ROOT,
        env={**os.environ, "PATH": path, "GITHUB_OUTPUT": str(tmp_path / "out"), **env},
        capture_output=True,
        text=True,
    )


def test_the_lint_step_runs_moos_lint(tmp_path: Path):
    proc = _run_step(
        "moos-lint",
        tmp_path,
        MOOS_LINT_PATHS="docs/example",
        MOOS_LINT_ARGS="--ignore M005 --no-cache",
        MOOS_LINT_FORMAT="github",
    )
    assert proc.returncode == 1, proc.stderr  # findings fail the job
    assert "::warning file=docs/example/alpha.moos,line=26" in proc.stdout
    assert "DEPOLY" not in proc.stdout  # the extra arguments were passed
    clean = _run_step(
        "moos-lint",
        tmp_path,
        MOOS_LINT_PATHS="fixtures/graph docs/*",
        MOOS_LINT_ARGS="",
        MOOS_LINT_FORMAT="concise",
    )
    # `docs/*` is a path that does not exist (never a glob): a usage error, nothing linted
    assert clean.returncode == 2 and clean.stdout == ""
    assert "docs/*: no such file or directory" in clean.stderr


def test_the_sarif_step_writes_a_report_and_an_output(tmp_path: Path):
    sarif = tmp_path / "moos-lint.sarif"
    proc = _run_step(
        "moos-lint (SARIF)",
        tmp_path,
        MOOS_LINT_PATHS="docs/example",
        MOOS_LINT_ARGS="--no-cache",
        MOOS_LINT_SARIF=str(sarif),
    )
    assert proc.returncode == 0, proc.stderr  # --exit-zero: the upload still runs
    report = json.loads(sarif.read_text())
    assert report["version"] == "2.1.0" and len(report["runs"][0]["results"]) == 2
    assert (tmp_path / "out").read_text() == f"file={sarif}\n"
