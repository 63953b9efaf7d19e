"""An update string that sets a parameter the behavior it updates does not have.

## What it does
In a mission (after nsplug expansion, with its behavior files), takes each
posting whose value the mission writes out (a behavior flag, a uTimerScript
event, a pMarineViewer button or action, ...) to a variable that a behavior
reads its updates from (`updates = WPT_UPDATE`). The value is an update
string: `param=value` pieces separated by `#`. Reports a piece whose
parameter that behavior does not take, judged as unknown-behavior-parameter
judges the behavior file's own lines (the behavior's `setParam` and its base
classes, in lower case). An update naming a behavior (`name=survey`) is
judged against that behavior only, as the helm applies it. When one
variable feeds behaviors of several kinds, each of them must take the
parameter: `endflag = WPT_UPDATE = depth=0` read by a BHV_ConstantDepth and
a BHV_Waypoint fails in the waypoint.

Not judged: behaviors of kinds the catalogue does not describe, values with
an nsplug macro or a run-time placeholder, a parameter the project's own copy
of the behavior reads (as unknown-behavior-parameter), and pieces after a `#`
where the posting's own syntax ends its value there (a viewer button's next
pair).

## Why is this bad?
The helm applies the pieces it can and rejects the others: it posts
`BHV_WARNING` "Faulty update for behavior: survey. Bad parameter(s): depth"
(`IvPBehavior::checkUpdates`) at every such update, and the change the
button or flag was meant to make never happens.

## Example
```moos
ProcessConfig = pMarineViewer
{
  button_one = SLOW # WPT_UPDATE=speeed=1   // BHV_Waypoint has `speed`
}
```

## How to fix
Respell the parameter, or post the update to the behavior that has it.

## Options
None.
"""

from __future__ import annotations

import re

from moos_lint.files.diagnostics import Severity, Subject
from moos_lint.frontends.parsers.nodes import has_macro
from moos_lint.rules.kit.declare import Kind, Scope, rule
from moos_lint.rules.kit.wording import listed
from moos_lint.rules.mission._behaviors import lookup, own_source_keys
from moos_lint.rules.mission._posted import value_after
from moos_lint.rules.mission.unknown_parameter import suggestions
from moos_lint.semantics.catalogue import catalogue_for
from moos_lint.semantics.mission_model import mission_model
from moos_lint.semantics.variables import PUBLISH

#: a parameter's name
_KEY = re.compile(r"[A-Za-z_][\w.]*")


@rule(
    code="M013",
    name="unknown-update-parameter",
    severity=Severity.WARNING,
    scope=Scope.MISSION,
    kinds=(Kind.MOOS,),
)
def check(ctx):
    model = mission_model(ctx)
    #: an updates variable -> (behavior name, kind, its parameters, its file) of each reader
    readers: dict[str, list[tuple[str, str, set[str], str]]] = {}
    for path, bf in model.behavior_files:
        for bhv in bf.behaviors:
            updates = [p.value.strip() for p in bhv.params if p.lkey == "updates"]
            if not updates or has_macro(updates[-1]):
                continue
            kind = bhv.kind.strip()
            info, _known = lookup(ctx, kind)
            if info is None or not info.params:
                continue
            name = bhv.name.value.strip() if bhv.name is not None else ""
            readers.setdefault(updates[-1], []).append((name, info.name, info.params, path))
    if not readers:
        return
    cat = catalogue_for(ctx.run)
    for ref in model.refs:
        if ref.role != PUBLISH or ref.name not in readers:
            continue
        value = value_after(ref)  # (None when it holds a macro or a placeholder)
        if value is None:
            continue
        pieces = [piece.strip().strip("\"'").partition("=") for piece in value.split("#")]
        if any(not sep or not _KEY.fullmatch(key.strip()) for key, sep, _v in pieces):
            continue  # not an update string
        keys = [key.strip() for key, _sep, _v in pieces]
        named = [v.strip() for key, _sep, v in pieces if key.strip().lower() == "name"]
        updated = [r for r in readers[ref.name] if not named or named[-1] == r[0]]
        lacking = []  # (behavior, kind, the keys it lacks)
        for bname, kind, params, path in updated:
            bad = [k for k in keys if k.lower() != "name" and k.lower().lstrip("_") not in params]
            if bad:  # (what the project's own copy of the behavior reads, asked only now)
                own = own_source_keys(ctx, kind, path)
                bad = [k for k in bad if k.lower().lstrip("_") not in own]
            if bad:
                lacking.append((bname or kind, kind, bad))
        if not lacking:
            continue
        yield ctx.report(
            ref.span,
            _message(cat, ref.name, updated, lacking, len(keys)),
            line=ref.line,
            subject=Subject(variable=ref.name, app=ref.app, key=ref.param),
        )


def _message(cat, var: str, updated, lacking, pieces: int) -> str:
    """What the update sets that its behaviors do not have, and what the helm does."""
    who = listed([f"`{b or k}` ({k})" for b, k, _p, _f in updated])
    first_bad = lacking[0][2]
    same = all(bad == first_bad for _b, _k, bad in lacking) and len(lacking) == len(updated)
    keys = ", ".join(f"`{k}`" for k in first_bad)
    if len(updated) == 1:
        what = f"`{var}` updates behavior {who}, which has no parameter {keys}"
    elif same:
        none = "neither" if len(updated) == 2 else "none of them"
        what = f"`{var}` updates {who}, and {none} has a parameter {keys}"
    else:
        by_bad: dict[tuple[str, ...], list[str]] = {}
        for b, _k, bad in lacking:
            by_bad.setdefault(tuple(bad), []).append(f"`{b}`")
        each = "; ".join(
            listed(names)
            + (" have" if len(names) > 1 else " has")
            + " no parameter "
            + ", ".join(f"`{k}`" for k in bad)
            for bad, names in by_bad.items()
        )
        what = f"`{var}` updates {who}, and {each}"
    others = ", applying the other pieces," if len(first_bad) < pieces else ""
    hint = ""
    bname, kind, bad = lacking[0]
    if len(bad) == 1:
        params = next(p for b, k, p, _f in updated if (b or k) == bname)
        close = suggestions(bad[0].lower(), params)
        hint = f"; did you mean `{close[0]}`?" if len(close) == 1 else ""
        old = cat.retired_key("behaviors", kind, bad[0].lower())
        if old is not None:
            hint = f" (MOOS-IvP of {old} read it: written for an older release?){hint}"
    return (
        f"{what}: the helm rejects it{others} and posts `BHV_WARNING` 'Faulty update for "
        f"behavior' each time it is posted{hint}"
    )
