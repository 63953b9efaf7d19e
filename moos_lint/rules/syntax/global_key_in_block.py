"""A global mission key (ServerPort, LatOrigin, ...) inside a ProcessConfig block.

## What it does
Reports `ServerHost`, `ServerPort`, `Community`, `MOOSTimeWarp`, `LatOrigin`
or `LongOrigin` set inside a block.

## Why is this bad?
There is no syntactic global section in a `.moos` file: every app reads these
keys with a lookup that returns the *first* matching line anywhere in the
file, blocks included. A `MOOSTimeWarp = 7` inside one app's block therefore
sets the time warp of every app and of the MOOSDB, shadowing the real line
at the top of the file.

## Example
```moos
ProcessConfig = uSimMarineV22
{
  LatOrigin = 42.358
}
```

## How to fix
Set these keys once, outside every block. To give one app a different time
warp use its `moos_time_warp` parameter.

## Options
None.
"""

from moos_lint.files.diagnostics import Severity
from moos_lint.frontends.parsers.nodes import GLOBAL_KEYS
from moos_lint.rules.kit.declare import Scope, rule


@rule(code="R009", name="global-key-in-block", severity=Severity.ERROR, scope=Scope.FILE)
def check(ctx):
    for block in ctx.moos.blocks:
        for p in block.params:
            if p.lkey in GLOBAL_KEYS:
                yield ctx.report(
                    p.key_span,
                    f"`{p.key}` inside block `{block.name}` is read by every app in the "
                    "mission: it shadows the global setting",
                    line=p.line,
                )
