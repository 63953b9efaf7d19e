"""JSON output: an array of findings in a deterministic order."""

from __future__ import annotations

import json

from moos_lint.commands.output import display_path
from moos_lint.files.boundary import OUTSIDE_CODE, OUTSIDE_NAME, notes
from moos_lint.files.diagnostics import Diagnostic


def to_dict(d: Diagnostic, cwd: str) -> dict:
    s = d.span
    fix = None
    if d.fix is not None:
        fix = {
            "message": d.fix.message,
            "edits": [
                {
                    "path": display_path(e.span.path, cwd),
                    "line": e.span.line,
                    "column": e.span.col,
                    "end_line": e.span.end_line,
                    "end_column": e.span.end_col,
                    "content": e.text,
                }
                for e in d.fix.edits
            ],
        }
    return {
        "code": d.code,
        "name": d.name,
        "severity": d.severity.value,
        "path": display_path(s.path, cwd),
        "line": s.line,
        "column": s.col,
        "end_line": s.end_line,
        "end_column": s.end_col,
        "message": d.message,
        "fix": fix,
        "include_chain": [
            {"path": display_path(site.path, cwd), "line": site.line} for site in d.chain
        ],
    }


def note_dict(path: str, note: str, cwd: str) -> dict:
    """A boundary note (see :mod:`moos_lint.files.boundary`), shaped like a finding."""
    return {
        "code": OUTSIDE_CODE,
        "name": OUTSIDE_NAME,
        "severity": "info",
        "path": display_path(path, cwd),
        "line": 1,
        "column": 1,
        "end_line": 1,
        "end_column": 1,
        "message": note,
        "fix": None,
        "include_chain": [],
    }


def render(result, cwd: str, **_kw) -> str:
    items = [to_dict(d, cwd) for d in result.diagnostics]
    items += [note_dict(path, note, cwd) for path, note in notes(result)]
    if not items:
        return "[]\n"
    # one finding per line: the same JSON, written by the C encoder (indent= is pure Python)
    return "[\n" + ",\n".join("  " + json.dumps(item) for item in items) + "\n]\n"
