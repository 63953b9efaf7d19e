"""Two missions tied by pShare, each with its own local-grid origin.

## What it does
Reports a mission's `LatOrigin` when a mission of the same folder that pShare
ties to it (the pShare one launches sends on a route the other's listens on:
`output = ..., route=localhost:9200` in a vehicle, `input = route=localhost:9200`
in the shoreside) sets an origin more than `min-distance` metres (10 by
default) away. Both origins are literal numbers after nsplug expansion, each the one
line MOOS reads.

## Why is this bad?
Local x and y are metres east and north of the origin (the MOOS
conventions: a local MOOSGrid about `LatOrigin`/`LongOrigin`). A vehicle that
shares `NODE_REPORT` (its `X`, `Y`), `VIEW_POINT`, `VIEW_SEGLIST` or a
waypoint update with a shoreside that has another origin puts every one of
them that far off in the shoreside's grid: pMarineViewer draws the vehicle in
the wrong place, and shoreside apps that compare positions (uFldNodeComms'
ranges, uFldCollisionDetect, contact managers fed by the shoreside) work on
shifted coordinates. Nothing warns: each community is consistent on its own.
This happens when one file of a pair keeps a lab's template origin
(Forest Lake, `43.8253, -70.3304`) while the other was moved to the field.

Deliberately not reported:
- an origin holding a macro (`$(LAT)`), missing, not a number, or set in
  `#ifdef` branches: unknown here (latlong-origin, U004, judges the lines
  themselves);
- `LatOrigin = 0, LongOrigin = 0`, the "no geodesy" choice of simulations;
- a mission that a shell script beside it launches with its own origin
  (`pAntler alpha.moos --LatOrigin=43.8 --LongOrigin=-70.3`): pAntler runs a
  copy of the file with those lines in place of the file's;
- a pShare block no Run line starts (`//Run = pShare`): it shares nothing;
- ties made at run time by uFldNodeBroker and uFldShoreBroker, whose routes
  the brokers exchange while the missions run;
- missions in other folders, even when a route matches: a route such as
  `localhost:9200` names a port of one machine, which unrelated missions of a
  repository reuse. nsplug's outputs (`targ_*.moos`) are compared only with
  each other.

## Example
```moos
// alpha.moos
LatOrigin  = 43.825300
LongOrigin = -70.330400
ProcessConfig = pShare
{
  output = src_name=NODE_REPORT_LOCAL, dest_name=NODE_REPORT, route=localhost:9200
}

// shoreside.moos, in the same folder
LatOrigin  = 42.358456
LongOrigin = -71.087589
ProcessConfig = pShare
{
  input = route = localhost:9200
}
```

## How to fix
Give the missions one origin, best from one plug that both include
(MOOS-IvP's missions include `plug_origin_warp.moos`).

## Options
- `min-distance` (number, default 10): how many metres apart two origins must
  be to be reported.
"""

from __future__ import annotations

import os

from moos_lint.files.diagnostics import Severity
from moos_lint.files.launch import antler_overrides
from moos_lint.rules.kit.declare import Kind, Scope, rule
from moos_lint.rules.units.latlong_origin import origin
from moos_lint.semantics.background_images import apart
from moos_lint.semantics.shares import share_partners


def _told(metres: float) -> str:
    return f"{metres / 1000:.0f} km" if metres >= 10_000 else f"{metres:.0f} m"


def _moved_at_launch(path: str) -> bool:
    """Whether a launch script beside the mission gives pAntler its own origin
    (``pAntler alpha.moos --LatOrigin=43.8 --LongOrigin=-70.3``): pAntler runs a copy of
    the file with those lines in place of the file's."""
    given = antler_overrides(os.path.dirname(path), path)
    return "latorigin" in given or "longorigin" in given


@rule(
    code="U006",
    name="origin-mismatch",
    severity=Severity.WARNING,
    scope=Scope.MISSION,
    kinds=(Kind.MOOS,),
    options={"min-distance": 10},
)
def check(ctx):
    mine = origin(ctx.moos)
    if mine is None:
        return
    try:
        least = float(ctx.options.get("min-distance", 10))
    except (TypeError, ValueError):
        least = 10.0
    far: list[tuple[str, tuple, float, str]] = []
    for path, other, route in share_partners(ctx.run, ctx.path, ctx.moos):
        theirs = origin(other)
        if theirs is None:
            continue
        metres = apart(mine[:2], theirs[:2])
        if metres > least and not _moved_at_launch(path):
            far.append((os.path.basename(path), theirs, metres, route))
    if not far or _moved_at_launch(ctx.path):
        return  # (the scripts are read only for a mismatch the files show)
    others = "; ".join(
        f"`{name}` ({theirs[3]}), {_told(metres)} away (route `{route}`)"
        for name, theirs, metres, route in far[:3]
    )
    more = f"; and {len(far) - 3} more" if len(far) > 3 else ""
    whose = "those of the missions" if len(far) > 1 else "that of the mission"
    yield ctx.report(
        mine[2].key_span,
        f"this mission's origin ({mine[3]}) differs from {whose} pShare ties it to: "
        f"{others}{more}; the local x/y they share (NODE_REPORT, VIEW_*) land that far off",
        line=mine[2].line,
    )
