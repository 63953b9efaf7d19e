"""Baselines: --write-baseline records findings per file and rule; --baseline reports the new."""

from __future__ import annotations

import io
import json
import os
import shutil
from contextlib import redirect_stderr, redirect_stdout

import pytest

from moos_lint.commands.cli import main
from moos_lint.core import baseline as bl

SELECT = "R003,R012"
BRACES = "ProcessConfig = pA {\n}\nProcessConfig = pB {\n}\n"


def run(*args: str) -> tuple[int, str, str]:
    out, err = io.StringIO(), io.StringIO()
    with redirect_stdout(out), redirect_stderr(err):
        status = main(list(args))
    return status, out.getvalue(), err.getvalue()


def check(*args: str) -> tuple[int, list[dict]]:
    status, out, _ = run("check", ".", "--select", SELECT, "--output-format", "json", *args)
    return status, json.loads(out)


@pytest.fixture
def project(tmp_path, monkeypatch):
    (tmp_path / ".git").mkdir()  # the project root
    (tmp_path / "missions").mkdir()
    (tmp_path / "missions" / "a.moos").write_text(BRACES)
    (tmp_path / "missions" / "b.moos").write_text("ServerPort = 9000\njunk here\n")
    monkeypatch.chdir(tmp_path)
    return tmp_path


def test_write_then_check_reports_nothing(project):
    status, _, err = run("check", ".", "--select", SELECT, "--write-baseline", "baseline.json")
    assert status == 0
    assert "wrote 3 finding(s) in 2 file(s) to baseline.json" in err
    data = json.loads((project / "baseline.json").read_text())
    assert data == {
        "moos-lint-baseline": 1,
        "files": {
            "missions/a.moos": {"R003": ["ProcessConfig = pA {", "ProcessConfig = pB {"]},
            "missions/b.moos": {"R012": ["junk here"]},
        },
    }
    status, found = check("--baseline", "baseline.json")
    assert status == 0 and found == []
    status, out, _ = run("check", ".", "--select", SELECT, "--baseline", "baseline.json")
    assert "All checks passed" in out and "3 older finding(s) hidden by the baseline" in out


def test_moved_lines_do_not_come_back(project):
    run("check", ".", "--select", SELECT, "--write-baseline", "baseline.json")
    (project / "missions" / "a.moos").write_text("// new header\n\n" + BRACES.replace("pB", "pC"))
    status, found = check("--baseline", "baseline.json")
    assert status == 0 and found == []  # same count per file and rule: nothing new


def test_the_excess_is_reported_preferring_lines_not_in_the_baseline(project):
    run("check", ".", "--select", SELECT, "--write-baseline", "baseline.json")
    (project / "missions" / "a.moos").write_text(
        "ProcessConfig = pNew {\n}\n" + BRACES + "ProcessConfig = pLast {\n}\n"
    )
    status, found = check("--baseline", "baseline.json")
    assert status == 1
    assert [(f["path"], f["line"]) for f in found] == [
        ("missions/a.moos", 1),
        ("missions/a.moos", 7),
    ]
    # Without matching text, the last ones in the file are taken as the new ones.
    (project / "missions" / "a.moos").write_text(BRACES.replace("pA", "pX").replace("pB", "pY"))
    (project / "missions" / "a.moos").write_text(
        (project / "missions" / "a.moos").read_text() + "ProcessConfig = pZ {\n}\n"
    )
    _, found = check("--baseline", "baseline.json")
    assert [f["line"] for f in found] == [5]


def test_new_file_and_new_rule_are_reported(project):
    run("check", ".", "--select", SELECT, "--write-baseline", "baseline.json")
    (project / "missions" / "c.moos").write_text("ProcessConfig = pA {\n}\n")
    (project / "missions" / "b.moos").write_text("ProcessConfig = pA {\n}\njunk here\n")
    _, found = check("--baseline", "baseline.json")
    assert sorted((f["path"], f["code"]) for f in found) == [
        ("missions/b.moos", "R003"),
        ("missions/c.moos", "R003"),
    ]


def test_rewriting_prunes_what_is_gone_and_keeps_what_was_not_linted(project):
    run("check", ".", "--select", SELECT, "--write-baseline", "baseline.json")
    (project / "missions" / "a.moos").write_text("ProcessConfig = pA {\n}\n")
    # Only b.moos is linted, and only R003 runs: a.moos and R012 entries are kept as they were.
    run("check", "missions/b.moos", "--select", "R003", "--write-baseline", "baseline.json")
    data = json.loads((project / "baseline.json").read_text())["files"]
    assert data["missions/a.moos"]["R003"] == ["ProcessConfig = pA {", "ProcessConfig = pB {"]
    assert data["missions/b.moos"] == {"R012": ["junk here"]}
    # A full run prunes a.moos's fixed finding.
    run("check", ".", "--select", SELECT, "--write-baseline", "baseline.json")
    data = json.loads((project / "baseline.json").read_text())["files"]
    assert data["missions/a.moos"] == {"R003": ["ProcessConfig = pA {"]}
    # A deleted file disappears from the baseline.
    (project / "missions" / "b.moos").unlink()
    run("check", "missions/a.moos", "--select", SELECT, "--write-baseline", "baseline.json")
    data = json.loads((project / "baseline.json").read_text())["files"]
    assert list(data) == ["missions/a.moos"]


def test_baseline_works_on_another_clone_and_from_another_folder(project, tmp_path_factory):
    run("check", ".", "--select", SELECT, "--write-baseline", "baseline.json")
    clone = tmp_path_factory.mktemp("clone") / "repo"
    shutil.copytree(project, clone)
    status, out, _ = run(
        "check",
        str(clone / "missions"),
        "--select",
        SELECT,
        "--baseline",
        str(clone / "baseline.json"),
        "--output-format",
        "json",
    )
    assert status == 0 and json.loads(out) == []


def test_bad_baselines_are_usage_errors(project):
    for content in ("not json", "[]", '{"moos-lint-baseline": 1, "files": {"a": {"R003": 3}}}'):
        (project / "bad.json").write_text(content)
        status, out, err = run("check", ".", "--baseline", "bad.json")
        assert status == 2 and out == "" and "bad.json" in err
    status, _, err = run("check", ".", "--baseline", "missing.json")
    assert status == 2 and "cannot read baseline" in err
    (project / "folder.json").mkdir()
    for opt in ("--baseline", "--write-baseline"):
        status, _, err = run("check", ".", opt, "folder.json")
        assert status == 2 and "folder.json" in err
    if hasattr(os, "mkfifo"):  # never block on a FIFO
        os.mkfifo(project / "fifo.json")
        status, _, err = run("check", ".", "--baseline", "fifo.json")
        assert status == 2 and "not a regular file" in err


def test_baseline_and_fix_together(project):
    """Only new findings are fixed; findings the baseline hides are left alone."""
    (project / "missions" / "a.moos").write_text("ServerPort = 1  // moos-lint: ignore[R012]\n")
    run("check", ".", "--select", "R012,L001", "--write-baseline", "baseline.json")
    (project / "missions" / "b.moos").write_text("ServerPort = 2  // moos-lint: ignore[R012]\n")
    status, out, _ = run(
        "check", ".", "--select", "R012,L001", "--baseline", "baseline.json", "--fix"
    )
    assert status == 0, out
    assert (project / "missions" / "b.moos").read_text() == "ServerPort = 2\n"
    assert "ignore[R012]" in (project / "missions" / "a.moos").read_text()


def test_new_findings_api_keeps_internal_errors():
    from moos_lint.files.diagnostics import Diagnostic, Severity, Span

    d = Diagnostic("L900", "internal-error", Severity.ERROR, Span("/r/x.moos", 1), "boom")
    base = bl.Baseline(root="/r", files={"x.moos": {"L900": [""]}})
    kept, hidden = bl.new_findings([d], base, {})
    assert kept == [d] and hidden == 0


def test_without_vcs_or_config_paths_are_relative_to_the_baseline_file(tmp_path, monkeypatch):
    (tmp_path / "missions").mkdir()
    (tmp_path / "missions" / "a.moos").write_text(BRACES)
    monkeypatch.chdir(tmp_path)
    run("check", ".", "--select", SELECT, "--write-baseline", "baseline.json")
    assert "missions/a.moos" in json.loads((tmp_path / "baseline.json").read_text())["files"]
    monkeypatch.chdir(tmp_path / "missions")
    status, out, _ = run("check", ".", "--select", SELECT, "--baseline", "../baseline.json")
    assert status == 0, out
