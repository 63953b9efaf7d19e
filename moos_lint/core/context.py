"""Mission context: lint a changed fragment inside the missions that use it.

A ``.plug`` fragment or a ``.bhv`` file is only half a program: mission rules
(duplicate processes, blocks nobody launches, ...) can only judge it inside the
``.moos`` missions that ``#include`` it or hand it to the helm. Tools that pass
only the changed files (pre-commit, an editor on save) use
``moos-lint check --context FILES``: the engine then also lints every mission
under the project root that uses one of the files, and keeps only the findings
located in the given files or in those missions.

A mission *uses* a file when

* its nsplug expansion includes the file (``#include``, at any depth), or
* one of its pHelmIvP blocks names a behavior file (``behaviors = FILE``,
  relative to the mission's folder; a still-unknown ``$(MACRO)`` matches any
  text) that is the file or whose own expansion includes it. A behavior file
  that a launch script writes (``targ_$(VNAME).bhv`` made by nsplug from
  ``meta_vehicle.bhv``) links its template only when a generated file exists.

The project root is the one :mod:`moos_lint.files.project` defines: the folder of
the configuration file in use; without one, the nearest folder above the
first given path holding ``.git``, ``.hg`` or ``.svn``; otherwise the working
folder when the given paths lie under it, else their deepest common folder.
"""

from __future__ import annotations

import fnmatch
import os
import re
from collections.abc import Iterable
from pathlib import Path

TYPE_CHECKING = False  # typing itself is not imported at run time

if TYPE_CHECKING:  # the parsers are imported by the functions that read missions
    from moos_lint.core.config import Settings
    from moos_lint.frontends.nsplug import FileCache

_MACRO = re.compile(r"[$%]\([^)]*\)")


def project_root(
    settings: Settings, paths: Iterable[str | os.PathLike] = (), fallback: str | None = None
) -> str:
    """The project root (:func:`moos_lint.files.project.project_root`) of a run over ``paths``
    with ``settings``; ``fallback`` stands for the working folder (a baseline outside
    any project is relative to its own folder)."""
    from moos_lint.files.project import project_root as root_of

    return root_of(list(paths), settings.config_path, cwd=fallback)


def _norm(path: str) -> str:
    return os.path.normpath(os.path.abspath(path))


def _behavior_files(moos, mission_dir: str) -> list[str]:
    """The (possibly glob) paths named by ``behaviors =`` in the mission's helm blocks."""
    out: list[str] = []
    for block in moos.blocks:
        if not block.lname.startswith("phelmivp"):
            continue
        for param in block.get("behaviors"):
            value = param.value.strip()
            if value:
                out.append(_norm(os.path.join(mission_dir, _MACRO.sub("*", value))))
    return out


def related_missions(
    files: list[str], settings: Settings, cache: FileCache | None = None
) -> list[str]:
    """The missions under the project root that use one of ``files`` (absolute paths).

    Files that are missions themselves are not looked up again; only
    fragments (files without an ANTLER block after expansion) are.
    """
    from moos_lint.files.discovery import discover, kind_of
    from moos_lint.frontends.nsplug import FileCache, Preprocessor
    from moos_lint.frontends.parsers.moos import parse_moos

    cache = cache or FileCache()
    pre = Preprocessor(
        defines=settings.defines, include_paths=settings.include_paths, mode="lint", cache=cache
    )
    given = {_norm(f) for f in files}
    fragments: set[str] = set()
    for path in sorted(given):
        kind = kind_of(path)
        if kind not in ("moos", "bhv"):
            continue  # C++ sources are no part of a mission's text
        if kind == "bhv":
            fragments.add(path)
            continue
        exp = pre.expand(path)
        if exp.read_problem is not None:
            continue
        if not parse_moos(exp).is_mission:
            fragments.add(path)
    if not fragments:
        return []
    root = project_root(settings, files)
    candidates = discover(
        [Path(root)], settings.exclude, settings.root, settings.respect_gitignore
    ).files
    # Which behavior files include a fragment (a .bhv may #include pieces).
    bhv_users: dict[str, bool] = {}

    def bhv_uses(path: str) -> bool:
        if path not in bhv_users:
            exp = pre.expand(path)
            bhv_users[path] = path in fragments or bool(fragments & set(exp.sources))
        return bhv_users[path]

    bhv_files = [c for c in candidates if kind_of(c) == "bhv"]
    out: list[str] = []
    for cand in candidates:
        if kind_of(cand) != "moos" or cand in given:
            continue
        exp = pre.expand(cand)
        if exp.read_problem is not None:
            continue
        moos = parse_moos(exp)
        if not moos.is_mission:
            continue
        if fragments & set(exp.sources):
            out.append(cand)
            continue
        patterns = _behavior_files(moos, os.path.dirname(cand))
        if any(bhv_uses(b) for b in bhv_files if any(fnmatch.fnmatch(b, p) for p in patterns)):
            out.append(cand)
    return out
