"""A radian angle outside [-π, π].

## What it does
Reports a literal value given to a radian angle field (a name ending in the
word `YAW`, `PITCH`, `ROLL` or `RADIANS`, see `yaw-in-degrees` for
where values are found) whose magnitude is larger than π but not larger than
2π. Larger values look like degrees and are left to `yaw-in-degrees` and
`angle-in-degrees`. A fix replaces the literal with the wrapped value,
rounded to 4 decimals.


In C++, it reports a yaw, pitch or roll published in radians whose range is
known not to be ±π: a heading in [0, 360) turned into a yaw
(`-heading*M_PI/180` without `angle180`), a yaw shifted by π, a one-sided
wrap (`if (yaw < 0) yaw += 2*M_PI`) or `fmod(yaw, 2*M_PI)` into [0, 2π).
Wraps are read from `MOOS_ANGLE_WRAP`, `radAngleWrap`, `angle180`, wrap
loops and `if`s, and `fmod`. A one-sided wrap by one full turn is read even
when the value's range before it is unknown (a device's struct field): the
author takes the value to lie in the turn the `if` names (`if (yaw < 0) yaw
= yaw + 2*M_PI`: [0, 2π)), and a turn of 2π says radians; so does `fmod` by
a turn, which keeps the sign of what it divides (in `if (psi < 0) out =
fmod(psi, 2*M_PI) + 2*M_PI; else out = fmod(psi, 2*M_PI);` both branches
land in [0, 2π)).
In a branch of an `if` that compares the value with a constant, the value
lies on that side of it: `if (y > M_PI) out = y - 2*M_PI; else out = y;`
wraps `y` into `out`.

The value comes from moos-lint's value analysis of C++, which follows it
through locals, members, functions anywhere in the repository and struct fields
(README, "C++ apps"). The finding says why, as a chain; what the analysis
cannot know is never reported.

## Why is this bad?
The MOOS Conventions wrap every angle to ±π, and the code that reads these
variables assumes it: a yaw of `4.71` and one of `-1.57` are the same
direction, but comparisons, differences and averages between an unwrapped
and a wrapped value are off by a full turn. It can also be a degree value
that happens to be small (`5` meaning 5°).

Deliberately not reported:
- heading fields, which MOOS-IvP keeps in degrees, [0, 360);
- a rounded π such as `3.1416` (values within 0.001 of ±π count as wrapped);
- pMarinePID's `maxpitch`, a configuration key in degrees;
- values that are not one plain number (`$(MACRO)`, `$[MACRO]`, strings).

## Example
```moos
ProcessConfig = uTimerScript
{
  event = var=NAV_YAW, val=4.71, time=10
}
```

## How to fix
Wrap the angle to ±π:
```moos
  event = var=NAV_YAW, val=-1.5732, time=10
```

## Options
None.
"""

import math

from moos_lint.files.diagnostics import Severity
from moos_lint.rules.kit.declare import Kind, Scope, rule
from moos_lint.semantics.angles import WRAP_TOLERANCE, angle_values, format_rad, wrap_pi


@rule(
    code="U002",
    name="angle-not-wrapped",
    severity=Severity.WARNING,
    scope=Scope.FILE,
    kinds=(Kind.MOOS, Kind.BHV, Kind.CPP),
    fixable=True,
)
def check(ctx):
    if ctx.unit.kind is Kind.CPP:
        yield from cpp_check(ctx)
        return
    for av in angle_values(ctx):
        mag = abs(av.value)
        if not (math.pi + WRAP_TOLERANCE < mag <= 2 * math.pi):
            continue
        new = format_rad(wrap_pi(av.value))
        yield ctx.report(
            av.span,
            f"`{av.name}` = {av.literal} is outside [-π, π]: MOOS wraps radian angles "
            f"to ±π; wrapped it is {new} (or is it in degrees?)",
            line=av.line,
            fix=av.fix(new, f"wrap the angle to ±π: {new}"),
        )


def cpp_check(ctx):
    """The C++ check, on the app model (see :mod:`moos_lint.semantics.cpp_checks`)."""
    from moos_lint.rules.kit.cpp import cpp_findings
    from moos_lint.semantics.cpp_checks import angle_not_wrapped

    yield from cpp_findings(ctx, angle_not_wrapped)
