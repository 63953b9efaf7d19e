"""Two ProcessConfig blocks for one name.

## What it does
Reports a second `ProcessConfig` block with the same name (compared without
regard to case, as MOOS does) in one file, after nsplug expansion.

## Why is this bad?
MOOS uses the first block it finds and silently ignores the later one: edits
to the second block have no effect. Through nsplug `#include`s this is easy to
do by accident. Blocks in mutually exclusive `#ifdef` branches are fine.

## Example
```moos
ProcessConfig = pLogger
{
  AsyncLog = true
}
ProcessConfig = pLogger
{
  WildCardLogging = true
}
```

## How to fix
Merge the two blocks into one.

## Options
None.
"""

from moos_lint.declare import Scope, rule
from moos_lint.diagnostics import Severity


@rule(code="R011", name="duplicate-process-config", severity=Severity.ERROR, scope=Scope.FILE)
def check(ctx):
    seen: dict[str, list] = {}
    for block in ctx.moos.blocks:
        earlier = [b for b in seen.get(block.lname, []) if not b.header.excludes(block.header)]
        if earlier:
            first = earlier[0]
            yield ctx.report(
                block.name_span,
                f"second block for `{block.name}` (first at "
                f"{_where(first.header)}): MOOS ignores this one",
                line=block.header,
            )
        seen.setdefault(block.lname, []).append(block)


def _where(line) -> str:
    import os

    return f"{os.path.basename(line.path)}:{line.lineno}"
