"""The files of moos-lint's caches: where they live, and how each entry is sealed.

Both caches (the result cache, :mod:`moos_lint.speed.cache`, and the replay of an
unchanged run, :mod:`moos_lint.speed.replay`) keep their entries as text (JSON,
and the replay's NUL-separated fields): data that no loader turns into code.
Each entry is also sealed with an HMAC-SHA256 under a key that belongs to
the user and lives outside every repository, so an entry that a repository
brings along (committed into a cache folder, or crafted in one it can write)
is never believed: it is a cache miss, like a corrupt, partial or old entry.

**Where the caches live.**

- ``--cache-dir DIR`` on the command line, or ``$MOOS_LINT_CACHE_DIR``: that
  folder, wherever it is;
- else a ``cache-dir`` set in the project's configuration: that folder, which
  must lie inside the project root (the configuration loader refuses any
  other);
- else the user's cache folder, ``$XDG_CACHE_HOME/moos-lint`` (by default
  ``~/.cache/moos-lint``), in a subfolder named by a hash of the project
  root's real path (:func:`moos_lint.files.project.project_root`).

Replay entries are kept in the folder the replay can find before the command
line is parsed: the ``--cache-dir`` or ``$MOOS_LINT_CACHE_DIR`` folder, else
``replay/`` in the user's cache folder.

**The key** is ``key`` in the user's cache folder: 32 random bytes, created
with mode 0600 on first use. A key file that is not a regular file owned by
the user and private to them is never used, and then neither is any cache.

**An entry file** is one line ``moos-lint-entry VERSION MAC`` followed by the
entry's text; MAC is the HMAC-SHA256 of the file's name, a NUL and the text. A
file that git tracks is never read (its name is looked up in the checkout's
index, :mod:`moos_lint.files.gitindex`), nor written.

Only ``os`` is imported here: the replay uses this module before anything
else loads.
"""

from __future__ import annotations

import os

TYPE_CHECKING = False  # typing itself is not imported at run time
if TYPE_CHECKING:
    from typing import Any

#: the version of the entry envelope (the first line)
VERSION = 3
MAGIC = b"moos-lint-entry %d " % VERSION
KEY_NAME = "key"
KEY_BYTES = 32
#: the replay's folder in the user's cache folder
REPLAY = "replay"
ENV_VAR = "MOOS_LINT_CACHE_DIR"


def user_base() -> str | None:
    """``$XDG_CACHE_HOME/moos-lint`` (``~/.cache/moos-lint`` by default), or None when
    there is no home folder to keep it in (never ``/.cache``)."""
    xdg = os.environ.get("XDG_CACHE_HOME", "")
    if os.path.isabs(xdg):  # the XDG specification ignores a relative value
        return os.path.join(xdg, "moos-lint")
    home = os.path.expanduser("~")
    if not os.path.isabs(home) or os.path.dirname(home) == home:  # no home, or ``/``
        return None
    return os.path.join(home, ".cache", "moos-lint")


def project_folder(root: str) -> str | None:
    """The default cache folder of the project rooted at ``root``."""
    base = user_base()
    if base is None:
        return None
    name = _sha256(os.fsencode(os.path.realpath(root))).hexdigest()[:32]
    return os.path.join(base, name)


def replay_folder() -> str | None:
    base = user_base()
    return None if base is None else os.path.join(base, REPLAY)


def command_line_folder(argv_dir: str | None) -> str | None:
    """The folder the command line or the environment names (``--cache-dir`` wins)."""
    if argv_dir:
        return os.path.abspath(argv_dir)
    env = os.environ.get(ENV_VAR)
    return os.path.abspath(env) if env else None


# ------------------------------------------------------------------ the key
def user_key(create: bool) -> bytes | None:
    """The user's key (made on first use when ``create``), or None when there is none
    that can be trusted."""
    base = user_base()
    if base is None:
        return None
    path = os.path.join(base, KEY_NAME)
    key = _read_key(path)
    if key is not None or not create:
        return key
    try:
        os.makedirs(base, mode=0o700, exist_ok=True)
        tmp = os.path.join(base, f".key-{os.getpid()}-{os.urandom(6).hex()}")
        fd = os.open(tmp, os.O_WRONLY | os.O_CREAT | os.O_EXCL | _NOFOLLOW, 0o600)
        try:
            os.write(fd, os.urandom(KEY_BYTES))
        finally:
            os.close(fd)
        try:
            os.link(tmp, path)  # fails when another run made the key first: use that one
        except FileExistsError:
            pass
        finally:
            os.unlink(tmp)
    except OSError:
        return None
    return _read_key(path)


_NOFOLLOW = getattr(os, "O_NOFOLLOW", 0)


def _read_key(path: str) -> bytes | None:
    try:
        fd = os.open(path, os.O_RDONLY | _NOFOLLOW)
    except OSError:
        return None
    try:
        st = os.fstat(fd)
        private = st.st_mode & 0o077 == 0 and st.st_size == KEY_BYTES
        owned = not hasattr(os, "geteuid") or st.st_uid == os.geteuid()
        if not (private and owned and (st.st_mode & 0o170000) == 0o100000):
            return None
        key = os.read(fd, KEY_BYTES + 1)
    except OSError:
        return None
    finally:
        os.close(fd)
    return key if len(key) == KEY_BYTES else None


# ------------------------------------------------------------------ sealing
def _sha256(data: bytes = b"") -> Any:
    """A SHA-256 object from the built-in module (``_sha256`` before Python 3.12, ``_sha2``
    from it), which loads no OpenSSL; hashlib's where neither is built."""
    global _SHA256
    if _SHA256 is None:
        for name in ("_sha256", "_sha2"):
            try:
                _SHA256 = __import__(name).sha256
                break
            except ImportError:
                continue
        else:  # pragma: no cover
            from hashlib import sha256

            _SHA256 = sha256
    return _SHA256(data)


_SHA256: Any = None

_IPAD = bytes(x ^ 0x36 for x in range(256))
_OPAD = bytes(x ^ 0x5C for x in range(256))


def mac(key: bytes, name: str, body: bytes) -> str:
    """HMAC-SHA256 (RFC 2104) of ``name``, a NUL and ``body`` under ``key``, in hex.

    Written out over the built-in SHA-256 module rather than :mod:`hmac`,
    which loads OpenSSL: the replay pays for every module it loads.
    """
    if len(key) > 64:
        key = _sha256(key).digest()
    key = key.ljust(64, b"\0")
    inner = _sha256(key.translate(_IPAD))
    inner.update(os.fsencode(name) + b"\0")
    inner.update(body)
    outer = _sha256(key.translate(_OPAD))
    outer.update(inner.digest())
    return outer.hexdigest()


def seal(key: bytes, name: str, body: bytes) -> bytes:
    return MAGIC + mac(key, name, body).encode("ascii") + b"\n" + body


def unseal(key: bytes, name: str, data: bytes) -> bytes | None:
    """The body of an entry sealed under ``key`` with ``name``, else None."""
    if not data.startswith(MAGIC):
        return None
    end = data.find(b"\n", len(MAGIC))
    if end != len(MAGIC) + 64:
        return None
    body = data[end + 1 :]
    from _operator import _compare_digest  # (what hmac.compare_digest falls back to)

    if not _compare_digest(data[len(MAGIC) : end], mac(key, name, body).encode("ascii")):
        return None
    return body


# ------------------------------------------------------------------ a cache folder
#: the largest entry read (a run's entry holds the text of the files with findings)
MAX_ENTRY = 512 * 1024 * 1024
_READ_FLAGS = os.O_RDONLY | _NOFOLLOW | getattr(os, "O_NONBLOCK", 0)


class Folder:
    """One cache folder: entries are read and written only when sealed under the key,
    and never when git tracks them."""

    def __init__(self, path: str, key: bytes) -> None:
        self.path = path
        self.key = key
        self._tracked: frozenset[str] | None = None
        self._known = False

    def tracked(self, name: str) -> bool:
        if not self._known:
            from moos_lint.files.gitindex import tracked_names

            self._tracked = tracked_names(self.path)
            self._known = True
        return self._tracked is None or name in self._tracked

    def read(self, name: str) -> bytes | None:
        """The body of the entry ``name``, when it is there, sealed and not tracked.

        Only a regular file is read, never through a link, and never one larger
        than :data:`MAX_ENTRY` (a link to a device or a FIFO would never end).
        """
        try:
            fd = os.open(os.path.join(self.path, name), _READ_FLAGS)
        except OSError:
            return None
        try:
            st = os.fstat(fd)
            if (st.st_mode & 0o170000) != 0o100000 or st.st_size > MAX_ENTRY:
                return None
            chunks = []
            while True:
                chunk = os.read(fd, max(st.st_size + 1, 65536))
                if not chunk:
                    break
                chunks.append(chunk)
                if sum(map(len, chunks)) > MAX_ENTRY:
                    return None
        except OSError:
            return None
        finally:
            os.close(fd)
        if self.tracked(name):
            return None
        return unseal(self.key, name, b"".join(chunks))

    def write(self, name: str, body: bytes) -> None:
        """Seal and write the entry ``name`` atomically (raises OSError when it cannot)."""
        if self.tracked(name):
            raise OSError(f"{name}: tracked by git")
        atomic_write(self.path, os.path.join(self.path, name), seal(self.key, name, body))


def open_folder(path: str | None, create: bool, gitignore: bool = False) -> Folder | None:
    """The cache folder at ``path`` (made when ``create``), or None when it cannot be
    used: no key, a folder that cannot be made, or one git tracks files in."""
    if not path:
        return None
    key = user_key(create)
    if key is None:
        return None
    if create:
        try:
            os.makedirs(path, mode=0o700, exist_ok=True)
        except OSError:
            return None
        ignore = os.path.join(path, ".gitignore")
        if gitignore and not os.path.exists(ignore):
            try:
                atomic_write(path, ignore, b"# created by moos-lint\n*\n")
            except OSError:
                return None
    elif not os.path.isdir(path):
        return None
    return Folder(path, key)


def atomic_write(folder: str, path: str, data: bytes) -> None:
    """Write ``data`` to ``path`` through a temporary file in ``folder``, so that a reader
    never sees half of it (and a link at ``path`` is replaced, not followed)."""
    import contextlib  # (these two only when an entry is written)
    import tempfile

    fd, tmp = tempfile.mkstemp(dir=folder, prefix=".tmp-", suffix=".part")
    try:
        with os.fdopen(fd, "wb") as fh:
            fh.write(data)
        os.replace(tmp, path)
    except BaseException:
        with contextlib.suppress(OSError):
            os.unlink(tmp)
        raise


#: entries kept per kind and folder (one per distinct run, report or command line)
KEEP = 16
KINDS = ("run", "files", "out", "replay")


def prune(folder: str, keep: int = KEEP) -> None:
    """Keep the ``keep`` most recently written entries of each kind in ``folder``."""
    import contextlib  # (only when an entry is written)

    kinds: dict[str, list[tuple[int, str]]] = {}
    try:
        names = os.listdir(folder)
    except OSError:
        return
    for name in names:
        kind = name.split("-", 1)[0]
        if kind in KINDS and name.endswith((".json", ".rec")):
            try:
                mtime = os.stat(os.path.join(folder, name)).st_mtime_ns
            except OSError:
                continue
            kinds.setdefault(kind, []).append((mtime, name))
    for entries in kinds.values():
        for _, name in sorted(entries, reverse=True)[keep:]:
            with contextlib.suppress(OSError):
                os.unlink(os.path.join(folder, name))
