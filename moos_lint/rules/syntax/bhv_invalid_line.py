"""A line in a behavior file that the helm rejects.

## What it does
Reports a line of a `.bhv` file that the IvP helm's behavior-file reader does
not accept: a top-level line that is not `initialize`, `Behavior =`, `set`,
a brace or a comment; a Behavior-block line without `=`; an `initialize`
followed by a tab or with a malformed `VAR=VALUE` pair; a `#` line (not a
comment in a behavior file); a merge-conflict marker (`<<<<<<< HEAD`), named
as such.

A line in the `#else` branch of an nsplug `#ifdef` chain on a macro the
launch script gives, in a branch that holds nothing but comments and such
lines, is not reported: it is a guard its author wrote to break the file
on purpose when the launch script gives no known value (`~~ no vehicle role
given ~~`).

A run of consecutive lines rejected for the same reason (a `/* ... */` block,
a pasted paragraph) is one finding, on its first line. A `.bhv` file with no
line shaped like a behavior file's (`Behavior`, `initialize`, `set`, a brace,
`key = value`) is not one (the test inputs of nsplug, notes) and is left
alone, and so is a file written for the C preprocessor (one that uses
`#warning`, `#error`, `#pragma` or `#undef`, which nsplug does not have): the
behavior templates of MOOS-IvP's early years were expanded with `cpp`, which
also strips their `/* ... */` comments, and only its output reaches the helm.

A `.bhv` file of nsplug sections (`<tag><muster_regions>`) is written to be
included a section at a time (`#include plugs.bhv <muster_regions>`): it is
judged in the files that include it, where its lines land (inside a Behavior
block, a section of `muster_region = ...` lines is what the helm expects),
not alone.

A line that is nothing but a template placeholder (`###Path_1###`,
`@POINTS@`, `{{points}}`, `%%RETURN%%`: one word, no spaces) is not reported
either: the file is the template of a generator that writes the behavior file
the helm loads.

## Why is this bad?
The helm reports `Problem with line N in the BehaviorSet file` and the *whole*
behavior set fails to load: the vehicle has no behaviors at all.

## Example
```bhv
# the survey behaviors
initialize DEPLOY = false
Behavior = BHV_Waypoint
{
  name = survey
  speed 2.0
}
```

## How to fix
Use `//` for comments, and `key = value` for every parameter line.

## Options
None.
"""

import re

from moos_lint.files.diagnostics import Severity
from moos_lint.frontends.nsplug import written_for_cpp
from moos_lint.frontends.parsers.bhv import shaped_like_behaviors
from moos_lint.rules.kit.declare import Kind, Scope, rule

#: an nsplug section header (``<tag><muster_regions>``)
_TAG_LINE = re.compile(r"^[ \t]*<tag>", re.M)

#: a line that is one placeholder of a template generator: `###Path_1###`, `@X@`, `{{x}}`
_PLACEHOLDER = re.compile(
    r"\s*(?:#{3}[A-Za-z_][\w.-]*#{3}|@[A-Za-z_][\w.-]*@|\{\{[\w.-]+\}\}|%%[A-Za-z_][\w.-]*%%)\s*"
)


@rule(
    code="B001",
    name="bhv-invalid-line",
    severity=Severity.ERROR,
    scope=Scope.FILE,
    kinds=(Kind.BHV,),
)
def check(ctx):
    bhv = ctx.bhv
    if not (bhv.behaviors or bhv.initializes or bhv.sets) and not shaped_like_behaviors(
        line.text for line in bhv.lines
    ):
        return  # nothing shaped like a behavior file's lines: not one
    if written_for_cpp(line.text for line in bhv.lines):
        return  # a template of the C preprocessor: the helm reads only its output
    own = ctx.expansion.sources.get(ctx.unit.path)
    if own is not None and _TAG_LINE.search(own.text):
        return  # sections that files include where they fit: judged there
    flagged = {(p.span.path, p.span.line) for p in ctx.expansion.problems}
    guards = _guard_branches(ctx.expansion, bhv) if bhv.invalid else set()
    runs: list[list] = []  # consecutive lines rejected for one reason: one finding
    for line, reason in ctx.bhv.invalid:
        if (line.path, line.lineno) in flagged:
            continue  # an nsplug problem on this line is reported already
        if guards and any(b in guards for b in line.branches):
            continue  # a guard that breaks the file on purpose when no branch applies
        if _PLACEHOLDER.fullmatch(line.text):
            continue  # a generator fills it in: the helm loads the generator's output
        last = runs[-1][-1] if runs else None
        if (
            last
            and last[1] == reason
            and last[0].path == line.path
            and (line.lineno - last[0].lineno == 1)
        ):
            runs[-1].append((line, reason))
        else:
            runs.append([(line, reason)])
    for run in runs:
        line, reason = run[0]
        after = "the line after it" if len(run) == 2 else f"the {len(run) - 1} lines after it"
        more = f" (and {after})" if len(run) > 1 else ""
        yield ctx.at_line(line, f"{reason}{more}: the helm fails to load the whole behavior file")


def _guard_branches(exp, bhv) -> set[tuple[int, int]]:
    """The ``#else`` branches of an ``#ifdef`` chain whose macro's value is unknown (the
    launch script gives it) that hold nothing but comments and lines the helm rejects:
    a guard its author wrote to break the file when no branch applies (``~~ no vehicle
    role given ~~``)."""
    elses = {b for b, cond in exp.conditions.items() if cond == "else"}
    if not elses:
        return set()
    rejected = {id(line) for line, _reason in bhv.invalid}
    kept_groups: dict[int, set[int]] = {}
    holds_other: set[tuple[int, int]] = set()
    for line in bhv.lines:
        for b in line.branches:
            kept_groups.setdefault(b[0], set()).add(b[1])
            if b in elses and id(line) not in rejected and not _blank(line.text):
                holds_other.add(b)
    # the chain's other branches were kept too: its macro's value is unknown
    return {b for b in elses - holds_other if len(kept_groups.get(b[0], ())) > 1}


def _blank(text: str) -> bool:
    stripped = text.strip()
    return not stripped or stripped.startswith("//")
