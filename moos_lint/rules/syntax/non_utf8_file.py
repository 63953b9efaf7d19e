"""A file that is not valid UTF-8 (read as latin-1).

## What it does
Notes a file whose bytes are not valid UTF-8. moos-lint then reads it as
latin-1, so every byte maps to a character and linting goes on.

## Why is this bad?
MOOS itself does not care about encodings, but editors, diff tools and the
web views of code hosts do: a mission file saved in latin-1 shows garbled
characters for every accented letter in its comments, and a value holding
such a character reaches other apps as bytes they may not expect.

## Example
A comment `// Forêt lake` saved by an editor set to latin-1.

## How to fix
Save the file as UTF-8 (most editors offer "Save with encoding").

## Options
None.
"""

from moos_lint.files.diagnostics import Severity, Span
from moos_lint.rules.kit.declare import Kind, Scope, rule


@rule(
    code="R002",
    name="non-utf8-file",
    severity=Severity.INFO,
    scope=Scope.FILE,
    kinds=(Kind.MOOS, Kind.BHV),
)
def check(ctx):
    src = ctx.expansion.sources.get(ctx.path)
    if src is not None and src.encoding != "utf-8":
        for i, text in enumerate(src.lines, 1):
            if any(ord(ch) > 127 for ch in text):
                col = next(j for j, ch in enumerate(text) if ord(ch) > 127) + 1
                yield ctx.report(
                    Span(ctx.path, i, col, i, col + 1),
                    "file is not valid UTF-8; read as latin-1 (first non-ASCII byte here)",
                )
                return
