"""A speed published in knots, km/h or miles an hour.

## What it does
Reports `Notify` of a speed (a variable whose last word is `SPEED`, `SOG` or
`STW`: `NAV_SPEED`, `GPS_SPEED`, `DESIRED_SPEED`) whose value is in knots, km/h
or miles an hour with no conversion to metres per second:

- a field of an NMEA 0183 speed sentence parsed with `atof`/`stod`, where the
  code handles that one sentence (an `if` on `$GPRMC`, or a function named for
  it, `handleGPRMC`): RMC's speed over ground is knots, VTG's and VHW's fields
  5 and 7 knots and km/h;
- a value whose name gives its unit (`dbl_kts`, `speedKnots`, `sog_kn`,
  `speed_kmh`, `mph`);
- a conversion to knots or miles an hour (`nav_speed * 1.94384`).

Multiplying by the conversion factor (`* 0.514444`, `/ 1.94384`, `/ 3.6`,
`* 0.44704`) gives metres per second; any other factor leaves the unit unknown,
and nothing unknown is reported. A variable whose own name gives another unit
(`SPEED_KNOTS`) is left to non-si-unit.

The value comes from moos-lint's value analysis of C++, which follows it
through locals, members, functions anywhere in the repository and struct fields
(README, "C++ apps"). The finding says why, as a chain.

## Why is this bad?
MOOS speeds are metres per second (the MOOS conventions: SI units). The helm's
DESIRED_SPEED, uSimMarine's NAV_SPEED and every behavior's speed are m/s; a GPS
speed of 4 knots published as it comes reads as 4 m/s, almost twice as fast:
odometry, waypoint arrival times and the speed a vehicle reports to its
collision-avoidance peers are all off.

## Example
```cpp
if(flds[0] == "$GPRMC") {
  double sog = atof(flds[7].c_str());
  Notify("GPS_SPEED", sog);
}
```

## How to fix
```cpp
if(flds[0] == "$GPRMC") {
  double sog = atof(flds[7].c_str()) * 0.514444;   // knots to m/s
  Notify("GPS_SPEED", sog);
}
```

## Options
None.
"""

from moos_lint.files.diagnostics import Severity
from moos_lint.rules.kit.declare import Kind, Scope, rule


@rule(
    code="C010",
    name="speed-in-knots",
    severity=Severity.WARNING,
    scope=Scope.CPP,
    kinds=(Kind.CPP,),
)
def check(ctx):
    # the C++ model is loaded only by runs that lint C++
    from moos_lint.rules.kit.cpp import cpp_findings
    from moos_lint.semantics.cpp_checks import speed_in_knots

    yield from cpp_findings(ctx, speed_in_knots)
