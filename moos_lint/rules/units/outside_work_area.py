"""Local-grid coordinates far outside the work area.

## What it does
Reports local-grid (x, y) coordinates farther from the origin than
`max-distance` metres (20 km by default), in:
- behavior parameters that take points or polygons: `points`, `xpoints`,
  `point`, `polygon`, `station_pt`, `center_assign`, `bearing_point`,
  `match_region`, `ignore_region`;
- the same keys in `.moos` blocks, and pMarineViewer `op_vertex` and
  uFldGenericSensor `source_point`;
- uSimMarine start positions: `start_pos` (`x=0, y=-20, heading=180` or
  the older `80, 0, 180, 0`), `start_x`, `start_y`.

Only forms the MOOS-IvP geometry readers accept are read: vertex lists
(`60,-40 : 60,-160`, with `label,NAME` parts), `pts={...}`, and keyed forms
with a centre or point (`x=.., y=..`, `format=radial|ellipse|lawnmower|
bowtie|wedge`, `radial:: x=..`). For a shape given by its centre only the
centre is checked. A value with a macro (`$(START_POS)`, `$[X]`), or in a form
not understood, is skipped.

## Why is this bad?
x and y are metres east and north of `LatOrigin`/`LongOrigin`. MOOSGrid's
geodesy assumes a local work area, a square under about 20 km on a side
with the origin in it, so a point more than 20 km away is either a mistake (a
UTM easting or northing,
which the message names from 100 km on, or a value typed in the wrong field:
the vehicle then heads for a point far away, or the polygon is off the map)
or an origin placed far from where the vehicle works, where the flat grid
drifts from the true positions.

Deliberately not reported: headings and speeds in `start_pos`,
pMarineViewer pan and zoom settings (screen values, not coordinates), and any
value not fully understood. If your missions really span more than 20 km,
raise `max-distance`.

## Example
```bhv
Behavior = BHV_Waypoint
{
  name   = transit
  points = 330120,4853270 : 330200,4853100
}
```

## How to fix
Give points in metres relative to the mission's origin:
```bhv
  points = 60,-40 : 140,-210
```
Convert lat/long or UTM positions with the geodesy tools, or move the origin
closer to the operating area.

## Options
- `max-distance` (number, metres): the largest distance from the origin that
  is not reported. Default: `20000` (a point 16 km off still fits a 20 km
  square with the origin near one side: a work area placed so is not
  reported). Lower it to hear of points far from a centred origin.
"""

import math

from moos_lint.files.diagnostics import Severity
from moos_lint.rules.kit.declare import Kind, Scope, rule
from moos_lint.semantics.geometry import geometry_points, start_pos_points

GEOMETRY_KEYS = {
    "points",
    "xpoints",
    "point",
    "polygon",
    "station_pt",
    "center_assign",
    "bearing_point",
    "match_region",
    "ignore_region",
    "op_vertex",
    "source_point",
}
SIM_PREFIX = "usimmarine"


def _app_names(moos) -> dict[str, str]:
    """Block name (lower case) -> the binary launched under that name."""
    out: dict[str, str] = {}
    for run in moos.runs:
        binary = run.program
        out[run.name.lower()] = binary.lower()
    return out


def _distance(metres: float) -> str:
    return f"{metres / 1000:.1f} km" if metres >= 1000 else f"{metres:.0f} m"


def _points(key: str, value: str, sim: bool):
    if key in GEOMETRY_KEYS:
        return geometry_points(value)
    if sim and key == "start_pos":
        return start_pos_points(value)
    if sim and key == "start_x":
        return geometry_points(f"x={value}, y=0")
    if sim and key == "start_y":
        return geometry_points(f"x=0, y={value}")
    return None


#: at least this far (metres), a point is most likely a UTM easting or northing (eastings
#: run from about 160 to 840 km): nothing a MOOS grid holds
UTM_SCALE = 100_000


@rule(
    code="U005",
    name="outside-work-area",
    severity=Severity.WARNING,
    scope=Scope.FILE,
    kinds=(Kind.MOOS, Kind.BHV),
    options={"max-distance": 20000},
)
def check(ctx):
    limit = float(ctx.options.get("max-distance", 20000))
    found = []
    if ctx.moos is not None:
        apps = _app_names(ctx.moos)
        for block in ctx.moos.blocks:
            app = apps.get(block.lname, block.lname)
            sim = app.startswith(SIM_PREFIX) or block.lname.startswith(SIM_PREFIX)
            for p in block.params:
                found.append((p, _points(p.lkey, p.value, sim)))
    if ctx.bhv is not None:
        for behavior in ctx.bhv.behaviors:
            for p in behavior.params:
                found.append((p, _points(p.lkey, p.value, False)))
    for p, pts in found:
        if not pts:
            continue
        far = max(pts, key=lambda pt: math.hypot(*pt))
        dist = math.hypot(*far)
        if dist <= limit:
            continue
        if dist >= UTM_SCALE:
            why = "local x/y are metres from LatOrigin/LongOrigin (a UTM coordinate?)"
        else:
            why = (
                "the local grid is a flat map of a work area of about 20 km around "
                "LatOrigin/LongOrigin (move the origin near the operating area?)"
            )
        yield ctx.report(
            p.value_span,
            f"`{p.key}`: the point ({far[0]:g}, {far[1]:g}) is {_distance(dist)} from the "
            f"origin, farther than {_distance(limit)}: {why}",
            line=p.line,
        )
