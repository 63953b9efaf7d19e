"""Colour and progress, driving the real ``moos-lint`` program in a pseudo-terminal."""

from __future__ import annotations

import os
import subprocess
import sys
from pathlib import Path

import pytest

pexpect = pytest.importorskip("pexpect")

MISSION = "ServerPort = 9000\nCommunity = alpha\n\nProcessConfig = uXMS\n{\n  BogusKey = 1\n}\n"
#: enough files for a cold run to last well over the second progress waits for
MANY = 2000
ESC = "\x1b["


def _env(**extra: str) -> dict:
    env = {k: v for k, v in os.environ.items() if k not in ("NO_COLOR", "FORCE_COLOR")}
    env.update(TERM="xterm", COLUMNS="200", **extra)
    return env


def _tty(cwd: Path, *args: str, **env: str) -> str:
    """What ``moos-lint ARGS`` writes to a terminal (stdout and stderr)."""
    child = pexpect.spawn(
        sys.executable,
        ["-m", "moos_lint", *args],
        cwd=str(cwd),
        env=_env(**env),
        encoding="utf-8",
        timeout=120,
        dimensions=(50, 200),
    )
    child.expect(pexpect.EOF)
    child.close()
    assert child.exitstatus in (0, 1), child.before
    return child.before


def _piped(cwd: Path, *args: str, **env: str) -> subprocess.CompletedProcess:
    return subprocess.run(
        [sys.executable, "-m", "moos_lint", *args],
        cwd=cwd,
        env=_env(**env),
        capture_output=True,
        text=True,
    )


@pytest.fixture
def mission(tmp_path: Path) -> Path:
    (tmp_path / "alpha.moos").write_text(MISSION)
    return tmp_path


def test_colour_on_a_terminal_only(mission: Path):
    out = _tty(mission, "check", "--no-cache")
    assert f"{ESC}1malpha.moos{ESC}0m{ESC}36m:{ESC}0m6" in out  # the path, bold
    assert f"{ESC}1;31mM001{ESC}0m [unknown-parameter]" in out  # the code, bold red
    assert f"{ESC}1;31m^^^^^^^^{ESC}0m" in out  # the caret
    piped = _piped(mission, "check", "--no-cache")
    assert piped.returncode == 1 and ESC not in piped.stdout
    assert "alpha.moos:6:3: M001 [unknown-parameter]" in piped.stdout


def test_no_color_force_color_and_the_option(mission: Path):
    assert ESC not in _tty(mission, "check", "--no-cache", NO_COLOR="1")
    assert ESC not in _tty(mission, "check", "--no-cache", "--color", "never")
    assert ESC in _piped(mission, "check", "--no-cache", FORCE_COLOR="1").stdout
    assert ESC in _piped(mission, "check", "--no-cache", "--color", "always").stdout
    concise = _piped(mission, "check", "--no-cache", "--color=always", "--output-format=concise")
    assert f"{ESC}1;31mM001{ESC}0m" in concise.stdout
    # machine formats are never coloured
    assert ESC not in _tty(mission, "check", "--no-cache", "--output-format", "json")


def test_colour_is_not_replayed_to_a_pipe(mission: Path, tmp_path: Path):
    cache = str(tmp_path / "cache")
    assert ESC in _tty(mission, "check", "--cache-dir", cache)
    assert ESC not in _piped(mission, "check", "--cache-dir", cache).stdout
    assert ESC in _tty(mission, "check", "--cache-dir", cache)


@pytest.fixture(scope="module")
def big(tmp_path_factory) -> Path:
    """A large folder that is no project: no config, no repository."""
    root = tmp_path_factory.mktemp("unsorted")
    for i in range(MANY):
        (root / f"m{i}.moos").write_text(MISSION.replace("alpha", f"a{i}"))
    return root


def test_progress_and_announcement_on_a_terminal(big: Path):
    out = _tty(
        big,
        "check",
        "--no-cache",
        "-j",
        "1",
        "--output-format",
        "concise",
        NO_COLOR="1",
        MOOS_LINT_PROGRESS_DELAY="0",  # shown from the start, however fast the machine
    )
    first = out.index("m0.moos:6:3")
    notice = f"moos-lint: linting {MANY} files under {big} "
    assert out.index(notice) < first
    progress = out[:first]
    assert f"\r{ESC}Kmoos-lint: checking " in progress
    assert f"/{MANY} files" in progress
    assert progress.endswith(f"\r{ESC}K")  # cleared before the report


def test_no_progress_off_a_terminal_in_ci_formats_or_when_warm(big: Path, tmp_path: Path):
    github = _tty(big, "check", "--no-cache", "--output-format", "github")
    assert "moos-lint:" not in github and "::warning file=m0.moos" in github
    cache = str(tmp_path / "cache")
    cold = _piped(big, "check", "--cache-dir", cache, "--output-format", "concise")
    assert cold.returncode == 1 and cold.stderr == ""
    warm = _tty(big, "check", "--cache-dir", cache, "--output-format", "concise", NO_COLOR="1")
    assert "moos-lint:" not in warm and "m0.moos:6:3" in warm
