"""Findings: where they are, how bad, and how to fix them."""

from __future__ import annotations

import enum
from dataclasses import dataclass, field

#: the code of a finding that says moos-lint itself failed (the run goes on)
INTERNAL_ERROR = "L900"


class Severity(enum.Enum):
    ERROR = "error"
    WARNING = "warning"
    INFO = "info"


@dataclass(frozen=True, slots=True)
class Span:
    """A range in one file. Lines and columns are 1-based; ``end_col`` is exclusive."""

    path: str
    line: int
    col: int = 1
    end_line: int = 0
    end_col: int = 0

    def __post_init__(self) -> None:
        if self.end_line < self.line:
            object.__setattr__(self, "end_line", self.line)
        if self.end_line == self.line and self.end_col < self.col:
            object.__setattr__(self, "end_col", self.col)


@dataclass(frozen=True, slots=True)
class IncludeSite:
    """An ``#include`` line that led to the line a finding is on."""

    path: str
    line: int


@dataclass(frozen=True, slots=True)
class Edit:
    """Replace ``span`` (one line) with ``text``."""

    span: Span
    text: str


@dataclass(frozen=True, slots=True)
class Fix:
    message: str
    edits: tuple[Edit, ...]


@dataclass(frozen=True, slots=True)
class Subject:
    """What a finding is about, for tools that read findings (the graph): never parsed
    out of the message. Each field is None when the finding is not about one."""

    variable: str | None = None  # a MOOS variable
    app: str | None = None  # a MOOS app or behavior (as launched or declared)
    key: str | None = None  # a configuration key (lower case)


@dataclass(slots=True)
class Diagnostic:
    code: str
    name: str
    severity: Severity
    span: Span
    message: str
    chain: tuple[IncludeSite, ...] = ()
    fix: Fix | None = None
    notes: list[str] = field(default_factory=list)
    #: what the finding is about (not part of its identity: the message says it too)
    subject: Subject | None = None

    @property
    def sort_key(self) -> tuple[str, int, int, str, str]:
        s = self.span
        return (s.path, s.line, s.col, self.code, self.message)

    @property
    def identity(self) -> tuple[str, str, int, int, int, int, str]:
        """Two findings with one identity are one finding (reached twice through includes)."""
        s = self.span
        return (self.code, s.path, s.line, s.col, s.end_line, s.end_col, self.message)
