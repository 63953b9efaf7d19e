"""A rule's snapshot: every finding of its fixtures, whole, as reviewed text.

``fixtures/rules/<rule>/snapshot.txt`` holds, for the ``fire`` and the
``quiet`` folder in turn:

* each finding of the rule, in report order: code, name, severity, span
  (start and end, 1-based, end column exclusive), message, notes, the include
  chain, and its fix: the fix's message, each edit, and the diff of the fix
  applied alone (through :func:`moos_lint.core.fix.apply_fixes`);
* each file as ``moos-lint check --fix`` leaves it (the real fix loop,
  :func:`moos_lint.core.fix.fix_until_stable`, in memory), in full, and the rule's
  findings that remain after the fixes.

Paths are relative to the rule's fixture folder, so a snapshot is the same on
every machine. See CONTRIBUTING.md for how snapshots are written and reviewed.
"""

from __future__ import annotations

import difflib
import os
from pathlib import Path

from moos_lint.core.fix import Document, apply_fixes, unified_diff
from moos_lint.files.diagnostics import Diagnostic, Span
from tests.fixture_expect import FIXTURES, RULE_FIXTURES
from tests.rule_runs import FOLDERS, FolderRun

SNAPSHOT_NAME = "snapshot.txt"
UPDATE_COMMAND = "python -m pytest tests/test_rule_snapshots.py --snapshot-update"
_REPO = FIXTURES.parent


def snapshot_path(rule) -> Path:
    return RULE_FIXTURES / rule.name / SNAPSHOT_NAME


class _Paths:
    """Machine paths made relative to the rule's fixture folder."""

    def __init__(self, rule):
        self.base = str(RULE_FIXTURES / rule.name)

    def rel(self, path: str) -> str:
        return Path(os.path.relpath(os.path.abspath(path), self.base)).as_posix()

    def text(self, text: str) -> str:
        """``text`` (a message, a note) with the machine's paths taken out."""
        text = text.replace(self.base + os.sep, "").replace(self.base, ".")
        return text.replace(str(_REPO) + os.sep, "<repo>/").replace(str(_REPO), "<repo>")


def _plain(text: str) -> bool:
    """No line breaks, no control characters, no trailing blanks: shown as it is."""
    return text == text.rstrip() and not any((c < " " and c != "\t") or c == "\x7f" for c in text)


def _value(text: str) -> str:
    """One field's value on one line, quoted (``~ '...'``) when it is not plain."""
    return text if _plain(text) else f"~ {text!r}"


def _span(s: Span) -> str:
    return f"{s.line}:{s.col}-{s.end_line}:{s.end_col}"


def _diff_lines(diff: str) -> list[str]:
    """A unified diff, a line that is not plain quoted (an empty context line stays empty)."""
    lines = diff.split("\n")[:-1]  # (a carriage return stays in its line, and shows)
    return ["" if line == " " else _value(line) for line in lines]


def _file_text(text: str) -> list[str]:
    """A file's text, ``| line`` for each line (``~ '...'`` for a line that is not plain)."""
    lines = text.split("\n")  # (a carriage return stays in its line, and shows)
    last = lines.pop()
    out = [("| " + body).rstrip() if _plain(body) else _value(body) for body in lines]
    if last:
        out += [("| " + last).rstrip() if _plain(last) else _value(last)]
        out.append("\\ no newline at end of file")
    return out


def _fix_alone(d: Diagnostic, paths: _Paths) -> list[str]:
    """The diff of this one fix applied to the files as they are on disk."""
    docs: dict[str, Document] = {}
    step = apply_fixes([d], docs)
    if not step.applied:
        return ["(this fix does not apply to the file as it is)"]
    out: list[str] = []
    for path, doc in sorted(docs.items()):
        if doc.changed:
            out += _diff_lines(unified_diff(doc, paths.rel(path)))
    return out or ["(this fix changes nothing)"]


def _finding(d: Diagnostic, paths: _Paths) -> list[str]:
    s = d.span
    out = [
        f"-- {paths.rel(s.path)}:{s.line}:{s.col}",
        f"code: {d.code}",
        f"name: {d.name}",
        f"severity: {d.severity.value}",
        f"span: {_span(s)}",
        f"message: {_value(paths.text(d.message))}",
    ]
    out += [f"note: {_value(paths.text(n))}" for n in d.notes]
    out += [f"included from: {paths.rel(site.path)}:{site.line}" for site in d.chain]
    if d.fix is None:
        out.append("fix: none")
        return out
    out.append(f"fix: {_value(paths.text(d.fix.message))}")
    for e in d.fix.edits:
        out.append(f"  edit: {paths.rel(e.span.path)} {_span(e.span)} -> {e.text!r}")
    out.append("  applied alone:")
    out += [f"    {line}".rstrip() for line in _fix_alone(d, paths)]
    return out


def _fixed_files(run: FolderRun, paths: _Paths) -> list[str]:
    outcome = run.fixed
    if not outcome.changed:
        return []
    out = [
        "",
        f"== {run.kind}: the files after `moos-lint check --fix` "
        f"(fixes applied: {outcome.fixed}, passes: {outcome.passes})",
    ]
    for doc in outcome.changed:
        out += ["", f"-- {paths.rel(doc.path)}"]
        out += _file_text(doc.text)
    left = [d for d in outcome.result.diagnostics if d.code == run.rule.code]
    out += ["", f"== {run.kind}: {run.rule.code} findings left after the fixes: {len(left)}"]
    out += [
        f"{paths.rel(d.span.path)}:{d.span.line}:{d.span.col}: {_value(paths.text(d.message))}"
        + (" (offers a fix)" if d.fix is not None else "")
        for d in left
    ]
    return out


def render(rule, runs: dict[str, FolderRun]) -> str:
    """The snapshot text of ``rule`` from the runs of its ``fire`` and ``quiet`` folders."""
    paths = _Paths(rule)
    out = [
        f"# Snapshot of {rule.code} {rule.name}: every finding in its fixtures, and its fixes.",
        f"# Written by `{UPDATE_COMMAND}`;",
        "# review its diff like code.",
    ]
    for kind in FOLDERS:
        run = runs[kind]
        found = run.findings
        out += ["", f"== {kind}: {len(found)} finding{'' if len(found) == 1 else 's'}"]
        for d in found:
            out.append("")
            out += _finding(d, paths)
        out += _fixed_files(run, paths)
    return "\n".join(out) + "\n"


def diff(expected: str, actual: str, name: str) -> str:
    """A readable diff from the stored snapshot to what the rule reports now."""
    return "".join(
        difflib.unified_diff(
            expected.splitlines(keepends=True),
            actual.splitlines(keepends=True),
            fromfile=f"{name} (stored)",
            tofile=f"{name} (now)",
        )
    )
