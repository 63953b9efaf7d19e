"""A line that is neither a comment, a directive, a brace nor `key = value`.

## What it does
Reports a line in a `.moos` file that MOOS cannot read as anything: it has no
`key =` (a name before an `=`), is not a `//` comment, not a block brace and
not an nsplug directive.

## Why is this bad?
MOOS drops such a line without a word. It is usually a typo (`AppTick 4`,
a missing `=`) or a leftover note, and whatever the author meant it to set is
not set. The markers of a C block comment (`/*` alone on its line, `*/`)
around lines MOOS reads are named as such: MOOS has only `//` comments, so the
lines between the two markers, meant to be switched off, are read (a block
comment around lines MOOS drops anyway, or around top-of-file keys that
neither MOOS nor its apps read there, such as timer events kept below the
blocks, and a one-line `/* ... */` are harmless and not reported). A
merge-conflict marker (`<<<<<<< HEAD`, `>>>>>>> branch`) is named as such:
the file was committed in the middle of a merge, and MOOS reads the lines of
both sides, the later line of a key winning or both kept.

A ruler (a line of only `=`, `-`, `*`, `_`, `~`, `+` or `.`, such as
`=====`) and the title between the two rulers that open a file, or a plug
it includes (the banner that MOOS-IvP apps' `--example` output began with,
pasted into a file without its `//`), are decoration: MOOS drops them, and
nothing was meant to be set there, so they are not reported. A line between
two rulers further down is reported: it may be a key that lost its `=`.

A markup tag alone on its line, such as `<tdma>` and `</tdma>` around the
lines of a section, is not reported: MOOS drops it, and it is there for an app
that reads its block's lines itself (with the mission reader's `GoTo` and
`GetNextValidLine`), not a key that lost its `=`.

A `.moos` file that is a developer's notes rather than configuration (no
ProcessConfig block, no key MOOS knows at the top of the file, included by no
linted file, and more unreadable lines than `key = value` ones) is read by no
MOOS program, and its lines are not reported.

## Example
```moos
ProcessConfig = pLogger
{
  AppTick 4
}
```

Inside a block that an app reads with protobuf's text format (goby's MOOS
apps such as pAcommsHandler and iFrontSeat, or a block whose lines are mostly
`key: value`, or that holds only field lines, one of them a whole nested
message: `common { verbosity: DEBUG2 }`), the line must read as protobuf text
instead: `name: value`, `name { ... }` with balanced braces, `#` comments. The
app stops at start-up on such a line ("fatal configuration errors").

## How to fix
Add the `=`, or turn the line into a `//` comment. In a protobuf-text block,
write `name: value` or `name { ... }`.

## Options
None.
"""

import re

from moos_lint.files.diagnostics import Severity
from moos_lint.frontends.parsers.moos import block_comments, looks_commented, strip_comment
from moos_lint.frontends.parsers.nodes import MOOS_GLOBALS, conflict_marker
from moos_lint.rules.kit.declare import Scope, rule


@rule(code="R012", name="malformed-line", severity=Severity.WARNING, scope=Scope.FILE)
def check(ctx):
    if _notes(ctx):
        return  # notes kept under a `.moos` name: no MOOS program reads the file
    opens, closes = _block_comments(ctx.moos.lines)
    titles = _banner_titles(ctx.moos.lines) if ctx.moos.malformed else set()
    for line in ctx.moos.malformed:
        text = line.text.strip()
        if id(line) in titles or _ruler(strip_comment(text).strip()):
            continue  # decoration
        if id(line) in opens:
            msg = "MOOS has no `/* */` comments: it drops this line, but reads the lines "
            yield ctx.at_line(line, msg + "after it up to `*/` as usual")
            continue
        if looks_commented(text):
            continue  # not-a-comment's (when MOOS keeps the line) or the nsplug rules'
        if _MARKUP.fullmatch(strip_comment(text).strip()):
            continue  # a section marker for an app that reads its block's lines itself
        if id(line) in closes:
            if closes[id(line)]:
                msg = "MOOS has no `/* */` comments: this `*/` closes nothing, and the lines "
                yield ctx.at_line(line, msg + "before it were read as usual")
            continue  # (the end of a block comment around lines MOOS drops anyway: harmless)
        if conflict_marker(text):
            msg = "a merge-conflict marker: the file was committed mid-merge, and MOOS reads "
            yield ctx.at_line(line, msg + "the lines of both sides")
            continue
        yield ctx.at_line(line, "MOOS cannot read this line: it has no `key = value` form")
    for block in ctx.moos.blocks:
        for line, start, end, why in block.text_errors:
            yield ctx.report(
                line.span(start, end),
                f"{block.name} reads this block as protobuf text: {why}",
                line=line,
            )


#: a markup tag alone on its line (``<tdma>``, ``</tdma>``): no typo of a ``key = value``
_MARKUP = re.compile(r"</?[A-Za-z_][\w.:-]*>")

#: what a ruler line is made of (``=====``, ``-----``, ``*****``)
_RULER = frozenset("=-*_~+. \t")


def _ruler(text: str) -> bool:
    return len(text) >= 3 and set(text) <= _RULER


def _banner_titles(lines) -> set[int]:
    """The ids of the titles of the banners that open the file and each file it includes:
    a line without an ``=`` between two rulers, the first of them the source file's first
    line with text (a line between two rulers further down may be a key that lost its
    ``=``: it is reported)."""
    by_file: dict[tuple, list] = {}
    for line in lines:
        by_file.setdefault((line.path, line.chain), []).append(line)
    found: set[int] = set()
    for own in by_file.values():
        for i, line in enumerate(own):
            if strip_comment(line.text).strip():
                texts = [strip_comment(x.text).strip() for x in own[i : i + 3]]
                banner = len(texts) == 3 and _ruler(texts[0]) and _ruler(texts[2])
                if banner and texts[1] and "=" not in texts[1]:
                    found.add(id(own[i + 1]))
                break
    return found


def _block_comments(lines) -> tuple[set[int], dict[int, bool]]:
    """The ids of the lines that open (``/*`` with no ``*/`` after it) a C block comment
    around at least one line MOOS reads, and of the lines that close one (``*/``), with
    whether it is around such a line. MOOS reads a ``key = value`` inside a block and a
    brace; at the top of the file, only the keys MOOS and its apps read there (an
    ``event = ...`` between the markers, below the blocks, is dropped anyway)."""
    opens: set[int] = set()
    closes: dict[int, bool] = {}
    known = {k.lower() for k in MOOS_GLOBALS}
    for start, end, depth in block_comments(lines):
        reads = False
        for line in lines[start + 1 : end]:
            text = strip_comment(line.text).strip()
            if text in ("{", "}"):
                reads = True
            elif "=" in text:
                key = text.split("=", 1)[0].strip().lower()
                reads = depth > 0 or key in known
            depth += text == "{"
            depth -= text == "}"
            if reads:
                break
        if reads:
            opens.add(id(lines[start]))
        closes[id(lines[end])] = reads
    return opens, closes


def _notes(ctx) -> bool:
    """Whether the file is a developer's notes with a ``.moos`` name rather than MOOS
    configuration: no ProcessConfig block, no key MOOS knows at the top, no linted file
    includes it, and more of its lines are unreadable than ``key = value``."""
    moos = ctx.moos
    if moos.blocks or moos.is_mission or ctx.unit.path in ctx.run.included_elsewhere:
        return False
    known = {k.lower() for k in MOOS_GLOBALS}
    if any(p.key.strip().lower() in known for p in moos.globals):
        return False
    return len(moos.malformed) > len(moos.globals)
