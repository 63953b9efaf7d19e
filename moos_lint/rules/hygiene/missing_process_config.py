"""A process launched by Antler with no ProcessConfig block.

## What it does
In a mission (a `.moos` file with an ANTLER block, after nsplug expansion, its
includes included), reports a `Run` line whose process has no
`ProcessConfig = NAME` block. `NAME` is the Run line's `~ alias` when there is
one (or `--alias=` passed through `ExtraProcessParams`), otherwise the program
name; MOOS compares it with block names without regard to case. An app linted in
the same run whose `main` passes a literal name to `Run`
(`GPSInstrument.Run("iGPS_MB1", mission)`) while CMake builds it under another
(`add_executable(iGPS ...)`) connects under that literal whatever its Run line
or alias says, and reads only the block of that name.

## Why is this bad?
The process starts on its built-in defaults. MOOS-IvP apps built on
AppCastingMOOSApp then post the configuration warning "No mission config block
found for NAME"; core MOOS apps such as pShare say nothing and silently share
nothing. (pLogger is the exception: without a block it logs every variable.)
The usual causes are a forgotten `#include plug_X.moos`, an
`#include plugs.moos <tag>` naming a section the plug file lacks, or an alias
(`~ pShare_B`) whose block was never written. When exactly one block that no
Run line starts has a name near the process's (a typo or two apart, or one
name the other with a word or number added), the finding names it: it is
probably the block meant (unlaunched-process-config, H001, reports it).

## Example
```moos
ProcessConfig = ANTLER
{
  Run = MOOSDB  @ NewConsole = false
  Run = pShare  @ NewConsole = false
}
// no "ProcessConfig = pShare" anywhere
```

## How to fix
Add the block (or the `#include` that brings it in), or fix the alias so that
it names the existing block.

## Options
- `needs-no-config` (list of strings): when given, the programs that run
  correctly without a block, instead of what the app catalogue says. They are
  compared with the program of the Run line (not its alias). By default the
  catalogue decides, from the sources: the IvP apps that declare
  `must_have_moosblock=false` at start-up (pRealm, pMissionHash, iSay,
  uLoadWatch, uMACView, uMayFinish, uQueryDB, uXMS), those that read their
  block only when there is one (uMAC, uPokeDB), or read none (uFunctionVis),
  pLogger (without a block it logs every variable), MOOSDB and the uMS scope
  (top-of-file settings only), pAntler (it reads the ANTLER block), and core MOOS's
  tools that read no mission file (the uPlayback and uIndexedPlayback GUIs, uPoke); an app
  linted in the same run needs its block unless its C++ declares it optional,
  or it is a plain CMOOSApp whose start-up compares keys with the `foo` and
  `bar` placeholders of MOOS-IvP's GenMOOSApp template and nothing else, or
  never reads its configuration at all (no mission-reader call outside a
  comment: core MOOS says nothing when its block is missing, so it runs the
  same without one);
  a user catalogue says `needs_process_config = false`. A program the
  catalogue does not know is expected to have a block. In MOOS-IvP's own
  missions none of the 109 MOOSDB Run lines and 45 of the 49 pRealm Run lines
  have a block, by design.

MOOS-IvP caveats, deliberately not reported:
- a mission with an `#include` that could not be followed (a macro in its path
  or a missing file): the block may be in that file;
- a Run name or block name holding an unexpanded `$(X)` macro (may be any name);
- a Run line with `InhibitMOOSParams = true`: pAntler does not pass the
  mission file, so the process reads no block at all;
- a process whose only block has `{` on its header line: MOOS never finds that
  block, and brace-on-header (R003) reports it;
- a script started by a Run line (`Run = ./iSonar.py`, also `.sh`, `.pl`,
  `.rb`, `.js`, `.lua`, `.jar`): it names its MOOS client and reads its
  configuration its own way, if at all;
- a renamed copy whose source moos-lint cannot see: a program neither in the
  catalogue nor in the linted C++ whose name is that of a block no Run line
  starts, a word or number longer (`Run = iRemoteMod` beside `ProcessConfig =
  iRemote`), most often still connects under the name it was copied from, and
  reads that block (unlaunched-process-config takes the block as its, too);
- an app's example configuration (`src/pCoroner/pCoroner.moos`: a file named
  after one of its blocks, with no `ServerPort` or `Community`, that no other
  file includes) whose ANTLER block does not launch that app: the block is a
  list the app itself reads (a watchdog's processes to watch), and the app is
  started with the file (`pCoroner pCoroner.moos`).
A Run line and a block in mutually exclusive `#ifdef` branches do not count as
a match: in the branch that launches the process, the block is missing.
"""

from moos_lint.files.diagnostics import Severity
from moos_lint.frontends.parsers.nodes import has_macro
from moos_lint.rules.hygiene._shared import (
    app_example,
    exclusive,
    extends_one_of,
    names_match,
    near_name,
    where,
)
from moos_lint.rules.kit.declare import Scope, rule
from moos_lint.semantics.catalogue import catalogue_for


@rule(
    code="H002",
    name="missing-process-config",
    severity=Severity.WARNING,
    scope=Scope.MISSION,
    options={"needs-no-config": None},
)
def check(ctx):
    moos = ctx.moos
    if ctx.expansion.incomplete or app_example(ctx):
        return  # (an app's example: its ANTLER block is a list the app reads)
    given = ctx.options.get("needs-no-config")
    if isinstance(given, str):
        given = [given]
    exempt = None if given is None else {str(a).lower() for a in given}
    cat = catalogue_for(ctx.run)
    # the blocks by name (a name with a macro may match any run): each Run line looks at
    # the blocks that may configure it, not at every block
    by_name: dict[str, list] = {}
    any_name: list = []
    for b in moos.blocks:
        if b.header is not None and b.name:
            if has_macro(b.name):
                any_name.append(b)
            else:
                by_name.setdefault(b.name.lower(), []).append(b)
    unread: dict | None = None  # the blocks no Run line names, by name
    unread_names: frozenset[str] = frozenset()  # (their names, lower case)
    for run in moos.runs:
        name = run.name
        if not name or has_macro(name) or has_macro(run.binary):
            continue
        if not run.has_at and "~" in run.param.value:
            continue  # not a program pAntler can start: run-alias-without-at
        program = run.program
        if exempt is not None:
            if program.lower() in exempt:
                continue
        elif cat.needs_process_config(program) is False:
            continue
        if run.inhibits_moos_params:
            continue
        if run.script_block is not None:
            continue  # a script reads its configuration its own way, if at all
        reads = cat.block_names(run)
        if any(
            names_match(b.name, n) and not exclusive(b.header, run.param.line, ctx.expansion)
            for n in reads
            for b in (*by_name.get(n.lower(), ()), *any_name)
        ):
            continue
        if reads == run.block_names:
            why = f"has no `ProcessConfig = {name}` block"
        else:
            why = (
                f"connects as `{reads[0]}` (its main passes that name to Run) and has no "
                f"`ProcessConfig = {reads[0]}` block"
            )
        unknown = cat.program_name(program) is None and cat.app(program) is None
        if unread is None:
            unread = _unread_blocks(moos, cat)
            unread_names = frozenset(b.lower() for b in unread)
        if unknown and extends_one_of(reads[0].lower(), unread_names):
            continue  # a renamed copy (iRemoteMod) most often reads the block of its original
        if unknown:
            then = (
                f": `{program}` is no MOOS-IvP or core MOOS program and no app of the linted "
                "C++ (is it installed?); if it runs, it runs on its defaults"
            )
        else:
            then = ": it runs on its defaults"
        near = near_name(reads[0], unread)
        if near is not None:
            then += (
                f"; block `{near}` ({where(unread[near].header)}), which no Run line starts, "
                "may be meant for it"
            )
        yield ctx.report(
            run.name_span,
            f"`{name}` is launched but {why}{then}",
            line=run.param.line,
        )


def _unread_blocks(moos, cat) -> dict:
    """The blocks whose name no Run line of the mission gives (the ANTLER block and names
    with a macro aside), by name as written: the first of each name."""
    launched = {n.lower() for run in moos.runs for n in cat.block_names(run)}
    if any(has_macro(n) for n in launched):
        return {}  # a Run name with a macro may read any block
    found: dict = {}
    for b in moos.blocks:
        if b.header is None or not b.name or has_macro(b.name) or b.lname == "antler":
            continue
        if b.lname not in launched:
            found.setdefault(b.name, b)
    return found
