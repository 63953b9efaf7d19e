"""A ProcessConfig parameter that the app does not read (`yaw_pid_kpp`, `Apptick2`).

## What it does
Looks up the app that reads each ProcessConfig block (the Run line's program
for an alias such as `pShare ~ ShareA`, otherwise the block name) in the app
catalogue, and reports a parameter that the app's configuration parser does
not handle. It says which known parameter is close (`did you mean ...?`,
compared without regard to case, as MOOS compares keys), and offers a fix
that respells the key when exactly one known parameter is close.

The catalogue holds the apps whose C++ is linted in the same run, the
catalogue files named in `catalogues = [...]`, and the stock MOOS and
MOOS-IvP apps (generated from their sources; see `moos_lint/catalogue/`).
Every app also accepts the keys its base classes read (`AppTick`,
`CommsTick`, `MaxAppTick`, `IterateMode`, the `moos_*` flags, and
AppCasting's `comms_policy`, `app_logging`, `term_report_interval`, ...).

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
only one), or delete the line. For your own app, lint its C++ in the same run
or describe it in a catalogue file.

## Options
None.

MOOS-IvP caveats, deliberately not reported:
- apps the catalogue does not know, and apps whose parser does not reject
  other keys (the core MOOS apps pLogger, pShare, pMOOSBridge, pScheduler:
  they read keys one by one and never see the others), so that a key list
  that may be incomplete never produces a finding;
- the ANTLER block (unknown-key, R-series, checks it);
- keys holding an nsplug macro, `[section]` keys, and keys starting with `#`
  or `/` (not-a-comment reports those);
- parameters handed to a library the app links: the catalogue counts every
  key the library's configuration functions compare against, so some
  misspellings that match another app's key go unnoticed;
- an app of the linted repository whose final `else` hands every other key
  to code elsewhere (`else handled = m_viewer.setParam(param, value);`, as
  pMarineViewer does): its own files do not list those keys, so it is not
  judged. An app of the repository that the stock catalogue also knows (a
  fork of a MOOS-IvP app, or MOOS-IvP itself) keeps the stock keys too: the
  keys of the libraries it links (`flip:N` for pEchoVar).
"""

import difflib
import functools

from moos_lint.catalogue import catalogue_for
from moos_lint.declare import Kind, Scope, rule
from moos_lint.diagnostics import Edit, Fix, Severity
from moos_lint.model import has_macro


def block_apps(ctx):
    """(block, AppInfo) for each ProcessConfig block of an app the catalogue knows."""
    cat = catalogue_for(ctx.run)
    aliases: dict[str, str] = {}
    for run in ctx.moos.runs:
        if run.name and not has_macro(run.name):
            aliases.setdefault(run.name.lower(), run.binary.replace("\\", "/").rsplit("/", 1)[-1])
    for block in ctx.moos.blocks:
        if block.lname == "antler" or has_macro(block.name):
            continue
        app = cat.app(aliases.get(block.lname, block.name).strip())
        if app is not None:
            yield block, app


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
    for block, app in block_apps(ctx):
        if not app.strict:
            continue
        for p in block.params:
            key = p.lkey
            if not key or app.reads(key) or has_macro(p.key):
                continue
            if key.startswith(("#", "/", "[")) or "[" in key or "]" in key:
                continue
            close = suggestions(key, app.params)
            msg = f"`{p.key.strip()}`: {app.name} does not read this parameter"
            fix = None
            if close:
                msg += "; did you mean " + " or ".join(f"`{c}`" for c in close) + "?"
            if len(close) == 1:
                fix = Fix(f"respell as `{close[0]}`", (Edit(p.key_span, close[0]),))
            yield ctx.report(p.key_span, msg + f" ({app.provenance})", line=p.line, fix=fix)
