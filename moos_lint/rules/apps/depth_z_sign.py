"""A Z variable published from a depth without negation.

## What it does
Reports `Notify` of a variable whose last word is `Z` (`NAV_Z`, `GPS_Z`) when
the value is positive down without a minus sign: a depth (`m_depth`,
`record.getDepth()`, `NAV_DEPTH` read by mail) or the z of a NED frame
(`m_ned.z`); and of a variable whose last word is `DEPTH` published from
`NAV_Z` as is. A frame used inside the process is free: only what is
published counts, with one exception that is a sign error in any frame: a
NED z (positive down: a field named so, `m_ned_down`, or the `z` of a NED
type, `mavlink_set_position_target_local_ned_t sp; sp.z`) set from `NAV_Z`
(positive up) without negation.

The value is read by moos-lint's value analysis of C++ (unit, sense, range
and sign): the conversion helpers of MOOS and MOOS-IvP, `π/180` arithmetic,
inverse trigonometry, wraps, the variables read by mail, NMEA fields, and
names and comments that state a unit, followed through locals, members set in
any method, functions anywhere in the repository (a library getter) and the
fields of structs that the repository's code writes (also C files);
another app of the repository that converts the variable from degrees on
arrival counts as evidence too. The finding says why, as a chain. What the
analysis cannot know is never reported. With `--cpp-backend clang` and a
compile database, the same analysis reads the code as compiled (a conversion
inside an `#ifdef` the build leaves out does not count), folds the constants
only the compiler sees (a `const` or `constexpr` variable or an enum value in
another folder's header, a macro from a header or a `-D` flag, named in the
chain with where it is defined), and judges numbers only: a published string
or bool is never an angle.

## Why is this bad?
In the MOOS frame Z points up: a vehicle 10 m below the surface has
`NAV_Z = -10` and `NAV_DEPTH = 10`. uSimMarine publishes `NAV_Z` as
`-depth`; an app publishing the depth as Z puts the vehicle above the water
for every consumer of NAV_Z.

## Example
```cpp
Notify("NAV_Z", m_depth);
```

## How to fix
```cpp
Notify("NAV_Z", -m_depth);
```

## Options
None.
"""

from moos_lint.files.diagnostics import Severity
from moos_lint.rules.kit.declare import Kind, Scope, rule


@rule(
    code="C005",
    name="depth-z-sign",
    severity=Severity.WARNING,
    scope=Scope.CPP,
    kinds=(Kind.CPP,),
)
def check(ctx):
    # the C++ model is loaded only by runs that lint C++
    from moos_lint.rules.kit.cpp import cpp_findings
    from moos_lint.semantics.cpp_checks import depth_z_sign

    yield from cpp_findings(ctx, depth_z_sign)
