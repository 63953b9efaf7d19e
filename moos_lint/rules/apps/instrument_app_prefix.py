"""A class derived from CMOOSInstrument whose process is not `i`-prefixed.

## What it does
Reports a C++ app class that derives (directly or through classes of the
linted code) from `CMOOSInstrument` or `AppCastingMOOSInstrument` when the
app's process name does not start with `i`. The process name is the literal
given to `App.Run("name", ...)` in `main`, else the CMake
`add_executable(name ...)` of the app's folder (of a folder that builds
several programs, the one whose source list holds the app class's files), else
the folder name. A name in capitals with an underscore (`MOOSAPPFACTORY_NAME`)
is the placeholder of a template an app generator copies, and is not judged.

## Why is this bad?
`CMOOSInstrument` is the base for apps that talk to hardware (it brings the
serial-port setup). The MOOS conventions name instruments with an `i` prefix,
so that a mission's Antler block says which processes touch the vehicle's
devices.

## Example
```cpp
class GPSReader : public CMOOSInstrument { ... };
// CMakeLists.txt: add_executable(pGPS ...)
```

## How to fix
Name the process `iGPS` (in `add_executable` and in the missions' Antler
blocks), or derive from `CMOOSApp` if the app does not use a device.

## Options
None.
"""

from moos_lint.files.diagnostics import Severity
from moos_lint.rules.kit.declare import Kind, Scope, rule


@rule(
    code="C002",
    name="instrument-app-prefix",
    severity=Severity.WARNING,
    scope=Scope.CPP,
    kinds=(Kind.CPP,),
)
def check(ctx):
    # the C++ model is loaded only by runs that lint C++
    from moos_lint.rules.kit.cpp import cpp_findings
    from moos_lint.semantics.cpp_checks import instrument_app_prefix

    yield from cpp_findings(ctx, instrument_app_prefix)
