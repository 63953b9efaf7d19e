"""The rule registry: every rule's metadata, its docs, and rule selection.

A rule is one module in :mod:`moos_lint.rules`. Its module docstring is its
documentation, in fixed sections (see :data:`DOC_SECTIONS`), and it declares
itself with the :func:`rule` decorator on its check function::

    @rule(code="M003", name="brace-on-header", severity=Severity.ERROR, scope=Scope.FILE)
    def check(ctx):
        ...
        yield ctx.report(span, "message")
"""

from __future__ import annotations

import enum
import importlib
import pkgutil
import re
import sys
from collections.abc import Callable, Iterable
from dataclasses import dataclass, field
from typing import Any

from moos_lint.diagnostics import Severity
from moos_lint.selectors import selects

DOC_SECTIONS = ("What it does", "Why is this bad?", "Example", "How to fix", "Options")
CODE_RE = re.compile(r"^[A-Z][0-9]{3}$")
NAME_RE = re.compile(r"^[a-z][a-z0-9]*(-[a-z0-9]+)*$")
DOCS_URL = "https://github.com/moos-lint/moos-lint/blob/main/rules/{name}.md"


class Scope(enum.Enum):
    FILE = "file"  # one file, after nsplug expansion
    MISSION = "mission"  # one mission: a .moos file with an ANTLER block, with its includes
    CPP = "cpp"  # one C++ unit
    PROJECT = "project"  # everything linted in one run


class Kind(enum.Enum):
    MOOS = "moos"  # .moos, .moos++, .plug, .def
    BHV = "bhv"
    CPP = "cpp"  # C++ sources of MOOS apps


@dataclass(slots=True)
class Rule:
    code: str
    name: str
    severity: Severity
    scope: Scope
    check: Callable[..., Iterable[Any]]
    kinds: tuple[Kind, ...] = (Kind.MOOS,)
    default_enabled: bool = True
    options: dict[str, Any] = field(default_factory=dict)
    fixable: bool = False
    doc: str = ""
    module: str = ""

    @property
    def summary(self) -> str:
        """The first line of the docs."""
        return self.doc.strip().splitlines()[0].strip() if self.doc.strip() else self.name

    @property
    def url(self) -> str:
        return DOCS_URL.format(name=self.name)

    def section(self, title: str) -> str:
        return doc_sections(self.doc).get(title, "")


_RULES: dict[str, Rule] = {}
_LOADED = False


def rule(
    *,
    code: str,
    name: str,
    severity: Severity,
    scope: Scope,
    kinds: tuple[Kind, ...] = (Kind.MOOS,),
    default_enabled: bool = True,
    options: dict[str, Any] | None = None,
    fixable: bool = False,
) -> Callable:
    """Declare a rule; the decorated function is its check."""

    def wrap(fn: Callable) -> Callable:
        if not CODE_RE.match(code):
            raise ValueError(f"bad rule code {code!r}")
        if not NAME_RE.match(name):
            raise ValueError(f"bad rule name {name!r}")
        if code in _RULES and _RULES[code].module != fn.__module__:
            raise ValueError(f"rule code {code} is used twice")
        module = sys.modules.get(fn.__module__)
        _RULES[code] = Rule(
            code=code,
            name=name,
            severity=severity,
            scope=scope,
            check=fn,
            kinds=kinds,
            default_enabled=default_enabled,
            options=dict(options or {}),
            fixable=fixable,
            doc=(module.__doc__ or "") if module else "",
            module=fn.__module__,
        )
        return fn

    return wrap


def load_rules() -> None:
    global _LOADED
    if _LOADED:
        return
    import moos_lint.rules as pkg

    for info in sorted(pkgutil.iter_modules(pkg.__path__), key=lambda m: m.name):
        importlib.import_module(f"{pkg.__name__}.{info.name}")
    _LOADED = True


def all_rules() -> list[Rule]:
    load_rules()
    return sorted(_RULES.values(), key=lambda r: r.code)


def get_rule(key: str) -> Rule | None:
    """A rule by code or name."""
    load_rules()
    if key.upper() in _RULES:
        return _RULES[key.upper()]
    for r in _RULES.values():
        if r.name == key:
            return r
    return None


def matches(selector: str, r: Rule) -> bool:
    """``ALL``, a code, a code prefix (``M``, ``M0``), or a rule name."""
    return selects(selector, r.code, r.name)


def is_valid_selector(selector: str) -> bool:
    load_rules()
    return any(matches(selector, r) for r in _RULES.values())


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


def doc_sections(doc: str) -> dict[str, str]:
    """Split a rule docstring into its ``## Section`` parts (the first part is the summary)."""
    out: dict[str, str] = {}
    current = "summary"
    buf: list[str] = []
    for line in doc.strip().splitlines():
        m = re.match(r"^##\s+(.*?)\s*$", line)
        if m:
            out[current] = "\n".join(buf).strip()
            current, buf = m.group(1), []
        else:
            buf.append(line)
    out[current] = "\n".join(buf).strip()
    return out
