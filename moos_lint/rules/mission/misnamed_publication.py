"""A posted variable nothing reads, named with the words of one that is read (`UPDATES_RETURN`).

## What it does
In a mission (after nsplug expansion, with its behavior files), takes each
variable the mission's configuration posts (a behavior flag, a uTimerScript
event, a pMarineViewer button or action, ...) that nothing in the mission
reads, as unread-publication finds them. It reports one whose name has the
same `_`-separated words as a variable that is read, in another order or
with a plural `S` more or less: `UPDATES_RETURN` where the return behavior
reads `updates = RETURN_UPDATE`, `RETURN_UPDATES` for `RETURN_UPDATE`; or
whose name is a typo from the name of exactly one variable that is read: the
same words but one, with a letter left out, added, changed or two swapped
(`endflag = RETRUN = true` where the return behavior waits for `RETURN`,
`MOOS_MANUAL_OVERIDE`), or its letters in another order
(`SBR_RANGE_REQUEST` for `BRS_RANGE_REQUEST`); or whose name is a read
one with an underscore more or less (`FRONT_SURVEY` for `FRONTSURVEY`,
`STATIONKEEP` for `STATION_KEEP`). A typo's read name must be
settled: read by an app's or a behavior's code, or published in the mission
too; a name only a condition waits for may be the misspelt one, and
unpublished-subscription reports it there. A posting a typo away from a
behavior's `updates` variable that nothing posts (`STATOIN_UPDATES` where a
behavior reads `updates = STATION_UPDATES`) is reported too, as a mismatch
whose misspelt side is not known: the updates name is the mission's own
choice, so either may be wrong, and no fix is offered. Names of four letters or fewer,
and names that differ in a number (`VEHICLE_1`, `VEHICLE_2`), in a word of
one or two letters (`NAV_X`, `NAV_Y`), by a letter of a short word
(`SET_POS`, `GET_POS`) or by a short word (`TERM_NEG`, `TERM_NUM`), are not
compared so.

Unlike unread-publication, which reports every unread posting and is off by
default, this reports only postings that the name of a read variable says
are meant for it: it is on by default.

## Why is this bad?
MOOS names are exact. The posting goes to a variable no one subscribes to,
and the reader waits for its own name: the button or flag does nothing, and
nothing says so. MOOS-IvP's minicourse missions (`s2_alpha` ... `s8_alpha`)
post `UPDATES_RETURN=speed=1.4` from a viewer action while the return
behavior reads `RETURN_UPDATE`, and many course missions copy it.

## Example
```moos
ProcessConfig = pMarineViewer
{
  action = UPDATES_RETURN=speed=1.4    // the behavior reads RETURN_UPDATE
}
```

## How to fix
Post the name the reader uses.

## Options
None.

MOOS-IvP caveats, deliberately not reported: as unread-publication, a
mission that launches an app the catalogue does not know (it may read
anything); a name another mission of its folder reads, when the mission
shares variables with them (pShare, the node and shore brokers), or any name
when one of those missions may read anything or is not whole (a macro or an
include it leaves unread); names with run-time placeholders or nsplug macros.
"""

from __future__ import annotations

import functools
import re
from collections.abc import Callable, Iterator

from moos_lint.files.diagnostics import Edit, Fix, Severity, Subject
from moos_lint.rules.kit.declare import Kind, Scope, rule
from moos_lint.rules.kit.spelling import VariableSpeller, sized_like
from moos_lint.rules.mission.unread_publication import judged_postings
from moos_lint.semantics.mission_model import mission_model
from moos_lint.semantics.variables import SUBSCRIBE, bare_name

_NAME = re.compile(r"[A-Z][A-Z0-9_]*")


@functools.lru_cache(maxsize=8192)  # (the read names of a folder's missions, asked per mission)
def words(name: str) -> tuple[str, ...]:
    """The name's `_`-separated words, a plural `S` dropped, in sorted order."""
    return tuple(sorted(w[:-1] if len(w) > 2 and w.endswith("S") else w for w in name.split("_")))


@rule(
    code="M011",
    name="misnamed-publication",
    severity=Severity.WARNING,
    scope=Scope.MISSION,
    kinds=(Kind.MOOS,),
    fixable=True,
)
def check(ctx):
    judged = judged_postings(ctx)
    if judged is None:
        return
    names, unread = judged
    by_words: dict[tuple[str, ...], set[str]] = {}
    by_letters: dict[str, set[str]] = {}  # the names without their underscores
    for read in names:
        if _NAME.fullmatch(read) and not read.endswith("_"):
            by_words.setdefault(words(read), set()).add(read)
            by_letters.setdefault(read.replace("_", ""), set()).add(read)
    postings = [(ref, name) for ref, name in unread if _NAME.fullmatch(name)]
    # the postings no read name has the words of: each may be a typo of one
    unmatched = [
        name
        for _ref, name in postings
        if not by_words.get(words(name), set()) - {name}
        and not by_letters.get(name.replace("_", ""), set()) - {name}
    ]
    fits = sized_like(unmatched)
    speller: VariableSpeller | None = None
    updates: VariableSpeller | None = None
    for ref, name in postings:
        meant = sorted(by_words.get(words(name), set()) - {name})
        how = "with the same words"
        either = False
        letters = name.replace("_", "")
        if not meant and len(letters) > 4:
            meant = sorted(by_letters.get(letters, set()) - {name})
            how = "the same but for its underscores"
        if not meant:
            if speller is None:
                speller = VariableSpeller(_settled(ctx, by_words, fits))
            typo = speller.meant(name)
            if typo is None:
                if updates is None:
                    updates = VariableSpeller(n for n in _unposted_updates(ctx) if fits(n))
                typo = updates.meant(name)
                either = typo is not None
            if typo is None:
                continue
            meant, how = [typo], "a typo away"
        shown = " or ".join(f"`{m}`" for m in meant)
        other = (
            "is a behavior's `updates` variable that nothing posts: one of the two names is "
            "misspelt"
            if either
            else "is read: did you mean it?"
        )
        msg = (
            f"`{name}` is posted ({ref.app}: {ref.param}) but nothing in the mission reads it; "
            f"{shown}, {how}, {other}"
        )
        fix = None
        if len(meant) == 1 and not either and ref.line.text == ref.line.raw:
            span = ref.line.span(ref.start, ref.start + len(name))
            fix = Fix(f"post `{meant[0]}`", (Edit(span, meant[0]),))
        yield ctx.report(
            ref.span,
            msg,
            line=ref.line,
            fix=fix,
            subject=Subject(variable=name, app=ref.app, key=ref.param),
        )


def _unposted_updates(ctx) -> Iterator[str]:
    """The behaviors' ``updates`` variables that nothing in the mission posts: a posting
    nothing reads that is a typo from one is the other half of one mismatch, and either
    name may be the misspelt one."""
    model = mission_model(ctx)
    for ref in model.refs:
        if ref.role == SUBSCRIBE and ref.param == "updates":
            name = bare_name(ref.name)
            if name and name == ref.name and not model.is_published(name):
                yield name


def _settled(
    ctx, by_words: dict[tuple[str, ...], set[str]], fits: Callable[[str], bool]
) -> Iterator[str]:
    """The read names whose spelling is settled, so that a posting a typo away from one
    is the misspelt side: a name an app's or a behavior's code reads (uFldBeaconRangeSensor
    registers for `BRS_RANGE_REQUEST`), or one the mission also publishes. A name only
    the mission's own configuration waits for, which nothing publishes, may be the typo
    itself (a condition on `DEPOLY` while a button posts `DEPLOY`): unpublished-subscription
    reports that one, where it is read."""
    model = mission_model(ctx)
    coded: set[str] = set()
    for proc in model.processes:
        if proc.app is not None:
            coded |= proc.app.subscribes
    for _path, bf in model.behavior_files:
        for bhv in bf.behaviors:
            info = model.catalogue.behavior(bhv.kind)
            if info is not None:
                coded |= info.reads
    for names in by_words.values():
        for name in names:
            if fits(name) and (name in coded or model.is_published(name)):
                yield name
