"""Bad input never crashes, never hangs and never stops the other files from being linted.

The committed files are in ``fixtures/bad-input/`` (each expected finding marked
``// expect: CODE``, or in a ``NAME.expect`` sidecar for binary files). What git
cannot hold (a FIFO, a device, symlink loops, a 10 MB line, an unreadable file)
is made at test time. The real command line is driven in a subprocess with a
timeout, so a hang fails the test instead of blocking the suite.
"""

from __future__ import annotations

import functools
import json
import os
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

from moos_lint.files.discovery import kind_of
from moos_lint.files.source import read_source
from moos_lint.frontends.nsplug import MAX_INCLUDE_DEPTH
from tests.fixture_expect import FIXTURES, expectations
from tests.unprivileged import unprivileged

BAD = FIXTURES / "bad-input"
TIMEOUT = 180  # seconds; generous for slow CI machines, still far from a hang
CHAIN_DEPTH = 1000
HUGE_LINE = 10 * 1024 * 1024
MANY_LINES = 100_000


def run_cli(*args: str, cwd: Path, timeout: float = TIMEOUT) -> subprocess.CompletedProcess:
    """``moos-lint ARGS`` in a subprocess; a hang raises TimeoutExpired (the test fails)."""
    return subprocess.run(
        [sys.executable, "-m", "moos_lint", *args],
        cwd=cwd,
        stdin=subprocess.DEVNULL,
        capture_output=True,
        text=True,
        timeout=timeout,
    )


def findings(proc: subprocess.CompletedProcess) -> list[dict]:
    assert "Traceback" not in proc.stderr, proc.stderr
    return json.loads(proc.stdout)


@functools.cache
def line_count(path: Path) -> int:
    """How many lines a diagnostic may point at in ``path`` (1 for an empty or unread file)."""
    src = read_source(path)
    lines = getattr(src, "lines", None)
    return max(1, len(lines)) if lines is not None else 1


def check_positions(found: list[dict], cwd: Path) -> None:
    """Every finding names an existing path and a line and columns inside it."""
    for d in found:
        path = cwd / d["path"]
        assert os.path.lexists(path), d
        assert 1 <= d["line"] <= d["end_line"] <= line_count(path), d
        assert d["column"] >= 1 and d["end_column"] >= 1, d
        if d["end_line"] == d["line"]:
            assert d["column"] <= d["end_column"], d
        for site in d["include_chain"]:
            assert 1 <= site["line"] <= line_count(cwd / site["path"]), d


def build_tree(tmp_path: Path) -> tuple[Path, set[tuple[str, int, str]]]:
    """The committed bad inputs plus those made now; returns the tree and what must be found."""
    tree = tmp_path / "bad"
    shutil.copytree(BAD, tree, symlinks=True)
    expected = {(os.path.relpath(p, tree), line, code) for p, line, code in expectations(tree)}

    def want(rel: str, line: int, code: str) -> None:
        expected.add((rel, line, code))

    # A 10 MB single line and a 100,000-line file, with a finding at the very end.
    (tree / "huge-line.moos").write_text("ServerPort = 9000\nLog = " + "x" * HUGE_LINE + "\n")
    want("huge-line.moos", 2, "R008")
    body = "".join(f"key{i} = {i}\n" for i in range(1, MANY_LINES))
    (tree / "many-lines.moos").write_text(body + "}\n")
    want("many-lines.moos", MANY_LINES, "R006")

    # Things that are not regular files: never read, never waited on.
    os.mkfifo(tree / "fifo.moos")
    want("fifo.moos", 1, "R001")
    os.mkfifo(tree / "a-fifo")
    (tree / "include-fifo.moos").write_text("#include a-fifo\nServerPort = 9000\n")
    want("include-fifo.moos", 1, "P001")
    # A link to a file outside the project is not linted: one note (L901).
    os.symlink("/dev/zero", tree / "zero.moos")
    want("zero.moos", 1, "L901")

    # Symlink loops and a dangling link in discovery.
    (tree / "links").mkdir()
    os.symlink("..", tree / "links" / "up")
    os.symlink(".", tree / "links" / "here")
    os.symlink("b.moos", tree / "links" / "a.moos")
    os.symlink("a.moos", tree / "links" / "b.moos")
    os.symlink("nowhere.moos", tree / "links" / "dangling.moos")
    for name in ("a.moos", "b.moos", "dangling.moos"):
        want(f"links/{name}", 1, "R001")

    # An include of a file outside the project: read (it is part of the mission), but
    # its findings are not listed: one note (L901) names the file and counts them.
    outside = tmp_path / "elsewhere" / "outside.plug"
    outside.parent.mkdir()
    outside.write_text("ServerPort = 9000\n}\n")
    (tree / "include-outside.moos").write_text(f"#include {outside}\n")
    want(os.path.relpath(outside, tree), 1, "L901")

    # An include chain 1,000 deep (the chain files have a suffix that is not linted alone).
    chain = tree / "_chain"
    chain.mkdir()
    (tree / "chain.moos").write_text("#include _chain/c0001.inc\n")
    for i in range(1, CHAIN_DEPTH + 1):
        nxt = f"#include _chain/c{i + 1:04d}.inc\n" if i < CHAIN_DEPTH else ""
        (chain / f"c{i:04d}.inc").write_text(f"// level {i}\n{nxt}")
    want(f"_chain/c{MAX_INCLUDE_DEPTH:04d}.inc", 2, "P002")
    return tree, expected


def test_bad_input_tree_end_to_end(tmp_path):
    tree, expected = build_tree(tmp_path)
    proc = run_cli("check", ".", "--output-format", "json", cwd=tree)
    found = findings(proc)
    assert proc.returncode == 1, proc.stderr
    assert not [d for d in found if d["code"] == "L900"]
    check_positions(found, tree)
    codes = {code for _, _, code in expected}
    got = {
        (os.path.relpath(tree / d["path"], tree), d["line"], d["code"])
        for d in found
        if d["code"] in codes
    }
    assert got == expected
    # Each unreadable file is named with the reason.
    messages = {d["path"]: d["message"] for d in found if d["code"] == "R001"}
    assert "directory" in messages["folder.moos"]
    assert "not a regular file" in messages["fifo.moos"]
    notes = {d["path"]: d["message"] for d in found if d["code"] == "L901"}
    assert notes["zero.moos"] == "a link to a file outside the project: not linted"
    assert notes[str(tmp_path / "elsewhere" / "outside.plug")].startswith("1 finding in this")
    assert "NUL" in messages["binary.moos"]
    assert "symbolic links" in messages[os.path.join("links", "a.moos")]


def test_every_rule_survives_the_bad_inputs(tmp_path):
    tree, _ = build_tree(tmp_path)
    proc = run_cli("check", ".", "--select", "ALL", "--output-format", "json", cwd=tree)
    found = findings(proc)
    assert not [d for d in found if d["code"] == "L900"], proc.stderr
    assert proc.returncode == 1
    check_positions(found, tree)
    # The text report shows excerpts of a 10 MB line without printing all of it.
    proc = run_cli("check", ".", "--select", "ALL", cwd=tree)
    assert proc.returncode == 1 and "Traceback" not in proc.stderr
    assert len(proc.stdout) < HUGE_LINE


@pytest.mark.parametrize("target", ["/dev/zero", "fifo.moos", "empty.moos", "binary.moos"])
def test_a_special_path_given_by_name(tmp_path, target):
    tree = tmp_path / "t"
    shutil.copytree(BAD, tree, symlinks=True)
    os.mkfifo(tree / "fifo.moos")
    proc = run_cli("check", target, "--output-format", "json", cwd=tree, timeout=60)
    found = findings(proc)
    if target == "empty.moos":
        assert proc.returncode == 0 and found == []
        return
    assert proc.returncode == 1
    assert [(d["code"], d["line"]) for d in found] == [("R001", 1)]
    assert found[0]["path"] == target


@pytest.mark.parametrize("target", ["/dev/zero", "fifo.moos", "folder.moos", "missing.moos"])
def test_expand_refuses_what_is_not_a_file(tmp_path, target):
    os.mkfifo(tmp_path / "fifo.moos")
    (tmp_path / "folder.moos").mkdir()
    proc = run_cli("expand", target, cwd=tmp_path, timeout=60)
    assert proc.returncode == 2
    assert target in proc.stderr and "Traceback" not in proc.stderr


def test_expand_does_not_block_on_includes_of_devices(tmp_path):
    os.mkfifo(tmp_path / "a-fifo")
    (tmp_path / "adir").mkdir()
    (tmp_path / "m.moos").write_text(
        "#include /dev/zero\n#include a-fifo\n#include adir\n#include m.moos\nServerPort = 1\n"
    )
    proc = run_cli("expand", "m.moos", cwd=tmp_path, timeout=60)
    assert proc.returncode == 1, proc.stderr
    assert proc.stdout == "ServerPort = 1\n"
    assert proc.stderr.count("m.moos:") == 4


@pytest.mark.parametrize("config", ["/dev/zero", "fifo.toml", "folder.toml", "binary.toml"])
def test_a_config_that_is_not_a_text_file(tmp_path, config):
    os.mkfifo(tmp_path / "fifo.toml")
    (tmp_path / "folder.toml").mkdir()
    (tmp_path / "binary.toml").write_bytes(b"\x00\xff\xfe select = [")
    (tmp_path / "m.moos").write_text("ServerPort = 1\n")
    proc = run_cli("check", "m.moos", "--config", config, cwd=tmp_path, timeout=60)
    assert proc.returncode == 2
    assert config in proc.stderr and "Traceback" not in proc.stderr


def test_config_files_that_are_not_files_are_not_read_when_searching(tmp_path):
    os.mkfifo(tmp_path / "moos-lint.toml")
    (tmp_path / ".moos-lint.toml").mkdir()
    (tmp_path / "m.moos").write_text("ServerPort = 1\n}\n")
    proc = run_cli("check", "m.moos", "--output-format", "json", cwd=tmp_path, timeout=60)
    assert [d["code"] for d in findings(proc)] == ["R006"]
    assert proc.returncode == 1


def test_an_unreadable_file_is_reported_and_the_others_are_linted(tmp_path, monkeypatch, capsys):
    """Root-proof: opening the file fails with EACCES, as chmod 000 does for other users."""
    from moos_lint.commands.cli import main
    from moos_lint.files import source

    (tmp_path / "secret.moos").write_text("ServerPort = 1\n")
    (tmp_path / "other.moos").write_text("ServerPort = 1\n}\n")
    real_open = os.open

    def deny(path, *args, **kw):
        if os.fspath(path).endswith("secret.moos"):
            raise PermissionError(13, "Permission denied", os.fspath(path))
        return real_open(path, *args, **kw)

    monkeypatch.setattr(source.os, "open", deny)
    monkeypatch.chdir(tmp_path)
    status = main(["check", ".", "--output-format", "json"])
    found = json.loads(capsys.readouterr().out)
    assert status == 1
    got = {(d["path"], d["line"], d["code"]) for d in found}
    assert ("secret.moos", 1, "R001") in got and ("other.moos", 2, "R006") in got
    assert any("Permission denied" in d["message"] for d in found if d["path"] == "secret.moos")


def test_chmod_000_file_end_to_end():
    # as a user the file's mode shuts out, even when the tests run as root
    with unprivileged() as user:
        tree = user.root / "repo"
        tree.mkdir()
        secret = tree / "secret.moos"
        secret.write_text("ServerPort = 1\n")
        secret.chmod(0)
        (tree / "other.moos").write_text("}\n")
        (tree / "m.moos").write_text("#include secret.moos\n")
        proc = user.cli("check", ".", "--output-format", "json", cwd=tree, timeout=60)
    got = {(d["path"], d["line"], d["code"]) for d in findings(proc)}
    assert {("secret.moos", 1, "R001"), ("other.moos", 1, "R006"), ("m.moos", 1, "P001")} <= got
    assert proc.returncode == 1


def test_deeply_nested_conditionals_and_braces(tmp_path):
    depth = 5000
    text = "".join(f"#ifdef M{i}\n" for i in range(depth))
    text += "ProcessConfig = p\n" + "{\n" * depth + "}\n" * (depth + 1)
    text += "".join("#endif\n" for _ in range(depth))
    (tmp_path / "deep.moos").write_text(text)
    # A line inside each level: the nesting must not cost O(depth) per line.
    text = "".join(f"#ifdef M{i}\nkey{i} = {i}\n#else\nother{i} = {i}\n" for i in range(depth))
    (tmp_path / "alternating.moos").write_text(text + "#endif\n" * depth)
    (tmp_path / "deep.bhv").write_text("{\n" * depth + "}\n" * depth)
    proc = run_cli("check", ".", "--select", "ALL", "--output-format", "json", cwd=tmp_path)
    found = findings(proc)
    assert not [d for d in found if d["code"] == "L900"]
    check_positions(found, tmp_path)


CPP_DEPTH = 1000


@pytest.mark.skipif(kind_of("App.cpp") != "cpp", reason="moos-lint does not lint C++ files")
def test_cpp_bad_inputs(tmp_path):
    """C++ that is deep, broken, binary or not a file: no crash, no hang, the rest linted."""
    app = tmp_path / "pApp"
    app.mkdir()
    deep = "if(a) {" * CPP_DEPTH + 'Notify("DESIRED_SPEED", 1.0);' + "}" * CPP_DEPTH
    (app / "Deep.cpp").write_text(f"bool App::Iterate() {{\n{deep}\nreturn true;\n}}\n")
    (app / "Broken.cpp").write_text(
        'bool App::OnStartUp( {{ Register("NAV_X" ; Notify(,,, "A" ; ))) }}}\n'
        + "class : public CMOOSApp { template< < < #if\n" * 50
        + 'R"(never closed\n'
    )
    (app / "Binary.cpp").write_bytes(b'Notify("A", 1);\x00\x00\xff\xfe\n')
    (app / "Latin1.cpp").write_bytes(b'// caf\xe9\r\nvoid f() { Notify("NAV_HEADING", 1); }\r\n')
    (app / "Bom.h").write_bytes(b"\xef\xbb\xbfclass App : public CMOOSApp {};\r")
    (app / "Empty.cpp").write_bytes(b"")
    (app / "Long.cpp").write_text('void f() { Notify("A", ' + "1+" * 500_000 + "1); }\n")
    (app / "Folder.cpp").mkdir()
    os.mkfifo(app / "Fifo.cpp")
    os.symlink("/dev/zero", app / "Zero.h")
    (tmp_path / "m.moos").write_text("ServerPort = 9000\n}\n")
    proc = run_cli("check", ".", "--select", "ALL", "--output-format", "json", cwd=tmp_path)
    found = findings(proc)
    assert not [d for d in found if d["code"] == "L900"], proc.stderr
    assert proc.returncode == 1, proc.stderr
    check_positions(found, tmp_path)
    assert ("m.moos", 2, "R006") in {(d["path"], d["line"], d["code"]) for d in found}


def test_files_read_to_learn_about_others_are_never_waited_for(tmp_path):
    """A FIFO or a device under the name of a file moos-lint reads to learn about the
    others (a template's kind, a Windows module definition, a launch script, an ignore
    file, a project behavior's C++) is never waited for: the run neither hangs nor
    fails."""
    (tmp_path / ".git").mkdir()
    (tmp_path / "m.moos").write_text(
        "ProcessConfig = ANTLER\n{\n  Run = MOOSDB @ NewConsole = false\n"
        "  Run = pHelmIvP @ NewConsole = false\n}\n"
        "ProcessConfig = pHelmIvP\n{\n  behaviors = m.bhv\n}\n"
    )
    (tmp_path / "m.bhv").write_text(
        "Behavior = BHV_Listener\n{\n  name = x\n}\n"
        "Behavior = BHV_Waypoint\n{\n  name = w\n  condition = HEARD = true\n}\n"
    )
    (tmp_path / "lib").mkdir()
    for name in ("a.meta", "b.def", "launch.sh", ".gitignore", "lib/BHV_Listener.cpp"):
        os.mkfifo(tmp_path / name)
    os.symlink("/dev/zero", tmp_path / "zero.meta")
    proc = run_cli("check", ".", "--select", "ALL", "--output-format", "json", cwd=tmp_path)
    found = findings(proc)
    assert not [d for d in found if d["code"] == "L900"], proc.stderr
    # a `.def` is a MOOS file by its name: one that cannot be read says so; a `.meta`
    # whose text cannot be read is no template
    assert {d["path"] for d in found} == {"m.moos", "m.bhv", "b.def"}
    assert ("b.def", "R001") in {(d["path"], d["code"]) for d in found}
    assert ("m.bhv", "M005") in {(d["path"], d["code"]) for d in found}


@pytest.mark.skipif(kind_of("App.cpp") != "cpp", reason="moos-lint does not lint C++ files")
def test_a_crash_in_the_cpp_reader_is_an_internal_error_not_a_traceback(tmp_path, monkeypatch):
    from moos_lint.core.config import Settings
    from moos_lint.core.engine import INTERNAL_ERROR, lint_files
    from moos_lint.semantics import cpp_units as units

    for folder in ("a", "b"):
        (tmp_path / folder).mkdir()
        (tmp_path / folder / "App.cpp").write_text('void f() { Notify("X", 1); }\n')
    (tmp_path / "m.moos").write_text("}\n")
    real = units.build_cpp_units

    def crash_in_a(run, paths):
        if any(os.sep + "a" + os.sep in p for p in paths):
            raise RecursionError("maximum recursion depth exceeded")
        return real(run, paths)

    monkeypatch.setattr(units, "build_cpp_units", crash_in_a)
    files = [str(tmp_path / "a" / "App.cpp"), str(tmp_path / "b" / "App.cpp")]
    result = lint_files([*files, str(tmp_path / "m.moos")], Settings(root=str(tmp_path)))
    assert result.internal_errors == 1
    got = [(d.code, d.span.path) for d in result.diagnostics]
    assert (INTERNAL_ERROR, files[0]) in got
    assert ("R006", str(tmp_path / "m.moos")) in got
