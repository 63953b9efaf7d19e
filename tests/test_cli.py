"""The command line contract: output, exit status, selection, config, suppressions."""

from __future__ import annotations

import json
import subprocess
import sys
from pathlib import Path

import pytest

from moos_lint.commands.cli import main

ROOT = Path(__file__).resolve().parent.parent
EXAMPLE = ROOT / "fixtures" / "example"

BAD = (
    "ServerPort = 9000\n"
    "ProcessConfig = ANTLER\n{\n  Run = MOOSDB @ NewConsole = false\n}\n"
    "ProcessConfig = pLogger {\n  AsyncLog = true\n}\n"
)


@pytest.fixture
def project(tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    return tmp_path


def run(*args: str) -> tuple[int, str]:
    from io import StringIO

    out = StringIO()
    old = sys.stdout
    sys.stdout = out
    try:
        status = main(list(args))
    finally:
        sys.stdout = old
    return status, out.getvalue()


def test_text_output_has_location_excerpt_and_caret(project):
    (project / "m.moos").write_text(BAD)
    status, out = run("check", "m.moos")
    assert status == 1
    assert "m.moos:6:1: R003 [brace-on-header]" in out
    assert "  6 | ProcessConfig = pLogger {" in out
    assert "^^^^" in out


def test_include_chain_is_shown(project):
    (project / "frag.plug").write_text("ProcessConfig = pX {\n}\n")
    (project / "m.moos").write_text("#include frag.plug\n")
    _, out = run("check", "m.moos", "--select", "R003")
    assert "frag.plug:1:1: R003" in out
    assert "= included from m.moos:1" in out


def test_json_output_keys_and_order(project):
    (project / "b.moos").write_text(BAD)
    (project / "a.moos").write_text("#fidef X\nProcessConfig = pY {\n}\n")
    status, out = run("check", ".", "--output-format", "json")
    data = json.loads(out)
    assert status == 1
    assert [(d["path"], d["line"]) for d in data] == [("a.moos", 1), ("a.moos", 2), ("b.moos", 6)]
    keys = {"code", "name", "severity", "path", "line", "column", "end_line", "end_column"}
    assert keys | {"message", "fix"} <= set(data[0])
    assert data[0]["code"] == "P003" and data[0]["fix"] is None


def test_exit_statuses(project):
    (project / "ok.moos").write_text("ServerPort = 9000\n")
    assert run("check", "ok.moos")[0] == 0
    (project / "bad.moos").write_text(BAD)
    assert run("check", "bad.moos")[0] == 1
    assert run("check", "bad.moos", "--exit-zero")[0] == 0
    assert run("check", "bad.moos", "--select", "no-such-rule")[0] == 2


def test_select_ignore_by_code_prefix_and_name(project):
    (project / "bad.moos").write_text(BAD)
    assert run("check", "bad.moos", "--ignore", "brace-on-header")[0] == 0
    assert run("check", "bad.moos", "--ignore", "R0")[0] == 0
    assert run("check", "bad.moos", "--select", "P", "--extend-select", "R003")[0] == 1
    assert run("check", "bad.moos", "--select", "ALL", "--ignore", "R003")[0] == 0


def test_statistics_and_quiet(project):
    (project / "bad.moos").write_text(BAD)
    _, out = run("check", "bad.moos", "--statistics", "--quiet")
    assert "     1  R003  brace-on-header" in out
    assert "Found" not in out


def test_config_file_and_errors(project):
    (project / "bad.moos").write_text(BAD)
    (project / "moos-lint.toml").write_text('ignore = ["brace-on-header"]\n')
    assert run("check", "bad.moos")[0] == 0
    (project / "moos-lint.toml").write_text('ignroe = ["R003"]\n')
    assert run("check", "bad.moos")[0] == 2
    (project / "moos-lint.toml").write_text('select = ["X999"]\n')
    assert run("check", "bad.moos")[0] == 2
    (project / "moos-lint.toml").write_text("[rules.line-too-long]\nmax-len = 3\n")
    assert run("check", "bad.moos")[0] == 2


def test_pyproject_config_found_walking_up(project):
    (project / "pyproject.toml").write_text(
        '[tool.moos-lint]\nexclude = ["old"]\ndefines = { VNAME = "abe" }\n'
        '[tool.moos-lint.per-file-ignores]\n"sub/*.moos" = ["R003"]\n'
    )
    (project / "sub").mkdir()
    (project / "sub" / "m.moos").write_text(BAD)
    (project / "old").mkdir()
    (project / "old" / "m.moos").write_text(BAD)
    assert run("check", ".")[0] == 0
    status, out = run("check", ".", "--show-settings")
    settings = json.loads(out)
    assert status == 0 and settings["defines"] == {"VNAME": "abe"}
    assert settings["config"].endswith("pyproject.toml")


def test_defines_select_branches(project):
    (project / "m.moos").write_text(
        "#ifdef VNAME abe\nProcessConfig = pA {\n}\n#else\nServerPort = 1\n#endif\n"
    )
    assert run("check", "m.moos", "-D", "VNAME=ben")[0] == 0
    assert run("check", "m.moos", "-D", "VNAME=abe")[0] == 1
    assert run("check", "m.moos")[0] == 1  # unknown: every branch is linted


def test_include_path_option(project):
    (project / "lib").mkdir()
    (project / "lib" / "origin.plug").write_text("LatOrigin = 43.8\n")
    (project / "m.moos").write_text("#include origin.plug\n")
    assert run("check", "m.moos")[0] == 1
    assert run("check", "m.moos", "--include-path", "lib")[0] == 0


def test_suppressions(project):
    (project / "m.moos").write_text(
        "ProcessConfig = pA {   // moos-lint: ignore[R003]\n}\n"
        "// moos-lint: ignore[brace-on-header] the demo needs it\n"
        "ProcessConfig = pB {\n}\n"
        "// moos-lint: disable[R003]\nProcessConfig = pC {\n}\n// moos-lint: enable[R003]\n"
        "ProcessConfig = pD {\n}\n"
    )
    _, out = run("check", "m.moos", "--output-format", "json")
    data = json.loads(out)
    assert [(d["code"], d["line"]) for d in data] == [("R003", 10)]
    (project / "m.moos").write_text("// moos-lint: file-ignore[R]\nProcessConfig = pA {\n}\n")
    assert run("check", "m.moos")[0] == 0


def test_unused_suppression(project):
    (project / "m.moos").write_text("ServerPort = 9000   // moos-lint: ignore[R003]\n")
    _, out = run("check", "m.moos", "--output-format", "json")
    assert [d["code"] for d in json.loads(out)] == ["L001"]
    assert run("check", "m.moos", "--ignore", "R003")[0] == 0


def test_a_missing_path_is_a_usage_error_even_with_exit_zero(project, capsys):
    (project / "bad.moos").write_text(BAD)
    for extra in ([], ["--exit-zero"]):
        status = main(["check", "bad.moos", "nope.moos", "--output-format", "json", *extra])
        out, err = capsys.readouterr()
        assert status == 2 and out == ""
        assert "nope.moos: no such file or directory" in err


def test_expand_command(project, capsys):
    (project / "m.moos").write_text("#define W 4\n#ifdef VNAME abe\nx = $(W)\n#endif\ny = $(U)\n")
    assert main(["expand", "m.moos", "--define", "VNAME=abe"]) == 0
    assert capsys.readouterr().out == "x = 4\ny = $(U)\n"
    (project / "n.moos").write_text("#include missing.plug\n")
    assert main(["expand", "n.moos"]) == 1
    assert "missing.plug" in capsys.readouterr().err


def test_rule_and_rules_commands(capsys):
    assert main(["rule", "R003"]) == 0
    page = capsys.readouterr().out
    assert page.startswith("# R003 brace-on-header") and "## How to fix" in page
    assert main(["rule", "brace-on-header"]) == 0
    assert main(["rule", "nope"]) == 2
    capsys.readouterr()
    assert main(["rules", "--output-format", "json"]) == 0
    assert any(r["name"] == "brace-on-header" for r in json.loads(capsys.readouterr().out))


def test_console_script_runs_on_the_example():
    proc = subprocess.run(
        [sys.executable, "-m", "moos_lint", "check", str(EXAMPLE), "--output-format", "json"],
        capture_output=True,
        text=True,
        timeout=120,
    )
    assert proc.returncode == 1, proc.stderr
    codes = {d["code"] for d in json.loads(proc.stdout)}
    assert {"R003", "R007"} <= codes


def test_version_is_fast_and_light():
    code = (
        "import sys, moos_lint.commands.cli as c\n"
        "try:\n c.main(['--version'])\nexcept SystemExit: pass\n"
        "print(sorted(m for m in sys.modules if m.split('.')[0] in "
        "('tree_sitter', 'clang', 'pygls', 'moos_lint')))"
    )
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True).stdout
    assert "tree_sitter" not in out and "pygls" not in out and "clang" not in out
    assert "moos_lint.core.engine" not in out
