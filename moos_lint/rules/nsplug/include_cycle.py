"""An `#include` loop (a file that includes itself, directly or not).

## What it does
Reports an `#include` that would include a file already being included
(A includes B includes A), include chains nested absurdly deep, and a file
whose includes and macros expand without bound: more than 400,000 lines (a
file included many times at many levels), or macros that grow a line past a
mebibyte or the file past 16 MiB. moos-lint stops reading such a file at the
line that ran over.

Like every nsplug rule, it leaves alone a `.bhv` file in which no line, as
written, is shaped like a behavior file's (a `Behavior` header, `initialize`,
`set`, a brace or `key = value`): nsplug's own test inputs and notes on its
directives (MOOS-IvP's `app_nsplug/testcases/meta_vehicle.bhv`), which no
helm loads.

## Why is this bad?
nsplug does not catch include loops: it recurses until it crashes with a
segmentation fault, and no mission file is written. An include tree that
multiplies at each level runs nsplug out of time or memory the same way.

## Example
```moos
// a.plug
#include b.plug
// b.plug
#include a.plug
```

## How to fix
Remove the include that closes the loop.

## Options
None.
"""

from moos_lint.files.diagnostics import Severity
from moos_lint.rules.kit.declare import Kind, Scope, rule
from moos_lint.rules.nsplug._problems import problem_findings


@rule(
    code="P002",
    name="include-cycle",
    severity=Severity.ERROR,
    scope=Scope.FILE,
    kinds=(Kind.MOOS, Kind.BHV),
)
def check(ctx):
    yield from problem_findings(ctx, "include-cycle")
