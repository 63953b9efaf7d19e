"""A block of `Run` lines named after pAntler but not `ANTLER` (`ProcessConfig = pAntler`).

## What it does
Reports a `ProcessConfig` block whose name holds `antler` but is not `ANTLER`
(`pAntler`, `Antler2`), when the block has `Run` lines. Names are compared
as MOOS compares them, without regard to case: `ProcessConfig = Antler` is
read.

## Why is this bad?
pAntler reads its launch list only from the block named `ANTLER`, whatever
name it is started under: it sets its own name to `ANTLER` before reading the
mission (MOOSEssentials, `pAntler/Antler.cpp`:
`m_MissionReader.SetAppName("ANTLER")`). A block named after the program is
never read: pAntler finds no `Run` line and launches nothing, silently.

## Example
```moos
ProcessConfig = pAntler
{
  Run = MOOSDB   @ NewConsole = false
  Run = pHelmIvP @ NewConsole = false
}
```

## How to fix
```moos
ProcessConfig = ANTLER
{
  Run = MOOSDB   @ NewConsole = false
  Run = pHelmIvP @ NewConsole = false
}
```

## Options
None.
"""

from moos_lint.files.diagnostics import Edit, Fix, Severity
from moos_lint.rules.kit.declare import Scope, rule


@rule(
    code="R014",
    name="misnamed-antler-block",
    severity=Severity.ERROR,
    scope=Scope.FILE,
    fixable=True,
)
def check(ctx):
    for block in ctx.moos.blocks:
        if block.header is None or "antler" not in block.lname or block.lname == "antler":
            continue
        if not any(p.lkey == "run" for p in block.params):
            continue
        yield ctx.report(
            block.name_span,
            f"`ProcessConfig = {block.name}`: pAntler reads its Run lines only from the block "
            "named ANTLER, so this block launches nothing",
            line=block.header,
            fix=Fix("rename the block ANTLER", (Edit(block.name_span, "ANTLER"),)),
        )
