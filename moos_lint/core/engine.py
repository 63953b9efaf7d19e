"""The engine: files -> nsplug -> model -> rules -> diagnostics.

It knows nothing of output formats. :func:`lint_paths` is what the CLI calls;
:func:`lint_files` is the core, also usable on in-memory text (editors).
"""

from __future__ import annotations

import fnmatch
import os
from collections.abc import Callable, Iterable, Iterator
from dataclasses import dataclass, field
from pathlib import Path
from typing import TYPE_CHECKING, Any, Protocol

from moos_lint.core.config import Settings
from moos_lint.core.registry import (
    Kind,
    Rule,
    Scope,
    get_rule,
    is_valid_selector,
    matches,
    select_rules,
)
from moos_lint.core.result import Result
from moos_lint.files.boundary import Boundary, split_linted
from moos_lint.files.boundary import apply as apply_boundary
from moos_lint.files.diagnostics import (
    INTERNAL_ERROR,
    Diagnostic,
    Fix,
    IncludeSite,
    Severity,
    Span,
    Subject,
)
from moos_lint.files.discovery import discover, kind_of
from moos_lint.files.launch import read_once
from moos_lint.files.source import ReadProblem, SourceFile
from moos_lint.frontends.nsplug import Expansion, FileCache, Line, Preprocessor, parsed
from moos_lint.frontends.parsers.bhv import is_behavior_fragment, parse_bhv
from moos_lint.frontends.parsers.moos import parse_moos
from moos_lint.frontends.parsers.nodes import BehaviorFile, MoosFile
from moos_lint.frontends.unit import Unit
from moos_lint.rules.kit.suppressions import Suppression, SuppressionIndex, parse_suppressions
from moos_lint.semantics.run_state import RunMemos

if TYPE_CHECKING:  # the progress display is the command line's; the engine only tells it
    from moos_lint.commands.progress import Progress
    from moos_lint.semantics.cpp_units import ParsedFolder


class LintStopped(Exception):
    """A lint given a ``stop`` check (see :func:`lint_files`) was told to stop."""


@dataclass
class Context:
    """What a rule's check function receives."""

    rule: Rule
    unit: Unit
    settings: Settings
    run: LintRun
    options: dict[str, Any] = field(default_factory=dict)

    @property
    def path(self) -> str:
        return self.unit.path

    @property
    def moos(self) -> MoosFile | None:
        return self.unit.moos

    @property
    def bhv(self) -> BehaviorFile | None:
        return self.unit.bhv

    @property
    def expansion(self) -> Expansion:
        return self.unit.expansion

    def runs(self, code: str) -> bool:
        """Whether the rule with ``code`` runs in this lint too (two rules that would
        report one line leave it to the one that runs)."""
        return code in self.run.codes

    def report(
        self,
        span: Span,
        message: str,
        *,
        line: Line | None = None,
        chain: tuple[IncludeSite, ...] | None = None,
        fix: Fix | None = None,
        severity: Severity | None = None,
        subject: Subject | None = None,
    ) -> Diagnostic:
        if chain is None:
            chain = line.chain if line is not None else ()
        return Diagnostic(
            code=self.rule.code,
            name=self.rule.name,
            severity=severity or self.rule.severity,
            span=span,
            message=message,
            chain=chain,
            fix=fix,
            subject=subject,
        )

    def at_line(self, line: Line, message: str, **kw: Any) -> Diagnostic:
        return self.report(line.span(), message, line=line, **kw)


class LintRun:
    """State shared by every unit of one lint run (not a MOOS ``Run =`` line)."""

    def __init__(self, settings: Settings, rules: list[Rule], cache: FileCache | None = None):
        self.settings = settings
        self.rules = rules
        self.codes = frozenset(r.code for r in rules)  # (what Context.runs asks)
        self.cache = cache or FileCache()
        self.preprocessor = Preprocessor(
            defines=settings.defines,
            include_paths=settings.include_paths,
            mode="lint",
            cache=self.cache,
        )
        self.preprocessor.memo = {}  # each file is expanded once per run
        self.sources: dict[str, SourceFile] = {}
        self.mission_files: set[str] = set()  # files analysed as part of a mission
        self.included_elsewhere: set[str] = set()  # linted files that other files include
        self.units: list[Unit] = []
        self.suppressions: dict[str, list[Suppression]] = {}
        self._options: dict[str, dict[str, Any]] = {}
        self._applicable: dict[tuple[Kind, bool, bool, bool], list[Rule]] = {}
        #: what the model builders keep for the run (see :mod:`moos_lint.semantics.run_state`)
        self.memos = RunMemos()
        #: asked between units and rules; True stops the run (:class:`LintStopped`)
        self.stop: Callable[[], bool] | None = None

    def check_stop(self) -> None:
        if self.stop is not None and self.stop():
            raise LintStopped

    def suppress(self, diags: Iterable[Diagnostic]) -> list[Diagnostic]:
        """Drop findings that a comment or per-file-ignores suppresses; record what was used."""
        for path, src in self.sources.items():
            if path not in self.suppressions:  # (a file without the marker has none)
                found = parse_suppressions(path, src.lines) if "moos-lint:" in src.text else []
                self.suppressions[path] = found
        index = {path: SuppressionIndex(sups) for path, sups in self.suppressions.items() if sups}
        kept: list[Diagnostic] = []
        for d in diags:
            if d.code != INTERNAL_ERROR and self.file_ignored(d):
                continue
            hit = False
            at = index.get(d.span.path)
            for sup in at.at(d.span.line) if at is not None else ():
                sel = sup.covers(d)
                if sel is not None:
                    sup.used.add(sel)
                    hit = True
            if not hit:
                kept.append(d)
        return kept

    def _options_for(self, r: Rule) -> dict[str, Any]:
        """The rule's options (resolved once per run; each check gets its own copy)."""
        options = self._options.get(r.name)
        if options is None:
            options = self._options[r.name] = self.settings.options_for(r.name)
        return dict(options)

    def names_a_rule(self, selector: str) -> bool:
        """Whether ``selector`` selects any moos-lint rule (run in this run or not)."""
        return is_valid_selector(selector)

    def file_ignored(self, d: Diagnostic) -> bool:
        return _per_file_ignored(d, self.settings)

    def build_unit(self, path: str) -> Unit:
        if kind_of(path) == "cpp":
            from moos_lint.semantics.cpp_units import (
                build_cpp_units,  # only for C++: it loads tree-sitter
            )

            return build_cpp_units(self, [path])[0]
        kind = Kind.BHV if kind_of(path) == "bhv" else Kind.MOOS
        exp = self.preprocessor.expand(path)
        if kind is Kind.MOOS and path.lower().endswith(".plug") and is_behavior_fragment(exp):
            kind = Kind.BHV  # a plug of behaviors, included by a behavior template
        self.sources.update(exp.sources)
        unit = Unit(path=exp.path, kind=kind, expansion=exp)
        if exp.read_problem is None:
            if kind is Kind.MOOS:
                unit.moos = parsed(exp, parse_moos)
                if unit.moos.is_mission:
                    self.mission_files.update(exp.sources)
            else:
                unit.bhv = parsed(exp, parse_bhv)
        return unit

    def _rules_for(self, unit: Unit) -> list[Rule]:
        """The rules that check ``unit`` (worked out once per kind of unit)."""
        read_problem = unit.expansion.read_problem is not None
        mission = unit.kind is Kind.CPP or bool(unit.moos and unit.moos.is_mission)
        key = (unit.kind, unit.cpp is None, read_problem, mission)
        found = self._applicable.get(key)
        if found is not None:
            return found
        found = []
        for r in self.rules:
            if unit.kind not in r.kinds or r.scope is Scope.PROJECT:
                continue
            if unit.kind is Kind.CPP:
                if unit.cpp is None:
                    continue
            elif r.scope not in (Scope.FILE, Scope.MISSION):
                continue
            if read_problem and r.code != "R001":
                continue
            if r.scope is Scope.MISSION and not mission:
                continue
            found.append(r)
        self._applicable[key] = found
        return found

    def run_rules(self, unit: Unit) -> tuple[list[Diagnostic], int]:
        out: list[Diagnostic] = []
        errors = 0
        for r in self._rules_for(unit):
            self.check_stop()
            ctx = Context(r, unit, self.settings, self, self._options_for(r))
            try:
                out.extend(r.check(ctx) or ())
            except Exception as exc:  # a rule bug must not stop the run
                errors += 1
                out.append(internal_error(unit.path, f"in rule {r.code} ({r.name})", exc))
        self.memos.checked(unit.path)
        return out, errors


def internal_error(path: str, what: str, exc: BaseException) -> Diagnostic:
    """A finding that says moos-lint itself failed (``what``: where), so the run goes on."""
    import traceback  # (only when a rule fails)

    where = traceback.extract_tb(exc.__traceback__)[-1] if exc.__traceback__ else None
    at = f" at {os.path.basename(where.filename)}:{where.lineno}" if where else ""
    return Diagnostic(
        code=INTERNAL_ERROR,
        name="internal-error",
        severity=Severity.ERROR,
        span=Span(path, 1, 1),
        message=f"internal error {what}: {type(exc).__name__}: {exc}{at}; please report it",
    )


def _build_cpp_units(
    run: LintRun, files: list[str], parsed: Iterable[Any] | None = None
) -> tuple[list[Unit], list[Diagnostic]]:
    """The C++ units; a folder whose C++ cannot be analysed is an internal error, not a crash.

    ``parsed``: the folders worker processes read and parsed, in any order.
    """
    from moos_lint.semantics.cpp_units import build_cpp_units  # only for C++: it loads tree-sitter

    if parsed is not None:
        by_folder: dict[str, ParsedFolder] = {}
        for paths, sources, cpp_files, _error, names in parsed:
            if cpp_files is None:  # redo every folder here, where errors are reported
                by_folder = {}
                break
            by_folder[os.path.dirname(paths[0])] = (sources, cpp_files, names)
        if by_folder:
            try:
                return build_cpp_units(run, files, by_folder), []
            except Exception:
                pass
    try:
        return build_cpp_units(run, files), []
    except Exception:
        pass
    units: list[Unit] = []
    errors: list[Diagnostic] = []
    folders: dict[str, list[str]] = {}
    for p in files:
        folders.setdefault(os.path.dirname(p), []).append(p)
    for _folder, paths in sorted(folders.items()):
        try:
            units.extend(build_cpp_units(run, paths))
        except Exception as exc:  # one folder's C++ must not stop the run
            errors.append(
                internal_error(sorted(paths)[0], "reading the C++ files of this folder", exc)
            )
    return units, errors


class Parallel(Protocol):
    """Worker processes that share a run's work: :mod:`moos_lint.speed.parallel`.

    The engine never starts processes itself: a caller that wants ``jobs`` (the
    command line, the result cache) passes the worker machinery in.
    """

    def effective_jobs(self, jobs: int | None, n_files: int) -> int: ...

    def pool(self, jobs: int) -> Any: ...

    def start_cpp(self, workers: Any, paths: list[str]) -> Iterator[Any]: ...

    def stop(self, workers: Any) -> None: ...

    def run_rules_parallel(
        self, run: LintRun, jobs: int, progress: Progress | None = None
    ) -> list[tuple[list[Diagnostic], int]]: ...


def lint_files(
    files: list[str],
    settings: Settings,
    rules: list[Rule] | None = None,
    cache: FileCache | None = None,
    jobs: int | None = 1,
    checked: Callable[[Unit], bool] | None = None,
    progress: Progress | None = None,
    parallel: Parallel | None = None,
    stop: Callable[[], bool] | None = None,
) -> Result:
    """Lint the given files with the given settings.

    ``jobs``: worker processes (None: one per CPU), started by ``parallel``
    (without it, the run stays in one process); the result is the same as
    with one. Small inputs stay in one process.
    ``checked``: when given, only the units it accepts are checked by the rules;
    the others are still read, expanded and parsed (they include files, share
    behavior files, are sibling missions). The language server uses it to keep
    only the findings one document can show. ``progress``: told of each file read and
    checked (:mod:`moos_lint.commands.progress`).
    ``stop``: asked between files and between rules; when it answers True the
    lint raises :class:`LintStopped` (the language server's time budget and
    cancellation).
    """
    with read_once():  # the scripts beside the missions, listed once for the whole run
        return _lint_files(files, settings, rules, cache, jobs, checked, progress, parallel, stop)


def _lint_files(
    files: list[str],
    settings: Settings,
    rules: list[Rule] | None,
    cache: FileCache | None,
    jobs: int | None,
    checked: Callable[[Unit], bool] | None,
    progress: Progress | None,
    parallel: Parallel | None,
    stop: Callable[[], bool] | None,
) -> Result:
    bound = Boundary(settings.project_root) if settings.project_root else None
    outside_links: list[str] = []
    if bound is not None:  # a link to a file outside the project is not linted
        files, outside_links = split_linted(files, bound)
    jobs = parallel.effective_jobs(jobs, len(files)) if parallel is not None else 1
    if progress is not None:
        progress.start(len(files))
    cpp_files = [p for p in files if kind_of(p) == "cpp"]
    workers = parallel.pool(jobs) if parallel is not None and jobs > 1 and cpp_files else None
    try:
        # the workers read and parse the C++ (started first: they need no rule) while this
        # process loads the rules and reads the missions
        cpp_parsed = None
        if parallel is not None and workers is not None:
            cpp_parsed = parallel.start_cpp(workers, cpp_files)
        if rules is None:
            rules = select_rules(settings.select, settings.extend_select, settings.ignore)
        run = LintRun(settings, rules, cache)
        run.stop = stop
        result = Result(files=list(files), outside_links=outside_links)
        for path in files:
            if kind_of(path) != "cpp":
                run.check_stop()
                run.units.append(run.build_unit(path))
                if progress is not None:
                    progress.advance()
        cpp_errors: list[Diagnostic] = []
        if cpp_files:
            units, cpp_errors = _build_cpp_units(run, cpp_files, cpp_parsed)
            if progress is not None:
                progress.advance(len(cpp_files))
            run.units.extend(units)
            result.internal_errors += len(cpp_errors)
    finally:
        if parallel is not None and workers is not None:
            parallel.stop(workers)
    for unit in run.units:
        run.included_elsewhere.update(p for p in unit.expansion.sources if p != unit.path)
    found: dict[tuple[Any, ...], Diagnostic] = {d.identity: d for d in cpp_errors}
    per_unit: Iterable[tuple[list[Diagnostic], int]]
    if progress is not None:
        progress.begin("checking", len(run.units))
    parallel_rules = parallel is not None and checked is None and jobs > 1 and len(run.units) > 1
    if checked is None:  # every unit is checked: a folder's shared models go once it is done
        run.memos.expect(unit.path for unit in run.units)
    if checked is not None:
        per_unit = (run.run_rules(unit) for unit in run.units if checked(unit))
    elif parallel is not None and parallel_rules:
        per_unit = parallel.run_rules_parallel(run, jobs, progress)
    else:
        per_unit = (run.run_rules(unit) for unit in run.units)
    for diags, errors in per_unit:
        if progress is not None and not parallel_rules:
            progress.advance()
        result.internal_errors += errors
        for d in diags:
            found.setdefault(d.identity, d)
    kept = run.suppress(_one_claim_per_place(found.values()))
    for r in rules:
        if r.scope is Scope.PROJECT:
            ctx = Context(r, _empty_unit(), settings, run, settings.options_for(r.name))
            try:
                kept.extend(d for d in r.check(ctx) or () if not run.file_ignored(d))
            except Exception as exc:
                result.internal_errors += 1
                where = files[0] if files else "."
                kept.append(internal_error(where, f"in rule {r.code} ({r.name})", exc))
    kept.sort(key=lambda d: d.sort_key)
    if bound is not None:
        kept, result.outside = apply_boundary(kept, bound, _texts_read(run))
    result.diagnostics = kept
    result.sources = run.sources
    result.units = run.units
    return result


def _texts_read(run: LintRun) -> dict[str, str]:
    """The text of every file the run read (what a message may quote), by path."""
    texts = {path: src.text for path, src in run.sources.items()}
    for exp in (run.preprocessor.memo or {}).values():
        for path, src in exp.sources.items():
            texts.setdefault(path, src.text)
    return texts


def _empty_unit() -> Unit:
    return Unit(path=".", kind=Kind.MOOS, expansion=Expansion(path="."))


def _per_file_ignored(d: Diagnostic, settings: Settings) -> bool:
    if not settings.per_file_ignores:
        return False
    rel = os.path.relpath(d.span.path, settings.root)
    r = get_rule(d.code)
    for glob, selectors in settings.per_file_ignores.items():
        hit = fnmatch.fnmatch(rel, glob) or fnmatch.fnmatch(os.path.basename(rel), glob)
        if hit and r is not None and any(matches(s, r) for s in selectors):
            return True
    return False


def lint_paths(
    paths: Iterable[Path],
    settings: Settings,
    *,
    context: bool = False,
    cache: FileCache | None = None,
    jobs: int | None = 1,
    progress: Progress | None = None,
    parallel: Parallel | None = None,
) -> Result:
    """Discover files under ``paths`` and lint them.

    With ``context``, the missions under the project root that use one of the
    files (see :mod:`moos_lint.core.context`) are linted too, and only findings in
    the given files or in those missions are kept. ``jobs``,
    ``parallel``: see :func:`lint_files`. The result cache wraps this function
    from outside (:func:`moos_lint.speed.cache.cached_lint`).
    """
    paths = list(paths) or [Path(".")]
    with read_once():
        return _lint_paths(paths, settings, context, cache, jobs, progress, parallel)


def _lint_paths(
    paths: list[Path],
    settings: Settings,
    context: bool,
    cache: FileCache | None,
    jobs: int | None,
    progress: Progress | None,
    parallel: Parallel | None,
) -> Result:
    found = discover(paths, settings.exclude, settings.root, settings.respect_gitignore)
    if not context:
        result = lint_files(
            found.files, settings, cache=cache, jobs=jobs, progress=progress, parallel=parallel
        )
        result.missing = found.missing
        return result
    from moos_lint.core.context import related_missions

    cache = cache or FileCache()
    missions = related_missions(found.files, settings, cache)
    result = lint_files(
        [*found.files, *missions],
        settings,
        cache=cache,
        jobs=jobs,
        progress=progress,
        parallel=parallel,
    )
    keep = {os.path.normpath(p) for p in (*found.files, *missions)}
    result.diagnostics = [
        d
        for d in result.diagnostics
        if d.code == INTERNAL_ERROR or os.path.normpath(d.span.path) in keep
    ]
    result.missing = found.missing
    return result


_RANK = {Severity.ERROR: 0, Severity.WARNING: 1, Severity.INFO: 2}


def _one_claim_per_place(found: Iterable[Diagnostic]) -> list[Diagnostic]:
    """The findings, one per claim: a mission rule sees a shared file once per mission,
    and a mission whose check is incomplete says the same with a note added
    (``...; the check is incomplete: ...``, at info). Of two findings of one rule at one
    span where one message extends the other, the more severe is kept."""
    out: list[Diagnostic] = []
    by_place: dict[tuple[str, str, int, int, int, int], list[int]] = {}
    for d in found:
        s = d.span
        place = (d.code, s.path, s.line, s.col, s.end_line, s.end_col)
        merged = False
        for i in by_place.get(place, ()):
            other = out[i]
            if d.message.startswith(other.message) or other.message.startswith(d.message):
                mine = (_RANK[d.severity], len(d.message))
                if mine < (_RANK[other.severity], len(other.message)):
                    out[i] = d
                merged = True
                break
        if not merged:
            by_place.setdefault(place, []).append(len(out))
            out.append(d)
    return out


__all__ = [
    "INTERNAL_ERROR",
    "Context",
    "LintRun",
    "LintStopped",
    "Parallel",
    "ReadProblem",
    "Result",
    "Unit",
    "lint_files",
    "lint_paths",
]
