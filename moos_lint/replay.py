"""Replaying an unchanged ``moos-lint check`` before anything else loads.

A warm run must cost little more than starting Python. The result cache
(:mod:`moos_lint.cache`) already prints an unchanged run's report again
without loading the parsers or the rules, but it still parses the command
line, resolves the settings and validates its entries, and the modules that
takes (argparse, pathlib, hashlib, pickle, json) cost more than the checks
themselves. So each report the cache prints is also kept as a *replay
entry*: the exact command line, working folder and environment it answered,
the (mtime, size) of every file it depends on and the mtime of every folder
whose listing it depends on, and the text (printed, or written to the
``--output-file`` again) and exit status. The next identical
command checks those with ``os.stat`` and prints the text; it imports only
``marshal`` and ``zlib``.

**What an entry depends on**, beyond what the run entry records (every file
the lint read, the folders they sit in, the folders discovery walked): the
paths given, moos-lint's own files, and what decides the settings and the
project root: each folder at and above the paths given is checked for the
config files (their (mtime, size), or their absence) and for the
version-control folders (their presence). The environment variables moos-lint
reads and the folder moos-lint is installed in are part of the entry's
identity (another checkout of the same version is another program).

**Where it is found.** An entry lives in the cache folder of the run that
wrote it. Without parsing the command line, the replay looks in
``$MOOS_LINT_CACHE_DIR``, in the folder a ``--cache-dir`` names, and in the
``.moos_lint_cache`` folders at and above each argument that names an
existing path (else the working folder), nearest first. A cache folder that a
config file sets elsewhere is not found: such a run is replayed one step
later, by the result cache.

Anything unexpected (no entry, another command line, a changed file, an
unreadable or corrupt entry) falls through to the normal run, which writes a
fresh entry. :func:`replay` writes nothing but the ``--output-file`` the
command line names; :func:`remember`, called by the normal run, writes only
in the cache folder.
"""

from __future__ import annotations

import marshal
import os
import sys

import moos_lint
from moos_lint import __version__
from moos_lint.markers import CACHE_DIR, CONFIG_FILES, VCS_MARKERS
from moos_lint.stamps import file_stamp, folder_mtime, package_stamps

#: bump when the entry layout changes
FORMAT = 1
#: the environment variables a check run reads
ENV = (
    "GITHUB_ACTIONS",
    "MOOS_LINT_CACHE_DIR",
    "HOME",
    "XDG_CONFIG_HOME",
    "NO_COLOR",
    "FORCE_COLOR",
)
_PACKAGE = os.path.dirname(os.path.abspath(moos_lint.__file__))


def identity(argv: list[str]) -> list:
    """What an entry must have been written for: version, where moos-lint is installed
    (two checkouts of one version are two programs), interpreter, command line, working
    folder and environment."""
    return [
        __version__,
        FORMAT,
        _PACKAGE,
        sys.version,
        list(argv),
        os.getcwd(),
        [os.environ.get(k) for k in ENV],
        os.isatty(1),  # (``--color auto``)
    ]


def entry_name(argv: list[str]) -> str:
    import zlib

    data = "\0".join(argv).encode("utf-8", "surrogatepass")
    return f"replay-{zlib.crc32(data):08x}.marshal"


def _candidates(argv: list[str]) -> list[str]:
    """The cache folders an entry for ``argv`` may be in, most likely first."""
    out = []
    env = os.environ.get("MOOS_LINT_CACHE_DIR")
    if env:
        out.append(os.path.abspath(env))
    starts = []
    for i, arg in enumerate(argv):
        if arg == "--cache-dir" and i + 1 < len(argv):
            out.append(os.path.abspath(argv[i + 1]))
        elif arg.startswith("--cache-dir="):
            out.append(os.path.abspath(arg.split("=", 1)[1]))
        elif not arg.startswith("-") and os.path.exists(arg):
            starts.append(arg)
    seen: set[str] = set()
    for start in starts or ["."]:
        here = os.path.abspath(start)
        if not os.path.isdir(here):
            here = os.path.dirname(here)
        while here not in seen:
            seen.add(here)
            cache = os.path.join(here, CACHE_DIR)
            if os.path.isdir(cache):
                out.append(cache)
            parent = os.path.dirname(here)
            if parent == here:
                break
            here = parent
    return list(dict.fromkeys(out))


def replay(argv: list[str]) -> int | None:
    """Print the report of an unchanged run of ``moos-lint`` with ``argv`` and return its
    exit status; None (having printed nothing) when there is no valid entry."""
    try:
        name = entry_name(argv)
        for folder in _candidates(argv):
            try:
                with open(os.path.join(folder, name), "rb") as fh:
                    entry = marshal.load(fh)
            except OSError:
                continue
            if _holds(entry, argv):
                target = entry.get("output_file")
                if target is None:
                    sys.stdout.write(entry["text"])
                else:  # ``--output-file``: written as the normal run writes it
                    with open(target, "w", encoding="utf-8") as fh:
                        fh.write(entry["text"])
                return int(entry["status"])
    except Exception:  # a corrupt or foreign entry: the normal run decides
        return None
    return None


def _holds(entry: dict, argv: list[str]) -> bool:
    if entry.get("identity") != identity(argv):
        return False
    stat = os.stat  # (``file_stamp``, inlined: this loop runs over thousands of files)
    for path, want in entry["files"]:
        try:
            st = stat(path)
        except OSError:
            if want is not None:
                return False
            continue
        if want is None or st.st_mtime_ns != want[0] or st.st_size != want[1]:
            return False
    for path, want in entry["dirs"]:
        if folder_mtime(path) != want:
            return False
    exists = os.path.exists
    return all(exists(path) == want for path, want in entry["exist"])


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
    cache_dir: str,
    argv: list[str],
    paths: list[str],
    config: str | None,
    watch: dict,
    text: str,
    status: int,
    output_file: str | None = None,
) -> None:
    """Keep the report of a cached run as a replay entry for the same ``argv`` (the
    result cache's ``watch``: what the result depends on; ``output_file``: where the
    report was written, None for stdout). Never raises."""
    try:
        files, exist = _settings_inputs(paths)
        own_files, own_dirs = package_stamps(_PACKAGE)  # moos-lint's own code
        files.update(own_files)
        if config is not None:
            files[os.path.abspath(config)] = file_stamp(config)
        for p in paths:
            files[os.path.abspath(p)] = file_stamp(p)
        files.update(watch["files"])
        dirs = {**own_dirs, **watch["dirs"]}
        entry = {
            "identity": identity(argv),
            "files": sorted(files.items()),
            "dirs": sorted(dirs.items()),
            "exist": sorted(exist.items()),
            "text": text,
            "status": status,
            "output_file": output_file,
        }
        from moos_lint.cache import atomic_write, prune

        atomic_write(cache_dir, os.path.join(cache_dir, entry_name(argv)), marshal.dumps(entry))
        prune(cache_dir)
    except Exception:
        return
