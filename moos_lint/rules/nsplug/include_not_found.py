"""An `#include` whose file cannot be found or read.

## What it does
Reports an nsplug `#include` of a file that does not exist in any of the
folders nsplug searches, or that cannot be read.

moos-lint searches where nsplug does: the folder nsplug runs in (taken to be
the top-level file's folder), then each `--include-path` folder (nsplug's
`--path`), then the including file's folder, then the folders that the
launch scripts beside the top-level file (`*.sh`, read as text, never run)
hand nsplug with `--path=DIR` or `-p DIR`, then the folder above when a
launch script there runs nsplug on the template from outside its folder
(`nsplug bhvs/meta_heron.bhv targ_heron.bhv`: nsplug runs, and looks for
`#include bhvs/plug_return.bhv`, in the mission folder). A file that a
launch script beside the top-level file writes before it runs nsplug
(`cat > plug_pShare.moos <<EOF`), or that a clean script deletes, is made at
launch: its absence is not reported; so is one the repository's `.gitignore`
keeps out of git (`plug_SENSOR*`): a build step writes it, in whatever
language (a mission generator), and it is never committed. When one of those folders holds the
file under the same name in another case (`plug_v1_origin.moos` for
`#include plug_V1_origin.moos`), the message says so: the mission then works
on a case-insensitive file system (macOS's default) and fails on Linux. A
`// comment` behind the path is part of it for nsplug (Expander.cpp reads the
rest of the line as the path, an `<tag>` aside), and the message says so.

An absolute path outside the top-level file's folder that does not exist here
(`#include /home/student/VehicleConfig/plug_iGPS.moos`) is not reported: it
names a file of the machine the mission runs on (the vehicle's own
configuration), which the machine that lints need not have. The mission is
then taken as incomplete, as for a macro in the path.

Like every nsplug rule, it leaves alone a `.bhv` file in which no line, as
written, is shaped like a behavior file's (a `Behavior` header, `initialize`,
`set`, a brace or `key = value`): nsplug's own test inputs and notes on its
directives (MOOS-IvP's `app_nsplug/testcases/meta_vehicle.bhv`), which no
helm loads.

## Why is this bad?
nsplug stops with an error and writes no mission file, so the launch script
fails; with `--force` in a script the old generated file is used instead.
Includes whose path still holds an unknown `$(MACRO)` are skipped, not
reported.

## Example
```moos
#include plug_origin_warp.moos   // the file is plugs/plug_origin_warp.moos
```

## How to fix
Fix the path, or pass the folder with `--include-path` (config:
`include-paths`) as the launch script passes it to nsplug with `--path`.

## Options
None.
"""

from moos_lint.files.diagnostics import Severity
from moos_lint.rules.kit.declare import Kind, Scope, rule
from moos_lint.rules.nsplug._problems import problem_findings


@rule(
    code="P001",
    name="include-not-found",
    severity=Severity.ERROR,
    scope=Scope.FILE,
    kinds=(Kind.MOOS, Kind.BHV),
)
def check(ctx):
    yield from problem_findings(ctx, "include-not-found")
