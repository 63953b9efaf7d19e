"""What a long run is doing, on a terminal: ``checking 120/505 files`` on stderr.

Shown only when stderr is a terminal and the report is for a person (the text
and concise formats), and only once a run has lasted about a second: a quick
run, a report replayed from the cache, CI and editors see nothing. The line is
redrawn in place (at most ten times a second) and cleared before the report
is written.

A run over many files in a folder that is no project (no moos-lint config,
no version-control checkout) first says what it is about to do, since a
mistyped working folder (a home folder) can mean minutes of work.
"""

from __future__ import annotations

import os
import time


def _delay() -> float:
    """Seconds a run lasts before its progress shows (``MOOS_LINT_PROGRESS_DELAY``, default 1)."""
    try:
        return max(0.0, float(os.environ.get("MOOS_LINT_PROGRESS_DELAY", "1.0")))
    except ValueError:
        return 1.0


#: seconds a run lasts before its progress shows
DELAY = _delay()
#: seconds between two redraws
REDRAW = 0.1
#: files from which a run outside any project is announced
LARGE = 1000


class Progress:
    """Counts the files a run has read and checked; draws the count on ``stream``."""

    def __init__(self, stream, announce_under: str | None = None) -> None:
        self.stream = stream
        #: the folder to name when announcing a large run outside any project
        self.announce_under = announce_under
        self.started = time.monotonic()
        self.last = 0.0
        self.total = 0
        self.done = 0
        self.phase = "reading"
        self.drawn = False

    def start(self, total: int) -> None:
        """A run over ``total`` files begins."""
        self.total = total
        self.done = 0
        if self.announce_under is not None and total >= LARGE:
            self._write(
                f"moos-lint: linting {total} files under {self.announce_under} "
                "(no moos-lint config or repository here; Ctrl-C to stop)\n"
            )
            self.announce_under = None

    def begin(self, phase: str, total: int) -> None:
        """Counting starts again for ``phase`` (``checking``) over ``total`` files."""
        self.phase = phase
        self.total = total
        self.done = 0

    def advance(self, n: int = 1) -> None:
        self.done += n
        now = time.monotonic()
        if now - self.started < DELAY or now - self.last < REDRAW:
            return
        self.last = now
        total = max(self.total, self.done)
        self._write(f"\r\x1b[Kmoos-lint: {self.phase} {self.done}/{total} files")
        self.drawn = True

    def close(self) -> None:
        """Clear the line (before the report is written)."""
        if self.drawn:
            self._write("\r\x1b[K")
            self.drawn = False

    def _write(self, text: str) -> None:
        try:
            self.stream.write(text)
            self.stream.flush()
        except (OSError, ValueError):
            pass


def for_terminal(stream, fmt: str, quiet: bool, announce_under: str | None) -> Progress | None:
    """A :class:`Progress` when ``stream`` is a terminal and ``fmt`` is for a person."""
    if quiet or fmt not in ("text", "concise"):
        return None
    try:
        if not os.isatty(stream.fileno()):
            return None
    except (AttributeError, OSError, ValueError):
        return None
    return Progress(stream, announce_under)
