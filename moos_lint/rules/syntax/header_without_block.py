"""A `ProcessConfig = NAME` header not followed by a `{` line.

## What it does
Reports a block header whose next line (comments and blank lines aside) does
not start with `{`.

## Why is this bad?
MOOS expects the line after the header to open the block. When it does not,
the app finds no configuration and runs on its defaults.

## Example
```moos
ProcessConfig = pLogger
  AsyncLog = true
```

## How to fix
Add the `{ ... }` block after the header, or delete the header.

## Options
None.
"""

from moos_lint.files.diagnostics import Severity
from moos_lint.rules.kit.declare import Scope, rule


@rule(code="R013", name="header-without-block", severity=Severity.ERROR, scope=Scope.FILE)
def check(ctx):
    for line in ctx.moos.headers_without_block:
        yield ctx.at_line(line, "the line after this header does not open a block with `{`")
