"""An Antler `Run = X ~ Y` line without `@`.

## What it does
Reports a `Run` line in the ANTLER block that gives an alias with `~` but
has no `@`.

## Why is this bad?
pAntler takes everything before the first `@` as the program to launch.
Without an `@`, the alias becomes part of the program name (`pShare~ShareA`),
no such program exists, and the process never starts.

## Example
```moos
Run = pShare ~ ShareA
```

## How to fix
```moos
Run = pShare @ NewConsole = false ~ ShareA
```

## Options
None.
"""

from moos_lint.files.diagnostics import Severity
from moos_lint.rules.kit.declare import Scope, rule


@rule(code="R010", name="run-alias-without-at", severity=Severity.ERROR, scope=Scope.FILE)
def check(ctx):
    for run in ctx.moos.runs:
        if not run.has_at and "~" in run.param.value:
            yield ctx.report(
                run.param.value_span,
                f"no `@` on this Run line: pAntler would launch a program named "
                f"`{''.join(run.param.value.split())}`",
                line=run.param.line,
            )
