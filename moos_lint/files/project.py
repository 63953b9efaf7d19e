"""The project root: the one folder a run calls its project.

Everything that needs to know where the user's project begins and ends asks
this module: the result cache (which project an entry belongs to), the
project boundary (no text of a file outside it is ever shown, ``--fix``
never writes outside it), the search for the repository's C++ apps and
behaviors, the compile database search, and baselines.

The definition, in order:

1. the folder of the moos-lint configuration file in use (given with
   ``--config``, or the nearest one found at or above the linted paths);
2. else the top of the version-control checkout holding the first linted
   path (the nearest folder above it with ``.git``, ``.hg`` or ``.svn``);
3. else the working folder, when every linted path lies under it (as ruff
   does);
4. else the deepest folder common to the linted paths.

The module imports nothing of moos-lint but the marker names, so every layer
may use it.
"""

from __future__ import annotations

import os
from collections.abc import Iterable

from moos_lint.files.markers import VCS_MARKERS


def _folder_of(path: str) -> str:
    path = os.path.abspath(path)
    return path if os.path.isdir(path) else os.path.dirname(path)


def vcs_top(start: str) -> str | None:
    """The nearest folder at or above ``start`` that holds a version-control folder."""
    here = _folder_of(start)
    while True:
        if any(os.path.exists(os.path.join(here, m)) for m in VCS_MARKERS):
            return here
        parent = os.path.dirname(here)
        if parent == here:
            return None
        here = parent


def is_within(path: str, folder: str) -> bool:
    """True when ``path`` is ``folder`` or lies below it (both compared as given, absolute)."""
    path = os.path.abspath(path)
    folder = os.path.abspath(folder)
    if path == folder:
        return True
    prefix = folder if folder.endswith(os.sep) else folder + os.sep
    return path.startswith(prefix)


def project_root(
    paths: Iterable[str | os.PathLike] = (),
    config_path: str | os.PathLike | None = None,
    cwd: str | None = None,
) -> str:
    """The project root of a run over ``paths`` (absolute, not resolved through links)."""
    if config_path:
        return os.path.dirname(os.path.abspath(config_path))
    given = [os.path.abspath(os.fspath(p)) for p in paths] or [os.path.abspath(cwd or os.curdir)]
    top = vcs_top(given[0])
    if top is not None:
        return top
    here = os.path.abspath(cwd or os.getcwd())
    if all(is_within(p, here) for p in given):
        return here
    folders = [_folder_of(p) for p in given]
    try:
        return os.path.commonpath(folders)
    except ValueError:  # paths on different drives
        return folders[0]


def real_within(path: str, root: str) -> bool:
    """True when ``path``, its links followed, lies inside ``root`` (links followed too)."""
    return is_within(os.path.realpath(path), os.path.realpath(root))
