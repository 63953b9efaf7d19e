"""An endflag of a behavior that never ends: the helm never posts it.

## What it does
In a mission (after nsplug expansion, with its behavior files), takes each
behavior with an `endflag` whose kind never ends by itself, and which has no
duration to end it:

- the kind's source neither calls `setComplete()` nor posts its endflags
  (the catalogue's `completes` fact, generated from the MOOS-IvP sources:
  BHV_ConstantDepth, BHV_StationKeep, BHV_Timer, BHV_OpRegion, ...);
- its last `duration` line says `no-time-limit` (or `-1`), or it has none and
  the kind's constructor leaves IvPBehavior's "no time limit" in place
  (BHV_StationKeep; BHV_ConstantDepth and BHV_ConstantSpeed set 0, and end at
  once: behavior-completes-at-once reports those).

It reports such a flag only where it matters: a condition of the mission (a
behavior's other than its own, a mode's or an app's) waits for the flag's
variable to take the flag's value (`condition = SURFACED = true`), and nothing
else in the mission posts the variable with that value (another
behavior's flag, an `initialize`, a timer script or a button). A flag that only
repeats another publisher, or that nobody reads, is left alone: it does
nothing, but nothing waits on it. The message names the behaviors whose
conditions read it.

## Why is this bad?
IvPBehavior posts a behavior's endflags in `setComplete()` (IvPBehavior.cpp),
and the helm calls it for such a behavior only when its duration runs out
(`durationExceeded`, which a duration of -1 never does). The flag is never
posted, and whatever waits for it never starts: a surfacing timer with
`condition = SURFACED = true`, behind a BHV_ConstantDepth with
`endflag = SURFACED = true` and `duration = no-time-limit`, never runs.

## Example
```bhv
Behavior = BHV_ConstantDepth
{
  name      = go_under
  condition = DIVE = true
  depth     = 10
  duration  = no-time-limit
  endflag   = SURFACED = true    // never posted
}

Behavior = BHV_Timer
{
  name      = at_surface
  condition = SURFACED = true    // never true
  duration  = 60
  endflag   = SURFACED = false
}
```

## How to fix
Give the behavior a duration (`duration = 60`), or post the flag from a
behavior that ends (a BHV_Timer with a duration, a waypoint's last point).

## Options
None.

Not reported: a kind the catalogue does not describe, or that the project
defines itself; a behavior spawned from a template (`templating`: the helm
ends it when its contact is gone); a duration holding a macro or set in an
nsplug `#ifdef` branch; and a behavior whose `updates` variable may carry a
duration: one the mission posts update strings to that set `duration`, or
that another community, an app or a launch script may post.
"""

from __future__ import annotations

from moos_lint.files.diagnostics import Severity, Subject
from moos_lint.frontends.parsers.nodes import has_macro
from moos_lint.rules.kit.declare import Kind, Scope, rule
from moos_lint.rules.kit.wording import listed
from moos_lint.rules.mission._behaviors import repo_classes
from moos_lint.rules.mission._posted import value_after
from moos_lint.semantics.mission_model import mission_model
from moos_lint.semantics.variables import PUBLISH

#: the durations IvPBehavior::setParam takes as "no time limit"
NO_TIME_LIMIT = ("no-time-limit", "-1")


@rule(
    code="M015",
    name="endflag-never-posted",
    severity=Severity.WARNING,
    scope=Scope.MISSION,
    kinds=(Kind.MOOS,),
)
def check(ctx):
    if ctx.expansion.incomplete or not ctx.moos.is_mission:
        return
    model = mission_model(ctx)
    for _path, bf in model.behavior_files:
        for bhv in bf.behaviors:
            flags = bhv.get("endflag")
            if not flags:
                continue
            kind = bhv.kind.strip()
            info = model.catalogue.behavior(kind)
            if info is None or info.completes is not False:
                continue
            if bhv.get("templating"):
                continue  # a spawned behavior ends when its contact is gone
            how = _never_timed_out(bhv, info)
            if how is None or _duration_by_update(model, bhv):
                continue
            name = bhv.name.value.strip() if bhv.name is not None else kind
            own = {id(p.line) for p in bhv.params}  # (its own conditions wait for nothing)
            for flag in flags:
                found = _waited_for_alone(model, flag, own)
                if found is None:
                    continue
                var, waiting = found
                if kind.lower() in repo_classes(ctx):
                    break  # the project's own copy of the kind may end (asked only now)
                yield ctx.report(
                    flag.value_span,
                    f"`endflag = {flag.value.strip()}`: `{name}` ({kind}) never ends by itself "
                    f"({info.provenance} neither calls setComplete nor posts its endflags) and "
                    f"{how}, so the helm never posts it; nothing else in the mission posts "
                    f"`{var}` with that value, and {_waiters(waiting)} wait for it",
                    line=flag.line,
                    subject=Subject(variable=var, key="endflag"),
                )


def _waited_for_alone(model, flag, own: set[int]) -> tuple[str, list[str]] | None:
    """(the flag's variable, who waits for it) when a condition of the mission, other
    than the behavior's own (lines ``own``), waits for the variable to take the flag's
    value and nothing else posts it with that value; None otherwise (the flag then only
    repeats another publisher, or nobody else waits for it)."""
    var, sep, value = flag.value.partition("=")
    var, value = var.strip(), _norm(value)
    if not var or not sep or has_macro(flag.value):
        return None
    if any(p.how not in ("config", "behavior") for p in model.published_by(var)):
        return None  # an app, another community or a launch script may post it
    for ref in model.refs:
        if ref.role != PUBLISH or ref.name != var or ref.line is flag.line:
            continue
        other = value_after(ref)
        if other is None or _norm(other) == value:
            return None
    # (a condition that waits for the flag's own value: `SURFACED = true`, `== true`)
    wanted = (f"{var}={value}".lower(), f"{var}=={value}".lower())
    waiting = sorted(
        {
            r.app
            for r in model.waits
            if var in r.read_names
            and r.app
            and id(r.line) not in own
            and any(w in "".join(r.line.text.split()).lower() for w in wanted)
        }
    )
    return (var, waiting) if waiting else None


def _waiters(apps: list[str]) -> str:
    """The conditions that wait, as the message names them (``helm``: a mode's)."""
    kinds = [a for a in apps if a != "helm"]
    parts = [f"the conditions of {listed(kinds)}"] if kinds else []
    if "helm" in apps:
        parts.append("the helm's `set MODE` blocks")
    return listed(parts)


def _norm(value: str) -> str:
    """A posted value as a condition compares it: unquoted, without blanks, and in lower
    case (the helm's conditions compare booleans and words without regard to case)."""
    return "".join(value.split()).strip("\"'").lower()


def _never_timed_out(bhv, info) -> str | None:
    """How the behavior is left without a duration (its last ``duration`` line, or the
    kind's default), or None when a duration may end it."""
    lines = bhv.get("duration")
    if any(has_macro(p.value) or p.line.branches for p in lines):
        return None
    if lines:
        value = lines[-1].value.strip()
        return f"`duration = {value}` gives it no time limit" if value in NO_TIME_LIMIT else None
    default = info.defaults.get("duration")
    if default is not None and default[0] not in NO_TIME_LIMIT:
        return None  # (it ends at once: behavior-completes-at-once says so)
    return "it has no duration"


def _duration_by_update(model, bhv) -> bool:
    """Whether an update may give the behavior a duration: an update string of the
    mission that sets one, or a posting to its ``updates`` variable whose value the
    mission does not show (another community, an app, a launch script's poke)."""
    updates = bhv.get("updates")
    if not updates:
        return False
    var = updates[-1].value.strip()
    if has_macro(var) or model.receives:
        return True
    if any(p.how not in ("config", "behavior") for p in model.published_by(var)):
        return True
    for ref in model.refs:
        if ref.role != PUBLISH or ref.name != var:
            continue
        value = value_after(ref)
        if value is None:
            return True
        keys = (piece.partition("=")[0].strip().strip("\"'").lower() for piece in value.split("#"))
        if "duration" in keys:
            return True
    return False
