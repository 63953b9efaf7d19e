"""A behavior that ends on its first iteration: `duration = 0`, or a ConstantSpeed without one.

## What it does
Reports a behavior that is not perpetual and whose duration is 0:

- written so, `duration = 0` (any kind), when the behavior posts no
  `endflag`: a behavior that ends at once and posts nothing when it ends does
  nothing at all;
- by its kind's default, when the behavior gives no `duration`: the
  ConstantSpeed, ConstantHeading, ConstantDepth and MaintainHeading
  behaviors set their duration to 0 in their constructors ("we force the
  user to provide a duration value otherwise it will timeout immediately",
  BHV_ConstantHeading.cpp), where every other behavior has no time limit.
  The catalogue records each such default with the MOOS-IvP line that sets
  it.

A behavior is perpetual when its `perpetual` value is `true` in any case
(IvPBehavior compares `tolower(value) == "true"`: `perpetual = yes` is not).

## Why is this bad?
The helm ends a behavior once its running time reaches its duration
(`IvPBehavior::durationExceeded`: `elapsed_time >= m_duration`). The clock
starts at 0 when the behavior's conditions first hold, so with a duration of
0 the behavior completes on its first iteration, before it produces an
objective function: the vehicle never takes its speed, heading or depth, and
the helm says only `completed-byduration` in the behavior's status.
`duration = 0 // default` is what the behaviors' `--example` output prints.

## Example
```bhv
Behavior = BHV_ConstantSpeed
{
  name      = hold_still
  condition = ONSURFACE = true
  speed     = 0               // no duration: this kind's default is 0
}
```

## How to fix
Give the time the behavior should run, in seconds (`duration = 60`), or
`duration = no-time-limit`; or make it `perpetual = true` when it should
restart whenever its conditions hold again.

## Options
None.

MOOS-IvP caveats, deliberately not reported:
- a perpetual behavior: the helm resets its clock and it keeps running (it
  posts its end flags at every iteration);
- `duration = 0` with an `endflag`: a behavior used to post its flags once
  when its conditions first hold;
- a behavior whose `updates` variable the files beside it post with a
  `duration=` (a uTimerScript event, a button): the duration may change
  before it runs;
- a duration or `perpetual` value holding an nsplug macro, and a kind the
  project builds its own helm copy of (its default may differ).
"""

from __future__ import annotations

import os
import re

from moos_lint.files.diagnostics import Severity, Subject
from moos_lint.files.source import read_head
from moos_lint.frontends.parsers.nodes import has_macro
from moos_lint.rules.kit.declare import Kind, Scope, rule
from moos_lint.rules.mission._behaviors import lookup, own_source_keys
from moos_lint.semantics.mbutil import is_number

#: the files beside a behavior file that may post its updates (missions, behavior files,
#: launch scripts)
_BESIDE = (".moos", ".bhv", ".plug", ".sh")


@rule(
    code="M008",
    name="behavior-completes-at-once",
    severity=Severity.WARNING,
    scope=Scope.FILE,
    kinds=(Kind.BHV,),
)
def check(ctx):
    for bhv in ctx.bhv.behaviors:
        perpetual = bhv.get("perpetual")
        if perpetual and (
            has_macro(perpetual[-1].value) or perpetual[-1].value.strip().lower() == "true"
        ):
            continue
        kind = bhv.kind.strip()
        durations = bhv.get("duration")
        name = bhv.name.value.strip() if bhv.name is not None else ""
        label = f"{kind} `{name}`" if name else kind
        if durations:
            dur = durations[-1]
            value = dur.value.strip()
            if has_macro(value) or not is_number(value) or float(value) != 0:
                continue
            if bhv.get("endflag") or bhv.get("end_flag") or _updated(ctx.path, bhv):
                continue
            msg = (
                f"`duration = {value}`: {label} completes on its first iteration (the helm "
                "ends a behavior that is not perpetual once its running time reaches its "
                "duration), before it produces an objective function; give it the seconds "
                "it should run, or `no-time-limit`"
            )
            span, line = dur.value_span, dur.line
        else:
            info, _known = lookup(ctx, kind)
            default = info.defaults.get("duration") if info is not None else None
            if default is None or float(default[0]) != 0:
                continue
            if own_source_keys(ctx, kind, ctx.path) or _updated(ctx.path, bhv):
                continue
            msg = (
                f"{label} has no `duration`, and this kind's default is 0 ({default[1]}): it "
                "completes on its first iteration, before it produces an objective function; "
                "give it the seconds it should run, `duration = no-time-limit`, or "
                "`perpetual = true`"
            )
            span, line = bhv.kind_span, bhv.header
        yield ctx.report(span, msg, line=line, subject=Subject(key="duration"))


def _updated(path: str, bhv) -> bool:
    """Whether a file beside the behavior file posts a ``duration=`` to the behavior's
    ``updates`` variable (``CONST_SPD_UPDATES = duration=30``)."""
    names = [p.value.strip() for p in bhv.get("updates") if p.value.strip()]
    if not names:
        return False
    if any(has_macro(n) for n in names):
        return True
    pattern = re.compile(
        rb"\b(?:" + b"|".join(re.escape(n.encode()) for n in names) + rb")\b[^\n]*duration",
        re.IGNORECASE,
    )
    folder = os.path.dirname(os.path.abspath(path))
    try:
        entries = sorted(os.listdir(folder))
    except OSError:
        return True
    for entry in entries:
        if entry.endswith(_BESIDE):
            data = read_head(os.path.join(folder, entry), 1024 * 1024)
            if data is not None and pattern.search(data):
                return True
    return False
