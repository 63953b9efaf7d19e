"""Findings: where they are, how bad, and how to fix them."""

from __future__ import annotations

import enum
from dataclasses import dataclass, field


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

    @property
    def sort_key(self) -> tuple:
        s = self.span
        return (s.path, s.line, s.col, self.code, self.message)

    @property
    def identity(self) -> tuple:
        """Two findings with one identity are one finding (reached twice through includes)."""
        s = self.span
        return (self.code, s.path, s.line, s.col, s.end_line, s.end_col, self.message)
