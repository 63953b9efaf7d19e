"""A top-of-file or ANTLER-block key that MOOS does not read (`CommsTic`, `MSBetweenLaunch`).

## What it does
Reports a key outside every ProcessConfig block (a "global") that no MOOS or
MOOS-IvP program reads, and a key in the ANTLER block that pAntler does not
read. When the key is a misspelling of a known one it says which (`did you
mean ...?`, compared without regard to case, three typos at most: a key a
whole word away, `SONAR_SERIAL_PORT` beside `MODEM_SERIAL_PORT`, names another
thing), and when exactly one known key is close it offers a fix that respells
the key.

Known globals: `ServerHost`, `ServerPort`, `Community`, `MOOSTimeWarp`,
`LatOrigin`, `LongOrigin` (every app, the MOOSDB, pAntler); `UseMOOSComms`
(CMOOSApp); `NoNetwork`, `WebServerPort`, `ClientTimeout`, `WarningLatency`,
`tcpnodelay` (MOOSDB); `TERM_REPORTING` (every AppCasting app);
`GlobalLogPath` (pLogger); `CircuitName`, `MagneticOffset` (CMOOSInstrument);
`Simulator`, `Playback` (CMOOSApp before MOOS v10).

Known ANTLER keys: `Run`, `MSBetweenLaunches`, `ExecutablePath`,
`GentleKill`, `EnableDistributed`, `KillOnDBDisconnect`, and the named lists
that a Run line refers to with `ExtraProcessParams=NAME`, `XConfig=NAME` or
`Win32Config=NAME`, and console configurations, numbered or named
(`4 = -geometry,...`, `pSPConfig = -geometry,...`: any key whose value starts with
`-`), which old missions keep for `XConfig=` lines, some of them commented out.
A misspelt ANTLER key is respelt by `--fix` only when the block does not set the
right name already.
The app-level keys every MOOS app reads from its own
block (`AppTick`, `CommsTick`, `MaxAppTick`, `IterateMode`, `SortMailByTime`,
`CatchCommandMessages`, the `moos_*` flags, and AppCasting's `COMMS_POLICY`,
`APP_LOGGING`, `TERM_REPORT_INTERVAL`, `MAX_APPCAST_EVENTS`,
`MAX_APPCAST_RUN_WARNINGS`, `DEPRECATED_OK`) are accepted in the ANTLER block,
and so are the known globals: MOOS's file reader looks a global up on every
line of the file, blocks included, so `LatOrigin` in the ANTLER block is read
(global-key-in-block, R009, reports where it sits).

## Why is this bad?
MOOS never complains about a key it does not read: `MSBetweenLaunch = 500`
silently leaves pAntler at its default, and `MOOSTimewarp` is fine (keys
ignore case) but `MOOSTimeWrap = 10` silently runs the mission in real time.

## Example
```moos
ServerHost   = localhost
ServerPort   = 9000
MOOSTimeWrap = 10          // MOOSTimeWarp

ProcessConfig = ANTLER
{
  MSBetweenLaunch = 200    // MSBetweenLaunches
  Run = MOOSDB @ NewConsole = false
}
```

## How to fix
Respell the key (`moos-lint check --fix` applies the suggestion when there is
only one), or delete the line.

## Options
- `extra-globals` (list of strings, default `[]`): more top-of-file keys that
  your own apps read with `m_MissionReader.GetValue(...)`.

MOOS-IvP caveats, deliberately not reported:
- keys inside ProcessConfig blocks other than ANTLER: each app has its own
  keys, and IvP apps report unknown ones at run time ("Unhandled config line");
- a fragment that other linted files include: its top-level keys are judged
  where they land (inside a block, they are block keys), in the including
  mission; a `.moos` file that has no ProcessConfig block at all and is not a
  mission may be a fragment written for inclusion inside a block, so its keys
  are not judged either;
- keys holding an unexpanded `$(X)` macro, `define:` lines and `[section]`
  keys;
- a key starting with `#` or a single `/` (`#Run = pX`, `#LatOrigin = 43.8`):
  MOOS reads the line, but nothing asks for that key, so the line does what a
  comment does, as its writer meant;
- a key between the markers of a C block comment (`/*` and `*/` on lines of
  their own): its author meant it switched off, and MOOS ignores an unknown
  top-of-file key anyway; malformed-line names the markers when the lines
  between them are read.

A top-of-file key that an app of the linted repository reads with
`m_MissionReader.GetValue("KEY", value)` is known, and so is one whose start or
end an app builds the name from (`GetValue(s + "_Longitude", lon)` reads
`BeaconA_Longitude`). When an app asks its mission reader for a name it is
handed (`m_MissionReader.GetValue(key, value)`), any key may be read: only a
close misspelling of a known key is reported then. The same holds in a mission
that launches a program neither the catalogue nor the linted C++ knows (an app
of another repository may read `VEHICLE_CONFIG_FILE_PATH` with `GetValue`),
for a key shaped like a name an app could ask for.

In a mission that runs one of goby's apps (pAcommsHandler, iFrontSeat, ...), the
top-of-file keys those apps read into their configuration (`log`, `log_path`,
`modem_id`, `modem_id_lookup_path`, ...; the `moos_global` fields of goby's
`.proto` files) are known too.

`Simulator` and `Playback` are known: CMOOSApp read them in MOOS before v10
(the simulate and playback modes), and MOOS-IvP's own missions still set
`Simulator = true`. Today's MOOS ignores them, but the line is harmless, and
reporting it on every mission copied from MOOS-IvP's examples would bury the
misspellings this rule is for. A key whose nearest known spelling is one of
them (`Simulate = true`, `Simulation = false`) is reported as read by nothing,
without the hint and the respelling: the key meant is as idle. When one of the
project's apps reads that key from its own block, the finding says so.

A top-of-file key that one of the project's apps (linted C++) reads from its
own ProcessConfig block only (`GetConfigurationParam`) is reported as such:
the line never reaches the app; move it into the app's block.
"""

import difflib
import re
from collections.abc import Iterable, Mapping
from types import MappingProxyType

from moos_lint.files.diagnostics import Edit, Fix, Severity
from moos_lint.frontends.parsers.moos import block_comments, looks_commented
from moos_lint.frontends.parsers.nodes import LEGACY_GLOBALS, has_macro
from moos_lint.frontends.parsers.nodes import MOOS_GLOBALS as GLOBALS
from moos_lint.rules.kit.declare import Scope, rule
from moos_lint.rules.kit.file_wide import BuiltKeys, built_keys, repo_globals
from moos_lint.rules.kit.spelling import typos
from moos_lint.semantics.catalogue import catalogue_for, text_format_app, text_format_schema

ANTLER_KEYS = [
    "Run",
    "MSBetweenLaunches",
    "ExecutablePath",
    "GentleKill",
    "EnableDistributed",
    "KillOnDBDisconnect",
]
APP_KEYS = [
    "AppTick",
    "CommsTick",
    "MaxAppTick",
    "IterateMode",
    "SortMailByTime",
    "CatchCommandMessages",
    "COMMS_POLICY",
    "APP_LOGGING",
    "TERM_REPORT_INTERVAL",
    "MAX_APPCAST_EVENTS",
    "MAX_APPCAST_RUN_WARNINGS",
    "DEPRECATED_OK",
    "moos_app_tick",
    "moos_max_app_tick",
    "moos_iterate_mode",
    "moos_iterate_no_comms",
    "moos_no_comms",
    "moos_no_sort_mail",
    "moos_quiet",
    "moos_quit_on_iterate_fail",
    "moos_filter_command",
    "moos_suicide_channel",
    "moos_suicide_port",
    "moos_suicide_phrase",
    "moos_suicide_print",
    "moos_suicide_disable",
    "moos_time_warp",
    "moos_tw_delay_factor",
]
_LIST_OPTIONS = ("extraprocessparams", "xconfig", "win32config")


def _skip_key(key: str) -> bool:
    return not key or has_macro(key) or "define:" in key or "[" in key or "]" in key


def _norm(key: str) -> str:
    return "".join(key.split()).lower()


@rule(
    code="H005",
    name="unknown-key",
    severity=Severity.WARNING,
    scope=Scope.FILE,
    options={"extra-globals": []},
    fixable=True,
)
def check(ctx):
    moos = ctx.moos
    globals_known = [*GLOBALS, *(str(k) for k in ctx.options.get("extra-globals", []))]
    globals_known += sorted(repo_globals(ctx.run))
    if any(b.text_format for b in moos.blocks) or any(
        text_format_app(r.program) for r in moos.runs
    ):
        # goby's apps also read some top-of-file keys (`log_path`, `modem_id`)
        globals_known += list(text_format_schema().moos_globals)
    fragment = ctx.unit.path in ctx.run.included_elsewhere
    if not fragment and (moos.is_mission or moos.blocks):
        # lines between `/*` and `*/` were meant to be off: malformed-line names the markers
        off = {id(line) for s, e, _ in block_comments(moos.lines) for line in moos.lines[s:e]}
        built = built_keys(ctx.run)
        top = _by_lower(globals_known)
        for p in moos.globals:
            if id(p.line) not in off:
                yield from _judge(ctx, p, top, "top-of-file", _APP_KEYS_LOWER, built)
    for block in moos.antler_blocks:
        # a global key (`LatOrigin`) is read wherever it sits, blocks included (MOOS's
        # file reader scans every line for it): global-key-in-block (R009) reports the place
        known = [*ANTLER_KEYS, *APP_KEYS, *globals_known]
        for run in (r for r in moos.runs if r.param.block is block):
            for opt in _LIST_OPTIONS:
                if run.options.get(opt):
                    known.append(run.options[opt])
        present = frozenset(_norm(p.key) for p in block.params)
        by_lower = _by_lower(known)
        for p in block.params:
            if _norm(p.key).isdigit():
                continue  # a numbered console configuration (`4 = -geometry,...`, XConfig=4)
            if p.value.strip().startswith("-"):
                # a console configuration (`pSPConfig = -geometry,80x20+0+0,-bg,green`) or
                # a list of arguments, kept for a Run line that names it (or once did)
                continue
            yield from _judge(ctx, p, by_lower, "ANTLER-block", present=present)


def _by_lower(keys: Iterable[str]) -> dict[str, str]:
    """The keys by their lower case (the last spelling of one key wins)."""
    return {k.lower(): k for k in keys}


_APP_KEYS_LOWER = _by_lower(APP_KEYS)


def _judge(
    ctx,
    p,
    by_lower: dict[str, str],
    where: str,
    in_block: Mapping[str, str] = MappingProxyType({}),
    built: BuiltKeys | None = None,
    present: frozenset[str] = frozenset(),
):
    """``by_lower``: the keys known here, by their lower case; ``in_block``: the keys an
    app reads from its own block, by their lower case (for a top-of-file key)."""
    key = p.key
    if _skip_key(key):
        return
    lkey = _norm(key)
    if lkey in by_lower or (built is not None and built.matches(lkey)):
        return
    if lkey in in_block:
        yield ctx.report(
            p.key_span,
            f"`{key}` at the top of the file is ignored: every app reads "
            f"`{in_block[lkey]}` from its own ProcessConfig block",
            line=p.line,
        )
        return
    reader = _own_block_reader(ctx, lkey) if where == "top-of-file" else None
    if reader is not None:
        yield ctx.report(
            p.key_span,
            f"`{key}` at the top of the file is ignored: {reader} reads it from its own "
            "ProcessConfig block only",
            line=p.line,
        )
        return
    first = key.split()[0] if key.split() else ""
    if first != key.strip() and first.lower() in by_lower:
        # `Run pFoo @ NewConsole = false`: the `=` after the key word is missing, or
        # another mark stands in its place (`Run - pFoo @ NewConsole = false`)
        rest = key.split(None, 1)[1]
        mark, _, after = rest.partition(" ")
        if after.strip() and re.fullmatch(r"[-:+.,;]+", mark):
            what = f"`{mark}` stands where the `=` after `{first}` belongs"
            rest = after.strip()
        else:
            what = f"the `=` after `{first}` is missing"
        yield ctx.report(
            p.key_span,
            f"`{key.strip()}`: {what}, so MOOS reads the key `{key.strip()}` and ignores "
            f"the line (write `{first} = {rest} = {p.value}`)",
            line=p.line,
        )
        return
    if looks_commented(key):
        return  # `#Run = X`: no one asks for the key, so the line does what a comment does
    close = difflib.get_close_matches(lkey, list(by_lower), n=3, cutoff=0.75)
    names = [by_lower[c] for c in close]
    if not names:  # a misspelt block key at the top of the file
        names = [in_block[c] for c in difflib.get_close_matches(lkey, list(in_block), 3, 0.75)]
    who = "no MOOS app reads it" if where == "top-of-file" else "pAntler does not read it"
    if not names and built is not None and built.any_key:
        return  # one of the repository's apps reads a name it is handed: maybe this one
    if not names and where == "top-of-file" and _IDENT.fullmatch(key) and _unknown_program(ctx):
        return  # a program moos-lint cannot see may read it with GetValue
    # a name a word apart (`SONAR_SERIAL_PORT` beside `MODEM_SERIAL_PORT`) is another
    # device's key, not the one meant: only names a few typos away are offered
    names = [n for n in names if typos(key, n) <= _MOST_TYPOS]
    if names and all(n in LEGACY_GLOBALS for n in names):
        # `Simulate = true`: the `Simulator` meant is as idle (no hint, no respelling)
        meant = " or ".join(f"`{n}`" for n in names)
        yield ctx.report(
            p.key_span,
            f"unknown {where} key `{key}`: {who}, nor the {meant} it may mean, which MOOS "
            "has ignored since v10",
            line=p.line,
        )
        return
    if not names:
        yield ctx.report(p.key_span, f"unknown {where} key `{key}`: {who}", line=p.line)
        return
    hint = " or ".join(
        f"`{n}`" + (" (a block key)" if n.lower() not in by_lower else "") for n in names
    )
    fix = None
    # (no respelling onto a key the block already sets: that would make two of it)
    if len(names) == 1 and names[0].lower() in by_lower and names[0].lower() not in present:
        span = p.key_span
        raw = p.line.raw
        if span.line == p.line.lineno and raw[span.col - 1 : span.end_col - 1] == key:
            fix = Fix(f"respell as `{names[0]}`", (Edit(span, names[0]),))
    yield ctx.report(
        p.key_span,
        f"unknown {where} key `{key}`: {who}; did you mean {hint}?",
        line=p.line,
        fix=fix,
    )


def _own_block_reader(ctx, lkey: str) -> str | None:
    """The project's app that reads ``lkey`` from its block (``GetConfigurationParam``),
    where a top-of-file line never reaches it (`Simulate = true` for iCV100)."""
    for info in catalogue_for(ctx.run).apps.values():
        if info.own and lkey in info.params:
            return f"`{info.name}`"
    return None


#: the most typos between a key and a known one it is offered as the spelling meant
_MOST_TYPOS = 3


#: a key an app may ask for by name (``GetValue("VEHICLE_CONFIG_FILE_PATH", ...)``); not
#: ``10    paused``, a line pasted with its number
_IDENT = re.compile(r"[A-Za-z_][\w.:-]*")


def _unknown_program(ctx) -> bool:
    """Whether the mission launches a program that neither the catalogue nor the linted
    C++ describes (its code, which may read any top-of-file key, is not seen)."""
    cat = catalogue_for(ctx.run)
    return any(
        not has_macro(r.program) and cat.program_name(r.program) is None for r in ctx.moos.runs
    )
