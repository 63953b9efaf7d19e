"""A variable name that declares a non-SI unit.

## What it does
Reports a MOOS variable whose name carries a non-SI unit word after its first
word: `_KNOTS`, `_KTS`, `_FT`, `_FEET`, `_MPH`, `_KM`, `_KPH`, `_KMH`, or a
degree word (`_DEG`, `_DEGS`, `_DEGREES`) on anything but a heading-like
quantity. Names are read wherever `variable-name-case` reads them (helm flags
and conditions, stock app parameters; see `moos_lint/semantics/variables.py`).

Degrees are accepted on headings, courses and bearings (`HEADING`, `HDG`,
`COURSE`, `CRS`, `BEARING`, `BRG`, `BNG`) and on latitude and longitude
(`LAT`, `LON`, `LONG`), which MOOS-IvP keeps in decimal degrees
(`NAV_LAT`, `NAV_LONG`). MOOS-IvP's own missions name no variable after a
unit, so the rule is silent on them.

In C++, it reads the names an app publishes with `Notify` when they are known
statically (`Notify("DEPTH_FT", ...)`, a `#define`, a member's default).

## Why is this bad?
The MOOS Conventions (section 3) use SI units throughout: metres, seconds,
radians. Only heading variables are in degrees. A variable that announces
another unit (`SPEED_KNOTS`, `DEPTH_FT`, `PITCH_DEG`) invites every consumer
to convert, or, worse, to forget to; MOOS-IvP's controllers and behaviors
read speeds in m/s and depths in metres.

## Example
```bhv
Behavior = BHV_ConstantSpeed
{
  runflag = CRUISE_SPEED_KNOTS = 4
}
```

## How to fix
Publish the value in SI units under a name without a unit
(`CRUISE_SPEED = 2.06`), and convert for display only.

## Options
- `units` (list of strings, default
  `["KNOTS", "KTS", "FT", "FEET", "MPH", "KM", "KPH", "KMH"]`): unit words that
  are always reported.
- `degree-units` (list of strings, default `["DEG", "DEGS", "DEGREES"]`): unit
  words reported unless the name is heading-like.
- `degree-words` (list of strings, default
  `["HEADING", "HDG", "COURSE", "CRS", "BEARING", "BRG", "BNG", "LAT", "LON", "LONG"]`):
  words that make a name heading-like.
"""

from __future__ import annotations

from moos_lint.files.diagnostics import Severity
from moos_lint.rules.kit.declare import Kind, Scope, rule
from moos_lint.semantics.variables import bare_name, unit_variables


def unit_word(name: str, units: set[str], degree_units: set[str], degree_words: set[str]):
    """The offending unit word of a variable name, if any."""
    parts = [p for p in name.upper().split("_") if p]
    for p in parts[1:]:
        if p in units:
            return p
        if p in degree_units and not any(w in degree_words for w in parts):
            return p
    return None


@rule(
    code="N006",
    name="non-si-unit",
    severity=Severity.WARNING,
    scope=Scope.FILE,
    kinds=(Kind.MOOS, Kind.BHV, Kind.CPP),
    options={
        "units": ["KNOTS", "KTS", "FT", "FEET", "MPH", "KM", "KPH", "KMH"],
        "degree-units": ["DEG", "DEGS", "DEGREES"],
        "degree-words": [
            "HEADING",
            "HDG",
            "COURSE",
            "CRS",
            "BEARING",
            "BRG",
            "BNG",
            "LAT",
            "LON",
            "LONG",
        ],
    },
)
def check(ctx):
    units = {str(u).upper() for u in ctx.options.get("units", [])}
    degree_units = {str(u).upper() for u in ctx.options.get("degree-units", [])}
    degree_words = {str(u).upper() for u in ctx.options.get("degree-words", [])}
    if ctx.unit.kind is Kind.CPP:
        from moos_lint.semantics.cpp_checks import published_names

        app = ctx.unit.cpp
        for name, span in published_names(app) if app is not None else ():
            word = unit_word(name, units, degree_units, degree_words)
            if word is not None:
                what = (
                    "degrees on a variable that is not a heading" if word in degree_units else word
                )
                yield ctx.report(
                    span,
                    f"`{name}` declares a non-SI unit ({what}): MOOS uses metres, seconds and "
                    "radians",
                )
        return
    seen = set()
    for ref in unit_variables(ctx.moos, ctx.bhv):
        bare = bare_name(ref.name)
        if not bare:
            continue
        seen.add((ref.line.lineno, bare))  # (the line of ref.span, without making it)
        word = unit_word(bare, units, degree_units, degree_words)
        if word is None:
            continue
        what = "degrees on a variable that is not a heading" if word in degree_units else word
        yield ctx.report(
            ref.span,
            f"`{ref.name}` declares a non-SI unit ({what}): MOOS uses metres, seconds and radians",
            line=ref.line,
        )
    if ctx.moos is None:
        return
    from moos_lint.semantics.mission_model import configured_publications

    for c in configured_publications(ctx.run, ctx.moos):
        word = unit_word(c.name.upper(), units, degree_units, degree_words)
        if word is None or (c.span.line, c.name) in seen:
            continue
        what = "degrees on a variable that is not a heading" if word in degree_units else word
        yield ctx.report(
            c.span,
            f"`{c.name}` declares a non-SI unit ({what}): {c.says()}; MOOS uses metres, "
            "seconds and radians",
            line=c.line,
        )
