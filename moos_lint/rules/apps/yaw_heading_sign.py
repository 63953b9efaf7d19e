"""Yaw computed from heading as `+heading·π/180` (or heading from yaw), without the minus sign.

## What it does
Reports a yaw published (`Notify("NAV_YAW", ...)`) from a heading in degrees
turned into radians as `heading*M_PI/180`, `degToRadians(heading)` or
`MOOSDeg2Rad(hdg)` with no minus sign, also when the conversion is steps away
(a member set in one method and published in another). A heading is a value
read as `NAV_HEADING`, `relAng`/`radToHeading` results, or a name that says
heading. A yaw taken about a Z axis pointing down turns clockwise as a heading
does: MAVLink's ATTITUDE yaw (`mavlink_msg_attitude_get_yaw`, or the `yaw`
of a `mavlink_attitude_t` the message is decoded into) published as a yaw
without the minus sign is reported too.

The reverse is reported as well: a heading published (`Notify("VIEW_HEADING",
...)`) from a MOOS yaw turned into degrees with no minus sign, where the yaw
is one MOOS gives (`NAV_YAW` read by mail, or a value negated from a heading).
A variable merely named yaw is not taken as one: a device's yaw may be about
Z-down, which turns as a heading does.

A yaw and a heading that one function publishes from the same angle, one
made from the other by `·π/180` or `·180/π` (a wrap aside) with the same sign,
are reported at the yaw, whatever the angle is: `Notify("AHRS_YAW", e)` beside
`Notify("AHRS_HEADING", angle360(e*180/M_PI))`, or `HEX_YAW` as
`h*(M_PI/180)` beside `HEX_HEADING` as `h`. One of the two turns the wrong
way; most often the yaw, a device's yaw about Z-down (NED) that turns
clockwise as a heading does. A name that gives its frame (`AHRS_YAW_NED`,
`_ENU`, `_BODY`) is left alone.

The value comes from moos-lint's value analysis of C++, which follows it
through locals, members, functions anywhere in the repository and struct fields
(README, "C++ apps"). The finding says why, as a chain; what the analysis
cannot know is never reported.

## Why is this bad?
Heading is measured in degrees clockwise from north; yaw in radians
counter-clockwise (the MOOS conventions, and what uSimMarine publishes:
`NAV_YAW = -degToRadians(angle180(heading))`). Without the minus sign a vehicle
turning right reports yaw turning right too: controllers and loggers reading
NAV_YAW see the mirror image of the motion.

Headings converted in the math convention (`(90 - heading)·π/180`,
`headingToRadians`) are not reported: that is a different frame, used on
purpose (the NODE_REPORT `YAW`).

## Example
```cpp
double yaw = heading * M_PI / 180.0;
Notify("NAV_YAW", yaw);
```

## How to fix
```cpp
double yaw = MOOS_ANGLE_WRAP(-heading * M_PI / 180.0);
Notify("NAV_YAW", yaw);
```

## Options
None.
"""

from moos_lint.files.diagnostics import Severity
from moos_lint.rules.kit.declare import Kind, Scope, rule


@rule(
    code="C003",
    name="yaw-heading-sign",
    severity=Severity.WARNING,
    scope=Scope.CPP,
    kinds=(Kind.CPP,),
)
def check(ctx):
    # the C++ model is loaded only by runs that lint C++
    from moos_lint.rules.kit.cpp import cpp_findings
    from moos_lint.semantics.cpp_checks import yaw_heading_sign

    yield from cpp_findings(ctx, yaw_heading_sign)
