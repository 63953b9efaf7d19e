"""moos-lint leaves out what git ignores, in a real git repository, driving the real program.

git is used only to make the repository and to give its own answer to compare with;
moos-lint never runs it.
"""

from __future__ import annotations

import os
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

pytestmark = pytest.mark.skipif(shutil.which("git") is None, reason="needs git")

#: each file has one finding, so the concise report names every file linted
MISSION = "ServerPort = 9000\nCommunity = alpha\n\nProcessConfig = uXMS\n{\n  BogusKey = 1\n}\n"
BEHAVIORS = "Behavior = BHV_Waypoint\n{\n  name = w\n  bogus_param = 3\n}\n"


def _git(repo: Path, *args: str) -> str:
    env = {**os.environ, "GIT_CONFIG_NOSYSTEM": "1", "HOME": str(repo.parent)}
    return subprocess.run(
        ["git", "-C", str(repo), *args], check=True, capture_output=True, text=True, env=env
    ).stdout


def _lint(cwd: Path, *args: str, home: Path | None = None) -> list[str]:
    """The files a real run reported on (each has a finding), relative to ``cwd``."""
    env = {**os.environ, "HOME": str(home or cwd.parent)}
    env.pop("XDG_CONFIG_HOME", None)
    proc = subprocess.run(
        [sys.executable, "-m", "moos_lint", "check", "--output-format", "concise", *args],
        cwd=cwd,
        capture_output=True,
        text=True,
        env=env,
    )
    assert proc.returncode in (0, 1), proc.stderr
    return sorted({line.split(":", 1)[0] for line in proc.stdout.splitlines()})


def _count(cwd: Path, *args: str) -> str:
    """The summary line of a real text run (with the result cache and replay on)."""
    env = {**os.environ, "HOME": str(cwd.parent)}
    proc = subprocess.run(
        [sys.executable, "-m", "moos_lint", *args], cwd=cwd, capture_output=True, text=True, env=env
    )
    assert proc.returncode in (0, 1), proc.stderr
    return proc.stdout.strip().splitlines()[-1]


@pytest.fixture
def repo(tmp_path: Path) -> Path:
    root = tmp_path / "missions"
    (root / "alpha").mkdir(parents=True)
    (root / "generated").mkdir()
    (root / "alpha" / "alpha.moos").write_text(MISSION)
    (root / "alpha" / "targ_alpha.moos").write_text(MISSION)
    (root / "alpha" / "targ_alpha.bhv").write_text(BEHAVIORS)
    (root / "alpha" / "meta.bhv").write_text(BEHAVIORS)
    (root / "alpha" / "launch.sh").write_text("pAntler targ_alpha.moos\n")
    (root / "generated" / "out.moos").write_text(MISSION)
    (root / ".gitignore").write_text("targ_*.moos\ntarg_*.bhv\ngenerated/\n")
    _git(root, "init", "-q")
    return root


def test_git_ignored_files_are_left_out(repo: Path):
    assert _lint(repo) == ["alpha/alpha.moos", "alpha/meta.bhv"]
    assert _count(repo) == "Found 2 findings in 2 file(s)."


def test_no_respect_gitignore_lints_everything(repo: Path):
    every = [
        "alpha/alpha.moos",
        "alpha/meta.bhv",
        "alpha/targ_alpha.bhv",
        "alpha/targ_alpha.moos",
        "generated/out.moos",
    ]
    assert _lint(repo, "--no-respect-gitignore") == every
    (repo / "moos-lint.toml").write_text("respect-gitignore = false\n")
    assert _lint(repo) == every
    assert _lint(repo, "--respect-gitignore") == ["alpha/alpha.moos", "alpha/meta.bhv"]


def test_a_file_named_on_the_command_line_is_linted(repo: Path):
    assert _lint(repo, "alpha/targ_alpha.moos") == ["alpha/targ_alpha.moos"]
    # a folder named there is walked; what is ignored below it is still left out
    assert _lint(repo, "alpha") == ["alpha/alpha.moos", "alpha/meta.bhv"]
    assert _lint(repo, "generated") == ["generated/out.moos"]
    assert _lint(repo / "alpha") == ["alpha.moos", "meta.bhv"]


def test_negation_nested_ignore_files_and_dot_ignore(repo: Path):
    (repo / "alpha" / ".gitignore").write_text("!targ_alpha.moos\n")
    (repo / ".ignore").write_text("meta.bhv\n")
    assert _lint(repo) == ["alpha/alpha.moos", "alpha/targ_alpha.moos"]


def test_info_exclude_and_global_excludes(repo: Path, tmp_path: Path):
    (repo / ".git" / "info").mkdir(exist_ok=True)
    (repo / ".git" / "info" / "exclude").write_text("meta.bhv\n")
    home = tmp_path / "home"
    home.mkdir()
    (home / "excludes").write_text("alpha.moos\n")
    (home / ".gitconfig").write_text(f"[core]\n\texcludesFile = {home / 'excludes'}\n")
    assert _lint(repo, home=home) == []
    assert _lint(repo, home=tmp_path) == ["alpha/alpha.moos"]


def test_outside_git_only_dot_ignore_counts(tmp_path: Path):
    root = tmp_path / "plain"
    root.mkdir()
    (root / "a.moos").write_text(MISSION)
    (root / "targ_a.moos").write_text(MISSION)
    (root / "launch.sh").write_text("pAntler targ_a.moos\n")
    (root / ".gitignore").write_text("targ_*.moos\n")
    assert _lint(root) == ["a.moos", "targ_a.moos"]
    (root / ".ignore").write_text("targ_*.moos\n")
    assert _lint(root) == ["a.moos"]


def test_agrees_with_git(repo: Path):
    """moos-lint's answer is git's own, on a mix of patterns."""
    (repo / "deep" / "keep").mkdir(parents=True)
    (repo / "deep" / "drop").mkdir()
    (repo / "tools" / "sub").mkdir(parents=True)
    for rel in (
        "deep/keep/a.moos",
        "deep/drop/b.moos",
        "deep/c.moos",
        "deep/d.bhv",
        "e.moos",
        "tools/x.moos",
        "tools/y.moos",
        "tools/sub/z.moos",
    ):
        (repo / rel).write_text(MISSION)
    (repo / "deep" / ".gitignore").write_text("*\n!*/\n!keep/**\n!d.bhv\n")
    (repo / ".gitignore").write_text(
        (repo / ".gitignore").read_text() + "/e.moos\n**/drop/\ntools/**\n!tools/x.moos\n"
    )
    git_says = _git(repo, "ls-files", "--others", "--exclude-standard")
    lintable = sorted(p for p in git_says.split() if p.endswith((".moos", ".bhv")))
    assert _lint(repo) == lintable
    assert "deep/keep/a.moos" in lintable and "deep/d.bhv" in lintable
    assert "tools/x.moos" in lintable and "tools/y.moos" not in lintable


def test_a_changed_gitignore_invalidates_the_warm_run(repo: Path, tmp_path: Path):
    cache = tmp_path / "cache"
    args = ("check", "--cache-dir", str(cache))
    assert _count(repo, *args) == "Found 2 findings in 2 file(s)."
    assert _count(repo, *args) == "Found 2 findings in 2 file(s)."  # replayed
    (repo / ".gitignore").write_text("generated/\n")  # the targ_ files come back
    assert _count(repo, *args) == "Found 4 findings in 4 file(s)."
    # a new ignore file in a parent of a walked folder counts too
    (repo / "alpha" / ".ignore").write_text("targ_alpha.bhv\n")
    assert _count(repo, *args) == "Found 3 findings in 3 file(s)."
