"""A variable an `i` process publishes that is not named `<SENSOR>_<CATEGORY>`.

## What it does
Looks at the ProcessConfig blocks of interface processes (a block name, or
the program behind an alias, that starts with `i` and an upper-case letter)
and reports each variable the block configures the process to publish whose
name is not `<SENSOR>_<CATEGORY>`: one or more upper-case words, `_`, and a
category from the `categories` option (`GPS_X`, `DEPTH_DEPTH`,
`DVL_BODY_VEL`).

A variable counts as published when the value of a parameter names it:
- the published variables `moos_lint/semantics/variables.py` knows for that app;
- the value of a parameter whose key matches `publish-keys` (`*_var`,
  `*_variable`, `publish`, ...) and that is one upper-case word such as
  `GPS_X` (values like `true` or `FALSE`, numbers, paths and lists are left alone).

Names with an nsplug macro (`$(X)`) or a run-time placeholder are skipped.

In C++, it reads what an interface app (process name `i...`) publishes with
`Notify`: a name known statically whose last word is a category but that has
no sensor prefix (`Notify("DEPTH", ...)`, `Notify("YAW", ...)`); and in a
mission, the same of a name given to a key that renames what the app's C++
publishes (`alt_name = DEPTH` when the app publishes `m_alt_name`).

This rule is off by default. MOOS-IvP does not follow this part of the 2007
document: its sensors and simulators publish `NAV_*` and app-prefixed names
(`USM_*`, `GPS_LAT`), and interface apps rarely take variable names from
their configuration at all, so most published names live only in C++ code.
Turn it on for a code base that adopted the convention.

## Why is this bad?
The MOOS Conventions (section 4.2) name sensor data after the sensor process
and the quantity measured: iGPS publishes `GPS_X` and `GPS_Y`, iDepth
publishes `DEPTH_DEPTH`. Consumers such as a navigator can then find every
position or depth source by its name, and names of different sensors never
collide.

## Example
```moos
ProcessConfig = iGPS
{
  x_var = EASTING
}
```

## How to fix
```moos
ProcessConfig = iGPS
{
  x_var = GPS_X
}
```

## Options
- `categories` (list of strings, default `["X", "Y", "Z", "DEPTH", "YAW", "BODY_VEL"]`):
  the allowed `<CATEGORY>` suffixes; add your own (`"TOF"`, `"PITCH"`, ...).
- `publish-keys` (list of strings, default
  `["*_var", "*_variable", "publish", "publish_*", "output_var*"]`): shell-style
  globs of parameter keys (lower case) whose value is a published variable.
"""

from __future__ import annotations

import fnmatch
import re
from typing import Any

from moos_lint.files.diagnostics import Severity, Subject
from moos_lint.rules.kit.declare import Kind, Scope, rule
from moos_lint.semantics.mbutil import BOOLEAN_WORDS
from moos_lint.semantics.variables import PUBLISH, bare_name, block_variables

_INTERFACE = re.compile(r"^i[A-Z]")
_WORD = re.compile(r"[A-Z][A-Z0-9_]*")


@rule(
    code="N004",
    name="sensor-variable-prefix",
    severity=Severity.INFO,
    scope=Scope.FILE,
    kinds=(Kind.MOOS, Kind.CPP),
    default_enabled=False,
    options={
        "categories": ["X", "Y", "Z", "DEPTH", "YAW", "BODY_VEL"],
        "publish-keys": ["*_var", "*_variable", "publish", "publish_*", "output_var*"],
    },
)
def check(ctx):
    from moos_lint.semantics.variables import app_of

    cats = sorted({str(c).upper() for c in ctx.options.get("categories", [])}, key=len)
    keys = [str(k).lower() for k in ctx.options.get("publish-keys", [])]
    alternatives = "|".join(map(re.escape, cats))
    good = re.compile(rf"[A-Z][A-Z0-9]*(?:_[A-Z0-9]+)*_(?:{alternatives})")
    if ctx.unit.kind is Kind.CPP:
        yield from _cpp(ctx, cats, good)
        return
    programs = {r.name.lower(): r.program for r in ctx.moos.runs}
    from moos_lint.semantics.mission_model import configured_publications

    configured: dict[str, list] = {}
    for c in configured_publications(ctx.run, ctx.moos):
        configured.setdefault(c.block, []).append(c)
    for block in ctx.moos.blocks:
        program = programs.get(block.lname, block.name)
        if not (_INTERFACE.match(block.name) or _INTERFACE.match(program)):
            continue
        found: list[tuple[str, Any, Any, str]] = []
        app = app_of(block.name, programs)
        if app is not None:
            found = [
                (r.name, r.span, r.line, "")
                for r in block_variables(block, app)
                if r.role == PUBLISH
            ]
        for p in block.params:
            if (
                any(fnmatch.fnmatchcase(p.lkey, k) for k in keys)
                and _WORD.fullmatch(p.value)
                and p.value.lower() not in BOOLEAN_WORDS  # `publish_raw = FALSE` is a switch
            ):
                found.append((p.value, p.value_span, p.line, ""))
        listed = {(s.line, n) for n, s, _l, _w in found}
        for c in configured.get(block.name, ()):
            # as in C++: a name that is a bare category (no sensor prefix)
            if c.name in cats and (c.span.line, c.name) not in listed:
                found.append((c.name, c.span, c.line, f" ({c.says()})"))
        for name, span, line, why in found:
            bare = bare_name(name)
            if bare is None or bare != name or (cats and good.fullmatch(name)):
                continue
            yield ctx.report(
                span,
                f"`{name}`, published by interface process `{block.name}`, is not named "
                f"`<SENSOR>_<CATEGORY>` ({', '.join(sorted(cats))}){why}",
                line=line,
                subject=Subject(variable=name, app=block.name),
            )


def _cpp(ctx, cats, good):
    from moos_lint.semantics.cpp_checks import published_names

    app = ctx.unit.cpp
    if app is None or not app.is_app or not _INTERFACE.match(app.process_name or ""):
        return
    bare_cats = {c for c in cats}
    for name, span in published_names(app):
        if name in bare_cats and not good.fullmatch(name):
            yield ctx.report(
                span,
                f"`{name}`, published by interface process `{app.process_name}`, is not named "
                f"`<SENSOR>_<CATEGORY>` ({', '.join(sorted(cats))})",
            )
