"""Walking the project's folders, for the files that rules read beside the linted ones
(the project's C++ class files, its CMake files, its other missions)."""

from __future__ import annotations

import os
from collections.abc import Iterator

#: folders never walked: version control, environments, caches
SKIP_DIRS = frozenset(
    {".git", ".hg", ".svn", "node_modules", ".venv", "__pycache__", ".moos_lint_cache"}
)
#: a walk stops after this many folders (a huge tree)
MAX_FOLDERS = 20000


def project_walk(root: str) -> Iterator[tuple[str, list[str]]]:
    """Each folder under ``root`` (build folders and :data:`SKIP_DIRS` left out), with the
    names of its files, folders in sorted order."""
    for count, (dirpath, dirs, files) in enumerate(os.walk(root)):
        dirs[:] = sorted(d for d in dirs if d not in SKIP_DIRS and not d.startswith("build"))
        yield dirpath, sorted(files)
        if count >= MAX_FOLDERS:
            return


__all__ = ["MAX_FOLDERS", "SKIP_DIRS", "project_walk"]
