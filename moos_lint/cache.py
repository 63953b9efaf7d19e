"""The result cache: a re-run over files that have not changed costs a few stat calls.

**What is stored.** One entry per *run*: the result of linting a given list of
files with given settings (the findings, the count of internal errors, and the
text of the files the findings point into, for the text output and
baselines). It lives in ``.moos_lint_cache/`` in the project root (the
config's folder, else the linted folder), or in the folder the ``cache-dir``
setting names; ``--no-cache`` neither reads nor writes it.

**The key** is a hash of the moos-lint version (and, for a development
install, the size and mtime of each of its own source files), the settings
(``--show-settings``: selection, options, defines, include paths, ...), the
paths given, ``--context``, and the sorted list of files the run lints (after
discovery, so a new or deleted mission file is a different key).

**When an entry is valid.** The entry records every file the run read: the
linted files, every file an ``#include`` pulled in, behavior files and sibling
missions the mission model opened, the C++ files (also the ones the prefilter
skipped), the shell scripts beside the missions (``uPokeDB`` lines), the
``CMakeLists.txt`` that names a C++ app's process, and user catalogues. For
each it keeps the modification time, the size and a hash of the content. An
entry is used only when every file still has the same (mtime, size), or, when
that changed (a ``touch``, a checkout), the same content hash. It also records
the modification time of every folder those files sit in, of the include
paths, and of the folders nsplug searched for an include: a file created or
deleted there (an include that was missing now exists) invalidates it too.
Not seen: a file created outside those folders that only a project-wide
search finds (the repository's C++ file names for ``unknown-behavior``);
run once with ``--no-cache`` after such a change.

**Lighter entries** make an unchanged run cheaper still. The list of
files discovery found is kept with the modification time of every folder it
walked (adding, removing or renaming a file changes its folder's) and the
(mtime, size) of every ignore file that decided it (``.gitignore``, ``.ignore``,
``info/exclude``, the user's git config and global excludes, or their absence),
and reused while they hold. And the report a cached result was rendered to is kept, named
by the run entry it came from (a random token written with that entry) and by
how it was rendered (format, ``--statistics``, ``--quiet``, working folder, the
paths that do not exist): once the run entry is validated, that text is
printed again without unpickling the findings. The run entry keeps its header
(key, token, dependencies) first, so validating it reads no finding. Last,
each report printed is kept as a replay entry (:mod:`moos_lint.replay`), which
the next identical command line checks and prints before argparse loads.

There is no finer, per-file reuse: findings cross files (a mission joins the
C++ apps it launches, its behavior files and its sibling missions;
``unused-suppression`` needs every finding), so a changed file re-lints the
whole run. The language server does not use this cache.

**Safety.** An entry is written to a temporary file and moved into place with
:func:`os.replace`, so two runs that overlap never see half an entry; an entry
that cannot be read or decoded (partial, corrupt, from another version) is
ignored and rewritten, never an error; a cache folder that cannot be written
is silently not used. Nothing is written outside the cache folder.
"""

from __future__ import annotations

import contextlib
import glob
import hashlib
import json
import os
import pickle
from pathlib import Path

import moos_lint
from moos_lint import __version__
from moos_lint.markers import CACHE_DIR
from moos_lint.stamps import file_stamp, folder_mtime, package_stamps
from moos_lint.suffixes import is_cpp

TYPE_CHECKING = False  # typing itself is not imported at run time
if TYPE_CHECKING:
    from typing import Any

    from moos_lint.config import Settings
    from moos_lint.progress import Progress
    from moos_lint.result import Result

ENV_VAR = "MOOS_LINT_CACHE_DIR"
#: bump when the entry layout changes
FORMAT = 2
#: entries kept (one per distinct run: paths, settings, moos-lint version)
KEEP = 8
_PACKAGE = os.path.dirname(os.path.abspath(moos_lint.__file__))


def cache_dir_for(settings: Settings) -> str:
    """The cache folder: ``$MOOS_LINT_CACHE_DIR``, the ``cache-dir`` setting, else
    ``.moos_lint_cache`` in the root (``--cache-dir`` overrides them all)."""
    configured = os.environ.get(ENV_VAR) or settings.cache_dir
    if configured:
        return os.path.abspath(configured)
    return os.path.join(os.path.abspath(settings.root), CACHE_DIR)


def _code_fingerprint() -> list:
    """The version, and each of moos-lint's own files' (name, (mtime, size))."""
    files, _folders = package_stamps(_PACKAGE)
    return [__version__, FORMAT, *((os.path.relpath(p, _PACKAGE), st) for p, st in files.items())]


def run_key(settings: Settings, paths: list[Path], files: list[str], context: bool) -> str:
    # the selected rules follow from the selection settings and moos-lint's own code
    data = {
        "code": _code_fingerprint(),
        "settings": _settings_dict(settings),
        "paths": [os.path.abspath(p) for p in paths],
        "context": context,
        "files": files,
    }
    text = json.dumps(data, sort_keys=True, default=str)
    return hashlib.sha256(text.encode("utf-8", "surrogatepass")).hexdigest()[:40]


def _settings_dict(settings: Settings) -> dict:
    """Every setting (rule option defaults come with the code), without loading the rules."""
    return {k: v for k, v in vars(settings).items() if not k.startswith("_")}


def _digest(path: str) -> str:
    """A hash of the file's bytes; for a file that cannot be read (a FIFO, a device, a
    file too large, a missing one), why it cannot: the safe reader never blocks."""
    from moos_lint.source import read_bytes

    data = read_bytes(Path(path))
    if not isinstance(data, bytes):
        return f"unread:{data.kind}"
    return hashlib.blake2b(data, digest_size=20).hexdigest()


def _side_files(result: Result, settings: Settings) -> set[str]:
    """Files the analysis opens outside the nsplug reader."""
    out: set[str] = set(settings.catalogues)
    cc = settings.compile_commands
    if cc:
        out.add(os.path.join(cc, "compile_commands.json") if os.path.isdir(cc) else cc)
    moos_dirs = {os.path.dirname(p) for p in result.files if not is_cpp(p)}
    for d in moos_dirs:
        out.update(glob.glob(os.path.join(glob.escape(d), "*.sh")))
    cpp_dirs = {os.path.dirname(p) for p in result.files if is_cpp(p)}
    for d in cpp_dirs:
        for cm in (
            os.path.join(d, "CMakeLists.txt"),
            os.path.join(os.path.dirname(d), "CMakeLists.txt"),
        ):
            out.add(cm)
    return out


def _dependencies(
    result: Result, settings: Settings, read: set[str], probed: set[str]
) -> dict[str, Any]:
    files = set(read) | set(result.files) | set(result.sources) | _side_files(result, settings)
    deps = {}
    for path in sorted(files):
        deps[path] = (file_stamp(path), _digest(path))
    dirs = {os.path.dirname(p) for p in files}
    dirs.update(settings.include_paths)
    dirs.update(probed)
    return {"files": deps, "dirs": {d: folder_mtime(d) for d in sorted(dirs)}}


def _valid(entry: dict) -> dict | None:
    """The (mtime, size) each file of a valid entry has now (a touched file whose content
    is the same keeps the entry valid), or None when the entry no longer holds."""
    deps = entry["deps"]
    for d, mtime in deps["dirs"].items():
        if folder_mtime(d) != mtime:
            return None
    seen = {}
    for path, (st, digest) in deps["files"].items():
        now = file_stamp(path)
        if now != st and _digest(path) != digest:
            return None
        seen[path] = now
    return seen


def _valid_header(fh: Any, key: str) -> dict | None:
    """The entry's header (key, token, dependencies) when it is for ``key`` and still
    valid; its ``watch`` holds the stats that validated it (see :func:`_watch`)."""
    header = pickle.load(fh)
    if not isinstance(header, dict) or header.get("key") != key:
        return None
    seen = _valid(header)
    if seen is None:
        return None
    header["watch"] = {"files": seen, "dirs": dict(header["deps"]["dirs"])}
    return header


def _watch(watch: dict, walked: dict) -> dict:
    """What a result depends on, in stat terms: each file's (mtime, size) and each
    folder's mtime (the run entry's ``watch``, and the folders discovery walked and
    the ignore files that decided it: ``walked``, from :func:`_discover`).
    :mod:`moos_lint.replay` checks these before anything else loads."""
    return {
        "files": {**watch["files"], **walked["files"]},
        "dirs": {**watch["dirs"], **walked["dirs"]},
    }


def load(folder: str, key: str) -> Any | None:
    """The stored result for ``key`` when it is still valid, else None (never raises)."""
    path = os.path.join(folder, f"run-{key}.pickle")
    try:
        with open(path, "rb") as fh:
            header = _valid_header(fh, key)
            if header is None:
                return None
            result = pickle.load(fh)
        result.cache_token = header["token"]
        result.cache_watch = header["watch"]
        return result
    except Exception:  # a missing, partial or corrupt entry is a cache miss
        return None


def store(
    folder: str, key: str, result: Result, settings: Settings, read: set[str], probed: set[str]
) -> None:
    """Write the entry for ``key`` atomically; a folder that cannot be written is skipped."""
    from moos_lint.result import Result

    keep = {d.span.path for d in result.diagnostics}
    for d in result.diagnostics:
        keep.update(site.path for site in d.chain)
    slim = Result(
        diagnostics=result.diagnostics,
        files=result.files,
        internal_errors=result.internal_errors,
        missing=result.missing,
        sources={p: s for p, s in result.sources.items() if p in keep},
        outside=result.outside,
        outside_links=result.outside_links,
    )
    try:
        # first the folder: creating it changes its parent's mtime, which the entry records
        os.makedirs(folder, exist_ok=True)
        ignore = os.path.join(folder, ".gitignore")
        if not os.path.exists(ignore):
            atomic_write(folder, ignore, b"# created by moos-lint\n*\n")
        token = os.urandom(12).hex()  # names this very entry (outputs refer to it)
        deps = _dependencies(result, settings, read, probed)
        header = {"key": key, "token": token, "deps": deps}
        # the header first: a run that only validates the entry never unpickles the findings
        data = pickle.dumps(header, protocol=pickle.HIGHEST_PROTOCOL)
        data += pickle.dumps(slim, protocol=pickle.HIGHEST_PROTOCOL)
        atomic_write(folder, os.path.join(folder, f"run-{key}.pickle"), data)
        result.cache_token = token
        result.cache_watch = {
            "files": {p: st for p, (st, _digest) in deps["files"].items()},
            "dirs": dict(deps["dirs"]),
        }
        prune(folder)
    except Exception:
        return


def _output_path(folder: str, token: str, render_key: str, missing: list[str]) -> str:
    data = json.dumps([render_key, sorted(missing)])
    rkey = hashlib.sha256(data.encode("utf-8", "surrogatepass")).hexdigest()[:24]
    return os.path.join(folder, f"out-{token}-{rkey}.pickle")


def store_output(
    folder: str, result: Result, render_key: str, text: str, has_findings: bool
) -> None:
    """Keep the report rendered from a cached result (``render_key``: how it was rendered:
    format, options, working folder), so that an unchanged run prints it again as is."""
    token = result.cache_token
    if not token:
        return
    entry = {"render_key": render_key, "text": text, "has_findings": has_findings}
    with contextlib.suppress(Exception):
        path = _output_path(folder, token, render_key, result.missing)
        atomic_write(folder, path, pickle.dumps(entry, protocol=pickle.HIGHEST_PROTOCOL))
        prune(folder)


def cached_output(
    paths: list[Path], settings: Settings, *, context: bool, cache_dir: str, render_key: str
) -> tuple[str, bool, dict] | None:
    """The report an unchanged run printed, rendered the same way: (text, has findings,
    what it depends on (see :func:`_watch`)).

    The run's entry is validated as :func:`cached_lint` does; the findings are
    never unpickled, nor is the report rendered again.
    """
    try:
        found, walked = _discover(paths, settings, cache_dir)
        key = run_key(settings, paths, found.files, context)
        with open(os.path.join(cache_dir, f"run-{key}.pickle"), "rb") as fh:
            header = _valid_header(fh, key)
        if header is None:
            return None
        with open(_output_path(cache_dir, header["token"], render_key, found.missing), "rb") as fh:
            entry = pickle.load(fh)
        if not isinstance(entry, dict) or entry.get("render_key") != render_key:
            return None
        return entry["text"], bool(entry["has_findings"]), _watch(header["watch"], walked)
    except Exception:  # no entry, a changed run, or a corrupt file: render afresh
        return None


def prune(folder: str) -> None:
    """Keep the :data:`KEEP` most recently written entries of each kind (runs, file
    lists, reports)."""
    kinds: dict[str, list[tuple[int, str]]] = {}
    for name in os.listdir(folder):
        kind = name.split("-", 1)[0]
        if kind in ("run", "files", "out", "replay") and name.endswith((".pickle", ".marshal")):
            with contextlib.suppress(OSError):
                mtime = os.stat(os.path.join(folder, name)).st_mtime_ns
                kinds.setdefault(kind, []).append((mtime, name))
    for entries in kinds.values():
        for _, name in sorted(entries, reverse=True)[KEEP:]:
            with contextlib.suppress(OSError):
                os.unlink(os.path.join(folder, name))


def atomic_write(folder: str, path: str, data: bytes) -> None:
    import tempfile  # only when an entry is written

    fd, tmp = tempfile.mkstemp(dir=folder, prefix=".tmp-", suffix=".part")
    try:
        with os.fdopen(fd, "wb") as fh:
            fh.write(data)
        os.replace(tmp, path)
    except BaseException:
        with contextlib.suppress(OSError):
            os.unlink(tmp)
        raise


def cached_discover(paths: list[Path], settings: Settings, cache_dir: str) -> Any:
    """:func:`moos_lint.discovery.discover`, reused while no folder it looked in changed.

    Adding, removing or renaming a file changes its folder's modification
    time, so the stored list holds while every walked folder (and the folder of
    every path given) keeps its own.
    """
    return _discover(paths, settings, cache_dir)[0]


def _discover(paths: list[Path], settings: Settings, cache_dir: str) -> tuple[Any, dict]:
    """:func:`cached_discover`, and what it depends on: ``{"dirs": the mtime of each
    folder it walked, "files": the stamp of each ignore file that decided (None: absent)}``.
    """
    from moos_lint.discovery import Discovered, discover

    data = json.dumps(
        [
            __version__,
            FORMAT,
            [os.path.abspath(p) for p in paths],
            settings.exclude,
            os.path.abspath(settings.root),
            settings.respect_gitignore,
            # where the user's git config and global excludes are
            [os.environ.get(k) for k in ("HOME", "XDG_CONFIG_HOME")],
        ]
    )
    key = hashlib.sha256(data.encode("utf-8", "surrogatepass")).hexdigest()[:40]
    path = os.path.join(cache_dir, f"files-{key}.pickle")
    try:
        with open(path, "rb") as fh:
            entry = pickle.load(fh)
        if (
            entry["key"] == key
            and all(folder_mtime(d) == m for d, m in entry["folders"].items())
            and all(file_stamp(f) == m for f, m in entry["ignore"].items())
        ):
            found = Discovered(
                list(entry["files"]), list(entry["missing"]), list(entry["folders"]), []
            )
            found.ignore_files = list(entry["ignore"])
            return found, {"dirs": dict(entry["folders"]), "files": dict(entry["ignore"])}
    except Exception:  # missing, partial or corrupt: walk the folders
        pass
    with contextlib.suppress(OSError):  # first: creating it changes its parent's mtime
        os.makedirs(cache_dir, exist_ok=True)
    found = discover(paths, settings.exclude, settings.root, settings.respect_gitignore)
    folders = {d: folder_mtime(d) for d in found.folders}
    ignore = {f: file_stamp(f) for f in found.ignore_files}
    if all(m is not None for m in folders.values()):
        entry = {
            "key": key,
            "folders": folders,
            "ignore": ignore,
            "files": found.files,
            "missing": found.missing,
        }
        with contextlib.suppress(Exception):
            atomic_write(cache_dir, path, pickle.dumps(entry, protocol=pickle.HIGHEST_PROTOCOL))
    return found, {"dirs": folders, "files": ignore}


def cached_lint(
    paths: list[Path],
    settings: Settings,
    *,
    context: bool,
    jobs: int | None,
    cache_dir: str,
    progress: Progress | None = None,
) -> Result:
    """:func:`moos_lint.engine.lint_paths` through the cache."""
    found, walked = _discover(paths, settings, cache_dir)
    key = run_key(settings, paths, found.files, context)
    hit = load(cache_dir, key)
    if hit is not None:
        hit.missing = list(found.missing)
        hit.cache_watch = _watch(hit.cache_watch, walked)
        return hit
    from moos_lint import parallel
    from moos_lint.engine import lint_paths  # the parsers and rules: only on a miss
    from moos_lint.nsplug import FileCache

    reader = FileCache()
    result = lint_paths(
        paths,
        settings,
        context=context,
        cache=reader,
        jobs=jobs,
        progress=progress,
        parallel=parallel,
    )
    if not result.internal_errors:  # a crash is never replayed from the cache
        store(cache_dir, key, result, settings, reader.paths(), reader.probed)
        if result.cache_watch is not None:
            result.cache_watch = _watch(result.cache_watch, walked)
    return result


__all__ = [
    "CACHE_DIR",
    "atomic_write",
    "cache_dir_for",
    "cached_lint",
    "cached_output",
    "load",
    "prune",
    "run_key",
    "store",
    "store_output",
]
