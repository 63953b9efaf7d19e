"""A variable the mission's configuration publishes that nothing in the mission reads.

## What it does
In a mission (after nsplug expansion, with its behavior files), takes the
variables that configuration values publish: behavior flags (`endflag`,
`runflag`, ...), `initialize` and `set MODE` variables, uTimerScript events,
pMarineViewer buttons and actions, pEchoVar targets, and so on. It reports
(once per variable, at its first publication) a variable that no launched
app subscribes to (the catalogue's `Register` calls: pMarineViewer draws
the `VIEW_*` it registers for), no condition or `updates` line reads, and no
share or bridge route carries away. Names that only an observer's
configuration lists (pLogger `log`, uXMS `var`, a viewer's `scope`) do not
count as read. Which apps are observers (pLogger, uXMS, uMAC, pMarineViewer,
...) and which subscribe to names they build at run time comes from the app
catalogue, with its evidence in the app sources: pMissionEval reads the
variables of its conditions, uFldShoreBroker `qbridge = X` reads `X_ALL` and
`X_<VNAME>`.

It is off by default and an `info`: a flag posted for the log or for a person
watching is fine. Use it to find dead configuration and misspelled names
(the reading side spelled `RETURN_HOME`, the flag `RETURN_HOM`).

## Why is this bad?
A posting that nobody reads is either dead configuration or the half of a
hand-off whose other half is spelled differently.

## Example
```bhv
Behavior = BHV_Waypoint
{
  name    = transit
  endflag = RETURN_HOM = true    // the return behavior waits for RETURN_HOME
}
```

## How to fix
Correct the name, or delete the posting.

## Options
None.

MOOS-IvP caveats, deliberately not reported:
- variables published by apps themselves (their C++): most are status for
  the log;
- names with run-time placeholders (`$[OWNSHIP]`) or nsplug macros;
- missions that launch an app the catalogue does not know or that
  subscribes to names it builds at run time (it may read anything): the
  pHelmIvP, pShare and broker apps are modelled through their
  configuration instead;
- variables the other missions of the folder read, when the mission shares
  variables with them (and every variable, when one of them may read anything
  or is not whole: a macro or an include it leaves unread).
"""

import fnmatch
from collections.abc import Iterator

from moos_lint.files.diagnostics import Severity, Subject
from moos_lint.rules.kit.declare import Kind, Scope, rule
from moos_lint.semantics.mission_model import MissionModel, mission_model, sibling_model
from moos_lint.semantics.variables import PUBLISH, SUBSCRIBE, VarRef, bare_name


def readers(model: MissionModel) -> tuple[set[str], bool]:
    """Names read in the mission (``*`` in a name: any text), and whether some process
    may read any name.

    What the catalogue says of each launched app decides: an observer's
    configuration (what a viewer shows, a logger logs) reads nothing, its
    conditions aside; an app that subscribes to names built at run time may read
    anything, unless those names are the ones its configuration gives (modelled
    in :mod:`moos_lint.semantics.variables`) or it is an observer.
    """
    names: set[str] = set()
    open_ended = bool(model.unknown_apps or model.unresolved_behaviors)
    apps = {p.name: p.app for p in model.processes}
    for ref in model.refs:
        if ref.role != SUBSCRIBE:
            continue
        app = apps.get(model.ref_process.get(id(ref), ""))
        if app is not None and app.observer and ref.param != "condition":
            continue
        for read in ref.read_names:
            name = bare_name(read)
            if name:
                names.add(name)
    for _path, bf in model.behavior_files:
        for bhv in bf.behaviors:
            info = model.catalogue.behavior(bhv.kind)
            if info is not None:
                names |= info.reads
    for proc in model.processes:
        app = proc.app
        if app is None:
            continue
        names |= app.subscribes  # a viewer that registers for VIEW_POINT draws it
        if app.subscribes_dynamic and not (app.observer or app.subscriptions_from_config):
            open_ended = True
    return names, open_ended


def is_read(name: str, names: set[str]) -> bool:
    return name in names or any("*" in n and fnmatch.fnmatchcase(name, n) for n in names)


def unread(model: MissionModel, names: set[str]) -> Iterator[tuple[VarRef, str]]:
    """``(ref, name)`` of the first posting of each plain name (no macro, no wildcard)
    that none of ``names`` (:func:`readers`) reads."""
    seen: set[str] = set()
    for ref in model.refs:
        if ref.role != PUBLISH:
            continue
        name = bare_name(ref.name)
        if not name or name != ref.name or "*" in name or name in seen:
            continue
        seen.add(name)
        if not is_read(name, names):
            yield ref, name


def judged_postings(ctx) -> tuple[set[str], Iterator[tuple[VarRef, str]]] | None:
    """The names the mission reads (:func:`readers`) and its unread postings
    (:func:`unread`); None when the mission cannot be judged: some process may read any
    name, or missions beside it publish to it."""
    model = mission_model(ctx)
    names, open_ended = readers(model)
    if open_ended:
        return None
    for path in model.sibling_missions:  # what the missions beside it read counts too
        sibling = sibling_model(ctx.run, path)
        if sibling is None:
            return None
        their_names, their_open = readers(sibling)
        if their_open:
            return None
        names |= their_names
    return names, unread(model, names)


@rule(
    code="M006",
    name="unread-publication",
    severity=Severity.INFO,
    scope=Scope.MISSION,
    kinds=(Kind.MOOS,),
    default_enabled=False,
)
def check(ctx):
    judged = judged_postings(ctx)
    if judged is None:
        return
    for ref, name in judged[1]:
        yield ctx.report(
            ref.span,
            f"`{name}` is published ({ref.app}: {ref.param}) but nothing in the mission reads it",
            line=ref.line,
            subject=Subject(variable=name, app=ref.app, key=ref.param),
        )
