"""Helpers for the behavior-catalogue rules: known behavior kinds, the repo's own classes."""

from __future__ import annotations

import os
import re
from typing import TYPE_CHECKING

from moos_lint.files.source import read_head
from moos_lint.files.stamps import file_stamp
from moos_lint.files.suffixes import is_cpp
from moos_lint.files.walk import project_walk
from moos_lint.semantics.catalogue import BehaviorInfo, catalogue_for

if TYPE_CHECKING:  # rules are loaded by the engine: they do not import it
    from moos_lint.core.engine import Context


def repo_classes(ctx: Context) -> dict[str, str]:
    """The names of the C++ files and classes under the project root, lower case -> as
    written (``BHV_Pulse.cpp``: bhv_pulse -> BHV_Pulse).

    MOOS-IvP behaviors live in a file named after their class, so a kind with
    such a file is the repo's own behavior. Cached on the run.
    """
    run = ctx.run
    cached = run.memos.repo_cpp_stems
    if cached is not None:
        return cached
    stems: set[str] = set()
    for unit in run.units:
        app = unit.cpp
        for f in app.files if app is not None else ():
            for c in f.classes:
                stems.add(c.name)
    root = _root(ctx)
    for dirpath, files in project_walk(root):
        for name in files:
            if is_cpp(name):
                stem = os.path.splitext(name)[0]
                stems.add(stem)
                if name.lower().startswith("bhv_") and name.lower().endswith(".cpp"):
                    files_of = run.memos.repo_behavior_files.setdefault(stem.lower(), [])
                    files_of.append(os.path.join(dirpath, name))
            if name == "CMakeLists.txt":
                # the helm loads a behavior by its library's name (libBHV_X.so)
                stems.update(_library_behaviors(os.path.join(dirpath, name)))
            if name.endswith((".h", ".hpp")) and not name.lower().startswith("bhv_"):
                # a behavior class in a file named otherwise (TrailiSBL_PingFormation.h
                # declares BHV_TrailiSBL_PingFormation): read the declarations
                stems.update(_declared_behaviors(os.path.join(dirpath, name)))
    run.memos.repo_cpp_stems = found = {s.lower(): s for s in sorted(stems)}
    return found


#: ``postMessage("VAR", value)`` and its kin: what an IvP behavior posts, and under
#: which name (ivp/src/lib_behaviors/IvPBehavior.h:128-134; postEMessage and
#: postWMessage take a text, not a name)
_POST = re.compile(rb"post(?:Bool|Int|Repeatable|)Message\s*\(\s*([^,)]*)")
_NAME = re.compile(rb'^"([A-Za-z_]\w*)"\s*$')


def repo_behavior_posts(ctx: Context, kind: str) -> tuple[frozenset[str], bool]:
    """What the project's own C++ of behavior ``kind`` (``BHV_FrontSearch.cpp``) posts
    (``postMessage("VNAME", m_name)``), and whether that is all it may post: its file was
    found and every post names its variable as a literal."""
    memo = ctx.run.memos.repo_behavior_posts
    low = kind.lower()
    if low in memo:
        return memo[low]
    repo_classes(ctx)  # (the walk finds the files)
    paths = ctx.run.memos.repo_behavior_files.get(low, [])
    found: set[str] = set()
    known = bool(paths)
    for path in paths:
        data = read_head(path, 1024 * 1024)
        if data is None:
            known = False
            continue
        for m in _POST.finditer(data):
            name = _NAME.match(m.group(1).strip())
            if name is None:
                known = False  # a name held elsewhere (``postMessage(m_report_var, ...)``)
            else:
                found.add(name.group(1).decode("ascii"))
    memo[low] = answer = (frozenset(found), known)
    return answer


#: literal first (``class(?<=\bclass)`` is ``\bclass``): a leading ``\b`` is tried at every byte
_CLASS = re.compile(rb"class(?<=\bclass)\s+(BHV_\w+)\s*(?::|\{)")


def _declared_behaviors(path: str) -> set[str]:
    """The names of the ``BHV_*`` classes a header declares."""
    data = read_head(path, 256 * 1024)
    if data is None or b"BHV_" not in data:
        return set()
    return {m.group(1).decode("ascii", "replace") for m in _CLASS.finditer(data)}


_LIBRARY = re.compile(rb"add_library\s*\(\s*(BHV_\w+)", re.IGNORECASE)


def _library_behaviors(path: str) -> set[str]:
    """The ``BHV_*`` library targets a CMakeLists.txt builds."""
    data = read_head(path, 256 * 1024)
    if data is None:
        return set()
    return {m.group(1).decode("ascii", "replace") for m in _LIBRARY.finditer(data)}


def _root(ctx: Context) -> str:
    """The project root (:mod:`moos_lint.files.project`), which the settings carry: the
    config's folder, else the version-control top, else the working folder."""
    return os.path.abspath(ctx.settings.root)


_LITERAL = re.compile(rb'"([A-Za-z_][A-Za-z0-9_]*)"')


def own_source_keys(ctx: Context, kind: str, bhv_path: str) -> frozenset[str]:
    """The keys (lower case) that the project's own copy of behavior ``kind`` may read:
    every string literal of its C++ file named after the class (``BHV_AvoidCollision.cpp``
    of a vendored older MOOS-IvP, whose ``setParam`` still takes ``active_grade``).

    Only a project that builds its own helm runs its copies of the stock behaviors: the
    helm makes a stock kind with its static factory before it looks for a library of that
    name (BehaviorSet.cpp), so a student's own ``BHV_ZigZag`` never replaces MOOS-IvP's.
    The helm is looked for as MOOS-IvP lays it out, a ``lib_helmivp/BFactoryStatic.cpp``
    in a ``src`` (or ``ivp/src``) folder at or above the behavior file's, and the copy
    beside it (``src/*/BHV_X.cpp``): a few look-ups, not a walk of the project (the
    language server asks at every edit). Empty when there is no such helm or copy."""
    folder = os.path.dirname(os.path.abspath(bhv_path))
    sources = ctx.run.memos.helm_sources.get(folder)
    if sources is None:
        sources = ctx.run.memos.helm_sources[folder] = _helm_sources(folder)
    if not sources:
        return frozenset()
    # by the helms found, not by the mission's folder: the missions of a tree share them
    memo = ctx.run.memos.repo_behavior_keys
    key = f"{kind}@{os.pathsep.join(sources)}"
    found = memo.get(key)
    if found is not None:
        return found
    keys: set[str] = set()
    for src in sources:
        copies = ctx.run.memos.helm_copies.get(src)
        if copies is None:
            copies = ctx.run.memos.helm_copies[src] = _behavior_sources(src)
        for path in copies.get(kind + ".cpp", ()):
            keys.update(_literals(path))
    memo[key] = found = frozenset(keys)
    return found


#: Kept from one run to the next, as the language server re-lints at every edit: a
#: helm source folder -> (the modification time of each folder below it, what
#: :func:`_behavior_sources` found there); a behavior's C++ file -> (its stamp, its
#: literals). A listing holds while no folder below gained or lost an entry, a file's
#: literals while the file is unchanged.
_KEPT_COPIES: dict[str, tuple[tuple[tuple[str, int], ...], dict[str, list[str]]]] = {}
_KEPT_LITERALS: dict[str, tuple[tuple[int, int], frozenset[str]]] = {}
_KEPT_SIZE = 256


def _literals(path: str) -> frozenset[str]:
    """The string literals (lower case) of the C++ file at ``path`` that could be keys."""
    stamp = file_stamp(path)
    kept = _KEPT_LITERALS.get(path)
    if kept is not None and stamp is not None and kept[0] == stamp:
        return kept[1]
    data = read_head(path, 1024 * 1024)
    if data is None:
        return frozenset()
    found = frozenset(m.group(1).decode("ascii").lower() for m in _LITERAL.finditer(data))
    if stamp is not None:
        if len(_KEPT_LITERALS) >= _KEPT_SIZE:
            _KEPT_LITERALS.clear()
        _KEPT_LITERALS[path] = (stamp, found)
    return found


#: where a source tree keeps the helm's library, from a folder at or above a mission's
_HELM_LIBRARY = (
    "lib_helmivp",
    os.path.join("src", "lib_helmivp"),
    os.path.join("ivp", "src", "lib_helmivp"),
)


def _behavior_sources(src: str) -> dict[str, list[str]]:
    """The ``BHV_*.cpp`` files one folder below source folder ``src``, by file name."""
    found: dict[str, list[str]] = {}
    try:
        stamps = tuple(
            sorted(
                (e.path, e.stat().st_mtime_ns)
                for e in os.scandir(src)
                if e.is_dir() and e.name[0] != "."
            )
        )
    except OSError:
        return found
    kept = _KEPT_COPIES.get(src)
    if kept is not None and kept[0] == stamps:
        return kept[1]
    for sub, _mtime in stamps:
        try:
            names = [e.name for e in os.scandir(sub) if e.name.startswith("BHV_")]
        except OSError:
            continue
        for name in sorted(names):
            if name.endswith(".cpp"):
                found.setdefault(name, []).append(os.path.join(sub, name))
    if len(_KEPT_COPIES) >= _KEPT_SIZE:
        _KEPT_COPIES.clear()
    _KEPT_COPIES[src] = (stamps, found)
    return found


def _helm_sources(folder: str, levels: int = 6) -> list[str]:
    """The source folders (the parents of ``lib_helmivp``) holding a copy of the helm's
    factory of stock behaviors, at or above ``folder``."""
    found: list[str] = []
    here = folder
    for _ in range(levels):
        for lib in _HELM_LIBRARY:
            if os.path.isfile(os.path.join(here, lib, "BFactoryStatic.cpp")):
                found.append(os.path.dirname(os.path.join(here, lib)))
        parent = os.path.dirname(here)
        if parent == here:
            break
        here = parent
    return found


def lookup(ctx: Context, kind: str) -> tuple[BehaviorInfo | None, bool]:
    """(catalogue entry or None, known at all)."""
    cat = catalogue_for(ctx.run)
    info = cat.behavior(kind)
    if info is not None:
        return info, True
    return None, cat.behavior_exists(kind) or kind.lower() in repo_classes(ctx)


def repo_behaviors(ctx: Context) -> dict[str, str]:
    """The project's own behavior kinds (its ``BHV_*`` files, classes and libraries),
    lower case -> as written."""
    return {low: name for low, name in repo_classes(ctx).items() if low.startswith("bhv_")}
