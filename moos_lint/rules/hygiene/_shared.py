"""Helpers shared by the configuration-hygiene rules (H001-H007).

- :func:`exclusive`: two lines that never both survive nsplug, either because they
  sit in different branches of one ``#ifdef`` or because their ``#ifdef``
  conditions test one macro for different values (``#ifdef ROLE SIDE`` and a
  later ``#ifdef ROLE MIDDLE``).
- :func:`names_match`: a process or block name compared the way MOOS compares
  it (without regard to case), where an unexpanded ``$(X)`` matches anything.
- :func:`near_name`: the one name of a list a process or block name was probably
  meant as (a typo or two, or a word or number added), for the hint that ties an
  unread block (H001) to a launched process without one (H002).
- :func:`extends`: a program name that is another with a word or number added
  (``iRemoteMod`` of ``iRemote``): a renamed copy whose source moos-lint cannot see,
  which most often still connects under the name it was copied from.
- :func:`app_example`: a file that is one app's example configuration, whose ANTLER
  block is a list the app reads (a watchdog's processes), not a launch.
- :func:`commented_runs`: where the commented-out Run lines of a mission's ANTLER
  block are (`//Run = pLogger`), by the names their processes would run under.
"""

from __future__ import annotations

import os
import re

from moos_lint.files.launch import script_names
from moos_lint.frontends.nsplug import Expansion, Line
from moos_lint.frontends.parsers.moos import strip_comment
from moos_lint.frontends.parsers.nodes import Param, has_macro, parse_run
from moos_lint.rules.kit.per_run import per_run
from moos_lint.rules.kit.spelling import typos

_MACRO = re.compile(r"[$%]\([^()]*\)")

#: `//Run = X`, and `#Run = X`, `/Run = X` or `/* Run = X */`: not comments to MOOS,
#: but a Run line its author meant to switch off all the same (pAntler launches only the
#: lines whose key is `Run`)
_COMMENTED_RUN = re.compile(r"^\s*(?:/+\**|#+)\s*run\s*=\s*\S", re.I)


def _ifdef_values(cond: str | None) -> tuple[str, frozenset[str]] | None:
    """``ifdef A v1 || A v2`` -> ``("A", {"v1", "v2"})``; None for any other form."""
    if not cond or not cond.startswith("ifdef "):
        return None
    rest = cond[len("ifdef ") :]
    if "&&" in rest:
        return None
    name = None
    values: set[str] = set()
    for term in rest.split("||"):
        macro, _, value = term.strip().partition(" ")
        value = value.strip()
        if not macro or not value or (name is not None and macro != name):
            return None
        name = macro
        values.add(value)
    return (name, frozenset(values)) if name else None


def _ifndef_names(cond: str | None) -> frozenset[str]:
    if not cond or not cond.startswith("ifndef "):
        return frozenset()
    return frozenset(cond.split()[1:])


def _disjoint(c1: str | None, c2: str | None) -> bool:
    """True when two branch conditions can never both hold."""
    t1, t2 = _ifdef_values(c1), _ifdef_values(c2)
    if t1 and t2:
        return t1[0] == t2[0] and not (t1[1] & t2[1])
    # `#ifdef A v` needs A set to v; `#ifndef A` needs A unset or empty.
    if t1 and t1[0] in _ifndef_names(c2):
        return True
    return bool(t2 and t2[0] in _ifndef_names(c1))


def exclusive(a: Line, b: Line, expansion: Expansion) -> bool:
    """True when nsplug never keeps both lines, whatever the macros are."""
    if a.excludes(b):
        return True
    conds = expansion.conditions
    for ga, ba in a.branches:
        for gb, bb in b.branches:
            if ga != gb and _disjoint(conds.get((ga, ba)), conds.get((gb, bb))):
                return True
    return False


def _pattern(text: str) -> re.Pattern:
    parts = _MACRO.split(text)
    return re.compile(".*".join(re.escape(p) for p in parts), re.IGNORECASE | re.DOTALL)


def names_match(a: str, b: str) -> bool:
    """Equal without regard to case; an unexpanded macro in either name matches anything."""
    if a.lower() == b.lower():
        return True
    if has_macro(a) and _pattern(a).fullmatch(b):
        return True
    return bool(has_macro(b) and _pattern(b).fullmatch(a))


def where(line: Line) -> str:
    return f"{os.path.basename(line.path)}:{line.lineno}"


#: the most names :func:`near_name` compares a name with
NEAR_NAMES_COMPARED = 40


def near_name(name: str, others) -> str | None:
    """The one of ``others`` that ``name`` is probably meant as: at most two typos apart
    (``pMarinePIDD``), or one of them is the other with a word or number added
    (``uFldHazardMgrX`` for ``uFldHazardMgr``, ``pShare2``); None when no name, or more
    than one, is that near. Names with a macro and short names (under 5 letters) are
    never compared, and neither are more than :data:`NEAR_NAMES_COMPARED` others (a
    hint, not worth a time that grows with the square of a generated mission's size)."""
    if has_macro(name) or len(name) < 5 or len(others) > NEAR_NAMES_COMPARED:
        return None
    low = name.lower()
    found: list[str] = []
    for other in others:
        lo = other.lower()
        if lo == low or has_macro(other) or len(other) < 5:
            continue
        longer, shorter = (lo, low) if len(lo) > len(low) else (low, lo)
        gap = len(longer) - len(shorter)
        added = gap <= 8 and longer.startswith(shorter)
        # (no fewer typos than the lengths differ by)
        if (added or (gap <= 2 and typos(lo, low) <= 2)) and other not in found:
            found.append(other)
    return found[0] if len(found) == 1 else None


def extends(longer: str, shorter: str) -> bool:
    """Whether ``longer`` is ``shorter`` with a word or a number added (lower case:
    ``iremotemod`` or ``ipydyna2`` of ``iremote``, ``ipydyna``; not ``uxms_nav``, an
    alias of ``uxms``): a copy of an app or a script kept under a new name most often
    connects under the old one, and moos-lint cannot see which, its source not being
    linted."""
    return (
        len(longer) > len(shorter) and longer.startswith(shorter) and longer[len(shorter)].isalnum()
    )


def extends_one_of(name: str, names: frozenset[str]) -> bool:
    """Whether ``name`` :func:`extends` one of ``names`` (all lower case), looked up by
    the starts of ``name``: time in its length alone, however many names."""
    return any(name[:k] in names and extends(name, name[:k]) for k in range(1, len(name)))


def app_example(ctx) -> bool:
    """Whether the mission is an app's example configuration, not a mission to launch.

    A file named after one of its blocks (``src/pCoroner/pCoroner.moos``), with no
    global setting (no ``ServerPort``, no ``Community``: a fragment), that no other
    file includes, and whose ANTLER block does not launch that app: the block lists
    what the app reads (a watchdog's processes to watch), and the app is started
    with the file (``pCoroner file.moos``)."""
    moos = ctx.moos
    if moos.globals or ctx.path in ctx.run.included_elsewhere:
        return False
    stem = os.path.splitext(os.path.basename(ctx.path))[0].lower()
    if not any(b.header is not None and b.lname == stem for b in moos.blocks):
        return False
    return not any(stem in (run.program.lower(), (run.name or "").lower()) for run in moos.runs)


def commented_runs(run, moos, cat, mission: str) -> tuple[dict[str, str], dict[str, str]]:
    """:func:`_commented_runs` of a mission, worked out once per run (the check of the
    mission and the facts gathered across the missions both ask for it)."""
    memo: dict[str, tuple[dict[str, str], dict[str, str]]] = per_run(
        run, "commented-runs", lambda units: {}
    )
    found = memo.get(mission)
    if found is None:
        found = memo[mission] = _commented_runs(moos, cat, mission)
    return found


def _commented_runs(moos, cat, mission: str) -> tuple[dict[str, str], dict[str, str]]:
    """Where a ``//Run = NAME`` line (or ``#Run = NAME``) sits in an ANTLER block, by the
    lower-case name of every block its process would read were it launched (the first
    such line): the line is read as a live one is, so an app whose ``main`` hard-codes its name
    (``Run("iRemote", ...)`` in iRemoteMod) and a script that connects under a name it
    quotes count too. Second, where each line is whose program moos-lint knows nothing
    of, by its lower-case name."""
    found: dict[str, str] = {}
    unknown: dict[str, str] = {}
    for antler in moos.antler_blocks:
        if antler.open is None:
            continue
        inside = False
        for line in moos.lines:
            if line is antler.open:
                inside = True
                continue
            if line is antler.close:
                break
            if not inside:
                continue
            m = _COMMENTED_RUN.match(line.text)
            if not m:
                continue
            here = where(line)
            eq = line.text.index("=")  # the one of `// Run =`: the key holds none
            # a trailing comment, as on a live line (`//Run = X @ NewConsole = false //~Y`)
            value = strip_comment(line.text[eq + 1 :]).rstrip()
            if value.endswith("*/"):  # `/* Run = X @ NewConsole = false */`
                value = value[:-2]
            run = parse_run(Param("Run", value.strip(), line, 0, eq + 1, len(line.text)), antler)
            # its name or alias, a script's stem (`// Run = ./iPydyna.py` would read
            # `ProcessConfig = iPydyna`), and the name its app's main hard-codes
            for name in (*run.block_names, *cat.block_names(run)):
                found.setdefault(name.lower(), here)
            if cat.program_name(run.program) is None:
                # an app whose source is not linted: its main may hard-code a shorter
                # name (iRemoteMod reads `iRemote`), which unlaunched-process-config looks for
                unknown.setdefault(run.name.lower(), here)
            if run.script_block is not None and not has_macro(run.binary):
                for name in script_names(mission, run.binary) or ():
                    found.setdefault(name, here)
    return found, unknown
