"""Replaying an unchanged ``moos-lint check`` before anything else loads.

A warm run must cost little more than starting Python. The result cache
(:mod:`moos_lint.speed.cache`) already prints an unchanged run's report again
without loading the parsers or the rules, but it still parses the command
line, resolves the settings and validates its entries, and the modules that
takes (argparse, pathlib, hashlib, the settings) cost more than the checks
themselves. So each report the cache prints is also kept as a *replay
entry*: the exact command line, working folder and environment it answered,
the (mtime, size) of every file it depends on and the mtime of every folder
whose listing it depends on, and the text and exit status. The next
identical command checks those with ``os.stat`` and prints the text; it
imports only the built-in SHA-256 (not even ``json``, whose import alone, with
the ``re`` and ``enum`` it pulls in, costs a third of a warm run).

**Trust.** A replay entry is plain text sealed with an HMAC-SHA256 under the
user's key (:mod:`moos_lint.speed.cache_files`); an entry that is not sealed under
that key, that git tracks, or that is not laid out as this version writes
it is ignored, and the normal run decides. No loader turns the text into
anything but strings: fields separated by NUL (which no path holds),

    repr(identity) NUL status NUL #files NUL #folders NUL #presences
    (NUL path NUL "mtime size" or "-")...      every file, or "-" for absent
    (NUL path NUL "mtime" or "-")...           every folder
    (NUL path NUL "1" or "0")...               every presence
    NUL text                                   the report (it may hold NULs)

and the identity is compared as the ``repr`` of the one this run computes.
Paths are written as the file system's bytes (``os.fsencode``), the rest as
UTF-8. The report goes where the command line sends it: to stdout, or to the
file ``-o``/``--output-file`` names on that command line; an entry names no file.

**What an entry depends on**, beyond what the run entry records (every file
the lint read, the folders they sit in, the folders discovery walked): the
paths given, moos-lint's own files, and what decides the settings and the
project root: each folder at and above the paths given is checked for the
config files (their (mtime, size), or their absence) and for the
version-control folders (their presence). The environment variables moos-lint
reads, the interpreter and where moos-lint is installed are part of the
entry's identity.

**Where it is found.** Without parsing the command line, the replay looks
in the folder a ``--cache-dir`` names, else in ``$MOOS_LINT_CACHE_DIR``,
else in ``replay/`` in the user's cache folder, under a name made of the
working folder and the command line.

Anything unexpected (no entry, another command line, a changed file, an
unreadable, unsealed or corrupt entry, a command line whose report file the
replay cannot tell for certain) falls through to the normal run, which
writes a fresh entry. :func:`replay` writes nothing but the report file the
command line names; :func:`remember`, called by the normal run, writes only
in the replay folder.
"""

from __future__ import annotations

import os
import sys

import moos_lint
from moos_lint import __version__
from moos_lint.files.markers import CONFIG_FILES, VCS_MARKERS
from moos_lint.files.stamps import file_stamp, folder_mtime, package_stamps
from moos_lint.files.streams import write_stdout
from moos_lint.speed.cache_files import ENV_VAR, Folder, open_folder, prune, replay_folder

#: bump when the entry layout changes
FORMAT = 3
#: the environment variables a check run reads
ENV = (
    "GITHUB_ACTIONS",
    ENV_VAR,
    "XDG_CACHE_HOME",
    "HOME",
    "XDG_CONFIG_HOME",
    "NO_COLOR",
    "FORCE_COLOR",
)
_PACKAGE = os.path.dirname(os.path.abspath(moos_lint.__file__))
#: replay entries kept in a folder (every project's share the user's replay folder)
KEEP = 64
#: the fields before the stamps: identity, status and the three counts
_HEAD = 5


def identity(argv: list[str]) -> list:
    """What an entry must have been written for: version, interpreter, installation,
    command line, working folder and environment."""
    return [
        __version__,
        FORMAT,
        sys.version,
        _PACKAGE,
        list(argv),
        os.getcwd(),
        [os.environ.get(k) for k in ENV],
        os.isatty(1),  # (``--color auto``)
    ]


def entry_name(argv: list[str]) -> str:
    from moos_lint.speed.cache_files import _sha256

    data = "\0".join([os.getcwd(), *argv]).encode("utf-8", "surrogatepass")
    return f"replay-{_sha256(data).hexdigest()[:32]}.rec"


def _folder_path(argv: list[str]) -> str | None:
    """The replay folder for ``argv``: ``--cache-dir``, ``$MOOS_LINT_CACHE_DIR``, else the
    user's."""
    for i, arg in enumerate(argv):
        if arg == "--":
            break
        if arg == "--cache-dir" and i + 1 < len(argv):
            return os.path.abspath(argv[i + 1])
        if arg.startswith("--cache-dir="):
            return os.path.abspath(arg.split("=", 1)[1])
    env = os.environ.get(ENV_VAR)
    if env:
        return os.path.abspath(env)
    return replay_folder()


class Unsure(Exception):
    """A command line whose report file the replay cannot tell for certain."""


def output_file(argv: list[str]) -> str | None:
    """The report file ``argv`` names (``-o FILE``, ``-oFILE``, ``--output-file FILE``,
    ``--output-file=FILE``), None for stdout; :class:`Unsure` for anything argparse might
    read otherwise (an abbreviated ``--output-fi``, ``-qo FILE``)."""
    target = None
    i = 0
    while i < len(argv):
        arg = argv[i]
        if arg == "--":
            break
        value = None
        if arg in ("-o", "--output-file"):
            if i + 1 >= len(argv):
                raise Unsure(arg)
            value = argv[i + 1]
            i += 1
        elif arg.startswith("--output-file="):
            value = arg.split("=", 1)[1]
        elif arg.startswith("-o") and not arg.startswith("--"):
            value = arg[2:]
        elif arg.startswith("--output-f") and not arg.startswith("--output-format"):
            raise Unsure(arg)  # an abbreviation of --output-file
        elif arg.startswith("-q") and len(arg) > 2 and not arg.startswith("--"):
            raise Unsure(arg)  # -q with other short options joined to it
        if value is not None:
            target = value  # (argparse keeps the last one)
        i += 1
    return target


def replay(argv: list[str]) -> int | None:
    """Print the report of an unchanged run of ``moos-lint`` with ``argv`` and return its
    exit status; None (having printed nothing) when there is no valid entry."""
    try:
        target = output_file(argv)
        folder = open_folder(_folder_path(argv), create=False)
        if folder is None:
            return None
        entry = _entry(folder, argv)
        if entry is None or not _holds(entry, argv):
            return None
        if target is None:
            write_stdout(entry.text)
        else:  # written as the normal run writes it
            with open(target, "w", encoding="utf-8", errors="surrogateescape") as fh:
                fh.write(entry.text)
        return entry.status
    except Exception:  # a corrupt or foreign entry, an unclear command line: the normal run
        return None


def encode(
    identity: list,
    files: list[tuple[str, tuple[int, int] | list[int] | None]],
    dirs: list[tuple[str, int | None]],
    exist: list[tuple[str, bool]],
    text: str,
    status: int,
) -> bytes:
    """An entry's body, laid out as the module's docstring says. A file's stamp is any
    (mtime, size) pair: stamps that went through the result cache's JSON are lists."""

    def utf8(value: str) -> bytes:
        return value.encode("utf-8", "surrogatepass")

    head = [repr(identity), str(status), str(len(files)), str(len(dirs)), str(len(exist))]
    fields = [utf8(f) for f in head]
    fsencode = os.fsencode  # (a path's own bytes, even one that is not UTF-8)
    for path, stamp in files:
        fields += (fsencode(path), b"-" if stamp is None else b"%d %d" % tuple(stamp))
    for path, mtime in dirs:
        fields += (fsencode(path), b"-" if mtime is None else b"%d" % mtime)
    for path, there in exist:
        fields += (fsencode(path), b"1" if there else b"0")
    fields.append(utf8(text))
    return b"\0".join(fields)


class _Entry:
    """A decoded entry: its paths and stamps still the bytes the file holds (``os.stat``
    takes bytes paths, and the stamps are compared as the text they are written as)."""

    __slots__ = ("counts", "fields", "identity", "status", "text")

    def __init__(self, identity: bytes, status: int, fields: list, counts: tuple, text: str):
        self.identity = identity
        self.status = status
        self.fields = fields
        self.counts = counts
        self.text = text


def _entry(folder: Folder, argv: list[str]) -> _Entry | None:
    """The sealed entry for ``argv``, when it has the layout this version writes."""
    body = folder.read(entry_name(argv))
    if body is None:
        return None
    head = body.split(b"\0", _HEAD)
    if len(head) != _HEAD + 1 or head[1] not in (b"0", b"1"):
        return None
    counts = tuple(int(n) for n in head[2:_HEAD])  # (ValueError: a miss, as any exception)
    if min(counts) < 0:
        return None
    stamps = 2 * sum(counts)
    fields = head[_HEAD].split(b"\0", stamps) if stamps else [head[_HEAD]]
    if len(fields) != stamps + 1:
        return None
    text = fields.pop().decode("utf-8", "surrogatepass")
    return _Entry(head[0], int(head[1]), fields, counts, text)


def _holds(entry: _Entry, argv: list[str]) -> bool:
    """Whether every file, folder and presence the entry records is as it was."""
    if entry.identity != repr(identity(argv)).encode("utf-8", "surrogatepass"):
        return False
    fields = entry.fields
    nfiles, ndirs, nexist = entry.counts
    stat = os.stat  # (``file_stamp``, inlined: this loop runs over thousands of files)
    end = 2 * nfiles
    for i in range(0, end, 2):
        want = fields[i + 1]
        try:
            st = stat(fields[i])
        except OSError:
            if want != b"-":
                return False
            continue
        if want != b"%d %d" % (st.st_mtime_ns, st.st_size):
            return False
    start, end = end, end + 2 * ndirs
    for i in range(start, end, 2):
        mtime = folder_mtime(fields[i])
        if fields[i + 1] != (b"-" if mtime is None else b"%d" % mtime):
            return False
    exists = os.path.exists
    for i in range(end, end + 2 * nexist, 2):
        if fields[i + 1] != (b"1" if exists(fields[i]) else b"0"):
            return False
    return True


def _settings_inputs(paths: list[str]) -> tuple[dict, dict]:
    """The config files (stat or absence) and version-control folders (presence) at and
    above the paths given (the working folder when none is)."""
    files: dict[str, tuple[int, int] | None] = {}
    exist: dict[str, bool] = {}
    seen: set[str] = set()
    for start in paths or ["."]:
        here = os.path.abspath(start)
        while here not in seen:  # (many paths given share their parents)
            seen.add(here)
            for name in CONFIG_FILES:
                files[os.path.join(here, name)] = file_stamp(os.path.join(here, name))
            for name in VCS_MARKERS:
                exist[os.path.join(here, name)] = os.path.exists(os.path.join(here, name))
            parent = os.path.dirname(here)
            if parent == here:
                break
            here = parent
    return files, exist


def remember(
    argv: list[str],
    paths: list[str],
    config: str | None,
    watch: dict,
    text: str,
    status: int,
) -> None:
    """Keep the report of a cached run as a replay entry for the same ``argv`` (the
    result cache's ``watch``: what the result depends on). Never raises."""
    try:
        output_file(argv)  # (a command line the replay cannot read is not kept)
        folder = open_folder(_folder_path(argv), create=True)
        if folder is None:
            return
        files, exist = _settings_inputs(paths)
        own_files, own_dirs = package_stamps(_PACKAGE)  # moos-lint's own code
        files.update(own_files)
        if config is not None:
            files[os.path.abspath(config)] = file_stamp(config)
        for p in paths:
            files[os.path.abspath(p)] = file_stamp(p)
        files.update(watch["files"])
        dirs = {**own_dirs, **watch["dirs"]}
        body = encode(
            identity(argv),
            sorted(files.items()),
            sorted(dirs.items()),
            sorted(exist.items()),
            text,
            status,
        )
        folder.write(entry_name(argv), body)
        prune(folder.path, KEEP)
    except Exception:
        return
