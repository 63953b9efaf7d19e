"""A global mission key (ServerPort, LatOrigin, ...) inside a ProcessConfig block.

## What it does
Reports `ServerHost`, `ServerPort`, `Community`, `MOOSTimeWarp`, `LatOrigin`
or `LongOrigin` set inside a block.

## Why is this bad?
There is no syntactic global section in a `.moos` file: every app reads these
keys with a lookup that returns the *first* matching line anywhere in the
file, blocks included. A `MOOSTimeWarp = 7` inside one app's block that comes
before the line at the top of the file therefore sets the time warp of every
app and of the MOOSDB; one that comes after it is read by no app at all, and
only misleads whoever reads the block. The message says which.

## Example
```moos
ProcessConfig = uSimMarineV22
{
  LatOrigin = 42.358
}
```

## How to fix
Set these keys once, outside every block. To give one app a different time
warp use its `moos_time_warp` parameter.

A fragment that a mission of the run includes is judged there, where the lines
before it are known (its own file alone would say its line comes first). A file
that is no mission (no ANTLER block, no key outside a block) and that no mission
of the run includes is an app's example configuration (`src/iGPS/iGPS.moos`,
whose app reads `LatOrigin` itself): there is no mission whose apps would read
its line, and it is left alone. In a mission with an `#include` that could
not be followed (a missing file, a macro in its path), a block's line is not
said to be the one every app reads: the missing file may set the key first.

## Options
None.
"""

import os

from moos_lint.files.diagnostics import Severity
from moos_lint.frontends.parsers.nodes import GLOBAL_KEYS, Param
from moos_lint.rules.kit.declare import Scope, rule
from moos_lint.rules.syntax._shared import example_file


@rule(code="R009", name="global-key-in-block", severity=Severity.ERROR, scope=Scope.FILE)
def check(ctx):
    if not ctx.moos.is_mission:
        if ctx.unit.path in ctx.run.included_elsewhere:
            return  # a fragment: judged in the missions that include it, after their lines
        if example_file(ctx):
            return  # an app's example block, alone in its file: no mission to misread
    order = {id(line): i for i, line in enumerate(ctx.moos.lines)}
    first: dict[str, tuple[int, Param]] = {}  # key -> the first line MOOS finds it on
    lines: dict[str, int] = {}  # key -> how many lines set it
    for p in (*ctx.moos.globals, *(q for b in ctx.moos.blocks for q in b.params)):
        if p.lkey in GLOBAL_KEYS:
            lines[p.lkey] = lines.get(p.lkey, 0) + 1
            at = order.get(id(p.line), len(order))
            if p.lkey not in first or at < first[p.lkey][0]:
                first[p.lkey] = (at, p)
    for block in ctx.moos.blocks:
        for p in block.params:
            if p.lkey not in GLOBAL_KEYS:
                continue
            winner = first[p.lkey][1]
            if winner is p and ctx.expansion.incomplete:
                continue  # an include nsplug could not follow may set the key before it
            if winner is p and lines[p.lkey] == 1:
                why = "is read by every app in the mission, as if it stood at the top of the file"
            elif winner is p:
                why = "is read by every app in the mission: it comes first, so it shadows the "
                why += f"other `{p.key}` lines of the file"
            else:
                line = winner.line
                where = f"line {line.lineno}"
                if line.path != p.line.path:
                    where = f"{os.path.basename(line.path)}:{line.lineno}"
                why = f"is read by no app: every app reads the first `{winner.key}` line of "
                why += f"the file ({where}), so this one only misleads"
            msg = f"`{p.key}` inside block `{block.name}` {why}"
            yield ctx.report(p.key_span, msg, line=p.line)
