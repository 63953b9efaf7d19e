"""A ProcessConfig parameter that the app does not read (`yaw_pid_kpp`, `Apptick2`).

## What it does
Looks up the app that reads each ProcessConfig block (the Run line's program
for an alias such as `pShare ~ ShareA`, otherwise the block name) in the app
catalogue, and reports a parameter that the app's configuration parser does
not handle. It says which known parameter is close (`did you mean ...?`,
compared without regard to case, as MOOS compares keys), and offers a fix
that respells the key when exactly one known parameter is close and differs
from the key by a slip (one letter inserted, deleted, replaced or two
swapped, two in a long key, or only underscores), or when the key is one an
older release read (a renamed key): `MODBUS_PORT` is named beside
`MOOS_PORT` but never respelled as it.

The catalogue holds the apps whose C++ is linted in the same run (the keys
their start-up compares with a literal, a `#define` or a member set to a
literal, `param == m_depth_key`, and the keys it reads by how they start:
`param.find("IMAGE_") == 0`, `compare(0, 6, "SONAR_") == 0`, `substr(0, 5) ==
"LAMP_"`, `starts_with`, `strBegins`), the
catalogue files named in `catalogues = [...]`, and the stock MOOS and
MOOS-IvP apps (generated from their sources; see `moos_lint/semantics/catalogue/`).
Every app also accepts the keys its base classes read (`AppTick`,
`CommsTick`, `MaxAppTick`, `IterateMode`, the `moos_*` flags, and
AppCasting's `comms_policy`, `app_logging`, `term_report_interval`, ...).

A key an older MOOS-IvP's app read (uQueryDB's `max_time`, which became
`halt_max_time` in 2021) is reported as such, with the respelling when one is
close: the mission was likely written for that release, and today's app
ignores the line. The older keys are those that MOOS-IvP of June 2012, June
2015, June 2017, August 2019, January 2021, August 2022 and August 2023 read
and that the missions of that tree set (`retired.json`, written by
`scripts/retired_keys.py` from their sources).

## Why is this bad?
MOOS-IvP apps only print "Unhandled config line" at start-up, in an appcast
few people read, and then run on the default: `yaw_pid_kpp = 0.5` leaves
the heading gain at its default, `max_rudder = 30` (the key is `maxrudder`)
leaves the rudder unlimited.

## Example
```moos
ProcessConfig = pMarinePIDV22
{
  AppTick    = 20
  maxrudder  = 100
  yaw_pid_kpp = 1.2     // yaw_pid_kp
}
```

## How to fix
Respell the key (`moos-lint check --fix` applies the suggestion when there is
only one and it is a slip of the key), or delete the line. For your own app,
lint its C++ in the same run or describe it in a catalogue file.

## Options
None.

Blocks an app reads with protobuf's text format (goby's MOOS apps:
pAcommsHandler, iFrontSeat, pTranslator) are checked against the app's
configuration message, nested messages included (`common { verbosity: ... }`),
as generated from goby's `.proto` files (`moos_lint/frontends/goby.json`).
goby 2 and goby 3 ship these apps under the same names with different
schemas (goby 3 reads `driver_type` inside `driver_cfg`, goby 2 at the top of
the block), so a field is reported only when neither release declares it
there, and the message names the release the block fits best. Extension
fields (`[micromodem.protobuf.Config.reset_nvram]`) the catalogue does not
know are not judged.

MOOS-IvP caveats, deliberately not reported:
- apps the catalogue does not know, and apps whose parser does not reject
  other keys (pMOOSBridge, pScheduler: they read keys one by one and never
  see the others), so that a key list that may be incomplete never produces
  a finding. pShare and pLogger are checked: their whole key lists were read
  from their sources (`Output =` and `Log =` lines are theirs, whatever the
  value); so are pXRelay, uTermCommand, uHelmScope, uFldScope, uPokeDB and
  uMAC, whose start-up loops see every line and silently drop the keys they
  do not compare, and uFldContactRangeSensor, which warns about them. An app
  of the linted repository is checked when it reports
  unhandled lines (`reportUnhandledConfigWarning`), or when it is a plain
  CMOOSApp whose start-up loop still compares only the template's `FOO` and
  `BAR`: it reads no key of its own, so `Port = /dev/ttyACM1` in its block
  is ignored;
- the ANTLER block (unknown-key, R-series, checks it);
- the block of a script: one the mission launches (`Run = ./pSonar.py` reads
  `pSonar`), or a script beside the mission of the block's name
  (`pSonar.py`), when no Run line starts a compiled program of that name. The
  script, not the catalogue's app of the same name, reads that block;
- a global key inside a block (`term_reporting`, `ServerPort`), or a key an
  app of the linted repository reads with `m_MissionReader.GetValue("point1",
  s)`, or whose start or end it builds the name from (`GetValue(s +
  "_Longitude", lon)`): `GetValue` reads those from anywhere in the file,
  blocks included;
- keys holding an nsplug macro, `[section]` keys, and keys starting with `#`
  or `/` (not-a-comment reports those); a key with a `[...]` part
  (pMarineViewer's `left_context[return]`) is judged by the word before it, so
  `left_contect[return]` is reported;
- parameters handed to a library the app links: the catalogue counts every
  key the library's configuration functions compare against, so some
  misspellings that match another app's key go unnoticed;
- an app of the linted repository whose final `else` hands every other key
  to code elsewhere (`else handled = m_viewer.setParam(param, value);`, as
  pMarineViewer does): its own files do not list those keys, so it is not
  judged. An app of the repository that the stock catalogue also knows (a
  fork of a MOOS-IvP app, or MOOS-IvP itself) keeps the stock keys too: the
  keys of the libraries it links (`flip:N` for pEchoVar);
- a key one of two apps of one name in the linted repository reads (a course
  repository holding two students' `pPointAssign`): which copy a mission runs
  depends on what its machine built;
- the block of an app of the linted repository whose C++ holds an unresolved
  merge conflict (`<<<<<<< HEAD`): which side's keys it reads is not known,
  and the file does not compile as committed.
"""

import difflib
import functools
import re

from moos_lint.files.diagnostics import Edit, Fix, Severity, Span
from moos_lint.files.launch import scripts_beside
from moos_lint.frontends.parsers.nodes import has_macro
from moos_lint.rules.kit.declare import Kind, Scope, rule
from moos_lint.rules.kit.file_wide import built_keys, file_wide
from moos_lint.rules.kit.spelling import cased_like, slip
from moos_lint.semantics.catalogue import catalogue_for, text_format_app, text_format_schema

_WORD = re.compile(r"[a-z_][a-z0-9_]*")


def _programs(moos, cat) -> dict[str, str]:
    """Lower-case block name -> the program the mission starts to read it (a script's
    block is the script's, not the block's namesake app's)."""
    out: dict[str, str] = {}
    for run in moos.runs:
        if run.name and not has_macro(run.name):
            for name in cat.block_names(run):
                out.setdefault(name.lower(), run.program)
    return out


def block_apps(ctx):
    """(block, AppInfo) for each ProcessConfig block of an app the catalogue knows."""
    cat = catalogue_for(ctx.run)
    aliases = _programs(ctx.moos, cat)
    scripts = scripts_beside(ctx.path)
    for block in ctx.moos.blocks:
        if block.lname == "antler" or has_macro(block.name):
            continue
        if block.lname in scripts and block.lname not in aliases:
            continue  # a script beside the mission is the program that reads it
        app = cat.app(aliases.get(block.lname, block.name).strip())
        if app is not None:
            yield block, app


def text_blocks(ctx):
    """(block, TextFormatApp) for each protobuf-text block of an app the catalogue knows."""
    aliases = _programs(ctx.moos, catalogue_for(ctx.run))
    for block in ctx.moos.blocks:
        if not block.text_format or has_macro(block.name):
            continue
        app = text_format_app(aliases.get(block.lname, block.name).strip())
        if app is not None:
            yield block, app


def _text_unknown(fields, message: str, schema, app):
    """(field, message, suggestions) for each field its message does not declare."""
    known = schema.messages.get(message)
    if known is None:
        return
    for f in fields:
        if f.extension:
            exts = schema.extensions.get(message, {})
            name = f.name.lstrip(".")
            kind = next((t for e, t in exts.items() if e == name or name.endswith("." + e)), None)
            if kind is None:
                kind = next((t for e, t in exts.items() if e.endswith("." + name)), None)
        else:
            kind = known.get(f.name)
            if kind is None:
                yield f, message, suggestions(f.name.lower(), known)
                continue
        if kind is not None and f.children is not None and kind in schema.messages:
            yield from _text_unknown(f.children, kind, schema, app)


def _text_unknown_in_every_release(fields, tapp, schema):
    """(app, field, message, suggestions) for each field that no goby release of the app
    reads where the block puts it (each release rejects it, or a field around it), as
    the release the block fits best words it: the one that rejects or never reaches the
    fewest of its fields (the first release on a tie). A project builds one release."""
    found = []
    for app in tapp.all_releases:
        if app.message not in schema.messages:
            continue
        unknown = list(_text_unknown(fields, app.message, schema, app))
        unread: set[int] = set()  # the fields this release rejects or never reaches
        for f, _message, _close in unknown:
            unread |= _within(f)
        found.append((app, unknown, unread))
    if not found:
        return
    app, unknown, _unread = min(found, key=lambda each: len(each[2]))
    for f, message, close in unknown:
        if all(id(f) in unread for _app, _unknown, unread in found):
            yield app, f, message, close


def _within(f) -> set[int]:
    """The ids of a protobuf-text field and of every field nested in it."""
    out = {id(f)}
    for child in f.children or ():
        out |= _within(child)
    return out


def suggestions(key: str, known) -> list[str]:
    # a plug included by many missions asks the same question many times
    return list(_close_matches(key, tuple(sorted(known))))


@functools.lru_cache(maxsize=4096)
def _close_matches(key: str, known: tuple[str, ...]) -> tuple[str, ...]:
    return tuple(difflib.get_close_matches(key, known, n=3, cutoff=0.75))


@rule(
    code="M001",
    name="unknown-parameter",
    severity=Severity.WARNING,
    scope=Scope.FILE,
    kinds=(Kind.MOOS,),
    fixable=True,
)
def check(ctx):
    # keys apps read with CMOOSFileReader::GetValue, which scans the whole file, blocks
    # included: `term_reporting = false` inside a block is read by every AppCasting app
    # (AppCastingMOOSApp.cpp:349); global-key-in-block (R009) judges such lines
    wide = file_wide(ctx.run)
    built = built_keys(ctx.run)
    for block, app in block_apps(ctx):
        if not app.strict:
            continue
        for p in block.params:
            key = p.lkey
            if not key or app.reads(key) or has_macro(p.key) or key in wide:
                continue
            if built.matches(key):  # a name an app builds for GetValue (`s + "_Longitude"`)
                continue
            if key.startswith(("#", "/", "[")):
                continue
            word, span = key, p.key_span
            if "[" in key or "]" in key:
                # pMarineViewer's `left_context[return] = ...`: the word before `[` is
                # the key the app compares (strBegins); a section name is no key
                word = key.split("[", 1)[0].strip()
                if not _WORD.fullmatch(word) or app.reads(word) or "]" not in key:
                    continue
                span = Span(span.path, span.line, span.col, span.line, span.col + len(word))
            old = catalogue_for(ctx.run).retired_key("apps", app.name, word)
            written = p.key.strip().split("[", 1)[0].strip()
            close = [cased_like(written, c) for c in suggestions(word, app.params)]
            msg = f"`{p.key.strip()}`: {app.name} does not read this parameter"
            if old is not None:
                msg = (
                    f"`{p.key.strip()}`: {app.name} no longer reads this parameter (MOOS-IvP of "
                    f"{old} did: written for an older release?)"
                )
            fix = None
            if close:
                msg += "; did you mean " + " or ".join(f"`{c}`" for c in close) + "?"
            # a key an older release read is most often renamed (`max_time`, now
            # `halt_max_time`): the one close key is what the author meant
            if len(close) == 1 and (old is not None or slip(written, close[0])):
                fix = Fix(f"respell as `{close[0]}`", (Edit(span, close[0]),))
            yield ctx.report(p.key_span, msg + f" ({app.provenance})", line=p.line, fix=fix)
    schema = text_format_schema()
    for block, tapp in text_blocks(ctx):
        for app, f, message, close in _text_unknown_in_every_release(
            block.text_fields, tapp, schema
        ):
            msg = f"`{f.name}`: {app.name} reads this block as protobuf text, and `{message}`"
            msg += " has no such field"
            fix = None
            if close:
                msg += "; did you mean " + " or ".join(f"`{c}`" for c in close) + "?"
            if len(close) == 1 and slip(f.name, close[0]):
                fix = Fix(f"respell as `{close[0]}`", (Edit(f.name_span, close[0]),))
            src = schema.sources.get(message, "")
            yield ctx.report(f.name_span, msg + f" ({app.provenance}; {src})", line=f.line, fix=fix)
