"""The app catalogue, the mission model, the M-rules on the real corpus, and `moos-lint graph`."""

from __future__ import annotations

import json
import os
import shutil
import subprocess
import tempfile
from pathlib import Path

import pytest

from moos_lint.commands.cli import main
from moos_lint.commands.graph import build_graph, to_dot, to_html
from moos_lint.core.config import ConfigError, Settings, load_config
from moos_lint.core.engine import LintRun, lint_files
from moos_lint.core.registry import select_rules
from moos_lint.rules.mission.invalid_parameter_value import is_number, problem
from moos_lint.semantics.catalogue import (
    STOCK,
    Catalogue,
    CatalogueError,
    load_user_catalogue,
    stock,
)
from moos_lint.semantics.mission_model import behavior_paths, model_of
from scripts.generate_catalogue import _names

CORPUS = Path(__file__).resolve().parents[2] / "shared" / "corpus" / "moos-ivp"
FIXTURES = Path(__file__).resolve().parents[1] / "fixtures" / "rules"


def needs_corpus() -> Path:
    if not CORPUS.is_dir():
        pytest.skip("the MOOS-IvP corpus is not beside the repository")
    return CORPUS


# ------------------------------------------------------------------ catalogue
def test_stock_catalogue_records_its_source_and_corrections():
    cat = stock()
    assert len(cat.source.get("commit", "")) == 40
    assert len(cat.apps) >= 50 and len(cat.behaviors) >= 40
    pid = cat.app("pmarinepidv22")
    assert pid is not None and pid.strict
    assert {"yaw_pid_kp", "maxrudder", "apptick", "comms_policy"} <= pid.params
    assert pid.forms["ignore_nav_yaw"][0] == "bool"
    assert "MarinePID.cpp" in pid.forms["ignore_nav_yaw"][1]
    # pLogger's and pShare's key lists were read whole from their sources (Log/Output
    # lines stay free); pMOOSBridge reads keys one by one and is not judged
    assert cat.app("pLogger").strict and {"log", "asynclog"} <= cat.app("pLogger").params
    assert cat.app("pShare").strict
    assert not cat.app("pMOOSBridge").strict
    # a library's keys are credited only through the classes the app reaches
    assert "speed_factor" in pid.params and "hash_viewable" not in pid.params
    helm = cat.app("pHelmIvP")
    assert {"DESIRED_HEADING", "IVPHELM_STATE"} <= helm.publishes
    wpt = cat.behavior("bhv_waypoint")
    assert {"points", "capture_radius", "name", "condition", "templating"} <= wpt.params


def test_stock_json_says_which_entries_were_corrected():
    path = Path(STOCK)
    data = json.loads(path.read_text(encoding="utf-8"))
    corrected = [n for n, a in data["apps"].items() if a.get("corrected")]
    assert {"pHelmIvP", "pShare", "uSimMarineV22", "pMOOSBridge"} <= set(corrected)
    assert data["source"]["repository"].endswith("moos-ivp/moos-ivp")
    assert all("source" in b for b in data["behaviors"].values())


def test_dynamic_names_keep_their_known_suffix():
    class N:
        def __init__(self, text, prefix, source):
            self.text, self.prefix, self.source = text, prefix, source

    class P:
        def __init__(self, n):
            self.name = n

    got = _names([P(N("A", "", '"A"')), P(N(None, "", 'prefix+"_X"')), P(N(None, "B_", "x"))])
    assert got == (["A"], ["B_"], ["_X"], False)


def test_user_catalogue_adds_apps_and_behaviors(tmp_path):
    cat_file = tmp_path / "mine.toml"
    cat_file.write_text(
        '[apps.pMine]\nparams = ["speed"]\nstrict = true\npublishes = ["MINE_STATUS"]\n'
        '[behaviors.BHV_Mine]\nparams = ["radius"]\n'
    )
    cat = Catalogue()
    load_user_catalogue(str(cat_file), cat)
    mine = cat.app("pmine")
    assert mine.strict and "speed" in mine.params and "apptick" in mine.params
    assert {"radius", "condition", "name"} <= cat.behavior("BHV_Mine").params
    bad = tmp_path / "bad.toml"
    bad.write_text('[apps.pX]\nparms = ["a"]\n')
    with pytest.raises(CatalogueError, match="parms"):
        load_user_catalogue(str(bad), Catalogue())


def test_config_catalogues_key_is_validated(tmp_path):
    (tmp_path / "mine.json").write_text(
        '{"apps": {"pMine": {"params": ["speed"], "strict": true}}}'
    )
    cfg = tmp_path / "moos-lint.toml"
    cfg.write_text('catalogues = ["mine.json"]\n')
    assert load_config(cfg).catalogues == [str((tmp_path / "mine.json").resolve())]
    cfg.write_text('catalogues = ["missing.json"]\n')
    with pytest.raises(ConfigError, match="not found"):
        load_config(cfg)
    cfg.write_text('catalogues = "mine.json"\n')
    with pytest.raises(ConfigError, match="list of strings"):
        load_config(cfg)


def test_user_catalogue_drives_unknown_parameter(tmp_path):
    (tmp_path / "mine.json").write_text(
        '{"apps": {"pMine": {"params": ["speed"], "strict": true}}}'
    )
    (tmp_path / "moos-lint.toml").write_text('catalogues = ["mine.json"]\nselect = ["M001"]\n')
    mission = tmp_path / "m.moos"
    mission.write_text(
        "ProcessConfig = ANTLER\n{\n  Run = MOOSDB @ NewConsole = false\n"
        "  Run = pMine @ NewConsole = false\n}\n\n"
        "ProcessConfig = pMine\n{\n  speed = 2\n  speeed = 3\n}\n"
    )
    result = lint_files([str(mission)], load_config(tmp_path / "moos-lint.toml"))
    assert [(d.code, d.span.line) for d in result.diagnostics] == [("M001", 10)]
    assert result.diagnostics[0].fix is not None


# ------------------------------------------------------------------ values
def test_is_number_matches_moos_ivp():
    for ok in ("1", "-2.5", ".5", "+3", "10."):
        assert is_number(ok), ok
    for bad in ("", "-", "1e3", "2m", "1.2.3", "3-", "+"):
        assert not is_number(bad), bad
    assert problem("positive", "0") and problem("nonneg", "-1") and not problem("uint", "0")
    assert problem("moos_double", ".5") and not problem("moos_double", "-0.5")
    assert problem("bool", "1") and not problem("bool", "Toggle")


# ------------------------------------------------------------------ model
def test_behavior_paths_find_the_template(tmp_path):
    (tmp_path / "meta_vehicle.bhv").write_text("")
    got, ok = behavior_paths("targ_$(VNAME).bhv", str(tmp_path))
    assert ok and got == [str(tmp_path / "meta_vehicle.bhv")]
    (tmp_path / "meta_shoreside.bhv").write_text("")
    got, ok = behavior_paths("targ_shoreside.bhv", str(tmp_path))
    assert ok and got == [str(tmp_path / "meta_shoreside.bhv")]
    (tmp_path / "alpha.bhv").write_text("")
    assert behavior_paths(" alpha.bhv ", str(tmp_path)) == ([str(tmp_path / "alpha.bhv")], True)
    assert behavior_paths("gone.bhv", str(tmp_path)) == ([], True)


def _model(path: Path):
    run = LintRun(Settings(root=str(path.parent)), select_rules(["M005"], [], []))
    unit = run.build_unit(str(path))
    run.units.append(unit)
    return model_of(run, unit.path, unit.moos)


def test_a_missions_whole_model_is_let_go_once_its_rules_ran():
    path = FIXTURES / "unpublished-subscription" / "quiet" / "meta_vehicle.moos"
    run = LintRun(Settings(root=str(path.parent)), select_rules(["M005"], [], []))
    unit = run.build_unit(str(path))
    run.units.append(unit)
    model = model_of(run, unit.path, unit.moos)
    assert model_of(run, unit.path, unit.moos) is model  # once per run, while its rules run
    run.run_rules(unit)
    assert run.memos.mission_models == {}  # only its own rules read it
    assert os.path.normpath(str(path)) in run.memos.mission_cores  # the siblings' share stays


def test_model_joins_processes_behaviors_and_siblings():
    m = _model(FIXTURES / "unpublished-subscription" / "quiet" / "meta_vehicle.moos")
    assert [p.name for p in m.processes][:3] == ["MOOSDB", "uSimMarineV22", "pHelmIvP"]
    assert [os.path.basename(p) for p, _ in m.behavior_files] == ["meta_vehicle.bhv"]
    assert [p.binary for p in m.inbound] == ["pShare", "uFldNodeBroker"]
    assert [os.path.basename(s) for s in m.sibling_missions] == ["meta_shoreside.moos"]
    assert m.published_by("DEPLOY") and m.published_by("NAV_X") and m.published_by("GO_HOME")
    assert not m.published_by("NO_SUCH_THING")
    assert m.complete


# ------------------------------------------------------------------ corpus
def _corpus_findings(rel: str, code: str) -> list[tuple[str, int, str]]:
    corpus = needs_corpus()
    path = corpus / rel
    if not path.exists():
        pytest.skip(f"{rel} is not in the corpus")
    settings = Settings(root=str(corpus), select=[code])
    result = lint_files([str(path)], settings)
    assert result.internal_errors == 0
    return sorted(
        (os.path.relpath(d.span.path, corpus), d.span.line, d.message.split("`")[1])
        for d in result.diagnostics
    )


@pytest.mark.parametrize(
    ("rel", "code", "expected"),
    [
        (
            "ivp/missions/berta_cmgr/meta_vehicle.moos",
            "M001",
            [
                ("ivp/missions/berta_cmgr/meta_vehicle.moos", 102, "early_warning_range"),
                ("ivp/missions/berta_cmgr/meta_vehicle.moos", 104, "early_warning_ref_spd"),
            ],
        ),
        (
            "ivp/missions/x1_legs/alpha.bhv",
            "M004",
            [
                ("ivp/missions/x1_legs/alpha.bhv", 43, "legflag"),
                ("ivp/missions/x1_legs/alpha.bhv", 52, "mid_pct"),
            ],
        ),
        (
            "ivp/missions/s10_juliet/juliet.moos",
            "M005",
            [("ivp/missions/s10_juliet/juliet.moos", 207, "TIME_AT_SURFACE")],
        ),
        (
            "ivp/missions/s6_foxtrot/foxtrot.moos",
            "M005",
            [("ivp/missions/s6_foxtrot/foxtrot.bhv", 53, "HSLINE")],
        ),
        (
            "ivp/missions/u6_alpha/meta_vehicle.moos",
            "M002",
            [
                # the pre-pShare form, which today's uFldNodeBroker rejects
                (
                    "ivp/missions/u6_alpha/plug_uFldNodeBroker.moos",
                    10,
                    "TRY_SHORE_HOST = hostip=localhost,port_udp=9200",
                ),
                ("ivp/missions/u6_alpha/plug_uFldNodeBroker.moos", 14, "BRIDGE = scr=VIEW_POINT"),
            ],
        ),
        ("ivp/missions/s1_alpha/alpha.moos", "M001", []),
        ("ivp/missions/s1_alpha/alpha.moos", "M005", []),
        ("ivp/missions/m2_berta/meta_vehicle.moos", "M005", []),
        ("ivp/missions/m2_berta/meta_shoreside.moos", "M005", []),
    ],
)
def test_corpus_missions_checked_by_hand(rel, code, expected):
    assert _corpus_findings(rel, code) == expected


def test_corpus_action_that_no_behavior_reads():
    got = _corpus_findings("ivp/missions/s1_alpha/alpha.moos", "M006")
    assert ("ivp/missions/s1_alpha/alpha.moos", 203, "UPDATES_RETURN") in got


def test_corpus_runs_every_mission_without_internal_errors():
    corpus = needs_corpus()
    settings = Settings(root=str(corpus), select=["M"])
    from moos_lint.files.discovery import discover

    files = discover([corpus / "ivp" / "missions"], [], str(corpus)).files
    result = lint_files(files, settings)
    assert result.internal_errors == 0
    by_code: dict[str, int] = {}
    for d in result.diagnostics:
        by_code[d.code] = by_code.get(d.code, 0) + 1
    assert by_code.get("M003", 0) == 0  # every behavior kind in the corpus is a stock one
    assert by_code.get("M005", 0) <= 12  # checked by hand: see the rule's docs


# ------------------------------------------------------------------ graph
GRAPH_MISSION = FIXTURES / "unpublished-subscription" / "fire" / "alpha.moos"


def test_graph_json_and_dot(capsys):
    assert main(["graph", str(GRAPH_MISSION), "--format", "json"]) == 0
    data = json.loads(capsys.readouterr().out)
    names = [p["name"] for p in data["processes"]]
    assert names[:2] == ["MOOSDB", "uSimMarineV22"] and "pHelmIvP" in names
    variables = {v["name"]: v for v in data["variables"]}
    assert variables["DEPOLY"]["findings"][0]["code"] == "M005"
    assert {"from": "p:pMarineViewer", "to": "v:DEPLOY", "kind": "publish", "how": "config"} in (
        data["edges"]
    )
    dot = to_dot(build_graph(str(GRAPH_MISSION), Settings(root=str(GRAPH_MISSION.parent))))
    assert dot.startswith("digraph mission {") and '"v:DEPOLY" [shape=ellipse, color=red' in dot


def test_graph_refuses_a_non_mission(tmp_path, capsys):
    f = tmp_path / "frag.moos"
    f.write_text("ProcessConfig = pX\n{\n  a = 1\n}\n")
    assert main(["graph", str(f)]) == 2
    assert "not a mission" in capsys.readouterr().err


def test_graph_html_is_self_contained(tmp_path):
    out = tmp_path / "g.html"
    assert main(["graph", str(GRAPH_MISSION), "-o", str(out)]) == 0
    page = out.read_text(encoding="utf-8")
    assert "<svg" in page and "http://" not in page.replace("http://www.w3.org/2000/svg", "")
    assert "https://" not in page and "<script src" not in page


def _chromium() -> str | None:
    for name in ("chromium", "chromium-browser", "google-chrome"):
        found = shutil.which(name)
        if found:
            return found
    return None


def test_graph_html_renders_in_headless_chromium(tmp_path):
    browser = _chromium()
    if browser is None:
        pytest.skip("chromium is not installed")
    g = build_graph(str(GRAPH_MISSION), Settings(root=str(GRAPH_MISSION.parent)))
    page = tmp_path / "g.html"
    page.write_text(to_html(g), encoding="utf-8")
    with tempfile.TemporaryDirectory() as profile:
        proc = subprocess.run(
            [
                browser,
                "--headless",
                "--no-sandbox",
                "--disable-gpu",
                "--disable-quic",
                "--no-first-run",
                "--disable-background-networking",
                "--disable-component-update",
                "--disable-sync",
                f"--user-data-dir={profile}",
                "--dump-dom",
                page.as_uri(),
            ],
            capture_output=True,
            text=True,
            timeout=90,
            check=False,
        )
    dom = proc.stdout
    if not dom.strip():
        pytest.skip(f"chromium rendered nothing: {proc.stderr[-300:]}")
    # the script ran: it counted the drawn nodes into the body
    n_nodes = len(g.processes) + len(g.variables)
    assert f'data-rendered="{n_nodes}"' in dom
    for p in g.processes:
        assert f'id="p:{p["name"]}"' in dom
    assert "DEPOLY" in dom and "M005" in dom


def test_a_changed_poke_script_is_read_again(tmp_path):
    """The pokes of a folder's shell scripts are kept across runs (the language server
    re-lints at every edit) only while each script keeps its (mtime, size)."""
    (tmp_path / "m.moos").write_text(
        "ServerPort = 9000\nCommunity = alpha\n\nProcessConfig = ANTLER\n{\n"
        "  Run = MOOSDB @ NewConsole = false\n  Run = uTimerScript @ NewConsole = false\n}\n\n"
        "ProcessConfig = uTimerScript\n{\n  condition = GO_HOME = true\n"
        "  event = var=RETURN, val=true, time=1\n}\n"
    )
    script = tmp_path / "launch.sh"

    def waits() -> list[str]:
        settings = Settings(root=str(tmp_path), select=["M005"])
        result = lint_files([str(tmp_path / "m.moos")], settings)
        return [d.message.split("`")[1] for d in result.diagnostics if d.code == "M005"]

    script.write_text("#!/bin/bash\nuPokeDB m.moos GO_HOME=true\n")
    assert waits() == []
    script.write_text("#!/bin/bash\nuPokeDB m.moos GO_AWAY=true, X=1\n")
    assert waits() == ["GO_HOME"]
    script.unlink()
    assert waits() == ["GO_HOME"]
    (tmp_path / "go.sh").write_text("uPokeDB m.moos GO_HOME=true\n")
    assert waits() == []


def test_what_a_sibling_publishes_is_kept_across_editor_runs_while_unchanged(tmp_path, monkeypatch):
    """The language server re-lints a mission at every edit; the publishers of the missions
    beside it are kept from one run to the next only while nothing they came from changed:
    the sibling mission, its behavior files (text and which files a name resolves to)."""
    from moos_lint.commands.lsp.analysis import analyse
    from moos_lint.semantics import mission_model as mm

    shore = tmp_path / "shore.moos"
    shore.write_text(
        "ServerPort = 9000\nCommunity = shoreside\n\nProcessConfig = ANTLER\n{\n"
        "  Run = MOOSDB @ NewConsole = false\n  Run = pShare @ NewConsole = false\n"
        "  Run = uTimerScript @ NewConsole = false\n}\n\n"
        "ProcessConfig = uTimerScript\n{\n  condition = SURVEY_DONE = true\n"
        "  event = var=RETURN_ALL, val=true, time=1\n}\n"
    )
    (tmp_path / "vehicle.moos").write_text(
        "ServerPort = 9001\nCommunity = abe\n\nProcessConfig = ANTLER\n{\n"
        "  Run = MOOSDB @ NewConsole = false\n  Run = pHelmIvP @ NewConsole = false\n}\n\n"
        "ProcessConfig = pHelmIvP\n{\n  behaviors = vehicle.bhv\n}\n"
    )
    bhv = tmp_path / "vehicle.bhv"

    def behaviors(flag: str) -> str:
        return f"Behavior = BHV_Waypoint\n{{\n  name = survey\n  endflag = {flag} = true\n}}\n"

    built: list[str] = []
    real = mm._Builder.build_core

    def build_core(b):
        if b.m.path.endswith("vehicle.moos"):  # the sibling's own part, built again
            built.append(b.m.path)
        return real(b)

    monkeypatch.setattr(mm._Builder, "build_core", build_core)
    monkeypatch.setattr(mm, "_KEPT", mm.OrderedDict())

    def waits() -> list[str]:
        found = analyse(str(shore), {}).findings
        return [f.diagnostic.message.split("`")[1] for f in found if f.diagnostic.code == "M005"]

    bhv.write_text(behaviors("SURVEY_DONE"))
    assert waits() == [] and len(built) == 1
    assert waits() == [] and len(built) == 1  # kept: nothing changed
    bhv.write_text(behaviors("SURVEY_OVER"))  # the sibling's behavior file changes
    assert waits() == ["SURVEY_DONE"] and len(built) == 2
    bhv.unlink()  # the name now resolves to no file
    (tmp_path / "vehicle_b.bhv").write_text(behaviors("SURVEY_DONE"))
    assert waits() == ["SURVEY_DONE"] and len(built) == 3
    vehicle = tmp_path / "vehicle.moos"  # the sibling mission itself changes
    vehicle.write_text(vehicle.read_text().replace("vehicle.bhv", "vehicle_b.bhv"))
    assert waits() == [] and len(built) == 4
    assert waits() == [] and len(built) == 4


def test_a_kept_sibling_follows_a_changed_user_catalogue(tmp_path, monkeypatch):
    from moos_lint.commands.lsp.analysis import analyse
    from moos_lint.semantics import mission_model as mm

    monkeypatch.setattr(mm, "_KEPT", mm.OrderedDict())
    (tmp_path / "moos-lint.toml").write_text('catalogues = ["apps.toml"]\n')
    apps = tmp_path / "apps.toml"
    apps.write_text('[apps.pSurvey]\nparams = []\npublishes = ["SURVEY_DONE"]\n')
    shore = tmp_path / "shore.moos"
    shore.write_text(
        "ServerPort = 9000\nCommunity = shoreside\n\nProcessConfig = ANTLER\n{\n"
        "  Run = MOOSDB @ NewConsole = false\n  Run = pShare @ NewConsole = false\n"
        "  Run = uTimerScript @ NewConsole = false\n}\n\n"
        "ProcessConfig = uTimerScript\n{\n  condition = SURVEY_DONE = true\n"
        "  event = var=RETURN_ALL, val=true, time=1\n}\n"
    )
    (tmp_path / "vehicle.moos").write_text(
        "ServerPort = 9001\nCommunity = abe\n\nProcessConfig = ANTLER\n{\n"
        "  Run = MOOSDB @ NewConsole = false\n  Run = pSurvey @ NewConsole = false\n}\n"
    )

    def waits() -> list[str]:
        found = analyse(str(shore), {}).findings
        return [f.diagnostic.message.split("`")[1] for f in found if f.diagnostic.code == "M005"]

    assert waits() == []
    assert waits() == []
    apps.write_text('[apps.pSurvey]\nparams = []\npublishes = ["SURVEY_OVER_NOW"]\n')
    assert waits() == ["SURVEY_DONE"]


def test_graph_reads_the_project_apps_as_check_does(tmp_path, monkeypatch):
    """One model: a repository app known to `check` is known to `graph` too."""
    (tmp_path / ".git").mkdir()
    app = tmp_path / "src" / "pNavFilter"
    app.mkdir(parents=True)
    (app / "NavFilter.h").write_text(
        '#include "MOOS/libMOOS/MOOSLib.h"\n'
        "class NavFilter : public CMOOSApp {\n public:\n  bool Iterate();\n"
        "  bool OnNewMail(MOOSMSG_LIST &m);\n  bool OnStartUp();\n};\n"
    )
    (app / "NavFilter.cpp").write_text(
        '#include "NavFilter.h"\n'
        'bool NavFilter::Iterate() { Notify("NAV_FILTERED", 1.0); return true; }\n'
        "bool NavFilter::OnNewMail(MOOSMSG_LIST &m) { return true; }\n"
        'bool NavFilter::OnStartUp() { Register("NAV_X", 0); return true; }\n'
    )
    (app / "main.cpp").write_text(
        '#include "NavFilter.h"\nint main(int argc, char* argv[]) {\n'
        '  NavFilter app;\n  app.Run("pNavFilter", argv[1]);\n  return 0;\n}\n'
    )
    mission = tmp_path / "missions" / "alpha.moos"
    mission.parent.mkdir()
    mission.write_text(
        "ServerHost = localhost\nServerPort = 9000\n\n"
        "ProcessConfig = ANTLER\n{\n  Run = MOOSDB @ NewConsole = false\n"
        "  Run = pNavFilter @ NewConsole = false\n  Run = pEchoVar @ NewConsole = false\n}\n\n"
        "ProcessConfig = pEchoVar\n{\n  echo = NAV_FILTERED -> NAV_OUT\n}\n"
    )
    monkeypatch.chdir(tmp_path)
    g = build_graph(str(mission), Settings(root=str(tmp_path)))
    assert not any("not in the catalogue" in n for n in g.notes)
    flagged = {f["code"] for f in g.findings} | {
        f["code"] for v in g.variables for f in v.get("findings", [])
    }
    assert "M005" not in flagged
    names = {v["name"] for v in g.variables}
    assert "NAV_FILTERED" in names


def test_flags_of_an_app_without_a_table_are_read_when_the_app_reads_the_key(tmp_path):
    from moos_lint.frontends.nsplug import Preprocessor
    from moos_lint.frontends.parsers.moos import parse_moos
    from moos_lint.semantics.variables import PUBLISH, flag_variables

    text = "ProcessConfig = pMine\n{\n  done_flag = MINE_DONE=true\n  color_flag = red\n"
    text += "  other_flag = MINE_OTHER=1\n}\n"
    (tmp_path / "m.moos").write_text(text)
    exp = Preprocessor().expand(tmp_path / "m.moos")
    (block,) = parse_moos(exp).blocks
    refs = list(flag_variables(block, lambda key: key in ("done_flag", "color_flag"), "pMine"))
    assert [(r.name, r.role, r.param) for r in refs] == [("MINE_DONE", PUBLISH, "done_flag")]
