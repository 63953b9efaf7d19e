"""What the caches compare a file or folder by, without reading it.

A file's stamp is its (modification time in ns, size); a folder's is its
modification time, which changes when an entry is added, removed or renamed.
Either is None for a path that cannot be stat'ed. No imports beyond ``os``: the
replay of an unchanged run (:mod:`moos_lint.speed.replay`) uses them before anything
else loads.
"""

from __future__ import annotations

import os


def file_stamp(path: str) -> tuple[int, int] | None:
    try:
        st = os.stat(path)
    except OSError:
        return None
    return st.st_mtime_ns, st.st_size


def folder_mtime(path: str | bytes) -> int | None:
    try:
        return os.stat(path).st_mtime_ns
    except OSError:
        return None


def package_stamps(root: str) -> tuple[dict[str, tuple[int, int] | None], dict[str, int | None]]:
    """The stamp of each ``.py`` and ``.json`` file below ``root`` and the mtime of each
    folder there (``__pycache__`` left out): what moos-lint's own code is, for the caches."""
    files: dict[str, tuple[int, int] | None] = {}
    folders: dict[str, int | None] = {}
    for dirpath, dirnames, filenames in os.walk(root):
        dirnames[:] = sorted(d for d in dirnames if d != "__pycache__")
        folders[dirpath] = folder_mtime(dirpath)
        for name in sorted(filenames):
            if name.endswith((".py", ".json")):
                files[os.path.join(dirpath, name)] = file_stamp(os.path.join(dirpath, name))
    return files, folders
