"""Colour for the text and concise reports, as ruff colours them: the path bold, the
code bold red, the separators cyan, the source gutter bold blue, the caret bold red.

``--color auto`` (the default) colours only a terminal, and honours the
``NO_COLOR`` (no colour) and ``FORCE_COLOR`` (colour) conventions
(https://no-color.org, https://force-color.org); ``always`` and ``never`` decide
whatever the environment says.
"""

from __future__ import annotations

import os

TYPE_CHECKING = False  # typing itself is not imported at run time
if TYPE_CHECKING:
    from collections.abc import Mapping

CHOICES = ("auto", "always", "never")

BOLD = "\x1b[1m"
RED = "\x1b[1;31m"
BLUE = "\x1b[1;34m"
CYAN = "\x1b[36m"
RESET = "\x1b[0m"


def wanted(choice: str, fd: int, env: Mapping[str, str] | None = None) -> bool:
    """Whether to colour what is written to the file descriptor ``fd``."""
    if choice == "always":
        return True
    if choice == "never":
        return False
    environ = os.environ if env is None else env
    if environ.get("NO_COLOR"):
        return False
    if environ.get("FORCE_COLOR"):
        return True
    try:
        return os.isatty(fd) and environ.get("TERM") != "dumb"
    except OSError:
        return False


class Palette:
    """Wraps text in escape codes, or leaves it as it is (``on`` False)."""

    __slots__ = ("on",)

    def __init__(self, on: bool) -> None:
        self.on = on

    def _wrap(self, code: str, text: str) -> str:
        return f"{code}{text}{RESET}" if self.on and text else text

    def path(self, text: str) -> str:
        return self._wrap(BOLD, text)

    def code(self, text: str) -> str:
        return self._wrap(RED, text)

    def sep(self, text: str) -> str:
        return self._wrap(CYAN, text)

    def gutter(self, text: str) -> str:
        return self._wrap(BLUE, text)

    def caret(self, text: str) -> str:
        marks = text.lstrip(" ")
        return text[: len(text) - len(marks)] + self._wrap(RED, marks)

    def location(self, path: str, line: int, col: int) -> str:
        """``path:line:col:`` with its separators coloured."""
        if not self.on:
            return f"{path}:{line}:{col}:"
        c = self.sep(":")
        return f"{self.path(path)}{c}{line}{c}{col}{c}"
