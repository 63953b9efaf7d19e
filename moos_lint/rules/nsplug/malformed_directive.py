"""An nsplug directive missing its argument.

## What it does
Reports `#define`, `#include`, `#ifdef` or `#ifndef` with nothing after
it.

Like every nsplug rule, it leaves alone a `.bhv` file in which no line, as
written, is shaped like a behavior file's (a `Behavior` header, `initialize`,
`set`, a brace or `key = value`): nsplug's own test inputs and notes on its
directives (MOOS-IvP's `app_nsplug/testcases/meta_vehicle.bhv`), which no
helm loads.

## Why is this bad?
nsplug stops with an error (`A #define line must have an argument`) or
evaluates an empty condition.

## Example
```moos
#define
```

## How to fix
Give the directive its argument, or delete the line.

## Options
None.
"""

from moos_lint.files.diagnostics import Severity
from moos_lint.rules.kit.declare import Kind, Scope, rule
from moos_lint.rules.nsplug._problems import problem_findings


@rule(
    code="P009",
    name="malformed-directive",
    severity=Severity.ERROR,
    scope=Scope.FILE,
    kinds=(Kind.MOOS, Kind.BHV),
)
def check(ctx):
    yield from problem_findings(ctx, "malformed-directive")
