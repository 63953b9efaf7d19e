"""What an app needs and does comes from the catalogue, each hand fact with its evidence."""

from __future__ import annotations

import json
import os
import re
import subprocess
import sys

import pytest

from moos_lint.commands.graph import _flagged_vars
from moos_lint.files.diagnostics import Diagnostic, Severity, Span, Subject
from moos_lint.files.suffixes import is_cpp, is_cpp_source
from moos_lint.frontends.nsplug import Preprocessor
from moos_lint.frontends.parsers.bhv import parse_bhv
from moos_lint.semantics.catalogue import (
    COMMAND_KEY_SUFFIX,
    DELEGATE,
    STOCK,
    TEMPLATE_MAIL_KEYS,
    UNASKED_MAIL,
    stock,
)

#: a source file and line (or line range) of MOOS-IvP or MOOS core
_EVIDENCE = re.compile(r"(ivp/src|MOOS_Jul2724)/[\w/.-]+\.(cpp|h):\d+")


def test_the_stock_catalogue_loads_every_start_up_fact():
    cat = stock()
    evald = cat.app("pMissionEval")
    assert evald.subscribes_dynamic and evald.subscriptions_from_config
    viewer = cat.app("pMarineViewer")
    assert viewer.subscribes_dynamic and viewer.observer and viewer.needs_origin
    xms = cat.app("uXMS")
    assert xms.observer and xms.launched_manually and not xms.needs_process_config
    # AppCastingMOOSApp posts "No mission config block found" for uHelmScope
    assert cat.app("uHelmScope").needs_process_config
    # without a block pLogger logs every variable (MOOSLogger.cpp:363, 393)
    assert not cat.app("pLogger").needs_process_config and cat.app("pLogger").observer
    assert not cat.app("uFunctionVis").needs_process_config  # it reads no configuration
    assert not cat.app("uMemWatch").subscribes_dynamic  # only <CLIENT>_PID
    assert cat.needs_process_config("MOOSDB") is False
    assert cat.needs_process_config("pAntler") is False
    assert cat.needs_process_config("pNoSuchApp") is None
    assert "ums" in cat.started_by_hand() and "uxms" in cat.started_by_hand()


def test_every_hand_fact_names_its_source_line():
    with open(STOCK, encoding="utf-8") as fh:
        data = json.load(fh)
    apps = data["apps"]
    hand = ("observer", "launched_manually", "subscriptions_from_config")
    for name, entry in apps.items():
        if any(entry.get(k) for k in hand):
            why = " ".join(entry.get("corrected", []))
            assert _EVIDENCE.search(why), f"{name}: {why!r}"
    for name, entry in data["programs"].items():
        assert _EVIDENCE.search(entry["why"]), name


def test_blocks_declared_optional_are_read_from_the_sources():
    cat = stock()
    for app in ("pRealm", "pMissionHash", "iSay", "uLoadWatch", "uMACView", "uMayFinish"):
        assert not cat.app(app).needs_process_config, app
    for app in ("pHelmIvP", "uTimerScript", "pShare", "uTermCommand"):
        assert cat.app(app).needs_process_config, app


def test_one_definition_of_the_cpp_suffixes():
    assert is_cpp("App.CPP") and is_cpp("a/b.hpp") and not is_cpp("m.moos")
    assert is_cpp_source("x.cc") and not is_cpp_source("x.h")


def test_the_bhv_reader_does_not_edit_the_shared_lines(tmp_path):
    path = tmp_path / "a.bhv"
    path.write_text(
        "Behavior = BHV_Waypoint\n{\n  name = a\n  points = 0,0: \\   \n    10,10\n}\n",
        encoding="utf-8",
    )
    exp = Preprocessor().expand(str(path))
    before = [line.text for line in exp.lines]
    first = parse_bhv(exp)
    assert [line.text for line in exp.lines] == before
    second = parse_bhv(exp)
    assert [p.value for b in first.behaviors for p in b.params] == [
        p.value for b in second.behaviors for p in b.params
    ]


def test_the_graph_reads_what_a_finding_is_about_not_its_message():
    span = Span("m.moos", 1, 1)
    ticked = Diagnostic("M005", "unpublished-subscription", Severity.WARNING, span, "`FOO`")
    about = Diagnostic(
        "M005",
        "unpublished-subscription",
        Severity.WARNING,
        span,
        "no names here",
        subject=Subject(variable="BAR"),
    )
    assert _flagged_vars([ticked, about]) == {"BAR"}


def test_an_apps_text_is_what_the_run_read_with_its_lines_ended_alike(tmp_path):
    """The catalogue reads an app's C++ as the front end read it (no second read of the
    file), with CRLF and bare CR line ends as ``\\n`` (as a file opened as text gives)."""
    from moos_lint.files.source import decode
    from moos_lint.semantics.catalogue import DELEGATE, app_text

    crlf = tmp_path / "App.cpp"
    body = "  else // a library's keys\r\n    handled = m_lib.setParam(param, value);\r\n"
    crlf.write_bytes(body.encode())
    cr = tmp_path / "Old.cpp"
    cr.write_bytes(body.replace("\r\n", "\r").encode())
    sources = {str(p): decode(p.read_bytes(), str(p)) for p in (crlf, cr)}
    want = body.replace("\r\n", "\n")
    assert app_text(str(crlf), sources) == want
    assert app_text(str(cr), sources) == want
    assert DELEGATE.search(app_text(str(cr), sources))
    crlf.write_text("changed since the run read it")
    assert app_text(str(crlf), sources) == want  # the run's text, not a second read
    assert app_text(str(crlf), {}) == "changed since the run read it"  # not read by the run
    assert app_text(str(tmp_path / "gone.cpp"), sources) == ""


def test_the_delegate_pattern_is_linear_on_commented_out_code():
    """A commented-out ``else`` whose lines hold a second ``//`` (each line can be split
    two ways) once took 2^lines steps: 40 such lines must match at once. The search runs
    in a child process with a deadline, so that a regression fails instead of hanging."""
    code = "if(a) {\n}\n//  else{\n" + "//    // a note\n" * 40 + "//  }\nx = 1;\n"
    script = (
        "import sys\nfrom moos_lint.semantics.catalogue import DELEGATE\n"
        "sys.exit(3 if DELEGATE.search(sys.stdin.read()) else 0)"
    )
    done = subprocess.run([sys.executable, "-c", script], input=code, text=True, timeout=60)
    assert done.returncode == 0
    # the pattern still finds a real hand-over, past comment lines
    assert DELEGATE.search("else {\n  // the rest\n  handled = m_lib.setParam(param, value);")


_TREE = os.environ.get("MOOS_IVP_TREE", "")


@pytest.mark.skipif(
    not os.path.isdir(_TREE), reason="set MOOS_IVP_TREE to a MOOS-IvP checkout to read the evidence"
)
def test_mail_facts_are_what_the_moos_sources_say():
    """The mail that comes unasked and the templates' placeholders, read from the sources."""

    def read(path: str) -> str:
        with open(os.path.join(_TREE, path), encoding="utf-8", errors="replace") as fh:
            return fh.read()

    core = "MOOS/MOOSCore/Core/libMOOS"
    assert 'm_Comms.Register("APPCAST_REQ", 0)' in read(
        f"{core}/Thirdparty/AppCasting/AppCastingMOOSApp.cpp"
    )
    assert '"_async_timing"' in read(f"{core}/Comms/MOOSAsyncCommClient.cpp")
    assert {"APPCAST_REQ", "_async_timing"} == UNASKED_MAIL
    template = read("scripts/GenMOOSApp_AppCasting")
    assert 'if(key == "FOO")' in template and '// Register("FOOBAR", 0);' in template
    assert {"FOO", "FOOBAR"} == TEMPLATE_MAIL_KEYS
    command = read(f"{core}/App/MOOSApp.cpp")
    assert 'GetAppName()+"_CMD"' in command and COMMAND_KEY_SUFFIX == "_CMD"


def test_a_behaviors_own_duration_default_comes_from_its_constructor():
    cat = stock()
    for kind in ("BHV_ConstantSpeed", "BHV_ConstantHeading", "BHV_ConstantDepth"):
        value, at = cat.behavior(kind).defaults["duration"]
        assert value == "0" and _EVIDENCE.search(at) and kind + ".cpp" in at
    # IvPBehavior's -1 (no time limit) is not recorded as a default of its own
    assert "duration" not in cat.behavior("BHV_Waypoint").defaults
    assert "duration" not in cat.behavior("BHV_Timer").defaults


def test_the_domains_a_behavior_halts_without_come_from_its_run_state():
    cat = stock()
    needs = {
        "BHV_ConstantDepth": "depth",
        "BHV_GoToDepth": "depth",
        "BHV_MaxDepth": "depth",
        "BHV_ConstantHeading": "course",
        "BHV_ConstantSpeed": "speed",
        "BHV_MaxSpeed": "speed",
    }
    for kind, var in needs.items():
        domains = cat.behavior(kind).domains
        assert list(domains) == [var], kind
        assert _EVIDENCE.search(domains[var]) and kind + ".cpp" in domains[var]
    # a behavior that reads the domain without halting the helm needs none
    assert cat.behavior("BHV_Waypoint").domains == {}
    assert cat.behavior("BHV_AvoidCollision").domains == {}


def test_whether_a_behavior_ends_by_itself_comes_from_its_sources():
    """``completes``: the line where a kind calls setComplete() (or posts its endflags),
    False for a kind that ends only when its duration runs out."""
    cat = stock()
    for kind in ("BHV_ConstantDepth", "BHV_ConstantSpeed", "BHV_StationKeep", "BHV_Timer"):
        assert cat.behavior(kind).completes is False, kind
    for kind, where in (
        ("BHV_Waypoint", "BHV_Waypoint.cpp"),
        ("BHV_LegRun", "BHV_LegRun.cpp"),  # postFlags(m_end_flags)
        ("BHV_Shadow", "IvPContactBehavior.cpp"),  # a base class ends it
    ):
        at = cat.behavior(kind).completes
        assert isinstance(at, str) and _EVIDENCE.search(at) and where in at, kind


def test_the_helm_posts_mode_only_as_its_set_blocks_name_it():
    # ModeSet::evaluate posts the variables its set blocks name: the mission model reads
    # them from the behavior files, and the catalogue does not list MODE for every helm
    assert "MODE" not in stock().app("pHelmIvP").publishes


def test_which_of_two_lines_holds_follows_the_parser():
    from moos_lint.semantics.catalogue import single_valued

    cat = stock()
    assert single_valued(cat.app("pHelmIvP").forms["apptick"][0]) == "first"
    assert single_valued(cat.app("uTimerScript").forms["reset_max"][0]) == "last"
    assert single_valued(cat.app("uFldNodeBroker").forms["bridge"][0]) is None
    assert single_valued(cat.behavior("BHV_Waypoint").forms["points"][0]) is None
    assert _EVIDENCE.search(cat.single_behavior_params["updates"])
