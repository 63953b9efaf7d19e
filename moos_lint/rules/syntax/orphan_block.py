"""A `{ ... }` block with no `ProcessConfig =` header.

## What it does
Reports a block opened by `{` that no `ProcessConfig = NAME` line names. This
typically happens when the header was commented out and the block left behind.

## Why is this bad?
No app ever reads an orphan block. Worse, MOOS's global lookup scans the whole
file, so a global-looking key inside the orphan block (`MOOSTimeWarp = 10`)
still shadows the real one.

## Example
```moos
//ProcessConfig = pLogger
{
  AsyncLog = true
}
```

## How to fix
Restore the header, or delete the whole block.

## Options
None.
"""

from moos_lint.files.diagnostics import Severity
from moos_lint.rules.kit.declare import Scope, rule


@rule(code="R004", name="orphan-block", severity=Severity.WARNING, scope=Scope.FILE)
def check(ctx):
    for block in ctx.moos.orphan_blocks:
        yield ctx.report(
            block.open.span(),
            "block without a `ProcessConfig = NAME` header: no app reads it",
            line=block.open,
        )
