"""Keys MOOS apps read from anywhere in a mission file, blocks included.

``CMOOSFileReader::GetValue`` scans every line of the file and the first match
wins (MOOSFileReader.cpp:247-270): the stock top-of-file keys (`ServerPort`,
`LatOrigin`, `term_reporting`, ...) and the keys the run's own C++ apps read
with ``m_MissionReader.GetValue("KEY", s)`` are read wherever they stand.
unknown-key (H005) takes them as top-of-file keys; unknown-parameter (M001)
does not report them inside a block.

An app may build the name it reads: ``GetValue(s + "_Longitude", lon)`` in a loop
over ``s = "Beacon" + id`` reads `BeaconA_Longitude`, `BeaconB_Longitude`, ...
The literal start or end of such a name is kept (:class:`BuiltKeys`), and a
mission reader asked for a name with no literal part (``GetValue(key, v)``) may
read any key.
"""

from __future__ import annotations

import re
from dataclasses import dataclass

from moos_lint.frontends.parsers.nodes import GLOBAL_KEYS, MOOS_GLOBALS
from moos_lint.semantics.catalogue import app_text

#: the stock keys, lower case
STOCK_FILE_WIDE = frozenset({k.lower() for k in MOOS_GLOBALS} | set(GLOBAL_KEYS))

#: literal first, as the catalogue's ``DELEGATE``: searched over every file of every app
_GET_VALUE = re.compile(r"GetValue(?<=\bGetValue)\s*\(\s*\"([A-Za-z0-9_]+)\"", re.ASCII)


#: a ``GetValue(`` call, literal first; its first argument is read by :func:`_first_argument`
_GET_VALUE_CALL = re.compile(r"GetValue(?<=\bGetValue)\s*\(", re.ASCII)
#: a name's literal start (``"Beacon" + id``, ``std::string("Beacon") + id``) or end
_LITERAL_START = re.compile(r'(?:(?:std::)?string\s*\(\s*)?"(\w+)"\s*\)?\s*\+', re.ASCII)
_LITERAL_END = re.compile(r'\+\s*(?:(?:std::)?string\s*\(\s*)?"(\w+)"\s*\)?$', re.ASCII)
#: the object a call is made on is a mission file reader (``m_MissionReader.``)
_READER = re.compile(r"Reader\w*\s*(?:\.|->)\s*$")
#: the shortest literal start or end taken as a form (``+ "_X"`` says too little)
MIN_FORM = 3


@dataclass(frozen=True)
class BuiltKeys:
    """How the run's own apps build the names they read with ``GetValue``: a literal
    start (``"Beacon" + id``) or end (``s + "_Longitude"``), lower case, and whether a
    mission reader is asked for a name with no literal part at all (``any_key``)."""

    starts: tuple[str, ...] = ()
    ends: tuple[str, ...] = ()
    any_key: bool = False

    def matches(self, lkey: str) -> bool:
        """Whether the lower-case key ``lkey`` has a start or an end an app reads."""
        return lkey.startswith(self.starts) or lkey.endswith(self.ends)


def _first_argument(text: str, start: int) -> str | None:
    """The first argument of the call whose ``(`` is just before ``start``; None when the
    call has one argument or none (not a read into a variable)."""
    depth = 0
    for i in range(start, min(len(text), start + 300)):
        c = text[i]
        if c in "([{":
            depth += 1
        elif c in ")]}":
            if depth == 0:
                return None
            depth -= 1
        elif c == "," and depth == 0:
            return text[start:i].strip()
        elif c == ";":
            return None
    return None


def _bare(arg: str) -> str:
    """``(s + "_X").c_str()`` as ``s + "_X"``."""
    for tail in (".c_str()", ".data()"):
        if arg.endswith(tail):
            arg = arg[: -len(tail)].rstrip()
    if arg.startswith("(") and arg.endswith(")"):
        arg = arg[1:-1].strip()
    return arg


def repo_globals(run) -> frozenset[str]:
    """The keys the run's own C++ apps read with ``GetValue``, as written; once per run."""
    if run.memos.repo_globals is None:
        _read_names(run)
    return run.memos.repo_globals


def built_keys(run) -> BuiltKeys:
    """The names the run's own C++ apps build for ``GetValue``; once per run."""
    if run.memos.built_keys is None:
        _read_names(run)
    return run.memos.built_keys


def _read_names(run) -> None:
    """One pass over the run's apps: the names they give ``GetValue`` as literals
    (:func:`repo_globals`) and the names they build (:func:`built_keys`)."""
    keys: set[str] = set()
    starts: set[str] = set()
    ends: set[str] = set()
    any_key = False
    for unit in run.units:
        app = getattr(unit, "cpp", None)
        for f in getattr(app, "files", None) or []:
            # the text the C++ front end read (every file of an app is in the run's sources)
            text = app_text(f.path, run.sources)
            if "GetValue" not in text:
                continue
            keys.update(_GET_VALUE.findall(text))
            for m in _GET_VALUE_CALL.finditer(text):
                arg = _first_argument(text, m.end())
                if not arg or (arg.startswith('"') and arg.endswith('"') and arg.count('"') == 2):
                    continue  # a literal name (above), or no name
                arg = _bare(arg)
                head = _LITERAL_START.match(arg)
                tail = _LITERAL_END.search(arg)
                if head and len(head.group(1)) >= MIN_FORM:
                    starts.add(head.group(1).lower())
                if tail and len(tail.group(1)) >= MIN_FORM:
                    ends.add(tail.group(1).lower())
                if not head and not tail and '"' not in arg:
                    reader = _READER.search(text, max(0, m.start() - 80), m.start())
                    any_key = any_key or reader is not None
    run.memos.repo_globals = frozenset(keys)
    run.memos.built_keys = BuiltKeys(tuple(sorted(starts)), tuple(sorted(ends)), any_key)


def file_wide(run) -> frozenset[str]:
    """Every key read from anywhere in the file, lower case: the stock ones and the run's."""
    found = run.memos.file_wide
    if found is None:
        found = run.memos.file_wide = STOCK_FILE_WIDE | {k.lower() for k in repo_globals(run)}
    return found


__all__ = ["STOCK_FILE_WIDE", "BuiltKeys", "built_keys", "file_wide", "repo_globals"]
