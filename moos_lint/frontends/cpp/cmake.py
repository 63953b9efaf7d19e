"""The process name CMake gives an app: ``add_executable(pName ...)``, read as text.

CMake is never run. ``${VAR}`` is resolved from ``set(VAR value)`` in the same
file; a name that stays unresolved is not used.
"""

from __future__ import annotations

import os
import re

from moos_lint.files.source import SourceFile, read_source

_ADD_EXEC = re.compile(r"\badd_executable\s*\(\s*([^\s()]+)([^)]*)\)", re.I)
_SET = re.compile(r"\bset\s*\(\s*([A-Za-z_][A-Za-z0-9_]*)\s+\"?([^\s()\"]+)\"?", re.I)
_COMMENT = re.compile(r"#[^\n]*")


def _read(path: str) -> str | None:
    src = read_source(path)
    return src.text if isinstance(src, SourceFile) else None


def _executables(text: str) -> list[tuple[str, str, int]]:
    """(name, source list, line) of every add_executable with a resolvable name."""
    text = _COMMENT.sub("", text)
    sets = {m.group(1): m.group(2) for m in _SET.finditer(text)}
    out = []
    for m in _ADD_EXEC.finditer(text):
        name = m.group(1)
        for _ in range(3):
            name = re.sub(r"\$\{(\w+)\}", lambda v: sets.get(v.group(1), v.group(0)), name)
        if "${" in name or name.upper() in ("WIN32", "MACOSX_BUNDLE"):
            continue
        out.append((name, m.group(2), text.count("\n", 0, m.start()) + 1))
    return out


def executable_name(folder: str) -> tuple[str, str, int] | None:
    """(name, CMakeLists path, line) of the executable built from ``folder``, when one is clear."""
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
        return None
    parent = os.path.dirname(os.path.normpath(folder))
    above = os.path.join(parent, "CMakeLists.txt")
    if os.path.isfile(above):
        text = _read(above)
        base = os.path.basename(os.path.normpath(folder))
        for name, srcs, line in _executables(text or ""):
            if re.search(r"(^|[\s/])" + re.escape(base) + r"/", srcs):
                return name, above, line
    return None
