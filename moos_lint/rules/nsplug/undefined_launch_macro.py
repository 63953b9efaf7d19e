"""A macro of the template that a launch script's nsplug call leaves undefined.

## What it does
Reads the `nsplug TEMPLATE OUTPUT ...` commands of the shell scripts beside
a template (read as text, never run) and expands the template as each of them
has nsplug expand it: with the macros that call gives (`NAME=value` or a bare
`NAME`), the `#ifdef` branches those values take, and the template's own
`#define`s. Reports a `$(NAME)` or `%(NAME)` that one call leaves undefined
while another call of the same template gives it: the second launch script
(`launch_vehicle.sh`, `launch_shoreside.sh`, a field script) was copied from
the first and drifted from it, or the template gained a macro one script was
never told of. When the call gives a macro of a near name that the template
never uses (`DELAY_TIME` for `$(DELAYTIME)`), the message names it.

Not judged: a line behind `//` (nsplug expands it but never warns), a macro
with a default (`$(NAME=1)`), a line in an `#ifdef` branch that the call's
values do not decide (`VTYPE=$TYPE` against `#ifdef VTYPE kayak`), a call
with an argument whose words cannot be read from the script (`$MACROS`,
`"$@"`, `--macros=file`; a variable that holds only options, as
`NSFLAGS="--strict --force"`, is read), a `ServerPort` every other call
gives as 9000 (MOOS takes a value that is no number as not given and uses
port 9000, the one meant), and a macro that no call gives: it may be for
the app itself (pMarineViewer's `$(XPOS)`, uTimerScript's `$(DBTIME)`),
which reads it as written. Scripts are read in the template's folder and
in the folder above it (within the project: `nsplug bhvs/meta_vehicle.bhv
...` run from the mission folder), up to a command that changes folder. A
macro is reported once per file, at its first use, with the number of other
lines using it.

## Why is this bad?
nsplug leaves the whole line unexpanded, the call's other macros included
(`Expander.cpp`, `applyMacrosToLine`, without `--lenient`), and only prints
that the line "may contain an undefined macro". The app then reads
`$(SHOREIP)` as written: `TRY_SHORE_HOST = pshare_route=$(SHOREIP):9300`
never reaches the shoreside, `ServerPort = $(VPORT)` is no port, and a
behavior given `duration = $(DELAYTIME)` is rejected, so the helm reports
`MALCONFIG`. With `--strict` nsplug stops at the line instead, and the
script goes on with no mission, or the one an earlier run made.

## Example
```bash
# launch.sh
nsplug meta_vehicle.bhv targ_abe.bhv VNAME=abe DELAYTIME=20
# launch_vehicle.sh
nsplug meta_vehicle.bhv targ_abe.bhv VNAME=abe DELAY_TIME=20
```
```moos
duration = $(DELAYTIME)   // launch_vehicle.sh leaves it undefined
```

## How to fix
Give the macro in every script that makes the file, or give it a default in
the template (`$(DELAYTIME=20)`).

## Options
None.
"""

from __future__ import annotations

import os
import re

from moos_lint.files.diagnostics import Severity, Span
from moos_lint.files.launch import (
    launch_folders,
    nsplug_calls,
    project_folder,
    script_include_paths,
)
from moos_lint.files.nsplug_calls import NsplugCall
from moos_lint.frontends.nsplug import UNKNOWN, Expansion, Line, Preprocessor
from moos_lint.rules.kit.declare import Kind, Scope, rule
from moos_lint.rules.kit.spelling import typos
from moos_lint.rules.kit.wording import listed

#: a macro reference without a default: ``$(NAME)`` or ``%(NAME)``
_REF = re.compile(r"[$%]\(([^()=:$%\s]+)\)")
#: a copy of a script kept aside (``launch_OG.sh``, ``launch_old.sh``, ``old_launch.sh``):
#: it may give a macro, but what it leaves out is not judged
_BACKUP = re.compile(r"(?:^|[_\-.])(?:og|old|bak|backup|orig|copy)(?:[_\-.]|$)", re.I)


#: the mission's ``ServerPort`` line: MOOS takes a value that is no number as not given,
#: and the MOOSDB and the apps use port 9000 (``CMOOSFileReader::GetValue`` of an int,
#: ``MOOSDB.cpp`` and ``MOOSApp.cpp``)
_SERVER_PORT = re.compile(r"\s*serverport\s*=", re.I)
_DEFAULT_PORT = "9000"


@rule(
    code="P010",
    name="undefined-launch-macro",
    severity=Severity.WARNING,
    scope=Scope.FILE,
    kinds=(Kind.MOOS, Kind.BHV),
)
def check(ctx):
    path = os.path.normcase(os.path.abspath(ctx.path))
    # the scripts of the template's folder, and of the one above it in the project (a
    # script there runs `nsplug bhvs/meta_vehicle.bhv targ_$VNAME.bhv`)
    folders = launch_folders(ctx.path, project_folder(ctx.settings, ctx.path))[:2]
    calls = [c for f in folders for c in nsplug_calls(f) if os.path.normcase(c.template) == path]
    if len(calls) < 2:
        return
    given: dict[str, NsplugCall] = {}  # a macro -> the first call that gives it
    values: dict[str, set[str | None]] = {}  # a macro -> the values the calls give it
    for call in calls:
        for name, value in call.macros or ():
            given.setdefault(name, call)
            values.setdefault(name, set()).add(value)
    #: (file, macro) -> where it is first used, the lines using it, the calls lacking it
    missing: dict[tuple[str, str], tuple[Line, int, set[int], list[NsplugCall]]] = {}
    # every macro the template uses, in any branch (read as the linter expands it)
    used = {
        m.group(1) for ln in ctx.expansion.lines if "(" in ln.raw for m in _REF.finditer(ln.raw)
    }
    for call in calls:
        if call.macros is None or _BACKUP.search(os.path.basename(call.script)):
            continue
        mine = {name for name, _value in call.macros}
        if not ctx.expansion.incomplete and not (given.keys() - mine) & used:
            continue  # the call leaves out no macro the template uses
        exp = _expand(ctx, call)
        if exp is None:
            continue
        defined = exp.define_counts.keys()  # by the `#define`s of the branches taken
        for line in exp.lines:
            if "(" not in line.raw or line.raw.lstrip().startswith("//"):
                continue
            refs = list(_REF.finditer(line.raw))
            used.update(m.group(1) for m in refs)  # (an include the linter could not follow)
            if any(b in exp.undecided for b in line.branches):
                continue
            port = _SERVER_PORT.match(line.raw) is not None
            for m in refs:
                name = m.group(1)
                if name in mine or name in defined or name not in given:
                    continue
                if port and values[name] == {_DEFAULT_PORT}:
                    continue  # MOOS reads no number there and takes the port meant, 9000
                first = missing.setdefault((line.path, name), (line, m.start(), set(), []))
                first[2].add(line.lineno)
                if call not in first[3]:
                    first[3].append(call)
    # the macros first used on one line and left out by the same calls: one finding
    grouped: dict[tuple, list[str]] = {}
    for (path_, name), (line, _start, _linenos, lacking) in missing.items():
        grouped.setdefault((path_, line.lineno, tuple(lacking)), []).append(name)
    for (path_, _lineno, lacking), names in grouped.items():
        line, start, _linenos, _calls = missing[(path_, names[0])]
        lines = set().union(*(missing[(path_, n)][2] for n in names))
        end = start + len(names[0]) + 3
        yield ctx.report(
            Span(line.path, line.lineno, start + 1, line.lineno, end + 1),
            _message(ctx, line, names, list(lacking), given[names[0]], used, len(lines)),
            chain=line.chain,
        )


def _expand(ctx, call: NsplugCall) -> Expansion | None:
    """The template as ``call`` has nsplug expand it; None when an include cannot be
    followed (nsplug would stop, or the lines it reads are not known)."""
    base = ctx.run.preprocessor
    folder = os.path.dirname(call.script)
    pre = Preprocessor(
        include_paths=[*base.include_paths, *script_include_paths(folder)],
        mode="nsplug",
        cache=base.cache,
    )
    macros = {name: UNKNOWN if value is None else value for name, value in call.macros or ()}
    exp = pre.expand(call.template, macros)
    if exp.read_problem is not None or exp.incomplete:
        return None
    return exp


def _message(
    ctx, line: Line, names: list[str], lacking, giver: NsplugCall, used: set[str], lines: int
) -> str:
    """Which calls leave the macros undefined, which gives them, and what nsplug does."""
    where = os.path.dirname(line.path)  # script paths read from the reported file
    first = lacking[0]
    at = f"{os.path.relpath(first.script, where)}:{first.line}"
    more = f" (and {len(lacking) - 1} more)" if len(lacking) > 1 else ""
    template = ""
    if os.path.normcase(line.path) != os.path.normcase(os.path.abspath(ctx.path)):
        template = f" on `{os.path.relpath(os.path.abspath(ctx.path), where)}`"
    what = listed([f"`{n}`" for n in names], "or")
    refs = listed([f"`$({n})`" for n in names], "and")
    reader = "the helm" if ctx.bhv is not None else "the app"
    if first.strict:
        effect = "nsplug --strict stops at this line and writes no file (an older one stays)"
    elif first.lenient:
        effect = f"nsplug --lenient leaves {refs} in the line, and {reader} reads it as written"
    else:
        effect = (
            "nsplug leaves this whole line unexpanded, its other macros too, and "
            f"{reader} reads {refs} as written"
        )
    if lines > 1:
        effect += f" (here and on {lines - 1} more line{'s' if lines > 2 else ''} of this file)"
    unused = {n for n, _v in first.macros or ()} - used
    near = _near(names[0], unused) if len(names) == 1 else None
    hint = f"; the call gives `{near}`: is it the one meant?" if near else ""
    return (
        f"The nsplug call{template} at {at}{more} does not give {what}, which "
        f"{os.path.relpath(giver.script, where)}:{giver.line} gives: {effect}{hint}"
    )


def _near(name: str, unused: set[str]) -> str | None:
    """The one macro the call gives, and the template never uses, that ``name`` is
    probably meant as: the same but for underscores and case, or one typo apart."""
    flat = name.replace("_", "").lower()
    found = sorted(
        n
        for n in unused
        if n.replace("_", "").lower() == flat or (len(name) >= 5 and typos(n, name) <= 1)
    )
    return found[0] if len(found) == 1 else None
