"""Mission context (`check --context`): a fragment is linted inside the missions that use it."""

from __future__ import annotations

import io
import json
import os
from contextlib import redirect_stderr, redirect_stdout
from pathlib import Path

import pytest

from moos_lint.commands.cli import main
from moos_lint.core.config import Settings
from moos_lint.core.context import project_root, related_missions
from moos_lint.core.engine import lint_paths

ANTLER = "ProcessConfig = ANTLER\n{\n  Run = MOOSDB @ NewConsole = false\n}\n"


def write(root: Path, rel: str, text: str) -> str:
    path = root / rel
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text(text)
    return str(path)


@pytest.fixture
def repo(tmp_path, monkeypatch):
    (tmp_path / ".git").mkdir()
    monkeypatch.chdir(tmp_path)
    write(tmp_path, "plugs/logger.plug", "ProcessConfig = pLogger\n{\n  AsyncLog = false\n}\n")
    write(tmp_path, "plugs/outer.plug", '#include "logger.plug"\n')
    write(tmp_path, "plugs/other.plug", "ProcessConfig = pOther {\n}\n")
    write(
        tmp_path,
        "m1/alpha.moos",
        "ServerPort = 9000\n"
        + ANTLER
        + "ProcessConfig = pLogger\n{\n  AsyncLog = true\n}\n"
        + '#include "../plugs/outer.plug"\n'
        + '#include "../plugs/other.plug"\n'
        + "ProcessConfig = pBrace {\n}\n",
    )
    write(tmp_path, "m2/bravo.moos", "ServerPort = 9001\n" + ANTLER)
    write(tmp_path, "m2/not_a_mission.moos", '#include "../plugs/logger.plug"\n')
    write(
        tmp_path,
        "m3/charlie.moos",
        "ServerPort = 9002\n"
        + ANTLER
        + "ProcessConfig = pHelmIvP\n{\n  behaviors = targ_$(VNAME).bhv\n}\n",
    )
    write(tmp_path, "m3/targ_abe.bhv", '#include "../bhv/common.bhv"\n')
    write(tmp_path, "bhv/common.bhv", "Behavior = BHV_Waypoint\n{\n  name = w\n}\n")
    write(tmp_path, "bhv/unused.bhv", "Behavior = BHV_Loiter\n{\n}\n")
    write(tmp_path, "src/App.cpp", "int main() { return 0; }\n")
    return tmp_path


def names(paths) -> list[str]:
    return sorted(Path(p).name for p in paths)


def settings(root: Path) -> Settings:
    return Settings(root=str(root), select=["R003", "R011"])


def test_missions_that_include_a_fragment_at_any_depth(repo):
    found = related_missions([str(repo / "plugs/logger.plug")], settings(repo))
    assert names(found) == ["alpha.moos"]  # not_a_mission.moos includes it but is no mission
    assert names(related_missions([str(repo / "plugs/other.plug")], settings(repo))) == [
        "alpha.moos"
    ]


def test_missions_that_hand_a_behavior_file_to_the_helm(repo):
    s = settings(repo)
    assert names(related_missions([str(repo / "m3/targ_abe.bhv")], s)) == ["charlie.moos"]
    # a piece the behavior file includes
    assert names(related_missions([str(repo / "bhv/common.bhv")], s)) == ["charlie.moos"]
    assert related_missions([str(repo / "bhv/unused.bhv")], s) == []


def test_missions_and_cpp_need_no_context(repo):
    s = settings(repo)
    assert related_missions([str(repo / "m2/bravo.moos")], s) == []
    assert related_missions([str(repo / "src/App.cpp")], s) == []
    assert related_missions([str(repo / "no/such.plug")], s) == []


def test_context_reports_fragment_findings_only_visible_in_the_mission(repo):
    plug = repo / "plugs/logger.plug"
    alone = lint_paths([plug], settings(repo))
    assert alone.diagnostics == []
    result = lint_paths([plug], settings(repo), context=True)
    got = sorted(
        (os.path.relpath(d.span.path, repo), d.span.line, d.code) for d in result.diagnostics
    )
    # The duplicate pLogger block lands in the fragment; the mission's own R003 is kept;
    # other.plug's R003 (another fragment of the mission, not passed) is not reported.
    assert got == [("m1/alpha.moos", 12, "R003"), ("plugs/logger.plug", 1, "R011")]


def test_context_from_the_command_line(repo):
    out = io.StringIO()
    with redirect_stdout(out), redirect_stderr(io.StringIO()):
        status = main(
            [
                "check",
                "--context",
                "--select",
                "R011",
                "--output-format",
                "json",
                "plugs/logger.plug",
            ]
        )
    data = json.loads(out.getvalue())
    assert status == 1
    assert [(d["path"], d["code"]) for d in data] == [("plugs/logger.plug", "R011")]
    assert data[0]["include_chain"][0]["path"] == "m1/alpha.moos"


def test_project_root(tmp_path, monkeypatch):
    nested = tmp_path / "a" / "b"
    nested.mkdir(parents=True)
    (tmp_path / ".hg").mkdir()
    assert project_root(Settings(), [nested]) == str(tmp_path)
    cfg = tmp_path / "a" / "moos-lint.toml"
    cfg.write_text("")
    assert project_root(Settings(config_path=str(cfg)), [nested]) == str(tmp_path / "a")
    monkeypatch.chdir(nested)
    (tmp_path / ".hg").rmdir()
    outside = tmp_path / "x.moos"  # outside the working folder: its own folder
    assert project_root(Settings(), [outside]) == str(tmp_path)
    assert project_root(Settings(), [nested / "y.moos"]) == str(nested)  # the working folder
