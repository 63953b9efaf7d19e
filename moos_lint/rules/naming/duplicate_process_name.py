"""Two processes launched under one name in one community.

## What it does
Reports an Antler `Run` line that launches a process under a name an earlier
`Run` line of the same mission already uses. The name is the `~` alias when
there is one (or a `--alias=` given through `ExtraProcessParams`), otherwise
the program name; names are compared with regard to case, as the MOOSDB
compares them. `Run` lines in mutually exclusive `#ifdef` / `#elseifdef` /
`#else` branches are not duplicates, and names that hold an nsplug macro
(`$(X)`) are skipped. Only the first ANTLER block counts: pAntler ignores a
second one (see `duplicate-process-config`).

## Why is this bad?
pAntler does not check names: it starts both processes. The MOOSDB then
refuses the second client with "A client of this name already exists", so
the second process never gets a connection, and the first block
`ProcessConfig = NAME` configures both. MOOS-IvP's own minicourse mission
`lab_henry_gilda_baseline/meta_vehicle.moos` launches pRealm twice.

Names that differ only in case (`pRealm` and `prealm`) both connect, but they
read the same ProcessConfig block, because block names are compared without
regard to case; this rule does not report them.

## Example
```moos
ProcessConfig = ANTLER
{
  Run = MOOSDB        @ NewConsole = false
  Run = uTimerScript  @ NewConsole = false
  Run = uTimerScript  @ NewConsole = false
}
```

## How to fix
Delete the second line, or give each instance its own alias and block:
```moos
  Run = uTimerScript  @ NewConsole = false ~ uTimerScript_PING
  Run = uTimerScript  @ NewConsole = false ~ uTimerScript_PONG
```

## Options
None.
"""

from __future__ import annotations

import os

from moos_lint.files.diagnostics import Severity
from moos_lint.frontends.parsers.nodes import Block, antler_runs, has_macro
from moos_lint.rules.kit.declare import Kind, Scope, rule


@rule(
    code="N002",
    name="duplicate-process-name",
    severity=Severity.ERROR,
    scope=Scope.MISSION,
    kinds=(Kind.MOOS,),
)
def check(ctx):
    effective: list[Block] = []
    for block in ctx.moos.antler_blocks:
        header = block.header
        if any(
            b.header is None or header is None or not b.header.excludes(header) for b in effective
        ):
            continue  # pAntler reads the first ANTLER block only
        effective.append(block)
    seen: dict[str, list] = {}
    for block in effective:
        for run in antler_runs(block):
            name = run.name
            if not name or has_macro(name) or run.inhibits_moos_params:
                continue  # (a program started without its MOOS name is no client of it)
            line = run.param.line
            earlier = [r for r in seen.get(name, []) if not r.param.line.excludes(line)]
            if earlier:
                first = earlier[0].param.line
                yield ctx.report(
                    run.name_span,
                    f"`{name}` is launched twice (first at {os.path.basename(first.path)}:"
                    f"{first.lineno}): the MOOSDB refuses a second client of that name",
                    line=line,
                )
            seen.setdefault(name, []).append(run)
