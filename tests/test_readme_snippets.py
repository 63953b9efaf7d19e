"""The copy-paste snippets of the README parse, and name options the CLI has."""

from __future__ import annotations

import re
from pathlib import Path

import pytest

from moos_lint.commands.cli import build_parser

README = Path(__file__).resolve().parents[1] / "README.md"


def blocks(lang: str) -> list[str]:
    return re.findall(rf"```{lang}\n(.*?)```", README.read_text(encoding="utf-8"), re.S)


def test_yaml_snippets_parse():
    yaml = pytest.importorskip("yaml", reason="PyYAML (a pre-commit dependency) is missing")
    snippets = blocks("yaml")
    assert len(snippets) >= 3  # pre-commit, GitHub Actions, GitLab CI
    for text in snippets:
        assert yaml.safe_load(text)


def test_check_options_in_snippets_exist():
    check = build_parser()._subparsers._group_actions[0].choices["check"]
    known = {opt for action in check._actions for opt in action.option_strings}
    text = "\n".join(blocks("yaml") + blocks("sh"))
    for line in text.splitlines():
        if "moos-lint check" not in line:
            continue
        for opt in re.findall(r"(?<![\w-])(--[a-z][a-z-]*)", line.split("#")[0]):
            assert opt in known, f"{opt} in README: {line.strip()}"
