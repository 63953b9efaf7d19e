"""A vector published with its vertical and a horizontal axis exchanged.

## What it does
Reports three publications that make one vector, `<NAME>_X`, `<NAME>_Y` and
`<NAME>_Z`, each taken from one component of the same C++ vector (`dvl.x`,
`vel->y`, `v.z()`, `acc[2]`, negated or not), when the vertical is taken
from a horizontal component and the exchange is a mirror image: an odd
number of axes exchanged and signs changed together (`DVL_VEL_Y = dvl.z`,
`DVL_VEL_Z = dvl.y`, no sign changed).

Not reported: a rotation (the same exchange with one sign changed is a
sensor mounted on its side), an exchange of the two horizontal axes only (NED
to ENU swaps north and east), and vectors whose three components are not all
published from one source.

## Why is this bad?
Every frame a marine vehicle uses (ENU, NED, the body's forward-right-down
and forward-left-up) is right-handed, and every sensor mounting is a
rotation: it may send the sensor's z to the vehicle's y, but then with a sign
change somewhere. An exchange with no sign change mirrors the vector: a
DVL's vertical velocity published as its sideways one makes a vehicle that
dives look as if it slides to starboard, and navigation fed with it drifts.

## Example
```cpp
Notify("DVL_VEL_X", dvl.x);
Notify("DVL_VEL_Y", dvl.z);
Notify("DVL_VEL_Z", dvl.y);
```

## How to fix
```cpp
Notify("DVL_VEL_X", dvl.x);
Notify("DVL_VEL_Y", dvl.y);
Notify("DVL_VEL_Z", dvl.z);
```

## Options
None.
"""

from moos_lint.files.diagnostics import Severity
from moos_lint.rules.kit.declare import Kind, Scope, rule


@rule(
    code="C013",
    name="mirrored-axes",
    severity=Severity.WARNING,
    scope=Scope.CPP,
    kinds=(Kind.CPP,),
)
def check(ctx):
    # the C++ model is loaded only by runs that lint C++
    from moos_lint.rules.kit.cpp import cpp_findings
    from moos_lint.semantics.cpp_checks import mirrored_axes

    yield from cpp_findings(ctx, mirrored_axes)
