"""A condition compares a variable with a value the mission posts only in another case.

## What it does
In a mission (after nsplug expansion, with its behavior files), takes every
logic condition that compares a variable with a word (`AT_HOME = FALSE`,
`MODE == returning`, `STATE != Done`) and every value the mission posts to
that variable: behavior flags (`endflag = AT_HOME = true`), `initialize`,
`set MODE = ... {} ELSE` values, uTimerScript events (`var=X, val=Y`),
pMarineViewer buttons and the like. It reports the comparison when the word
equals a posted value only when case is ignored (`FALSE` against `false`).

It judges a variable only when every publisher of it in the mission is such
a `VAR = value` whose value is written out: a variable an app posts, a person
pokes, another community sends, or a launched app the catalogue does not know
might post, is left alone.

## Why is this bad?
lib_logic compares strings exactly, case included (`ParseNode::evaluate`:
`left == right`; `==` matches `:`-separated fields exactly, `strFieldMatch`).
A condition waiting for `AT_HOME = FALSE` when the flags post `false` never
holds: the behavior never runs, and nothing says why. A `!=` against such a
word always holds.

## Example
```bhv
initialize AT_HOME = false

Behavior = BHV_StationKeep
{
  name      = keep
  condition = AT_HOME = FALSE     // the mission posts `false`
  endflag   = AT_HOME = true
}
```

## How to fix
Write the value as the mission posts it (`AT_HOME = false`). The fix does it
when one posted value matches.

## Options
None.
"""

from __future__ import annotations

from moos_lint.files.diagnostics import Edit, Fix, Severity, Subject
from moos_lint.rules.kit.declare import Kind, Scope, rule
from moos_lint.rules.mission._posted import all_written, compared_once, posted_values
from moos_lint.semantics.mission_model import mission_model


@rule(
    code="M007",
    name="condition-value-case",
    severity=Severity.WARNING,
    scope=Scope.MISSION,
    kinds=(Kind.MOOS,),
    fixable=True,
)
def check(ctx):
    model = mission_model(ctx)
    if model.unknown_apps or model.unresolved_behaviors:
        return  # a process or behavior the model cannot see may post any value
    if model.receives and not model.sibling_missions:
        return  # values may come from a community the linter cannot see
    posted = posted_values(model)
    seen: set[tuple[str, int, int]] = set()
    for ref in model.waits:
        var = ref.name
        values = posted.get(var)
        if not values or None in values:
            continue
        pubs = model.published_by(var)
        if not pubs or not all_written(pubs):
            continue
        found = compared_once(ref, seen)
        if found is None:
            continue
        op, word, start = found
        known = {v for v in values if v is not None}
        fields = known | {f.strip() for v in known for f in v.split(":")} if op == "==" else known
        if word in fields:
            continue
        alike = sorted({f for f in fields if f.lower() == word.lower()})
        if not alike:
            continue
        shown = " or ".join(f"`{v}`" for v in sorted(known))
        outcome = "always holds" if op == "!=" else "never holds"
        msg = (
            f"`{var} {op} {word}`: the mission posts `{var}` only as {shown}, and lib_logic "
            f"compares strings with their case, so this {outcome}"
        )
        span = ref.line.span(start, start + len(word))
        fix = None
        if len(alike) == 1:
            fix = Fix(f"write `{alike[0]}`", (Edit(span, alike[0]),))
        subject = Subject(variable=var, app=ref.app or None, key=ref.param)
        yield ctx.report(span, msg, line=ref.line, fix=fix, subject=subject)
