"""Two missions tied by pShare, each with its own MOOSTimeWarp.

## What it does
Reports a mission's `MOOSTimeWarp` when a mission of the same folder that
pShare ties to it (the pShare one launches sends on a route the other's
listens on: `output = ..., route=localhost:9200` in a vehicle, `input =
route=localhost:9200` in the shoreside) runs at another warp. Both warps are
literal numbers after nsplug expansion, each the first line MOOS reads.

## Why is this bad?
The time warp scales every community's clock (`MOOSTime()`), its app ticks
and its timers. Communities that exchange mail must run at one warp: a
shoreside at 10 and a vehicle at 1 see each other's `NODE_REPORT` time stamps
drift apart by nine seconds every second, so the shoreside's apps take the
vehicle for silent or stale (uFldNodeComms, pMarineViewer's stale reports,
uFldContactRangeSensor), while the shoreside's commands reach a vehicle whose
behaviors run ten times slower than planned. MOOS-IvP's launch scripts give
every community the same `WARP` for this reason. Nothing warns: each
community runs correctly on its own.

Deliberately not reported:
- a warp holding a macro (`$(WARP)`), or given in `#ifdef` branches: unknown
  here;
- a mission that a shell script beside it launches with its own warp
  (`pAntler $COMMUNITY.moos --MOOSTimeWarp=$TIME_WARP`, MOOS-IvP's usual
  launch line): pAntler runs a copy of the file with that line in place of
  the file's (`mission.moos++`), so the file's warp is not the one that runs;
- a pShare block no Run line starts (`//Run = pShare`): it shares nothing;
- ties made at run time by uFldNodeBroker and uFldShoreBroker, whose routes
  the brokers exchange while the missions run;
- missions in other folders, even when a route matches: a route such as
  `localhost:9200` names a port of one machine, which unrelated missions of a
  repository reuse. nsplug's outputs (`targ_*.moos`) are compared only with
  each other.

## Example
```moos
// shoreside.moos
MOOSTimeWarp = 10
ProcessConfig = pShare
{
  input = route = localhost:9200
}

// alpha.moos, in the same folder
MOOSTimeWarp = 1
ProcessConfig = pShare
{
  output = src_name=NODE_REPORT_LOCAL, dest_name=NODE_REPORT, route=localhost:9200
}
```

## How to fix
Give the missions one warp, best from one macro or plug (`MOOSTimeWarp =
$(WARP)`, with the launch script passing the same `WARP` to every mission).

## Options
None.
"""

from __future__ import annotations

import os

from moos_lint.files.diagnostics import Severity
from moos_lint.files.launch import antler_overrides
from moos_lint.frontends.nsplug import derived
from moos_lint.frontends.parsers.nodes import has_macro
from moos_lint.rules.kit.declare import Kind, Scope, rule
from moos_lint.semantics.shares import share_partners


def time_warp(moos):
    """``(warp, its parameter)`` of a mission whose warp is known: the first
    `MOOSTimeWarp` line of the file (MOOS reads the first, blocks included), when no
    other sits in an exclusive `#ifdef` branch of it, a literal positive number. Once
    per expansion (each mission of a folder asks about the others)."""
    return derived(moos.expansion, "literal-time-warp", lambda: (_time_warp(moos),))[0]


def _time_warp(moos):
    params = moos.read_values("MOOSTimeWarp")
    if len(params) != 1:
        return None
    first = params[0]
    text = "".join(first.value.split())
    if has_macro(text):
        return None
    try:
        warp = float(text)
    except ValueError:
        return None
    return (warp, first) if warp > 0 else None


def _warped_at_launch(path: str) -> bool:
    """Whether a launch script beside the mission gives pAntler its own warp
    (``pAntler $COMMUNITY.moos --MOOSTimeWarp=$TIME_WARP``): the file's is not the one
    that runs."""
    return "moostimewarp" in antler_overrides(os.path.dirname(path), path)


@rule(
    code="H006",
    name="time-warp-mismatch",
    severity=Severity.WARNING,
    scope=Scope.MISSION,
    kinds=(Kind.MOOS,),
)
def check(ctx):
    mine = time_warp(ctx.moos)
    if mine is None:
        return
    other_warps: list[str] = []
    for path, other, route in share_partners(ctx.run, ctx.path, ctx.moos):
        theirs = time_warp(other)
        if theirs is not None and theirs[0] != mine[0] and not _warped_at_launch(path):
            other_warps.append(
                f"`{os.path.basename(path)}` ({theirs[1].value.strip()}, route `{route}`)"
            )
    if not other_warps or _warped_at_launch(ctx.path):
        return  # (the scripts are read only for a mismatch the files show)
    whose = "those of the missions" if len(other_warps) > 1 else "that of the mission"
    yield ctx.report(
        mine[1].value_span,
        f"`MOOSTimeWarp = {mine[1].value.strip()}` differs from {whose} pShare ties this one "
        f"to: {'; '.join(other_warps[:3])}"
        f"{f'; and {len(other_warps) - 3} more' if len(other_warps) > 3 else ''}; communities "
        "that exchange mail run at one warp, or their clocks and time stamps drift apart",
        line=mine[1].line,
    )
