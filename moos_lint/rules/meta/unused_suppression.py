"""A `moos-lint:` suppression comment that suppresses nothing.

## What it does
Reports a rule code or name in a `// moos-lint: ignore[...]`,
`disable[...]` or `file-ignore[...]` comment that matched no finding, and
selectors that name no rule at all.

## Why is this bad?
Stale suppressions hide future problems: the line they once excused has been
fixed or moved, but a new problem of the same kind there would be silenced.
An unknown code in a suppression is usually a typo that suppresses nothing.

## Example
```moos
ProcessConfig = pLogger   // moos-lint: ignore[brace-on-header]
{
}
```

## How to fix
Delete the suppression (or just the codes that suppress nothing).

`moos-lint check --fix` does it: a comment whose every selector is unused is
removed (the whole line when the comment is alone on it), otherwise only the
unused selectors are taken out of its list. For an unused `disable[X]`, `X` is
also taken out of the matching `enable[...]` comment. Selectors of rules that
did not run (for example outside `--select`) are never touched.

## Options
None.
"""

from __future__ import annotations

from moos_lint.files.diagnostics import Edit, Fix, Severity, Span
from moos_lint.rules.kit.declare import Kind, Scope, rule
from moos_lint.rules.kit.selectors import selects
from moos_lint.rules.kit.suppressions import COMMENT_RE


@rule(
    code="L001",
    name="unused-suppression",
    severity=Severity.WARNING,
    scope=Scope.PROJECT,
    kinds=(Kind.MOOS, Kind.BHV),
    fixable=True,
)
def check(ctx):
    # Project rules run after every other finding was matched against suppressions.
    run = ctx.run
    for path, sups in sorted(run.suppressions.items()):
        in_mission = path in run.mission_files
        found = []  # (suppression, selector, message)
        for sup in sups:
            for sel in sup.selectors:
                if sel in sup.used:
                    continue
                if not run.names_a_rule(sel):
                    msg = f"`{sel}` names no moos-lint rule"
                else:
                    ran = [
                        r
                        for r in run.rules
                        if selects(sel, r.code, r.name)
                        and r.scope is not Scope.PROJECT
                        and (in_mission or r.scope is not Scope.MISSION)
                    ]
                    if not ran:
                        continue  # the rule did not run on this file: we cannot tell
                    msg = f"unused suppression: `{sel}` suppressed nothing here"
                found.append((sup, sel, msg))
        fixes = _fixes(path, run.sources.get(path), found)
        for sup, _sel, msg in found:
            yield ctx.report(sup.span, msg, fix=fixes.get((sup.line, sup.col)))


def _fixes(path: str, src, found) -> dict[tuple[int, int], Fix]:
    """One fix per suppression comment, removing all its unused selectors at once."""
    if src is None:
        return {}
    drop: dict[tuple[int, int], set[str]] = {}
    for sup, sel, _msg in found:
        drop.setdefault((sup.line, sup.col), set()).add(sel)
    # A `disable[X]` whose X goes away takes X out of the `enable[...]` that closes it too.
    partners: dict[tuple[int, int], set[str]] = {}
    for sup, sel, _msg in found:
        if sup.verb != "disable" or sup.last == sup.line:
            continue
        for m in COMMENT_RE.finditer(src.line(sup.last)):
            names = [s.strip().lower() for s in m.group("codes").split(",")]
            if m.group("verb") == "enable" and sel.lower() in names:
                partners.setdefault((sup.last, m.start() + 1), set()).add(sel.lower())
                break
    out: dict[tuple[int, int], Fix] = {}
    for (line, col), sels in drop.items():
        edits = []
        edit = _edit(path, src, line, col, sels)
        if edit is None:
            continue
        edits.append(edit)
        for sup, _sel, _msg in found:
            if (sup.line, sup.col) != (line, col) or sup.verb != "disable":
                continue
            for (pline, pcol), psels in partners.items():
                if pline == sup.last:
                    pedit = _edit(path, src, pline, pcol, psels)
                    if pedit is not None and pedit not in edits:
                        edits.append(pedit)
        whole = edit.text == ""  # nothing kept: the comment goes
        message = "Remove the unused suppression" if whole else "Remove the unused selectors"
        out[(line, col)] = Fix(message, tuple(edits))
    return out


def _match(src, line: int, col: int):
    for m in COMMENT_RE.finditer(src.line(line)):
        if m.start() + 1 == col:
            return m
    return None


def _edit(path: str, src, line: int, col: int, sels: set[str]) -> Edit | None:
    """The edit that takes ``sels`` out of the comment at (line, col)."""
    m = _match(src, line, col)
    if m is None:
        return None
    text = src.line(line)
    low = {s.lower() for s in sels}
    kept = [s.strip() for s in m.group("codes").split(",") if s.strip()]
    kept = [s for s in kept if s.lower() not in low]
    if kept:
        start, end = m.start("codes"), m.end("codes")
        return Edit(Span(path, line, start + 1, line, end + 1), ", ".join(kept))
    nxt = COMMENT_RE.search(text, m.end())
    if nxt is not None:  # another moos-lint comment follows: stop there
        return Edit(Span(path, line, m.start() + 1, line, nxt.start() + 1), "")
    start = len(text[: m.start()].rstrip())
    if start == 0:  # the comment is the whole line: remove the line
        return Edit(Span(path, line, 1, line + 1, 1), "")
    return Edit(Span(path, line, start + 1, line, len(text) + 1), "")
