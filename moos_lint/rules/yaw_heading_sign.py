"""Yaw computed from heading as `+heading·π/180`, without the minus sign.

## What it does
Reports a yaw computed from a heading in degrees as `heading*M_PI/180`,
`degToRadians(heading)` or `MOOSDeg2Rad(hdg)` with no minus sign in front,
where the result is published to a YAW variable (`Notify("NAV_YAW", ...)`,
directly or through local variables) or assigned to a variable whose name
says yaw.

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

from moos_lint.declare import Kind, Scope, rule
from moos_lint.diagnostics import Severity


@rule(
    code="C003",
    name="yaw-heading-sign",
    severity=Severity.WARNING,
    scope=Scope.CPP,
    kinds=(Kind.CPP,),
)
def check(ctx):
    # the C++ model is loaded only by runs that lint C++
    from moos_lint.cpp.checks import yaw_heading_sign
    from moos_lint.cpp.rulekit import cpp_findings

    yield from cpp_findings(ctx, yaw_heading_sign)
