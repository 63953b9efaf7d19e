"""One of MOOS's angle functions given an angle in the other unit.

## What it does
Reports a call of a MOOS or MOOS-IvP angle function whose argument is known to
be in the unit the function does not take: `angle360()` or `angle180()` (which
wrap degrees) of radians, `MOOS_ANGLE_WRAP()` or `radAngleWrap()` (which wrap
radians) of degrees, a conversion to radians (`MOOSDeg2Rad()`,
`degToRadians()`, `headingToRadians()`) of radians, or one to degrees
(`MOOSRad2Deg()`, `radToDegrees()`, `radToHeading()`) of degrees. An angle is
in radians when it comes from `atan2`, `asin` and the other inverse
trigonometric functions, a conversion to radians or `NAV_YAW` read by mail, and
in degrees when it comes from a conversion to degrees, `NAV_HEADING` read by
mail or the helm's buffer, or an NMEA field. The value comes from moos-lint's
value analysis of C++, which follows it through locals, members, functions
anywhere in the repository and struct fields (README, "C++ apps"); the finding
says why, as a chain.

Not reported: a value whose unit only its name suggests (`yaw_deg`), a
function of that name the app defines itself, a variable read by mail that an
app of the same repository publishes in a unit not known to be the one the
conventions give it, and a value converted where it is kept
(`m_max_pitch = MOOSDeg2Rad(m_max_pitch)`: what it held before is what the
author converts).

## Why is this bad?
The wrap or conversion does its arithmetic in the unit it takes. `angle360()`
of a yaw of −1.2 rad gives 358.8: a "heading" of almost north for a vehicle
heading east-north-east (68.8°, as −MOOSRad2Deg(−1.2) says). `MOOSDeg2Rad()`
of an angle already in radians makes it 57 times too small, and
`MOOS_ANGLE_WRAP()` of 270° gives −0.18 (270 radians less 43 turns of 2π),
where −π/2 was meant. Nothing fails: the number is simply wrong.

## Example
```cpp
if(key == "NAV_YAW")
  m_heading = angle360(-msg.GetDouble());
```

## How to fix
```cpp
if(key == "NAV_YAW")
  m_heading = angle360(-MOOSRad2Deg(msg.GetDouble()));
```

## Options
None.
"""

from moos_lint.files.diagnostics import Severity
from moos_lint.rules.kit.declare import Kind, Scope, rule


@rule(
    code="C019",
    name="angle-argument-unit",
    severity=Severity.WARNING,
    scope=Scope.CPP,
    kinds=(Kind.CPP,),
)
def check(ctx):
    # the C++ model is loaded only by runs that lint C++
    from moos_lint.rules.kit.cpp import cpp_findings
    from moos_lint.semantics.cpp_checks import angle_argument_unit

    yield from cpp_findings(ctx, angle_argument_unit)
