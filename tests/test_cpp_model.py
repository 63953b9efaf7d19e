"""The C++ app model: what tree-sitter extracts from one folder of a MOOS app."""

from __future__ import annotations

import os
from pathlib import Path

import pytest

pytest.importorskip("tree_sitter")
pytest.importorskip("tree_sitter_cpp")

from moos_lint.core.config import Settings
from moos_lint.core.engine import lint_files
from moos_lint.frontends.cpp.app import build_apps, read_relevant
from moos_lint.frontends.cpp.cmake import executable_name, unbuilt
from moos_lint.frontends.cpp.prefilter import mentions_moos

APP = Path(__file__).resolve().parent.parent / "fixtures" / "cpp" / "model_app"


def _app(folder: Path = APP):
    files = sorted(str(p) for p in folder.iterdir() if p.suffix in (".cpp", ".h"))
    apps = build_apps(read_relevant(files))
    assert len(apps) == 1
    return apps[0]


def test_class_chain_and_process_name_from_cmake():
    app = _app()
    assert app.app_class is not None and app.app_class.name == "Survey"
    assert app.base_chain == ["Survey", "SurveyBase", "AppCastingMOOSApp"]
    assert (app.process_name, app.process_name_source) == ("pSurvey", "cmake")


def test_names_resolved_from_members_defines_and_concatenation():
    app = _app()
    names = {p.name.source: p.name.text for p in app.publications}
    assert names['m_prefix + "_STATUS"'] == "SURVEY_STATUS"  # member initialiser
    assert names["REPORT_VAR"] == "SURVEY_REPORT"  # #define
    assert names["m_out_var"] is None  # set from the configuration: dynamic
    assert "OLD_REPORT" not in {p.name.text for p in app.publications}  # #if 0


def test_subscriptions_mail_keys_and_config_params():
    app = _app()
    subs = {s.name.text: s.name.wildcard for s in app.subscriptions}
    assert subs == {"SURVEY_START": False, "SURVEY_STOP": False, "NODE_*": True}
    exact = {k.text for k in app.mail_keys if not k.prefix}
    assert {"SURVEY_START", "SURVEY_STOP"} <= exact
    assert "NODE_" in {k.text for k in app.mail_keys if k.prefix}
    params = {c.text for c in app.config_params}
    assert {"lanes", "spacing", "out_var", "speed"} <= params


def test_device_io_is_found():
    kinds = {(u.kind, u.detail) for u in _app().io}
    assert ("device", "/dev/ttyS0") in kinds
    assert ("serial", "cfsetispeed") in kinds
    assert ("termios", "termios.h") in kinds


def test_trailing_space_after_include_does_not_lose_facts():
    # main.cpp has `#include <string> ` (a trailing space tree-sitter marks as an error)
    main = next(f for f in _app().files if f.path.endswith("main.cpp"))
    assert main.has_main


def test_prefilter_skips_files_without_moos_api(tmp_path):
    assert mentions_moos(b'Notify("X", 1);')
    assert mentions_moos(b"class A : public CMOOSApp {};")
    assert not mentions_moos(b"int notify_all(); // Registering\n")
    # a helm behavior that reads the helm's buffer and does angle arithmetic
    assert mentions_moos(b'double h = getBufferDoubleVal("NAV_HEADING", ok); cos(h);')
    assert mentions_moos(b'getBufferDoubleValX("NAV_X", x); y = x * M_PI;')
    assert mentions_moos(b'getBufferDoubleValX("H", h); y = degToRadians(h);')
    assert not mentions_moos(b'double h = getBufferDoubleVal("NAV_HEADING", ok);')
    assert not mentions_moos(b'getBufferDoubleVal("H", ok); cosine(h); MPI;')
    (tmp_path / "plain.cpp").write_text("int f() { return 1; }\n")
    assert read_relevant([str(tmp_path / "plain.cpp")]) == {}


def test_cmake_names(tmp_path):
    (tmp_path / "CMakeLists.txt").write_text(
        "# add_executable(commented out)\nset(APP iDepth)\nadd_executable(${APP} main.cpp)\n"
    )
    assert executable_name(str(tmp_path))[0] == "iDepth"
    (tmp_path / "CMakeLists.txt").write_text("add_executable(${UNSET} main.cpp)\n")
    assert executable_name(str(tmp_path)) is None


def test_cmake_above_building_several_programs_from_the_folder(tmp_path):
    """A CMakeLists.txt above the sources (``add_executable(relay src/relay.cpp)``) that
    builds several programs from the folder names the app by its class's file only."""
    (tmp_path / "src").mkdir()
    (tmp_path / "CMakeLists.txt").write_text(
        "add_executable(source_node src/source_node.cpp)\n"
        "add_executable(relay_node src/relay_node.cpp)\n"
    )
    src = str(tmp_path / "src")
    assert executable_name(src, frozenset({"relay_node.cpp"}))[0] == "relay_node"
    assert executable_name(src, frozenset({"other.cpp"})) is None
    assert executable_name(src) is None


def test_process_name_falls_back_to_folder(tmp_path):
    folder = tmp_path / "Gauge"
    folder.mkdir()
    (folder / "main.cpp").write_text(
        "class G : public CMOOSApp {};\n"
        "int main(int argc, char **argv) { G g; g.Run(argv[0], argv[1]); return 0; }\n"
    )
    app = _app(folder)
    assert (app.process_name, app.process_name_source) == ("Gauge", "folder")


def test_folder_building_two_programs(tmp_path):
    """The app is the program whose source list holds its class; else it has no name."""
    folder = tmp_path / "Actuation"
    folder.mkdir()
    (folder / "Motor.h").write_text("class Motor : public CMOOSInstrument {};\n")
    (folder / "MotorMain.cpp").write_text(
        '#include "Motor.h"\nint main(int c, char **v) { Motor m; m.Run(v[0], v[1]); }\n'
    )
    (folder / "CMakeLists.txt").write_text(
        "SET(MOTOR_SRCS\n Motor.cpp Motor.h\n MotorMain.cpp)\n"
        "SET(SET_SRCS SetMain.cpp Set.cpp)\n"
        "ADD_EXECUTABLE(iMotor ${MOTOR_SRCS})\nADD_EXECUTABLE(iSet ${SET_SRCS})\n"
    )
    app = _app(folder)
    assert (app.process_name, app.process_name_source) == ("iMotor", "cmake")
    (folder / "CMakeLists.txt").write_text(
        "ADD_EXECUTABLE(iMotor MotorMain.cpp)\nADD_EXECUTABLE(iSet SetMain.cpp)\n"
    )
    app = _app(folder)
    assert app.process_name is None


def test_bad_input_never_raises(tmp_path):
    (tmp_path / "broken.cpp").write_bytes(
        b'#if\nclass : public CMOOSApp {\nNotify(\xff\xfe "X, ;;\n}}}}\nRegister(\n'
    )
    (tmp_path / "binary.h").write_bytes(b"\x00\x01Notify")
    settings = Settings(root=str(tmp_path))
    settings.select = ["ALL"]
    result = lint_files([str(p) for p in sorted(tmp_path.iterdir())], settings)
    assert result.internal_errors == 0


def test_inline_suppression_in_cpp(tmp_path):
    src = (
        "class A : public CMOOSApp {\n"
        " bool Iterate() {\n"
        '  Notify("nav_x", 1.0); // moos-lint: ignore[N003]\n'
        '  Notify("nav_y", 1.0);\n'
        "  return true; }\n};\n"
    )
    (tmp_path / "A.cpp").write_text(src)
    settings = Settings(root=str(tmp_path))
    settings.select = ["N003"]
    result = lint_files([str(tmp_path / "A.cpp")], settings)
    assert [(d.code, d.span.line) for d in result.diagnostics] == [("N003", 4)]


def test_directory_discovery_takes_cpp(tmp_path):
    from moos_lint.files.discovery import discover

    (tmp_path / "App.cpp").write_text("int x;\n")
    (tmp_path / "notes.txt").write_text("x\n")
    found = discover([tmp_path], [], str(tmp_path)).files
    assert found == [os.path.join(str(tmp_path), "App.cpp")]


def test_discovery_leaves_pantlers_copies_of_missions(tmp_path):
    from moos_lint.files.discovery import discover

    (tmp_path / "alpha.moos").write_text("ServerPort = 9000\n")
    (tmp_path / "alpha.moos++").write_text("ServerPort = 9000\n")  # written by pAntler
    (tmp_path / "kept.moos++").write_text("ServerPort = 9000\n")  # its mission moved away
    found = discover([tmp_path], [], str(tmp_path)).files
    assert [os.path.basename(f) for f in found] == ["alpha.moos"]
    # named on the command line, it is linted
    named = discover([tmp_path / "alpha.moos++"], [], str(tmp_path)).files
    assert [os.path.basename(f) for f in named] == ["alpha.moos++"]


def test_discovery_leaves_nsplugs_output_beside_its_template(tmp_path):
    from moos_lint.files.discovery import discover

    missions = tmp_path / "missions"
    missions.mkdir()
    for name in ("meta_vehicle.moos", "meta_vehicle.bhv", "targ_alpha.moos", "targ_alpha.bhv"):
        (missions / name).write_text("ServerPort = 9000\n")
    (missions / "worked_targ_alpha.moos").write_text("ServerPort = 9000\n")  # a kept copy
    archive = tmp_path / "archive"  # an output kept away from its template, with results
    archive.mkdir()
    (archive / "targ_alpha.moos").write_text("ServerPort = 9000\n")
    runs = tmp_path / "runs"  # an output that a launch script beside it runs: the mission
    runs.mkdir()
    (runs / "targ_bravo.moos").write_text("ServerPort = 9000\n")
    (runs / "launch.sh").write_text("pAntler targ_bravo.moos\n")
    named_so = tmp_path / "named_so"  # a template named like an output: it is linted
    named_so.mkdir()
    (named_so / "targ_charlie.moos").write_text('ServerPort = 9000\n#include "plug_x.moos"\n')
    discovered = discover([tmp_path], [], str(tmp_path))
    assert [os.path.relpath(f, tmp_path) for f in discovered.files] == [
        os.path.join("missions", "meta_vehicle.bhv"),
        os.path.join("missions", "meta_vehicle.moos"),
        os.path.join("named_so", "targ_charlie.moos"),
        os.path.join("runs", "targ_bravo.moos"),
    ]
    # the files whose text decided are stamped with the listing, as the ignore files are
    decided = [os.path.relpath(f, tmp_path) for f in discovered.ignore_files]
    assert os.path.join("archive", "targ_alpha.moos") in decided
    assert os.path.join("named_so", "targ_charlie.moos") in decided
    # named on the command line (a pre-commit hook on a committed targ file), it is linted
    named = discover([missions / "targ_alpha.moos"], [], str(tmp_path)).files
    assert [os.path.basename(f) for f in named] == ["targ_alpha.moos"]


@pytest.mark.parametrize("newline", ["\n", "\r\n", "\r"])
def test_positions_hold_for_every_line_ending(tmp_path, newline):
    app = tmp_path / "pFoo"
    app.mkdir()
    lines = [
        '#include "MOOS/libMOOS/App/MOOSApp.h"',
        "// two",
        "bool Foo::Iterate() {",
        '  Notify("nav_yaw", 3);',
        "  return true;",
        "}",
    ]
    (app / "Foo.cpp").write_bytes(newline.join(lines).encode() + newline.encode())
    result = lint_files([str(app / "Foo.cpp")], Settings(select=["N003"]))
    assert [(d.span.line, d.span.col) for d in result.diagnostics] == [(4, 10)]


def test_names_through_a_function_that_returns_its_argument(tmp_path):
    """``Notify(postVar("WATCH_SUMMARY"), ...)``: a function of one string that returns it
    unless configured otherwise names the literal; one that builds another name does not."""
    (tmp_path / "Watch.cpp").write_text(
        "class Watch : public AppCastingMOOSApp {};\n"
        "std::string Watch::postVar(std::string varname)\n{\n"
        "  if (m_map.count(varname)) return(m_map[varname]);\n  return(varname);\n}\n"
        'std::string Watch::prefixed(const std::string& v) { return "W_" + v; }\n'
        "bool Watch::Iterate()\n{\n"
        '  Notify(postVar("WATCH_SUMMARY"), m_summary);\n'
        '  Notify(prefixed("EVENT"), 1);\n  return true;\n}\n'
    )
    names = [p.name.text for p in _app(tmp_path).publications]
    assert names == ["WATCH_SUMMARY", None]


def test_names_through_a_function_that_returns_a_reference(tmp_path):
    """``const std::string& Watch::postVar(...)``: a function returning a reference is
    found by its name as one returning a value is."""
    (tmp_path / "Watch.cpp").write_text(
        "class Watch : public AppCastingMOOSApp {};\n"
        "const std::string& Watch::postVar(const std::string& varname) const\n{\n"
        "  return(varname);\n}\n"
        "bool Watch::Iterate()\n{\n"
        '  Notify(postVar("WATCH_SUMMARY"), m_summary);\n  return true;\n}\n'
    )
    names = [p.name.text for p in _app(tmp_path).publications]
    assert names == ["WATCH_SUMMARY"]


def test_discovery_leaves_windows_module_definitions(tmp_path):
    """``proj.def`` / ``iMatlab.def`` (a DLL's exports) share the suffix of nsplug's
    definition files; they are not MOOS files, walked or named."""
    from moos_lint.files.discovery import discover

    (tmp_path / "iMatlab.def").write_text("LIBRARY iMatlab\nEXPORTS mexFunction\n")
    (tmp_path / "proj.def").write_text("; comment\nVERSION 1.2\nEXPORTS\n  pj_init @1\n")
    (tmp_path / "vehicle.def").write_text("#define VNAME alpha\n#define VPORT 9001\n")
    found = discover([tmp_path], [], str(tmp_path)).files
    assert [os.path.basename(f) for f in found] == ["vehicle.def"]
    named = discover([tmp_path / "proj.def"], [], str(tmp_path)).files
    assert named == []


def test_unbuilt_sources_only_when_every_list_is_known(tmp_path):
    names = frozenset({"App.cpp", "App_back.cpp", "main.cpp", "App.h"})
    cmake = tmp_path / "CMakeLists.txt"
    cmake.write_text("SET(SRC App.cpp main.cpp)\nADD_EXECUTABLE(pApp ${SRC})\n")
    assert unbuilt(str(tmp_path), names) == {"App_back.cpp"}  # headers are never judged
    cmake.write_text("ADD_LIBRARY(app_lib App_back.cpp)\nADD_EXECUTABLE(pApp App.cpp main.cpp)\n")
    assert unbuilt(str(tmp_path), names) == set()
    for unknown in (
        "FILE(GLOB SRC *.cpp)\nADD_EXECUTABLE(pApp ${SRC})\n",
        "ADD_EXECUTABLE(pApp ${SOURCES})\n",
        "SET(SRC App.cpp)\nLIST(APPEND SRC main.cpp)\nADD_EXECUTABLE(pApp ${SRC})\n",
        "SET(SRC App.cpp)\n",
    ):
        cmake.write_text(unknown)
        assert unbuilt(str(tmp_path), names) == set(), unknown
    cmake.unlink()
    assert unbuilt(str(tmp_path), names) == set()


_STREAMED = """\
#include <sstream>
#include "MOOS/libMOOS/MOOSLib.h"
class Front : public CMOOSApp
{
  bool Iterate();
  std::string m_vname;
};
bool Front::Iterate()
{
  std::stringstream ss;
  ss << "DONE_WITH_FIRST_" << m_vname;
  std::string note = ss.str();
  Notify(note, "true");
  std::ostringstream whole;
  whole << "FRONT_" << "REPORT";
  Notify(whole.str(), 1);
  std::ostringstream reset;
  reset << "FIRST_";
  reset.str("");
  reset << "OTHER";
  Notify(reset.str(), 2);
  std::ostringstream given("SEED_");
  given << "X";
  Notify(given.str(), 3);
  return true;
}
int main(int argc, char *argv[]) { Front app; app.Run("pFront", argv[1]); }
"""


def test_names_built_with_a_string_stream(tmp_path):
    (tmp_path / "Front.cpp").write_text(_STREAMED)
    (app,) = build_apps(read_relevant([str(tmp_path / "Front.cpp")]))
    names = {p.name.source: (p.name.text, p.name.prefix) for p in app.publications}
    assert names["note"] == (None, "DONE_WITH_FIRST_")  # the vehicle's name follows
    assert names["whole.str()"] == ("FRONT_REPORT", "FRONT_REPORT")
    # a stream reset, or given a first text, is not followed
    assert names["reset.str()"] == (None, "")
    assert names["given.str()"] == (None, "")


def test_a_publication_that_is_a_whole_statement_knows_its_place_in_its_block():
    from moos_lint.files.source import SourceFile
    from moos_lint.frontends.cpp.app import parse_folder

    code = """
void A::Go(double x, double y) {
  Notify("A_X", x);
  // a comment takes no place
  Notify("A_Y", y);
  double z = x;
  Notify("A_Z", z);
  if(x > 0)
    Notify("A_SPEED", x);
  bool ok = Notify("A_HEADING", y);
}
"""
    files = parse_folder({"app/A.cpp": SourceFile("app/A.cpp", code)})
    places = {p.name.text: p.statement for f in files for p in f.publications}
    block = places["A_X"][0]
    assert [places[n] for n in ("A_X", "A_Y", "A_Z")] == [(block, 0), (block, 1), (block, 3)]
    assert places["A_SPEED"] is None  # the branch of an if, not a block's statement
    assert places["A_HEADING"] is None  # part of a declaration


def test_a_mail_branch_says_how_it_reads_the_value():
    from moos_lint.files.source import SourceFile
    from moos_lint.frontends.cpp.app import parse_folder

    code = """
bool Odo::OnNewMail(MOOSMSG_LIST &NewMail) {
  MOOSMSG_LIST::iterator p;
  for(p=NewMail.begin(); p!=NewMail.end(); p++) {
    CMOOSMsg &msg = *p;
    string key = msg.GetKey();
    double dval = msg.GetDouble();
    string sval = msg.GetString();
    if(key == "NAV_X") m_x = dval;
    else if(key == "DEPLOY") setBooleanOnString(m_deploy, sval);
    else if(key == "RESET") {
      bool reset = msg.GetDouble();
      if(reset) m_total = 0;
    }
    else if(key == "RETURN") {
      if(msg.IsDouble()) m_ret = msg.GetDouble() != 0;
    }
    else if(key == "PING") handlePing(msg);
    else if(key == "POKE") m_pokes++;
    else if(key == "SPD") m_spd = atof(sval.c_str());
    else if(key == "NAV_Y") m_y = msg.GetDouble();
    else if(key == "REGEN") add_vertex(m_x, m_y);
    else if(key == "SCOPE") {
      if(msg.IsDouble()) sval = doubleToStringX(msg.GetDouble(), 8);
      m_scope = sval;
    }
  }
  return true;
}
"""
    files = parse_folder({"app/A.cpp": SourceFile("app/A.cpp", code)})
    reads = {k.text: k.reads for f in files for k in f.mail_keys}
    assert reads == {
        "NAV_X": "number",
        "DEPLOY": "text",
        "RESET": "number",
        "RETURN": "text",  # its type asked
        "PING": "",  # the message handed on
        "POKE": "",  # its value not read
        "SPD": "text",
        "NAV_Y": "number",
        "REGEN": "",  # members other branches set from their own messages
        "SCOPE": "text",
    }
