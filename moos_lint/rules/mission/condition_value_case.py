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

import re

from moos_lint.files.diagnostics import Edit, Fix, Severity, Subject
from moos_lint.rules.kit.declare import Kind, Scope, rule
from moos_lint.semantics.mbutil import is_number
from moos_lint.semantics.mission_model import mission_model
from moos_lint.semantics.variables import PUBLISH

#: a relation after the variable's name in a condition, and the word it compares with
_RELATION = re.compile(r'\s*(==|!=|=)\s*("[^"]*"|[^\s()"]+)')
#: what ends a posted value: a button's next pair, a flag's condition, a block's brace
_VALUE_END = re.compile(r"#|\[if\]|\{|//")
_EVENT_VAL = re.compile(r"\bval\s*=\s*([^,]*)", re.IGNORECASE)
#: publishers whose value is written in the mission (the others may post anything)
_WRITTEN = ("config", "behavior")


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
    if model.inbound and not model.sibling_missions:
        return  # values may come from a community the linter cannot see
    posted = _posted_values(model)
    # the helm posts a `set` block's variable with the values its blocks write
    helms = {p.name for p in model.processes if p.binary.lower() == "phelmivp"}
    modes = {sb.mode_var for _path, bf in model.behavior_files for sb in bf.sets}
    seen: set[tuple[str, int, int]] = set()
    for ref in model.waits:
        var = ref.name
        values = posted.get(var)
        if not values or None in values:
            continue
        pubs = [p for p in model.published_by(var) if not (var in modes and p.who in helms)]
        if not pubs or any(p.how not in _WRITTEN or p.line is None for p in pubs):
            continue
        found = _compared(ref)
        if found is None:
            continue
        op, word, start = found
        key = (ref.line.path, ref.line.lineno, start)
        if key in seen:
            continue
        seen.add(key)
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


def _compared(ref) -> tuple[str, str, int] | None:
    """(relation, word, start of the word in the line) of a condition's ``VAR op word``,
    when the word is text (not a number, a variable's macro or a run-time placeholder)."""
    end = ref.start + len(ref.name)
    m = _RELATION.match(ref.line.text, end)
    if m is None:
        return None
    word, start = m.group(2), m.start(2)
    if word.startswith('"'):
        word, start = word[1:-1], start + 1
    if not word or "$" in word or is_number(word):  # lib_logic's test (ParseNode.cpp)
        return None
    return m.group(1), word, start


def _posted_values(model) -> dict[str, list[str | None]]:
    """Variable -> the values the mission's own lines post to it (None: a value that is
    not written out)."""
    out: dict[str, list[str | None]] = {}
    for ref in model.refs:
        if ref.role == PUBLISH:
            out.setdefault(ref.name, []).append(_value_after(ref))
    for _path, bf in model.behavior_files:
        for sb in bf.sets:
            if sb.else_value is not None:
                out.setdefault(sb.mode_var, []).append(_clean(sb.else_value))
    return out


def _value_after(ref) -> str | None:
    """The value a ``VAR = value`` (or a uTimerScript ``var=VAR, val=value``) posts."""
    text = ref.line.text
    m = re.match(r"\s*=\s*", text[ref.start + len(ref.name) :])
    if m is not None:
        rest = text[ref.start + len(ref.name) + m.end() :]
        cut = _VALUE_END.search(rest)
        return _clean(rest[: cut.start()] if cut else rest)
    if ref.param == "event":
        v = _EVENT_VAL.search(text)
        return _clean(v.group(1)) if v else None
    return None


def _clean(value: str) -> str | None:
    value = value.strip()
    if len(value) >= 2 and value[0] == value[-1] == '"':
        value = value[1:-1]
    return None if not value or "$" in value else value
