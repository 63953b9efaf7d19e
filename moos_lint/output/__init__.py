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


def render(fmt: str, result, cwd: str | None = None, **kw) -> str:
    module = importlib.import_module(f"moos_lint.output.{fmt}_format")
    return module.render(result, cwd or os.getcwd(), **kw)
