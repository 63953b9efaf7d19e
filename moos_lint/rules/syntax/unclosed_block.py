"""A ProcessConfig block whose closing `}` is missing.

## What it does
Reports a block that is not closed by a line starting with `}` before the
next block header or the end of the file. A `{` with no header of its own is
no app's block and MOOS reads nothing into it: orphan-block reports that one.
A line that starts with `{` and goes on (`{ configuration block`) opens a
block only right after a header; elsewhere it is a line MOOS drops
(malformed-line).

## Why is this bad?
MOOS reads on past the end of the intended block: the next
`ProcessConfig = Y` line becomes a parameter of this block, and the next
block's parameters are read by this app. The next app may never find its own
block. MOOS prints at most an easily missed `missing "}"` message. The last
block of a file, left open, is answered as missing: MOOS's reader reaches the
end of the file still looking for the `}` and says there is no block, though
it has listed the block's lines. What the app then runs with depends on how it
reads them: `AppTick`, `CommsTick` and every parameter asked for by name
(`GetConfigurationParam`) fall back to their defaults; an app that checks the
answer loses the whole block (pLogger logs nothing it was told to); an app that
reads the list anyway keeps the lines and warns `No config block found`
(pMarineViewer and the AppCasting template).

## Example
```moos
ProcessConfig = pLogger
{
  AsyncLog = true

ProcessConfig = pHelmIvP
{
  behaviors = alpha.bhv
}
```

## How to fix
Add the missing `}` at the end of the block.

## Options
None.
"""

from moos_lint.files.diagnostics import Severity
from moos_lint.rules.kit.declare import Scope, rule


@rule(code="R005", name="unclosed-block", severity=Severity.ERROR, scope=Scope.FILE)
def check(ctx):
    for block in ctx.moos.unclosed_blocks:
        line = block.header or block.open
        what = f"block `{block.name}`" if block.name else "block"
        if _runs_to_the_end(ctx.moos, block, line):
            effect = (
                "MOOS reads to the end of the file looking for it and answers that the "
                "block is missing: AppTick, CommsTick and parameters asked for by name "
                "fall back to their defaults, an app that checks the answer (pLogger) "
                "loses the block, and one that reads its lines anyway warns "
                "`No config block found`"
            )
        else:
            effect = "MOOS reads the following lines into it"
        yield ctx.report(line.span(), f"{what} is never closed by `}}`: {effect}", line=line)


def _runs_to_the_end(moos, block, line) -> bool:
    """Whether no block opens after ``block``: its lines run to the end of the file, where
    MOOS's reader, still looking for the `}`, returns no block at all
    (ProcessConfigReader.cpp, GetConfiguration)."""
    if not moos.blocks or moos.blocks[-1] is not block:
        return False
    if not moos.orphan_blocks:
        return True
    index = {id(x): i for i, x in enumerate(moos.lines)}
    at = index.get(id(line), -1)
    return all(index.get(id(o.open), -1) < at for o in moos.orphan_blocks)
