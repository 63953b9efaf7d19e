"""What the modules that build shared models keep for one lint run, declared.

The engine's :class:`moos_lint.core.engine.LintRun` holds one :class:`RunMemos`.
Each field is filled, and read, only by the module that owns it, through its
typed accessor:

- ``catalogue``: :func:`moos_lint.semantics.catalogue.catalogue_for`;
- ``mission_models``, ``mission_cores``, ``pokes``, ``app_publishers``, ``external_publishers``,
  ``mission_files``: :func:`moos_lint.semantics.mission_model.mission_model` and its helpers;
- ``shared_out``, ``share_partners``: :mod:`moos_lint.semantics.shares`;
- ``repo_cpp_stems``, ``repo_behavior_files``:
  :func:`moos_lint.rules.mission._behaviors.repo_classes`;
- ``repo_behavior_posts``: :func:`moos_lint.rules.mission._behaviors.repo_behavior_posts`;
- ``repo_globals``, ``file_wide``, ``built_keys``: :mod:`moos_lint.rules.kit.file_wide`.

Those modules see the run through :class:`RunView`, the part of it they read,
so that none of them imports the engine.
"""

from __future__ import annotations

import os
from collections.abc import Iterable
from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Any, Protocol

if TYPE_CHECKING:  # types only: the owners import this module, not the reverse
    from moos_lint.core.config import Settings
    from moos_lint.files.source import SourceFile
    from moos_lint.frontends.nsplug import Preprocessor
    from moos_lint.frontends.unit import Unit
    from moos_lint.semantics.catalogue import Catalogue
    from moos_lint.semantics.mission_model import MissionModel, Publisher


@dataclass
class RunMemos:
    """The memos of one lint run (see the module docs for who fills each)."""

    #: the run's app and behavior catalogue (stock, user files, the run's own C++)
    catalogue: Catalogue | None = None
    #: normalised mission path -> its model
    mission_models: dict[str, MissionModel] = field(default_factory=dict)
    #: normalised mission path -> the builder of its own part (without what the missions
    #: beside it publish), which its model and its siblings' models share
    mission_cores: dict[str, Any] = field(default_factory=dict)
    #: folder -> ``VAR`` -> the script whose ``uPokeDB`` posts it
    pokes: dict[str, dict[str, str]] = field(default_factory=dict)
    #: (id of the app's catalogue entry, process name) -> (key, publisher) pairs
    app_publishers: dict[tuple[int, str], list[tuple[str, Publisher]]] = field(default_factory=dict)
    #: normalised sibling mission path -> what it publishes, by key
    external_publishers: dict[str, dict[str, list[Publisher]]] = field(default_factory=dict)
    #: folder -> the normalised paths of the ``.moos`` files there that may be missions
    mission_files: dict[str, list[str]] = field(default_factory=dict)
    #: route -> the variables the project's missions send on it with pShare
    shared_out: dict[str, frozenset[str]] | None = None
    #: normalised mission path -> the missions beside it that pShare ties it to (read by
    #: the rules of that mission only)
    share_partners: dict[str, list[Any]] = field(default_factory=dict)
    #: the names of the C++ files and classes of the project: lower case -> as written
    repo_cpp_stems: dict[str, str] | None = None
    #: the project's ``BHV_*.cpp`` files: lower-case class name -> paths (walked with the stems)
    repo_behavior_files: dict[str, list[str]] = field(default_factory=dict)
    #: behavior kind (lower case) -> the variables the project's own C++ of it posts, and
    #: whether those are all it may post
    repo_behavior_posts: dict[str, tuple[frozenset[str], bool]] = field(default_factory=dict)
    #: ``KIND@helm source folders`` -> the keys the project's own copy of behavior KIND,
    #: beside those helms it builds itself, compares with
    repo_behavior_keys: dict[str, frozenset[str]] = field(default_factory=dict)
    #: folder -> the source folders holding a helm of the project's own at or above it
    helm_sources: dict[str, list[str]] = field(default_factory=dict)
    #: such a source folder -> ``BHV_X.cpp`` -> its copies one folder below it
    helm_copies: dict[str, dict[str, list[str]]] = field(default_factory=dict)
    #: program name -> whether the project's CMake builds a program of exactly that name
    built_programs: dict[str, bool] = field(default_factory=dict)
    #: top-of-file keys the run's own C++ apps read with ``GetValue``
    repo_globals: frozenset[str] | None = None
    file_wide: frozenset[str] | None = None
    #: how those apps build the names they read (``GetValue(s + "_Longitude", v)``)
    built_keys: Any = None

    #: folder -> how many of the run's units there the rules have yet to check (see
    #: :meth:`expect`); empty when the run did not say
    unchecked: dict[str, int] = field(default_factory=dict)

    def expect(self, paths: Iterable[str]) -> None:
        """The rules will check the units at ``paths``, each once (see :meth:`checked`)."""
        for path in paths:
            folder = os.path.dirname(os.path.normpath(os.path.abspath(path)))
            self.unchecked[folder] = self.unchecked.get(folder, 0) + 1

    def checked(self, path: str) -> None:
        """The rules are done with the unit at ``path``: drop what only its rules read.

        A mission's whole model (and its pShare partners) is read only by the rules
        of that mission; its core stays while the missions beside it are checked
        (their models are made from it). Once every unit of a folder the run said it would check
        (:meth:`expect`) is checked, the cores of its missions, what they publish
        for one another and the pokes beside them are dropped too: the models of
        the missions of one folder are made from one another only. (A rule that
        asks for one again later gets it built anew.)
        """
        norm = os.path.normpath(os.path.abspath(path))
        self.mission_models.pop(norm, None)
        self.share_partners.pop(norm, None)
        folder = os.path.dirname(norm)
        left = self.unchecked.get(folder)
        if left is None:
            return
        if left > 1:
            self.unchecked[folder] = left - 1
            return
        del self.unchecked[folder]
        for memo in (self.mission_cores, self.external_publishers):
            for key in [k for k in memo if os.path.dirname(k) == folder]:
                del memo[key]
        self.pokes.pop(folder, None)


class RunView(Protocol):
    """The part of a lint run that the model builders read."""

    @property
    def settings(self) -> Settings: ...
    @property
    def units(self) -> list[Unit]: ...
    @property
    def sources(self) -> dict[str, SourceFile]: ...
    @property
    def preprocessor(self) -> Preprocessor: ...
    @property
    def memos(self) -> RunMemos: ...


__all__ = ["RunMemos", "RunView"]
