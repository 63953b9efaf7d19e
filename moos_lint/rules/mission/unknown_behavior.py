"""A `Behavior = BHV_X` whose kind the helm does not know (`BHV_Waypiont`).

## What it does
Reports a misspelt behavior kind: one a typo or two away from a known kind,
and neither a stock MOOS-IvP behavior (the
catalogue lists every `BHV_*` class of moos-ivp: `BHV_Waypoint`,
`BHV_Loiter`, `BHV_AvdColregsV22`, ...), nor a behavior described in a
catalogue file (`catalogues = [...]`), nor a class of the linted project (a
C++ file named after the kind, `BHV_Pulse.cpp`, anywhere under the project:
the folder of the configuration file, else the version-control root above
the behavior file, else the behavior file's folder; MOOS-IvP behaviors are
named after their file). The kind is compared
without regard to case. It reports a kind a typo or two away from a known one
(the project's own, the stock and the catalogue ones; a missing `BHV_` counts
as one typo), suggests those, and offers the single one as a fix.

A kind that no known kind is a typo or two away from (`BHV_Scout`,
`BHV_Cover`, and `BHV_SailWaypoint` or `BHV_SimpleWaypoint`, named like
`BHV_Waypoint` but other behaviors) is most often a behavior of another tree (a
course's, a team's), which the helm loads through `IVP_BEHAVIOR_DIRS` or
`ivp_behavior_dir` from outside the project: it is reported only with the
`all-kinds` option, with the known kinds whose names are like it.

## Why is this bad?
The helm cannot build the behavior: it reports "failed to load dynamic
behavior ... Check IVP_BEHAVIOR_DIRS", the whole behavior set fails and the
helm posts `IVPHELM_STATE = MALCONFIG`. The vehicle never leaves the dock.

## Example
```bhv
Behavior = BHV_Waypiont     // BHV_Waypoint
{
  name   = transit
  points = 0,0 : 100,0
}
```

## How to fix
Respell the kind. For a behavior of your own that lives in another
repository, describe it in a catalogue file (`[behaviors.BHV_Mine]`).

## Options
- `all-kinds` (boolean, default false): also report a kind that no known kind
  is a typo or two away from (`BHV_Teleport`, `BHV_SimpleWaypoint`), for a
  project that holds every behavior its missions load, or whose other trees
  are described in catalogue files.

MOOS-IvP caveats, deliberately not reported:
- a kind holding an nsplug macro;
- a kind with a C++ file of the same name in the project (its own behavior,
  loaded through `ivp_behavior_dir`), a `BHV_*` class declared in one of the
  project's headers, or a `BHV_*` library a CMakeLists.txt of the project
  builds (the helm loads `libBHV_X.so` by the kind's name);
- a kind that is not a name (`Behavior = ??` in a template);
- a kind that MOOS-IvP's editor mode (`editor-modes/moos-bhvs.el`) lists but
  the moos-ivp tree does not build: the behaviors of MIT's other public trees
  (`BHV_TaskMuster`, `BHV_MusterX`, `BHV_ConvoyV21`, `BHV_LegRunX`, ...), which
  missions load from those trees through `IVP_BEHAVIOR_DIRS`. Their parameters
  are not judged (unknown-behavior-parameter knows no list for them).
"""

import difflib
import os
import re

from moos_lint.files.diagnostics import Edit, Fix, Severity
from moos_lint.frontends.parsers.nodes import has_macro
from moos_lint.rules.kit.declare import Kind, Scope, rule
from moos_lint.rules.kit.spelling import typos
from moos_lint.rules.mission._behaviors import _root, lookup, repo_behaviors
from moos_lint.semantics.catalogue import catalogue_for

_IDENT = re.compile(r"[A-Za-z_][A-Za-z0-9_]*")
#: a respelling is offered as a fix only this many letter edits away (a typo, not another
#: behavior: BHV_SimpleWaypoint is not a misspelt BHV_Waypoint)
MAX_TYPOS = 2


def _shown(folder: str) -> str:
    """The searched folder, relative to the working folder when it lies under it."""
    rel = os.path.relpath(folder)
    return "the working folder" if rel == "." else f"`{folder if rel.startswith('..') else rel}`"


@rule(
    code="M003",
    name="unknown-behavior",
    severity=Severity.ERROR,
    scope=Scope.FILE,
    kinds=(Kind.BHV,),
    fixable=True,
    options={"all-kinds": False},
)
def check(ctx):
    cat = catalogue_for(ctx.run)
    for bhv in ctx.bhv.behaviors:
        kind = bhv.kind.strip()
        if not kind or has_macro(kind) or not _IDENT.fullmatch(kind):
            continue  # `Behavior = ??` in a template is a placeholder, not a kind
        _info, known = lookup(ctx, kind)
        if known:
            continue
        # the project's and the catalogue's behaviors first: the others only when none of
        # those is close; of the close ones, those a typo or two away if any
        own = {b.name.lower(): b.name for b in cat.behaviors.values()} | repo_behaviors(ctx)
        close = _close(kind, own) or _close(kind, cat.outside_behaviors)
        near = [c for c in close if _typos_away(kind, c) <= MAX_TYPOS]
        if not near and not ctx.options.get("all-kinds"):
            # a behavior of another tree, most often, even when its name is like a known
            # one's (BHV_SailWaypoint, BHV_SimpleWaypoint: not misspelt BHV_Waypoints)
            continue
        close = near or close
        msg = f"`{kind}`: no such helm behavior (not a stock behavior, not in a catalogue file, "
        msg += f"no C++ file, class or library of that name under {_shown(_root(ctx))})"
        fix = None
        if close:
            msg += "; did you mean " + " or ".join(f"`{c}`" for c in close) + "?"
        if len(near) == 1:
            fix = Fix(f"respell as `{near[0]}`", (Edit(bhv.kind_span, near[0]),))
        yield ctx.report(bhv.kind_span, msg, line=bhv.header, fix=fix)


def _close(kind: str, names: dict[str, str]) -> list[str]:
    """The names (lower case -> as written) close to ``kind``, closest first."""
    return [names[c] for c in difflib.get_close_matches(kind.lower(), names, n=3, cutoff=0.75)]


def _typos_away(kind: str, name: str) -> int:
    """How many typos make ``kind`` into ``name``; a missing ``BHV_`` is one
    (``Behavior = Waypoint``)."""
    found = typos(kind, name)
    if not kind.lower().startswith("bhv_"):
        found = min(found, 1 + typos("BHV_" + kind, name))
    return found
