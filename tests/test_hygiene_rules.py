"""Configuration-hygiene rules (H001-H005): behaviour the fixtures cannot show."""

from __future__ import annotations

from pathlib import Path

from moos_lint.core.config import Settings
from moos_lint.core.engine import lint_files
from moos_lint.frontends.nsplug import Preprocessor
from moos_lint.rules.hygiene._shared import exclusive, names_match


def _lint(tmp_path: Path, files: dict[str, str], select: list[str], **opts) -> list:
    for name, text in files.items():
        (tmp_path / name).write_text(text)
    settings = Settings(root=str(tmp_path), select=select, rule_options=opts)
    paths = [str(tmp_path / n) for n in files if not n.startswith("_")]
    result = lint_files(paths, settings)
    assert result.internal_errors == 0
    return result.diagnostics


MISSION = "ServerPort = 9000\nProcessConfig = ANTLER\n{\n  Run = MOOSDB @ NewConsole = false\n}\n"


def test_unknown_key_fix_respells_the_key(tmp_path):
    diags = _lint(tmp_path, {"m.moos": "MOOSTimeWrap = 10\n" + MISSION}, ["H005"])
    (d,) = diags
    assert d.code == "H005" and "`MOOSTimeWarp`" in d.message
    assert d.fix is not None
    (edit,) = d.fix.edits
    assert (edit.span.line, edit.span.col, edit.span.end_col) == (1, 1, 13)
    assert edit.text == "MOOSTimeWarp"


def test_unknown_key_no_fix_when_candidates_are_ambiguous_or_block_keys(tmp_path):
    text = "CommsTic = 4\n" + MISSION
    (d,) = _lint(tmp_path, {"m.moos": text}, ["H005"])
    assert "`CommsTick` (a block key)" in d.message
    assert d.fix is None


def test_unknown_key_app_key_at_top_of_file(tmp_path):
    (d,) = _lint(tmp_path, {"m.moos": "apptick = 4\n" + MISSION}, ["H005"])
    assert "reads `AppTick` from its own ProcessConfig block" in d.message


def test_hash_run_does_what_a_comment_does(tmp_path):
    # pAntler launches only the lines whose key is `Run`, and no app asks for a key
    # `#LatOrigin`: such lines do what a comment would, and nothing reports them
    text = "#LatOrigin = 43.8\n" + MISSION.replace(
        "}\n", "  #Run = pLogger @ NewConsole = false\n}\n", 1
    )
    assert _lint(tmp_path, {"m.moos": text}, ["H005", "R007"]) == []


def test_unknown_key_extra_globals_option(tmp_path):
    files = {"m.moos": "FleetName = red\n" + MISSION}
    assert len(_lint(tmp_path, files, ["H005"])) == 1
    assert (
        _lint(tmp_path, files, ["H005"], **{"unknown-key": {"extra-globals": ["FLEETNAME"]}}) == []
    )


APP = """#include "MOOS/libMOOS/App/MOOSApp.h"
class Reader : public CMOOSApp {
  bool OnStartUp() {
    std::string value;
    %s
    return true;
  }
  bool Iterate() { return true; }
  bool OnNewMail(MOOSMSG_LIST &mail) { return true; }
};
int main(int argc, char *argv[]) { Reader app; app.Run("pReader", argv[1]); return 0; }
"""


def test_unknown_key_when_an_app_reads_a_name_it_is_handed(tmp_path):
    """A mission reader asked for a name with no literal part may read any key: only a
    close misspelling of a known key is reported."""
    text = "FleetName = red\nMOOSTimeWrap = 10\n" + MISSION
    handed = APP % "m_MissionReader.GetValue(m_key, value);"
    (d,) = _lint(tmp_path, {"m.moos": text, "Reader.cpp": handed}, ["H005"])
    assert "`MOOSTimeWarp`" in d.message
    # the same call on an object that is not a mission reader says nothing of the mission
    other = APP % "m_table.GetValue(m_key, value);"
    found = _lint(tmp_path, {"m.moos": text, "Reader.cpp": other}, ["H005"])
    assert [d.message.split(":")[0] for d in found] == [
        "unknown top-of-file key `FleetName`",
        "unknown top-of-file key `MOOSTimeWrap`",
    ]


def test_unknown_parameter_leaves_a_built_name_in_a_block(tmp_path):
    """`GetValue` reads a key from anywhere in the file, blocks included: a key whose end
    an app builds the name from is read there too."""
    block = "ProcessConfig = pMarinePID\n{\n  SPEED_FACTOR = 1\n  BeaconA_Depth = 10\n}\n"
    files = {
        "m.moos": MISSION + block,
        "Reader.cpp": APP % "m_MissionReader.GetValue(m_key, value);",
    }
    (d,) = _lint(tmp_path, files, ["M001"])  # (no literal part: not a form)
    assert d.message.startswith("`BeaconA_Depth`: pMarinePID does not read this parameter")
    files["Reader.cpp"] = APP % 'm_MissionReader.GetValue(m_id + "_Depth", value);'
    assert _lint(tmp_path, files, ["M001"]) == []


def test_fragment_globals_are_judged_where_they_land(tmp_path):
    files = {
        "m.moos": MISSION + "ProcessConfig = pLogger\n{\n#include plug_body.moos\n}\n",
        "plug_body.moos": "AsyncLog = true\n",
    }
    assert _lint(tmp_path, files, ["H005"]) == []
    files["top.moos"] = "#include plug_body.moos\n" + MISSION
    (d,) = _lint(tmp_path, files, ["H005"])
    assert d.span.path.endswith("plug_body.moos") and d.chain[0].path.endswith("top.moos")


def test_manual_apps_option(tmp_path):
    files = {"m.moos": MISSION + "ProcessConfig = uXMS\n{\n  var = DEPLOY\n}\n"}
    assert _lint(tmp_path, files, ["H001"]) == []
    opts = {"unlaunched-process-config": {"manual-apps": []}}
    (d,) = _lint(tmp_path, files, ["H001"], **opts)
    assert "`uXMS`" in d.message


def test_commented_runs_option(tmp_path):
    text = MISSION.replace("}\n", "  //Run = uTimerScript @ NewConsole = false\n}\n", 1)
    files = {"m.moos": text + "ProcessConfig = uTimerScript\n{\n  event = var=A, val=1\n}\n"}
    assert _lint(tmp_path, files, ["H001"]) == []
    opts = {"unlaunched-process-config": {"commented-runs": True}}
    (d,) = _lint(tmp_path, files, ["H001"], **opts)
    assert "its Run line is commented out at m.moos:" in d.message


def test_needs_no_config_option(tmp_path):
    files = {"m.moos": MISSION}
    assert _lint(tmp_path, files, ["H002"]) == []
    opts = {"missing-process-config": {"needs-no-config": []}}
    (d,) = _lint(tmp_path, files, ["H002"], **opts)
    assert "`MOOSDB` is launched" in d.message


def test_file_params_option(tmp_path):
    text = MISSION.replace("}\n", "  Run = uFldObstacleSim @ NewConsole = false\n}\n")
    text += "ProcessConfig = uFldObstacleSim\n{\n  obstacle_file = obst.txt\n}\n"
    files = {"m.moos": text}
    assert len(_lint(tmp_path, files, ["H003"])) == 1
    opts = {"missing-behavior-file": {"file-params": ["pHelmIvP:behaviors"]}}
    assert _lint(tmp_path, files, ["H003"], **opts) == []
    (tmp_path / "obst.txt").write_text("poly = pts={0,0:1,1:1,0}\n")
    assert _lint(tmp_path, files, ["H003"]) == []


def test_exclusive_branches(tmp_path):
    (tmp_path / "a.moos").write_text(
        "#ifdef ROLE A\nx = 1\n#endif\n"
        "#ifdef ROLE B || ROLE C\ny = 2\n#endif\n"
        "#ifdef ROLE A\nz = 3\n#endif\n"
        "#ifndef ROLE\nw = 4\n#endif\n"
        "#ifdef OTHER A\nv = 5\n#endif\n"
    )
    exp = Preprocessor().expand(tmp_path / "a.moos")
    x, y, z, w, v = exp.lines
    assert exclusive(x, y, exp) and exclusive(y, x, exp)
    assert not exclusive(x, z, exp)
    assert exclusive(w, x, exp) and exclusive(y, w, exp)
    assert not exclusive(x, v, exp)


def test_names_match():
    assert names_match("pShare_B", "PSHARE_b")
    assert names_match("uTimerScript_$(VNAME)", "uTimerScript_abe")
    assert names_match("pX", "$(APP)")
    assert not names_match("uTimerScript_$(VNAME)", "pLogger")


def test_bad_input_never_raises(tmp_path):
    files = {
        "m.moos": "ProcessConfig = ANTLER\n{\n  Run =\n  Run = @\n  Run = ~\n  = x\n}\n"
        "ProcessConfig =\n{\n  behaviors =\n}\n",
        "b.bhv": "Behavior = BHV_X\n{\n  name =\n  name\n}\nBehavior = BHV_Y\n{\n",
    }
    _lint(tmp_path, files, ["H001", "H002", "H003", "H004", "H005"])
