"""A ProcessConfig block for a process that no Run line launches.

## What it does
In a mission (a `.moos` file with an ANTLER block, after nsplug expansion, its
includes included), reports a `ProcessConfig = NAME` block when no `Run` line
of the ANTLER block starts a process called `NAME`. The process name is the
`~ alias` of the Run line when there is one (or `--alias=` passed through
`ExtraProcessParams`), otherwise the program name; an app linted in the same
run whose `main` passes a literal name to `Run` (`Run("iGPS_MB1", mission)`)
while CMake builds it under another (`add_executable(iGPS ...)`) reads only
the block of that literal, whatever its Run line says, and the message says
so. Names compare without regard to case, as MOOS looks blocks up. A plug fragment is judged in the
missions that include it; the finding points at the block in the fragment,
with the include chain.

## Why is this bad?
No process ever reads the block: edits to it have no effect, and readers of
the mission believe the process runs. Often the block's name and the Run
line's name differ (a block written for `iGPS` while `iGPS_KF` is launched,
a Run line naming the plug file `uProcessWatch_fld` instead of the program):
then the launched process runs without its configuration too, and
missing-process-config (H002) reports its Run line. When exactly one launched
process without a block of its own has a name near the block's (a typo or two
apart, or the block's name with a word or number added: `uFldHazardMgrX`),
the finding names it, and H002's finding names the block.

## Example
```moos
ProcessConfig = ANTLER
{
  Run = MOOSDB   @ NewConsole = false
  Run = iGPS_KF  @ NewConsole = false
}

ProcessConfig = iGPS
{
  port = /dev/ttyUSB0
}
```

## How to fix
Launch the process, give the block the launched name, or delete the block.
To keep a block around for a process started by hand, declare the app
`launched_manually = true` in a catalogue file, list it in `manual-apps`, or
suppress the finding on the header line.

## Options
- `manual-apps` (list of strings): when given, the tools that users start by
  hand with the mission file (`uXMS targ_shoreside.moos`), instead of what the
  app catalogue says; their block is read although no Run line starts them.
  By default the catalogue decides: uXMS, uMAC, uMACView, uPokeDB, uQueryDB,
  uMayFinish, uTermCommand, uHelmScope and uCommand (each documents
  `Usage: APP file.moos`), the uMS scope, core MOOS's keyboard remote control
  iRemote (`iRemoteLite mission.moos` in a terminal), and the apps a user catalogue
  declares `launched_manually = true`. A block whose name *starts with* one of
  these names (`uTermCommandFoo`, `uXMS_nav`) is never reported, even when a
  script beside the mission starts the tool with another file (`uCommand
  targ_commander_$VTEAM.moos`): its user may start it by hand with this one.
- `commented-runs` (boolean, default false): also report a block whose Run
  line is commented out in the ANTLER block (`//Run = uTimerScript ...`; also
  `#Run = ...`, `/Run = ...` and `/* Run = ... */`, which MOOS does not take
  for comments but which launch nothing all the same).
  Commenting a Run line out while keeping its block is how MOOS users switch a
  process off for a while (a simulator for field runs, a logger, a timer
  script; 4 of the 8 such blocks in MOOS-IvP's own missions), so by default
  such a block is taken as switched off on purpose. The commented line is read
  as a live one is: the block its app's `main` hard-codes (`Run("iRemote", ...)`
  in iRemoteMod) and the names its script quotes count as switched off too.

MOOS-IvP caveats, deliberately not reported:
- the ANTLER block itself;
- an app's example configuration (`src/pCoroner/pCoroner.moos`: a file named
  after one of its blocks, with no `ServerPort` or `Community`, that no other
  file includes) whose ANTLER block does not launch that app: the app is
  started with the file (`pCoroner pCoroner.moos`), and the ANTLER block is a
  list it reads (a watchdog's processes to watch);
- in a mission whose ANTLER block starts the MOOSDB alone (an app's bench
  file, `iYellowSubDAQ.moos` beside its source), the block of an app that is
  not one of MOOS's or MOOS-IvP's: the project's driver is started by hand
  with the file while it is tested (`iYellowSubDAQ iYellowSubDAQ.moos`). A
  stock app's block there is reported (pAntler launches those, and the
  catalogue knows the few started by hand);
- a block a launched script reads: a script started by a Run line
  (`Run = ./iSonar.py`) connects under the name it chooses and reads its
  configuration its own way, so its stem's block (`iSonar`) and any block
  whose name it quotes (`MoosReader(file, "iSonar")`) count as read. The
  script is read as text, never run;
- a renamed copy whose source moos-lint cannot see: a launched script that is
  not in the project (`Run = ./iPydyna2.py`) or a commented-out app that is
  neither in the catalogue nor in the linted C++ (`//Run = iRemoteMod`) most
  often connects under the name it was copied from, so a block named as the
  start of its name, a word or number short (`iPydyna`, `iRemote`), is taken
  as its;
- a block that a process started another way launches: a `Run` line of an
  nspatch patch file (`*.xmoos`) beside the mission (`nspatch
  --stem=meta_shoreside.moos full-logging.xmoos` overwrites or augments the
  stem's ANTLER block), or a shell script beside it that starts the program
  with this mission or nsplug's output of it (`uMAC targ_shoreside.moos` for
  `meta_shoreside.moos`, `"$BIN" targ_shoreside.moos --alias=pTrafficManager`),
  or a CMake file beside it whose `COMMAND` does (a test harness's
  `EXECUTE_PROCESS( COMMAND uMissionTester alpha.moos ...)`). All are read as
  text, never run;
- a block or Run name holding an unexpanded `$(X)` macro: an unknown name may
  be any name, so it launches (or is launched by) anything it could match; an
  ANTLER line that is a macro alone (`$(RUN)`, the whole Run line given by the
  launch script) may launch any block, so nothing is reported;
- a block and a Run line in mutually exclusive `#ifdef` branches do not launch
  each other (`#ifdef XMODE SIM` / `#elseifdef XMODE M300`, or two `#ifdef`s
  testing one macro for different values), so such a block is reported;
- a mission with an `#include` that could not be followed (a macro in its
  path, a missing file): a Run line may be in it, so nothing is reported;
- a block with `{` on its header line: MOOS never finds it whatever launches
  it, and brace-on-header (R003) reports that line;
- a block of a fragment that several missions include (one `plug_uTimerScript.moos`
  for the vehicle and the shoreside), when another mission of the lint run that
  includes the fragment launches it (the block is read there, and deleting it
  would break that mission) or has its Run line commented out (switched off
  there on purpose);
- a block of a program that is not one of MOOS's or MOOS-IvP's, which three or
  more missions of the lint run configure while none launches it, not even in a
  commented-out Run line: the project starts that program another way (a tool
  started by hand, `iKST targ_alpha.moos`), or the missions pick from a shared
  set of configurations; two copies of a mission are no such sign, and their
  block is reported, nor is a stock app's (the catalogue knows which of those
  are started by hand);
- a block that reaches the mission through a file of `#include` lines alone
  (three or more, and comments), other than the mission itself: a library of
  per-app configuration files that every mission includes whole
  (`#include "common/includes.moos"`, which includes `processes/pTrustGPS.moos`,
  `processes/pMarinePID.moos`, ...), each mission launching the apps it needs. The
  mission chose the library, not the block. A fragment the mission (or a plug
  file that also holds blocks) includes by itself is still judged;
- a block whose name holds, between underscores, the stem of a launched script
  moos-lint cannot read (`heron_realtime_reachability` for
  `Run = ../falcon/heron/realtime_reachability.py`): such a script connects
  under the name it chooses, often its package's name joined to its own.
"""

import os
import re

from moos_lint.files.diagnostics import Severity
from moos_lint.files.launch import patch_launches, script_launches, script_names
from moos_lint.frontends.nsplug import derived
from moos_lint.frontends.parsers.nodes import has_macro
from moos_lint.rules.hygiene._shared import (
    app_example,
    commented_runs,
    exclusive,
    extends,
    names_match,
    near_name,
)
from moos_lint.rules.kit.declare import Scope, rule
from moos_lint.rules.kit.per_run import per_run
from moos_lint.semantics.catalogue import catalogue_for, stock


@rule(
    code="H001",
    name="unlaunched-process-config",
    severity=Severity.WARNING,
    scope=Scope.MISSION,
    options={"manual-apps": None, "commented-runs": False},
)
def check(ctx):
    moos = ctx.moos
    if ctx.expansion.incomplete:
        return
    if any(b.macro_lines for b in moos.antler_blocks):
        return  # a line the launch script gives (`$(RUN)`) may launch any block's process
    if app_example(ctx):
        return  # an app's example configuration: the app is started with the file
    # pAntler starts the MOOSDB alone: the project's own apps are started by hand
    db_alone = all(run.program.lower() == "moosdb" for run in moos.runs)
    given = ctx.options.get("manual-apps")
    if isinstance(given, str):
        given = [given]
    cat = catalogue_for(ctx.run)
    if given is None:
        manual = cat.started_by_hand()
    else:
        manual = [str(a).lower() for a in given]
    # the Run lines by name (a name with a macro may match any block): each block looks
    # at the lines that may launch it, not at every Run line
    by_name: dict[str, list] = {}
    any_name: list = []
    reads = {id(run): cat.block_names(run) for run in moos.runs}
    elsewhere = _reads_other(moos.runs, reads)
    for run in moos.runs:
        if has_macro(run.name):
            any_name.append(run)
        else:
            for name in reads[id(run)]:
                by_name.setdefault(name.lower(), []).append(run)
    switched = not ctx.options.get("commented-runs")  # a commented Run line switches off
    scripts: tuple[frozenset[str], dict[str, str]] | None = None  # what launched scripts quote
    patched: frozenset[str] | None = None  # what the nspatch patches beside it launch
    blockless: list[str] | None = None  # what launched processes read that has no block
    for block in moos.blocks:
        if block.header is None or not block.name or block.lname == "antler":
            continue
        if block.brace_on_header:
            continue  # MOOS never finds it: brace-on-header (R003) reports the line
        if has_macro(block.name) or any(block.lname.startswith(m) for m in manual if m):
            continue
        if any(
            any(names_match(name, block.name) for name in reads[id(run)])
            and not exclusive(run.param.line, block.header, ctx.expansion)
            for run in (*by_name.get(block.name.lower(), ()), *any_name)
        ):
            continue
        if db_alone and not _of_stock_app(block.lname):
            continue  # a driver on the bench, started with the file (`iGPS_Hover nostromo.moos`)
        if block.header.path != ctx.path and _launched_by_includer(ctx.run, block, cat, switched):
            continue  # a shared fragment: another mission that includes it launches it
        if _from_library(ctx.expansion, ctx.path, block):
            continue  # one entry of a configuration library the mission includes whole
        if switched and _started_elsewhere(ctx.run, block.lname, cat):
            continue  # configured across the project, launched by no mission: by hand
        if scripts is None:
            scripts = _script_words(ctx.path, moos)
        quoted, unread = scripts
        if block.lname in quoted or _extends(block.lname, unread) or _holds(block.lname, unread):
            continue  # a launched script names it (or may): it reads it its own way
        if patched is None:
            folder = os.path.dirname(os.path.abspath(ctx.path))
            patched = patch_launches(folder) | script_launches(folder, ctx.path)
        if block.lname in patched:
            continue  # an nspatch patch or a shell script beside the mission launches it
        why = elsewhere.get(block.lname)
        advice = "rename the block"
        near = None
        if why is None:
            lines, unknown = commented_runs(ctx.run, moos, cat, ctx.path)
            hint = lines.get(block.lname) or _extends(block.lname, unknown)
            if hint and switched:
                continue  # switched off on purpose
            why = f"its Run line is commented out at {hint}" if hint else "no Run line starts it"
            advice = "launch it or delete the block"
            if not hint:
                if blockless is None:
                    blockless = _blockless(moos, reads)
                near = near_name(block.name, blockless)
        msg = f"no process reads block `{block.name}`: {why} ({advice})"
        if near is not None:  # (an extension of the plain message: see _one_claim_per_place)
            msg += f"; `{near}` is launched with no block of its own: is the block meant for it?"
        yield ctx.report(block.name_span, msg, line=block.header)


def _blockless(moos, reads) -> list[str]:
    """The names launched processes read whose block the mission lacks."""
    blocks = {b.lname for b in moos.blocks if b.header is not None and b.name}
    return [
        reads[id(run)][0]
        for run in moos.runs
        if reads[id(run)]
        and run.script_block is None  # a script reads its configuration its own way
        and not has_macro(run.name)
        and not any(n.lower() in blocks for n in reads[id(run)])
    ]


def _reads_other(runs, reads) -> dict[str, str]:
    """Why a block named as a Run line is not read, by lower-case name: the app's ``main``
    connects under a name it hard-codes (``Run("iGPS_MB1", ...)``)."""
    found: dict[str, str] = {}
    for run in runs:
        names = reads[id(run)]
        if names != run.block_names:
            for n in run.block_names:
                found.setdefault(
                    n.lower(),
                    f"`{run.program}` connects as `{names[0]}` (its main passes that name to "
                    f"Run) and reads block `{names[0]}`",
                )
    return found


def _launched_by_includer(run, block, cat, switched: bool) -> bool:
    """Whether a mission of the run that includes the fragment holding ``block`` launches
    a process of its name (or, ``switched``, has its Run line commented out: switched off
    there on purpose)."""
    key = "switched-by-fragment" if switched else "names-by-fragment"
    names = per_run(run, key, lambda units: _names_by_fragment(run, units, cat, switched))
    return any(names_match(name, block.name) for name in names.get(block.header.path, ()))


def _names_by_fragment(run, units, cat, switched: bool) -> dict[str, set[str]]:
    """Every included file of the missions -> the process names (names of the blocks
    their Run lines read) launched by the missions that include it, with ``switched``
    those of their commented-out Run lines too."""
    found: dict[str, set[str]] = {}
    for unit in units:
        moos = unit.moos
        if moos is None or not moos.runs:
            continue
        launched = {name for r in moos.runs for name in cat.block_names(r)}
        included = [path for path in unit.expansion.sources if path != unit.path]
        if switched and included:
            launched |= set(commented_runs(run, moos, cat, unit.path)[0])
        for path in included:
            found.setdefault(path, set()).update(launched)
    return found


#: a file of at least this many `#include` lines and nothing else is a library's index
_LIBRARY_INCLUDES = 3


def _from_library(exp, mission: str, block) -> bool:
    """Whether ``block`` reaches the mission through a file of `#include` lines alone
    (:func:`_includes_only`) other than the mission: the mission took a whole library of
    per-app configurations (``#include "common/includes.moos"``), not this block."""
    return any(
        site.path != mission and _includes_only(exp, site.path) for site in block.header.chain
    )


def _includes_only(exp, path: str) -> bool:
    """Whether the file at ``path`` holds at least :data:`_LIBRARY_INCLUDES` `#include`
    lines and nothing else but comments and blank lines."""
    source = exp.sources.get(path)
    if source is None:
        return False

    def read() -> bool:
        count = 0
        for raw in source.text.splitlines():
            text = raw.strip()
            if not text or text.startswith("//"):
                continue
            if not text.startswith("#include"):
                return False
            count += 1
        return count >= _LIBRARY_INCLUDES

    return derived(exp, f"includes-only:{path}", read)


def _of_stock_app(lname: str) -> bool:
    """Whether block ``lname`` is a MOOS or MOOS-IvP app's, under its name or an alias
    that starts with it (`uTimerScript_PING`)."""
    cat = stock()
    return any(lname.startswith(name) for name in (*cat.apps, *cat.programs))


#: a block that at least this many missions of the run configure, and none launches
#: (not even in a commented-out Run line), is taken as started another way
_CONFIGURED_ACROSS = 3


def _started_elsewhere(run, lname: str, cat) -> bool:
    """Whether block ``lname`` is configured by several missions of the run and launched by
    none of them, not even in a commented-out Run line: a tool the project starts another
    way (by hand in a terminal, `iKST targ.moos`; from a script outside the missions), or a
    shared set of configurations the missions pick from. The block is kept on purpose.
    Not for an app of MOOS or MOOS-IvP: the catalogue knows which of those are started by
    hand, and the others are launched by pAntler."""
    if lname in stock().apps or lname in stock().programs:
        return False
    configured, launched, macros = per_run(
        run, "blocks-across-missions", lambda units: _across(run, units, cat)
    )
    if configured.get(lname, 0) < _CONFIGURED_ACROSS or lname in launched:
        return False
    return not any(names_match(name, lname) for name in macros)


def _across(run, units, cat) -> tuple[dict[str, int], set[str], set[str]]:
    """How many missions of the run configure each block (by lower-case name), the
    lower-case names the missions launch or have commented out, and the launched names
    that hold a macro (any name may match them)."""
    configured: dict[str, int] = {}
    launched: set[str] = set()
    macros: set[str] = set()
    for unit in units:
        moos = unit.moos
        if moos is None or not moos.is_mission:
            continue
        for name in {b.lname for b in moos.blocks if b.header is not None and b.name}:
            configured[name] = configured.get(name, 0) + 1
        for r in moos.runs:
            if has_macro(r.name):
                macros.add(r.name)
            launched.update(name.lower() for name in cat.block_names(r))
        launched.update(commented_runs(run, moos, cat, unit.path)[0])
    return configured, launched, macros


def _script_words(mission: str, moos) -> tuple[frozenset[str], dict[str, str]]:
    """The lower-case words the scripts the mission launches quote (see
    :func:`moos_lint.files.launch.script_names`), and the program of each script that
    cannot be read, by lower-case stem: such a script may connect under any name."""
    words: set[str] = set()
    unread: dict[str, str] = {}
    for run in moos.runs:
        if run.script_block is not None and not has_macro(run.binary):
            quoted = script_names(mission, run.binary)
            if quoted is None:
                unread[run.script_block.lower()] = run.binary
            words |= quoted or frozenset()
    return frozenset(words), unread


def _extends(name: str, names) -> str | None:
    """What ``names`` holds for a name that is ``name`` with a word or a number added
    (``ipydyna2`` or ``iremotemod`` for block ``iremote``): a copy of an app or a script
    kept under a new name most often connects under the old one, and moos-lint cannot
    see which, its source not being linted."""
    for other in names:
        if extends(other, name):
            return names[other]
    return None


def _holds(name: str, unread: dict[str, str]) -> str | None:
    """What ``unread`` holds for a script whose stem is a part of block ``name`` between
    underscores (``heron_realtime_reachability`` for ``realtime_reachability.py``): a
    script moos-lint cannot read connects under the name it chooses, often its package's
    name joined to its own."""
    for stem, program in unread.items():
        if re.search(rf"(?:^|_){re.escape(stem)}(?:_|$)", name):
            return program
    return None
