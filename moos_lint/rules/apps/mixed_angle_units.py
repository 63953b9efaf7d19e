"""Degrees and radians added, subtracted or compared.

## What it does
Reports a sum, difference or comparison (`+`, `-`, `<`, `>`, `<=`, `>=`, `==`,
`!=`) whose one side is an angle known to be in degrees and the other an angle
known to be in radians: an `acos` result against a value converted with
`180/PI`, a heading read by mail (or by a helm behavior from the helm's
buffer) against an `atan2`, `MOOSDeg2Rad(x)` against `MOOSRad2Deg(y)`. The
units come from moos-lint's value analysis of C++ (README, "C++ apps"), which
follows values through locals, members and functions; the finding says where
each side's unit comes from. Only operands that are a name, a member, an array
element or a call, and whose text may hold an angle (heading, yaw, pitch,
roll, theta, phi, psi, angle, bearing, course, azimuth, a `deg` or `rad` in
the name), are looked at, and a unit that only a name suggests is not trusted.

It also reports a turn written in degrees (`90`, `180`, `270` or `360`, as a
number) added to or taken from an angle known to be in radians:
`atan2(dy, dx) + 90`, `90 - atan2(dx, dy)`. In radians such a number is no
turn at all (90 radians is 14 turns and a third of a radian); the sum is meant
in degrees, and the conversion of the other side was forgotten.

## Why is this bad?
A comparison of 0.6 radians with 35 degrees is always decided by the unit,
not by the angles: a test of a transmission angle against its limit never
passes, a heading error `desired - current` is a mixture that steers the
vehicle wrong. Nothing fails or warns at run time.

## Example
```cpp
m_theta_max = (180/PI) * acos(c0 / c_bottom);   // degrees
m_theta_0   = acos(c0 / (g * m_radius));        // radians
if(m_theta_0 > m_theta_max)
  Notify("PATH_FOUND", "false");
```

```cpp
// a heading from two antennas: the baseline's angle turned a quarter turn
m_heading = atan2(m_right_y - m_left_y, m_right_x - m_left_x) + 90;
```

## How to fix
```cpp
m_theta_max = acos(c0 / c_bottom);               // keep both in radians
m_theta_0   = acos(c0 / (g * m_radius));
if(m_theta_0 > m_theta_max)
  Notify("PATH_FOUND", "false");
```

```cpp
// convert the angle before the turn is added (or add M_PI/2 in radians)
m_heading = MOOSRad2Deg(atan2(m_right_y - m_left_y, m_right_x - m_left_x)) + 90;
```

## Options
None.
"""

from moos_lint.files.diagnostics import Severity
from moos_lint.rules.kit.declare import Kind, Scope, rule


@rule(
    code="C014",
    name="mixed-angle-units",
    severity=Severity.WARNING,
    scope=Scope.CPP,
    kinds=(Kind.CPP,),
)
def check(ctx):
    # the C++ model is loaded only by runs that lint C++
    from moos_lint.rules.kit.cpp import cpp_findings
    from moos_lint.semantics.cpp_checks import mixed_angle_units

    yield from cpp_findings(ctx, mixed_angle_units)
