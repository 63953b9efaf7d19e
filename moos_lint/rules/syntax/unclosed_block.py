"""A ProcessConfig block whose closing `}` is missing.

## What it does
Reports a block that is not closed by a line starting with `}` before the
next block header or the end of the file. A `{` with no header of its own is
no app's block and MOOS reads nothing into it: orphan-block reports that one.
A line that starts with `{` and goes on (`{ configuration block`) opens a
block only right after a header; elsewhere it is a line MOOS drops
(malformed-line).

## Why is this bad?
MOOS reads on past the end of the intended block: the next
`ProcessConfig = Y` line becomes a parameter of this block, and the next
block's parameters are read by this app. The next app may never find its own
block. MOOS prints at most an easily missed `missing "}"` message.

## Example
```moos
ProcessConfig = pLogger
{
  AsyncLog = true

ProcessConfig = pHelmIvP
{
  behaviors = alpha.bhv
}
```

## How to fix
Add the missing `}` at the end of the block.

## Options
None.
"""

from moos_lint.files.diagnostics import Severity
from moos_lint.rules.kit.declare import Scope, rule


@rule(code="R005", name="unclosed-block", severity=Severity.ERROR, scope=Scope.FILE)
def check(ctx):
    for block in ctx.moos.unclosed_blocks:
        line = block.header or block.open
        what = f"block `{block.name}`" if block.name else "block"
        yield ctx.report(
            line.span(),
            f"{what} is never closed by `}}`: MOOS reads the following lines into it",
            line=line,
        )
