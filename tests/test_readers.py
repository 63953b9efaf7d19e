"""The .moos and .bhv readers build the model MOOS and the helm would see."""

from __future__ import annotations

from pathlib import Path

from moos_lint.frontends.nsplug import Preprocessor
from moos_lint.frontends.parsers.bhv import parse_bhv
from moos_lint.frontends.parsers.moos import parse_moos, strip_comment


def moos(tmp_path: Path, text: str):
    path = tmp_path / "m.moos"
    path.write_text(text, encoding="utf-8")
    return parse_moos(Preprocessor().expand(path))


def bhv(tmp_path: Path, text: str):
    path = tmp_path / "b.bhv"
    path.write_text(text, encoding="utf-8")
    return parse_bhv(Preprocessor().expand(path))


def test_comments_and_quotes():
    assert strip_comment("a = b // c") == "a = b "
    assert strip_comment('url = "http://x//y" // c') == 'url = "http://x//y" '
    assert strip_comment("#Run = pFoo") == "#Run = pFoo"


def test_globals_blocks_and_case(tmp_path):
    mf = moos(
        tmp_path,
        "Serverhost = localhost\n"
        "Processconfig = ANTLER\n{\n  Run = MOOSDB @ NewConsole = false\n}\n"
        "LatOrigin = 43.8\n"
        "ProcessConfig = pHelmIvP\n// note\n{\n  behaviors = a.bhv\n  ok = x=1, y=2 @ z:3\n}\n",
    )
    assert [p.key for p in mf.globals] == ["Serverhost", "LatOrigin"]
    assert [b.name for b in mf.blocks] == ["ANTLER", "pHelmIvP"]
    assert mf.is_mission
    helm = mf.blocks_named("PHELMIVP")[0]
    assert [(p.key, p.value) for p in helm.params] == [
        ("behaviors", "a.bhv"),
        ("ok", "x=1, y=2 @ z:3"),
    ]
    p = helm.params[1]
    assert (p.key_span.line, p.key_span.col) == (11, 3)
    assert (p.value_span.col, p.value_span.end_col) == (8, 22)


def test_antler_runs_and_aliases(tmp_path):
    mf = moos(
        tmp_path,
        "ProcessConfig = ANTLER\n{\n"
        "  Run = MOOSDB @ NewConsole = false\n"
        "  Run = pShare @ NewConsole = false ~ ShareA\n"
        "  Run = uTimerScript @ NewConsole = false, ExtraProcessParams = TS\n"
        "  TS = --alias=uTimerScript_PING\n"
        "  Run = pShare ~ ShareB\n"
        "}\n",
    )
    runs = mf.runs
    assert [r.name for r in runs] == ["MOOSDB", "ShareA", "uTimerScript_PING", "pShare~ShareB"]
    assert runs[0].options == {"newconsole": "false"}
    assert not runs[3].has_at
    span = runs[1].name_span
    assert (span.line, span.col, span.end_col) == (4, 39, 45)


def test_structural_problems(tmp_path):
    mf = moos(
        tmp_path,
        "ProcessConfig = pA {\n  x = 1\n}\n"
        "{\n  y = 2\n}\n"
        "}\n"
        "ProcessConfig = pB\n{\n  z = 3\n"
        "ProcessConfig = pC\n{\n}\n"
        "no equals here\n"
        "ProcessConfig = pD\nnot a brace = 1\n",
    )
    assert [b.name for b in mf.blocks if b.brace_on_header] == ["pA"]
    assert len(mf.orphan_blocks) == 1
    assert [ln.lineno for ln in mf.stray_closers] == [7]
    assert [b.name for b in mf.unclosed_blocks] == ["pB"]
    assert [ln.lineno for ln in mf.malformed] == [14]
    assert [ln.lineno for ln in mf.headers_without_block] == [15]


def test_behavior_file(tmp_path):
    bf = bhv(
        tmp_path,
        "initialize DEPLOY = false, RETURN=false\n"
        "set MODE = ACTIVE {\n  DEPLOY = true\n} INACTIVE\n\n"
        "Behavior = BHV_Waypoint\n{\n  name = survey\n  points = 0,0 : \\\n   10,10\n}\n"
        "Behavior=BHV_Loiter {\n  _Name = loiter\n}\n",
    )
    assert [(i.var, i.value) for i in bf.initializes] == [("DEPLOY", "false"), ("RETURN", "false")]
    assert bf.sets[0].mode_var == "MODE" and bf.sets[0].else_value == "INACTIVE"
    assert [b.kind for b in bf.behaviors] == ["BHV_Waypoint", "BHV_Loiter"]
    survey = bf.behaviors[0]
    assert survey.get("points")[0].value == "0,0 : 10,10"
    assert bf.behaviors[1].name.value == "loiter"
    assert bf.invalid == [] and bf.unclosed == []


def test_behavior_file_rejections(tmp_path):
    bf = bhv(tmp_path, "# note\ninitialize\tX=1\nBehavior = BHV_A\n{\n  speed 2\n}\njunk\n")
    reasons = [(ln.lineno, reason.split(":")[0]) for ln, reason in bf.invalid]
    assert [n for n, _ in reasons] == [1, 2, 5, 7]
