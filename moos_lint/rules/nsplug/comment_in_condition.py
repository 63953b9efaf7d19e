"""A `//` comment on an `#ifdef` line.

## What it does
Reports `#ifdef` and `#elseifdef` lines with a `//` comment after the
condition.

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
