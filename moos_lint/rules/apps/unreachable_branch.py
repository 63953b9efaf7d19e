"""An `else if` that tests for a name an earlier branch of the same chain already takes.

## What it does
Reports a branch of an `if` / `else if` chain whose test repeats a test of an
earlier branch of the chain: `else if(key == "NAV_HEADING")` after
`if(key == "NAV_HEADING")` in OnNewMail, `else if(param == "max_rudder")` after
`if(param == "max_rudder")` in OnStartUp. A test is a comparison of a name with a
string literal: `x == "NAME"`, `msg.IsName("NAME")` or `MOOSStrCmp(x, "NAME")`
(which ignores case, so it also takes a later `x == "name"`).

The later branch is reported when it cannot run: its test is one an earlier
branch took, or a `&&` with such a test as one side
(`(key == "NAV_X") && !m_enabled`), or an `||` of only such tests. An earlier
branch with `&&` in its test takes nothing (`(param == "range") && (value ==
"nolimit")` leaves `param == "range"` to the next branch). Separate `if`
statements (no `else`) both run and are not reported; nor are code under `#if 0`,
tests of anything that could change between the two tests (a call other than
`GetKey()`, `GetString()`, `c_str()`, `tolower()`, `toupper()` and the like; a name
a test between them assigns or hands to a call, as `biteStringX(sval, ',')` bites
`sval`), or an `||` with one alternative still free.

## Why is this bad?
OnNewMail and OnStartUp are long chains of name tests, grown by copy and paste.
When a name is tested twice, the first branch takes every message or parameter
of that name and the second never runs. The code in it looks like it handles
the name (a second sensor report, a new configuration parameter that replaced
an old one) and it is silently dead: the app behaves as if it were not there,
and no compiler warns.

## Example
```cpp
else if(param == "max_rudder")
  handled = setDoubleOnString(m_max_rudder, value);
else if(param == "max_thrust")
  handled = setDoubleOnString(m_max_thrust, value);
else if(param == "max_rudder")          // never runs
  handled = setDoubleOnString(m_max_rudder_rate, value);
```

## How to fix
Give the later branch the name it was meant for (`"max_rudder_rate"`), merge its
code into the earlier branch, or delete it.

## Options
None.
"""

from moos_lint.files.diagnostics import Severity
from moos_lint.rules.kit.declare import Kind, Scope, rule


@rule(
    code="C016",
    name="unreachable-branch",
    severity=Severity.WARNING,
    scope=Scope.CPP,
    kinds=(Kind.CPP,),
)
def check(ctx):
    # the C++ model is loaded only by runs that lint C++
    from moos_lint.rules.kit.cpp import cpp_findings
    from moos_lint.semantics.cpp_checks import unreachable_branch

    yield from cpp_findings(ctx, unreachable_branch)
