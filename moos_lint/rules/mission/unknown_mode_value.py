"""A condition compares a mode variable with a mode its set blocks never declare.

## What it does
In a mission (after nsplug expansion, with its behavior files), takes each
variable the helm's hierarchical mode declarations set (`set MODE = SURVEYING
{ MODE = ACTIVE ... } RETURNING`) and works out every value the helm may post
to it, as `ModeSet::evaluate` builds them: the block's value or its else
value, after its prefix (the first condition of the form `MODE = ACTIVE`),
`ACTIVE:SURVEYING`. Values the mission's other lines write out (an
`initialize`, a flag, a uTimerScript event) count too. A block whose prefix
is none of those values (`MODE = ACTIV`) never posts its own.

It then reports a condition on that variable (`condition = MODE ==
STATION-KEEPING`, a set block's own `MODE = ACTIVE`) whose word holds a
`:`-separated mode name that none of those values has: the mode was renamed,
misspelled or never declared (or an empty name, `ACTIVE::SURVEYING`). A name
the values hold in another case is left to condition-value-case.

When the helm loads one behavior file of several (`behaviors =
targ_$(VNAME).bhv`, made from each vehicle's `meta_*.bhv`), a condition is
judged against the set blocks of its own file: another vehicle's modes do
not count.

It judges a variable only when every publisher of it in the mission is the
helm's set blocks or a line whose value is written out: a variable an app
posts, a person pokes or a launched app the catalogue does not know might
post is left alone. There is one exception: a behavior's condition on a
variable that a top-level set block (one with no `MODE = ...` prefix and an
else value) gives a value on every helm iteration. The helm evaluates its
set blocks and writes their values into its own buffer before any behavior
reads a condition (HelmEngine.cpp:168, ModeSet.cpp:95-97), so what another
process posts to that variable never reaches a behavior: an app the
catalogue does not know does not stop the check there.

## Why is this bad?
lib_logic compares a word with a mode value field by field (`==`,
`strFieldMatch`: `SURVEYING` matches `ACTIVE:SURVEYING`) or whole (`=`,
`!=`). A mode name that no set block declares never matches: a behavior
waiting for `MODE == STATION-KEEPING` never runs, and one guarded by `MODE !=
ACTIVE:STATION-KEEPING` is never switched off. The helm says nothing.

## Example
```bhv
set MODE = ACTIVE {
  DEPLOY = true
} INACTIVE

set MODE = STATIONING {
  MODE = ACTIVE
  STATION_KEEP = true
} TRANSITING

Behavior = BHV_AvoidCollision
{
  name      = avdcol
  condition = MODE != ACTIVE:STATION-KEEPING   // the mode is STATIONING
}
```

## How to fix
Write a mode the set blocks declare, or declare the mode with a `set` block.

## Options
None.
"""

from __future__ import annotations

import difflib

from moos_lint.files.diagnostics import Severity, Subject
from moos_lint.rules.kit.declare import Kind, Scope, rule
from moos_lint.rules.mission._posted import all_written, compared_once, posted_values
from moos_lint.semantics.mission_model import mission_model

#: how many of a variable's values a message lists
_SHOWN = 6


@rule(
    code="M009",
    name="unknown-mode-value",
    severity=Severity.WARNING,
    scope=Scope.MISSION,
    kinds=(Kind.MOOS,),
)
def check(ctx):
    model = mission_model(ctx)
    if model.unresolved_behaviors:
        return  # a behavior the model cannot see may post any value
    entries = _mode_entries(model.behavior_files)
    if not entries:
        return
    own = _own_entries(model)
    others = posted_values(model, with_sets=False)
    always = _always_set(model.behavior_files)
    bhv_paths = {path for path, _bf in model.behavior_files}
    seen: set[tuple[str, int, int]] = set()
    for ref in model.waits:
        var = ref.name
        pairs = own.get((ref.line.path, ref.line.lineno), {}).get(var) or entries.get(var)
        if pairs is None:
            continue
        extra = others.get(var, [])
        if var in always and ref.line.path in bhv_paths:
            # the set blocks overwrite the helm's own copy before behaviors read it: what
            # other processes post never reaches this condition
            extra = [v for v in extra if v is not None]
        elif model.unknown_apps or None in extra or not all_written(model.published_by(var)):
            continue  # a process the model cannot see, or an app, may post any value
        found = compared_once(ref, seen)
        if found is None:
            continue
        op, word, start = found
        every = _reached(pairs, {v for v in extra if v is not None})
        if not every:
            continue
        fields = {f.strip() for v in every for f in v.split(":")}
        unknown = [f.strip() for f in word.split(":") if f.strip() not in fields]
        if not unknown or any(f.lower() in {x.lower() for x in fields} for f in unknown):
            continue  # (another case: condition-value-case says so)
        outcome = "always holds" if op == "!=" else "never holds"
        names = sorted(every)
        shown = ", ".join(f"`{v}`" for v in names[:_SHOWN])
        if len(names) > _SHOWN:
            shown += f" and {len(names) - _SHOWN} more"
        given = f"(the mission posts it only as {shown}), so this {outcome}"
        if "" in unknown:  # `ACTIVE::SURVEYING`: lib_logic splits out an empty field
            msg = f"`{var} {op} {word}`: no value of `{var}` has an empty mode name {given}"
        else:
            missing = " and ".join(f"`{f}`" for f in unknown)
            verb = "is no mode" if len(unknown) == 1 else "are no modes"
            msg = f"`{var} {op} {word}`: {missing} {verb} of `{var}` {given}"
            stranded = [p for p, v in pairs if v == unknown[0] and f"{p}:{v}" not in every]
            close = difflib.get_close_matches(unknown[0], sorted(fields), n=1, cutoff=0.6)
            if stranded:  # declared under a prefix that is never posted
                msg += (
                    f": its set block waits for `{var} = {stranded[0]}`, which is no value "
                    f"of `{var}`"
                )
            elif close:
                msg += f"; did you mean `{close[0]}`?"
        span = ref.line.span(start, start + len(word))
        subject = Subject(variable=var, app=ref.app or None, key=ref.param)
        yield ctx.report(span, msg, line=ref.line, subject=subject)


def _own_entries(model) -> dict[tuple[str, int], dict[str, list[tuple[str, str]]]]:
    """(path, line) -> the set blocks of the one behavior file that holds the line, when
    the helm loads one file of several (``behaviors = targ_$(VNAME).bhv`` names each
    vehicle's): its conditions can only mean its own modes. Empty when the helm loads its
    files together (several ``behaviors`` lines), or a line sits in several files (an
    included plug): their modes are pooled."""
    helm_lines = [
        p
        for proc in model.processes
        if proc.binary.lower() == "phelmivp" and proc.block is not None
        for p in proc.block.get("behaviors")
    ]
    if len(helm_lines) != 1 or len(model.behavior_files) < 2:
        return {}
    owners: dict[tuple[str, int], list[int]] = {}
    for i, (_path, bf) in enumerate(model.behavior_files):
        for line in bf.lines:
            owners.setdefault((line.path, line.lineno), []).append(i)
    per_file = [_mode_entries([pair]) for pair in model.behavior_files]
    return {at: per_file[found[0]] for at, found in owners.items() if len(set(found)) == 1}


def _always_set(files) -> set[str]:
    """The mode variables a top-level set block (no ``VAR = ...`` prefix) gives a value
    on every helm iteration: its own value when its conditions hold, else its else value
    (``ModeSet::evaluate``)."""
    out: set[str] = set()
    for _path, bf in files:
        for sb in bf.sets:
            var = sb.mode_var
            prefixed = any(
                left.strip() == var and sep
                for left, sep, _right in (text.partition("=") for text, _line in sb.conditions)
            )
            if not prefixed and sb.value and sb.else_value:
                out.add(var)
    return out


def _mode_entries(files) -> dict[str, list[tuple[str, str]]]:
    """Mode variable -> the (prefix, value) of each value its set blocks post
    (``ACTIVE``, ``SURVEYING``: ``ModeSet::evaluate`` posts ``ACTIVE:SURVEYING``). A
    variable whose blocks hold a placeholder or a macro is left out."""
    entries: dict[str, list[tuple[str, str]]] = {}
    broken: set[str] = set()
    for _path, bf in files:
        for sb in bf.sets:
            var = sb.mode_var
            prefix = ""
            for text, _line in sb.conditions:
                # ModeEntry::addCondition: the first condition `VAR = value` is the prefix
                left, sep, right = text.partition("=")
                if sep and left.strip() == var and right.strip():
                    prefix = right.strip()
                    break
            for value in (sb.value, sb.else_value):
                if value is None:
                    continue
                value = value.strip()
                if not value or "$" in value or "$" in prefix or prefix.startswith("="):
                    broken.add(var)
                else:
                    entries.setdefault(var, []).append((prefix, value))
    return {var: pairs for var, pairs in entries.items() if var not in broken}


def _reached(pairs: list[tuple[str, str]], seeds: set[str]) -> set[str]:
    """The values the blocks ``pairs`` (prefix, value) post, with the variable's other
    values ``seeds``: a block whose prefix (``MODE = ACTIVE``) no value equals never
    posts (lib_logic's `=` compares whole strings)."""
    reached = set(seeds)
    grew = True
    while grew:
        grew = False
        for prefix, value in pairs:
            full = f"{prefix}:{value}" if prefix else value
            if full not in reached and (not prefix or prefix in reached):
                reached.add(full)
                grew = True
    return reached
