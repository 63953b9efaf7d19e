"""`ProcessConfig = NAME {` with the brace on the header line.

## What it does
Reports a `ProcessConfig` header whose opening `{` is on the same line as the
header.

## Why is this bad?
MOOS looks a block up by comparing whole lines: it searches for a line that
reads exactly `ProcessConfig=NAME` once spaces are removed. A header line
that also holds the `{` never matches, so the app never finds its block and
runs on its defaults, without a word of warning.

## Example
```moos
ProcessConfig = pHelmIvP {
  behaviors = alpha.bhv
}
```

## How to fix
Put the brace on its own line:
```moos
ProcessConfig = pHelmIvP
{
  behaviors = alpha.bhv
}
```

## Options
None.
"""

from moos_lint.files.diagnostics import Severity
from moos_lint.rules.kit.declare import Scope, rule


@rule(code="R003", name="brace-on-header", severity=Severity.ERROR, scope=Scope.FILE)
def check(ctx):
    for block in ctx.moos.blocks:
        if block.brace_on_header:
            yield ctx.report(
                block.header.span(),
                f"`{{` on the header line: MOOS never finds the block `{block.name}` "
                "and the app runs unconfigured",
                line=block.header,
            )
