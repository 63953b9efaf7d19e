"""Which files of a folder git tracks, read from the checkout's index file.

The caches never read an entry that git tracks: a file committed into a cache
folder came from a repository, not from an earlier run of moos-lint on this
machine. git itself is never run (running it in a checkout runs the hooks and
filters its configuration names); its index file is read as data. Versions
2, 3 and 4 of the index format are understood, with SHA-1 or SHA-256 object
names; an index that cannot be read as one of them answers "unknown", which
the caller treats as "everything is tracked".
"""

from __future__ import annotations

import os

_HEADER = 12
_STAT = 40  # ctime, mtime (seconds and nanoseconds), dev, ino, mode, uid, gid, size


def git_dir(folder: str) -> tuple[str, str] | None:
    """(work tree top, git folder) of the checkout holding ``folder``, or None.

    A ``.git`` file (a linked worktree, a submodule) names its git folder on a
    ``gitdir:`` line.
    """
    here = os.path.abspath(folder)
    while True:
        marker = os.path.join(here, ".git")
        if os.path.isdir(marker):
            return here, marker
        if os.path.isfile(marker):
            try:
                with open(marker, encoding="utf-8", errors="replace") as fh:
                    line = fh.read(4096).strip()
            except OSError:
                return here, marker
            if line.startswith("gitdir:"):
                return here, os.path.join(here, line[len("gitdir:") :].strip())
            return here, marker
        parent = os.path.dirname(here)
        if parent == here:
            return None
        here = parent


def tracked_names(folder: str) -> frozenset[str] | None:
    """The names of the files directly in ``folder`` that git tracks (empty outside a
    checkout), or None when the index cannot be read."""
    found = git_dir(folder)
    if found is None:
        return frozenset()
    top, gitdir = found
    rel = os.path.relpath(os.path.abspath(folder), top)
    prefix = b"" if rel == "." else os.fsencode(rel.replace(os.sep, "/")) + b"/"
    try:
        with open(os.path.join(gitdir, "index"), "rb") as fh:
            data = fh.read()
    except FileNotFoundError:
        return frozenset()  # a fresh repository: nothing tracked yet
    except OSError:
        return None
    if data[:4] != b"DIRC" or len(data) < _HEADER:
        return None
    version = int.from_bytes(data[4:8], "big")
    if version not in (2, 3, 4):
        return None
    if version != 4 and prefix and prefix not in data:
        return frozenset()  # whole paths are stored: none lies in the folder
    for hash_len in (20, 32):
        paths = _paths(data, version, hash_len)
        if paths is not None:
            break
    else:
        return None
    out = set()
    for path in paths:
        if path.startswith(prefix):
            rest = path[len(prefix) :]
            out.add(os.fsdecode(rest.split(b"/", 1)[0]))
    return frozenset(out)


def _paths(data: bytes, version: int, hash_len: int) -> list[bytes] | None:
    """The paths of the index entries, or None when they do not parse with ``hash_len``."""
    count = int.from_bytes(data[8:12], "big")
    pos = _HEADER
    previous = b""
    out: list[bytes] = []
    end = len(data)
    for _ in range(count):
        fixed = _STAT + hash_len + 2
        if pos + fixed > end:
            return None
        flags = int.from_bytes(data[pos + fixed - 2 : pos + fixed], "big")
        start = pos + fixed
        if flags & 0x4000:  # extended flags (version 3 and later)
            if version < 3:
                return None
            start += 2
        if version == 4:
            strip, start = _varint(data, start)
            if strip is None or strip > len(previous):
                return None
            nul = data.find(b"\0", start)
            if nul < 0:
                return None
            path = previous[: len(previous) - strip] + data[start:nul]
            pos = nul + 1
        else:
            nul = data.find(b"\0", start)
            if nul < 0:
                return None
            path = data[start:nul]
            entry = nul - pos
            pos += (entry + 8) & ~7  # padded with 1 to 8 NULs
        length = flags & 0xFFF
        if length < 0xFFF and length != len(path):
            return None
        out.append(path)
        previous = path
    return out


def _varint(data: bytes, pos: int) -> tuple[int | None, int]:
    """git's offset encoding (index version 4)."""
    if pos >= len(data):
        return None, pos
    byte = data[pos]
    value = byte & 0x7F
    pos += 1
    while byte & 0x80:
        if pos >= len(data):
            return None, pos
        byte = data[pos]
        value = ((value + 1) << 7) | (byte & 0x7F)
        pos += 1
    return value, pos
