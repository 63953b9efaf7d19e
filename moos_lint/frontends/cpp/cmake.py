"""The process name CMake gives an app: ``add_executable(pName ...)``, read as text.

CMake is never run. ``${VAR}`` is resolved from ``set(VAR value)`` in the same
file; a name that stays unresolved is not used. A folder that builds several
programs gives the app the one whose source list holds the app class's files.
A source file its folder's CMakeLists.txt compiles into no target, when its lists
are all known, is not part of the app (:func:`unbuilt`).
"""

from __future__ import annotations

import os
import re

from moos_lint.files.source import SourceFile, read_source
from moos_lint.files.suffixes import CPP_SOURCE_SUFFIXES

_ADD_EXEC = re.compile(r"\badd_executable\s*\(\s*([^\s()]+)([^)]*)\)", re.I)
_ADD_TARGET = re.compile(r"\badd_(?:executable|library)\s*\(\s*([^\s()]+)([^)]*)\)", re.I)
#: what adds sources a list of names does not show: a glob, a folder's every file, a
#: list grown elsewhere or in a loop, an included file, sources added to a target later
_OPEN_LISTS = re.compile(
    r"\b(?:file\s*\(\s*GLOB|aux_source_directory|list\s*\(\s*(?:APPEND|INSERT)|foreach"
    r"|include|target_sources|string\s*\()\b",
    re.I,
)
_SET_LIST = re.compile(r"\bset\s*\(\s*([A-Za-z_][A-Za-z0-9_]*)\s+([^)]*)\)", re.I)
_VAR = re.compile(r"\$\{(\w+)\}")
_COMMENT = re.compile(r"#[^\n]*")


def _read(path: str) -> str | None:
    src = read_source(path)
    return src.text if isinstance(src, SourceFile) else None


def _targets(text: str, pattern: re.Pattern[str]) -> list[tuple[str, str, int]]:
    """(name, source list, line) of every target ``pattern`` finds in ``text`` (comments
    removed), ``${VAR}`` replaced by the values of ``set(VAR a b c)`` (in a name, by the
    first value); what stays unresolved keeps its ``${VAR}``."""
    text = _COMMENT.sub("", text)
    lists = {m.group(1): m.group(2) for m in _SET_LIST.finditer(text)}
    sets = {k: v.split()[0].strip('"') for k, v in lists.items() if v.split()}  # first value
    out = []
    for m in pattern.finditer(text):
        name, srcs = m.group(1), m.group(2)
        for _ in range(3):
            name = _VAR.sub(lambda v: sets.get(v.group(1), v.group(0)), name)
            srcs = _VAR.sub(lambda v: lists.get(v.group(1), v.group(0)), srcs)
        out.append((name, srcs, text.count("\n", 0, m.start()) + 1))
    return out


def _executables(text: str) -> list[tuple[str, str, int]]:
    """(name, source list, line) of every add_executable with a resolvable name."""
    return [
        (name, srcs, line)
        for name, srcs, line in _targets(text, _ADD_EXEC)
        if "${" not in name and name.upper() not in ("WIN32", "MACOSX_BUNDLE")
    ]


def unbuilt(folder: str, names: frozenset[str]) -> frozenset[str]:
    """Which of the source files ``names`` (file names in ``folder``) the folder's own
    CMakeLists.txt compiles into none of its executables and libraries: a stray copy
    (``Test.cpp``, ``Old_App.cpp``) beside the app's real sources. Empty when that is not
    clear: no CMakeLists.txt, no target, a glob, a list grown elsewhere, a name left
    unresolved. Headers are never judged (a source includes them)."""
    sources = frozenset(n for n in names if n.lower().endswith(CPP_SOURCE_SUFFIXES))
    if not sources:
        return frozenset()
    text = _read(os.path.join(folder, "CMakeLists.txt"))
    if text is None or _OPEN_LISTS.search(_COMMENT.sub("", text)):
        return frozenset()
    targets = _targets(text, _ADD_TARGET)
    if not targets or any("${" in srcs or "$<" in srcs for _n, srcs, _l in targets):
        return frozenset()  # no target, or a list we cannot read: it may hold any file
    listed = set().union(*(_file_names(srcs) for _n, srcs, _l in targets))
    return frozenset(n for n in sources if n not in listed)


def executables_in(folder: str) -> list[str]:
    """The names of the executables the folder's own CMakeLists.txt builds."""
    text = _read(os.path.join(folder, "CMakeLists.txt"))
    return [name for name, _srcs, _line in _executables(text or "")]


def executable_name(
    folder: str, members: frozenset[str] = frozenset()
) -> tuple[str, str, int] | None:
    """(name, CMakeLists path, line) of the executable built from ``folder``, when one is clear.

    A CMakeLists.txt that builds several programs from one folder (its own, or the
    one above it listing ``folder/...`` sources) names the app's by the folder's name,
    or by the one source list that holds one of ``members`` (the file names of the
    app's own class).
    """
    here = os.path.join(folder, "CMakeLists.txt")
    if os.path.isfile(here):
        text = _read(here)
        if text is not None:
            exes = _executables(text)
            base = os.path.basename(os.path.normpath(folder))
            if len(exes) == 1:
                return exes[0][0], here, exes[0][2]
            for name, _srcs, line in exes:
                if name == base:
                    return name, here, line
            holding = [(n, ln) for n, srcs, ln in exes if members & _file_names(srcs)]
            if len(holding) == 1:
                return holding[0][0], here, holding[0][1]
        return None
    parent = os.path.dirname(os.path.normpath(folder))
    above = os.path.join(parent, "CMakeLists.txt")
    if os.path.isfile(above):
        text = _read(above)
        base = os.path.basename(os.path.normpath(folder))
        inside = [
            (name, srcs, line)
            for name, srcs, line in _executables(text or "")
            if re.search(r"(^|[\s/])" + re.escape(base) + r"/", srcs)
        ]
        if len(inside) > 1:  # several programs from the folder: the one holding the class
            inside = [e for e in inside if members & _file_names(e[1])]
        if len(inside) == 1:
            return inside[0][0], above, inside[0][2]
    return None


def _file_names(srcs: str) -> set[str]:
    """The file names (no folder) a source list names."""
    return {os.path.basename(tok.strip('"')) for tok in srcs.split()}
