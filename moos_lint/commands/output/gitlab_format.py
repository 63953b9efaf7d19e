"""GitLab Code Quality report (a JSON array, the ``codequality`` artifact).

A fingerprint identifies a finding across commits, so it must not change when
unrelated lines move: it hashes the rule code, the file's path, the message
with any line numbers taken out, and the text of the finding's line (without
its indentation). Identical findings in one file are told apart by their rank.
"""

from __future__ import annotations

import hashlib
import json
import re

from moos_lint.commands.output import display_path
from moos_lint.files.boundary import OUTSIDE_CODE, OUTSIDE_NAME, notes
from moos_lint.files.diagnostics import Severity

TYPE_CHECKING = False  # typing itself is not imported at run time
if TYPE_CHECKING:
    from moos_lint.core.result import Result
    from moos_lint.files.diagnostics import Diagnostic

SEVERITIES = {Severity.ERROR: "major", Severity.WARNING: "minor", Severity.INFO: "info"}
_LINE_REFS = re.compile(r"(?i)(?::\d+(?::\d+)?\b|\blines?\s+\d+)")


def line_text(result: Result, d: Diagnostic) -> str:
    src = result.sources.get(d.span.path)
    if src is None:
        return ""
    return src.line(d.span.line).strip()


def fingerprint_key(code: str, path: str, message: str, text: str) -> str:
    return "\x1f".join((code, path, _LINE_REFS.sub(":#", message), text))


def render(result: Result, cwd: str, **_kw) -> str:
    seen: dict[str, int] = {}
    out = []
    for d in result.diagnostics:
        path = display_path(d.span.path, cwd).replace("\\", "/")
        key = fingerprint_key(d.code, path, d.message, line_text(result, d))
        rank = seen.get(key, 0)
        seen[key] = rank + 1
        digest = hashlib.sha256(f"{key}\x1f{rank}".encode("utf-8", "surrogatepass")).hexdigest()
        out.append(
            {
                "description": f"{d.code} [{d.name}] {d.message}",
                "check_name": d.code,
                "fingerprint": digest[:32],
                "severity": SEVERITIES[d.severity],
                "location": {
                    "path": path,
                    "lines": {"begin": d.span.line, "end": max(d.span.end_line, d.span.line)},
                },
            }
        )
    for path, note in notes(result):
        shown = display_path(path, cwd).replace("\\", "/")
        key = fingerprint_key(OUTSIDE_CODE, shown, note, "")
        out.append(
            {
                "description": f"{OUTSIDE_CODE} [{OUTSIDE_NAME}] {note}",
                "check_name": OUTSIDE_CODE,
                "fingerprint": hashlib.sha256(key.encode("utf-8", "surrogatepass")).hexdigest()[
                    :32
                ],
                "severity": "info",
                "location": {"path": shown, "lines": {"begin": 1, "end": 1}},
            }
        )
    return json.dumps(out, indent=2) + "\n"
