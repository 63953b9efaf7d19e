"""What git ignores, as discovery needs it: ``.gitignore``, ``.ignore``, the repository's
``info/exclude`` and the user's global excludes file.

The patterns are read with pathspec's ``gitwildmatch`` (the gitignore syntax,
negations and ``dir/`` patterns included); git itself is never run. Running
``git check-ignore`` or ``git ls-files`` would read the linted repository's
own ``.git/config``, which can name programs git starts (``core.fsmonitor``,
for one): nothing a linted repository contains is executed. It would also
cost a process start per run.

The precedence is git's (and ripgrep's, which ruff follows): a pattern in a
deeper folder wins over one in a shallower folder; in one folder ``.ignore``
wins over ``.gitignore``; the repository's ``info/exclude`` and the global
excludes file come last. A ``.gitignore`` (and ``info/exclude``) counts only
inside a git work tree, as for git; ``.ignore`` counts anywhere at or below
the project root. A nested repository (a folder holding ``.git``) starts
afresh: its parent's patterns do not reach into it.

The global excludes file is ``core.excludesFile`` in the user's git config
(``~/.gitconfig`` or ``$XDG_CONFIG_HOME/git/config``, read as text), else
``$XDG_CONFIG_HOME/git/ignore`` (``~/.config/git/ignore``).

Every file that decided (or whose absence decided) what is ignored is listed
in :attr:`Ignorer.inputs`, for the caches to compare.
"""

from __future__ import annotations

import os
import re

from moos_lint.files.source import read_head

#: per-folder ignore files, weakest first
FOLDER_FILES = (".gitignore", ".ignore")


#: how pathspec's regex of a pattern ends when it also matches what lies below a match
#: (pathspec 0.12, then 1.x), and when the pattern names folders only (``name/``)
_BELOW = ("(?:(?P<ps_d>/).*)?$", "(?:(?P<ps_d>/)|$)")
_FOLDER_ONLY = ("(?P<ps_d>/).*$", "(?P<ps_d>/)")


def _exact(line: str) -> tuple[bool, re.Pattern | None, re.Pattern] | None:
    """A pattern as (include, regex for a file, regex for a folder), matching one path
    itself: a walk decides each folder before it goes below it, as git does (a file
    in an ignored folder stays ignored whatever a deeper ``!`` pattern says).

    pathspec's regex also matches everything below a match (a ``ps_d`` group marks
    where); that tail is cut off. The regexes are used with ``search``."""
    from pathspec import GitIgnoreSpec

    try:
        patterns = GitIgnoreSpec.from_lines([line]).patterns
    except Exception:  # a malformed pattern: git skips it too
        return None
    include = patterns[0].include if patterns else None
    regex = patterns[0].regex if patterns else None
    if include is None or regex is None:
        return None
    src = regex.pattern
    for tail in _FOLDER_ONLY:
        if src.endswith(tail):
            head = src[: -len(tail)]
            return include, None, re.compile(head + "$" if head else ".")
    for tail in _BELOW:
        if src.endswith(tail):
            one = re.compile(src[: -len(tail)] + "$")
            return include, one, one
    return include, regex, regex


class _Layer:
    """The patterns of one ignore file, relative to its folder ``base``."""

    __slots__ = ("any_dir", "any_file", "base", "patterns", "prefix")

    def __init__(self, base: str, lines: list[str]) -> None:
        self.base = base
        self.prefix = base.rstrip(os.sep) + os.sep  # what a path below ``base`` starts with
        self.patterns = [p for p in map(_exact, lines) if p is not None]
        #: one regex per kind of path that matches where any pattern matches: most paths
        #: match none, and one search then rules the whole layer out
        self.any_file = _any_of([f for _, f, _ in self.patterns])
        self.any_dir = _any_of([d for _, _, d in self.patterns])


def _any_of(regexes: list[re.Pattern | None]) -> re.Pattern | None:
    """A regex that finds a match where any of ``regexes`` does (None: not combinable)."""
    sources = [r.pattern for r in regexes if r is not None]
    if not sources:
        return None
    joined = "|".join(f"(?:{_NAMED.sub('(?:', src)})" for src in sources)
    try:
        return re.compile(joined)
    except re.error:  # (inline flags, a back-reference): every pattern is searched alone
        return None


_NAMED = re.compile(r"\(\?P<\w+>")


class Frame:
    """The ignore layers in force in one folder of a walk (shared with its parent when
    the folder adds none)."""

    __slots__ = ("git", "layers")

    def __init__(self, layers: tuple[_Layer, ...], git: bool) -> None:
        self.layers = layers
        self.git = git  # inside a git work tree (``.gitignore`` counts)


EMPTY = Frame((), False)


def _read_lines(path: str) -> list[str] | None:
    data = read_head(path, 1 << 20)
    if data is None:
        return None
    return data.decode("utf-8", "replace").splitlines()


def _git_dir(top: str) -> str | None:
    """The git folder of the work tree ``top`` (``.git``, or where a ``.git`` file points)."""
    dot = os.path.join(top, ".git")
    if os.path.isdir(dot):
        return dot
    lines = _read_lines(dot) or []
    for line in lines[:1]:
        if line.startswith("gitdir:"):
            target = os.path.join(top, line[len("gitdir:") :].strip())
            common = _read_lines(os.path.join(target, "commondir"))
            if common:  # a linked work tree: info/exclude is in the common folder
                return os.path.normpath(os.path.join(target, common[0].strip()))
            return os.path.normpath(target)
    return None


def user_git_configs() -> tuple[str, str]:
    """The user's git config files, in the order git reads them (later ones win)."""
    home = os.path.expanduser("~")
    xdg = os.environ.get("XDG_CONFIG_HOME") or os.path.join(home, ".config")
    return os.path.join(xdg, "git", "config"), os.path.join(home, ".gitconfig")


def global_excludes_file() -> str:
    """The user's global git excludes file (which may not exist)."""
    home = os.path.expanduser("~")
    xdg = os.environ.get("XDG_CONFIG_HOME") or os.path.join(home, ".config")
    found = None
    for config in user_git_configs():
        section = ""
        for raw in _read_lines(config) or ():
            line = raw.strip()
            if line.startswith("["):
                section = line[1:].split("]", 1)[0].strip().lower()
            elif section == "core" and "=" in line:
                key, _, value = line.partition("=")
                if key.strip().lower() == "excludesfile":
                    found = value.split("#", 1)[0].split(";", 1)[0].strip().strip('"')
    if found:
        return os.path.expanduser(found)
    return os.path.join(xdg, "git", "ignore")


class Ignorer:
    """Decides which paths of a walk are ignored; collects the files it read."""

    def __init__(self, root: str) -> None:
        self.root = os.path.abspath(root)
        #: every ignore file consulted, present or not
        self.inputs: set[str] = set()
        self._global: _Layer | None = None
        self._global_read = False

    def _layer(self, path: str, base: str) -> _Layer | None:
        self.inputs.add(path)
        lines = _read_lines(path)
        if not lines:
            return None
        layer = _Layer(base, lines)
        return layer if layer.patterns else None

    def _repo_frame(self, top: str) -> Frame:
        """The layers of a git work tree's top folder before its own ignore files."""
        layers: list[_Layer] = []
        if not self._global_read:
            self._global_read = True
            self.inputs.update(user_git_configs())
            self._global = self._layer(global_excludes_file(), "")
        git_dir = _git_dir(top)
        if git_dir is not None:
            exclude = self._layer(os.path.join(git_dir, "info", "exclude"), top)
            if self._global:
                layers.append(_rebase(self._global, top))
            if exclude is not None:
                layers.append(exclude)
        return Frame(tuple(layers), True)

    def enter(self, parent: Frame, folder: str, names: set[str] | None = None) -> Frame:
        """The frame of ``folder`` (a child of the folder of ``parent``); ``names``: the
        folder's entries when the walk has them (else they are probed)."""
        has = (lambda n: n in names) if names is not None else None
        is_repo = has(".git") if has else os.path.lexists(os.path.join(folder, ".git"))
        frame = self._repo_frame(folder) if is_repo else parent
        added = []
        for name in FOLDER_FILES:
            if name == ".gitignore" and not frame.git:
                continue
            path = os.path.join(folder, name)
            if has is not None and not has(name):
                continue
            layer = self._layer(path, folder)
            if layer is not None:
                added.append(layer)
        if not added:
            return frame
        return Frame(frame.layers + tuple(added), frame.git)

    def start(self, folder: str) -> Frame:
        """The frame of a folder a walk starts in: the ignore files of the folders from
        the git work tree's top (or the project root) down to it."""
        folder = os.path.abspath(folder)
        chain = [folder]
        here = folder
        top = None
        while True:
            if os.path.lexists(os.path.join(here, ".git")):
                top = here
                break
            parent = os.path.dirname(here)
            if parent == here:
                break
            here = parent
            chain.append(here)
        if top is None:  # outside git: the ``.ignore`` files from the project root down
            if not _within(folder, self.root):
                chain = [folder]
            else:
                chain = chain[: len(_parts(folder)) - len(_parts(self.root)) + 1]
        frame = EMPTY
        for here in reversed(chain):
            frame = self.enter(frame, here)
            if here != folder:  # the parents' listings were probed: their absence counts
                for name in FOLDER_FILES:
                    self.inputs.add(os.path.join(here, name))
        return frame


def _parts(path: str) -> list[str]:
    return [p for p in path.split(os.sep) if p]


def _within(path: str, folder: str) -> bool:
    return path == folder or path.startswith(folder.rstrip(os.sep) + os.sep)


def _rebase(layer: _Layer, base: str) -> _Layer:
    """The global layer, relative to a repository's top."""
    copy = _Layer.__new__(_Layer)
    copy.base = base
    copy.prefix = base.rstrip(os.sep) + os.sep
    copy.patterns = layer.patterns
    copy.any_file = layer.any_file
    copy.any_dir = layer.any_dir
    return copy


def ignored(frame: Frame, path: str, is_dir: bool) -> bool:
    """Whether ``path`` (a file, or a folder when ``is_dir``; absolute, as the walk joins
    it) is ignored in ``frame``."""
    decision = None
    for layer in frame.layers:
        if not path.startswith(layer.prefix):
            continue
        rel = path[len(layer.prefix) :]
        if os.sep != "/":
            rel = rel.replace(os.sep, "/")
        any_ = layer.any_dir if is_dir else layer.any_file
        if any_ is not None and any_.search(rel) is None:
            continue
        for include, file_re, dir_re in layer.patterns:
            regex = dir_re if is_dir else file_re
            if include != decision and regex is not None and regex.search(rel) is not None:
                decision = include
    return bool(decision)


def ignored_file(path: str, root: str) -> bool:
    """Whether ``path`` (a file, absolute) is ignored as discovery would find it, with
    ``root`` the project root: a file a project keeps out of git on purpose."""
    ignorer = Ignorer(root)
    return ignored(ignorer.start(os.path.dirname(path)), path, False)
