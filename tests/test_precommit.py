"""The pre-commit hook, run by the real pre-commit, offline.

The hook's repository is a fresh git repository holding this project's
package files (so the test sees the working tree, committed or not). A
project repository uses it the way `pre-commit try-repo` does: a config naming
the hook repository's path and commit. pip installs it into pre-commit's
virtualenv from a local wheelhouse built from the installed environment, with
the package index switched off. The hook is installed once for all tests
(`try-repo` would install it again on every call: a minute on a slow machine).
"""

from __future__ import annotations

import os
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

from tests import wheelhouse

REPO = Path(__file__).resolve().parents[1]
HOOK_FILES = ("pyproject.toml", "README.md", ".pre-commit-hooks.yaml", "LICENSE")

pytestmark = pytest.mark.skipif(shutil.which("git") is None, reason="git is not installed")


def _git(cwd: Path, *args: str) -> None:
    subprocess.run(
        [
            "git",
            "-c",
            "user.name=moos-lint tests",
            "-c",
            "user.email=tests@moos-lint.invalid",
            "-c",
            "commit.gpgsign=false",
            "-c",
            "init.defaultBranch=main",
            *args,
        ],
        cwd=cwd,
        check=True,
        capture_output=True,
    )


def _hook_repo(dest: Path) -> Path:
    dest.mkdir()
    for name in HOOK_FILES:
        if (REPO / name).is_file():
            shutil.copy2(REPO / name, dest / name)
    shutil.copytree(
        REPO / "moos_lint", dest / "moos_lint", ignore=shutil.ignore_patterns("__pycache__")
    )
    _git(dest, "init", "-q")
    _git(dest, "add", "-A")
    _git(dest, "commit", "-q", "-m", "hook repository")
    return dest


MISSION = """\
ServerPort = 9000
Community  = alpha

ProcessConfig = ANTLER
{{
  Run = MOOSDB   @ NewConsole = false
  Run = pLogger  @ NewConsole = false
}}

ProcessConfig = pLogger
{{
  AsyncLog = true
}}
#include "{plug}"
"""


@pytest.fixture(scope="module")
def env(tmp_path_factory):
    pytest.importorskip("pre_commit", reason="pre-commit is not installed (dev extra)")
    pytest.importorskip("virtualenv", reason="virtualenv (a pre-commit dependency) is missing")
    base = tmp_path_factory.mktemp("precommit")
    try:
        wheels = wheelhouse.build("moos-lint", base / "wheels")
    except wheelhouse.WheelhouseError as exc:
        pytest.skip(f"cannot build an offline wheelhouse: {exc}")
    hook_repo = _hook_repo(base / "hook-repo")
    project = base / "project"
    project.mkdir()
    _git(project, "init", "-q")
    environ = {
        k: v
        for k, v in os.environ.items()
        if not k.startswith(("PIP_", "PRE_COMMIT", "VIRTUALENV_", "GIT_"))
    }
    environ.update(
        PRE_COMMIT_HOME=str(base / "cache"),
        PIP_NO_INDEX="1",
        PIP_FIND_LINKS=str(wheels),
        PIP_DISABLE_PIP_VERSION_CHECK="1",
        VIRTUALENV_NO_PERIODIC_UPDATE="1",
        VIRTUALENV_NO_DOWNLOAD="1",
        PYTHONDONTWRITEBYTECODE="1",
    )
    rev = subprocess.run(
        ["git", "rev-parse", "HEAD"], cwd=hook_repo, capture_output=True, text=True, check=True
    ).stdout.strip()
    config = base / "pre-commit-config.yaml"
    config.write_text(
        f"repos:\n- repo: {hook_repo.as_posix()}\n  rev: {rev}\n  hooks:\n  - id: moos-lint\n"
    )
    env = {"hook_repo": hook_repo, "project": project, "environ": environ, "config": config}
    installed = _pre_commit(env, "install-hooks")
    assert installed.returncode == 0, installed.stdout + installed.stderr
    return env


def _pre_commit(env, *args: str) -> subprocess.CompletedProcess:
    return subprocess.run(
        [sys.executable, "-m", "pre_commit", *args, "--config", str(env["config"])],
        cwd=env["project"],
        env=env["environ"],
        capture_output=True,
        text=True,
        timeout=300,
    )


def _run_hook(env, *files: str) -> subprocess.CompletedProcess:
    return _pre_commit(env, "run", "moos-lint", "--color=never", "--files", *files)


def test_hook_fails_on_a_bad_file_and_passes_on_a_good_one(env):
    project = env["project"]
    (project / "good.moos").write_text("ServerPort = 9000\nCommunity = alpha\n")
    (project / "bad.moos").write_text("ProcessConfig = pLogger {\n  AsyncLog = true\n}\n")
    bad = _run_hook(env, "bad.moos")
    out = bad.stdout + bad.stderr
    assert bad.returncode == 1, out
    assert "R003" in out and "bad.moos:1:" in out, out
    good = _run_hook(env, "good.moos")
    assert good.returncode == 0, good.stdout + good.stderr
    assert "Passed" in good.stdout


def test_hook_lints_a_changed_fragment_inside_its_mission(env):
    """pre-commit passes only the fragment; its mission makes the fragment's block a duplicate."""
    project = env["project"]
    (project / "plugs").mkdir(exist_ok=True)
    (project / "plugs" / "logger.plug").write_text(
        "ProcessConfig = pLogger\n{\n  AsyncLog = false\n}\n"
    )
    (project / "mission.moos").write_text(MISSION.format(plug="plugs/logger.plug"))
    res = _run_hook(env, "plugs/logger.plug")
    out = res.stdout + res.stderr
    assert res.returncode == 1, out
    assert "R011" in out and "logger.plug:1:" in out, out


# ------------------------------------------------------------------ the hook's manifest


EXTENSIONS = (".moos", ".moos++", ".plug", ".def", ".bhv", ".cpp", ".cc", ".cxx", ".h", ".hpp")


def test_manifest_declares_the_hook():
    pytest.importorskip("pre_commit", reason="pre-commit is not installed (dev extra)")
    import re

    from pre_commit.clientlib import load_manifest

    (hook,) = load_manifest(str(REPO / ".pre-commit-hooks.yaml"))
    assert hook["id"] == "moos-lint"
    assert hook["language"] == "python"
    assert hook["require_serial"] is True
    assert hook["entry"].split()[:3] == ["moos-lint", "check", "--context"]
    pattern = re.compile(hook["files"])
    for ext in EXTENSIONS:
        assert pattern.search(f"dir/file{ext}"), ext
    for other in ("notes.txt", "file.moos.bak", "x.py", "plug"):
        assert not pattern.search(other), other


def test_try_repo_runs_the_hook_from_this_repository(env):
    """`pre-commit try-repo`, the way a user tries the hook before adding it to a config."""
    project = env["project"]
    (project / "try_bad.moos").write_text("ProcessConfig = pHelmIvP {\n}\n")
    res = subprocess.run(
        [
            sys.executable,
            "-m",
            "pre_commit",
            "try-repo",
            str(env["hook_repo"]),
            "moos-lint",
            "--color=never",
            "--files",
            "try_bad.moos",
        ],
        cwd=project,
        env=env["environ"],
        capture_output=True,
        text=True,
        timeout=600,
    )
    out = res.stdout + res.stderr
    assert res.returncode == 1, out
    assert "R003" in out and "try_bad.moos:1:" in out, out
