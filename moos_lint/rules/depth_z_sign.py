"""A Z variable published from a depth without negation.

## What it does
Reports `Notify` of a variable whose last word is `Z` (`NAV_Z`, `GPS_Z`) when
the value is a depth as is: a variable, member or getter whose name says
depth (`depth`, `m_depth`, `record.getDepth()`), followed through local
variables, with no minus sign.

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

from moos_lint.declare import Kind, Scope, rule
from moos_lint.diagnostics import Severity


@rule(
    code="C005",
    name="depth-z-sign",
    severity=Severity.WARNING,
    scope=Scope.CPP,
    kinds=(Kind.CPP,),
)
def check(ctx):
    # the C++ model is loaded only by runs that lint C++
    from moos_lint.cpp.checks import depth_z_sign
    from moos_lint.cpp.rulekit import cpp_findings

    yield from cpp_findings(ctx, depth_z_sign)
