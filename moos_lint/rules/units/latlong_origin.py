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
  or, both fitting a latitude, the origin lies more than 20 km from every
  background image the mission's pMarineViewer shows (`tiff_file`,
  `tiff_file_b`) and on one once swapped (`LatOrigin = -71.087589`,
  `LongOrigin = 42.358456` with `MIT_SP.tif`). Where an image lies comes from
  its `.info` file in the mission's folder or its parents up to the project
  root, read as data, or for the images MOOS-IvP ships (`forrest19.tif`,
  `MIT_SP.tif`) from the stock catalogue (their `ivp/data/*.info`);
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
- `LatOrigin = 0, LongOrigin = 0`, a common "no geodesy" choice in simulation;
- an origin merely far from the viewer's image, not swapped (an origin at Forrest
  Lake with `MIT_SP.tif`): pMarineViewer puts the image's own datum at the local
  grid's (0, 0), so a simulation looks right on the wrong shore; 91 missions of
  201 public repositories do so, copied from one lab to another;
- a viewer given an image nothing in the project describes and MOOS-IvP does not
  ship (it may show the origin as written).

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
from moos_lint.files.launch import antler_overrides, find_relative, launch_folders, project_folder
from moos_lint.files.source import ReadProblem, read_bytes
from moos_lint.frontends.nsplug import derived
from moos_lint.frontends.parsers.nodes import has_macro
from moos_lint.rules.kit.declare import Kind, Scope, rule
from moos_lint.semantics.background_images import ImageBox, apart, image_box, info_name
from moos_lint.semantics.catalogue import catalogue_for

# What MOOSIsNumeric accepts, roughly: a plain decimal number.
_NUMBER = re.compile(r"^[+-]?(\d+\.?\d*|\.\d+)([eE][+-]?\d+)?$")


def _number(param) -> float | None:
    text = "".join(param.value.split())
    if not _NUMBER.match(text):
        return None
    value = float(text)
    return value if math.isfinite(value) else None


def origin(moos):
    """``(lat, lon, the LatOrigin line's parameter, the origin as written)`` of a mission
    whose origin is known: one line of each that MOOS reads, literal numbers in range,
    not both 0. Once per expansion (each mission of a folder asks about the others)."""
    return derived(moos.expansion, "literal-origin", lambda: (_origin(moos),))[0]


def _origin(moos):
    lats = moos.read_values("LatOrigin")
    lons = moos.read_values("LongOrigin")
    if len(lats) != 1 or len(lons) != 1 or has_macro(lats[0].value + lons[0].value):
        return None
    lat, lon = _number(lats[0]), _number(lons[0])
    if lat is None or lon is None or abs(lat) > 90 or abs(lon) > 180 or lat == lon == 0:
        return None
    return lat, lon, lats[0], f"{lats[0].value.strip()}, {lons[0].value.strip()}"


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
    yield from _swapped_by_map(ctx)


#: how far from a background image an origin may lie and still be its place, metres (the
#: work area of a local grid)
_ON_MAP = 20_000.0
#: pMarineViewer's keys that each add a background image
_IMAGE_KEYS = ("tiff_file", "tiff_file_b")


def _swapped_by_map(ctx):
    """LatOrigin and LongOrigin swapped, both in range: the origin lies far from every
    background image the mission's pMarineViewer shows, and on one once swapped back."""
    found = origin(ctx.moos)
    if found is None:
        return
    lat, lon, lat_param, written = found
    if abs(lon) > 90 or lat == lon:
        return  # (a longitude beyond ±90° is no latitude: swapped, it is out of range)
    names = list(_images(ctx.moos))
    if not names:
        return
    folders = launch_folders(ctx.unit.path, project_folder(ctx.settings, ctx.unit.path))
    cat = catalogue_for(ctx.run)
    boxes = []
    for name in names:
        box = _described(name, folders, cat)
        if box is None:
            return  # an image nothing here describes may well show the origin as written
        boxes.append((name, box))
    if any(apart((lat, lon), b.nearest(lat, lon)) <= _ON_MAP for _n, b in boxes):
        return
    for name, box in boxes:
        if apart((lon, lat), box.nearest(lon, lat)) <= _ON_MAP:
            lat_text, lon_text = written.split(", ", 1)
            yield ctx.report(
                lat_param.value_span,
                f"`LatOrigin = {lat_text}`, `LongOrigin = {lon_text}` lie far from the "
                f"background map (`{name}` covers {box.shown()}, {box.source}) and swapped "
                "they lie on it: are LatOrigin and LongOrigin swapped?",
                line=lat_param.line,
            )
            return


def _images(moos):
    """The background images a launched pMarineViewer is given (``tiff_file``)."""
    names = {run.name.lower() for run in moos.runs if run.program.lower() == "pmarineviewer"}
    for block in moos.blocks:
        if block.header is None or block.lname not in names:
            continue
        for p in block.params:
            if p.lkey in _IMAGE_KEYS:
                value = "".join(p.value.split()).strip('"')
                if value and value.lower() != "null.tif":
                    yield value


def _described(name: str, folders: list[str], cat) -> ImageBox | None:
    """Where image ``name`` lies: its ``.info`` file in the mission's folders (a name with a
    macro, or outside the project, is not looked for), else the stock image of its name."""
    if has_macro(name) or os.path.isabs(name) or ".." in name.split("/"):
        return None
    info = find_relative(info_name(name), folders)
    if info is not None:
        data = read_bytes(info)
        if isinstance(data, ReadProblem):
            return None
        return image_box(data.decode("utf-8", "replace"), os.path.basename(info))
    return cat.background_images.get(os.path.basename(name).lower())


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
