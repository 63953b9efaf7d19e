"""Latitude or longitude published from a radian value.

## What it does
Reports `Notify` of a variable whose last word is `LAT`, `LON`, `LONG`,
`LATITUDE` or `LONGITUDE` with a value in radians: converted to radians
(`MOOSDeg2Rad`, `*M_PI/180`), an inverse trigonometric result, a variable
named `*_rad`, or a field a protocol gives in radians (the `lat` and `lon` of
LSTS IMC's `EstimatedState`, which DUNE bridges receive), with no conversion
back to degrees (DUNE's `Angles::degrees` is one).

The value comes from moos-lint's value analysis of C++, which follows it
through locals, members, functions anywhere in the repository and struct fields
(README, "C++ apps"). The finding says why, as a chain; what the analysis
cannot know is never reported.

## Why is this bad?
MOOS and MOOS-IvP carry positions as decimal degrees (`NAV_LAT`, `NAV_LONG`,
`LatOrigin`, `LongOrigin`): the geodesy, pMarineViewer and the log tools read
them that way. A latitude of 0.76 (radians) puts the vehicle off the coast of
Africa instead of at 43.8° N.

## Example
```cpp
Notify("NAV_LAT", MOOSDeg2Rad(lat));
```

## How to fix
```cpp
Notify("NAV_LAT", lat);
```

## Options
None.
"""

from moos_lint.files.diagnostics import Severity
from moos_lint.rules.kit.declare import Kind, Scope, rule


@rule(
    code="C006",
    name="latlong-in-radians",
    severity=Severity.WARNING,
    scope=Scope.CPP,
    kinds=(Kind.CPP,),
)
def check(ctx):
    # the C++ model is loaded only by runs that lint C++
    from moos_lint.rules.kit.cpp import cpp_findings
    from moos_lint.semantics.cpp_checks import latlong_in_radians

    yield from cpp_findings(ctx, latlong_in_radians)
