"""A parameter that holds one value given twice in a block with different values (`AppTick`).

## What it does
Reports a second line for a parameter that the app or behavior keeps one
value of, when the two lines differ:

- in a ProcessConfig block, a key whose value form the catalogue records
  (a boolean, a number, one of a set of words: uTimerScript's `reset_max`,
  pContactMgrV20's `contact_max_age`), and every app's `AppTick`,
  `CommsTick` and `MaxAppTick`;
- in a behavior, such a key of its kind, and IvPBehavior's own `updates`,
  `duration`, `perpetual` and `pwt`.

Keys that may repeat are left alone: lists and shapes (uFldNodeBroker's
`bridge`, a polygon), and every key the catalogue has no form for
(`behaviors`, `event`, `condition`, `endflag`).

The message says which line holds:
- `AppTick`, `CommsTick` and `MaxAppTick` are read with
  `GetConfigurationParam`, which returns the first line naming the key
  (ProcessConfigReader.cpp): the second line is ignored;
- an app's own parser and a behavior's `setParam` take the block's lines
  in turn, each setting the same member: the last line wins, and the first
  does nothing. A line whose value the parser refuses (`reset_max = no_limit`,
  where uTimerScript takes `nolimit`) sets nothing: the line before it holds,
  and invalid-parameter-value reports the refused one.

## Why is this bad?
Only one of the two values is used, without a word, and it is often not the
one the author looks at: `AppTick = 10` then `AppTick = 4` runs the helm at
10 Hz. A second `updates = RETURN_UPDATES` replaces the first variable, so
the updates posted to the first are never applied.

## Example
```moos
ProcessConfig = pHelmIvP
{
  AppTick = 10
  AppTick = 4        // ignored: CMOOSApp reads the first
}
```

## How to fix
Keep one line, with the value meant.

## Options
None.

MOOS-IvP caveats, deliberately not reported: lines in different branches of an
nsplug `#ifdef`, lines on the two sides of a merge conflict left in the file
(bhv-invalid-line reports its markers), a value holding a macro, a boolean
`toggle`, two lines with the same value, and two words one branch of the
parser takes alike (uTimerScript's `reset_time = end` and `reset_time =
all-posted` both set it to 0, TS_MOOSApp.cpp: the catalogue records such words
with the key's form).
"""

from __future__ import annotations

import os
from typing import Any

from moos_lint.files.diagnostics import Severity, Subject
from moos_lint.frontends.parsers.nodes import conflict_marker, has_macro
from moos_lint.rules.kit.declare import Kind, Scope, rule
from moos_lint.rules.mission._behaviors import lookup
from moos_lint.rules.mission.invalid_parameter_value import problem
from moos_lint.rules.mission.unknown_parameter import block_apps
from moos_lint.semantics.catalogue import FIRST_LINE_AT, catalogue_for, single_valued
from moos_lint.semantics.mbutil import BOOLEAN_GROUPS


@rule(
    code="M010",
    name="duplicate-parameter",
    severity=Severity.WARNING,
    scope=Scope.FILE,
    kinds=(Kind.MOOS, Kind.BHV),
)
def check(ctx):
    cat = catalogue_for(ctx.run)
    if ctx.moos is not None:
        commit = cat.source.get("commit", "")[:8]
        first_at = f"moos-ivp {commit} {FIRST_LINE_AT}"
        for block, app in block_apps(ctx):
            yield from _repeats(ctx, block.params, app.name, app.forms, {}, first_at, cat)
    if ctx.bhv is not None:
        single = cat.single_behavior_params
        for bhv in ctx.bhv.behaviors:
            info, _known = lookup(ctx, bhv.kind.strip())
            if info is not None:
                yield from _repeats(ctx, bhv.params, info.name, info.forms, single, "", cat)


def _repeats(ctx, params, owner: str, forms: dict, single: dict, first_at: str, cat):
    """A finding for each later line of a one-value key that differs from the first."""
    first: dict[str, Any] = {}
    for p in params:
        key = p.lkey
        form = forms.get(key)
        holds = single_valued(form[0]) if form is not None else ("last" if key in single else None)
        value = p.value.strip()
        if holds is None or has_macro(value) or has_macro(p.key) or value.lower() == "toggle":
            continue
        if holds == "last" and form is not None and _rejected(form[0], value):
            continue  # the parser refuses it and keeps what it had (invalid-parameter-value)
        earlier = first.get(key)
        if earlier is None:
            first[key] = p
            continue
        before = earlier.value.strip()
        if before == value or (
            form and form[0] == "bool" and _alike(BOOLEAN_GROUPS, before, value)
        ):
            continue  # (`true`, `True` and `yes` set a boolean alike)
        if (
            form
            and form[0] == "true_word"
            and (before.lower() == "true") == (value.lower() == "true")
        ):
            continue  # (`true` and `TRUE` set it alike, and so do `false` and `no`)
        if form and _alike(cat.same_values.get(form[1], ()), before, value):
            continue  # two words the parser stores alike (`end`, `all-posted`)
        if earlier.line.excludes(p.line):
            continue  # two branches of one #ifdef
        if _across_conflict(ctx, earlier.line, p.line):
            continue  # the two sides of a merge conflict (bhv-invalid-line reports it)
        where = f"line {earlier.line.lineno}"
        if earlier.line.path != p.line.path:
            where += f" of {os.path.basename(earlier.line.path)}"
        said = f"`{earlier.key.strip()} = {before}` ({where})"
        if holds == "first":
            msg = (
                f"`{p.key.strip()} = {value}`: {owner} already has {said}, and CMOOSApp reads "
                f"the first line naming a key ({first_at}): this line is ignored"
            )
        else:
            at = form[1] if form is not None else single[key]
            msg = (
                f"`{p.key.strip()} = {value}`: {owner} already has {said}, and it keeps one "
                f"value, set by each line in turn ({at}): this line wins, and {where} does "
                "nothing"
            )
        yield ctx.report(p.value_span, msg, line=p.line, subject=Subject(app=owner, key=key))


def _alike(groups, a: str, b: str) -> bool:
    """Whether two values are words of one group the parser stores alike (it compares
    them lower-cased)."""
    return any(a.lower() in g and b.lower() in g for g in groups)


def _rejected(form: str, value: str) -> bool:
    """Whether a parser that sets the member line by line refuses ``value`` and leaves the
    member as it was (uTimerScript's `reset_max = no_limit` after `reset_max = 5000`: the
    5000 holds). A number beyond a ``clip:`` bound is taken, as the bound."""
    if form.startswith("clip:") or form == "true_word":
        return False  # taken: as the bound, or as false (`perpetual = yes`)
    return problem(form, value) is not None


def _across_conflict(ctx, first, second) -> bool:
    """Whether a merge-conflict marker (``=======``) stands between two lines of one file:
    they are the two sides of a conflict, and resolving it keeps one."""
    if first.path != second.path:
        return False
    return any(
        line.path == first.path
        and first.lineno < line.lineno < second.lineno
        and conflict_marker(line.text)
        for line in ctx.expansion.lines
    )
