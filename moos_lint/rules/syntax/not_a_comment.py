"""A line that looks like a comment but that MOOS hands to an app.

## What it does
Reports a line starting with `#` that is not an nsplug directive, and a line
starting with a single `/` or with `/*`, inside a process's configuration
block, when MOOS reads it: when it holds `=` (or a `[` or `]`, which MOOS also
keeps). In a `.moos` file only `//` starts a comment. A line holding a brace
is reported wherever it is: `#}` does not close a block.

## Why is this bad?
MOOS hands `#share = [NAV_X] -> ...` to the app as a live line whose key is
`#share`: an AppCasting app reports it as an unhandled configuration line, an
app that refuses unknown keys fails to start, and one that reads keys by
their start may take it for another. `#}` or `/}` is not a closing brace: the
block runs on into the next one, whose header becomes a parameter of this one.

Deliberately not reported: a `#` or `/` line at the top of the file or inside
the ANTLER block. MOOS reads it, but nothing ever asks for its key (`#Run` is
not `Run`, `#LatOrigin` not `LatOrigin`: pAntler launches only Run lines, and
an app looks a top-level key up by its whole name), so the line does what a
comment would: `#Run = pLogger` launches nothing, as its writer meant. A line
without `=` (a `/--------` banner, the lines of a `/* ... */` comment) is
dropped by MOOS unread, as a comment would be (`ProcessConfigReader::GetConfiguration`
keeps only `key=value` lines and lines with `[` or `]`); so is `#//x = 1`,
since MOOS first cuts a line at its `//` (`MOOSFileReader::GetNextValidLine`),
leaving `#`. Inside a block that an app reads as protobuf text (goby's
pAcommsHandler), `#` does start a comment, and such lines are not reported.

## Example
```moos
ProcessConfig = pShare
{
  input = route = localhost:9301
  #output = src_name=NAV_X, route=localhost:9300
}
```

## How to fix
Comment lines out with `//`.

## Options
None.
"""

from moos_lint.files.diagnostics import Severity
from moos_lint.frontends.parsers.moos import looks_commented
from moos_lint.rules.kit.declare import Scope, rule


@rule(code="R007", name="not-a-comment", severity=Severity.WARNING, scope=Scope.FILE)
def check(ctx):
    flagged = {
        (p.span.path, p.span.line)
        for p in ctx.expansion.problems
        if p.kind in ("unknown-directive", "malformed-directive")
    }
    protobuf = _text_format_lines(ctx.moos)
    read: dict[int, str] | None = None
    for line in ctx.moos.lines:
        text = line.text
        if not looks_commented(text) or not _kept(text) or (line.path, line.lineno) in flagged:
            continue
        if id(line) in protobuf:
            continue  # protobuf text: `#` starts a comment there
        if read is None:
            read = _read_by_apps(ctx.moos)
        app = read.get(id(line))
        brace = any(c in _before_comment(text) for c in "{}")
        if app is None and not brace:
            continue  # at the top or in the ANTLER block: no one asks for its key
        stripped = text.lstrip()
        if stripped.startswith("/*"):
            what, fix = "`/*` does not start a comment in a .moos file", "use `//` on each line"
        elif stripped.startswith("#"):
            what, fix = "`#` does not start a comment in a .moos file", "use `//`"
        else:
            what, fix = "a single `/` does not start a comment", "use `//`"
        if brace:
            does = "MOOS reads its brace as text, not as one that opens or closes a block"
        else:
            does = f"MOOS hands this line to `{app}` as a parameter"
        yield ctx.at_line(line, f"{what}: {does} ({fix})")


def _text_format_lines(moos) -> set[int]:
    """The ids of the lines inside the blocks an app reads as protobuf text (goby's
    pAcommsHandler), where ``#`` does start a comment."""
    out: set[int] = set()
    spans = [(b.open, b.close) for b in moos.blocks if b.text_format and b.open and b.close]
    if not spans:
        return out
    index = {id(line): i for i, line in enumerate(moos.lines)}
    for first, last in spans:
        start, end = index.get(id(first)), index.get(id(last))
        if start is not None and end is not None:
            out.update(id(line) for line in moos.lines[start : end + 1])
    return out


def _read_by_apps(moos) -> dict[int, str]:
    """The ids of the lines inside the blocks MOOS hands to an app, with the block's name:
    a block under its header (``{`` on the line after it), ANTLER's aside (pAntler reads
    only its Run lines and settings by name); an unclosed block runs to the end of the
    file."""
    out: dict[int, str] = {}
    index = {id(line): i for i, line in enumerate(moos.lines)}
    for b in moos.blocks:
        if b.header is None or b.open is None or b.brace_on_header or b.lname == "antler":
            continue
        start = index.get(id(b.open))
        end = index.get(id(b.close)) if b.close is not None else len(moos.lines) - 1
        if start is not None and end is not None:
            out.update((id(line), b.name) for line in moos.lines[start + 1 : end])
    return out


def _before_comment(text: str) -> str:
    """The line as MOOS keeps it: up to its ``//``, unless a quote comes first."""
    cut = text.find("//")
    return text[:cut] if cut >= 0 and '"' not in text[:cut] else text


def _kept(text: str) -> bool:
    """Whether MOOS keeps the line: a line without ``=``, ``[``, ``]`` or a brace before
    its ``//`` is dropped unread, like a comment (``#//Run = pFoo``: MOOS cuts a line at
    ``//``, unless a quote comes first, MOOSFileReader::GetNextValidLine)."""
    return any(c in _before_comment(text) for c in "=[]{}")
