"""LatOrigin / LongOrigin missing, out of range, swapped or in radians.

## What it does
Checks the origin of the local grid (MOOSGrid) in a mission, after nsplug
expansion with its includes:
- **missing**: the mission launches an app that converts between lat/long and
  local x/y (the helm, the simulators, pNodeReporter, pMarineViewer, contact
  managers, uFld sensors and referees; the app catalogue says which: the
  stock apps whose sources read `LatOrigin`, and the repository's own apps
  whose C++ does), but the file has no `LatOrigin` or no `LongOrigin` line.
  Reported once, at the first such `Run` line;
- **not a number**: MOOS reads the origin as a number and ignores anything
  else, so the apps run as if it were missing;
- **out of range**: a latitude beyond ±90° or a longitude beyond ±180°
  (with a hint when the value looks like NMEA `ddmm.mmmm`);
- **swapped**: `LatOrigin` beyond ±90° while `LongOrigin` fits a latitude;
- **in radians**: both values within ±π/2 and ±π, not both zero. Origins are
  decimal degrees.

MOOS reads the *first* `LatOrigin` line anywhere in the file, so only that
one is checked (and, with `#ifdef` branches, the first of each branch).

## Why is this bad?
Without an origin the IvP apps only warn ("No LatOrigin in *.moos file",
"Lat or Lon Origin not set") and carry on: the simulator publishes no
NAV_LAT/NAV_LONG, the helm does not derive x/y from node reports, and the
viewer has no datum. A wrong origin puts the whole local grid somewhere else
on Earth, and every conversion between lat/long and x/y is wrong.

Deliberately not reported:
- values holding an unexpanded macro (`LatOrigin = $(LAT)`): unknown;
- a missing origin when an `#include` could not be followed (the origin is
  often in a plug such as `plug_origin_warp.moos`), or when the file is itself
  included by another linted file;
- missions that launch no app that reads the origin (a bare MOOSDB with
  pLogger and uXMS needs no origin);
- a missing origin that a shell script beside the mission gives pAntler on
  its command line (`pAntler alpha.moos --LatOrigin=43.8 --LongOrigin=-70.3`):
  pAntler runs a copy of the file with those lines added;
- `LatOrigin = 0, LongOrigin = 0`, a common "no geodesy" choice in simulation.

## Example
```moos
LatOrigin  = -70.330400
LongOrigin = 43.825300

ProcessConfig = ANTLER
{
  Run = MOOSDB   @ NewConsole = false
  Run = pHelmIvP @ NewConsole = false
}
```

## How to fix
Set both, in decimal degrees, near the operating area:
```moos
LatOrigin  = 43.825300
LongOrigin = -70.330400
```

## Options
- `needs-origin` (list of strings): when given, the apps (binary names,
  compared without regard to case; an alias does not matter) that read the
  origin, instead of what the app catalogue says. By default the catalogue
  decides: among the stock apps pHelmIvP, pMarineViewer, pNodeReporter,
  uSimMarine, uSimMarineV22, uSimMarineV23, pBasicContactMgr,
  pContactMgrV20, uFldNodeComms, uFldObstacleSim, uFldBeaconRangeSensor,
  uFldContactRangeSensor, uFldCollisionDetect and uFldCollObDetect read it;
  an app linted in the same run reads it when its C++ names `LatOrigin`, unless
  each read is the test of an `if` with no `else`
  (`if (m_MissionReader.GetValue("LatOrigin", lat) && ...) { ... }`: the app
  goes on without an origin and says nothing, as one that makes its own from
  its first fixes does); a user catalogue says so with `needs_origin = true`.
"""

import math
import os
import re

from moos_lint.files.diagnostics import Severity
from moos_lint.files.launch import antler_overrides
from moos_lint.frontends.parsers.nodes import has_macro
from moos_lint.rules.kit.declare import Kind, Scope, rule
from moos_lint.semantics.catalogue import catalogue_for

# What MOOSIsNumeric accepts, roughly: a plain decimal number.
_NUMBER = re.compile(r"^[+-]?(\d+\.?\d*|\.\d+)([eE][+-]?\d+)?$")


def _number(param) -> float | None:
    text = "".join(param.value.split())
    if not _NUMBER.match(text):
        return None
    value = float(text)
    return value if math.isfinite(value) else None


def _nmea_hint(value: float, limit: float) -> str:
    deg, minutes = divmod(abs(value), 100)
    if deg <= limit and minutes < 60:
        dec = math.copysign(deg + minutes / 60, value)
        return f" (NMEA ddmm.mmmm? that would be {dec:.6f}°)"
    return ""


@rule(
    code="U004",
    name="latlong-origin",
    severity=Severity.WARNING,
    scope=Scope.MISSION,
    kinds=(Kind.MOOS,),
    options={"needs-origin": None},
)
def check(ctx):
    lats = ctx.moos.read_values("LatOrigin")
    lons = ctx.moos.read_values("LongOrigin")
    yield from _missing(ctx, lats, lons)
    for key, found, limit in (("LatOrigin", lats, 90.0), ("LongOrigin", lons, 180.0)):
        for p in found:
            if has_macro(p.value):
                continue
            value = _number(p)
            if value is None:
                yield ctx.report(
                    p.value_span,
                    f"`{key} = {p.value}` is not a number: MOOS apps read no origin",
                    line=p.line,
                )
                continue
            if abs(value) <= limit:
                continue
            if key == "LatOrigin" and abs(value) <= 180 and _swapped(lons, p):
                yield ctx.report(
                    p.value_span,
                    f"`LatOrigin = {p.value}` is beyond ±90° while `LongOrigin` is within it: "
                    "are LatOrigin and LongOrigin swapped?",
                    line=p.line,
                )
                continue
            yield ctx.report(
                p.value_span,
                f"`{key} = {p.value}` is out of range: a "
                f"{'latitude' if key == 'LatOrigin' else 'longitude'} lies within "
                f"±{limit:g}°{_nmea_hint(value, limit)}",
                line=p.line,
            )
    yield from _radians(ctx, lats, lons)


def _swapped(lons, lat) -> bool:
    for q in lons:
        if q.line.excludes(lat.line) or has_macro(q.value):
            continue
        v = _number(q)
        if v is not None and abs(v) <= 90:
            return True
    return False


def _radians(ctx, lats, lons):
    for lat in lats:
        for lon in lons:
            if lat.line.excludes(lon.line) or has_macro(lat.value) or has_macro(lon.value):
                continue
            a, b = _number(lat), _number(lon)
            if a is None or b is None or (a == 0 and b == 0):
                continue
            if abs(a) <= math.pi / 2 and abs(b) <= math.pi:
                yield ctx.report(
                    lat.value_span,
                    f"`LatOrigin = {lat.value}`, `LongOrigin = {lon.value}` look like radians "
                    f"({math.degrees(a):.6f}°, {math.degrees(b):.6f}°): the origin is in "
                    "decimal degrees",
                    line=lat.line,
                )
                return


def _missing(ctx, lats, lons):
    if lats and lons:
        return
    if ctx.expansion.incomplete or ctx.unit.path in ctx.run.included_elsewhere:
        return
    at_launch = antler_overrides(os.path.dirname(ctx.unit.path), ctx.unit.path)
    lats = lats or "latorigin" in at_launch  # (`pAntler x.moos --LatOrigin=43.8`)
    lons = lons or "longorigin" in at_launch
    if lats and lons:
        return
    given = ctx.options.get("needs-origin")
    if isinstance(given, str):
        given = [given]
    wanted = None if given is None else {str(name).lower() for name in given}
    cat = catalogue_for(ctx.run)
    for run in ctx.moos.runs:
        binary = run.program
        if has_macro(binary):
            continue
        if wanted is not None:
            if binary.lower() not in wanted:
                continue
        else:
            app = cat.app(binary)
            if app is None or not app.needs_origin:
                continue
        keys = " and ".join(k for k, v in (("LatOrigin", lats), ("LongOrigin", lons)) if not v)
        yield ctx.report(
            run.binary_span,
            f"`{binary}` converts between lat/long and the local grid, but "
            f"{os.path.basename(ctx.unit.path)} sets no {keys}",
            line=run.param.line,
        )
        return
