"""An nsplug directive missing its argument.

## What it does
Reports `#define`, `#include`, `#ifdef` or `#ifndef` with nothing after
it.

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
