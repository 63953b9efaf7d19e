"""An `#ifdef` that mixes `||` and `&&`.

## What it does
Reports an `#ifdef` / `#elseifdef` condition using both `||` and `&&`.

Like every nsplug rule, it leaves alone a `.bhv` file in which no line, as
written, is shaped like a behavior file's (a `Behavior` header, `initialize`,
`set`, a brace or `key = value`): nsplug's own test inputs and notes on its
directives (MOOS-IvP's `app_nsplug/testcases/meta_vehicle.bhv`), which no
helm loads.

## Why is this bad?
nsplug does not support mixed conditions: it prints a warning and evaluates
the condition as false (with `--strict` it exits).

## Example
```moos
#ifdef VNAME abe || VNAME ben && SIM
```

## How to fix
Nest two conditionals instead.

## Options
None.
"""

from moos_lint.files.diagnostics import Severity
from moos_lint.rules.kit.declare import Kind, Scope, rule
from moos_lint.rules.nsplug._problems import problem_findings


@rule(
    code="P008",
    name="mixed-and-or",
    severity=Severity.ERROR,
    scope=Scope.FILE,
    kinds=(Kind.MOOS, Kind.BHV),
)
def check(ctx):
    yield from problem_findings(ctx, "mixed-and-or")
