"""A lint result as JSON data, and back, for the result cache (:mod:`moos_lint.speed.cache`).

:func:`decode_result` checks every value against the layout :func:`encode_result`
writes (types, lengths, known severities) and raises :class:`BadEntry` on the
first difference: an entry of another layout or version is a cache miss,
never a half-built result.
"""

from __future__ import annotations

from pathlib import Path

from moos_lint.core.result import Result
from moos_lint.files.diagnostics import Diagnostic, Edit, Fix, IncludeSite, Severity, Span
from moos_lint.files.source import SourceFile, split_lines

TYPE_CHECKING = False
if TYPE_CHECKING:
    from typing import Any

#: bump when the layout below changes
LAYOUT = 2
_SEVERITIES = {s.value: s for s in Severity}


class BadEntry(ValueError):
    """A stored value that is not what this version of moos-lint writes."""


def want(value: Any, kind: type | tuple[type, ...], what: str) -> Any:
    """``value`` when it has type ``kind`` (a bool is not an int here), else BadEntry."""
    if not isinstance(value, kind) or (isinstance(value, bool) and bool not in _types(kind)):
        raise BadEntry(f"{what}: expected {kind}, got {type(value).__name__}")
    return value


def _types(kind: type | tuple[type, ...]) -> tuple[type, ...]:
    return kind if isinstance(kind, tuple) else (kind,)


def want_list(value: Any, what: str, length: int | None = None) -> list:
    want(value, list, what)
    if length is not None and len(value) != length:
        raise BadEntry(f"{what}: expected {length} items, got {len(value)}")
    return value


def want_strings(value: Any, what: str) -> list[str]:
    for v in want_list(value, what):
        want(v, str, what)
    return value


# ------------------------------------------------------------------ encoding
def _span(s: Span) -> list:
    return [s.path, s.line, s.col, s.end_line, s.end_col]


def _diagnostic(d: Diagnostic) -> dict:
    fix = None
    if d.fix is not None:
        fix = [d.fix.message, [[_span(e.span), e.text] for e in d.fix.edits]]
    return {
        "code": d.code,
        "name": d.name,
        "severity": d.severity.value,
        "span": _span(d.span),
        "message": d.message,
        "chain": [[c.path, c.line] for c in d.chain],
        "fix": fix,
        "notes": list(d.notes),
    }


def _source(src: SourceFile) -> dict:
    out = {
        "path": str(src.path),
        "text": src.text,
        "encoding": src.encoding,
        "bom": src.bom,
        "newline": src.newline,
    }
    lines = src._lines  # (lines never split need not be stored: they follow from the text)
    if lines is not None and lines != split_lines(src.text):
        out["lines"] = list(lines)
    return out


def encode_result(result: Result, keep_sources: set[str]) -> dict:
    """The findings, files, counts and the text of the files in ``keep_sources``."""
    return {
        "layout": LAYOUT,
        "diagnostics": [_diagnostic(d) for d in result.diagnostics],
        "files": list(result.files),
        "internal_errors": result.internal_errors,
        "missing": list(result.missing),
        "sources": {p: _source(s) for p, s in result.sources.items() if p in keep_sources},
        "outside": dict(result.outside),
        "outside_links": list(result.outside_links),
    }


# ------------------------------------------------------------------ decoding
def _decode_span(v: Any, what: str) -> Span:
    path, line, col, end_line, end_col = want_list(v, what, 5)
    want(path, str, what)
    for n in (line, col, end_line, end_col):
        want(n, int, what)
    return Span(path, line, col, end_line, end_col)


def _decode_diagnostic(v: Any) -> Diagnostic:
    want(v, dict, "finding")
    if set(v) != {"code", "name", "severity", "span", "message", "chain", "fix", "notes"}:
        raise BadEntry("finding: unexpected keys")
    severity = _SEVERITIES.get(want(v["severity"], str, "severity"))
    if severity is None:
        raise BadEntry("finding: unknown severity")
    chain = []
    for site in want_list(v["chain"], "chain"):
        path, line = want_list(site, "include site", 2)
        chain.append(IncludeSite(want(path, str, "include site"), want(line, int, "include site")))
    fix = None
    if v["fix"] is not None:
        message, edits = want_list(v["fix"], "fix", 2)
        fix = Fix(
            want(message, str, "fix"),
            tuple(
                Edit(_decode_span(span, "edit"), want(text, str, "edit"))
                for span, text in (want_list(e, "edit", 2) for e in want_list(edits, "edits"))
            ),
        )
    return Diagnostic(
        code=want(v["code"], str, "code"),
        name=want(v["name"], str, "name"),
        severity=severity,
        span=_decode_span(v["span"], "span"),
        message=want(v["message"], str, "message"),
        chain=tuple(chain),
        fix=fix,
        notes=want_strings(v["notes"], "notes"),
    )


def _decode_source(v: Any) -> SourceFile:
    want(v, dict, "source")
    if not set(v) <= {"path", "text", "encoding", "bom", "newline", "lines"}:
        raise BadEntry("source: unexpected keys")
    text = want(v["text"], str, "source text")
    lines = want_strings(v["lines"], "source lines") if "lines" in v else None
    return SourceFile(
        path=Path(want(v["path"], str, "source path")),
        text=text,
        encoding=want(v["encoding"], str, "encoding"),
        bom=want(v["bom"], bool, "bom"),
        newline=want(v["newline"], str, "newline"),
        lines=lines,
    )


def decode_result(v: Any) -> Result:
    """The result :func:`encode_result` stored, or BadEntry."""
    want(v, dict, "result")
    if v.get("layout") != LAYOUT or set(v) != {
        "layout",
        "diagnostics",
        "files",
        "internal_errors",
        "missing",
        "sources",
        "outside",
        "outside_links",
    }:
        raise BadEntry("result: another layout")
    sources = want(v["sources"], dict, "sources")
    outside = want(v["outside"], dict, "outside")
    for path, count in outside.items():
        want(path, str, "outside")
        want(count, int, "outside")
    return Result(
        diagnostics=[_decode_diagnostic(d) for d in want_list(v["diagnostics"], "findings")],
        files=want_strings(v["files"], "files"),
        internal_errors=want(v["internal_errors"], int, "internal errors"),
        missing=want_strings(v["missing"], "missing"),
        sources={want(p, str, "source"): _decode_source(s) for p, s in sources.items()},
        outside=outside,
        outside_links=want_strings(v["outside_links"], "outside links"),
    )
