"""An `#include FILE <tag>` of a tag the file does not have.

## What it does
Reports `#include plugs.moos <name>` when `plugs.moos` has no
`<tag><name>` section. Not when the file that holds the `#include` is the one
nsplug expands and has a `<tag><name>` section itself (the block was moved into
the mission, the include left behind): nsplug writes every section of the file
it expands, whatever its mode (Expander.cpp, `expandFile` with no tag), so the
block is there.

Like every nsplug rule, it leaves alone a `.bhv` file in which no line, as
written, is shaped like a behavior file's (a `Behavior` header, `initialize`,
`set`, a brace or `key = value`): nsplug's own test inputs and notes on its
directives (MOOS-IvP's `app_nsplug/testcases/meta_vehicle.bhv`), which no
helm loads.

## Why is this bad?
nsplug includes nothing and says nothing: the block the author meant to
include is silently missing from the mission.

## Example
```moos
#include plugs.moos <pShare>     // plugs.moos has <tag><pshare>
```

## How to fix
Use the tag as spelled in the included file (tags are case-sensitive).

## Options
None.
"""

from moos_lint.files.diagnostics import Severity
from moos_lint.rules.kit.declare import Kind, Scope, rule
from moos_lint.rules.nsplug._problems import problem_findings


@rule(
    code="P007",
    name="unknown-include-tag",
    severity=Severity.ERROR,
    scope=Scope.FILE,
    kinds=(Kind.MOOS, Kind.BHV),
)
def check(ctx):
    yield from problem_findings(ctx, "unknown-include-tag")
