"""SARIF 2.1.0 output, for GitHub code scanning and other SARIF viewers.

One run, with a rules table (every registered rule: id, name, short and full
description, help text and page, default level and whether it is on by
default) and one result per finding. Paths under the working directory are
relative URIs against ``%SRCROOT%`` (the working directory); the include chain
becomes ``relatedLocations`` and a fix becomes a SARIF ``fix``.
"""

from __future__ import annotations

import json
import os
from pathlib import Path
from urllib.parse import quote

from moos_lint import __version__
from moos_lint.core.registry import Rule, all_rules, doc_sections
from moos_lint.files.boundary import OUTSIDE_CODE, notes
from moos_lint.files.diagnostics import Diagnostic, Fix, Severity, Span

TYPE_CHECKING = False  # typing itself is not imported at run time
if TYPE_CHECKING:
    from moos_lint.core.result import Result

SCHEMA_URI = "https://json.schemastore.org/sarif-2.1.0.json"
INFORMATION_URI = "https://github.com/moos-lint/moos-lint"
LEVELS = {Severity.ERROR: "error", Severity.WARNING: "warning", Severity.INFO: "note"}
SRCROOT = "%SRCROOT%"


def _artifact(path: str, cwd: str) -> dict:
    """An artifactLocation: relative to ``%SRCROOT%`` when under it, else a file URI."""
    try:
        rel = os.path.relpath(path, cwd)
    except ValueError:
        rel = ".."
    if rel == ".." or rel.startswith(".." + os.sep) or os.path.isabs(rel):
        return {"uri": Path(os.path.abspath(path)).as_uri()}
    return {"uri": quote(rel.replace(os.sep, "/")), "uriBaseId": SRCROOT}


def _region(span: Span) -> dict:
    region = {"startLine": max(span.line, 1), "startColumn": max(span.col, 1)}
    if span.end_line >= span.line:
        region["endLine"] = max(span.end_line, 1)
    if span.end_col > 0:
        region["endColumn"] = max(span.end_col, 1)
    return region


def _rule_descriptor(r: Rule) -> dict:
    sections = doc_sections(r.doc)
    full = sections.get("What it does") or r.summary
    return {
        "id": r.code,
        "name": r.name,
        "shortDescription": {"text": r.summary},
        "fullDescription": {"text": full},
        "help": {"text": f"{r.summary} See {r.url}", "markdown": r.doc.strip() or r.summary},
        "helpUri": r.url,
        "defaultConfiguration": {
            "level": LEVELS[r.severity],
            "enabled": r.default_enabled,
        },
        "properties": {"scope": r.scope.value, "fixable": r.fixable},
    }


def _extra_descriptor(d: Diagnostic) -> dict:
    """A descriptor for a code that is no registered rule (L900 internal errors)."""
    return {
        "id": d.code,
        "name": d.name,
        "shortDescription": {"text": d.name.replace("-", " ")},
        "defaultConfiguration": {"level": LEVELS[d.severity]},
    }


def _fix(fix: Fix, cwd: str) -> dict:
    by_path: dict[str, list[dict]] = {}
    for e in fix.edits:
        by_path.setdefault(e.span.path, []).append(
            {"deletedRegion": _region(e.span), "insertedContent": {"text": e.text}}
        )
    return {
        "description": {"text": fix.message},
        "artifactChanges": [
            {"artifactLocation": _artifact(p, cwd), "replacements": reps}
            for p, reps in by_path.items()
        ],
    }


def _result(d: Diagnostic, index: int, cwd: str) -> dict:
    out: dict = {
        "ruleId": d.code,
        "ruleIndex": index,
        "level": LEVELS[d.severity],
        "message": {"text": d.message},
        "locations": [
            {
                "physicalLocation": {
                    "artifactLocation": _artifact(d.span.path, cwd),
                    "region": _region(d.span),
                }
            }
        ],
    }
    if d.chain:
        out["relatedLocations"] = [
            {
                "id": i,
                "physicalLocation": {
                    "artifactLocation": _artifact(site.path, cwd),
                    "region": {"startLine": max(site.line, 1)},
                },
                "message": {"text": "included from here"},
            }
            for i, site in enumerate(reversed(d.chain))
        ]
    if d.fix is not None and d.fix.edits:
        out["fixes"] = [_fix(d.fix, cwd)]
    return out


def _invocation(result: Result, cwd: str) -> dict:
    """The run's invocation: whether it succeeded (no internal error, and something to
    lint), a warning when it found nothing to lint, and a notification for each file
    outside the project whose findings are not shown (see :mod:`moos_lint.files.boundary`)."""
    out: dict = {"executionSuccessful": not result.internal_errors and not result.warnings}
    # a run that found nothing to lint did not do its job: a warning says so
    notifications: list[dict] = [
        {"level": "warning", "message": {"text": w}} for w in result.warnings
    ]
    notifications += [
        {
            "descriptor": {"id": OUTSIDE_CODE},
            "level": "note",
            "message": {"text": note},
            "locations": [{"physicalLocation": {"artifactLocation": _artifact(path, cwd)}}],
        }
        for path, note in notes(result)
    ]
    if notifications:
        out["toolExecutionNotifications"] = notifications
    return out


def to_sarif(result: Result, cwd: str) -> dict:
    rules = all_rules()
    descriptors = [_rule_descriptor(r) for r in rules]
    index = {r.code: i for i, r in enumerate(rules)}
    results = []
    for d in result.diagnostics:
        if d.code not in index:
            index[d.code] = len(descriptors)
            descriptors.append(_extra_descriptor(d))
        results.append(_result(d, index[d.code], cwd))
    root_uri = Path(os.path.abspath(cwd)).as_uri().rstrip("/") + "/"
    return {
        "$schema": SCHEMA_URI,
        "version": "2.1.0",
        "runs": [
            {
                "tool": {
                    "driver": {
                        "name": "moos-lint",
                        "version": __version__,
                        "semanticVersion": __version__,
                        "informationUri": INFORMATION_URI,
                        "rules": descriptors,
                    }
                },
                "originalUriBaseIds": {SRCROOT: {"uri": root_uri}},
                "columnKind": "unicodeCodePoints",
                "invocations": [_invocation(result, cwd)],
                "results": results,
            }
        ],
    }


def render(result: Result, cwd: str, **_kw) -> str:
    return json.dumps(to_sarif(result, cwd), indent=2) + "\n"
