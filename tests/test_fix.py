"""Autofix: `--fix` and `--diff`, the fix machinery, and the unused-suppression fix."""

from __future__ import annotations

import io
import os
import shutil
from contextlib import redirect_stderr, redirect_stdout
from pathlib import Path

import pytest

from moos_lint.commands.cli import main
from moos_lint.core.fix import Document, apply_fixes, load_document, write_atomic
from moos_lint.files.diagnostics import Diagnostic, Edit, Fix, Severity, Span

FIXTURES = Path(__file__).resolve().parents[1] / "fixtures" / "fix"
SELECT = "R,L001"


def run(*args: str) -> tuple[int, str, str]:
    out, err = io.StringIO(), io.StringIO()
    with redirect_stdout(out), redirect_stderr(err):
        status = main(list(args))
    return status, out.getvalue(), err.getvalue()


@pytest.fixture
def case(tmp_path, monkeypatch):
    """A copy of a fix fixture's `before/` folder; its `after/` folder is what --fix must make."""

    def make(name: str) -> tuple[Path, Path]:
        work = tmp_path / name
        shutil.copytree(FIXTURES / name / "before", work)
        monkeypatch.chdir(work)
        return work, FIXTURES / name / "after"

    return make


def snapshot(folder: Path) -> dict[str, tuple[bytes, int]]:
    return {p.name: (p.read_bytes(), p.stat().st_mtime_ns) for p in sorted(folder.iterdir())}


def diag(path: str, *edits: Edit, message: str = "m") -> Diagnostic:
    return Diagnostic(
        "L001",
        "unused-suppression",
        Severity.WARNING,
        edits[0].span,
        message,
        fix=Fix(message, edits),
    )


def edit(path: str, line: int, col: int, end_col: int, text: str, end_line: int = 0) -> Edit:
    return Edit(Span(path, line, col, end_line or line, end_col), text)


# ------------------------------------------------------------------------ --fix and --diff


def test_fix_removes_unused_suppressions(case):
    work, after = case("unused-suppression")
    status, out, err = run("check", "mission.moos", "--select", SELECT, "--fix")
    assert status == 0, out
    assert "All checks passed" in out
    assert "fixed 9 finding(s) in 2 file(s)" in err
    for expected in after.iterdir():
        assert (work / expected.name).read_text() == expected.read_text(), expected.name
    assert sorted(p.name for p in work.iterdir()) == sorted(p.name for p in after.iterdir())


def test_diff_previews_and_writes_nothing(case):
    work, _ = case("unused-suppression")
    before = snapshot(work)
    status, out, err = run("check", "mission.moos", "--select", SELECT, "--diff")
    assert status == 1
    assert snapshot(work) == before
    assert out.startswith("--- a/_frag.plug\n+++ b/_frag.plug\n")
    assert "--- a/mission.moos\n+++ b/mission.moos\n" in out
    assert "-// moos-lint: ignore[brace-on-header]\n" in out
    assert "+// moos-lint: disable[R003]\n" in out
    assert "would fix 9 finding(s) in 2 file(s)" in err


def test_diff_matches_what_fix_does(case):
    case("unused-suppression")
    _, diff, _ = run("check", "mission.moos", "--select", SELECT, "--diff")
    run("check", "mission.moos", "--select", SELECT, "--fix")
    _, again, _ = run("check", "mission.moos", "--select", SELECT, "--diff")
    assert diff and again == ""


def test_nothing_is_written_without_fix(case):
    work, _ = case("unused-suppression")
    before = snapshot(work)
    status, _, _ = run("check", "mission.moos", "--select", SELECT)
    assert status == 1
    for fmt in ("json", "sarif"):
        run("check", "mission.moos", "--select", SELECT, "--output-format", fmt)
    assert snapshot(work) == before


def test_fix_without_fixable_findings_writes_nothing(tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    (tmp_path / "m.moos").write_text("ProcessConfig = pA {\n}\n")
    before = snapshot(tmp_path)
    status, out, err = run("check", "m.moos", "--select", SELECT, "--fix")
    assert status == 1 and "R003" in out and err == ""
    assert snapshot(tmp_path) == before
    status, out, _ = run("check", "m.moos", "--select", SELECT, "--diff")
    assert status == 0 and out == ""


def test_fix_reports_what_remains(tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    (tmp_path / "m.moos").write_text("ProcessConfig = pA {   // moos-lint: ignore[R012]\n}\n")
    status, out, _ = run("check", "m.moos", "--select", SELECT, "--fix")
    assert status == 1
    assert "m.moos:1:1: R003" in out and "L001" not in out
    assert (tmp_path / "m.moos").read_text() == "ProcessConfig = pA {\n}\n"


def test_fix_keeps_file_mode_and_leaves_no_temporary_file(tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    path = tmp_path / "m.moos"
    path.write_text("ServerPort = 9000   // moos-lint: ignore[R003]\n")
    os.chmod(path, 0o640)
    run("check", "m.moos", "--select", SELECT, "--fix")
    assert path.read_text() == "ServerPort = 9000\n"
    assert (path.stat().st_mode & 0o777) == 0o640
    assert [p.name for p in tmp_path.iterdir()] == ["m.moos"]


# ------------------------------------------------------------- encodings and line endings


TEMPLATE = [
    "// caf\u00e9 au lait",
    "ServerPort = 9000   // moos-lint: ignore[R003]",
    "// moos-lint: ignore[R012]",
    "ProcessConfig = pA",
    "{",
    "}",
]
FIXED = ["// caf\u00e9 au lait", "ServerPort = 9000", "ProcessConfig = pA", "{", "}"]


@pytest.mark.parametrize("newline", ["\n", "\r\n", "\r"], ids=["lf", "crlf", "cr"])
@pytest.mark.parametrize("encoding", ["utf-8", "utf-8-sig", "latin-1"])
@pytest.mark.parametrize("final_newline", [True, False], ids=["eol", "no-eol"])
def test_fix_keeps_encoding_bom_and_line_endings(
    tmp_path, monkeypatch, newline, encoding, final_newline
):
    monkeypatch.chdir(tmp_path)
    end = newline if final_newline else ""
    data = (newline.join(TEMPLATE) + end).encode(encoding)
    (tmp_path / "m.moos").write_bytes(data)
    run("check", "m.moos", "--select", "R003,R012,L001", "--fix")
    assert (tmp_path / "m.moos").read_bytes() == (newline.join(FIXED) + end).encode(encoding)


def test_fix_of_the_last_line_without_newline(tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    (tmp_path / "m.moos").write_bytes(b"ServerPort = 9000\r\n// moos-lint: ignore[R003]")
    run("check", "m.moos", "--select", SELECT, "--fix")
    assert (tmp_path / "m.moos").read_bytes() == b"ServerPort = 9000\r\n"


# ------------------------------------------------------------------- the generic machinery


def test_overlapping_fixes_are_applied_over_passes(tmp_path):
    path = str(tmp_path / "f.moos")
    Path(path).write_text("abcdef\n")
    docs: dict[str, Document] = {}
    first = diag(path, edit(path, 1, 1, 4, "X"))
    clash = diag(path, edit(path, 1, 3, 5, "Y"))
    later = diag(path, edit(path, 1, 5, 7, "Z"))
    step = apply_fixes([first, clash, later], docs)
    assert step.applied == [first, later] and step.skipped == [clash]
    assert docs[path].text == "XdZ\n"
    assert Path(path).read_text() == "abcdef\n"  # nothing written by the machinery


def test_a_fix_is_all_or_nothing(tmp_path):
    path = str(tmp_path / "f.moos")
    Path(path).write_text("one\ntwo\n")
    docs: dict[str, Document] = {}
    a = diag(path, edit(path, 1, 1, 4, "ONE"))
    both = diag(path, edit(path, 2, 1, 4, "TWO"), edit(path, 1, 2, 3, "N"))
    step = apply_fixes([a, both], docs)
    assert step.skipped == [both]
    assert docs[path].text == "ONE\ntwo\n"


def test_identical_edits_are_applied_once(tmp_path):
    path = str(tmp_path / "f.moos")
    Path(path).write_text("x = 1 // c\n")
    same = edit(path, 1, 6, 11, "")
    docs: dict[str, Document] = {}
    step = apply_fixes([diag(path, same), diag(path, same)], docs)
    assert len(step.applied) == 2
    assert docs[path].text == "x = 1\n"


def test_multiline_edits_and_newlines_follow_the_file(tmp_path):
    path = str(tmp_path / "f.moos")
    Path(path).write_bytes(b"a\r\nb\r\nc\r\n")
    docs: dict[str, Document] = {}
    join = Edit(Span(path, 1, 2, 2, 2), "+")  # "a" .. "b" -> "a+"
    split = edit(path, 3, 2, 2, "\nd")  # after "c": insert a line
    apply_fixes([diag(path, join), diag(path, split)], docs)
    assert docs[path].encode() == b"a+\r\nc\r\nd\r\n"


def test_edit_outside_the_file_or_unencodable_is_skipped(tmp_path):
    path = str(tmp_path / "f.moos")
    Path(path).write_bytes("caf\u00e9\n".encode("latin-1"))
    docs: dict[str, Document] = {}
    far = diag(path, edit(path, 9, 1, 2, "x"))
    pi = diag(path, edit(path, 1, 1, 2, "\u03c0"))
    step = apply_fixes([far, pi], docs)
    assert step.applied == [] and step.skipped == [far, pi]
    assert not docs[path].changed


def test_unreadable_target_is_skipped(tmp_path):
    path = str(tmp_path / "missing.moos")
    step = apply_fixes([diag(path, edit(path, 1, 1, 2, "x"))], {})
    assert step.applied == []
    binary = tmp_path / "b.moos"
    binary.write_bytes(b"\x00\x01")
    assert load_document(str(binary)) is None


def test_write_atomic_replaces_content(tmp_path):
    path = tmp_path / "f.moos"
    path.write_bytes(b"old\n")
    doc = load_document(str(path))
    doc.text = "new\n"
    write_atomic(doc)
    assert path.read_bytes() == b"new\n"
    assert [p.name for p in tmp_path.iterdir()] == ["f.moos"]


def test_fix_through_a_symlink_rewrites_the_target(tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    real = tmp_path / "real"
    real.mkdir()
    (real / "m.moos").write_text("ServerPort = 9000   // moos-lint: ignore[R003]\n")
    (tmp_path / "link.moos").symlink_to(real / "m.moos")
    run("check", "link.moos", "--select", SELECT, "--fix")
    assert (tmp_path / "link.moos").is_symlink()
    assert (real / "m.moos").read_text() == "ServerPort = 9000\n"
    assert sorted(p.name for p in real.iterdir()) == ["m.moos"]
