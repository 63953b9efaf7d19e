"""A `//` comment on an `#ifdef` line.

## What it does
Reports `#ifdef` and `#elseifdef` lines with a `//` comment after the
condition.

Like every nsplug rule, it leaves alone a `.bhv` file in which no line, as
written, is shaped like a behavior file's (a `Behavior` header, `initialize`,
`set`, a brace or `key = value`): nsplug's own test inputs and notes on its
directives (MOOS-IvP's `app_nsplug/testcases/meta_vehicle.bhv`), which no
helm loads.

## Why is this bad?
nsplug does not strip comments from directive lines: `#ifdef VNAME abe // shore`
compares VNAME with `abe // shore`, which is never true.

## Example
```moos
#ifdef VNAME abe   // the first vehicle
```

## How to fix
Put the comment on its own line above the directive.

## Options
None.
"""

from moos_lint.files.diagnostics import Severity
from moos_lint.rules.kit.declare import Kind, Scope, rule
from moos_lint.rules.nsplug._problems import problem_findings


@rule(
    code="P006",
    name="comment-in-condition",
    severity=Severity.WARNING,
    scope=Scope.FILE,
    kinds=(Kind.MOOS, Kind.BHV),
)
def check(ctx):
    yield from problem_findings(ctx, "comment-in-condition")
