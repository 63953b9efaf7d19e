"""A parameter value the app or behavior rejects or misreads (`verbose = 1`, `AppTick = .5`).

## What it does
Checks the values of parameters whose form the app's own parser enforces,
as recorded in the catalogue with the source line that enforces it:

- in a block an app reads as protobuf text (goby's pAcommsHandler,
  iFrontSeat, ...), a field of an enum type must hold one of the enum's
  values (`driver_type: DRIVER_UPD`), as goby's `.proto` files declare them;

- a boolean read with MOOS-IvP's `setBooleanOnString` accepts only `true`,
  `false`, `on`, `off`, `yes`, `no` and `toggle` (any case): `verbose = 1`
  is rejected;
- a number read with `setDoubleOnString` and friends must pass MOOS-IvP's
  `isNumber`: digits, at most one `.`, a `-` only in front (no exponent, no
  units: `speed = 2m/s` is rejected); `setNonNegDoubleOnString` and
  `setUIntOnString` also reject negative values, `setPosDoubleOnString`
  rejects zero, `setPosUIntOnString` values below 1;
- a number a behavior's `setParam` guards itself (`double dval =
  atof(val.c_str()); if((dval < 1) || (dval >= 360) || (!isNumber(val)))
  return(false);`): the PeriodicSurface behavior's `period` must be a number
  above 0, the HeadingChange behavior's `heading_delta` lie in [1, 360), the
  StationKeep behavior's `outer_radius` be above 0; the number may be read
  once, before the branches (the Waypoint behavior's `radius`, `if(dval <= 0)
  return(false)`); a guard without `!isNumber` lets a word through as 0, and
  is read only where it rejects 0;
- a number a behavior clips to bounds without a word (`m_desired_depth =
  vclip_min(dval, 0)`): the ConstantDepth behavior's `depth = -10` runs at the
  surface, taken as 0 (a depth is positive down; the conventions' Z is its
  negative), the ConstantSpeed behavior's `speed = -1` as 0, a `summitdelta`
  above 100 as 100 (17 such keys in MOOS-IvP);
- a parameter the parser compares with a fixed set of words (any case),
  rejecting any other: `comms_policy` (every AppCasting app: `open`, `lean`,
  `dire`), `app_logging` (`true`, `log`, `file`, `off`), `deprecated_ok`
  (`true`, `false`); the Waypoint behavior's `capture_line` (`true`,
  `false`, `absolute`) and `efficiency_measure` (`all`, `off`); the Loiter
  behavior's `clockwise` (`best` or a boolean);
- more fixed sets: the HeadingBias behavior's `bias` (`right`, `left`);
  uSimMarineV22/V23's `thrust_mode_diff` (`differential`, `normal`, `true`,
  `false`), `thrust_mode_reverse` (`reverse`, `normal`, `true`, `false`) and
  `thrust_reflect` (`true`, `false`); uFldBeaconRangeSensor's `report_vars`
  (`both`, `short`, `long`) and `ping_payments` (`upon_response`,
  `upon_request`, `upon_accept`);
- a few words or else a number, where the parser warns for any other
  value: uTimerScript's `reset_max` takes `any`, `unlimited` or `nolimit`
  (any case) or a whole number 0 or more, so `reset_max = no_limit` is
  rejected; its `reset_time` takes `end`, `all-posted`, `none` or a number
  greater than 0; uProcessWatch's `allow_retractions` `true`, `false` or a
  number;
- a polygon, point list or point, judged by a port of MOOS-IvP's own
  `string2Poly`, `string2SegList` and `string2Point`, where the parser
  rejects what they cannot read: the `polygon` of the Loiter, OpRegion and
  OpRegionRecover behaviors and pObstacleMgr's `given_obstacle` must be a
  convex polygon of at least 3 vertices (`60,-40 : 60` has no y, two
  vertices are not a polygon); the Waypoint behavior's `points` and
  `polygon` must hold at least one vertex (or be `empty` / `start`); points
  (`point` of the Waypoint, StationKeep and AbortToPoint behaviors,
  `station_pt`, `bearing_point`, the LegRun behavior's `p1` / `p2`) must read
  as `x,y`, `x:y` or `x=..,y=..`;
- a route such as uFldNodeBroker's and uFldShoreBroker's
  `bridge = src=VAR, alias=VAR2` must have its `src=` field: `scr=VAR` is
  rejected and nothing is bridged;
- a uTimerScript `event` must have its `var=` and `val=` fields (or be
  `quit`), or it is dropped; any field but `var`, `val`, `time`, `amt` and
  `quit` is warned about and skipped, so `t(ime=35` or `tme=35` posts the
  event at time 0, before the events written above it;
- a behavior's flag (`endflag`, `runflag`, any `*flag`) written as a
  condition, `endflag = MODE==SURVEYING`: the helm splits a flag at its first
  `=` (`setVarDataPairOnString`), so it posts `MODE` = `=SURVEYING`, a value
  no condition on `MODE` expects; the fix drops one `=`; in parentheses,
  `endflag = (DEPLOY = false)` posts `(DEPLOY` = `false)`, and the fix drops
  them;
- `AppTick` and `MaxAppTick` (every MOOS app) are read with
  `GetConfigurationParam(double)`, which ignores a value that does not start
  with a digit or `-`: `AppTick = .5` or `+4` leaves the default;
  `CommsTick` with `GetConfigurationParam(int)`, through `atoi`: a value
  that does not start with a digit or a sign (`CommsTick = four`) is 0, and
  the comms client then ticks at 1 Hz;
- IvPBehavior's own parameters, which every behavior takes: `pwt` (also
  `priwt`, `priority`) must be a number 0 or more and `duration` too (or
  `no-time-limit`), `comms_policy` one of `open`, `lean`, `dire`, and
  `duration_idle_decay` a boolean, or the helm fails the behavior;
  `perpetual` takes any word, but only `true` (any case) sets it:
  `perpetual = ture` or `yes` is read as false, without a warning.

The message names the parser's source line in moos-ivp. A repository that
carries its own copy of a MOOS-IvP app (a fork of MOOS-IvP, or the MOOS-IvP
tree itself) has the app's keys read from the copy, and the forms MOOS-IvP's
parser enforces hold for the keys the copy still reads in a copy of the file
that reads them (the file's path in the MOOS-IvP tree,
`ivp/src/uTimerScript/TS_MOOSApp.cpp`); a course's own app of a stock name
(`src/pOdometry` of a moos-ivp-extend tree) is not judged by MOOS-IvP's forms.

## Why is this bad?
An IvP app reports the line as "Unhandled config line" and keeps its default;
a behavior's `setParam` fails, and the helm rejects the whole behavior set
(`IVPHELM_STATE = MALCONFIG`). `AppTick = .5` is ignored without a word, and
the app runs at 4 Hz instead of 0.5 Hz.

## Example
```moos
ProcessConfig = pMarinePIDV22
{
  AppTick        = .5       // 0.5
  ignore_nav_yaw = 1        // true
}
```

```
Behavior = BHV_Loiter
{
  polygon = 60,-40 : 60,-160 : 150    // the last vertex has no y
}
```

## How to fix
Write the value in the form the parser reads: `0.5`, `true`,
`60,-40 : 60,-160 : 150,-160`.

## Options
None.

MOOS-IvP caveats, deliberately not reported:
- values holding an nsplug macro, or the `{{NAME}}` placeholder of another
  template generator (`speed = {{SPEED}}`, filled in by a script);
- parameters whose parser the catalogue does not tie to one of these
  setters, fixed word sets or geometry parsers (other enums, and polygons
  read by other code, such as contact filters' regions, are not judged);
- polygon and point-list forms the port does not follow exactly:
  `format=radial`, `radial::`, `ellipse:`, `wedge:`, `pylon:`, `oval:`,
  `zigzag:`, `lawnmower`, edge `tags=`; a polygon of more than 400
  vertices; a polygon whose convexity rests on floating-point rounding (a
  vertex all but on an edge's line);
- apps the catalogue does not know;
- in a project that builds its own helm (a vendored, often older, MOOS-IvP,
  found as unknown-behavior-parameter finds it), a word its own copy of the
  stock behavior names (`src/*/BHV_Waypoint.cpp` holding `"internal"`, which
  MOOS-IvP 14.7's BHV_Waypoint still took for `efficiency_measure`): that
  helm runs its copy, not today's.
"""

import re

from moos_lint.files.diagnostics import Edit, Fix, Severity
from moos_lint.frontends.parsers.bhv import split_commas
from moos_lint.frontends.parsers.nodes import has_macro
from moos_lint.rules.kit.declare import Kind, Scope, rule
from moos_lint.rules.mission._behaviors import lookup, own_source_keys
from moos_lint.rules.mission.unknown_parameter import block_apps, text_blocks
from moos_lint.semantics.catalogue import text_format_schema
from moos_lint.semantics.geometry_forms import INVALID, is_geometry_form, judge
from moos_lint.semantics.mbutil import BOOLEAN_WORDS, is_number, var_data_pair
from moos_lint.semantics.variables import is_flag_param

_MOOS_DOUBLE = re.compile(r"^[0-9-]")
#: what ``atoi`` reads a number from (the value's blanks are gone)
_MOOS_INT = re.compile(r"^[+-]?[0-9]")


def _atof(s: str) -> float:
    m = re.match(r"^[+-]?(\d+\.?\d*|\.\d+)", s.strip())
    try:
        return float(m.group(0)) if m else 0.0
    except ValueError:
        return 0.0


#: what a value of each geometry form must be, for the message
_GEOMETRY_WHAT = {
    "convex_polygon": "is not a convex polygon",
    "waypoints": "is not a point list or polygon",
    "point": "is not a point",
}


def clipped(form: str, value: str) -> tuple[str, float] | None:
    """For a number beyond a bound of a ``clip:LO,HI`` form: why, and the bound taken."""
    low, _, high = form[len("clip:") :].partition(",")
    v = _atof(value)
    if low and v < float(low):
        return f"is below {float(low):g}", float(low)
    if high and v > float(high):
        return f"is above {float(high):g}", float(high)
    return None


def problem(form: str, value: str) -> str | None:
    """Why ``value`` does not have the ``form``, or None."""
    if is_geometry_form(form):
        # the app's own parser, ported; only a sure rejection is reported
        verdict = judge(form, value)
        if verdict.status != INVALID:
            return None
        what = _GEOMETRY_WHAT.get(form.split("|", 1)[0], "is not read")
        return f"{what} ({verdict.reason})" if verdict.reason else what
    if form == "timer_event":
        return _timer_event(value)
    if form.startswith("fields:"):
        # `key=value` pairs separated by commas; the listed fields must be there
        pairs = {}
        for item in value.split(","):
            left, eq, right = item.partition("=")
            if eq:
                pairs[left.strip().lower()] = right.strip()
        missing = [f for f in form[len("fields:") :].split("+") if not pairs.get(f)]
        if missing:
            return "has no " + " or ".join(f"`{f}=` field" for f in missing)
        return None
    if form.startswith("enum_or_"):
        # a few words (lower-cased) or else a number of the named form
        number, _, words = form[len("enum_or_") :].partition(":")
        allowed = words.split("|")
        if value.lower() in allowed:
            return None
        why = problem(number, value)
        if why is None:
            return None
        listed = ", ".join(f"`{a}`" for a in allowed)
        return f"is not one of {listed}, and {why}"
    if form.startswith("enum:"):
        # compared lower-cased with a fixed set, as the parser does
        allowed = form[len("enum:") :].split("|")
        if value.lower() not in allowed:
            return "is not one of " + ", ".join(f"`{a}`" for a in allowed)
        return None
    if form == "bool":
        if value.lower() not in BOOLEAN_WORDS:
            return "is not a boolean (true/false, on/off, yes/no)"
        return None
    if form == "moos_double":
        if not _MOOS_DOUBLE.match(value):
            return "does not start with a digit or `-`"
        return None
    if form == "moos_int":
        if not _MOOS_INT.match(value):
            return "does not start with a digit or a sign"
        return None
    if form == "true_word":
        if value.lower() not in ("true", "false"):
            return "is neither `true` nor `false`"
        return None
    if form.startswith("clip:"):
        # a number, taken as the nearest bound when beyond one: `clip:0,` clips at 0
        if not is_number(value):
            return "is not a number (digits, one `.`, a leading `-`)"
        got = clipped(form, value)
        return None if got is None else got[0]
    if form.startswith("range:"):
        # a number within bounds: `range:[1,360)` takes 1 up to but not 360
        if not is_number(value):
            return "is not a number (digits, one `.`, a leading `-`)"
        low, _, high = form[len("range:") :].partition(",")
        v = _atof(value)
        below = low[1:] and (v < float(low[1:]) or (low[0] == "(" and v == float(low[1:])))
        above = high[:-1] and (v > float(high[:-1]) or (high[-1] == ")" and v == float(high[:-1])))
        if below or above:
            return f"is outside {low[0]}{low[1:] or '-∞'}, {high[:-1] or '∞'}{high[-1]}"
        return None
    if form in ("number", "nonneg", "positive", "uint", "posuint", "int"):
        if not is_number(value):
            return "is not a number (digits, one `.`, a leading `-`)"
        v = _atof(value)
        if form in ("nonneg", "uint") and v < 0:
            return "is negative (the parser takes values >= 0)"
        if form == "positive" and v <= 0:
            return "is not greater than 0"
        if form == "posuint" and v < 1:
            return "is less than 1"
    return None


@rule(
    code="M002",
    name="invalid-parameter-value",
    severity=Severity.WARNING,
    scope=Scope.FILE,
    kinds=(Kind.MOOS, Kind.BHV),
    fixable=True,
)
def check(ctx):
    if ctx.moos is not None:
        for _block, app in block_apps(ctx):
            read: dict[str, list] = {}
            for p in _block.params:
                got = app.forms.get(p.lkey)
                if got is None:
                    continue
                if got[0].startswith("moos_"):
                    earlier = read.setdefault(p.lkey, [])
                    if any(not e.line.excludes(p.line) for e in earlier):
                        continue  # CMOOSApp reads the first line only (duplicate-parameter)
                    earlier.append(p)
                value = "".join(p.value.split())  # MOOS drops every blank of a config line
                yield from _judge(ctx, p, value, got, app.name)
        yield from _text_enums(ctx)
    if ctx.bhv is not None:
        for bhv in ctx.bhv.behaviors:
            info, _known = lookup(ctx, bhv.kind.strip())
            for p in bhv.params:
                if is_flag_param(p.lkey):  # any behavior's, known to the catalogue or not
                    yield from _double_equals(ctx, p)
                got = None if info is None else info.forms.get(p.lkey)
                if info is None or got is None:
                    continue
                if got[0].startswith(("enum:", "enum_or_")) and p.value.strip().lower() in (
                    own_source_keys(ctx, bhv.kind.strip(), ctx.path)
                ):
                    continue  # the project's own helm runs its copy, which names the word
                yield from _judge(ctx, p, p.value.strip(), got, info.name)


def _double_equals(ctx, p):
    """A flag written as a condition (``runflag = MODE==SURVEY``): the helm splits it at
    its first ``=`` and posts ``MODE`` = ``=SURVEY``; in parentheses
    (``endflag = (A_ONE = true)``) the parentheses go into the name and the value."""
    pair = var_data_pair(p.value)
    if pair is not None and pair[0].startswith("(") and not has_macro(p.value):
        yield from _parenthesised(ctx, p, *pair)
        return
    if pair is None or not pair[1].startswith("=") or has_macro(p.value):
        return
    var, val = pair
    meant = val.lstrip("=").strip()
    if not meant:
        return
    start = p.line.text.find("==", p.value_start, p.value_end)
    at = p.line.text.find("=", p.value_start, p.value_end)
    fix = None
    if start == at >= 0 and p.line.text == p.line.raw:  # one `=` fewer is meant
        edit = Edit(p.line.span(start, start + 2), "=")
        fix = Fix(f"post `{var}={meant}`", (edit,))
    yield ctx.report(
        p.value_span,
        f"`{p.key.strip()} = {p.value.strip()}` posts `{var}` = `{val}`: the helm splits a "
        f"flag at its first `=` (setVarDataPairOnString), so `{var}` never reads `{meant}`",
        line=p.line,
        fix=fix,
    )


def _parenthesised(ctx, p, var: str, val: str):
    """``endflag = (A_ONE = true)``: posts ``(A_ONE`` = ``true)``."""
    inner = p.value.strip()
    fix = None
    if inner.startswith("(") and inner.endswith(")") and "(" not in inner[1:]:
        meant = inner[1:-1].strip().replace("==", "=")
        fix = Fix(f"post `{meant}`", (Edit(p.value_span, meant),))
    yield ctx.report(
        p.value_span,
        f"`{p.key.strip()} = {p.value.strip()}` posts `{var}` = `{val}`: a flag is "
        "`VAR = value`, not a condition; the helm splits it at its first `=` "
        "(setVarDataPairOnString), parentheses and all",
        line=p.line,
        fix=fix,
    )


def _text_enums(ctx):
    """Enum fields of protobuf-text blocks (goby's apps) whose value the enum lacks, in
    every goby release of the app that reads the field as an enum (a project builds one
    of them; the first such release words the finding)."""
    schema = text_format_schema()
    for block, tapp in text_blocks(ctx):
        judged: dict[int, list] = {}  # id(field) -> [(app, message, kind, values), ...]
        for app in tapp.all_releases:
            for f, message, kind, values in _enum_fields(block.text_fields, app.message, schema):
                judged.setdefault(id(f), [f]).append((app, message, kind, values))
        for f, *verdicts in judged.values():
            value = f.value or ""
            if any(value in values for _app, _message, _kind, values in verdicts):
                continue
            app, message, kind, values = verdicts[0]
            shown = ", ".join(f"`{v}`" for v in values[:8]) + (", ..." if len(values) > 8 else "")
            yield ctx.report(
                f.line.span(f.end - len(value), f.end),
                f"`{f.name}: {value}` is not a value of `{kind}` ({shown}): {app.name} stops "
                f"at start-up with a configuration error ({app.provenance}; "
                f"{schema.sources.get(message, '')})",
                line=f.line,
            )


def _enum_fields(fields, root: str, schema):
    """(field, message, enum, its values) for each enum field under message ``root`` whose
    value is a name that may be judged (not a number, which protobuf also reads, nor a
    macro)."""
    todo = [(fields, root)]
    while todo:
        fields, message = todo.pop()
        known = schema.messages.get(message, {})
        for f in fields:
            kind = None if f.extension else known.get(f.name)
            if kind is None:
                continue
            if f.children is not None:
                if kind in schema.messages:
                    todo.append((f.children, kind))
                continue
            values = schema.enums.get(kind)
            value = f.value or ""
            if not values or not value or has_macro(value):
                continue
            if not value.replace("_", "").isalnum() or value[0].isdigit():
                continue  # a number: protobuf also reads an enum by its number
            yield f, message, kind, values


#: the fields of a uTimerScript event (TS_MOOSApp::addNewEvent)
_EVENT_FIELDS = ("var", "val", "time", "amt")
#: how a problem about a field the parser warns about and skips begins
_UNKNOWN_FIELD = "has a field"


def _timer_event(value: str) -> str | None:
    """Why uTimerScript drops or misreads an ``event``: its pieces, split at commas outside
    quotes (``parseStringQ``), are ``quit`` or ``var=``, ``val=``, ``time=``, ``amt=``; an
    event without a variable or a value is dropped, and any other field is warned about
    and skipped, so a misspelt ``time=`` posts the event at 0."""
    fields: dict[str, str] = {}
    unknown: list[str] = []
    quit = False
    for piece, _offset in split_commas(value):
        if piece.strip().lower() == "quit":
            quit = True
            continue
        left, _eq, right = piece.partition("=")
        key = left.strip().lower()
        if key in _EVENT_FIELDS:
            fields[key] = right.strip()
        elif key:
            unknown.append(left.strip())
    missing = [f for f in ("var", "val") if not fields.get(f)]
    if missing and not quit:
        return "has no " + " or ".join(f"`{f}=` field" for f in missing)
    if unknown:
        listed = ", ".join(f"`{f}`" for f in (*_EVENT_FIELDS, "quit"))
        later = " (the event is posted at time 0)" if "time" not in fields else ""
        return f"{_UNKNOWN_FIELD} `{unknown[0]}`, none of {listed}{later}"
    return None


#: what a parser that does not reject a value of the wrong form does with it
_EFFECTS = {
    "moos_double": "ignores it and keeps its default",
    "moos_int": "reads it with atoi, as 0",
    "true_word": "takes it as false",
}


def _judge(ctx, p, value, got, owner):
    form, at = got
    if not value or has_macro(value) or has_macro(p.key):
        return
    why = problem(form, value)
    if why is None:
        return
    where = f" ({at})" if at else ""
    effect = _EFFECTS.get(form, "rejects it")
    if why.startswith(_UNKNOWN_FIELD):
        effect = "warns about that field and skips it"
    got = clipped(form, value) if form.startswith("clip:") and is_number(value) else None
    if got is not None:
        effect = f"takes it as {got[1]:g}, silently"
        if "depth" in p.key.lower() and _atof(value) < 0:
            effect += " (a depth is positive down: a negative one is a Z)"
    yield ctx.report(
        p.value_span, f"`{p.key.strip()} = {value}` {why}: {owner} {effect}{where}", line=p.line
    )
