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

from moos_lint.diagnostics import INTERNAL_ERROR, Diagnostic, Span
from moos_lint.selectors import selects

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
