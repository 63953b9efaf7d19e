"""Two ProcessConfig blocks for one name.

## What it does
Reports a second `ProcessConfig` block with the same name (compared without
regard to case, as MOOS does) in one file, after nsplug expansion.

## Why is this bad?
MOOS uses the first block it finds and silently ignores the later one: edits
to the second block have no effect. Through nsplug `#include`s this is easy to
do by accident. Blocks in mutually exclusive `#ifdef` branches are fine.

An app's example configuration is left alone: a file named after the app
(`src/iSonar/iSonar.moos`) that lists presets of its block ("360 scan, low
resolution", "sector scan", ...) for the reader to copy one of, when the file
is no mission (no ANTLER block, no key outside a block) and no mission of the
run includes it. A fragment of other blocks, linted without the mission that
includes it (a pre-commit run on it alone), is still checked.

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

import os
from typing import Any

from moos_lint.files.diagnostics import Severity
from moos_lint.rules.kit.declare import Scope, rule
from moos_lint.rules.syntax._shared import example_file


@rule(code="R011", name="duplicate-process-config", severity=Severity.ERROR, scope=Scope.FILE)
def check(ctx):
    # an app's presets, side by side for the reader in the file named after it
    presets = _stem(ctx.unit.path) if example_file(ctx) else None
    # Per name, the first block of each distinct set of ``#ifdef`` branches, in order:
    # a block's first compatible predecessor is among them. Blocks outside any branch
    # are compatible with all, so none after the first such block is kept, and a file
    # of many duplicate blocks is checked in linear time.
    firsts: dict[str, dict[tuple, Any]] = {}
    closed: set[str] = set()  # names with a block outside any branch
    for block in ctx.moos.blocks:
        header = block.header
        kept = firsts.setdefault(block.lname, {})
        first = next((b for b in kept.values() if not b.header.excludes(header)), None)
        if first is not None and block.lname != presets:
            yield ctx.report(block.name_span, _message(block, first), line=header)
        if block.lname not in closed and header.branches not in kept:
            kept[header.branches] = block
            if not header.branches:
                closed.add(block.lname)


def _stem(path: str) -> str:
    return os.path.splitext(os.path.basename(path))[0].lower()


def _message(block, first) -> str:
    a, b = first.header, block.header
    if (a.path, a.lineno) == (b.path, b.lineno) and a.chain and b.chain and a.chain != b.chain:
        # one block of one file, read twice: the file is included twice
        name = os.path.basename(a.path)
        return (
            f"second block for `{block.name}`: `{name}` is included twice (at "
            f"{_site(a.chain[-1])} and {_site(b.chain[-1])}), and MOOS ignores this copy"
        )
    return f"second block for `{block.name}` (first at {_where(a)}): MOOS ignores this one"


def _site(site) -> str:
    return f"{os.path.basename(site.path)}:{site.line}"


def _where(line) -> str:
    return f"{os.path.basename(line.path)}:{line.lineno}"
