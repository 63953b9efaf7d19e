"""Inline suppression comments.

    key = value   // moos-lint: ignore[R003, brace-on-header] reason
    // moos-lint: ignore[R003]            (applies to the next line)
    // moos-lint: disable[N001]  ...  // moos-lint: enable[N001]
    // moos-lint: file-ignore[U001]

A selector is a rule code, a code prefix, a rule name, or ``ALL``.
"""

from __future__ import annotations

import re
from dataclasses import dataclass, field

from moos_lint.files.diagnostics import INTERNAL_ERROR, Diagnostic, Span
from moos_lint.rules.kit.selectors import selects

_COMMENT = re.compile(
    r"//\s*moos-lint:\s*(?P<verb>ignore|disable|enable|file-ignore)\s*"
    r"\[(?P<codes>[^\]]*)\]"
)
COMMENT_RE = _COMMENT  # public name, for the fix that removes unused selectors


@dataclass(slots=True)
class Suppression:
    verb: str
    selectors: list[str]
    path: str
    line: int
    col: int
    end_col: int
    first: int  # first line covered
    last: int  # last line covered (inclusive)
    used: set[str] = field(default_factory=set)  # selectors that suppressed something

    @property
    def span(self) -> Span:
        return Span(self.path, self.line, self.col, self.line, self.end_col)

    def covers(self, diag: Diagnostic) -> str | None:
        """The selector that suppresses ``diag``, if any."""
        if diag.span.path != self.path or not (self.first <= diag.span.line <= self.last):
            return None
        for sel in self.selectors:
            if sel.upper() == "ALL" or sel.upper() == diag.code:
                return sel
            # moos-lint's own failures are matched by code alone, not by name or prefix
            if diag.code != INTERNAL_ERROR and selects(sel, diag.code, diag.name):
                return sel
        return None


class SuppressionIndex:
    """One file's suppressions by the lines they cover: a finding is compared with those
    that cover its line, not with every suppression of the file."""

    def __init__(self, suppressions: list[Suppression]) -> None:
        self.by_line: dict[int, list[Suppression]] = {}
        #: those covering many lines (``disable`` ... ``enable``, a whole file): few
        self.ranges: list[Suppression] = []
        for sup in suppressions:
            if sup.last - sup.first < 8:
                for line in range(sup.first, sup.last + 1):
                    self.by_line.setdefault(line, []).append(sup)
            else:
                self.ranges.append(sup)

    def at(self, line: int) -> list[Suppression]:
        """The suppressions that may cover ``line``, in the file's order."""
        here = self.by_line.get(line, [])
        if not self.ranges:
            return here
        near = [s for s in self.ranges if s.first <= line <= s.last]
        return sorted([*here, *near], key=lambda s: (s.line, s.col)) if near else here


def parse_suppressions(path: str, lines: list[str]) -> list[Suppression]:
    """Every suppression comment in one file, with the lines it covers."""
    out: list[Suppression] = []
    open_ranges: dict[str, Suppression] = {}
    n = len(lines)
    for idx, text in enumerate(lines):
        if "moos-lint:" not in text:
            continue
        for m in _COMMENT.finditer(text):
            lineno = idx + 1
            verb = m.group("verb")
            selectors = [s.strip() for s in m.group("codes").split(",") if s.strip()]
            whole_line = text[: m.start()].strip() == ""
            sup = Suppression(
                verb, selectors, path, lineno, m.start() + 1, m.end() + 1, lineno, lineno
            )
            if verb == "ignore":
                sup.last = lineno + 1 if whole_line else lineno
                out.append(sup)
            elif verb == "file-ignore":
                sup.first, sup.last = 1, max(n, 1)
                out.append(sup)
            elif verb == "disable":
                # One range per selector, so each can be enabled on its own.
                for s in selectors:
                    rng = Suppression(
                        verb, [s], path, lineno, sup.col, sup.end_col, lineno, max(n, 1)
                    )
                    open_ranges[s.lower()] = rng
                    out.append(rng)
            else:  # enable
                for s in selectors:
                    start = open_ranges.pop(s.lower(), None)
                    if start is not None:
                        start.last = lineno
    return out
