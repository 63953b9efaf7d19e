"""Nothing a linted repository contains starts a GitHub Actions workflow command.

GitHub's runner reads every line of a job's output that starts with ``::`` as a
command (``::error``, ``::add-mask::``, ``::stop-commands::``...). File names
and messages come from the repository: a name with a line break and
``::error`` in it, or a key written ``::error::...``, must stay data in every
format.
"""

from __future__ import annotations

import io
import re
from contextlib import redirect_stderr, redirect_stdout

import pytest

from moos_lint.commands.cli import main
from moos_lint.commands.output import FORMATS, inert, shown_path

# GitHub's runner splits a log on CR and LF.
LINE_BREAK = re.compile(r"\r\n|\r|\n")
NAME = "a\n::error title=forged::injected.moos"
MISSION = """\
ProcessConfig = pHelmIvP
{
  ::error title=forged::from-file = 1
}
ProcessConfig = pHelmIvP
{
}
"""


@pytest.fixture
def tree(tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    monkeypatch.setenv("GITHUB_ACTIONS", "true")
    (tmp_path / ".git").mkdir()
    (tmp_path / NAME).write_text(MISSION)
    (tmp_path / "::warning::second.moos").write_text(MISSION)
    return tmp_path


def lint(*args: str) -> str:
    out, err = io.StringIO(), io.StringIO()
    with redirect_stdout(out), redirect_stderr(err):
        main(["check", "--no-cache", "--select", "ALL", *args, "."])
    return out.getvalue() + err.getvalue()


@pytest.mark.parametrize("fmt", [f for f in FORMATS if f != "github"])
def test_no_line_starts_a_workflow_command(tree, fmt):
    out = lint("--output-format", fmt)
    assert "forged" in out  # the findings are there...
    for line in LINE_BREAK.split(out):
        assert not line.lstrip(" \t").startswith("::"), line  # ...and inert


def github_commands(out: str) -> list[str]:
    lines = [line for line in LINE_BREAK.split(out) if line]
    for line in lines:
        assert re.match(r"::(error|warning|notice) file=[^,:]+,line=\d+,", line), line
    return lines


def test_github_format_has_one_command_per_finding(tree):
    commands = github_commands(lint("--output-format", "github"))
    concise = [line for line in LINE_BREAK.split(lint("--output-format", "concise")) if line]
    assert len(commands) == len(concise) >= 4
    assert any(c.startswith("::error file=a%0A%3A%3Aerror title=forged%3A%3A") for c in commands)


def test_default_format_on_github_actions_is_github(tree):
    assert github_commands(lint()) == github_commands(lint("--output-format", "github"))


def test_helpers_keep_names_on_one_line(tmp_path):
    assert inert("x\r\n::error::y\u2028z") == "x\\r\\n::error::y\\u2028z"
    assert shown_path(str(tmp_path / "::e.moos"), str(tmp_path)) == "./::e.moos"
    assert shown_path(str(tmp_path / "a\nb"), str(tmp_path)) == "a\\nb"
