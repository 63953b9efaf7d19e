"""A `{ ... }` block with no `ProcessConfig =` header.

## What it does
Reports a block opened by `{` that no `ProcessConfig = NAME` line names. This
typically happens when the header was commented out and the block left behind.

## Why is this bad?
No app ever reads an orphan block. Worse, MOOS's global lookup scans the whole
file, so a global-looking key inside the orphan block (`MOOSTimeWarp = 10`)
still shadows the real one.

## Example
```moos
//ProcessConfig = pLogger
{
  AsyncLog = true
}
```

## How to fix
Restore the header, or delete the whole block.

A header hidden behind something MOOS does not take for a comment
(`#ProcessConfig = pLogger`, `/*ProcessConfig = pLogger`: `.moos` files have no
`/* */` comments) is reported once, by not-a-comment (R007), when that rule is
enabled: the block below it is then not reported again.

## Options
None.
"""

import re

from moos_lint.files.diagnostics import Severity
from moos_lint.frontends.parsers.moos import looks_commented
from moos_lint.rules.kit.declare import Scope, rule


@rule(code="R004", name="orphan-block", severity=Severity.WARNING, scope=Scope.FILE)
def check(ctx):
    r007 = ctx.runs("R007")
    index: dict[int, int] | None = None
    for block in ctx.moos.orphan_blocks:
        if r007:
            if index is None:
                index = {id(line): i for i, line in enumerate(ctx.moos.lines)}
            if _hidden_header(ctx.moos.lines, index.get(id(block.open))):
                continue  # not-a-comment reports the header line
        yield ctx.report(
            block.open.span(),
            "block without a `ProcessConfig = NAME` header: no app reads it",
            line=block.open,
        )


_HEADER = re.compile(r"[#/*\s]*processconfig\s*=", re.IGNORECASE)


def _hidden_header(lines, at: int | None) -> bool:
    """Whether the line before the block's ``{`` (blank lines skipped) is a header behind
    something MOOS does not take for a comment (``#ProcessConfig = X``, ``/*ProcessConfig``)."""
    if at is None:
        return False
    for i in range(at - 1, -1, -1):
        text = lines[i].text.strip()
        if text:
            return looks_commented(text) and bool(_HEADER.match(text))
    return False
