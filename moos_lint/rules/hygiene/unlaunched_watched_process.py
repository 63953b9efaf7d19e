"""A process uProcessWatch watches that the mission never launches.

## What it does
In a mission (a `.moos` file with an ANTLER block, after nsplug expansion, its
includes included) that launches uProcessWatch, reports each name of its
`watch` lists (`watch = pHelmIvP, uSimMarine:SIM_OK`) that no process of the
mission connects under: no `Run` line starts a process of that name (the `~`
alias, or the program's name). uProcessWatch compares names exactly, so a name
that differs from a launched one only in case is reported too, and said so.
When a launched process has a near name (`uSimMarineV22` for `uSimMarine`, a
typo or a word added), the finding names it. The block may be in a plug the
mission includes; the finding points at the name in the plug, with the include
chain.

## Why is this bad?
uProcessWatch puts every name of a `watch` list on its watch list at once,
whatever is launched, and checks it against the MOOSDB's clients. A name no
process connects under is missing for the whole run (unless someone starts it
by hand): uProcessWatch reports it `AWOL` and posts `PROC_WATCH_ALL_OK = false`
from start to end, so the check that the vehicle's processes are all running
says no, and a real crash goes unseen among the false alarms (ProcessWatch.cpp,
`handleConfigWatchItem`, `isAlive`). The usual cause is a plug kept after the
mission changed: the list still names `uSimMarine` and `pMarinePID` after the
mission moved to `uSimMarineV22` and `pMarinePIDV22`, or `pLogger` after its
Run line was commented out.

Deliberately not reported:
- names with a `*` (a pattern: it watches what matches, when it runs), and
  names holding an nsplug macro;
- a mission with an `#include` that could not be followed, a Run line whose
  name holds a macro, or one that starts a script (it connects under a name of
  its own choosing): what connects is not all known; nor a mission (or an
  `#ifdef` branch of one) that launches no MOOSDB: its processes join the
  database of another file, whose processes are clients too;
- a process started another way: by an nspatch patch (`*.xmoos`) or a shell
  script beside the mission that starts it with this file, by a mission file
  beside it that launches no MOOSDB (its processes join this one's), or a tool
  users start by hand (uXMS, uMAC, ...: the catalogue's `launched_manually`
  apps);
- a uProcessWatch block no Run line starts (unlaunched-process-config reports
  it).

## Example
```moos
ProcessConfig = ANTLER
{
  Run = MOOSDB        @ NewConsole = false
  Run = uSimMarineV22 @ NewConsole = false
  Run = uProcessWatch @ NewConsole = false
}

ProcessConfig = uProcessWatch
{
  watch = uSimMarine    // never launched: AWOL for the whole run
}
```

## How to fix
Name the process as it is launched (`watch = uSimMarineV22`), or take the
name off the list.

## Options
None.
"""

import os

from moos_lint.files.diagnostics import Severity
from moos_lint.files.launch import patch_launches, script_launches
from moos_lint.frontends.parsers.nodes import has_macro
from moos_lint.rules.hygiene._shared import commented_runs, exclusive, near_name
from moos_lint.rules.kit.declare import Kind, Scope, rule
from moos_lint.semantics.catalogue import WATCH_LISTS, catalogue_for
from moos_lint.semantics.mission_model import missions_beside, sibling_model

#: the MOOS infrastructure, never a client of the MOOSDB's own list
_NOT_CLIENTS = {"moosdb", "pantler"}


@rule(
    code="H007",
    name="unlaunched-watched-process",
    severity=Severity.WARNING,
    scope=Scope.MISSION,
    kinds=(Kind.MOOS,),
)
def check(ctx):
    moos = ctx.moos
    if ctx.expansion.incomplete or not moos.is_mission:
        return
    if any(b.macro_lines for b in moos.antler_blocks):
        return  # a line the launch script gives (`$(RUN)`) may launch anything
    cat = catalogue_for(ctx.run)
    watchers: dict[str, str] = {}  # block name (lower case) -> the parameter listing names
    for run in moos.runs:
        if has_macro(run.name) or has_macro(run.binary) or run.script_block is not None:
            return  # it may connect under any name
        param = WATCH_LISTS.get(run.program.lower())
        if param is not None:
            watchers.update((n.lower(), param) for n in cat.block_names(run))
    if not watchers:
        return
    elsewhere: frozenset[str] | None = None  # started by scripts, patches, joining files
    for block in moos.blocks:
        param = watchers.get(block.lname) if block.header is not None else None
        if param is None:
            continue
        for p in block.get(param):
            # the processes that run beside this line (not in another `#ifdef` branch)
            live = [r for r in moos.runs if not exclusive(r.param.line, p.line, ctx.expansion)]
            if not any(r.program.lower() == "moosdb" for r in live):
                continue  # its processes join the database of another file
            names = {n for r in live for n in cat.block_names(r)}
            if block.lname not in {n.lower() for n in names}:
                continue  # the watcher does not run here
            lower = {n.lower(): n for n in names}
            for name, start in _items(p.value):
                if name in names or name.lower() in _NOT_CLIENTS:
                    continue
                if elsewhere is None:
                    elsewhere = _started_elsewhere(ctx, cat)
                if name.lower() in elsewhere and name.lower() not in lower:
                    continue
                hint = ""
                if name.lower() in lower:
                    why = (
                        f"the mission launches `{lower[name.lower()]}`, and uProcessWatch "
                        "compares names in their case"
                    )
                else:
                    at_line = commented_runs(ctx.run, moos, cat, ctx.path)[0].get(name.lower())
                    why = (
                        f"its Run line is commented out at {at_line}"
                        if at_line
                        else "no Run line of the mission starts it"
                    )
                    near = near_name(name, sorted(names))
                    if near is not None:
                        hint = f"; `{near}` is launched: is it the one meant?"
                at = p.value_start + start
                yield ctx.report(
                    p.line.span(at, at + len(name)),
                    f"uProcessWatch watches `{name}`, which no process of the mission "
                    f"connects as ({why}): it reports the process AWOL and posts "
                    "`PROC_WATCH_ALL_OK = false` as long as it is missing (the whole run, "
                    f"unless it is started another way){hint}",
                    line=p.line,
                )


def _items(value: str):
    """(name, offset in ``value``) of each process a ``watch`` list names as such: not a
    pattern (`uFld*`), not one holding a macro; `pLogger:LOGGER_OK` names `pLogger`."""
    offset = 0
    for item in value.split(","):
        here = offset
        offset += len(item) + 1
        text = item.strip()
        if not text or any(c.isspace() for c in text) or has_macro(text):
            continue
        if text.endswith("*"):
            continue
        name = text.split(":", 1)[0].strip()
        if name and name != "uProcessWatch":
            yield name, here + item.index(text)


def _started_elsewhere(ctx, cat) -> frozenset[str]:
    """The lower-case names of processes started beside the mission's own Run lines: by an
    nspatch patch or a shell script of its folder, by a mission file of its folder that
    launches no MOOSDB (its processes join this database), or by hand (the catalogue)."""
    folder = os.path.dirname(os.path.abspath(ctx.path))
    found = set(patch_launches(folder) | script_launches(folder, ctx.path))
    found.update(cat.started_by_hand())
    me = os.path.normcase(os.path.abspath(ctx.path))
    for cand in missions_beside(ctx.run, folder, True):
        other = None if os.path.normcase(cand) == me else sibling_model(ctx.run, cand)
        if other is not None and other.joins:
            found.update(n.lower() for r in other.moos.runs for n in cat.block_names(r))
    return frozenset(found)
