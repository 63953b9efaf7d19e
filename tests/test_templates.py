"""nsplug templates named for no kind (``moos.meta``, ``ecomapper_bhv.meta``): their
text says whether they are a mission, a behavior file or not MOOS at all."""

from __future__ import annotations

from pathlib import Path

import pytest

from moos_lint.core.config import resolve_settings
from moos_lint.core.engine import lint_paths
from moos_lint.files.discovery import discover, kind_of
from moos_lint.frontends.parsers.nodes import has_macro, has_placeholder

MISSION = """ServerHost = localhost
ServerPort = 9000
Community  = alpha
#include all.def
ProcessConfig = ANTLER
{
  Run = MOOSDB   @ NewConsole = false
  Run = pHelmIvP @ NewConsole = false
}
ProcessConfig = pHelmIvP
{
  AppTick   = 4
  behaviors = current.bhv
  Comms_Tick = 4
}
"""
BEHAVIORS = """initialize DEPLOY = false
Behavior = BHV_Waypoint
{
  name   = survey
  points = 0,0:10,10
}
"""


def _folder(tmp_path: Path) -> Path:
    (tmp_path / ".git").mkdir()
    (tmp_path / "moos.meta").write_text(MISSION)
    (tmp_path / "bhv.meta").write_text(BEHAVIORS)
    (tmp_path / "all.def").write_text("#define WARP 1\n")
    (tmp_path / "Scene.unity.meta").write_text("fileFormatVersion: 2\nguid: 6f1b2c\n")
    (tmp_path / "model.ckpt-1.meta").write_bytes(b"\x0a\x8b\x01\x00Behavior\xff" * 20)
    (tmp_path / "launch.sh").write_text("nsplug bhv.meta current.bhv\nnsplug moos.meta last.moos\n")
    return tmp_path


def test_a_template_is_read_for_its_kind(tmp_path):
    folder = _folder(tmp_path)
    assert kind_of(str(folder / "moos.meta")) == "moos"
    assert kind_of(str(folder / "bhv.meta")) == "bhv"
    assert kind_of(str(folder / "Scene.unity.meta")) is None
    assert kind_of(str(folder / "model.ckpt-1.meta")) is None
    assert kind_of(str(folder / "absent.meta")) is None
    found = discover([folder], [], str(folder)).files
    names = sorted(Path(f).name for f in found)
    assert names == ["all.def", "bhv.meta", "moos.meta"]
    # named on the command line (pre-commit passes every changed `.meta`), the same
    given = [folder / "Scene.unity.meta", folder / "moos.meta"]
    assert [Path(f).name for f in discover(given, [], str(folder)).files] == ["moos.meta"]


def test_a_template_is_linted_as_its_kind(tmp_path):
    folder = _folder(tmp_path)
    result = lint_paths([folder], resolve_settings([folder], None))
    found = {(Path(d.span.path).name, d.code) for d in result.diagnostics}
    # moos.meta is a mission: its helm block's misspelt key is found; the behavior file
    # it names is nsplug's output of bhv.meta, made at launch (not reported missing)
    assert ("moos.meta", "M001") in found
    assert not any(code == "H003" for _, code in found)
    assert not any(name.endswith((".unity.meta", ".ckpt-1.meta")) for name, _ in found)
    kinds = {Path(u.path).name: u.kind.value for u in result.units}
    assert kinds["moos.meta"] == "moos" and kinds["bhv.meta"] == "bhv"


def test_a_file_a_launch_script_makes_with_nsplug_is_not_linted_twice(tmp_path):
    """``splug META_K200.moos K200.moos`` in a script without a suffix: K200.moos is the
    template's output (its findings are the template's); a file named on the command
    line is linted, and so is one whose template is not beside it."""
    (tmp_path / "META_K200.moos").write_text("ServerPort = 9000\n")
    (tmp_path / "K200.moos").write_text("ServerPort = 9000\n")
    (tmp_path / "K201.moos").write_text("ServerPort = 9001\n")
    (tmp_path / "Expand").write_text(
        "#!/bin/sh\nsplug META_K200.moos K200.moos\nsplug META_K201.moos K201.moos\n"
    )
    found = discover([tmp_path], [], str(tmp_path))
    assert sorted(Path(f).name for f in found.files) == ["K201.moos", "META_K200.moos"]
    assert str(tmp_path / "Expand") in found.ignore_files  # an edit of the script is noticed
    given = discover([tmp_path / "K200.moos"], [], str(tmp_path)).files
    assert [Path(f).name for f in given] == ["K200.moos"]


@pytest.mark.parametrize(
    ("text", "placeholder"),
    [
        ("speed = {{SPEED}}", True),
        ("start_pos = x={{ cfg.start_x }}, y=0", True),
        ("points = $(POINTS)", False),  # nsplug's own macro: has_macro alone
        # uTimerScript's arithmetic is no placeholder: the value is judged as written
        ("event = var=POST_COUNT, val={{$[TCOUNT]+1}/2}, time=0.11", False),
        ("val = {{$[A]+1}*{$[B]+2}}", False),
    ],
)
def test_a_generator_placeholder_is_told_from_timer_arithmetic(text, placeholder):
    """Another generator's ``{{NAME}}`` placeholder is left unjudged, as an nsplug macro
    is; uTimerScript's ``{...}`` arithmetic is not one."""
    assert has_placeholder(text) is placeholder
    assert has_macro(text) is (placeholder or "$(" in text)
