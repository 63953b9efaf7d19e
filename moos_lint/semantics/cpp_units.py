"""C++ files as lint units: one unit per folder (an app), carrying its :class:`AppModel`.

:func:`build_cpp_units` parses the files, joins what crosses folders (base
classes), reads them again as compiled with libclang when the deep mode is asked for,
and finishes the value analysis across the repository.
"""

from __future__ import annotations

import os
import re
from collections.abc import Callable

from moos_lint.files.source import SourceFile
from moos_lint.files.suffixes import Kind
from moos_lint.frontends.cpp.app import build_apps, helper_io, link_apps, read_relevant
from moos_lint.frontends.cpp.cmake import unbuilt
from moos_lint.frontends.cpp.file_names import FileNames
from moos_lint.frontends.cpp.model import AppModel, CppFile, GeodesyCall
from moos_lint.frontends.nsplug import Expansion
from moos_lint.frontends.unit import Unit
from moos_lint.semantics.run_state import RunView

#: what a worker process read and parsed of one folder: its relevant sources, its files,
#: the value analysis's index of each file it read
ParsedFolder = tuple[dict[str, SourceFile], list[CppFile], dict[str, FileNames]]


def build_cpp_units(
    run: RunView, paths: list[str], parsed: dict[str, ParsedFolder] | None = None
) -> list[Unit]:
    """Units for the C++ files in ``paths``: one per folder, in folder order.

    ``parsed`` (folder -> (relevant sources, extracted files, index of the files read))
    is what worker processes already read and parsed (:mod:`moos_lint.speed.parallel`).
    """
    in_memory = run.preprocessor.cache.in_memory
    if parsed is not None and any(in_memory(p) is not None for p in paths):
        parsed = None  # files being fixed: the workers read the disk's text
    names: dict[str, FileNames] = {}
    if parsed is None:
        sources = read_relevant(paths, in_memory, names)
        run.sources.update(sources)
        apps = {a.folder: a for a in build_apps(sources)}
    else:
        found = {p: s for srcs, _, _ in parsed.values() for p, s in srcs.items()}
        for _, _, folder_names in parsed.values():
            names.update(folder_names)
        sources = {p: found[p] for p in paths if p in found}  # in the order of ``paths``
        run.sources.update(sources)
        linked = [AppModel(folder=f, files=fs) for f, (s, fs, _) in sorted(parsed.items()) if s]
        link_apps(linked)
        apps = {a.folder: a for a in linked}
    compiled = None
    if run.settings.cpp_backend == "clang" and apps:
        from moos_lint.frontends.cpp.clang import sharpen

        compiled = sharpen(list(apps.values()), sources, run.settings)
    if apps:
        from moos_lint.frontends.cpp.values import link_values

        link_values(list(apps.values()), paths, compiled, names)
        _own_geodesy(list(apps.values()), paths)
    units = []
    folders: dict[str, list[str]] = {}
    for p in paths:
        folders.setdefault(os.path.dirname(p), []).append(p)
    for folder, files in sorted(folders.items()):
        app = apps.get(folder) or AppModel(folder=folder)
        first = sorted(f.path for f in app.files)[0] if app.files else sorted(files)[0]
        if app.is_app:  # the I/O of the app's helper files that never name the MOOS API
            helpers = [p for p in files if p not in sources]
            stray = unbuilt(folder, frozenset(os.path.basename(p) for p in helpers))
            for src, helper in helper_io(p for p in helpers if os.path.basename(p) not in stray):
                run.sources[helper.path] = src
                app.files.append(helper)
        units.append(Unit(path=first, kind=Kind.CPP, expansion=Expansion(path=first), cpp=app))
    return units


def _own_geodesy(apps: list[AppModel], paths: list[str]) -> None:
    """Mark the calls of a CMOOSGeodesy conversion whose name the repository declares
    itself with other parameters (its own order). The repository is searched only for
    calls that would be reported."""
    from moos_lint.files.source import read_bytes
    from moos_lint.frontends.cpp.declarations import parameter_names
    from moos_lint.semantics.cpp_checks import differs_from_geodesy, geodesy_call_findings

    suspects = [g for a in apps for g in a.geodesy_calls if any(geodesy_call_findings(g))]
    if not suspects:
        return
    declared = parameter_names({g.function for g in suspects}, paths, read_bytes)
    for g in suspects:
        own = [p for p in declared.get(g.function, []) if differs_from_geodesy(g.function, p)]
        if own:
            g.own_signature = tuple(own[0])
        elif g.receiver and _declared_other_than_geodesy(g, paths, read_bytes):
            # a method of that name of another class, whose declaration is not among
            # the linted files (``Geodesy geod;`` of a library elsewhere): not judged
            g.own_signature = ()


def _declared_other_than_geodesy(
    g: GeodesyCall, paths: list[str], read: Callable[[str], object]
) -> bool:
    """Whether the call's object is declared, in the files of the call's folder, with a
    type other than CMOOSGeodesy (``Geodesy geod;``, ``MyGeo* m_geo;``)."""
    name = re.escape((g.receiver or "").rsplit(".", 1)[-1].rsplit("->", 1)[-1])
    declaration = re.compile(
        rb"\b([A-Za-z_][\w:]*)\s*[*&]?\s*\b" + name.encode() + rb"\s*[;=,)\[{(]"
    )
    folder = os.path.dirname(g.span.path)
    for path in paths:
        if os.path.dirname(path) != folder:
            continue
        data = read(path)
        if not isinstance(data, bytes):
            continue  # (a file that cannot be read: read_bytes said why)
        for m in declaration.finditer(data):
            kind = m.group(1).rsplit(b"::", 1)[-1]
            if kind in _NOT_TYPES:
                continue
            return kind != b"CMOOSGeodesy"
    return False


#: words that come before a name without being its type (``return geod;``)
_NOT_TYPES = frozenset({b"return", b"delete", b"new", b"sizeof", b"case", b"goto", b"else"})
