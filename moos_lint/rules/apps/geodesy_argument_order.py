"""A CMOOSGeodesy conversion given north for east, or longitude for latitude.

## What it does
Reports an argument of `LatLong2LocalGrid`, `LatLong2LocalUTM`,
`LocalGrid2LatLong` or `UTM2LatLong` whose name says the opposite of the
parameter it is passed to: `x`, `east` or `easting` (`nav_x`, `xUTM`,
`dfXLocal`) where the conversion takes or gives north, `y`, `north` or
`northing` where it wants east, a longitude where it wants the latitude, and
the reverse. A name that says nothing (`a`, `tmp`) or two things
(`latlon_vec[0]`, `n_x`) is not judged, nor a call whose two swapped
arguments are named alike. A function of the same name that the repository
declares itself with other parameters (`LatLong2LocalUTM(double Lat, double
Lon, double &x, double &y)`) has its own order: calls of that name are left
alone. So is a call on an object the app declares of another class than
CMOOSGeodesy (`Geodesy geod;` beside `geod.LatLong2LocalGrid(...)`), even where
that class's own declaration is not among the linted files (a library of the
repository elsewhere, a partial checkout).

## Why is this bad?
MOOS's local grid is East-North-Up: x is east, y is north. CMOOSGeodesy's
conversions do not mirror each other: `LatLong2LocalGrid(lat, lon,
MetersNorth, MetersEast)` gives north first, while `LocalGrid2LatLong(East,
North, lat, lon)` takes east first (core MOOS, MOOSGeodesy.h). Passing
`(lat, lon, x, y)` fills x with the northing: the vehicle is drawn and
steered reflected in the line y = x, and nothing fails.

## Example
```cpp
m_geodesy.LatLong2LocalGrid(lat, lon, nav_x, nav_y);
```

## How to fix
```cpp
m_geodesy.LatLong2LocalGrid(lat, lon, nav_y, nav_x);
```

## Options
None.
"""

from moos_lint.files.diagnostics import Severity
from moos_lint.rules.kit.declare import Kind, Scope, rule


@rule(
    code="C008",
    name="geodesy-argument-order",
    severity=Severity.WARNING,
    scope=Scope.CPP,
    kinds=(Kind.CPP,),
)
def check(ctx):
    # the C++ model is loaded only by runs that lint C++
    from moos_lint.rules.kit.cpp import cpp_findings
    from moos_lint.semantics.cpp_checks import geodesy_argument_order

    yield from cpp_findings(ctx, geodesy_argument_order)
