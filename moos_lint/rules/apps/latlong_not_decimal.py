"""Latitude or longitude published as an NMEA sentence writes it (ddmm.mmmm).

## What it does
Reports `Notify` of a variable whose last word is `LAT`, `LON`, `LONG`,
`LATITUDE` or `LONGITUDE` with a number parsed from an NMEA 0183 position
sentence (GGA, RMC, GLL, and Clearpath's front-seat `$CPNVG`, which writes
its position the same way) with `atof`, `strtod` or `std::stod`, where the code
handles that sentence (an `if` on its name, or a function named for it:
`handleGPGGA`), and nothing done to the number on its way to the publication
but its sign (the hemisphere). A value the code divides, adds minutes to or
converts in a function of its own is not reported, nor a field of another
sentence (a device's own sentence may give decimal degrees).

The value comes from moos-lint's value analysis of C++, which follows it
through locals, members and functions (README, "C++ apps"). The finding says
why, as a chain; what the analysis cannot know is never reported.

## Why is this bad?
NMEA writes a latitude as degrees and minutes run together, `ddmm.mmmm`
(`4916.45` is 49°16.45′, that is 49.274167°), and a longitude as
`dddmm.mmmm`. MOOS and MOOS-IvP carry positions as decimal degrees
(`NAV_LAT`, `NAV_LONG`, `LatOrigin`, `LongOrigin`): read as they are written,
the numbers are far outside any latitude, the geodesy's local grid puts the
vehicle thousands of kilometres away, and nothing fails.

## Example
```cpp
if(fields[0] == "$GPGGA") {
  double lat = atof(fields[2].c_str());
  if(fields[3] == "S")
    lat = -lat;
  Notify("GPS_LAT", lat);
}
```

## How to fix
```cpp
if(fields[0] == "$GPGGA") {
  double raw = atof(fields[2].c_str());
  double lat = floor(raw / 100) + fmod(raw, 100) / 60;
  if(fields[3] == "S")
    lat = -lat;
  Notify("GPS_LAT", lat);
}
```

## Options
None.
"""

from moos_lint.files.diagnostics import Severity
from moos_lint.rules.kit.declare import Kind, Scope, rule


@rule(
    code="C018",
    name="latlong-not-decimal",
    severity=Severity.WARNING,
    scope=Scope.CPP,
    kinds=(Kind.CPP,),
)
def check(ctx):
    # the C++ model is loaded only by runs that lint C++
    from moos_lint.rules.kit.cpp import cpp_findings
    from moos_lint.semantics.cpp_checks import latlong_not_decimal

    yield from cpp_findings(ctx, latlong_not_decimal)
