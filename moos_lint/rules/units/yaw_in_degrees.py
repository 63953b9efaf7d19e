"""A yaw value written in degrees.

## What it does
Reports a literal value given to a yaw field whose magnitude is larger than
2π, which can only be degrees. A yaw field is a MOOS variable or parameter
whose name ends in the word `YAW`: `NAV_YAW`, `START_YAW`, `YAW`. The
value may be a parameter (`START_YAW = 90`), a uTimerScript event
(`event = var=NAV_YAW, val=90, time=10`), a flag (`endflag = NAV_YAW = 90`),
a pMarineViewer button or action (`button_one = SET # NAV_YAW=90`) or a
behavior-file `initialize NAV_YAW=90`. The message gives the value in
radians (value·π/180, wrapped to ±π), and a fix replaces the literal with it,
rounded to 4 decimals.


In C++, it reports `Notify` (or `SetMOOSVar` of a dynamic variable published
under that name) of a YAW variable (`NAV_YAW`, or a name built
at run time whose last word is YAW) with a value in degrees: a literal above
2π (with `--cpp-backend clang`, also a constant expression that folds above
2π), a conversion to degrees (`* 180 / M_PI`, `radToDegrees`), a heading or
`*_deg` value, an NMEA field, a MAVLink VFR_HUD heading
(`mavlink_msg_vfr_hud_get_heading`, or the `heading` of a decoded
`mavlink_vfr_hud_t`), or a value that a consumer converts with
`MOOSDeg2Rad` on arrival.

The value comes from moos-lint's value analysis of C++, which follows it
through locals, members, functions anywhere in the repository and struct fields
(README, "C++ apps"). The finding says why, as a chain; what the analysis
cannot know is never reported.

## Why is this bad?
MOOS measures yaw in radians, wrapped to ±π (the MOOS Conventions; in
MOOS-IvP `NAV_YAW` is `-heading·π/180`, and the `YAW` field of a
NODE_REPORT is radians too). A yaw of `90` is read as 90 radians: about 14
turns, which wraps to 2.04 rad (about 117°) instead of a quarter turn, so
the vehicle or the display points the wrong way without any error.

Deliberately not reported:
- *heading* fields (`START_HEADING = 180`, `heading = 270` in a behavior,
  `DESIRED_HEADING`): MOOS-IvP works in heading degrees everywhere, and so
  does the IvP helm;
- names where YAW is not the last word, such as pMarinePID's gains
  `yaw_pid_kp` or a `YAW_RATE`;
- values that are not one plain number: `$(MACRO)`, `$[MACRO]`, quoted
  strings (uTimerScript posts `val="90"` as a string), lists;
- a parameter whose line comment says it is in degrees (`pose_yaw = -90  //
  degrees`, a vision library's mounting pose): an app's own key, read in the
  unit the app documents;
- values up to 2π: they may be radians (see `angle-not-wrapped` for values
  between π and 2π).

## Example
```moos
ProcessConfig = uTimerScript
{
  event = var=NAV_YAW, val=90, time=10
}
```

## How to fix
Give the yaw in radians, wrapped to ±π:
```moos
  event = var=NAV_YAW, val=1.5708, time=10
```
If the value is meant as a compass heading, use the heading variable
(`NAV_HEADING`, degrees) instead, or convert it with `yaw = -heading·π/180`.

## Options
None.
"""

import math

from moos_lint.files.diagnostics import Severity
from moos_lint.rules.kit.declare import Kind, Scope, rule
from moos_lint.semantics.angles import angle_values, degrees_to_radians


def _looks_like_degrees(value: float) -> bool:
    mag = abs(value)
    if mag > 2 * math.pi:
        return True
    return mag > math.pi and float(mag).is_integer() and int(mag) % 45 == 0


@rule(
    code="U001",
    name="yaw-in-degrees",
    severity=Severity.WARNING,
    scope=Scope.FILE,
    kinds=(Kind.MOOS, Kind.BHV, Kind.CPP),
    fixable=True,
)
def check(ctx):
    if ctx.unit.kind is Kind.CPP:
        yield from cpp_check(ctx)
        return
    for av in angle_values(ctx):
        if av.kind != "yaw" or not _looks_like_degrees(av.value):
            continue
        new, conv = degrees_to_radians(av.literal, av.value)
        message = (
            f"`{av.name}` = {av.literal} looks like degrees, but yaw is in radians: "
            f"as degrees it is {conv}"
        )
        yield ctx.report(
            av.span,
            message,
            line=av.line,
            fix=av.fix(new, f"write the yaw in radians: {new}"),
        )


def cpp_check(ctx):
    """The C++ check, on the app model (see :mod:`moos_lint.semantics.cpp_checks`)."""
    from moos_lint.rules.kit.cpp import cpp_findings
    from moos_lint.semantics.cpp_checks import yaw_in_degrees

    yield from cpp_findings(ctx, yaw_in_degrees)
