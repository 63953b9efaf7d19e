"""The rule registry: loads every rule module and selects among the declared rules.

Rules declare themselves with :func:`moos_lint.rules.kit.declare.rule`; this module
imports each module of :mod:`moos_lint.rules` once, and answers which rules
a selection enables.
"""

from __future__ import annotations

import importlib
import pkgutil

from moos_lint.rules.kit.declare import (
    CODE_RE,
    DOC_SECTIONS,
    DOCS_URL,
    NAME_RE,
    RULES,
    Kind,
    Rule,
    Scope,
    doc_sections,
    rule,
)
from moos_lint.rules.kit.selectors import selects

_LOADED = False


def load_rules() -> None:
    """Import every module under :mod:`moos_lint.rules` (each rule module declares its rule)."""
    global _LOADED
    if _LOADED:
        return
    import moos_lint.rules as pkg

    # rule modules may sit in sub-packages (one per family): walk them all
    found = pkgutil.walk_packages(pkg.__path__, prefix=f"{pkg.__name__}.")
    for name in sorted(info.name for info in found):
        importlib.import_module(name)
    _LOADED = True


def all_rules() -> list[Rule]:
    load_rules()
    return sorted(RULES.values(), key=lambda r: r.code)


def get_rule(key: str) -> Rule | None:
    """A rule by code or name."""
    load_rules()
    if key.upper() in RULES:
        return RULES[key.upper()]
    for r in RULES.values():
        if r.name == key:
            return r
    return None


def matches(selector: str, r: Rule) -> bool:
    """``ALL``, a code, a code prefix (``M``, ``M0``), or a rule name."""
    return selects(selector, r.code, r.name)


def is_valid_selector(selector: str) -> bool:
    load_rules()
    return any(matches(selector, r) for r in RULES.values())


def select_rules(
    select: list[str] | None, extend_select: list[str], ignore: list[str]
) -> list[Rule]:
    """The rules enabled by a selection, in code order."""
    rules = all_rules()
    if select is None:
        chosen = {r.code for r in rules if r.default_enabled}
    else:
        chosen = {r.code for r in rules if any(matches(s, r) for s in select)}
    chosen |= {r.code for r in rules if any(matches(s, r) for s in extend_select)}
    chosen -= {r.code for r in rules if any(matches(s, r) for s in ignore)}
    return [r for r in rules if r.code in chosen]


__all__ = [
    "CODE_RE",
    "DOCS_URL",
    "DOC_SECTIONS",
    "NAME_RE",
    "Kind",
    "Rule",
    "Scope",
    "all_rules",
    "doc_sections",
    "get_rule",
    "is_valid_selector",
    "load_rules",
    "matches",
    "rule",
    "select_rules",
]
