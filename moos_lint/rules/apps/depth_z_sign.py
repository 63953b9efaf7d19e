"""A Z variable published from a depth without negation.

## What it does
Reports `Notify` of a variable whose last word is `Z` (`NAV_Z`, `GPS_Z`) when
the value is positive down without a minus sign: a depth (`m_depth`,
`record.getDepth()`, `NAV_DEPTH` read by mail, a local named a depth and set
from a sum whose sign nothing else gives, `double depth = (p - p0) / (rho *
g)`) or the z of a NED frame
(`m_ned.z`); and of a variable whose last word is `DEPTH` published from
`NAV_Z` as is. A frame used inside the process is free: only what is
published counts, with one exception that is a sign error in any frame: a
NED z (positive down: a field named so, `m_ned_down`, or the `z` of a NED
type, `mavlink_set_position_target_local_ned_t sp; sp.z`) set from `NAV_Z`
(positive up) without negation.

A variable of the repository's own is left alone: one that an app of the
repository subscribes to and that no MOOS-IvP app or behavior publishes or
reads (a project's `VVV_Z`, kept positive down for its own depth
controller). Its readers were written with its publisher, so they, not the
MOOS frame, give its sense; negating the publication alone would invert them.
A Z that MOOS-IvP's apps know (`NAV_Z`), or one that nothing in the
repository reads, is judged.

The value comes from moos-lint's value analysis of C++, which follows it
through locals, members, functions anywhere in the repository and struct fields
(README, "C++ apps"). The finding says why, as a chain; what the analysis
cannot know is never reported.

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
    from moos_lint.semantics.catalogue import catalogue_for
    from moos_lint.semantics.cpp_checks import depth_z_sign

    cat = catalogue_for(ctx.run)
    me = ctx.unit.cpp.process_name if ctx.unit.cpp is not None else None

    def own(var: str) -> bool:
        return cat.project_variable(var, me or "")

    yield from cpp_findings(ctx, depth_z_sign, own=own)
