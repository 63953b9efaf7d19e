"""Two behaviors with the same name (or one name a prefix of the other) in a behavior file.

## What it does
Reports a behavior whose `name` equals the name of an earlier behavior in the
same `.bhv` file (after nsplug expansion), or where one name is a prefix of the
other (`loiter` and `loiter_return`). Names compare with case, as the helm
compares them.

## Why is this bad?
The helm insists on unique behavior names, and its check
(`BehaviorSet::uniqueNameX`) also treats a name that begins with another
behavior's name as a duplicate. It reports "Duplicate behavior name found",
the whole behavior set fails to build, and the helm posts
`IVPHELM_STATE = MALCONFIG`: no behavior runs. A copied-and-pasted behavior
whose `name` was not edited is the usual cause.

## Example
```
Behavior = BHV_Loiter
{
  name = loiter
  polygon = radial:: x=0, y=-75, radius=20, pts=8
}

Behavior = BHV_Loiter
{
  name = loiter        // copied: should be loiter_east
  polygon = radial:: x=80, y=-75, radius=20, pts=8
}
```

## How to fix
Give each behavior a distinct name that is not a prefix of another one
(`loiter_west`, `loiter_east`).

## Options
None.

MOOS-IvP caveats:
- behaviors in mutually exclusive `#ifdef` branches are not duplicates: two
  branches of one `#ifdef`, and also two `#ifdef`s that test one macro for
  different values (`#ifdef MISSION_ROLE SIDE` ... `#ifdef MISSION_ROLE
  MIDDLE`), as MOOS-IvP's own missions do;
- a behavior with `templating = spawn` is only a template: the helm deletes it
  right after checking it, so its name is not taken (its spawned instances get
  names from the spawning updates). `templating = clone` keeps the behavior, so
  its name counts;
- names holding an unexpanded `$(X)` compare as text: `loiter_$(VNAME)` twice
  is a duplicate whatever VNAME is, and `$(X)` against `loiter` is unknown
  (not reported);
- a behavior without `name` is not reported; when `name` (or `descriptor`)
  is given twice, the last one counts, as in the helm.
"""

from moos_lint.files.diagnostics import Severity
from moos_lint.frontends.parsers.nodes import has_macro
from moos_lint.rules.hygiene._shared import exclusive, where
from moos_lint.rules.kit.declare import Kind, Scope, rule


def _collide(a: str, b: str) -> str | None:
    """How two names clash in the helm, or None."""
    if a == b:
        return "same"
    if a.startswith(b) or b.startswith(a):
        return "prefix"
    return None


@rule(
    code="H004",
    name="duplicate-behavior-name",
    severity=Severity.ERROR,
    scope=Scope.FILE,
    kinds=(Kind.BHV,),
)
def check(ctx):
    named = []
    for bhv in ctx.bhv.behaviors:
        names = [p for p in bhv.params if p.lkey in ("name", "descriptor")]
        if not names or not names[-1].value:
            continue
        if any(p.value.strip() == "spawn" for p in bhv.get("templating")[-1:]):
            continue
        named.append(names[-1])
    # Each earlier name under each of its prefixes, and by itself: a name is compared
    # with the earlier names it may clash with (equal, a prefix of it, or starting with
    # it), in order, not with every earlier name.
    extending: dict[str, list[int]] = {}
    exact: dict[str, list[int]] = {}
    first_of: dict[int, int] = {}  # a name's first place among the alternatives of one body
    for i, p in enumerate(named):
        value = p.value
        candidates = list(extending.get(value, ()))
        for end in range(1, len(value)):
            candidates += exact.get(value[:end], ())
        for end in range(1, len(value) + 1):
            extending.setdefault(value[:end], []).append(i)
        exact.setdefault(value, []).append(i)
        # alternatives that share one body (`Behavior =` chosen by #ifdef) are one behavior:
        # the body is compared only with the names before its first alternative
        first = first_of.setdefault(id(p), i)
        for j in sorted(candidates):
            if j >= first:
                break
            q = named[j]
            if exclusive(p.line, q.line, ctx.expansion):
                continue
            how = _collide(p.value, q.value)
            if how is None:
                continue
            if how == "prefix" and (has_macro(p.value) or has_macro(q.value)):
                # A textual prefix stays a prefix whatever the macros expand to,
                # but only when the shorter name ends on a whole macro or text.
                shorter = min(p.value, q.value, key=len)
                if shorter.count("(") != shorter.count(")"):
                    continue
            if how == "same":
                msg = (
                    f"behavior name `{p.value}` is already used at {where(q.line)}: "
                    "the helm refuses the behavior set (MALCONFIG)"
                )
            else:
                msg = (
                    f"behavior names `{p.value}` and `{q.value}` ({where(q.line)}) clash: the "
                    "helm treats a name that starts with another behavior's name as a "
                    "duplicate and refuses the behavior set (MALCONFIG)"
                )
            yield ctx.report(p.value_span, msg, line=p.line)
            break
