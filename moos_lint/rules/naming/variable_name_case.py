"""A MOOS variable name that is not UPPER_SNAKE_CASE.

## What it does
Reports a MOOS variable name written with anything but upper-case letters,
digits and `_`, wherever a configuration value names a variable:

- helm `.bhv` files: conditions (`condition = (DEPLOY = true) and (RETURN != true)`),
  the conditions of `set` blocks, flags (`endflag = RETURN = true`, `runflag`,
  `activeflag`, `wptflag`, `cycleflag`, ..., also with `@` and `#` tags and
  `[if]` conditions), `updates`, `duration_status`, `post_mapping`,
  `initialize` and the `set MODE` variable;
- stock apps in `.moos` files: pLogger `Log = VAR @ 0`, uTimerScript
  `event = var=VAR, ...` and `condition`, pShare `output`, pMOOSBridge
  `SHARE`, uFldNodeBroker / uFldShoreBroker `bridge` and `qbridge`, pEchoVar
  `echo`, pMarineViewer `button_*`, `action`, `scope`, `cmd` and
  `left_context[...]`, uXMS `var` and many more (the full list is the table
  in `moos_lint/semantics/variables.py`).

Each name is reported once per file, at its first place, with the number of
other places in the file (and its includes) that use it. A boolean written
where the key takes a variable's name (`duration_reset = true`, which the
helm reads as a variable named `true`) is reported saying so. In a mission,
when nothing publishes the name as written but an app or behavior of the mission
publishes it in upper case (`Log = Nav_Speed` beside uSimMarine's `NAV_SPEED`),
the finding says who: the name is then not only of the wrong style, it reads
nothing.

Wildcards (`*`, `?`) are accepted where the app accepts them (pLogger
`WildCardPattern` / `WildCardOmitPattern`, pShare `output`). Elsewhere a
wildcard is reported: uXMS, for example, registers `VAR = IMS_*` literally
(a plain `Register`), so it shows a variable named `IMS_*` that nobody
posts; two MOOS-IvP missions (`m9_indigo/hotel.moos`,
`s9_indigo/indigo.moos`) do this. Run-time placeholders that the app
expands itself (`$[OWNSHIP]`, `$V`, `$UP_V1`) are left out of the check, and a
name holding an nsplug macro (`$(X)`, `%(X)`) is skipped. Values of
parameters moos-lint does not know are not looked at. A name an app builds
from an upper-case prefix and a vehicle's name as given (`ACK_MESSAGE_abe`:
uFldNodeComms posts `"ACK_MESSAGE_" + dest_name`; `RANGE_AVD_henry`:
BHV_AvoidCollision posts `"RANGE_AVD_" + m_contact`; prefixes the catalogue
lists) is not reported: the vehicle's name decides its case, not the writer.
Nor is a name whose upper-case prefix the same file also ends with a macro
(`GOTO_UPDATES_nostromo` where a line names `GOTO_UPDATES_$(VNAME3)`, and a
launch script sets `VNAME3="nostromo"`): the name is the one that macro
builds for one vehicle. Nor is an upper-case name joined to the name of a
vehicle of the mission's folder, as that vehicle is named: its community
(`Community = alpha` in `alpha.moos` beside the shoreside's `alpha_WPT_UPDATE`)
or the `VNAME` a launch script of the folder sets (`VNAME1="henry"` for
`RETURN_henry`, or a shoreside's list, `VNAMES="abe:ben"` for `ARRIVED_ben`),
at either end or between two upper-case words (`WAYPOINT_alpha_UPDATES`).
Such a name is one vehicle's copy of a variable, and the other end writes it
the same way; unless the mission publishes it in upper case
(`ALPHA_REPORT`), or its uFldShoreBroker bridges it in upper case (`qbridge =
DEPLOY` bridges `DEPLOY_$V`, and the broker puts the community upper-cased in
place of `$V`, ShoreBroker.cpp:546, 644-646: `DEPLOY_abe` is never bridged),
when the name as written reads nothing and is reported, saying so.

Nor is a name on one side of an `or` in a condition that nothing of the run
posts, as written or in upper case (no mission, behavior file, catalogued app
or behavior, nor an app of the linted C++): `condition = ((DEPLOY = true) or
(alpha = one)) or (bravo = two)`, as MOOS-IvP's `s8_hotel` mission writes it, is a
never-true placeholder beside the side that holds, whose case changes
nothing. `(Deploy = true) or (RETURN = true)` beside a button that posts
`DEPLOY` is still reported (in a mission file, the finding says who posts
`DEPLOY`).

MOOS-IvP's own missions follow the convention in all but a handful of the
more than 5000 variable names they configure. One exception remains, and is
reported:
- `button_seven = REFINE:N # CONTACT_INFO_ALL = name=avdcol # use_refinery=false`
  (`m2_berta`): pMarineViewer splits button values on `#`, so this button
  posts a second variable named `use_refinery` instead of one
  `CONTACT_INFO_ALL` value. That is a real bug (quote the value).


In C++, it checks the names an app publishes (`Notify`) and subscribes to
(`Register`) where they are known statically: literals, `"LIT" + suffix`
concatenations of known parts, string constants and members assigned one
literal, and `#define` string macros. Names built at run time are never
reported, nor names built from a member the configuration sets
(`m_sVehicleName = "UnNamed"` before `GetConfigurationParam("VehicleName",
m_sVehicleName)`: the literal is only a default). Nor is an upper-case name
joined to the name of one of the repository's own apps, as the app is named,
in C++ or in a mission (`iWhoiMicroModem_CMD`, which iWhoiMicroModem registers
as `GetAppName() + "_CMD"`): its publishers and subscribers must write the
app's case. The repository's apps are those of the linted C++ and the C++
folders named as processes are (`src/iWhoiMicroModem`). Core MOOS's apps
upper-case such names themselves (`PHELMIVP_CMD`), so a stock app's name is
not taken. Each name is reported once per app, at its first place, with the
number of other places that use it.

A name that a mission gives through a configuration key of one of the
repository's apps (`servo_var = servo_3` where the C++ publishes
`Notify(m_servo_var, ...)` and reads `m_servo_var` from `servo_var`) is checked
at the mission's line, unless the app upper-cases the value itself
(`m_servo_var = toupper(value)`, `MOOSToUpper`, `boost::to_upper`): many apps do,
and then any case is right.

## Why is this bad?
MOOS variable names are case-sensitive: `Deploy` and `DEPLOY` are two
variables, and a subscriber waiting for one never sees the other. The MOOS
Conventions and every MOOS-IvP app use UPPER_SNAKE_CASE, so a name in another
case is almost always a typo, or a value that the app reads as a variable
name by mistake.

## Example
```moos
ProcessConfig = pLogger
{
  Log = Nav_Speed @ 0
}
```

## How to fix
Write the name in upper case (and fix every publisher and subscriber of the
old name). If a value was meant to be a value, quote it or fix its separators.

## Options
- `allow` (list of strings, default `[]`): names (shell-style globs) that may
  be in any case, for apps outside your control.
- `check-tests` (bool, default `false`): also check test programs and test
  missions: files in a `test`, `tests` or `testing` folder (or `testcases`,
  `unittests`, a `*_test_scripts` folder). Their names are picked to exercise
  code: core MOOS's `testing/QueueTest.cpp` registers for `la`, `di` and `da`
  because its help text tells the tester to post them. A file named for a test
  outside such a folder (`sonar_test.moos`) is most often a mission run in the
  field, and is checked.
"""

from __future__ import annotations

import fnmatch
import os
import re

from moos_lint.files.diagnostics import Severity, Subject
from moos_lint.files.test_code import is_test_code
from moos_lint.frontends.nsplug import derived
from moos_lint.rules.kit.declare import Kind, Scope, rule
from moos_lint.rules.kit.per_run import per_run
from moos_lint.semantics.process_names import PREFIXED
from moos_lint.semantics.variables import (
    PUBLISH,
    bare_name,
    bhv_variables,
    moos_variables,
    one_alternative,
    scoped_to_app,
    unit_variables,
    upper_vehicle_prefixes,
)

_UPPER = re.compile(r"[A-Z0-9_]*")
#: a value where a variable's name belongs (`duration_reset = true`)
_BOOLEANS = frozenset({"true", "false"})
_UPPER_WILD = re.compile(r"[A-Z0-9_*?]*")


@rule(
    code="N003",
    name="variable-name-case",
    severity=Severity.WARNING,
    scope=Scope.FILE,
    kinds=(Kind.MOOS, Kind.BHV, Kind.CPP),
    options={"allow": [], "check-tests": False},
)
def check(ctx):
    if not ctx.options.get("check-tests", False) and is_test_code(
        ctx.path, ctx.settings.project_root
    ):
        return
    if ctx.unit.kind is Kind.CPP:
        yield from cpp_check(ctx)
        return
    allow = [str(a) for a in ctx.options.get("allow", [])]
    seen: set[tuple[int, str]] = set()
    found: dict[str, list[tuple]] = {}  # name -> (ref, message, subject) at each place
    vehicles: frozenset[str] | None = None  # the folder's vehicles, read when first needed
    for ref in unit_variables(ctx.moos, ctx.bhv):
        bare = bare_name(ref.name)
        if bare is None:
            continue
        pattern = _UPPER_WILD if ref.wildcard else _UPPER
        if pattern.fullmatch(bare):
            continue
        if bare.startswith("(") and ref.param.endswith("flag"):
            continue  # a condition written as a flag: invalid-parameter-value says so
        if any(fnmatch.fnmatchcase(ref.name, a) for a in allow):
            continue
        if _built_by_app(ctx, bare) or _built_by_macro(ctx, bare):
            continue  # `ACK_MESSAGE_abe`: an app's prefix and a vehicle's name as given
        if scoped_to_app(bare, own_apps(ctx.run)):
            continue  # `iWhoiMicroModem_CMD`: the app's name decides its case
        if ref.param.endswith("condition") and one_alternative(ref) and not _posted(ctx, bare):
            continue  # `(DEPLOY = true) or (alpha = one)`: an alternative nothing posts
        if vehicles is None:
            vehicles = _vehicles_beside(ctx)
        if vehicles and _named_for_vehicle(ctx, bare, vehicles):
            continue  # `henry_REFUEL_START`: one vehicle's copy of a variable, as it is named
        where = f"{ref.app} `{ref.param}`"
        if not ref.wildcard and _UPPER_WILD.fullmatch(bare):
            message = (
                f"MOOS variable `{ref.name}` is not UPPER_SNAKE_CASE: {where} takes names "
                "literally, so the wildcard matches no variable"
            )
        elif bare.lower() in _BOOLEANS:
            # `duration_reset = true`: the helm bites a variable's name off the value
            message = (
                f"MOOS variable `{ref.name}` ({where}) is not UPPER_SNAKE_CASE: a boolean "
                f"where `{ref.param}` takes a variable's name, so it names a variable "
                f"called `{ref.name}`"
            )
        else:
            message = f"MOOS variable `{ref.name}` ({where}) is not UPPER_SNAKE_CASE"
            reason = _posted_in_upper_case(ctx, ref.name)
            bridged = None if reason else _bridged_as(ctx, ref.name, vehicles or frozenset())
            if bridged:
                reason = (
                    f": uFldShoreBroker bridges `{bridged}`, upper-casing the vehicle's name, "
                    "and MOOS names are case-sensitive"
                )
            message += reason
        subject = Subject(variable=ref.name, app=ref.app, key=ref.param)
        seen.add((ref.span.line, ref.name))
        found.setdefault(ref.name, []).append((ref, message, subject))
    for places in found.values():
        # one finding per name, at its first place: a name misspelt once is misspelt at
        # every use, and each line would say the same
        ref, message, subject = places[0]
        more = len({(r.span.path, r.span.line) for r, _, _ in places}) - 1
        if more:
            message += f"; the file uses it in {more} more place{'s' if more > 1 else ''}"
        yield ctx.report(ref.span, message, line=ref.line, subject=subject)
    if ctx.moos is not None:
        yield from _configured(ctx, allow, seen)


def _built_by_app(ctx, name: str) -> bool:
    """Whether ``name`` is an upper-case prefix that an app or a behavior posts names
    under, followed by the rest as it writes it: uFldNodeComms posts
    ``"ACK_MESSAGE_" + dest_name`` with the vehicle's name as given (``ACK_MESSAGE_abe``),
    BHV_AvoidCollision ``"RANGE_AVD_" + m_contact`` with the contact's
    (``RANGE_AVD_henry``), and no one can write them otherwise."""
    from moos_lint.semantics.catalogue import catalogue_for

    def gather(_units) -> set[str]:
        cat = catalogue_for(ctx.run)
        found = {p for a in cat.apps.values() for p in a.publish_prefixes}
        return found | {p for b in cat.behaviors.values() for p in b.post_prefixes}

    prefixes = per_run(ctx.run, "publish-prefixes", gather)
    for i, ch in enumerate(name):
        if ch == "_" and name[: i + 1] in prefixes and _UPPER.fullmatch(name[:i]):
            return True
    return False


#: an upper-case prefix ended by an nsplug macro or a run-time placeholder, as written
_MACRO_SUFFIX = re.compile(r"\b([A-Z][A-Z0-9_]*_)[$%][({\[]")


def _posted(ctx, name: str) -> bool:
    """Whether anything of the run posts ``name``, as written or in upper case: a
    mission's or behavior file's configuration, or an app or behavior of the catalogue
    (MOOS-IvP's and the repository's own)."""

    def gather(units) -> frozenset[str]:
        from moos_lint.semantics.catalogue import catalogue_for

        cat = catalogue_for(ctx.run)
        found = {v for a in cat.apps.values() for v in a.publishes}
        found |= {v for b in cat.behaviors.values() for v in b.posts}
        for unit in units:
            if unit.moos is not None:
                found.update(r.name for r in moos_variables(unit.moos) if r.role == PUBLISH)
            if unit.bhv is not None:
                found.update(r.name for r in bhv_variables(unit.bhv) if r.role == PUBLISH)
        return frozenset(found)

    posted = per_run(ctx.run, "posted-names", gather)
    return name in posted or name.upper() in posted


def _built_by_macro(ctx, name: str) -> bool:
    """Whether ``name`` is an upper-case prefix that a line of the same file ends with a
    macro (``GOTO_UPDATES_$(VNAME3)``), followed by a rest in another case: the name that
    macro gives for one vehicle (``GOTO_UPDATES_nostromo``)."""
    unit = ctx.moos if ctx.moos is not None else ctx.bhv
    if unit is None:
        return False
    prefixes = derived(unit.expansion, "macro-ended-prefixes", lambda: _macro_ended(unit.lines))
    return any(
        ch == "_" and name[: i + 1] in prefixes and not _UPPER.fullmatch(name[i + 1 :])
        for i, ch in enumerate(name)
    )


def _macro_ended(lines) -> frozenset[str]:
    """The upper-case prefixes the lines end with a macro, as written."""
    return frozenset(m.group(1) for line in lines for m in _MACRO_SUFFIX.finditer(line.raw))


def _named_for_vehicle(ctx, name: str, vehicles: frozenset[str]) -> bool:
    """Whether ``name`` is an upper-case name joined to the name of one of ``vehicles``
    (the vehicles of the mission's folder, :func:`_vehicles_beside`) as that vehicle is
    named (``henry_REFUEL_START``, ``RETURN_aux``, ``WAYPOINT_alpha_UPDATES``). Not when
    the mission publishes the name in upper case, or its uFldShoreBroker bridges it so
    (``DEPLOY_<VNAME>``): the name as written then reads nothing."""
    for i, ch in enumerate(name):
        if ch != "_":
            continue
        head, tail = name[:i], name[i + 1 :]
        if (head in vehicles and _UPPER.fullmatch(tail)) or (
            tail in vehicles and _UPPER.fullmatch(head)
        ):
            return not (_bridged_as(ctx, name, vehicles) or _posted_in_upper_case(ctx, name))
        # the vehicle's name between two upper-case words (`WAYPOINT_alpha_UPDATES`)
        end = name.find("_", i + 1)
        if (
            end > i + 1
            and name[i + 1 : end] in vehicles
            and _UPPER.fullmatch(head)
            and _UPPER.fullmatch(name[end + 1 :])
        ):
            return not _posted_in_upper_case(ctx, name)
    return False


def _bridged_as(ctx, name: str, vehicles: frozenset[str]) -> str | None:
    """The name the unit's uFldShoreBroker bridges instead of ``name``, a name of one of its
    upper-casing prefixes (:func:`upper_vehicle_prefixes`) joined to one of ``vehicles`` in
    another case: `DEPLOY_ABE` for `DEPLOY_abe`."""
    moos = ctx.moos
    if moos is None or not vehicles:
        return None
    prefixes = derived(
        moos.expansion, "upper-vehicle-prefixes", lambda: upper_vehicle_prefixes(moos)
    )
    for prefix in prefixes:
        rest = name[len(prefix) :]
        if name.startswith(prefix) and rest in vehicles:
            return prefix + rest.upper()
    return None


def _vehicles_beside(ctx) -> frozenset[str]:
    """The names of the vehicles of the unit's folder that are not upper case: the
    communities of its missions, and the ``VNAME`` its launch scripts set."""
    from moos_lint.files.launch import vehicle_names

    folder = os.path.dirname(os.path.abspath(ctx.path))
    communities = per_run(ctx.run, "communities-by-folder", _communities)
    found = communities.get(folder, frozenset()) | vehicle_names(folder)
    return frozenset(v for v in found if not _UPPER.fullmatch(v))


def _communities(units) -> dict[str, frozenset[str]]:
    """Every folder of the run's missions -> the communities they name, as written."""
    found: dict[str, set[str]] = {}
    for unit in units:
        moos = unit.moos
        if moos is None or not moos.is_mission:
            continue
        folder = os.path.dirname(os.path.abspath(unit.path))
        for p in moos.global_values("Community"):
            if p.value and "$" not in p.value:
                found.setdefault(folder, set()).add(p.value.strip())
    return {k: frozenset(v) for k, v in found.items()}


def _posted_in_upper_case(ctx, name: str) -> str:
    """In a mission: who publishes the name in upper case, when nothing in the mission
    publishes it as written (the mistake is then not only of style)."""
    if ctx.moos is None or not ctx.moos.is_mission or "*" in name or "?" in name:
        return ""
    from moos_lint.semantics.mission_model import mission_model

    publishers = mission_model(ctx).publishers
    upper = name.upper()
    if name in publishers or upper not in publishers:
        return ""
    who = publishers[upper][0].who
    return f": {who} publishes `{upper}`, and MOOS names are case-sensitive"


def _configured(ctx, allow, seen):
    """``KEY = name`` lines naming a variable an app of the repository publishes, unless
    the app upper-cases the value itself."""
    from moos_lint.semantics.mission_model import configured_publications

    for c in configured_publications(ctx.run, ctx.moos):
        if c.published.upper or _UPPER.fullmatch(c.name) or (c.span.line, c.name) in seen:
            continue
        if any(fnmatch.fnmatchcase(c.name, a) for a in allow):
            continue
        seen.add((c.span.line, c.name))
        subject = Subject(variable=c.name, app=c.app.name, key=c.key.lower())
        yield ctx.report(
            c.span,
            f"MOOS variable `{c.name}` is not UPPER_SNAKE_CASE: {c.says()}, as written",
            line=c.line,
            subject=subject,
        )


def cpp_check(ctx):
    """The C++ check, on the app model (see :mod:`moos_lint.semantics.cpp_checks`)."""
    from moos_lint.rules.kit.cpp import cpp_findings
    from moos_lint.semantics.cpp_checks import variable_name_case

    yield from cpp_findings(
        ctx,
        variable_name_case,
        allow=tuple(str(a) for a in ctx.options.get("allow", [])),
        own_apps=own_apps(ctx.run),
    )


def own_apps(run) -> frozenset[str]:
    """The names of the repository's own apps: the process names of the apps of the
    run's C++, and the names of its C++ folders and of the folders above them that are
    process names (``src/iWhoiMicroModem/src``: an app's folder is named for it, also
    where moos-lint cannot tell the app's name from its code)."""

    def gather(units) -> frozenset[str]:
        names: set[str] = set()
        for u in units:
            if u.cpp is None:
                continue
            if u.cpp.process_name:
                names.add(u.cpp.process_name)
            folder = os.path.normpath(u.cpp.folder)
            for name in (os.path.basename(folder), os.path.basename(os.path.dirname(folder))):
                if PREFIXED.match(name):
                    names.add(name)
        return frozenset(names)

    return per_run(run, "own-app-names", gather)
