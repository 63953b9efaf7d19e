"""A `}` that closes no block.

## What it does
Reports a line starting with `}` outside any block.

## Why is this bad?
A stray `}` usually means a block was closed twice or its header and `{` were
deleted: the lines above it are not where the author thinks. MOOS ignores the
line silently.

## Example
```moos
ProcessConfig = pLogger
{
  AsyncLog = true
}
}
```

## How to fix
Delete the extra `}`, or restore the block it belonged to.

## Options
None.
"""

from moos_lint.files.diagnostics import Severity
from moos_lint.rules.kit.declare import Scope, rule


@rule(code="R006", name="stray-closing-brace", severity=Severity.WARNING, scope=Scope.FILE)
def check(ctx):
    for line in ctx.moos.stray_closers:
        yield ctx.at_line(line, "`}` without an open block")
