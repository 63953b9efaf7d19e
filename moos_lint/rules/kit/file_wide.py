"""Keys MOOS apps read from anywhere in a mission file, blocks included.

``CMOOSFileReader::GetValue`` scans every line of the file and the first match
wins (MOOSFileReader.cpp:247-270): the stock top-of-file keys (`ServerPort`,
`LatOrigin`, `term_reporting`, ...) and the keys the run's own C++ apps read
with ``m_MissionReader.GetValue("KEY", s)`` are read wherever they stand.
unknown-key (H005) takes them as top-of-file keys; unknown-parameter (M001)
does not report them inside a block.
"""

from __future__ import annotations

import re

from moos_lint.frontends.parsers.nodes import GLOBAL_KEYS, MOOS_GLOBALS
from moos_lint.semantics.catalogue import app_text

#: the stock keys, lower case
STOCK_FILE_WIDE = frozenset({k.lower() for k in MOOS_GLOBALS} | set(GLOBAL_KEYS))

#: literal first, as the catalogue's ``DELEGATE``: searched over every file of every app
_GET_VALUE = re.compile(r"GetValue(?<=\bGetValue)\s*\(\s*\"([A-Za-z0-9_]+)\"", re.ASCII)


def repo_globals(run) -> frozenset[str]:
    """The keys the run's own C++ apps read with ``GetValue``, as written; once per run."""
    found = run.memos.repo_globals
    if found is not None:
        return found
    keys: set[str] = set()
    for unit in run.units:
        app = getattr(unit, "cpp", None)
        for f in getattr(app, "files", None) or []:
            # the text the C++ front end read (every file of an app is in the run's sources)
            keys.update(_GET_VALUE.findall(app_text(f.path, run.sources)))
    run.memos.repo_globals = found = frozenset(keys)
    return found


def file_wide(run) -> frozenset[str]:
    """Every key read from anywhere in the file, lower case: the stock ones and the run's."""
    found = run.memos.file_wide
    if found is None:
        found = run.memos.file_wide = STOCK_FILE_WIDE | {k.lower() for k in repo_globals(run)}
    return found


__all__ = ["STOCK_FILE_WIDE", "file_wide", "repo_globals"]
