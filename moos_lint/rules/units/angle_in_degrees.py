"""A pitch, roll or other radian angle written in degrees.

## What it does
Reports a literal value larger than 2π given to a pitch, roll or other
radian field: a MOOS variable or parameter whose name ends in the word
`PITCH`, `ROLL` or `RADIANS` (`NAV_PITCH`, `NAV_ROLL`, `START_PITCH`,
`TILT_RADIANS`). Values are found where `yaw-in-degrees` finds
them (parameters, uTimerScript events, flags, pMarineViewer postings,
behavior-file `initialize`). Yaw itself is `yaw-in-degrees`. A fix replaces
the literal with its radian value (value·π/180, wrapped to ±π, 4 decimals).


In C++, it reports `Notify` of a ROLL or PITCH variable (also the axes of an
Euler triple: `IMU_EULER_P`, `EULER_THETA`; a name built at run time counts by
its known end, `m_prefix + "_PITCH"`, or a member every assignment of which
ends so, `m_name_pitch = pre + "PITCH"`) with a degree value (a literal above
2π, a radians-to-degrees conversion, a library getter or device value in
degrees, a raw count over a resolution named in degrees such as
`EULER_DIV_DEG`, an angle read from the same device array as one a consumer
converts from degrees, the pitch and roll of an OceanServer OS5000 compass
read from its text sentence in an app that names the device (`iOS5000`,
`CiOS5000`), the roll and pitch of the Xsens SDK's `XsEuler` (`euler.pitch()`,
`packet.orientationEuler().pitch()`), the yaw, pitch and roll the Razor AHRS
interface hands its data callback, a pitch a simulator's record is only ever
set to in degrees through its setter, `record.setPitch(angle180(p))`, calls on
objects of other classes apart), and of an angular rate (`*_GYRO_*`,
`YAW_RATE`) in degrees per second (`* 180 / M_PI`, a raw count over a `*_DPS`
scale).

The value comes from moos-lint's value analysis of C++, which follows it
through locals, members, functions anywhere in the repository and struct fields
(README, "C++ apps"). The finding says why, as a chain; what the analysis
cannot know is never reported.

## Why is this bad?
The MOOS Conventions put every angle except heading in radians, and MOOS-IvP
publishes `NAV_PITCH` in radians. A pitch of `15` is read as 15 radians.

In C++ the rule is on by default: a driver that publishes its pitch, roll
or rates in degrees breaks every consumer that follows the convention, and
the value analysis reports only a unit it can show. In `.moos` and `.bhv`
files it is off unless asked for (`in-missions`, below): unlike yaw, pitch and
roll appear in app configuration with app-specific units, and MOOS-IvP itself
documents some of them in degrees (pMarinePID's `maxpitch`, exempted here;
`DESIRED_ELEVATOR` is degrees too, but its name does not match).

Deliberately not reported: heading fields (degrees by convention), names
where the angle word is not the last (`pitch_pid_kp`), `maxpitch` and
`max_pitch`, values that are not one plain number, and a parameter whose line
comment says it is in degrees (`pose_roll = -106  // degrees`: an app's own
key, read in the unit the app documents).

## Example
```bhv
initialize NAV_PITCH=15
```

## How to fix
Give the angle in radians, wrapped to ±π:
```bhv
initialize NAV_PITCH=0.2618
```

## Options
- `in-missions` (boolean, default false): also check `.moos` and `.bhv`
  files. They are checked as well when `select` or `extend-select` names the
  rule (`U003`, `angle-in-degrees`, `U`, `ALL`), as they were when the rule
  was off by default.
"""

import math

from moos_lint.files.diagnostics import Severity
from moos_lint.rules.kit.declare import Kind, Scope, rule
from moos_lint.rules.kit.selectors import selects
from moos_lint.semantics.angles import angle_values, degrees_to_radians


@rule(
    code="U003",
    name="angle-in-degrees",
    severity=Severity.WARNING,
    scope=Scope.FILE,
    kinds=(Kind.MOOS, Kind.BHV, Kind.CPP),
    fixable=True,
    options={"in-missions": False},
)
def check(ctx):
    if ctx.unit.kind is Kind.CPP:
        yield from cpp_check(ctx)
        return
    if not _in_missions(ctx):
        return
    for av in angle_values(ctx):
        if av.kind == "yaw" or abs(av.value) <= 2 * math.pi:
            continue
        new, conv = degrees_to_radians(av.literal, av.value)
        what = "this field is" if av.kind == "radian" else f"{av.kind} is"
        yield ctx.report(
            av.span,
            f"`{av.name}` = {av.literal} looks like degrees, but {what} in radians: "
            f"as degrees it is {conv}",
            line=av.line,
            fix=av.fix(new, f"write the angle in radians: {new}"),
        )


def _in_missions(ctx) -> bool:
    """Whether mission and behavior files are checked: asked for by the option, or by a
    selector of the configuration that names the rule."""
    if ctx.options.get("in-missions"):
        return True
    chosen = [*(ctx.settings.select or ()), *ctx.settings.extend_select]
    return any(selects(s, ctx.rule.code, ctx.rule.name) for s in chosen)


def cpp_check(ctx):
    """The C++ check, on the app model (see :mod:`moos_lint.semantics.cpp_checks`)."""
    from moos_lint.rules.kit.cpp import cpp_findings
    from moos_lint.semantics.cpp_checks import angle_in_degrees

    yield from cpp_findings(ctx, angle_in_degrees)
