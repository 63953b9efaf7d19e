"""One linted file (or one folder of C++): its expansion and its model.

Kept apart from the engine so that the front ends that build units (the C++
reader) and the modules that read them depend on it, not on the engine.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import TYPE_CHECKING

from moos_lint.files.suffixes import Kind
from moos_lint.frontends.nsplug import Expansion
from moos_lint.frontends.parsers.nodes import BehaviorFile, MoosFile

if TYPE_CHECKING:  # a run over missions alone never loads the C++ reader
    from moos_lint.frontends.cpp.model import AppModel


@dataclass
class Unit:
    """One linted file: its expansion and its model."""

    path: str
    kind: Kind
    expansion: Expansion
    moos: MoosFile | None = None
    bhv: BehaviorFile | None = None
    #: C++ units (one folder of C++ files): the app model
    cpp: AppModel | None = None


__all__ = ["Unit"]
