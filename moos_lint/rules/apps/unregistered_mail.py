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
at run time (`Register(m_prefix + "_X")`, `Register(m_vars[i])`), no base class
in another folder, and no comms client (or the app itself) handed to
other code that could register. Beside a registration the configuration may
rename (`Register(m_heading_var)`, set from a key), a name tested as a literal
may be what the configuration gives: only names the app holds itself (a member
set to a literal, a constant) are judged there.

Left alone as well: a handler whose registration is commented out or under
`#if 0` (taken out on purpose); a test that is one alternative of an `||` whose
other name is registered (`key == "USM_FORCE_X" || key == "CURRENT_X"`: the
branch runs on the new name); a branch that does nothing (`{}`: the mail is
ignored); a `!=` test (the template's catch-all `else if(key != "APPCAST_REQ")`,
whose branch runs on every other name), unless its name is a near spelling of
one the app receives and no `==` test takes (`key != "APPCASE_REQ"`): the name
it meant to pass over then runs the branch (an "Unhandled Mail" warning on every
`APPCAST_REQ`), and that is reported; the app templates' placeholders
(`if(key == "FOO")`, `FOOBAR`). A key
that is only a `key=value` pair parsed from a message's text is not a message
name. A wildcard registration (`Register("POWER_*", "*", 0)`) covers the names
it matches. When a registered name is a near spelling of the handled one (`NAX_X` for
`NAV_X`), the finding names it.

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

    yield from cpp_findings(ctx, unregistered_mail, near=_near)


def _near(name: str, registered: list[str]) -> str | None:
    """The registered name ``name`` is a typo from (two for names of six letters or more),
    when only one is."""
    from moos_lint.rules.kit.spelling import misspelling_of

    return misspelling_of(name, registered, 1 if len(name) < 6 else 2)
