"""A Behavior block whose closing `}` is missing.

## What it does
Reports a `Behavior = BHV_Type` block not closed by `}` before the next
`Behavior` line or the end of the file.

## Why is this bad?
The helm reads the next lines as parameters of this behavior: the next
`Behavior = ...` line is a bad parameter, and the behavior file fails to load.

## Example
```bhv
Behavior = BHV_Loiter
{
  name = loiter

Behavior = BHV_Waypoint
{
  name = transit
}
```

## How to fix
Add the missing `}`.

## Options
None.
"""

from moos_lint.files.diagnostics import Severity
from moos_lint.rules.kit.declare import Kind, Scope, rule


@rule(
    code="B002",
    name="bhv-unclosed-block",
    severity=Severity.ERROR,
    scope=Scope.FILE,
    kinds=(Kind.BHV,),
)
def check(ctx):
    for line in ctx.bhv.unclosed:
        yield ctx.at_line(line, "Behavior block is never closed by `}`")
