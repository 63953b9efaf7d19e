"""The outcome of a lint run: what the output formats, the baseline and the cache read.

Kept apart from the engine, so that a result replayed from the cache is
shown without loading the parsers and the rules.
"""

from __future__ import annotations

from dataclasses import dataclass, field

TYPE_CHECKING = False  # typing itself is not imported at run time

if TYPE_CHECKING:
    from moos_lint.files.diagnostics import Diagnostic
    from moos_lint.files.source import SourceFile
    from moos_lint.frontends.unit import Unit


@dataclass
class Result:
    diagnostics: list[Diagnostic] = field(default_factory=list)
    files: list[str] = field(default_factory=list)
    internal_errors: int = 0
    missing: list[str] = field(default_factory=list)
    sources: dict[str, SourceFile] = field(default_factory=dict)
    baselined: int = 0  # findings hidden by --baseline
    #: findings not listed because they lie in a file outside the project, per file
    #: (see :mod:`moos_lint.files.boundary`)
    outside: dict[str, int] = field(default_factory=dict)
    #: linted paths that are links to files outside the project (not linted)
    outside_links: list[str] = field(default_factory=list)
    #: the linted files' expansions and models (engine units), in the order given
    units: list[Unit] = field(default_factory=list)
    #: what the run has to say besides its findings ("no MOOS or C++ files found ...")
    warnings: list[str] = field(default_factory=list)
    #: the result cache entry this result is stored in (see :mod:`moos_lint.speed.cache`)
    cache_token: str | None = None
    #: what the cached result depends on, in stat terms (see :mod:`moos_lint.speed.replay`)
    cache_watch: dict[str, object] | None = None
