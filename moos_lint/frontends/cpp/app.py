"""Building app models: C++ files grouped by folder, parsed once, with their process names."""

from __future__ import annotations

import os
import re
import threading
from collections import OrderedDict
from collections.abc import Callable, Iterable
from typing import Any

from moos_lint.files.diagnostics import Span
from moos_lint.files.source import SourceFile, decode, read_bytes
from moos_lint.files.suffixes import CPP_SUFFIXES
from moos_lint.frontends.cpp.cmake import executable_name, executables_in, unbuilt
from moos_lint.frontends.cpp.file_names import FileNames, file_names
from moos_lint.frontends.cpp.model import APP_BASES, AppModel, CppClass, CppFile, IOUse
from moos_lint.frontends.cpp.prefilter import mentions_moos


def read_relevant(
    paths: Iterable[str],
    in_memory: Callable[[str], object] | None = None,
    names: dict[str, FileNames] | None = None,
) -> dict[str, SourceFile]:
    """The C++ files that can be read and mention the MOOS API.

    The prefilter runs on the bytes, before decoding: most C++ files of a
    repository never mention the MOOS API and are never decoded. (The pattern is
    ASCII, so bytes and the re-encoded text match alike.) ``in_memory``: the text of
    a file held in memory instead of the disk's (a file ``--fix`` is fixing), or None.
    ``names``: when given, the value analysis's index of every file read from the disk
    is added to it (:func:`~moos_lint.frontends.cpp.file_names.file_names`), so that
    it needs no read of its own.
    """
    out: dict[str, SourceFile] = {}
    for path in paths:
        held = in_memory(path) if in_memory is not None else None
        if held is not None:
            if isinstance(held, SourceFile) and mentions_moos(held.text.encode("utf-8")):
                out[path] = held
            continue
        data = read_bytes(path)
        if not isinstance(data, bytes):
            continue
        kept = _read_memo.get(path) if PARSE_MEMO_SIZE else None
        if kept is not None and kept[0] == data:
            src = kept[1]  # the same bytes as last time: the same verdict, text and index
            if names is not None:
                names[path] = kept[2]
        else:
            src = None
            if mentions_moos(data):
                decoded = decode(data, path)
                if isinstance(decoded, SourceFile):
                    src = decoded
            index = file_names(data) if names is not None or PARSE_MEMO_SIZE else None
            if names is not None and index is not None:
                names[path] = index
            if PARSE_MEMO_SIZE and index is not None:
                _read_memo[path] = (data, src, index)
        if src is not None:
            out[path] = src
    return out


_INCLUDE_LINE = re.compile(rb'^[ \t]*#[ \t]*include[ \t]*[<"]([^>"\r\n]+)[>"]', re.M)
#: literal first (``add_(?<=\badd_)`` is ``\badd_``): a leading ``\b`` is tried at every byte
_LINK_CALL = re.compile(rb"(add_(?<=\badd_)(?:any|udp|tcp|serial)_connection)[ \t]*\(")


#: a device's path written as a string literal (``#define EVDEV_DIR "/dev/input/by-id/"``)
_DEVICE_LITERAL = re.compile(rb'"(/dev/[^"\r\n]*)"')


def _commented(data: bytes, pos: int) -> bool:
    """Whether ``pos`` is on a line after a ``//`` or on a line that starts a ``/*`` or
    ``*`` comment (a usage note quoting a device, not code that opens one)."""
    start = data.rfind(b"\n", 0, pos) + 1
    before = data[start:pos]
    return b"//" in before or before.lstrip().startswith((b"*", b"/*"))


def helper_io(paths: Iterable[str]) -> list[tuple[SourceFile, CppFile]]:
    """The I/O of an app's own C++ files that never mention the MOOS API: a helper class
    that opens the serial port, the socket or the autopilot link. Read from the bytes
    (the headers they include, MAVSDK's ``add_*_connection`` calls), never parsed; only
    the files that hold such I/O are returned, each with the :class:`CppFile` of it."""
    from moos_lint.frontends.cpp.extract import DEVICE_STRING, include_io

    out = []
    for path in paths:
        data = read_bytes(path)
        if not isinstance(data, bytes):
            continue
        if b"include" not in data and b"_connection" not in data and b'"/dev/' not in data:
            continue
        found: list[tuple[int, int, str, str]] = []
        for m in _INCLUDE_LINE.finditer(data):
            kind = include_io(m.group(1).decode("utf-8", "replace").strip())
            if kind:
                found.append((m.start(1), m.end(1), kind, m.group(1).decode("utf-8", "replace")))
        for m in _LINK_CALL.finditer(data):
            found.append((m.start(1), m.end(1), "socket", m.group(1).decode("ascii")))
        for m in _DEVICE_LITERAL.finditer(data):
            device = m.group(1).decode("utf-8", "replace")
            if DEVICE_STRING.match(device) and not _commented(data, m.start()):
                found.append((m.start(1) - 1, m.end(1) + 1, "device", device))
        if not found:
            continue
        src = decode(data, path)
        if not isinstance(src, SourceFile):
            continue
        f = CppFile(path=path)
        for start, end, kind, detail in sorted(found):
            line = data.count(b"\n", 0, start) + 1
            col = start - (data.rfind(b"\n", 0, start) + 1) + 1
            span = Span(path, line, col, line, col + (end - start))
            f.io.append(IOUse(kind, detail, span))
        out.append((src, f))
    return out


#: the language server's C++ files, by their bytes: a re-lint prefilters and decodes only
#: the files that changed
_read_memo: dict[str, tuple[bytes, SourceFile | None, FileNames]] = {}


def parse_folder(sources: dict[str, SourceFile], compiled: Any = None) -> list[CppFile]:
    """Parse the files of one folder and extract their facts.

    ``compiled`` (``--cpp-backend clang``: :class:`~moos_lint.frontends.cpp.clang_facts.ClangFacts`)
    is what libclang knows of the files: what the compiler skipped is blanked before
    the parse, and the value analysis asks it for constants and types.
    """
    from moos_lint.frontends.cpp.extract import Extractor, collect_tables
    from moos_lint.frontends.cpp.parse import backend

    be = backend()
    parsed = []
    for path, src in sorted(sources.items()):
        # a bare CR ends a line for moos-lint (and for the spans), not for tree-sitter
        text = src.text.replace("\r\n", "\n").replace("\r", "\n")
        data = text.encode("utf-8", "replace")
        if compiled is not None:
            data = compiled.live(path, data)
        parsed.append(_parse(be, path, data))
    tables = collect_tables(parsed)
    from moos_lint.frontends.cpp.values import Evaluator, Folder

    evaluator = Evaluator(Folder(parsed), compiled=compiled)
    return [Extractor(pf, tables, evaluator).run() for pf in parsed]


#: How many parsed files (tree, query matches and what the file gives its folder's tables,
#: by path and bytes) a process keeps. The language server turns it on: re-linting one
#: file then reparses only the files that changed, not every neighbour, and an edited
#: file incrementally from its last tree. A command-line run parses each file once and
#: keeps none.
PARSE_MEMO_SIZE = 0
_parse_memo: OrderedDict[tuple[str, bytes], Any] = OrderedDict()


#: the last tree of each path (language server): an edited file is parsed incrementally
_last_tree: OrderedDict[str, tuple[bytes, Any]] = OrderedDict()


#: one parse at a time: the language server lints on several threads, and a tree-sitter
#: parser and the memos above are shared
_PARSE_LOCK = threading.Lock()


def _parse(be: Any, path: str, data: bytes) -> Any:
    """The :class:`~moos_lint.frontends.cpp.extract.ParsedFile` of ``data``."""
    with _PARSE_LOCK:
        return _parse_locked(be, path, data)


def _parse_locked(be: Any, path: str, data: bytes) -> Any:
    from moos_lint.frontends.cpp.extract import ParsedFile

    key = (path, data)
    hit = _parse_memo.get(key) if PARSE_MEMO_SIZE else None
    if hit is not None:
        _parse_memo.move_to_end(key)
        return hit
    tree = None
    if PARSE_MEMO_SIZE and path in _last_tree:
        old_data, old_tree = _last_tree[path]
        tree = be.parse(data, edited(old_tree, old_data, data))
        # Error recovery may shape a broken text differently from a parse of the whole
        # text; a text without errors parses to the same tree either way.
        if tree is not None and tree.root_node.has_error:
            tree = None
    if tree is None:
        tree = be.parse(data)
    hit = ParsedFile(path, data, tree, be.matches(tree))
    if PARSE_MEMO_SIZE:
        _parse_memo[key] = hit
        while len(_parse_memo) > PARSE_MEMO_SIZE:
            _parse_memo.popitem(last=False)
        _last_tree[path] = (data, tree)
        _last_tree.move_to_end(path)
        while len(_last_tree) > PARSE_MEMO_SIZE:
            _last_tree.popitem(last=False)
    return hit


def _point(data: bytes, pos: int) -> tuple[int, int]:
    return data.count(b"\n", 0, pos), pos - (data.rfind(b"\n", 0, pos) + 1)


def _common(same: Any, limit: int) -> int:
    """The largest ``k <= limit`` with ``same(k)`` (``same`` holds up to some length)."""
    lo, hi = 0, limit
    while lo < hi:
        mid = (lo + hi + 1) // 2
        if same(mid):
            lo = mid
        else:
            hi = mid - 1
    return lo


def edited(old_tree: Any, old: bytes, new: bytes) -> Any:
    """A copy of ``old_tree`` told what changed from ``old`` to ``new`` (one edited range:
    the text between their common start and common end), for an incremental parse."""
    limit = min(len(old), len(new))
    start = _common(lambda k: old[:k] == new[:k], limit)
    end = _common(lambda k: old[len(old) - k :] == new[len(new) - k :], limit - start)
    tree = old_tree.copy()
    tree.edit(
        start_byte=start,
        old_end_byte=len(old) - end,
        new_end_byte=len(new) - end,
        start_point=_point(old, start),
        old_end_point=_point(old, len(old) - end),
        new_end_point=_point(new, len(new) - end),
    )
    return tree


def build_apps(sources: dict[str, SourceFile], strays: bool = False) -> list[AppModel]:
    """One :class:`AppModel` per folder of relevant C++ files, linked. ``strays``: keep
    the sources no target of their folder compiles (see :func:`link_apps`)."""
    by_folder: dict[str, dict[str, SourceFile]] = {}
    for path, src in sources.items():
        by_folder.setdefault(os.path.dirname(path), {})[path] = src
    apps = [AppModel(folder=f, files=parse_folder(s)) for f, s in sorted(by_folder.items())]
    link_apps(apps, strays)
    return apps


def link_apps(apps: list[AppModel], strays: bool = False) -> None:
    """Find each folder's app class (base chains may cross folders) and its process name.

    A source file the folder's CMakeLists.txt compiles into no target (a stray copy of
    the app's class beside its real sources) is dropped first, unless ``strays``: it
    never runs."""
    if not strays:
        for app in apps:
            stray = unbuilt(app.folder, frozenset(os.path.basename(f.path) for f in app.files))
            if stray:
                app.files = [f for f in app.files if os.path.basename(f.path) not in stray]
    bases: dict[str, list[str]] = {}
    for app in apps:
        for f in app.files:
            for c in f.classes:
                bases.setdefault(c.name, []).extend(c.bases)
    for app in apps:
        app.app_class, app.base_chain, app.process_name = None, [], None
        app.executable = None
        _find_app_class(app, bases)
        if app.is_app:
            _process_name(app)


def sibling_apps(app: AppModel) -> list[AppModel]:
    """The other programs of a folder that builds several (``add_executable(pCommand
    command.cpp)`` and ``add_executable(pStatus status.cpp)`` side by side): one model per
    other file with a ``main``, holding that file and the folder's files without one.
    The folder's own model names one app; these name the rest."""
    mains = [f for f in app.files if f.has_main]
    if len(mains) < 2 or not app.is_app:
        return []
    shared = [f for f in app.files if not f.has_main]
    bases: dict[str, list[str]] = {}
    for f in app.files:
        for c in f.classes:
            bases.setdefault(c.name, []).extend(c.bases)
    for name in app.base_chain[1:]:  # (the chain may cross folders: keep what was found)
        bases.setdefault(name, [])
    found: list[AppModel] = []
    names = {app.process_name}
    for main in mains:
        if any(c is app.app_class for c in main.classes):
            continue
        sub = AppModel(folder=app.folder, files=[main, *shared], backend=app.backend)
        _find_app_class(sub, bases)
        if not sub.is_app or sub.app_class is app.app_class:
            continue
        _process_name(sub)
        named = sub.process_name_source in ("run", "cmake")
        if sub.process_name and named and sub.process_name not in names:
            names.add(sub.process_name)
            found.append(sub)
    return found


def base_chain(name: str, bases: dict[str, list[str]], seen: frozenset = frozenset()) -> list[str]:
    """``[name, ..., MOOS base]`` when ``name`` derives from a MOOS app base, else []."""
    if name in APP_BASES:
        return [name]
    if name in seen:
        return []
    for b in bases.get(name, ()):
        chain = base_chain(b, bases, seen | {name})
        if chain:
            return [name, *chain]
    return []


def _find_app_class(app: AppModel, bases: dict[str, list[str]]) -> None:
    classes: list[CppClass] = [c for f in app.files for c in f.classes]
    candidates = [(c, base_chain(c.name, bases)) for c in classes]
    candidates = [(c, ch) for c, ch in candidates if len(ch) > 1]
    if not candidates:
        return
    derived_from = {b for c, _ in candidates for b in c.bases}
    leaves = [(c, ch) for c, ch in candidates if c.name not in derived_from] or candidates
    app.app_class, app.base_chain = leaves[0]


def _process_name(app: AppModel) -> None:
    found = executable_name(app.folder, _class_files(app))
    app.executable = found[0] if found is not None else None
    for f in app.files:
        if f.has_main and f.run_names:
            app.process_name, app.process_name_span = f.run_names[0]
            app.process_name_source = "run"
            return
    if found is not None:
        app.process_name = found[0]
        app.process_name_source = "cmake"
    elif any(f.has_main for f in app.files) and not executables_in(app.folder):
        # (a folder that builds several programs, none of them clearly this app's, has no name)
        app.process_name = os.path.basename(os.path.normpath(app.folder))
        app.process_name_source = "folder"
    if app.app_class is not None:
        app.process_name_span = app.app_class.span


def _class_files(app: AppModel) -> frozenset[str]:
    """The file names of the app class's own sources: its file and that file's ``.h``/``.cpp``."""
    for f in app.files:
        if any(c is app.app_class for c in f.classes):
            stem = os.path.splitext(os.path.basename(f.path))[0]
            return frozenset({os.path.basename(f.path)} | {stem + ext for ext in CPP_SUFFIXES})
    return frozenset()
