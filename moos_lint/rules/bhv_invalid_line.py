"""A line in a behavior file that the helm rejects.

## What it does
Reports a line of a `.bhv` file that the IvP helm's behavior-file reader does
not accept: a top-level line that is not `initialize`, `Behavior =`, `set`,
a brace or a comment; a Behavior-block line without `=`; an `initialize`
followed by a tab or with a malformed `VAR=VALUE` pair; a `#` line (not a
comment in a behavior file).

## Why is this bad?
The helm reports `Problem with line N in the BehaviorSet file` and the *whole*
behavior set fails to load: the vehicle has no behaviors at all.

## Example
```bhv
# the survey behaviors
initialize DEPLOY = false
Behavior = BHV_Waypoint
{
  name = survey
  speed 2.0
}
```

## How to fix
Use `//` for comments, and `key = value` for every parameter line.

## Options
None.
"""

from moos_lint.declare import Kind, Scope, rule
from moos_lint.diagnostics import Severity


@rule(
    code="B001",
    name="bhv-invalid-line",
    severity=Severity.ERROR,
    scope=Scope.FILE,
    kinds=(Kind.BHV,),
)
def check(ctx):
    flagged = {(p.span.path, p.span.line) for p in ctx.expansion.problems}
    for line, reason in ctx.bhv.invalid:
        if (line.path, line.lineno) in flagged:
            continue  # an nsplug problem on this line is reported already
        yield ctx.at_line(line, f"{reason}: the helm fails to load the whole behavior file")
