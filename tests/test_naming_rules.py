"""Options of the naming rules and the variable reader they share."""

from __future__ import annotations

from pathlib import Path

from moos_lint.core.config import Settings
from moos_lint.core.engine import lint_files
from moos_lint.frontends.nsplug import Preprocessor
from moos_lint.frontends.parsers.bhv import parse_bhv
from moos_lint.frontends.parsers.moos import parse_moos
from moos_lint.semantics.variables import (
    PUBLISH,
    SUBSCRIBE,
    bare_name,
    bhv_variables,
    moos_variables,
)


def _lint(tmp_path: Path, name: str, text: str, code: str, options: dict | None = None):
    path = tmp_path / name
    path.write_text(text, encoding="utf-8")
    settings = Settings(root=str(tmp_path))
    settings.select = [code]
    if options:
        rule_name = {"N001": "process-name-prefix", "N003": "variable-name-case"}[code]
        settings.rule_options[rule_name] = options
    result = lint_files([str(path)], settings)
    assert result.internal_errors == 0
    return [(d.span.line, d.message) for d in result.diagnostics if d.code == code]


def _refs(tmp_path: Path, name: str, text: str):
    path = tmp_path / name
    path.write_text(text, encoding="utf-8")
    exp = Preprocessor(mode="lint").expand(str(path))
    if name.endswith(".bhv"):
        return [(r.name, r.role, r.param) for r in bhv_variables(parse_bhv(exp))]
    return [(r.name, r.role, r.param) for r in moos_variables(parse_moos(exp))]


MISSION = """ProcessConfig = ANTLER
{
  Run = MOOSDB  @ NewConsole = false
  Run = pShare  @ NewConsole = false ~ ShareA
}
ProcessConfig = ShareA
{
  input = route = localhost:9301
}
"""


def test_aliases_can_be_left_alone(tmp_path):
    assert [line for line, _ in _lint(tmp_path, "m.moos", MISSION, "N001")] == [4]
    assert _lint(tmp_path, "m.moos", MISSION, "N001", {"check-aliases": False}) == []


def test_exempt_names_are_an_option(tmp_path):
    text = "ProcessConfig = ANTLER\n{\n  Run = MOOSDB @ NewConsole = false\n}\n"
    assert _lint(tmp_path, "m.moos", text, "N001") == []
    assert len(_lint(tmp_path, "m.moos", text, "N001", {"exempt": ["ANTLER"]})) == 1


def test_allowed_variable_names(tmp_path):
    text = "ProcessConfig = pLogger\n{\n  Log = ThirdParty_Var @ 0\n}\n"
    assert len(_lint(tmp_path, "m.moos", text, "N003")) == 1
    assert _lint(tmp_path, "m.moos", text, "N003", {"allow": ["ThirdParty_*"]}) == []


def test_condition_variables_are_left_sides(tmp_path):
    refs = _refs(
        tmp_path,
        "a.bhv",
        "Behavior = BHV_Waypoint\n{\n"
        "  condition = ((A = 1) or (B != two)) and !(C_D >= 3)\n"
        "  condition = MODE==SURVEYING:LEG\n"
        "  endflag = @cpa #group E = x=1 [if] (F = yes)\n"
        "}\n",
    )
    assert refs == [
        ("A", SUBSCRIBE, "condition"),
        ("B", SUBSCRIBE, "condition"),
        ("C_D", SUBSCRIBE, "condition"),
        ("MODE", SUBSCRIBE, "condition"),
        ("E", PUBLISH, "endflag"),
        ("F", SUBSCRIBE, "endflag"),
    ]


def test_app_syntaxes(tmp_path):
    refs = _refs(
        tmp_path,
        "m.moos",
        "ProcessConfig = ANTLER\n{\n  Run = uTimerScript @ NewConsole = false ~ PING\n}\n"
        'ProcessConfig = PING\n{\n  event = var=PING_OUT, val="a,b", time=1\n}\n'
        "ProcessConfig = pEchoVar\n{\n  echo = GPS_X -> NAV_X\n}\n"
        "ProcessConfig = pMOOSBridge\n{\n  SHARE = [A,B] -> C@localhost:9000 [D]\n}\n"
        "ProcessConfig = pShare\n{\n  output = X->Y:localhost:9021\n}\n",
    )
    assert refs == [
        ("PING_OUT", PUBLISH, "event"),
        ("GPS_X", SUBSCRIBE, "echo"),
        ("NAV_X", PUBLISH, "echo"),
        ("A", SUBSCRIBE, "share"),
        ("B", SUBSCRIBE, "share"),
        ("D", PUBLISH, "share"),
        ("X", SUBSCRIBE, "output"),
        ("Y", PUBLISH, "output"),
    ]


def test_bare_name():
    assert bare_name("RETURN_$[UP_VNAME_CLOSEST]") == "RETURN_"
    assert bare_name("NEAR_MISS_$UP_V1") == "NEAR_MISS_"
    assert bare_name("NODE_REPORT_$(VNAME)") is None


def test_test_code_is_left_alone_unless_asked(tmp_path):
    (tmp_path / "tests").mkdir()
    assert _lint(tmp_path, "tests/m.moos", MISSION, "N001") == []
    found = _lint(tmp_path, "tests/m.moos", MISSION, "N001", {"check-tests": True})
    assert [line for line, _ in found] == [4]
    assert [line for line, _ in _lint(tmp_path, "m.moos", MISSION, "N001")] == [4]


def test_test_code_is_told_by_its_folder_or_name():
    from moos_lint.files.test_code import is_test_code

    root = "/r"
    for path in (
        "MOOS/Core/libMOOS/testing/QueueTest.cpp",
        "src/pShare/pshare_test_scripts/pShareTest.moos",
        "tests/alpha.moos",
        "src/test/pvehicle/vehicle.h",
    ):
        assert is_test_code(f"{root}/{path}", root), path
    for path in (
        "missions/alpha/alpha.moos",
        "missions/euRathlon/test_waypoints/alpha.moos",
        "src/pContest/Contest.cpp",
        "missions/latest/latest.moos",
        "missions/testing.moos",
        # named for a test, but by its own name: most often a mission run in the field
        "missions/sonar_test/sonar_test.moos",
        "missions/IMUTest/IMUTest.moos",
        "src/iDVL/test_nav_stub.moos",
    ):
        assert not is_test_code(f"{root}/{path}", root), path
    # only the folders below the project's root count
    assert not is_test_code("/home/tests/project/missions/alpha.moos", "/home/tests/project")
