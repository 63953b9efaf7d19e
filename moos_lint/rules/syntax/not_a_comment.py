"""A line that looks like a comment but is not one to MOOS.

## What it does
Reports a line starting with `#` that is not an nsplug directive, and a line
starting with a single `/`, when MOOS reads it: when it holds `=` (or a `[`,
`]` or brace, which MOOS also keeps). In a `.moos` file only `//` starts a
comment.

## Why is this bad?
MOOS reads `#Run = pFoo` as a live line whose key is `#Run`: the Run line is
not a Run line any more, so the process silently never launches, and
`#LatOrigin = 43.8` silently drops the origin. Inside a block the line is
handed to the app, and an AppCasting app reports `#share = ...` as an
unhandled configuration line. A line without `=` (a `/--------` banner, the
lines of a `/* ... */` comment) is dropped by MOOS unread, as a comment would
be, so it is not reported (`ProcessConfigReader::GetConfiguration` keeps only
`key=value` lines and lines with `[` or `]`); so is `#//Run = pFoo`, since MOOS
first cuts a line at its `//` (`MOOSFileReader::GetNextValidLine`), leaving `#`.
Inside a block that an app reads as protobuf text (goby's pAcommsHandler), `#`
does start a comment, and such lines are not reported.

## Example
```moos
ProcessConfig = ANTLER
{
  Run = MOOSDB @ NewConsole = false
  #Run = pLogger @ NewConsole = false
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
    for line in ctx.moos.lines:
        text = line.text
        if not looks_commented(text) or not _kept(text) or (line.path, line.lineno) in flagged:
            continue
        if id(line) in protobuf:
            continue  # protobuf text: `#` starts a comment there
        if text.lstrip().startswith("#"):
            yield ctx.at_line(
                line,
                "`#` does not start a comment in a .moos file: MOOS reads this line (use `//`)",
            )
        elif text.lstrip().startswith("/*"):
            yield ctx.at_line(
                line,
                "`/*` does not start a comment in a .moos file: MOOS reads this line "
                "(use `//` on each line)",
            )
        else:
            yield ctx.at_line(
                line,
                "a single `/` does not start a comment: MOOS reads this line (use `//`)",
            )


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


def _kept(text: str) -> bool:
    """Whether MOOS keeps the line: a line without ``=``, ``[``, ``]`` or a brace before
    its ``//`` is dropped unread, like a comment (``#//Run = pFoo``: MOOS cuts a line at
    ``//``, unless a quote comes first, MOOSFileReader::GetNextValidLine)."""
    cut = text.find("//")
    if cut >= 0 and '"' not in text[:cut]:
        text = text[:cut]
    return any(c in text for c in "=[]{}")
