"""The project boundary: no report shows text of a file outside the project.

A repository under review commits includes and links that reach out of it
(``#include /etc/passwd``, ``pw.moos -> /etc/passwd``, a config's
``include-paths``). moos-lint still reads them (they are part of the mission),
but no output format, nor the language server, ever prints their text.
"""

from __future__ import annotations

import io
import json
import os
import xml.etree.ElementTree as ET
from contextlib import redirect_stderr, redirect_stdout
from pathlib import Path

import jsonschema
import pytest

from moos_lint.commands.cli import _keep_inside, main
from moos_lint.commands.output import FORMATS
from moos_lint.files.boundary import Boundary, apply
from moos_lint.files.diagnostics import Diagnostic, Edit, Fix, Severity, Span

MARKER = "Qz7MarkerOutsideText"
SCHEMA = Path(__file__).resolve().parents[1] / "fixtures" / "schemas" / "sarif-schema-2.1.0.json"

OUTSIDE_PLUG = f"""\
{MARKER}_TOP = 1
ProcessConfig = pHelmIvP
{{
  {MARKER}_key = 2
}}
}}
"""
OUTSIDE_DEFS = f"#define LEAKNAME {MARKER}_macro\n"
FIXABLE = f"ServerPort = 9000   // moos-lint: ignore[R003] {MARKER}\n"


@pytest.fixture
def project(tmp_path, monkeypatch):
    """A project (a git checkout) whose files reach a folder outside it in every way."""
    monkeypatch.delenv("GITHUB_ACTIONS", raising=False)
    out = tmp_path / "outside"
    out.mkdir()
    (out / "secret.plug").write_text(OUTSIDE_PLUG)
    (out / "defs.plug").write_text(OUTSIDE_DEFS)
    (out / "viapath.plug").write_text(f"ProcessConfig = uZq{MARKER}\n{{\n}}\n}}\n")
    (out / "pw.moos").write_text(FIXABLE)
    root = tmp_path / "project"
    root.mkdir()
    (root / ".git").mkdir()
    (root / "moos-lint.toml").write_text('include-paths = ["../outside"]\n')
    (root / "abs.moos").write_text(f"ServerPort = 9000\n#include {out / 'secret.plug'}\n")
    (root / "rel.moos").write_text("ServerPort = 9000\n#include ../outside/secret.plug\n")
    (root / "path.moos").write_text("ServerPort = 9000\n#include viapath.plug\n")
    (root / "macro.moos").write_text(
        "#include ../outside/defs.plug\nServerPort = 9000\n"
        "ProcessConfig = pHelmIvP\n{\n  $(LEAKNAME) = 1\n}\n"
    )
    (root / "pw.moos").symlink_to(out / "pw.moos")
    monkeypatch.chdir(root)
    return root


def run(*args: str) -> tuple[int, str, str]:
    out, err = io.StringIO(), io.StringIO()
    with redirect_stdout(out), redirect_stderr(err):
        status = main(["check", "--no-cache", *args])
    return status, out.getvalue(), err.getvalue()


@pytest.mark.parametrize("fmt", FORMATS)
def test_no_format_prints_an_outside_file(project, fmt):
    status, out, err = run("--select", "ALL", "--output-format", fmt, ".")
    assert status == 1, err
    assert MARKER not in out and MARKER not in err
    assert "secret.plug" in out and "viapath.plug" in out and "pw.moos" in out  # the notes
    # the findings inside are still there, the outside words shown as "…"
    assert "…" in out or fmt in ("gitlab", "junit", "sarif", "json")


def test_notes_are_valid_in_each_schema(project):
    _, out, _ = run("--select", "ALL", "--output-format", "sarif", ".")
    sarif = json.loads(out)
    jsonschema.Draft7Validator(json.loads(SCHEMA.read_text())).validate(sarif)
    notes = sarif["runs"][0]["invocations"][0]["toolExecutionNotifications"]
    where = {n["locations"][0]["physicalLocation"]["artifactLocation"]["uri"] for n in notes}
    assert "pw.moos" in where and any(u.endswith("/outside/secret.plug") for u in where)

    _, out, _ = run("--select", "ALL", "--output-format", "json", ".")
    items = json.loads(out)
    keys = {frozenset(item) for item in items}
    assert len(keys) == 1  # a note has the keys of a finding
    notes = {i["path"]: i["message"] for i in items if i["code"] == "L901"}
    assert notes["pw.moos"] == "a link to a file outside the project: not linted"
    secret = str(project.parent / "outside" / "secret.plug")
    assert notes[secret] == "3 findings in this file, outside the project, not shown"
    assert all(not i["path"].startswith("..") for i in items if i["code"] != "L901")

    _, out, _ = run("--select", "ALL", "--output-format", "junit", ".")
    suite = ET.fromstring(out).find("testsuite")
    skipped = suite.findall("testcase/skipped")
    assert len(skipped) == int(suite.get("skipped")) == len(notes)

    _, out, _ = run("--select", "ALL", "--output-format", "github", ".")
    assert sum(
        line.startswith("::notice title=L901 outside-project::") for line in out.splitlines()
    )


def test_outside_findings_do_not_fail_the_run(project):
    (project / "only.moos").write_text("#include ../outside/secret.plug\n")
    status, out, _ = run("--select", "R006", "only.moos")
    assert status == 0
    assert out.startswith("note: ") and MARKER not in out
    assert "1 finding in this file, outside the project, not shown" in out


def test_a_message_never_quotes_an_outside_macro(project):
    _, out, _ = run("--select", "M001", "--output-format", "concise", "macro.moos")
    assert out.startswith("macro.moos:5:1: M001 [unknown-parameter] `…`: ")
    assert MARKER not in out


def test_fix_leaves_a_link_to_an_outside_file_alone(project):
    before = (project.parent / "outside" / "pw.moos").read_text()
    status, out, err = run("--select", "R,L001", "--fix", "pw.moos")
    assert status == 0
    assert (project.parent / "outside" / "pw.moos").read_text() == before
    assert "pw.moos: a link to a file outside the project: not linted" in out
    assert MARKER not in out + err
    status, out, err = run("--select", "R,L001", "--diff", "pw.moos")
    assert status == 0 and MARKER not in out + err


def test_fix_refuses_a_document_outside_the_project(tmp_path, capsys):
    from moos_lint.core.fix import FixOutcome, load_document

    root = tmp_path / "project"
    root.mkdir()
    target = tmp_path / "outside.moos"
    target.write_text("a\n")
    (root / "link.moos").symlink_to(target)
    inside = root / "in.moos"
    inside.write_text("b\n")
    docs = {str(p): load_document(str(p)) for p in (root / "link.moos", inside)}
    for doc in docs.values():
        doc.text = "changed\n"
    outcome = FixOutcome(result=None, docs=docs, fixed=2, passes=1)
    _keep_inside(outcome, str(root))
    assert [d.path for d in outcome.changed] == [str(inside)]
    assert "not fixing" in capsys.readouterr().err


def test_apply_hides_redacts_and_drops_fixes(tmp_path):
    root = tmp_path / "p"
    root.mkdir()
    inside, outside = str(root / "m.moos"), str(tmp_path / "o.plug")
    texts = {inside: "ProcessConfig = pX\n", outside: f"{MARKER} = 1\nkey = 2\n"}

    def finding(path: str, message: str, fix_path: str | None = None) -> Diagnostic:
        fix = None
        if fix_path:
            fix = Fix("respell", (Edit(Span(fix_path, 1), "x"),))
        return Diagnostic(
            "M001", "unknown-parameter", Severity.WARNING, Span(path, 1), message, fix=fix
        )

    kept, hidden = apply(
        [
            finding(outside, "in the outside file"),
            finding(outside, "again"),
            finding(inside, f"`{MARKER}` and `key` and `pX`", fix_path=inside),
            finding(inside, "fix reaches out", fix_path=outside),
        ],
        Boundary(str(root)),
        texts,
    )
    assert hidden == {outside: 2}
    assert kept[0].message == "`…` and `key` and `pX`"  # `key`: a word moos-lint knows
    assert kept[0].fix is not None  # its edit carries no outside word
    assert kept[1].fix is None  # an edit of a file outside: dropped


def test_language_server_diagnostics_never_quote_an_outside_file(project):
    pytest.importorskip("lsprotocol")
    from moos_lint.commands.lsp.analysis import analyse
    from moos_lint.commands.lsp.features import diagnostics

    for name in ("abs.moos", "rel.moos", "path.moos", "macro.moos", "pw.moos"):
        path = str(project / name)
        text = Path(path).read_text()
        analysis = analyse(path, {path: text})
        shown = diagnostics(analysis, text, "utf-16", lambda p: Path(p).read_text().splitlines())
        dumped = repr([(d.message, d.related_information) for d in shown])
        assert MARKER not in dumped, name
    assert os.path.islink(project / "pw.moos")
