"""One value published as two kinds of quantity by calls written one after another.

## What it does
Reports a publication (`Notify`, `SetMOOSVar`, a `CMOOSMsg` posted) that gives
a variable of one kind of quantity the value that a publication just before it,
in the same run of consecutive calls of one block, gives a variable of another
kind: `NAV_Y` and then `NAV_SPEED` and `NAV_HEADING`, all given `y`. The kinds
come from the variables' last words: an angle (`HEADING`, `YAW`, `PITCH`,
`ROLL`), a speed (`SPEED`, `SOG`), a depth or height (`DEPTH`, `Z`,
`ALTITUDE`), a position (`X`, `Y`, `LAT`, `LONG`) and each actuator of the
MOOS Conventions (`THRUST`, `RUDDER`, `ELEVATOR`). The first publication of
the value is taken as the one its author meant; each later one of another
kind is reported.

Not reported: a constant (`0.0`, a member the app only sets to a number),
values that may change from one call to the next (any call but a cast, an
increment), publications with any other statement between them (the value may
have been set again, or an `if` chooses one), two kinds of angle (a sensor
mounted on its side publishes its roll as pitch), two kinds of position (NED
and ENU exchange x and y), and variables whose last word names no quantity
(`NAV_YAW_RATE`, `GPS_HDOP`).

## Why is this bad?
A block of `Notify` calls is written by copying the line above and changing
the name; a value left unchanged publishes a position as the vehicle's speed
and heading. Nothing fails: the helm, pMarineViewer and the logs take the
number as it is named, the vehicle is drawn pointing the wrong way and the
speed a behavior reads is a northing.

## Example
```cpp
Notify(m_nav_prefix + "_X", x);
Notify(m_nav_prefix + "_Y", y);
Notify(m_nav_prefix + "_SPEED", y);
Notify(m_nav_prefix + "_HEADING", y);
```

## How to fix
```cpp
Notify(m_nav_prefix + "_X", x);
Notify(m_nav_prefix + "_Y", y);
Notify(m_nav_prefix + "_SPEED", speed);
Notify(m_nav_prefix + "_HEADING", heading);
```

## Options
None.
"""

from moos_lint.files.diagnostics import Severity
from moos_lint.rules.kit.declare import Kind, Scope, rule


@rule(
    code="C017",
    name="pasted-publication",
    severity=Severity.WARNING,
    scope=Scope.CPP,
    kinds=(Kind.CPP,),
)
def check(ctx):
    # the C++ model is loaded only by runs that lint C++
    from moos_lint.rules.kit.cpp import cpp_findings
    from moos_lint.semantics.cpp_checks import pasted_publication

    yield from cpp_findings(ctx, pasted_publication)
