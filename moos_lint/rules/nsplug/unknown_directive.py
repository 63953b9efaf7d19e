"""A `#` line that looks like an nsplug directive but is not one.

## What it does
Reports lines such as `#fidef X`, `# ifdef X`, `#Include file` or
`#elseifndef X`: nsplug recognises only `#ifdef`, `#ifndef`, `#elseifdef`,
`#else`, `#endif`, `#include` and `#define`, spelled exactly so.

Like every nsplug rule, it leaves alone a `.bhv` file in which no line, as
written, is shaped like a behavior file's (a `Behavior` header, `initialize`,
`set`, a brace or `key = value`): nsplug's own test inputs and notes on its
directives (MOOS-IvP's `app_nsplug/testcases/meta_vehicle.bhv`), which no
helm loads.

## Why is this bad?
nsplug copies an unknown directive to the output as a normal line. The
conditional it was meant to open or close is not there, so the wrong lines are
kept or dropped, and the `#` line itself reaches MOOS or the helm as a live
line. nsplug has no `#elseifndef` at all.

## Example
```moos
#ifdef VNAME abe
  START_POS = 0,0
#elseifndef VNAME
  START_POS = 10,10
#endif
```

## How to fix
Spell the directive as nsplug knows it; rewrite `#elseifndef` with `#else`
and a nested `#ifndef`.

## Options
None.
"""

from moos_lint.files.diagnostics import Severity
from moos_lint.rules.kit.declare import Kind, Scope, rule
from moos_lint.rules.nsplug._problems import problem_findings


@rule(
    code="P003",
    name="unknown-directive",
    severity=Severity.ERROR,
    scope=Scope.FILE,
    kinds=(Kind.MOOS, Kind.BHV),
)
def check(ctx):
    yield from problem_findings(ctx, "unknown-directive")
