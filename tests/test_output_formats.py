"""The CI output formats: sarif, github, gitlab, junit, concise (and --output-file for all)."""

from __future__ import annotations

import io
import json
import sys
import xml.etree.ElementTree as ET
from contextlib import redirect_stderr, redirect_stdout
from pathlib import Path

import jsonschema
import pytest

from moos_lint.commands.cli import main
from moos_lint.commands.output import FORMATS, render
from moos_lint.commands.output.github_format import escape_data, escape_property
from moos_lint.core.engine import Result
from moos_lint.core.registry import all_rules
from moos_lint.files.diagnostics import Diagnostic, IncludeSite, Severity, Span

SCHEMA = Path(__file__).resolve().parents[1] / "fixtures" / "schemas" / "sarif-schema-2.1.0.json"
SELECT = "R003,R011,R012,L001"

MISSION = """\
ServerPort = 9000
ProcessConfig = ANTLER
{
  Run = MOOSDB @ NewConsole = false
}
ProcessConfig = pLogger {
  AsyncLog = true
}
ProcessConfig = pShare   // moos-lint: ignore[R003]
{
}
#include "frag.plug"
"""
FRAGMENT = "ProcessConfig = pShare\n{\n}\n"


@pytest.fixture
def project(tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    monkeypatch.delenv("GITHUB_ACTIONS", raising=False)
    (tmp_path / "m.moos").write_text(MISSION)
    (tmp_path / "frag.plug").write_text(FRAGMENT)
    return tmp_path


def run(*args: str) -> tuple[int, str]:
    out, err = io.StringIO(), io.StringIO()
    with redirect_stdout(out), redirect_stderr(err):
        status = main(list(args))
    return status, out.getvalue()


def check(*args: str) -> tuple[int, str]:
    return run("check", "m.moos", "--select", SELECT, *args)


def synthetic(path: str) -> Result:
    """Findings with every awkward character a message or a path can carry."""
    return Result(
        diagnostics=[
            Diagnostic(
                "R012",
                "malformed-line",
                Severity.ERROR,
                Span(path, 3, 2, 3, 9),
                '100% wrong:\nline two, with commas\r\x00\x07 <&> "quoted" ünïcödé',
                chain=(IncludeSite(path, 1),),
            ),
            Diagnostic("L001", "unused-suppression", Severity.WARNING, Span(path, 5), "stale"),
            Diagnostic("L900", "internal-error", Severity.ERROR, Span(path, 1), "boom"),
        ],
        files=[path],
    )


# ---------------------------------------------------------------------------------- sarif


def sarif_validator():
    schema = json.loads(SCHEMA.read_text(encoding="utf-8"))
    return jsonschema.Draft4Validator(schema)


def test_sarif_is_valid_against_the_official_schema(project):
    status, out = check("--output-format", "sarif")
    assert status == 1
    log = json.loads(out)
    sarif_validator().validate(log)
    assert log["version"] == "2.1.0"
    run_ = log["runs"][0]
    results = run_["results"]
    assert {r["ruleId"] for r in results} == {"R003", "R011", "L001"}
    # every result's ruleIndex points at its descriptor
    rules = run_["tool"]["driver"]["rules"]
    for r in results:
        assert rules[r["ruleIndex"]]["id"] == r["ruleId"]
    loc = results[0]["locations"][0]["physicalLocation"]
    assert loc["artifactLocation"] == {"uri": "frag.plug", "uriBaseId": "%SRCROOT%"}
    assert results[0]["relatedLocations"][0]["physicalLocation"]["artifactLocation"]["uri"] == (
        "m.moos"
    )
    (l001,) = [r for r in results if r["ruleId"] == "L001"]
    assert l001["fixes"][0]["artifactChanges"][0]["replacements"]
    assert run_["originalUriBaseIds"]["%SRCROOT%"]["uri"].startswith("file://")


def test_sarif_rules_table_describes_every_rule(project):
    _, out = check("--output-format", "sarif")
    rules = json.loads(out)["runs"][0]["tool"]["driver"]["rules"]
    by_id = {r["id"]: r for r in rules}
    for r in all_rules():
        d = by_id[r.code]
        assert d["name"] == r.name
        assert d["shortDescription"]["text"] == r.summary
        assert d["fullDescription"]["text"]
        assert d["helpUri"] == r.url and d["helpUri"].endswith(f"/rules/{r.name}.md")
        level = {"error": "error", "warning": "warning", "info": "note"}[r.severity.value]
        assert d["defaultConfiguration"] == {"level": level, "enabled": r.default_enabled}


def test_sarif_of_awkward_findings_is_valid(tmp_path):
    path = str(tmp_path / "dir with space" / "x.moos")
    log = json.loads(render("sarif", synthetic(path), cwd=str(tmp_path)))
    sarif_validator().validate(log)
    results = log["runs"][0]["results"]
    assert results[0]["locations"][0]["physicalLocation"]["artifactLocation"]["uri"] == (
        "dir%20with%20space/x.moos"
    )
    assert results[2]["ruleId"] == "L900"  # not a registered rule: a descriptor is added
    # a file outside the working directory becomes an absolute file URI
    outside = json.loads(render("sarif", synthetic("/elsewhere/y.moos"), cwd=str(tmp_path)))
    sarif_validator().validate(outside)
    uri = outside["runs"][0]["results"][0]["locations"][0]["physicalLocation"]
    assert uri["artifactLocation"]["uri"] == "file:///elsewhere/y.moos"


def test_sarif_without_findings_is_valid(tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    (tmp_path / "ok.moos").write_text("ServerPort = 9000\n")
    status, out = run("check", "ok.moos", "--select", SELECT, "--output-format", "sarif")
    assert status == 0
    log = json.loads(out)
    sarif_validator().validate(log)
    assert log["runs"][0]["results"] == []


# --------------------------------------------------------------------------------- github


def test_github_workflow_commands(project):
    status, out = check("--output-format", "github")
    assert status == 1
    lines = out.splitlines()
    assert len(lines) == 3
    assert lines[0].startswith("::error file=frag.plug,line=1,col=17,endColumn=23,title=R011 ")
    assert "::second block for `pShare` (first at m.moos%3A9)" not in lines[0]  # data: no %3A
    assert "(first at m.moos:9)" in lines[0]
    assert "%0Aincluded from m.moos:12" in lines[0]
    assert any(line.startswith("::warning file=m.moos,line=9,") for line in lines)
    assert any(line.startswith("::error file=m.moos,line=6,col=1,") for line in lines)


def test_github_escaping():
    assert escape_data("50% a\r\nb") == "50%25 a%0D%0Ab"
    assert escape_property("a:b,c%\n") == "a%3Ab%2Cc%25%0A"
    out = render("github", synthetic("/p/we,ird:name.moos"), cwd="/p")
    first = out.splitlines()[0]
    assert first.startswith("::error file=we%2Cird%3Aname.moos,line=3,col=2,endColumn=9,")
    assert "::100%25 wrong:%0Aline two, with commas%0D" in first
    assert "\n" not in first and "\r" not in first
    assert out.splitlines()[1].startswith("::warning ")


def test_github_is_chosen_on_github_actions(project, monkeypatch):
    monkeypatch.setenv("GITHUB_ACTIONS", "true")
    _, out = check()
    assert out.startswith("::error file=frag.plug,")
    _, out = check("--output-format", "text")  # an explicit format wins
    assert out.startswith("frag.plug:1:17: R011")
    monkeypatch.setenv("GITHUB_ACTIONS", "false")
    _, out = check()
    assert out.startswith("frag.plug:1:17: R011")


# --------------------------------------------------------------------------------- gitlab


def test_gitlab_code_quality_report(project):
    status, out = check("--output-format", "gitlab")
    assert status == 1
    report = json.loads(out)
    assert len(report) == 3
    for item in report:
        assert set(item) == {"description", "check_name", "fingerprint", "severity", "location"}
        assert item["severity"] in {"info", "minor", "major", "critical", "blocker"}
        assert isinstance(item["location"]["lines"]["begin"], int)
    assert {i["location"]["path"] for i in report} == {"m.moos", "frag.plug"}
    assert len({i["fingerprint"] for i in report}) == 3


def test_gitlab_fingerprints_do_not_depend_on_line_numbers(project):
    _, before = check("--output-format", "gitlab")
    # Unrelated lines above every finding: all line numbers move.
    (project / "m.moos").write_text("// a comment\n\n" + MISSION)
    (project / "frag.plug").write_text("// header\n" + FRAGMENT)
    _, after = check("--output-format", "gitlab")
    old, new = json.loads(before), json.loads(after)
    assert [i["location"]["lines"]["begin"] for i in old] != [
        i["location"]["lines"]["begin"] for i in new
    ]
    assert sorted(i["fingerprint"] for i in old) == sorted(i["fingerprint"] for i in new)


def test_gitlab_identical_findings_get_distinct_fingerprints(tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    block = "ProcessConfig = pA {\n}\n"
    (tmp_path / "m.moos").write_text(block * 3)
    _, out = run("check", "m.moos", "--select", "R003", "--output-format", "gitlab")
    prints = [i["fingerprint"] for i in json.loads(out)]
    assert len(prints) == 3 and len(set(prints)) == 3


# ---------------------------------------------------------------------------------- junit


def test_junit_is_valid_xml_with_a_case_per_finding(project):
    (project / "clean.moos").write_text("ServerPort = 9000\n")
    status, out = run(
        "check", "m.moos", "clean.moos", "--select", SELECT, "--output-format", "junit"
    )
    assert status == 1
    root = ET.fromstring(out.encode("utf-8"))
    assert root.tag == "testsuites"
    suite = root.find("testsuite")
    cases = suite.findall("testcase")
    failures = [c for c in cases if c.find("failure") is not None]
    assert len(failures) == 3 == int(suite.get("failures"))
    assert int(suite.get("tests")) == len(cases)
    clean = [c for c in cases if c.get("classname") == "clean.moos"]
    assert len(clean) == 1 and clean[0].find("failure") is None
    names = {c.get("name") for c in failures}
    assert "R011:1:17" in names


def test_junit_survives_control_characters(tmp_path):
    out = render("junit", synthetic(str(tmp_path / "a&b<c>.moos")), cwd=str(tmp_path))
    root = ET.fromstring(out.encode("utf-8"))
    msgs = [f.get("message") for f in root.iter("failure")]
    assert any("100% wrong" in m and "\ufffd" in m and "<&>" in m for m in msgs)
    assert {c.get("classname") for c in root.iter("testcase")} == {"a&b<c>.moos"}


# -------------------------------------------------------------------------------- concise


def test_concise_is_one_line_per_finding(project):
    status, out = check("--output-format", "concise")
    assert status == 1
    lines = out.splitlines()
    assert len(lines) == 3
    assert lines[0].startswith("frag.plug:1:17: R011 [duplicate-process-config] ")
    assert "m.moos:6:1: R003 [brace-on-header] " in out
    one = render("concise", synthetic("/p/x.moos"), cwd="/p")
    assert len(one.splitlines()) == 3


# ---------------------------------------------------------------------- every format, -o


@pytest.mark.parametrize("fmt", FORMATS)
def test_every_format_writes_the_same_report_to_a_file(project, fmt):
    status, shown = check("--output-format", fmt)
    assert status == 1 and shown
    status2, printed = check("--output-format", fmt, "--output-file", "report.out")
    assert status2 == 1 and printed == ""
    assert (project / "report.out").read_text(encoding="utf-8") == shown


@pytest.mark.parametrize("fmt", FORMATS)
def test_every_format_handles_no_findings(tmp_path, monkeypatch, fmt):
    monkeypatch.chdir(tmp_path)
    monkeypatch.delenv("GITHUB_ACTIONS", raising=False)
    (tmp_path / "ok.moos").write_text("ServerPort = 9000\n")
    status, out = run("check", "ok.moos", "--select", SELECT, "--output-format", fmt)
    assert status == 0
    if fmt in ("json", "gitlab"):
        assert json.loads(out) == []
    if fmt == "junit":
        assert ET.fromstring(out.encode()).find("testsuite").get("failures") == "0"


@pytest.mark.parametrize("fmt", FORMATS)
def test_a_run_that_finds_nothing_to_lint_says_so_in_every_format(tmp_path, monkeypatch, fmt):
    monkeypatch.chdir(tmp_path)
    monkeypatch.delenv("GITHUB_ACTIONS", raising=False)
    (tmp_path / "docs").mkdir()
    (tmp_path / "docs" / "notes.txt").write_text("no mission here\n")
    out, err = io.StringIO(), io.StringIO()
    with redirect_stdout(out), redirect_stderr(err):
        status = main(["check", "docs", "--output-format", fmt])
    out = out.getvalue()
    warning = "warning: no MOOS or C++ files found under docs"
    assert status == 0 and warning in err.getvalue()
    if fmt == "sarif":
        log = json.loads(out)
        sarif_validator().validate(log)
        (invocation,) = log["runs"][0]["invocations"]
        assert invocation["executionSuccessful"] is False
        assert invocation["toolExecutionNotifications"][0]["message"]["text"] == warning
    elif fmt == "github":
        assert out == f"::warning::{warning}\n"
    elif fmt == "junit":
        suite = ET.fromstring(out.encode()).find("testsuite")
        assert suite.get("skipped") == "1" and suite.get("failures") == "0"
        assert suite.find("testcase/skipped").get("message") == warning
    elif fmt in ("json", "gitlab"):
        assert json.loads(out) == []  # (their schemas hold findings only: stderr says it)


def test_unknown_format_is_a_usage_error(project):
    with pytest.raises(SystemExit) as exc, redirect_stderr(io.StringIO()):
        main(["check", "m.moos", "--output-format", "xml"])
    assert exc.value.code == 2


if sys.platform == "win32":  # pragma: no cover
    pytestmark = pytest.mark.skip("paths in these tests are POSIX paths")
