"""A heading measured from east, counter-clockwise (the math frame).

## What it does
Reports `Notify` of a heading (`NAV_HEADING`, `GPS_HDG`) whose value is the
math angle of the local grid, `atan2(Δy, Δx)` over a displacement (a
difference of two y coordinates over one of two x coordinates, or names that
say so: `dy`, `delta_x`, also through a local set once before the call), with
no turn to north after it. Adding a quarter turn is no such turn: `θ + 90`
counts counter-clockwise still, from south (`90 − θ` is the heading). A
heading is named so by its last word, or the word before a qualifier
(`HEADING_ESTIMATE`, `GPS_HDG_FILTERED`). Whether a plain `x` or `mag_y` is
on the grid or in the body frame, a name does not tell: only displacements
are judged. Adding an unknown offset (`θ + m_rotation`) or negating the angle
clears it.

A yaw in the math frame is not reported: MOOS-IvP itself writes the `YAW` of
its node reports as `headingToRadians(heading)`, from east (NodeRecord.cpp),
while uSimMarine's `NAV_YAW` is `−heading·π/180`, from north.

The value comes from moos-lint's value analysis of C++, which follows it
through locals, members, functions anywhere in the repository and struct fields
(README, "C++ apps"). The finding says why, as a chain; what the analysis
cannot know is never reported.

## Why is this bad?
MOOS measures heading in degrees from north, clockwise (at zero heading the
vehicle points north). `atan2(Δy, Δx)` is zero pointing east and grows
counter-clockwise: a vehicle heading north gets 90 instead of 0, one heading
east 0 instead of 90, one heading west 180 instead of 270. Every consumer (the
helm, pMarineViewer, pNodeReporter) then steers or draws the vehicle mirrored
about the north-east diagonal.

## Example
```cpp
double hdg = atan2(m_nav_y - m_prev_y, m_nav_x - m_prev_x) * 180 / M_PI;
Notify("GPS_HEADING", hdg);
```

## How to fix
```cpp
double hdg = atan2(m_nav_x - m_prev_x, m_nav_y - m_prev_y) * 180 / M_PI;
Notify("GPS_HEADING", angle360(hdg));
```

## Options
None.
"""

from moos_lint.files.diagnostics import Severity
from moos_lint.rules.kit.declare import Kind, Scope, rule


@rule(
    code="C009",
    name="angle-from-east",
    severity=Severity.WARNING,
    scope=Scope.CPP,
    kinds=(Kind.CPP,),
)
def check(ctx):
    # the C++ model is loaded only by runs that lint C++
    from moos_lint.rules.kit.cpp import cpp_findings
    from moos_lint.semantics.cpp_checks import angle_from_east

    yield from cpp_findings(ctx, angle_from_east)
