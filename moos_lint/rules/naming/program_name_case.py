"""A Run line naming a known program in another case (`pHelmIvp` for `pHelmIvP`).

## What it does
Reports an Antler `Run` line whose program is a program the app catalogue
knows (any program MOOS-IvP and the core MOOS it ships build, by their CMake
files; an app of a catalogue file or of the linted C++) written in another
case: `Run = pHelmIvp`,
`Run = uMacView`, `Run = moosdb`. A program the project builds itself under
that exact name (an `add_executable(iBlinkstick ...)` in one of its
CMakeLists.txt files) is its own, and is left alone.

## Why is this bad?
pAntler starts each program with `execvp(name)` (MOOSEssentials
pAntler/Antler.cpp), which looks the name up on the `PATH` as written. On
macOS's default, case-insensitive file system the mission works; on Linux,
the usual system of a vehicle's computer, the launch fails ("Failed exec - not
good"), the process never runs, and the rest of the mission starts without
it. The ProcessConfig block is still found (MOOS compares block names
without regard to case), so nothing else looks wrong.

## Example
```moos
ProcessConfig = ANTLER
{
  Run = MOOSDB   @ NewConsole = false
  Run = pHelmIvp @ NewConsole = false
}
```

## How to fix
```moos
  Run = pHelmIvP @ NewConsole = false
```

## Options
None.
"""

from __future__ import annotations

import os

from moos_lint.files.diagnostics import Edit, Fix, Severity
from moos_lint.files.walk import project_walk
from moos_lint.frontends.parsers.nodes import has_macro
from moos_lint.rules.kit.declare import Kind, Scope, rule
from moos_lint.semantics.catalogue import catalogue_for


@rule(
    code="N007",
    name="program-name-case",
    severity=Severity.WARNING,
    scope=Scope.FILE,
    kinds=(Kind.MOOS,),
    fixable=True,
)
def check(ctx):
    cat = catalogue_for(ctx.run)
    for run in ctx.moos.runs:
        program = run.program
        if not program or has_macro(program) or "/" in run.binary.replace("\\", "/"):
            continue  # a path names a file, not a program looked up on the PATH
        name = cat.program_name(program)
        if name is None or name == program:
            continue
        if _built_by_project(ctx, program):
            continue
        yield ctx.report(
            run.binary_span,
            f"`{program}`: the program is `{name}`; pAntler starts it by the name "
            "written here, which a case-insensitive file system (macOS's) finds and Linux "
            "does not: there the process never starts",
            line=run.param.line,
            fix=Fix(f"respell as `{name}`", (Edit(run.binary_span, name),)),
        )


def _built_by_project(ctx, program: str) -> bool:
    """Whether a CMakeLists.txt of the project builds a program named exactly ``program``."""
    memo = ctx.run.memos.built_programs
    if program in memo:
        return memo[program]
    from moos_lint.frontends.cpp.cmake import executables_in

    found = False
    for dirpath, files in project_walk(os.path.abspath(ctx.settings.root)):
        if "CMakeLists.txt" in files and program in executables_in(dirpath):
            found = True
            break
    memo[program] = found
    return found
