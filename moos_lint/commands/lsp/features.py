"""The editor features: diagnostics, hover, code actions, definitions, completion.

Each function takes the document's text and its last :class:`Analysis` and
returns lsprotocol objects; none of them touches the connection, so they are
tested without a server. Columns inside moos-lint are Python string indices;
they are converted to the position encoding the client asked for.
"""

from __future__ import annotations

import os
import re
from collections.abc import Callable

from lsprotocol import types as lsp

from moos_lint.commands.lsp.analysis import Analysis, Finding
from moos_lint.commands.lsp.catalogue import Catalogue, Component
from moos_lint.commands.lsp.documents import path_to_uri
from moos_lint.commands.rule_page import render_rule_page
from moos_lint.core.registry import all_rules, get_rule, is_valid_selector, matches
from moos_lint.files.diagnostics import Severity, Span
from moos_lint.files.source import split_lines
from moos_lint.frontends.nsplug import Preprocessor, tag_of

SOURCE = "moos-lint"
_SEVERITY = {
    Severity.ERROR: lsp.DiagnosticSeverity.Error,
    Severity.WARNING: lsp.DiagnosticSeverity.Warning,
    Severity.INFO: lsp.DiagnosticSeverity.Information,
}
_SUPPRESSION = re.compile(
    r"//\s*moos-lint:\s*(?:ignore|disable|enable|file-ignore)\s*\[(?P<codes>[^\]]*)\]"
)
_IGNORE = re.compile(r"//\s*moos-lint:\s*ignore\s*\[(?P<codes>[^\]]*)\]")
_INCLUDE = re.compile(r"^\s*#include\s+(?P<rest>.*?)\s*$")
_INCLUDE_TAG = re.compile(r"^(.*?)\s*<([^<>]+)>\s*$")
_KEY_VALUE = re.compile(r"^(?P<indent>\s*)(?P<key>[^=\s][^=]*?)\s*=\s*(?P<value>.*?)\s*$")
_HEADER = re.compile(r"^\s*(?P<what>ProcessConfig|Behavior)\s*=\s*(?P<name>[^\s{]+)", re.I)
_RUN = re.compile(r"^\s*Run\s*=\s*(?P<binary>[^\s@~]+)[^~]*(?:~\s*(?P<alias>\S+))?", re.I)

#: How a position is counted by the client, as negotiated at initialisation.
Encoding = str  # "utf-8" | "utf-16" | "utf-32"


# ------------------------------------------------------------------ positions
def _units(text: str, encoding: Encoding) -> int:
    if encoding == "utf-32":
        return len(text)
    if encoding == "utf-8":
        return len(text.encode("utf-8", "surrogatepass"))
    return len(text) + sum(1 for c in text if ord(c) > 0xFFFF)


def to_client(line: str, col: int, encoding: Encoding) -> int:
    """A 0-based string index in ``line`` as the client counts it."""
    return _units(line[: max(0, col)], encoding)


def from_client(line: str, character: int, encoding: Encoding) -> int:
    """A client's character offset in ``line`` as a 0-based string index."""
    if encoding == "utf-32":
        return max(0, min(character, len(line)))
    count = 0
    for idx, c in enumerate(line):
        if count >= character:
            return idx
        count += _units(c, encoding)
    return len(line)


def _line(lines: list[str], lineno: int) -> str:
    """The text of 0-based line ``lineno`` ('' past the end)."""
    return lines[lineno] if 0 <= lineno < len(lines) else ""


def span_range(span: Span, lines: list[str], encoding: Encoding) -> lsp.Range:
    """An LSP range for a 1-based span; an empty span covers its line's text."""
    start_line, end_line = span.line - 1, span.end_line - 1
    start_col, end_col = span.col - 1, span.end_col - 1
    if start_line == end_line and end_col <= start_col:
        text = _line(lines, start_line)
        start_col = len(text) - len(text.lstrip())
        end_col = len(text.rstrip())
    first, last = _line(lines, start_line), _line(lines, end_line)
    return lsp.Range(
        start=lsp.Position(max(0, start_line), to_client(first, start_col, encoding)),
        end=lsp.Position(max(0, end_line), to_client(last, end_col, encoding)),
    )


def _contains(rng: lsp.Range, pos: lsp.Position) -> bool:
    start = (rng.start.line, rng.start.character)
    end = (rng.end.line, rng.end.character)
    return start <= (pos.line, pos.character) <= end


# ---------------------------------------------------------------- diagnostics
LinesOf = Callable[[str], list[str]]


def to_diagnostic(
    finding: Finding, lines: list[str], encoding: Encoding, lines_of: LinesOf
) -> lsp.Diagnostic:
    d = finding.diagnostic
    r = get_rule(d.code)
    message = d.message
    related = None
    if finding.via is not None:
        where = os.path.basename(d.span.path)
        message = f"in included `{where}` line {d.span.line}: {d.message}"
        related = [
            lsp.DiagnosticRelatedInformation(
                location=lsp.Location(
                    uri=path_to_uri(d.span.path),
                    range=span_range(d.span, lines_of(d.span.path), encoding),
                ),
                message=d.message,
            )
        ]
    if d.notes:
        message += "\n" + "\n".join(d.notes)
    tags = None
    if r is not None and r.name == "unused-suppression":
        tags = [lsp.DiagnosticTag.Unnecessary]
    return lsp.Diagnostic(
        range=span_range(finding.span, lines, encoding),
        message=message,
        severity=_SEVERITY.get(d.severity, lsp.DiagnosticSeverity.Warning),
        code=d.code,
        code_description=lsp.CodeDescription(href=r.url) if r is not None else None,
        source=SOURCE,
        tags=tags,
        related_information=related,
    )


def diagnostics(
    analysis: Analysis, text: str, encoding: Encoding, lines_of: LinesOf
) -> list[lsp.Diagnostic]:
    lines = split_lines(text)
    return [to_diagnostic(f, lines, encoding, lines_of) for f in analysis.findings]


def findings_at(
    analysis: Analysis, lines: list[str], encoding: Encoding, rng: lsp.Range
) -> list[tuple[Finding, lsp.Range]]:
    out = []
    for f in analysis.findings:
        frange = span_range(f.span, lines, encoding)
        if _contains(frange, rng.start) or _contains(rng, frange.start):
            out.append((f, frange))
    return out


# ---------------------------------------------------------------------- hover
def _rule_docs(code: str) -> str | None:
    r = get_rule(code)
    return render_rule_page(r) if r is not None else None


def _selector_docs(selector: str) -> str | None:
    r = get_rule(selector)
    if r is not None:
        return render_rule_page(r)
    if not is_valid_selector(selector):
        return f"`{selector}` names no moos-lint rule."
    rows = [f"- `{x.code}` {x.name}: {x.summary}" for x in all_rules() if matches(selector, x)]
    return f"`{selector}` selects {len(rows)} rule(s):\n\n" + "\n".join(rows)


def hover(
    analysis: Analysis | None,
    text: str,
    pos: lsp.Position,
    encoding: Encoding,
    catalogue: Catalogue,
) -> lsp.Hover | None:
    lines = split_lines(text)
    line = _line(lines, pos.line)
    col = from_client(line, pos.character, encoding)
    # A code inside a suppression comment.
    for m in _SUPPRESSION.finditer(line):
        start = m.start("codes")
        if not start <= col <= m.end("codes"):
            continue
        offset = start
        for piece in m.group("codes").split(","):
            sel = piece.strip()
            lo = offset + piece.find(sel) if sel else offset
            if sel and lo <= col <= lo + len(sel):
                docs = _selector_docs(sel)
                rng = lsp.Range(
                    lsp.Position(pos.line, to_client(line, lo, encoding)),
                    lsp.Position(pos.line, to_client(line, lo + len(sel), encoding)),
                )
                return _markdown(docs, rng) if docs else None
            offset += len(piece) + 1
    # Findings under the cursor.
    if analysis is not None:
        here = lsp.Range(pos, pos)
        parts, seen = [], set()
        for f, _rng in findings_at(analysis, lines, encoding, here):
            d = f.diagnostic
            if d.code in seen:
                continue
            seen.add(d.code)
            docs = _rule_docs(d.code)
            parts.append(f"**{d.code} {d.name}**: {d.message}" + (f"\n\n{docs}" if docs else ""))
        if parts:
            return _markdown("\n\n---\n\n".join(parts))
    # A parameter or a component name, from the catalogue.
    if not catalogue.empty:
        docs = _catalogue_hover(lines, pos.line, col, analysis, catalogue)
        if docs:
            return _markdown(docs)
    return None


def _markdown(value: str, rng: lsp.Range | None = None) -> lsp.Hover:
    return lsp.Hover(
        contents=lsp.MarkupContent(kind=lsp.MarkupKind.Markdown, value=value), range=rng
    )


# ----------------------------------------------------------- block context
def enclosing_header(lines: list[str], lineno: int) -> tuple[str, str] | None:
    """``("processconfig"|"behavior", NAME)`` of the block around 0-based ``lineno``."""
    depth = 0
    for idx in range(min(lineno, len(lines)) - 1, -1, -1):
        s = lines[idx].split("//", 1)[0].strip()
        if s.startswith("}"):
            depth += 1
            continue
        if "{" not in s:
            continue
        if depth:
            depth -= 1
            continue
        header = s if s != "{" else ""
        if not header:
            for back in range(idx - 1, -1, -1):
                header = lines[back].split("//", 1)[0].strip()
                if header:
                    break
        m = _HEADER.match(header)
        return (m.group("what").lower(), m.group("name")) if m else None
    return None


def _aliases(lines: list[str]) -> dict[str, str]:
    """``alias -> binary`` from the document's ``Run = BINARY ~ ALIAS`` lines."""
    out = {}
    for line in lines:
        m = _RUN.match(line)
        if m and m.group("alias"):
            out[m.group("alias").lower()] = m.group("binary").replace("\\", "/").split("/")[-1]
    return out


def _component(
    lines: list[str], header: tuple[str, str] | None, catalogue: Catalogue
) -> Component | None:
    if header is None:
        return None
    what, name = header
    if what == "behavior":
        return catalogue.behavior(name)
    found = catalogue.app(name)
    if found is None:
        binary = _aliases(lines).get(name.lower())
        found = catalogue.app(binary) if binary else None
    return found


def _catalogue_hover(
    lines: list[str], lineno: int, col: int, analysis: Analysis | None, catalogue: Catalogue
) -> str | None:
    line = _line(lines, lineno)
    m = _HEADER.match(line)
    if m and m.start("name") <= col <= m.end("name"):
        comp = _component(lines, (m.group("what").lower(), m.group("name")), catalogue)
        return f"**{comp.name}**\n\n{comp.doc}".rstrip() if comp else None
    m = _RUN.match(line)
    if m and m.start("binary") <= col <= m.end("binary"):
        comp = catalogue.app(m.group("binary").replace("\\", "/").split("/")[-1])
        return f"**{comp.name}**\n\n{comp.doc}".rstrip() if comp else None
    kv = _KEY_VALUE.match(line)
    if not kv or not kv.start("key") <= col <= kv.end("key"):
        return None
    comp = _component(lines, enclosing_header(lines, lineno), catalogue)
    info = comp.param(kv.group("key")) if comp else None
    if comp is None or info is None:
        return None
    return f"**{comp.name}** `{info.name}`\n\n{info.doc}".rstrip()


# ------------------------------------------------------------------ completion
def completion(
    text: str, pos: lsp.Position, encoding: Encoding, catalogue: Catalogue
) -> list[lsp.CompletionItem]:
    if catalogue.empty:
        return []
    lines = split_lines(text)
    line = _line(lines, pos.line)
    before = line[: from_client(line, pos.character, encoding)]
    if re.match(r"^\s*Run\s*=\s*[^\s@~]*$", before, re.I):
        return [_item(c, lsp.CompletionItemKind.Module) for c in catalogue.apps()]
    if re.match(r"^\s*ProcessConfig\s*=\s*\S*$", before, re.I):
        return [_item(c, lsp.CompletionItemKind.Module) for c in catalogue.apps()]
    if re.match(r"^\s*Behavior\s*=\s*\S*$", before, re.I):
        return [_item(c, lsp.CompletionItemKind.Class) for c in catalogue.behaviors()]
    if "=" in before or not re.match(r"^\s*[\w.]*$", before):
        return []
    comp = _component(lines, enclosing_header(lines, pos.line), catalogue)
    if comp is None:
        return []
    return [
        lsp.CompletionItem(
            label=p.name,
            kind=lsp.CompletionItemKind.Property,
            detail=comp.name,
            documentation=p.doc or None,
            insert_text=f"{p.name} = ",
        )
        for p in comp.params.values()
    ]


def _item(c: Component, kind: lsp.CompletionItemKind) -> lsp.CompletionItem:
    return lsp.CompletionItem(label=c.name, kind=kind, documentation=c.doc or None)


# ---------------------------------------------------------------- code actions
def code_actions(
    uri: str,
    analysis: Analysis | None,
    text: str,
    params: lsp.CodeActionParams,
    encoding: Encoding,
    lines_of: LinesOf,
) -> list[lsp.CodeAction]:
    if analysis is None:
        return []
    lines = split_lines(text)
    newline = "\r\n" if "\r\n" in text else "\n"
    wanted = [d for d in params.context.diagnostics if d.source == SOURCE]
    out: list[lsp.CodeAction] = []
    done_suppress: set[tuple[int, str]] = set()
    for f, frange in findings_at(analysis, lines, encoding, params.range):
        d = f.diagnostic
        matching = [x for x in wanted if x.code == d.code and x.range == frange]
        if wanted and not matching:
            continue
        fix = f.fix
        if fix is not None and fix.edits:
            changes: dict[str, list[lsp.TextEdit]] = {}
            for edit in fix.edits:
                elines = lines if edit.span.path == analysis.path else lines_of(edit.span.path)
                changes.setdefault(path_to_uri(edit.span.path), []).append(
                    lsp.TextEdit(
                        range=span_range_exact(edit.span, elines, encoding), new_text=edit.text
                    )
                )
            out.append(
                lsp.CodeAction(
                    title=fix.message,
                    kind=lsp.CodeActionKind.QuickFix,
                    diagnostics=matching or None,
                    is_preferred=True,
                    edit=lsp.WorkspaceEdit(changes=changes),
                )
            )
        key = (f.span.line, d.code)
        if f.via is None and key not in done_suppress:
            done_suppress.add(key)
            edit = suppression_edit(lines, f.span.line - 1, d.code, encoding, newline)
            out.append(
                lsp.CodeAction(
                    title=f"Suppress {d.code} ({d.name}) on this line",
                    kind=lsp.CodeActionKind.QuickFix,
                    diagnostics=matching or None,
                    edit=lsp.WorkspaceEdit(changes={uri: [edit]}),
                )
            )
    return out


def span_range_exact(span: Span, lines: list[str], encoding: Encoding) -> lsp.Range:
    """An LSP range for an edit's span, empty spans kept empty (an insertion)."""
    first, last = _line(lines, span.line - 1), _line(lines, span.end_line - 1)
    return lsp.Range(
        start=lsp.Position(span.line - 1, to_client(first, span.col - 1, encoding)),
        end=lsp.Position(span.end_line - 1, to_client(last, span.end_col - 1, encoding)),
    )


def suppression_edit(
    lines: list[str], lineno: int, code: str, encoding: Encoding, newline: str = "\n"
) -> lsp.TextEdit:
    """Add ``code`` to the line's ``// moos-lint: ignore[...]`` comment, or write one.

    The comment goes at the end of the line, except on a ``#`` directive line
    (nsplug would read it as part of the directive): there it goes on its own
    line just above, where it covers the next line.
    """
    line = _line(lines, lineno)
    directive = line.lstrip().startswith("#")
    target = lineno - 1 if directive else lineno
    target_text = _line(lines, target) if target >= 0 else ""
    m = _IGNORE.search(target_text)
    if m and (not directive or not target_text[: m.start()].strip()):
        codes = [c.strip() for c in m.group("codes").split(",") if c.strip()]
        at = m.end("codes")
        insert = code if not codes else ", " + code
        if not codes:
            at = m.start("codes")
        pos = lsp.Position(target, to_client(target_text, at, encoding))
        return lsp.TextEdit(range=lsp.Range(pos, pos), new_text=insert)
    comment = f"// moos-lint: ignore[{code}]"
    if directive:
        indent = line[: len(line) - len(line.lstrip())]
        pos = lsp.Position(lineno, 0)
        return lsp.TextEdit(range=lsp.Range(pos, pos), new_text=indent + comment + newline)
    end = lsp.Position(lineno, to_client(line, len(line), encoding))
    sep = "" if not line or line[-1] in " \t" else "  "
    return lsp.TextEdit(range=lsp.Range(end, end), new_text=sep + comment)


# ----------------------------------------------------------------- definition
def definition(
    path: str,
    text: str,
    pos: lsp.Position,
    encoding: Encoding,
    analysis: Analysis | None,
    top_dirs: list[str],
    lines_of: LinesOf,
) -> lsp.Location | None:
    """The file an ``#include`` line or a ``behaviors = FILE`` value names."""
    lines = split_lines(text)
    line = _line(lines, pos.line)
    settings = analysis.settings if analysis is not None else None
    pre = Preprocessor(
        defines=settings.defines if settings else {},
        include_paths=settings.include_paths if settings else [],
    )
    here = os.path.dirname(path)
    m = _INCLUDE.match(line)
    if m:
        target = pre.expand_macros(m.group("rest"), dict(pre.defines)).strip()
        tag = None
        t = _INCLUDE_TAG.match(target)
        if t:
            target, tag = t.group(1).strip(), t.group(2).strip()
        if len(target) >= 2 and target[0] == target[-1] and target[0] in "\"'":
            target = target[1:-1]
        found = _resolve(pre, target, [*top_dirs, here], here)
        if found is None:
            return None
        row = 0
        if tag is not None:
            for idx, ln in enumerate(lines_of(found)):
                if "<tag>" in ln and tag_of(ln) == tag:
                    row = idx
                    break
        return _location(found, row)
    kv = _KEY_VALUE.match(line)
    if kv and "".join(kv.group("key").split()).lower() == "behaviors":
        value = pre.expand_macros(kv.group("value").split("//", 1)[0].strip(), {})
        found = _resolve(Preprocessor(), value, [here], here)
        return _location(found, 0) if found else None
    return None


def _resolve(pre: Preprocessor, target: str, tops: list[str], here: str) -> str | None:
    if not target or "$(" in target or "%(" in target:
        return None
    for top in tops:
        found = pre.resolve_include(target, top, here)
        if found is not None and os.path.isfile(found):
            return found
    return None


def _location(path: str, row: int) -> lsp.Location:
    pos = lsp.Position(row, 0)
    return lsp.Location(uri=path_to_uri(path), range=lsp.Range(pos, pos))
