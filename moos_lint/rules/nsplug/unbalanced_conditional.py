"""A dangling `#else`, `#elseifdef` or `#endif`.

## What it does
Reports `#else`, `#elseifdef` or `#endif` with no open `#ifdef`, a second
`#else`, a branch after `#else`, and `#elseifdef` after `#ifndef` (which
nsplug rejects as dangling).

Like every nsplug rule, it leaves alone a `.bhv` file in which no line, as
written, is shaped like a behavior file's (a `Behavior` header, `initialize`,
`set`, a brace or `key = value`): nsplug's own test inputs and notes on its
directives (MOOS-IvP's `app_nsplug/testcases/meta_vehicle.bhv`), which no
helm loads.

## Why is this bad?
nsplug stops with an error and writes no file.

## Example
```moos
#ifdef VNAME abe
  Run = pA @ NewConsole = false
#endif
#endif
```

## How to fix
Remove the extra directive, or add the missing `#ifdef`.

## Options
None.
"""

from moos_lint.files.diagnostics import Severity
from moos_lint.rules.kit.declare import Kind, Scope, rule
from moos_lint.rules.nsplug._problems import problem_findings


@rule(
    code="P004",
    name="unbalanced-conditional",
    severity=Severity.ERROR,
    scope=Scope.FILE,
    kinds=(Kind.MOOS, Kind.BHV),
)
def check(ctx):
    yield from problem_findings(ctx, "unbalanced-conditional")
