"""A number written with a decimal comma (`0,514444`), which C++ reads as the comma operator.

## What it does
Reports a comma between two numbers written together, with no space, where
C++ sees the comma operator rather than two arguments or two list items:
`speed = speed * 0,514444;` or `return 0,5;`. The fix writes a decimal point.
Arguments (`f(1,2)`), initialiser lists (`{1,2}`), comma expressions with
anything but digits after the comma (`i = 0, j = 0`) or of more than two
values, and Eigen's comma initialiser (`v << 0,0;`, whose comma is Eigen's own
operator) are not reported.

## Why is this bad?
A decimal comma is how much of the world writes decimals, and C++ accepts it
without a word: `speed = speed * 0,514444;` is `(speed = speed * 0), 514444;`.
The speed becomes 0 and the conversion factor is thrown away. Without
`-Wall` no compiler warns, and the published value (here a NAV_SPEED of 0)
looks like a vehicle at rest.

## Example
```cpp
if(unit == "N")
  dbl_speed = dbl_speed * 0,514444;   // knots to m/s
Notify("WIND_SPEED", dbl_speed);
```

## How to fix
```cpp
if(unit == "N")
  dbl_speed = dbl_speed * 0.514444;   // knots to m/s
Notify("WIND_SPEED", dbl_speed);
```

## Options
None.
"""

from moos_lint.files.diagnostics import Severity
from moos_lint.rules.kit.declare import Kind, Scope, rule


@rule(
    code="C011",
    name="decimal-comma",
    severity=Severity.WARNING,
    scope=Scope.CPP,
    kinds=(Kind.CPP,),
    fixable=True,
)
def check(ctx):
    # the C++ model is loaded only by runs that lint C++
    from moos_lint.rules.kit.cpp import cpp_findings
    from moos_lint.semantics.cpp_checks import decimal_comma

    yield from cpp_findings(ctx, decimal_comma)
