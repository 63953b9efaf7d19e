"""A condition waits for a variable that nothing in the mission publishes.

## What it does
In a mission (after nsplug expansion, with its behavior files), takes every
variable that a logic condition waits for: behavior `condition` and
`lead_condition` lines, the conditions of `set MODE` blocks, and the
`condition` parameters of launched apps (uTimerScript, pEchoVar, uQueryDB,
...). It reports a variable that no part of the mission publishes:

- a launched app (the catalogue: stock apps, catalogue files, the linted
  C++), including dynamic names with a known prefix or suffix, and the
  MOOSDB, which posts its own `DB_*` variables (`DB_UPTIME`, `DB_CLIENTS`, ...);
- a configuration value that names a published variable (uTimerScript
  events, pMarineViewer buttons and actions, pEchoVar targets and flips, the
  `*_flag` VarDataPairs of the apps that read them (pObstacleMgr
  `new_obs_flag = OBM_NEW_GIVEN=true`), share and
  bridge routes, iRemote's custom keys (`CustomKey = 9 : SURFACING @ "true"`), ...);
- a node message (`NODE_MESSAGE_LOCAL = src_node=alpha,dest_node=all,
  var_name=CHASER,string_val=alpha`) posted in a mission that launches
  uFldMessageHandler (the handler posts `CHASER` on the vehicle that
  receives it), or in another mission of its folder, whatever the receiving
  mission runs (the check stays quiet rather than guess where it goes);
- the behavior files: flags (`endflag`, `runflag`, ...), `initialize`,
  `set MODE` variables, the variables behaviors post, under names of their
  source (`AVD_STATUS`), names their parameters make (BHV_Timer's
  `var_status_idle` with `status_suffix = BASE`: `TIMER_IDLE_SECONDS_BASE`) and
  prefixes followed by a contact's name (BHV_AvoidCollision's `RANGE_AVD_`);
- a flag given in an update string of the mission or of a mission beside it
  (`button_two = STOP # LEG_UPDATE = midflag=FULL_STOPPING=true`: the behavior
  with `updates = LEG_UPDATE` takes the flag and posts `FULL_STOPPING`);
- a `uPokeDB ... VAR=value` in a shell script beside the mission, or in a
  note beside it (`README`, `*.md`, `*.txt`: the steps a person runs by hand,
  `$ uPokeDB WPT_REQUEST=true`);
- when the mission receives variables from another community (pShare,
  uFldNodeBroker, uFldShoreBroker, pMOOSBridge), or launches no MOOSDB (a
  second file of a community, whose processes join the database another file
  launches), anything the other missions in its folder publish (nsplug's
  outputs, `targ_*.moos`, count only for a `targ_` mission: in a repository
  that keeps only those, they are the other communities), and what any
  mission of the project sends with pShare on a route the mission's pShare
  listens on (`output = src_name=START, route=multicast_8` in
  `missions/launcher.moos`, `input = route=multicast_8` in the buoys' missions
  elsewhere).

- a behavior of the project's own (a kind the catalogue does not describe,
  whose `BHV_X.cpp` is under the project root) that posts it by name
  (`postMessage("VNAME", m_name)`, `postBoolMessage`, `postIntMessage`,
  `postRepeatableMessage`).
When the name is a typo away from exactly one published name (`DEPOLY`
and `DEPLOY`: a letter of one `_`-separated word left out, added, changed or
two swapped, as misnamed-publication counts typos), the message names it.

When the mission launches apps that the catalogue does not know, uses
behaviors it does not describe whose C++ is not in the project (or posts
under names held in variables), or names behavior files the model cannot
find, the finding is an `info` that says the check was incomplete, and names
what was not known. So it is when the mission launches a program that posts
variables of any name: the uMS scope (what its user pokes in its poke
dialog), uPlayback (the variables of the log it replays).

## Why is this bad?
A condition on a variable that is never posted never becomes true: the
behavior stays idle, the timer script never starts, and nothing says why.
Most often the name is misspelled (`DEPOLY = true`) or the app that should
post it is not launched.

## Example
```bhv
Behavior = BHV_Waypoint
{
  name      = transit
  condition = DEPOLY = true      // the button posts DEPLOY
  points    = 0,0 : 100,0
}
```

## How to fix
Correct the name, or launch (or configure) the process that posts it.

## Options
None.

MOOS-IvP caveats, deliberately not reported:
- names with run-time placeholders (`$[OWNSHIP]`, `$(VNAME)` left by
  nsplug) and wildcards;
- a variable on one side of an `or` (`(DEPLOY = true) or (ALPHA = one)`): the
  condition may hold without it (lib_logic evaluates the whole expression with
  the variables it has, IvPBehavior.cpp), unless the name is a typo away from
  a published one, as above (`(DEPLOY = true) or (RETRUN = true)`): that side
  is dead;
- a mission that receives variables from another community when no other
  mission in its folder describes that community: anything may arrive;
- a variable named after a launched app that the catalogue does not know,
  by its initials or its name (`UFRM_WINNER` when the mission runs
  uFldRescueMgr from another tree, `ODOMETRY_DIST` when it runs pOdometry):
  MOOS-IvP apps name their own variables so (uSimMarine `USM_*`,
  uFldShoreBroker `UFSB_*`), so that app most likely posts it;
- a variable whose name holds the `name` of a behavior whose kind the
  catalogue does not describe and whose C++ is not in the project
  (`condition = CONFINES_stayIN != VIOLATION` beside a `BHV_SecurityFence`
  named `stayIN`): such a behavior most likely posts it;
- a name a launched app builds from a value of its block: pMarinePIDV22's
  `output_suffix = _PID` makes `DESIRED_RUDDER_PID` of `DESIRED_RUDDER`
  (`"DESIRED_RUDDER" + m_output_suffix`), when the app builds names at run time
  and the rest of the name is one it publishes; for an app the catalogue does
  not know, a value that is a whole word at either end of the name
  (`PREFIX = NAV` and `NAV_DEPTH`); for an app of the linted C++, the name it
  publishes under a key of its block (`Notify(m_sim_prefix + "_DEPTH", ...)`
  with `m_sim_prefix` read from `PREFIX`).

A variable a person pokes by hand (uPokeDB from a terminal, uMAC) is reported
when nothing beside the mission shows the poke: write the step in a script or
a README beside it, give the variable a publisher in the mission, or suppress
the finding.
"""

import re

from moos_lint.files.diagnostics import Severity, Subject
from moos_lint.rules.kit.declare import Kind, Scope, rule
from moos_lint.rules.kit.spelling import VariableSpeller
from moos_lint.rules.mission._behaviors import repo_behavior_posts
from moos_lint.semantics.mission_model import mission_model
from moos_lint.semantics.process_names import own_prefixes
from moos_lint.semantics.shares import input_routes, received
from moos_lint.semantics.variables import bare_name, one_alternative


def _gaps(model, unknown_kinds: list[str]) -> list[str]:
    out = [_unknown_app(model, p) for p in model.unknown_apps]
    out += [f"behavior file `{b}` was not found" for b in model.unresolved_behaviors]
    out += [f"behavior `{k}` is not in the catalogue" for k in unknown_kinds]
    return out


def _unknown_app(model, p) -> str:
    """Why a launched program leaves the check incomplete: one whose posts have any name
    (the uMS scope's pokes, a playback's log), or one the catalogue does not know."""
    named = f"`{p.name}`" + (f" ({p.binary})" if p.binary != p.name else "")
    program = model.catalogue.programs.get(p.binary.lower())
    if program is not None and program.posts_any:
        return f"{named} posts {program.posts_any.split(' (', 1)[0]}"
    return named + " is not in the catalogue"


def _unknown_kinds(model) -> list[str]:
    """The behavior kinds of the mission's behavior files that the catalogue does not
    describe (the project's own behaviors): they may post anything."""
    kinds: list[str] = []
    for _path, bf in model.behavior_files:
        for bhv in bf.behaviors:
            kind = bhv.kind.strip()
            if kind and model.catalogue.behavior(kind) is None and kind not in kinds:
                kinds.append(kind)
    return kinds


@rule(
    code="M005",
    name="unpublished-subscription",
    severity=Severity.WARNING,
    scope=Scope.MISSION,
    kinds=(Kind.MOOS,),
)
def check(ctx):
    model = mission_model(ctx)
    if model.receives and not model.sibling_missions:
        return  # variables may come from a community the linter cannot see
    # what the project's own C++ of the behaviors the catalogue does not describe posts
    # by name; a kind whose C++ is not found, or that posts under a name held elsewhere,
    # leaves the check incomplete
    posted: set[str] = set()
    unknown_kinds = []
    for kind in _unknown_kinds(model):
        posts, known = repo_behavior_posts(ctx, kind)
        posted |= posts
        if not known:
            unknown_kinds.append(kind)
    gaps = _gaps(model, unknown_kinds)
    unknown_names = _behavior_names(model, unknown_kinds)
    unknown_prefixes = {pre for p in model.unknown_apps for pre in own_prefixes(p.binary)}
    seen: set[tuple[str, str, int]] = set()
    routes: set[str] | None = None  # the pShare routes the mission listens on
    flagged: set[str] | None = None  # names update strings set flags to post
    speller: VariableSpeller | None = None  # what a waited-for name may be a typo of
    for ref in model.waits:
        name = bare_name(ref.name)
        if not name or name != ref.name or ref.wildcard or "*" in name or "?" in name:
            continue
        if model.is_published(name) or name in posted:
            continue
        meant = None
        if one_alternative(ref):
            # one side of an `or`: the condition may hold without it, so it is not waited
            # for; a misspelling of a posted name still leaves that side dead
            if speller is None:
                speller = VariableSpeller(model.publishers)
            meant = speller.meant(name)
            if meant is None:
                continue
        key = (name, ref.line.path, ref.line.lineno)
        if key in seen:
            continue
        seen.add(key)
        if _named_after(name, unknown_prefixes):
            continue  # named after an app the catalogue does not know: likely its own
        if _names_one(name, unknown_names):
            continue  # named after a behavior of a kind not known: likely its post
        if model.built_from_config(name) is not None:
            continue  # a name an app builds from a value of its block (`output_suffix`)
        if flagged is None:
            flagged = _flag_targets(ctx, model)
        if name in flagged:
            continue  # an update string sets a behavior's flag to post it
        # last, as it may walk the project's missions (once per run): only for a finding
        if routes is None:
            routes = _listened(model)
        if received(ctx.run, routes, name):
            continue  # a mission elsewhere in the project sends it on a route this one hears
        owner = ref.app if ref.app else "the mission"
        subject = Subject(variable=name, app=ref.app or None, key=ref.param)
        if meant is not None:
            msg = f"`{name}`: nothing in the mission publishes it, so this side of "
            msg += f"{owner}'s {ref.param} never holds; did you mean `{meant}`?"
        else:
            msg = f"`{name}`: {owner}'s {ref.param} waits for it, "
            msg += "but nothing in the mission publishes it"
            if speller is None:
                speller = VariableSpeller(model.publishers)
            near = speller.meant(name)
            if near is not None:
                msg += f" (`{near}`, a typo away, is published)"
        if gaps:
            yield ctx.report(
                ref.span,
                msg + "; the check is incomplete: " + "; ".join(gaps[:3]),
                line=ref.line,
                severity=Severity.INFO,
                subject=subject,
            )
        else:
            yield ctx.report(ref.span, msg, line=ref.line, subject=subject)


#: a flag given in a behavior's update string: ``midflag=FULL_STOPPING=true``
_FLAG_IN_UPDATE = re.compile(r"\b\w*flag\s*=\s*([A-Za-z0-9_]+)\s*=", re.IGNORECASE)


def _flag_targets(ctx, model) -> set[str]:
    """The names an update string of the mission or of a mission beside it sets a
    behavior's flag to post: pMarineViewer's ``button_7 = STOP # LEG_UPDATE_ALL =
    midflag=FULL_STOPPING=true`` reaches a behavior with ``updates = LEG_UPDATE``,
    which then posts ``FULL_STOPPING``."""
    found: set[str] = set()
    expansions = [model.moos.expansion]
    for path in model.sibling_missions:
        exp = ctx.run.preprocessor.expand(path)
        if exp.read_problem is None:
            expansions.append(exp)
    for exp in expansions:
        for line in exp.lines:
            if "flag" in line.text.lower():
                found.update(_FLAG_IN_UPDATE.findall(line.text.split("//", 1)[0]))
    return found


def _listened(model) -> set[str]:
    """The routes the mission's pShare listens on."""
    found: set[str] = set()
    for proc in model.processes:
        if proc.binary.lower() == "pshare" and proc.block is not None:
            found |= input_routes(proc.block)
    return found


def _behavior_names(model, kinds: list[str]) -> list[tuple[str, ...]]:
    """The ``name`` of each behavior of ``kinds`` (kinds whose posts are not known), as
    its ``_``-separated words: a behavior whose posts are not known may post names made
    of its own (``CONFINES_stayIN``, waited for beside a ``BHV_SecurityFence`` named
    ``stayIN``)."""
    if not kinds:
        return []
    found: list[tuple[str, ...]] = []
    for _path, bf in model.behavior_files:
        for bhv in bf.behaviors:
            named = bhv.name
            if bhv.kind.strip() not in kinds or named is None:
                continue
            words = tuple(w for w in named.value.strip().split("_") if w)
            if len("".join(words)) >= 3 and words not in found:
                found.append(words)
    return found


def _names_one(name: str, names: list[tuple[str, ...]]) -> bool:
    """Whether ``name``'s ``_``-separated words hold one of ``names``' in a row."""
    parts = name.split("_")
    return any(
        tuple(parts[i : i + len(words)]) == words
        for words in names
        for i in range(len(parts) - len(words) + 1)
    )


def _named_after(name: str, prefixes: set[str]) -> bool:
    """Whether ``name`` is one of ``prefixes`` or starts with one and ``_``."""
    parts = name.split("_")
    return any("_".join(parts[:i]) in prefixes for i in range(1, len(parts) + 1))
