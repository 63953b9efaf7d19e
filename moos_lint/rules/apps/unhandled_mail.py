"""A variable the app registers for but its OnNewMail never handles.

## What it does
Reports a literal variable name passed to `Register` when the app's
`OnNewMail` dispatches on literal keys (`key == "X"`, `MOOSStrCmp(key, "X")`,
`msg.IsName("X")`, `m_Comms.PeekMail(NewMail, "X", msg)`, prefix tests like
`strBegins(key, "X_")`) and none of them
matches that name. A key compared with a name held elsewhere counts as that
name when it can be read: a `#define` or constant, a member set to a literal
(`m_visit_var = "VISIT_POINT"`). A name that cannot be read (a
collaborator's, `m_collab + "_NAV_X"`, given at run time) handles no literal
registration: `Register("COLLABORATOR_NAV_X")` beside such a test is a
literal written where the collaborator's name was meant.
A dynamic variable's subscription (`AddMOOSVariable(name, "X", ...)` with
`RegisterMOOSVariables()`) counts as a registration; passing the mail to
`UpdateMOOSVariables(NewMail)` handles it.
Wildcard registrations, names built at run time and names the app
publishes itself (registered to watch its own posts), or may publish under a
name it builds (`ss << "VISIT_POINT_" << m_vname; Notify(ss.str(), ...)`
beside `Register("VISIT_POINT_GILDA")`), are not reported, nor
are apps whose OnNewMail hands whole messages to code the linter does not
follow (`handleMail(msg)` outside any key test).

## Why is this bad?
Each registration makes the MOOSDB send every change of the variable to the
app. Mail that OnNewMail never looks at is dropped: either the handler was
forgotten (the usual case: the name in `Register` and in OnNewMail differ by a
typo), or the registration is dead and only costs bandwidth.

## Example
```cpp
Register("DEPLOY", 0);
Register("RETURN", 0);
...
if(key == "DEPLOY") handleDeploy(msg);   // RETURN is never handled
```

## How to fix
Handle the variable in OnNewMail, fix the name that differs, or remove the
registration.

## Options
None.
"""

from moos_lint.files.diagnostics import Severity
from moos_lint.rules.kit.declare import Kind, Scope, rule


@rule(
    code="C007",
    name="unhandled-mail",
    severity=Severity.WARNING,
    scope=Scope.CPP,
    kinds=(Kind.CPP,),
)
def check(ctx):
    # the C++ model is loaded only by runs that lint C++
    from moos_lint.rules.kit.cpp import cpp_findings
    from moos_lint.semantics.cpp_checks import unhandled_mail

    yield from cpp_findings(ctx, unhandled_mail)
