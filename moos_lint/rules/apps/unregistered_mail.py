"""A variable the app's OnNewMail handles but the app never registers for.

## What it does
Reports a name OnNewMail compares the message's own name with (`key == "X"` of
`string key = msg.GetKey()`, `MOOSStrCmp(msg.GetKey(), "X")`, `msg.IsName("X")`,
`PeekMail(NewMail, "X", msg)`, or a `#define` or constant holding the name) when no
`Register` of the app names it. Registrations the app makes through a dynamic
variable (`AddMOOSVariable`) count. Mail that comes unasked is not reported:
`APPCAST_REQ`, which AppCasting's base class registers for every app, and
`_async_timing`, which MOOS's asynchronous comms client puts in the mail itself.

Only apps whose registrations can all be read are judged: none with a name made
at run time (`Register(m_prefix + "_X")`, names from the configuration or a list),
no wildcard, no base class in another folder, and no comms client (or the app
itself) handed to other code that could register. A registration commented out
or under `#if 0` was taken out on purpose: its handler is left alone, and so is
the app templates' placeholders (`if(key == "FOO")`, `FOOBAR`). A key that is only a
`key=value` pair parsed from a message's text is not a message name.

## Why is this bad?
The MOOSDB sends an app only the variables it registered for. A handler for a
name the app never registers for never runs: the app silently ignores the
variable its author meant it to react to (a `DEPLOY`, a `HOLD_TOLERANCE`, a
sensor report), and nothing in the mission says so.

## Example
```cpp
bool Keeper::OnNewMail(MOOSMSG_LIST &NewMail)
{
  ...
    std::string key = msg.GetKey();
    if(key == "HOLD_POINT")
      setHoldPoint(msg.GetString());
    else if(key == "HOLD_TOLERANCE")     // never registered: never arrives
      m_tolerance = msg.GetDouble();
  ...
}

void Keeper::registerVariables()
{
  AppCastingMOOSApp::RegisterVariables();
  Register("HOLD_POINT", 0);
}
```

## How to fix
Register for the variable (`Register("HOLD_TOLERANCE", 0);`), fix the name that
differs, or remove the dead handler.

## Options
None.
"""

from moos_lint.files.diagnostics import Severity
from moos_lint.rules.kit.declare import Kind, Scope, rule


@rule(
    code="C015",
    name="unregistered-mail",
    severity=Severity.WARNING,
    scope=Scope.CPP,
    kinds=(Kind.CPP,),
)
def check(ctx):
    # the C++ model is loaded only by runs that lint C++
    from moos_lint.rules.kit.cpp import cpp_findings
    from moos_lint.semantics.cpp_checks import unregistered_mail

    yield from cpp_findings(ctx, unregistered_mail)
