"""A `{ ... }` block with no `ProcessConfig =` header.

## What it does
Reports a block opened by `{` that no `ProcessConfig = NAME` line names. This
typically happens when the header was commented out and the block left behind.
A block under a `Behavior = BHV_X` line (a behavior's example saved with a
`.moos` name) is reported with a note that only behavior files (`.bhv`) hold
helm behaviors.

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

A block under a header hidden behind something MOOS does not take for a
comment (`#ProcessConfig = pLogger`, `/*ProcessConfig = pLogger`: `.moos` files
have no `/* */` comments) is not reported: MOOS reads neither the header as one
nor the block, which is what its writer meant by hiding the header.

## Options
None.
"""

import re

from moos_lint.files.diagnostics import Severity
from moos_lint.frontends.parsers.moos import looks_commented
from moos_lint.rules.kit.declare import Scope, rule


@rule(code="R004", name="orphan-block", severity=Severity.WARNING, scope=Scope.FILE)
def check(ctx):
    orphans = ctx.moos.orphan_blocks
    if not orphans:
        return
    lines = ctx.moos.lines
    index = {id(line): i for i, line in enumerate(lines)}
    for block in orphans:
        at = index.get(id(block.open))
        if _hidden_header(lines, at):
            continue  # `#ProcessConfig = pX`: the block is switched off, as its writer meant
        message = "block without a `ProcessConfig = NAME` header: no app reads it"
        if _behavior_header(lines, at):
            message += (
                " (`Behavior = ...` starts a helm behavior, which only a behavior file, "
                "`.bhv`, holds)"
            )
        yield ctx.report(block.open.span(), message, line=block.open)


_HEADER = re.compile(r"[#/*\s]*processconfig\s*=", re.IGNORECASE)


_BEHAVIOR = re.compile(r"\s*behavior\s*=\s*\S", re.IGNORECASE)


def _line_before(lines, at: int | None) -> str:
    """The text of the last non-blank line before line ``at`` ("" when none)."""
    if at is None:
        return ""
    for i in range(at - 1, -1, -1):
        text = lines[i].text.strip()
        if text:
            return text
    return ""


def _behavior_header(lines, at: int | None) -> bool:
    """Whether the block's ``{`` follows a ``Behavior = BHV_X`` line."""
    return bool(_BEHAVIOR.match(_line_before(lines, at)))


def _hidden_header(lines, at: int | None) -> bool:
    """Whether the line before the block's ``{`` (blank lines skipped) is a header behind
    something MOOS does not take for a comment (``#ProcessConfig = X``, ``/*ProcessConfig``)."""
    text = _line_before(lines, at)
    return bool(text) and looks_commented(text) and bool(_HEADER.match(text))
