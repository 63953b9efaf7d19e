"""A behavior parameter that the behavior does not read (`capture_raduis`).

## What it does
For each behavior of a kind the catalogue describes, reports a parameter that
neither the behavior's `setParam` nor its base classes (`IvPBehavior`'s
generic keys: `name`, `pwt`, `condition`, `endflag`, `updates`, ...;
`IvPContactBehavior`'s contact keys) nor the helm's behavior spec
(`templating`, `max_spawnings`) accept. Keys are compared as the helm compares
them: in lower case, with a leading `_` ignored. A close known parameter is
suggested, and when there is exactly one, a slip away from the key (one
letter inserted, deleted, replaced or two swapped, as unknown-parameter
counts them) or a key an older release read, it is offered as a fix.

A parameter an older MOOS-IvP's behavior read is reported as such
(`activation_dist`, which BHV_AvoidObstacle read in 2015), with a respelling
only when one is close: the mission was likely written for that release.
Today's helm rejects it all the same. The older keys are those that MOOS-IvP of
June 2012, June 2015, June 2017, August 2019, January 2021, August 2022 and
August 2023 read and that the behavior files of that tree set
(`retired.json`, written by `scripts/retired_keys.py` from their sources).

## Why is this bad?
The helm is strict: an unknown parameter fails the behavior ("Line N: ..."),
the behavior set is rejected and the helm posts `IVPHELM_STATE = MALCONFIG`.

## Example
```bhv
Behavior = BHV_Waypoint
{
  name           = transit
  points         = 0,0 : 100,0
  capture_raduis = 5     // capture_radius
}
```

## How to fix
Respell the parameter, or delete it.

## Options
None.

MOOS-IvP caveats, deliberately not reported:
- behaviors of kinds the catalogue does not describe (the project's own
  behaviors, unless a catalogue file lists their parameters);
- parameters holding an nsplug macro;
- in a project that builds its own helm (a vendored, often older, MOOS-IvP:
  a `lib_helmivp/BFactoryStatic.cpp` in a `src` or `ivp/src` folder at or
  above the behavior file's), a parameter that its own copy of a stock
  behavior beside it names (`src/*/BHV_AvoidCollision.cpp` holding `"key"`):
  that helm runs its copies (`active_grade`, read by MOOS-IvP 15.5's
  BHV_AvoidCollision). A project's own `BHV_ZigZag` without
  its own helm is not: the helm makes stock kinds itself before it loads any
  library, so MOOS-IvP's BHV_ZigZag runs and judges the parameters.
"""

from moos_lint.files.diagnostics import Edit, Fix, Severity
from moos_lint.frontends.parsers.nodes import has_macro
from moos_lint.rules.kit.declare import Kind, Scope, rule
from moos_lint.rules.kit.spelling import cased_like, slip
from moos_lint.rules.mission._behaviors import lookup, own_source_keys
from moos_lint.rules.mission.unknown_parameter import suggestions
from moos_lint.semantics.catalogue import catalogue_for


@rule(
    code="M004",
    name="unknown-behavior-parameter",
    severity=Severity.ERROR,
    scope=Scope.FILE,
    kinds=(Kind.BHV,),
    fixable=True,
)
def check(ctx):
    for bhv in ctx.bhv.behaviors:
        info, _known = lookup(ctx, bhv.kind.strip())
        if info is None or not info.params:
            continue
        for p in bhv.params:
            key = p.lkey
            if not key or key in info.params or has_macro(p.key):
                continue
            if key in own_source_keys(ctx, bhv.kind.strip(), ctx.path):
                continue  # the project's own copy of the behavior reads it
            old = catalogue_for(ctx.run).retired_key("behaviors", info.name, key)
            close = [cased_like(p.key.strip(), c) for c in suggestions(key, info.params)]
            msg = f"`{p.key.strip()}`: {info.name} has no such parameter"
            if old is not None:
                msg = (
                    f"`{p.key.strip()}`: {info.name} no longer has this parameter (MOOS-IvP of "
                    f"{old} read it, and today's helm rejects the behavior file: written for an "
                    "older release?)"
                )
            fix = None
            if close:
                msg += "; did you mean " + " or ".join(f"`{c}`" for c in close) + "?"
            if len(close) == 1 and (old is not None or slip(p.key.strip(), close[0])):
                fix = Fix(f"respell as `{close[0]}`", (Edit(p.key_span, close[0]),))
            yield ctx.report(p.key_span, msg, line=p.line, fix=fix)
