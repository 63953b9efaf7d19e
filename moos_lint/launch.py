"""The folders a mission may be launched from.

pAntler, the helm and every MOOS app open relative paths (``behaviors =
targs/targ_abe.bhv``, ``obstacle_file = ...``) from the folder they were started
in, not from the mission file's folder. Launch scripts run ``pAntler
targs/targ_abe.moos`` from the mission folder, so a path inside a generated
mission is often relative to a parent of the file's folder. The plausible
launch folders of a mission file are its own folder and its parents up to the
project root (see :mod:`moos_lint.project`): a relative path is missing only
when none of them holds it.
"""

from __future__ import annotations

import os

from moos_lint.project import is_within, vcs_top


def project_folder(settings, path: str) -> str:
    """The project root for a file: the config's folder, the checkout's top, or the
    working folder holding the file (the file's own folder otherwise)."""
    config = getattr(settings, "config_path", None)
    if config:
        return os.path.dirname(os.path.abspath(config))
    top = vcs_top(path)
    if top is not None:
        return top
    here = os.getcwd()
    if is_within(path, here):
        return here
    return os.path.dirname(os.path.abspath(path))


def launch_folders(path: str, root: str) -> list[str]:
    """The file's folder, then each parent up to ``root`` (when the file lies under it)."""
    here = os.path.dirname(os.path.abspath(path))
    out = [here]
    root = os.path.abspath(root)
    if not is_within(here, root):
        return out
    while here != root:
        parent = os.path.dirname(here)
        if parent == here:
            break
        here = parent
        out.append(here)
    return out


def find_relative(name: str, folders: list[str]) -> str | None:
    """The first ``folder/name`` that exists, or None."""
    if os.path.isabs(name):
        return name if os.path.exists(name) else None
    for folder in folders:
        candidate = os.path.join(folder, name)
        if os.path.exists(candidate):
            return candidate
    return None
