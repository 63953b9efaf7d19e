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
`key=value` lines and lines with `[` or `]`).

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
    for line in ctx.moos.lines:
        text = line.text
        if not looks_commented(text) or not _kept(text) or (line.path, line.lineno) in flagged:
            continue
        if text.lstrip().startswith("#"):
            yield ctx.at_line(
                line,
                "`#` does not start a comment in a .moos file: MOOS reads this line (use `//`)",
            )
        else:
            yield ctx.at_line(
                line,
                "a single `/` does not start a comment: MOOS reads this line (use `//`)",
            )


def _kept(text: str) -> bool:
    """Whether MOOS keeps the line: a line without ``=``, ``[``, ``]`` or a brace is
    dropped unread, like a comment."""
    return any(c in text for c in "=[]{}")
