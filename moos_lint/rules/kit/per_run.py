"""Facts a rule works out once per lint run from all of the run's units.

Several rules look across the run (what every mission launches, what the
missions that include a fragment launch). The engine runs them on one unit at
a time, so each such fact is worked out on first use and kept beside the run,
until the run's units change (the language server re-lints in the same run).
"""

from __future__ import annotations

import weakref
from collections.abc import Callable
from typing import Any, TypeVar

T = TypeVar("T")

_FACTS: weakref.WeakKeyDictionary[Any, dict[str, tuple[tuple, Any]]] = weakref.WeakKeyDictionary()


def per_run(run: Any, name: str, build: Callable[[list], T]) -> T:
    """``build(run.units)``, worked out once per run and set of units under ``name``."""
    units = run.units
    key = (id(units), len(units), id(units[0]) if units else 0, id(units[-1]) if units else 0)
    facts = _FACTS.get(run)
    if facts is None:
        facts = _FACTS[run] = {}
    kept = facts.get(name)
    if kept is None or kept[0] != key:
        kept = facts[name] = (key, build(units))
    return kept[1]
