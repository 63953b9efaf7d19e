"""A radian value published to a HEADING variable without conversion.

## What it does
Reports `Notify` of a variable whose last word is `HEADING` or `HDG`
(`NAV_HEADING`, `DESIRED_HEADING`, `GPS_HDG`) with a value in radians: an
`atan2`/`atan`/`asin`/`acos` result, a degrees-to-radians conversion, a
`NAV_YAW` read by mail or a `*_rad` name, with no conversion back to degrees
(`MOOSRad2Deg`, `radToDegrees`, `radToHeading`, `*180/M_PI`).

The value comes from moos-lint's value analysis of C++, which follows it
through locals, members, functions anywhere in the repository and struct fields
(README, "C++ apps"). The finding says why, as a chain; what the analysis
cannot know is never reported.

## Why is this bad?
In MOOS and MOOS-IvP a heading is in degrees, clockwise from north: the helm,
pMarinePID, pNodeReporter and pMarineViewer all read NAV_HEADING that way. A
heading of 1.57 is read as 1.57° instead of 90°: the vehicle steers north
while it is heading east.

## Example
```cpp
double hdg = atan2(dx, dy);
Notify("NAV_HEADING", hdg);
```

## How to fix
```cpp
double hdg = angle360(MOOSRad2Deg(atan2(dx, dy)));
Notify("NAV_HEADING", hdg);
```

## Options
None.
"""

from moos_lint.files.diagnostics import Severity
from moos_lint.rules.kit.declare import Kind, Scope, rule


@rule(
    code="C004",
    name="heading-in-radians",
    severity=Severity.WARNING,
    scope=Scope.CPP,
    kinds=(Kind.CPP,),
)
def check(ctx):
    # the C++ model is loaded only by runs that lint C++
    from moos_lint.rules.kit.cpp import cpp_findings
    from moos_lint.semantics.cpp_checks import heading_in_radians

    yield from cpp_findings(ctx, heading_in_radians)
