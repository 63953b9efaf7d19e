"""The result cache: a re-run over files that have not changed costs a few stat calls.

The command layer wraps the linter with it (:func:`cached_lint` calls
:func:`moos_lint.core.engine.lint_paths` on a miss); the engine knows nothing of it.

**Trust.** Entries are JSON data in a cache folder of the user's
(:mod:`moos_lint.speed.cache_files`: by default ``$XDG_CACHE_HOME/moos-lint/``, in
a subfolder named by a hash of the project root's real path), each sealed
with an HMAC-SHA256 under the user's key, which lives outside every
repository. An entry that is not sealed under that key, that git tracks,
that does not parse, or whose values do not have the layout this version
writes (:mod:`moos_lint.speed.cache_codec`) is a miss: the run lints afresh. Nothing
read from an entry is ever run; the worst a damaged entry can do is cost a
re-lint. ``--no-cache`` neither reads nor writes the cache.

**What is stored.** One entry per *run*: the result of linting a given list of
files with given settings (the findings, the count of internal errors, and the
text of the files the findings point into, for the text output and
baselines).

**The key** is a hash of the moos-lint version (and, for a development
install, the size and mtime of each of its own source files), the settings
(``--show-settings``: selection, options, defines, include paths, ...), the
paths given, ``--context``, and the sorted list of files the run lints (after
discovery, so a new or deleted mission file is a different key).

**When an entry is valid.** The entry records every file the run read: the
linted files, every file an ``#include`` pulled in, behavior files and sibling
missions the mission model opened, the C++ files (also the ones the prefilter
skipped), the scripts beside the missions (``uPokeDB`` lines, the names a
launched script quotes), the
``CMakeLists.txt`` that names a C++ app's process, and user catalogues. For
each it keeps the modification time and size *from just before the run read
it* and a hash of the bytes it read (:func:`moos_lint.files.source.keep_journal`).
An entry is used only when every file still has the same (mtime, size), or,
when that changed (a ``touch``, a checkout), the same content hash. It also
records the modification time of every folder those files sit in, of the
include paths, and of the folders nsplug searched for an include: a file
created or deleted there (an include that was missing now exists)
invalidates it too. Not seen: a file created outside those folders that only
a project-wide search finds (the repository's C++ file names for
``unknown-behavior``); run once with ``--no-cache`` after such a change.

**Edits during a run.** A file saved while a run goes on (an editor's save
during a pre-commit run) must not be stored with findings about its older
text. So a result is stored only when every file it read still holds the
bytes the run read, and every folder known before the run (the linted files'
folders, the include paths) still has the time it had then; otherwise
nothing is stored and the next run lints again.

**Lighter entries** make an unchanged run cheaper still. The list of
files discovery found is kept with the modification time of every folder it
walked, taken before the folder was listed (adding, removing or renaming a
file changes its folder's), and the (mtime, size) of every ignore file that
decided it (``.gitignore``, ``.ignore``, ``info/exclude``, the user's git
config and global excludes, or their absence), and reused while they hold. And the report a
cached result was rendered to is kept, named by the run entry it came from (a
random token written with that entry) and by how it was rendered (format,
``--statistics``, ``--quiet``, working folder): once the run entry is
validated, that text is printed again without decoding the findings. The run
entry keeps its header (key, token, dependencies) on its first line, so
validating it decodes no finding. Last, each report printed is kept as a
replay entry (:mod:`moos_lint.speed.replay`), which the next identical command line
checks and prints before argparse loads.

There is no finer, per-file reuse: findings cross files (a mission joins the
C++ apps it launches, its behavior files and its sibling missions;
``unused-suppression`` needs every finding), so a changed file re-lints the
whole run. The language server does not use this cache.

**Safety.** An entry is written to a temporary file and moved into place with
:func:`os.replace`, so two runs that overlap never see half an entry; a cache
folder that cannot be written is silently not used. Nothing is written
outside the cache folder.
"""

from __future__ import annotations

import contextlib
import json
import os
from pathlib import Path

import moos_lint
from moos_lint import __version__
from moos_lint.files.gitignore import FOLDER_FILES
from moos_lint.files.stamps import file_stamp, folder_mtime, package_stamps
from moos_lint.files.suffixes import SCRIPT_SUFFIXES, is_cpp
from moos_lint.speed.cache_codec import BadEntry, decode_result, encode_result, want, want_list
from moos_lint.speed.cache_files import (
    Folder,
    command_line_folder,
    open_folder,
    project_folder,
    prune,
)

TYPE_CHECKING = False  # typing itself is not imported at run time
if TYPE_CHECKING:
    from typing import Any

    from moos_lint.commands.progress import Progress
    from moos_lint.core.config import Settings
    from moos_lint.core.result import Result

#: bump when the entry layout changes
FORMAT = 3
_PACKAGE = os.path.dirname(os.path.abspath(moos_lint.__file__))


def cache_folder(settings: Settings, paths: list[Path], command_line: str | None) -> Folder | None:
    """The run's cache folder (made when missing), or None when there is none to use.

    ``--cache-dir`` (``command_line``) or ``$MOOS_LINT_CACHE_DIR`` may name any
    folder; a ``cache-dir`` from the configuration lies inside the project root
    (:mod:`moos_lint.core.config` refuses any other); else the user's cache folder.
    """
    from moos_lint.files.project import project_root, real_within

    given = command_line_folder(command_line)
    if given:
        return open_folder(given, create=True, gitignore=True)
    root = project_root([str(p) for p in paths], settings.config_path)
    configured = settings.cache_dir
    if configured:
        if not real_within(configured, root):  # (the config loader already refused it)
            return None
        return open_folder(configured, create=True, gitignore=True)
    return open_folder(project_folder(root), create=True)


def _code_fingerprint() -> list:
    """The version, where moos-lint lives, and each of its own files' (name, stamp)."""
    files, _folders = package_stamps(_PACKAGE)
    return [
        __version__,
        FORMAT,
        _PACKAGE,
        *((os.path.relpath(p, _PACKAGE), st) for p, st in files.items()),
    ]


def _hash(data: Any) -> str:
    from hashlib import sha256

    text = json.dumps(data, sort_keys=True, default=str)
    return sha256(text.encode("utf-8", "surrogatepass")).hexdigest()[:40]


def run_key(settings: Settings, paths: list[Path], files: list[str], context: bool) -> str:
    # the selected rules follow from the selection settings and moos-lint's own code
    return _hash(
        {
            "code": _code_fingerprint(),
            "settings": _settings_dict(settings),
            "paths": [os.path.abspath(p) for p in paths],
            "context": context,
            "files": files,
        }
    )


def _settings_dict(settings: Settings) -> dict:
    """Every setting (rule option defaults come with the code), without loading the rules."""
    return {k: v for k, v in vars(settings).items() if not k.startswith("_")}


def _digest(path: str) -> str:
    """A hash of the file's bytes now (see :func:`moos_lint.files.source.content_digest`)."""
    from moos_lint.files.source import digest_now

    return digest_now(path)


def _side_files(files: list[str], settings: Settings) -> set[str]:
    """Files the analysis of ``files`` opens outside the safe reader's journal."""
    out: set[str] = set(settings.catalogues)
    cc = settings.compile_commands
    if cc:
        out.add(os.path.join(cc, "compile_commands.json") if os.path.isdir(cc) else cc)
    top = os.path.abspath(settings.project_root or settings.root)
    for d in {os.path.dirname(p) for p in files if not is_cpp(p)}:
        # shell scripts (uPokeDB lines, the files a launch makes) and the scripts missions
        # launch (what they quote), beside the file and in its `scripts` folder; the
        # launch scripts of the folder above, which may run nsplug on a template of this
        # one (files.launch.nsplug_working_folders), when that folder is in the project
        where = [d, os.path.join(d, "scripts")]
        parent = os.path.normpath(os.path.join(d, os.pardir))
        above = os.path.abspath(parent)
        if above == top or above.startswith(top + os.sep):
            where.append(parent)
        # the ignore files of the folder and those above it, up to the project root:
        # missing-behavior-file leaves out a file they ignore
        here = os.path.abspath(d)
        while here == top or here.startswith(top + os.sep):
            out.update(os.path.join(here, n) for n in FOLDER_FILES)
            if here == top:
                break
            here = os.path.dirname(here)
        for folder in where:
            try:
                names = os.listdir(folder)
            except OSError:
                continue
            out.update(
                os.path.join(folder, n) for n in names if n.lower().endswith(SCRIPT_SUFFIXES)
            )
    for d in {os.path.dirname(p) for p in files if is_cpp(p)}:
        out.add(os.path.join(d, "CMakeLists.txt"))
        out.add(os.path.join(os.path.dirname(d), "CMakeLists.txt"))
    return out


class _Before:
    """What the run's inputs were before it began: the side files (stamp and hash) and
    the folders known from the start (mtime)."""

    def __init__(self, files: list[str], settings: Settings) -> None:
        self.files = {p: (file_stamp(p), _digest(p)) for p in _side_files(files, settings)}
        dirs = {os.path.dirname(p) for p in files}
        dirs.update(settings.include_paths)
        self.dirs = {d: folder_mtime(d) for d in dirs}


def _dependencies(
    result: Any, settings: Settings, journal: dict, before: _Before, probed: set[str]
) -> dict[str, Any] | None:
    """What the result depends on, as it was when the run read it; None when a file or
    a folder changed during the run (the result must not be stored)."""
    files = set(journal) | set(result.files) | set(result.sources)
    files |= _side_files(result.files, settings)
    deps: dict[str, list] = {}
    for path in sorted(files):
        noted = journal.get(path) or before.files.get(path)
        now = _digest(path)
        if noted is None:  # opened outside the journal and unknown before the run
            deps[path] = [file_stamp(path), now]
            continue
        stamp, digest = noted
        if now != digest:
            return None  # changed since the run read it
        deps[path] = [list(stamp) if stamp is not None else None, digest]
    dirs = {os.path.dirname(p) for p in files}
    dirs.update(settings.include_paths)
    dirs.update(probed)
    out_dirs = {}
    for d in sorted(dirs):
        mtime = folder_mtime(d)
        if d in before.dirs and before.dirs[d] != mtime:
            return None  # a file was added or removed there during the run
        out_dirs[d] = mtime
    return {"files": deps, "dirs": out_dirs}


def _check_deps(deps: Any) -> dict:
    want(deps, dict, "dependencies")
    files = want(deps.get("files"), dict, "dependency files")
    dirs = want(deps.get("dirs"), dict, "dependency folders")
    for entry in files.values():
        stamp, digest = want_list(entry, "dependency", 2)
        want(digest, str, "digest")
        if stamp is not None:
            for n in want_list(stamp, "stamp", 2):
                want(n, int, "stamp")
    for mtime in dirs.values():
        if mtime is not None:
            want(mtime, int, "folder time")
    return deps


def _valid(deps: dict) -> dict | None:
    """The (mtime, size) each file of a valid entry has now (a touched file whose content
    is the same keeps the entry valid), or None when the entry no longer holds."""
    for d, mtime in deps["dirs"].items():
        if folder_mtime(d) != mtime:
            return None
    seen = {}
    for path, (st, digest) in deps["files"].items():
        now = file_stamp(path)
        if (list(now) if now is not None else None) != st and _digest(path) != digest:
            return None
        seen[path] = now
    return seen


def _run_name(key: str) -> str:
    return f"run-{key}.json"


def _valid_header(folder: Folder, key: str) -> tuple[dict, bytes] | None:
    """The entry for ``key`` when it is there, sealed and still valid: its header (with
    ``watch``: the stats that validated it, see :func:`_watch`) and the rest of the
    entry, not decoded."""
    body = folder.read(_run_name(key))
    if body is None:
        return None
    first, _, rest = body.partition(b"\n")
    header = want(json.loads(first), dict, "header")
    if header.get("key") != key or not isinstance(header.get("token"), str):
        return None
    seen = _valid(_check_deps(header.get("deps")))
    if seen is None:
        return None
    header["watch"] = {"files": seen, "dirs": dict(header["deps"]["dirs"])}
    return header, rest


def _watch(watch: dict, walked: dict) -> dict:
    """What a result depends on, in stat terms: each file's (mtime, size) and each
    folder's mtime (the run entry's ``watch``, and the folders discovery walked and
    the ignore files that decided it: ``walked``, from :func:`_discover`).
    :mod:`moos_lint.speed.replay` checks these before anything else loads."""
    return {
        "files": {**watch["files"], **walked["files"]},
        "dirs": {**watch["dirs"], **walked["dirs"]},
    }


def load(folder: Folder, key: str) -> Any | None:
    """The stored result for ``key`` when it is still valid, else None (never raises)."""
    try:
        found = _valid_header(folder, key)
        if found is None:
            return None
        header, rest = found
        result = decode_result(json.loads(rest))
        result.cache_token = header["token"]
        result.cache_watch = header["watch"]
        return result
    except Exception:  # a partial, corrupt or foreign entry is a cache miss
        return None


def store(
    folder: Folder,
    key: str,
    result: Result,
    settings: Settings,
    journal: dict,
    before: _Before,
    probed: set[str],
) -> None:
    """Write the entry for ``key``, unless an input changed during the run; a folder
    that cannot be written is skipped."""
    keep = {d.span.path for d in result.diagnostics}
    for d in result.diagnostics:
        keep.update(site.path for site in d.chain)
    try:
        deps = _dependencies(result, settings, journal, before, probed)
        if deps is None:
            return
        token = os.urandom(12).hex()  # names this very entry (outputs refer to it)
        header = {"key": key, "token": token, "deps": deps}
        # the header first: a run that only validates the entry decodes no finding
        body = (
            json.dumps(header).encode() + b"\n" + json.dumps(encode_result(result, keep)).encode()
        )
        folder.write(_run_name(key), body)
        result.cache_token = token
        result.cache_watch = {
            "files": {p: tuple(st) if st else None for p, (st, _d) in deps["files"].items()},
            "dirs": dict(deps["dirs"]),
        }
        prune(folder.path)
    except Exception:
        return


def _output_name(token: str, render_key: str, missing: list[str]) -> str:
    return f"out-{token}-{_hash([render_key, sorted(missing)])[:24]}.json"


def store_output(folder: Folder, result: Any, render_key: str, text: str, has_findings: bool):
    """Keep the report rendered from a cached result (``render_key``: how it was rendered:
    format, options, working folder), so that an unchanged run prints it again as is."""
    token = getattr(result, "cache_token", None)
    if not token:
        return
    entry = {"render_key": render_key, "text": text, "has_findings": has_findings}
    try:
        folder.write(_output_name(token, render_key, result.missing), json.dumps(entry).encode())
        prune(folder.path)
    except Exception:
        return


def cached_output(
    paths: list[Path], settings: Settings, *, context: bool, folder: Folder, render_key: str
) -> tuple[str, bool, dict] | None:
    """The report an unchanged run printed, rendered the same way: (text, has findings,
    what it depends on (see :func:`_watch`)).

    The run's entry is validated as :func:`cached_lint` does; the findings are
    never decoded, nor is the report rendered again.
    """
    try:
        found, walked = _discover(paths, settings, folder)
        key = run_key(settings, paths, found.files, context)
        valid = _valid_header(folder, key)
        if valid is None:
            return None
        header = valid[0]
        body = folder.read(_output_name(header["token"], render_key, found.missing))
        if body is None:
            return None
        entry = want(json.loads(body), dict, "report")
        if set(entry) != {"render_key", "text", "has_findings"}:
            return None
        if entry["render_key"] != render_key:
            return None
        text = want(entry["text"], str, "report text")
        has_findings = want(entry["has_findings"], bool, "report status")
        return text, has_findings, _watch(header["watch"], walked)
    except Exception:  # no entry, a changed run, or a corrupt file: render afresh
        return None


def _discover(paths: list[Path], settings: Settings, folder: Folder) -> tuple[Any, dict]:
    """:func:`moos_lint.files.discovery.discover`, reused while no folder it looked in changed;
    and what it depends on: ``{"dirs": the mtime of each folder it walked, "files": the
    stamp of each ignore file that decided (None: absent)}``.

    Adding, removing or renaming a file changes its folder's modification
    time, so the stored list holds while every walked folder (and the folder of
    every path given) keeps the time it had before it was listed, and every
    ignore file its stamp.
    """
    from moos_lint.files.discovery import Discovered, discover

    key = _hash(
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
    name = f"files-{key}.json"
    try:
        entry = _check_files_entry(json.loads(folder.read(name) or b"null"), key)
        if (
            entry is not None
            and all(folder_mtime(d) == m for d, m in entry["folders"].items())
            and all(_stamp_list(f) == m for f, m in entry["ignore"].items())
        ):
            found = Discovered(list(entry["files"]), list(entry["missing"]), entry["folders"])
            found.ignore_files = list(entry["ignore"])
            return found, {"dirs": dict(entry["folders"]), "files": dict(entry["ignore"])}
    except (ValueError, BadEntry):  # partial, corrupt or foreign: walk the folders
        pass
    found = discover(paths, settings.exclude, settings.root, settings.respect_gitignore)
    ignore = {f: _stamp_list(f) for f in found.ignore_files}
    if all(m is not None for m in found.folders.values()):
        entry = {
            "key": key,
            "folders": found.folders,
            "ignore": ignore,
            "files": found.files,
            "missing": found.missing,
        }
        with contextlib.suppress(Exception):
            folder.write(name, json.dumps(entry).encode())
    return found, {"dirs": dict(found.folders), "files": ignore}


def _stamp_list(path: str) -> list[int] | None:
    """:func:`moos_lint.files.stamps.file_stamp` as JSON keeps it."""
    st = file_stamp(path)
    return None if st is None else list(st)


def _check_files_entry(entry: Any, key: str) -> dict | None:
    if entry is None:
        return None
    want(entry, dict, "file list")
    if set(entry) != {"key", "folders", "ignore", "files", "missing"} or entry["key"] != key:
        return None
    for mtime in want(entry["folders"], dict, "folders").values():
        want(mtime, int, "folder time")
    for stamp in want(entry["ignore"], dict, "ignore files").values():
        if stamp is not None:
            for n in want_list(stamp, "ignore file", 2):
                want(n, int, "ignore file")
    for name in ("files", "missing"):
        for p in want_list(entry[name], name):
            want(p, str, name)
    return entry


def cached_lint(
    paths: list[Path],
    settings: Settings,
    *,
    context: bool,
    jobs: int | None,
    folder: Folder,
    progress: Progress | None = None,
) -> Result:
    """:func:`moos_lint.core.engine.lint_paths` through the cache."""
    found, walked = _discover(paths, settings, folder)
    key = run_key(settings, paths, found.files, context)
    hit = load(folder, key)
    if hit is not None:
        hit.missing = list(found.missing)
        hit.cache_watch = _watch(hit.cache_watch, walked)
        return hit
    from moos_lint.core.engine import lint_paths  # the parsers and rules: only on a miss
    from moos_lint.files import source
    from moos_lint.frontends.nsplug import FileCache
    from moos_lint.speed import parallel

    reader = FileCache()
    before = _Before(found.files, settings)
    source.keep_journal()
    try:
        result = lint_paths(
            paths,
            settings,
            context=context,
            cache=reader,
            jobs=jobs,
            progress=progress,
            parallel=parallel,
        )
    finally:
        journal = source.take_journal()
    if not result.internal_errors:  # a crash is never replayed from the cache
        store(folder, key, result, settings, journal, before, reader.probed)
        if result.cache_watch is not None:
            result.cache_watch = _watch(result.cache_watch, walked)
    return result


__all__ = [
    "cache_folder",
    "cached_lint",
    "cached_output",
    "load",
    "run_key",
    "store",
    "store_output",
]
