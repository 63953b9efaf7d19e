"""Linting one open document the way ``moos-lint check`` lints its folder.

A document is never linted alone: whether a fragment's ``#include`` resolves,
or whether a suppression is used, depends on the missions that include it. A
document is linted together with the mission and behavior files beside it and
with the open documents that include it, and only the findings that land in
the document are kept. A finding inside an included file that is not open is
shown on the ``#include`` line that pulls it in.
"""

from __future__ import annotations

import gc
import os
import threading
from collections.abc import Callable, Iterator, Sequence
from contextlib import contextmanager
from dataclasses import dataclass, field
from pathlib import Path

from moos_lint.commands.lsp.documents import DiskReads, MemoryReader, norm
from moos_lint.core.config import ConfigError, Settings, resolve_settings
from moos_lint.core.engine import Unit, lint_files
from moos_lint.files.diagnostics import Diagnostic, IncludeSite, Span
from moos_lint.files.discovery import DEFAULT_EXCLUDE, _excluded, kind_of
from moos_lint.files.project import project_root
from moos_lint.files.source import SourceFile
from moos_lint.frontends.cpp import app as cpp_app
from moos_lint.frontends.nsplug import ExpansionStore, FileCache

# re-linting a C++ file reparses only the files of its folder that changed
cpp_app.PARSE_MEMO_SIZE = 96  # a document and its neighbours (MAX_NEIGHBOURS)

#: At most this many neighbouring files are linted with a document.
MAX_NEIGHBOURS = 64
#: re-linting a document re-expands only the files that changed (see ExpansionStore)
_EXPANSIONS = ExpansionStore(size=2 * MAX_NEIGHBOURS)
#: ... and reads again only the files that changed
_DISK = DiskReads(size=8 * MAX_NEIGHBOURS)


_SETTLED = False


class Collector:
    """Cyclic garbage is collected between lints, never in the middle of one.

    A re-lint leaves reference cycles behind (expansions, units and models
    point at each other), and they survive while the lint runs, so only a full
    collection frees them: one walk of the tens of thousands of objects that
    a few re-lints leave, about 25 ms, landing in whichever re-lint is running
    then. So while any lint runs (:meth:`linting`) the cyclic collector is off, as
    it is for a whole ``moos-lint check``, and the server calls :meth:`idle` once
    a lint's diagnostics are published: when no other lint is running, the
    garbage is collected then, and the collector turned on again until the
    next lint. The next edit waits the debounce anyway, so the collection
    delays no diagnostics. Reference counting frees everything else as usual.
    """

    def __init__(self) -> None:
        self._lock = threading.Lock()
        self._running = 0

    @contextmanager
    def linting(self) -> Iterator[None]:
        with self._lock:
            if self._running == 0:
                gc.disable()
            self._running += 1
        try:
            yield
        finally:
            with self._lock:
                self._running -= 1

    def idle(self) -> bool:
        """Collect, when no lint is running; whether it did."""
        with self._lock:
            if self._running:
                return False
            gc.collect()
            gc.enable()
            return True


#: the server's collector (one per process: the cyclic collector is)
COLLECTOR = Collector()


def settle() -> None:
    """Load what every analysis uses, then put the objects that live as long as the
    server out of the garbage collector's sight.

    Python's cyclic collector, on a full collection, walks every object it
    tracks: after the imports, the rules and the stock catalogue, about 50,000,
    and such a walk is a pause that lands in the middle of some re-lint.
    Frozen (:func:`gc.freeze`), those objects are never walked again; they live
    as long as the server anyway. What the server makes later
    (the documents' expansions and models, which hold reference cycles) is
    collected as before. Only the first call does anything.
    """
    global _SETTLED
    if _SETTLED:
        return
    _SETTLED = True
    import gc

    from moos_lint.core.registry import all_rules
    from moos_lint.semantics.catalogue import stock
    from moos_lint.semantics.mission_model import mission_model  # noqa: F401 (the rules' models)

    all_rules()
    stock()
    gc.collect()
    gc.freeze()


@dataclass(slots=True)
class Finding:
    """A finding as the document shows it."""

    diagnostic: Diagnostic
    #: where it shows in the document: the finding's own span, or the ``#include``
    #: line that leads to it when it lies in another file
    span: Span
    via: IncludeSite | None = None

    @property
    def fix(self):
        return self.diagnostic.fix if self.via is None else None


@dataclass(slots=True)
class Analysis:
    path: str
    findings: list[Finding] = field(default_factory=list)
    reads: set[str] = field(default_factory=set)
    includes: set[str] = field(default_factory=set)
    settings: Settings | None = None
    config_error: str | None = None
    unit: Unit | None = None


def lintable(path: str) -> bool:
    """True for the files the engine lints (mission, fragment, behavior, ...)."""
    return kind_of(path) is not None


def settings_for(path: str) -> tuple[Settings, str | None]:
    """The settings ``moos-lint check`` would use for ``path``, and a config error."""
    try:
        settings, error = resolve_settings([Path(path)], None), None
    except ConfigError as exc:
        settings, error = Settings(root=os.path.dirname(path)), str(exc)
    settings.project_root = project_root([path], settings.config_path)
    return settings, error


def neighbours(path: str, settings: Settings) -> list[str]:
    """The lintable files beside ``path`` that the configuration does not exclude."""
    folder = os.path.dirname(path)
    patterns = [*DEFAULT_EXCLUDE, *settings.exclude]
    out: list[str] = []
    try:
        entries = sorted(os.scandir(folder), key=lambda e: e.name)
    except OSError:
        return out
    for entry in entries:
        if len(out) >= MAX_NEIGHBOURS:
            break
        if not lintable(entry.name):
            continue
        try:
            if not entry.is_file():
                continue
        except OSError:
            continue
        rel = os.path.normpath(os.path.relpath(entry.path, settings.root))
        if _excluded(rel, entry.name, patterns):
            continue
        out.append(norm(entry.path))
    return out


def _may_include(path: str, name: str) -> bool:
    """Whether the file at ``path`` may ``#include`` a file called ``name`` (by name, or
    through a macro); a file that cannot be read is kept (the engine reports it)."""
    src = _DISK.read(Path(path))
    if not isinstance(src, SourceFile):
        return True
    if "#include" not in src.text:
        return False
    # (the lines of a kept read are split once: nsplug reads the same ones)
    return any(
        line.lstrip().startswith("#include") and (name in line or "$(" in line or "%(" in line)
        for line in src.lines
    )


def analyse(
    path: str,
    texts: dict[str, str],
    includers: Sequence[str] = (),
    settings: Settings | None = None,
    stop: Callable[[], bool] | None = None,
) -> Analysis:
    """Lint the document at ``path``; ``texts`` holds every open document's text.

    ``stop``: see :func:`moos_lint.core.engine.lint_files` (raises ``LintStopped``).
    """
    path = norm(path)
    if not lintable(path):
        return Analysis(path, settings=settings)
    config_error = None
    if settings is None:
        settings, config_error = settings_for(path)
    out = Analysis(path, settings=settings, config_error=config_error)
    files = [path]
    nearby = neighbours(path, settings)
    if kind_of(path) == "moos":
        # only a file that includes a mission file can change what is found in it
        name = os.path.basename(path)
        nearby = [p for p in nearby if p in texts or _may_include(p, name)]
    for other in [*includers, *nearby]:
        if other not in files:
            files.append(other)
    seen: set[str] = set()
    is_bhv = kind_of(path) == "bhv"

    def can_report_here(unit: Unit) -> bool:
        # A rule reports in its unit's own files (the unit, what it includes) and, for a
        # mission, in the behavior files its helm reads: only those units are checked.
        if unit.path == path or path in unit.expansion.sources:
            return True
        if unit.cpp is not None and any(f.path == path for f in unit.cpp.files):
            return True  # a C++ app reports in any of its files
        if not is_bhv or unit.moos is None or not unit.moos.is_mission:
            return False
        # a mission reads behavior files only through a ``behaviors =`` line (its helm's)
        return any(block.get("behaviors") for block in unit.moos.blocks)

    reader = FileCache(reader=MemoryReader(texts, seen, _DISK.read), store=_EXPANSIONS)
    result = lint_files(files, settings, cache=reader, checked=can_report_here, stop=stop)
    out.reads = seen | {path}
    for unit in result.units:
        if unit.path == path:
            out.unit = unit
            out.includes = set(unit.expansion.sources) - {path}
    shown: set[tuple] = set()
    for d in result.diagnostics:
        if d.span.path == path:
            out.findings.append(Finding(d, d.span))
            continue
        if d.span.path in texts:
            continue  # an open document: it shows there
        sites = [s for s in d.chain if s.path == path]
        if not sites:
            continue
        site = sites[-1]
        key = (site.line, d.code, d.span.path, d.span.line, d.message)
        if key in shown:
            continue
        shown.add(key)
        out.findings.append(Finding(d, Span(path, site.line, 1, site.line, 1), via=site))
    return out
