"""Declaring a rule: its metadata, its docs, and the table of declared rules.

A rule is one module in :mod:`moos_lint.rules`. Its module docstring is its
documentation, in fixed sections (see :data:`DOC_SECTIONS`), and it declares
itself with the :func:`rule` decorator on its check function::

    @rule(code="M003", name="brace-on-header", severity=Severity.ERROR, scope=Scope.FILE)
    def check(ctx):
        ...
        yield ctx.report(span, "message")

The rules import this module; :mod:`moos_lint.core.registry` loads the rules and
selects among them.
"""

from __future__ import annotations

import enum
import re
import sys
from collections.abc import Callable, Iterable
from dataclasses import dataclass, field
from typing import Any

from moos_lint.files.diagnostics import Severity
from moos_lint.files.suffixes import Kind  # the kind of a file: defined with its suffixes

DOC_SECTIONS = ("What it does", "Why is this bad?", "Example", "How to fix", "Options")
CODE_RE = re.compile(r"^[A-Z][0-9]{3}$")
NAME_RE = re.compile(r"^[a-z][a-z0-9]*(-[a-z0-9]+)*$")
DOCS_URL = "https://github.com/moos-lint/moos-lint/blob/main/rules/{name}.md"


#: a rule's check: takes the rule's context (:class:`moos_lint.core.engine.Context`), yields
#: findings
Check = Callable[..., Iterable[Any]]


class Scope(enum.Enum):
    FILE = "file"  # one file, after nsplug expansion
    MISSION = "mission"  # one mission: a .moos file with an ANTLER block, with its includes
    CPP = "cpp"  # one C++ unit
    PROJECT = "project"  # everything linted in one run


@dataclass(slots=True)
class Rule:
    code: str
    name: str
    severity: Severity
    scope: Scope
    check: Check
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


#: code -> rule, for every rule module imported so far
RULES: dict[str, Rule] = {}


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
) -> Callable[[Check], Check]:
    """Declare a rule; the decorated function is its check."""

    def wrap(fn: Check) -> Check:
        if not CODE_RE.match(code):
            raise ValueError(f"bad rule code {code!r}")
        if not NAME_RE.match(name):
            raise ValueError(f"bad rule name {name!r}")
        if code in RULES and RULES[code].module != fn.__module__:
            raise ValueError(f"rule code {code} is used twice")
        module = sys.modules.get(fn.__module__)
        RULES[code] = Rule(
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


__all__ = [
    "CODE_RE",
    "DOCS_URL",
    "DOC_SECTIONS",
    "NAME_RE",
    "RULES",
    "Kind",
    "Rule",
    "Scope",
    "doc_sections",
    "rule",
]
