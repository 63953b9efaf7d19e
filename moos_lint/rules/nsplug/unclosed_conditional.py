"""An `#ifdef` or `#ifndef` never closed by `#endif`.

## What it does
Reports an `#ifdef` / `#ifndef` still open at the end of its file.

Like every nsplug rule, it leaves alone a `.bhv` file in which no line, as
written, is shaped like a behavior file's (a `Behavior` header, `initialize`,
`set`, a brace or `key = value`): nsplug's own test inputs and notes on its
directives (MOOS-IvP's `app_nsplug/testcases/meta_vehicle.bhv`), which no
helm loads.

## Why is this bad?
nsplug does not report it: when the condition is false, every line after it
is silently dropped from the generated mission, and the launch goes ahead
with a truncated file.

## Example
```moos
#ifdef SIM
  Run = uSimMarineV22 @ NewConsole = false
// ... the #endif was deleted; the rest of the file vanishes when SIM is unset
```

## How to fix
Add the missing `#endif`.

## Options
None.
"""

from moos_lint.files.diagnostics import Severity
from moos_lint.rules.kit.declare import Kind, Scope, rule
from moos_lint.rules.nsplug._problems import problem_findings


@rule(
    code="P005",
    name="unclosed-conditional",
    severity=Severity.ERROR,
    scope=Scope.FILE,
    kinds=(Kind.MOOS, Kind.BHV),
)
def check(ctx):
    yield from problem_findings(ctx, "unclosed-conditional")
