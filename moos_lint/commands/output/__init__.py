"""Output formats. Each format module has ``render(result, cwd) -> str``."""

from __future__ import annotations

import functools
import importlib
import os

FORMATS = ("text", "concise", "json", "sarif", "github", "gitlab", "junit")


def display_path(path: str, cwd: str | None = None) -> str:
    """``path`` relative to the working directory when it is under it."""
    return _display_path(path, cwd or os.getcwd())


@functools.lru_cache(maxsize=4096)
def _display_path(path: str, cwd: str) -> str:
    try:
        rel = os.path.relpath(path, cwd)
    except ValueError:
        return path
    return path if rel.startswith("..") else rel


#: Line breaks a CI log reader splits on (GitHub's runner: CR and LF), shown escaped.
_BREAKS = str.maketrans(
    {"\r": "\\r", "\n": "\\n", "\x85": "\\x85", "\u2028": "\\u2028", "\u2029": "\\u2029"}
)


def inert(text: str) -> str:
    """``text`` (a message, a file name) on one line: a line break in it is shown
    escaped, so nothing taken from a file starts a line of its own in a CI log (a
    GitHub Actions workflow command such as ``::error``)."""
    if "\r" in text or "\n" in text or "\x85" in text or "\u2028" in text or "\u2029" in text:
        return text.translate(_BREAKS)
    return text


def shown_path(path: str, cwd: str | None = None) -> str:
    """:func:`display_path` for a line of a text report: on one line, and never
    starting with ``:`` (``./::error::x.moos`` names the same file as ``::error::x.moos``)."""
    shown = inert(display_path(path, cwd))
    return "./" + shown if shown.startswith(":") else shown


def render(fmt: str, result, cwd: str | None = None, **kw) -> str:
    module = importlib.import_module(f"moos_lint.commands.output.{fmt}_format")
    return module.render(result, cwd or os.getcwd(), **kw)
