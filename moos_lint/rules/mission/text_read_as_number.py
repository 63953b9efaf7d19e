"""Text posted to a variable that an app of the repository reads as a number.

## What it does
In a mission (after nsplug expansion, with its behavior files), reports a line
that posts a word to a variable (a behavior's flag `endflag =
RESET_ODOMETRY=true`, an `initialize`, a pMarineViewer button or action, a
uTimerScript event's `val=`) when a launched app whose C++ is in the linted
repository reads that variable only as a number: every branch of its
`OnNewMail` that reads the value calls `msg.GetDouble()` (or uses a local set
from it, `double dval = msg.GetDouble();`) and none reads it as text
(`GetString()`), asks its type (`IsDouble()`, `IsString()`) or hands the
message on to another function.

Words are values MOOS-IvP posts as text: anything `isNumber` rejects (`true`,
`on`, `2m`); numbers, nsplug macros and run-time placeholders are left alone,
and so are apps known only from the catalogue (MOOS-IvP's own apps read their
mail by its type).

## Why is this bad?
A MOOS message holds a number or a text. The helm, pMarineViewer and
uTimerScript post `true` as the text "true", and core MOOS's `CMOOSMsg` gives
a text message's `GetDouble()` as -1, whatever the text says: the app reads
`RESET_ODOMETRY=true` and `RESET_ODOMETRY=false` alike, as -1 (true in a
`bool`, never equal to 1), and nothing fails or warns.

## Example
```cpp
else if(key == "RESET_ODOMETRY") {
  bool reset = msg.GetDouble();      // -1 for "true" and for "false"
  if(reset)
    m_total_distance = 0;
}
```
```bhv
Behavior = BHV_Waypoint
{
  endflag = RESET_ODOMETRY = true
}
```

## How to fix
Post a number (`endflag = RESET_ODOMETRY = 1`), or read the text in the app:
```cpp
else if(key == "RESET_ODOMETRY") {
  bool reset = false;
  if(setBooleanOnString(reset, msg.GetString()) && reset)
    m_total_distance = 0;
}
```

## Options
None.
"""

from __future__ import annotations

from moos_lint.files.diagnostics import Severity, Subject
from moos_lint.rules.kit.declare import Kind, Scope, rule
from moos_lint.rules.mission._posted import value_after
from moos_lint.semantics.mbutil import is_number
from moos_lint.semantics.mission_model import mission_model
from moos_lint.semantics.variables import PUBLISH


@rule(
    code="M012",
    name="text-read-as-number",
    severity=Severity.WARNING,
    scope=Scope.MISSION,
    kinds=(Kind.MOOS,),
)
def check(ctx):
    model = mission_model(ctx)
    readers: dict[str, tuple[str, str]] = {}
    for proc in model.processes:
        app = proc.app
        if app is None or not app.own:
            continue
        for var, where in app.reads_number.items():
            readers.setdefault(var, (proc.name, where))
    if not readers:
        return
    for ref in model.refs:
        if ref.role != PUBLISH or ref.name not in readers:
            continue
        value = value_after(ref)
        if value is None or is_number(value):
            continue
        process, where = readers[ref.name]
        yield ctx.report(
            ref.span,
            f"`{ref.name}={value}` posts text ({ref.app}: {ref.param}), but `{process}` reads "
            f"`{ref.name}` only as a number (the branch at {where} reads it with "
            "GetDouble()), which is -1 for any text, so `true` and `false` read alike: post a "
            "number, or read it with GetString()",
            line=ref.line,
            subject=Subject(variable=ref.name, app=ref.app, key=ref.param),
        )
