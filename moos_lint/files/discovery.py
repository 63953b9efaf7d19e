"""Finding the files to lint: mission, fragment, behavior and C++ files under the given paths."""

from __future__ import annotations

import fnmatch
import functools
import os
import re
from pathlib import Path

from moos_lint.files.gitignore import Frame, Ignorer, ignored
from moos_lint.files.source import read_head
from moos_lint.files.stamps import file_stamp
from moos_lint.files.suffixes import BHV_SUFFIXES, CPP_SUFFIXES, MOOS_SUFFIXES, TEMPLATE_SUFFIXES

#: folders and files never linted, whatever the configuration says
DEFAULT_EXCLUDE = (
    ".git",
    ".hg",
    ".svn",
    ".moos_lint_cache",
    "__pycache__",
    ".venv",
    "node_modules",
)

SUFFIXES = MOOS_SUFFIXES + BHV_SUFFIXES


def kind_of(path: str) -> str | None:
    """``moos``, ``bhv``, ``cpp`` or None, from the file name."""
    low = path.lower()
    if low.endswith(MOOS_SUFFIXES):
        return "moos"
    if low.endswith(BHV_SUFFIXES):
        return "bhv"
    if low.endswith(CPP_SUFFIXES):
        return "cpp"
    if low.endswith(TEMPLATE_SUFFIXES):
        return template_kind(path)
    return None


#: what makes a template a mission, or a behavior file
_MISSION_LINE = re.compile(rb"(?im)^[ \t]*ProcessConfig[ \t]*=")
_BEHAVIOR_LINE = re.compile(rb"(?im)^[ \t]*Behavior[ \t]*=")


def template_kind(path: str) -> str | None:
    """The kind of an nsplug template named for no kind (``moos.meta``), from its text:
    ``ProcessConfig =`` lines make a mission, ``Behavior =`` lines a behavior file;
    anything else with the suffix (a Unity or TensorFlow ``.meta``) is not MOOS."""
    stamp = file_stamp(path)
    return _sniffed(path, stamp) if stamp is not None else None


@functools.lru_cache(maxsize=1024)
def _sniffed(path: str, _stamp: tuple[int, int]) -> str | None:
    head = read_head(path, 64 * 1024)
    if head is None:
        return None
    if _MISSION_LINE.search(head):
        return "moos"
    if _BEHAVIOR_LINE.search(head):
        return "bhv"
    return None


class Discovered:
    """The files to lint (absolute paths, sorted), the paths given that do not exist, the
    folders whose listing decided the files (walked, or holding a path given), each
    with its modification time taken *before* it was listed (None: it cannot be
    stat'ed: a file added while the walk goes on changes its folder's time after
    that, so a list kept with these times is never taken for the newer listing), and
    the ignore files (``.gitignore``, ...) that decided, present or not
    (:mod:`moos_lint.files.gitignore`), with the files whose own text decided whether
    they are linted (a ``targ_`` file on its own) and the launch scripts whose nsplug
    commands did (a file they make from a template beside it is not linted)."""

    __slots__ = ("files", "folders", "ignore_files", "missing")

    def __init__(
        self,
        files: list[str],
        missing: list[str],
        folders: dict[str, int | None] | None = None,
        ignore_files: list[str] | None = None,
    ) -> None:
        self.files = files
        self.missing = missing
        self.folders = {} if folders is None else folders
        self.ignore_files = [] if ignore_files is None else ignore_files


def _mtime(path: str) -> int | None:
    try:
        return os.stat(path).st_mtime_ns
    except OSError:
        return None


def _excluded(rel: str, name: str, patterns: list[str]) -> bool:
    """Whether ``name`` or ``rel`` matches a pattern (or ``rel`` lies under one)."""
    m = _matcher(tuple(patterns))
    if m is None:
        return False
    return bool(m.match(os.path.normcase(name)) or m.match(os.path.normcase(rel)))


@functools.lru_cache(maxsize=16)
def _matcher(patterns: tuple[str, ...]) -> re.Pattern | None:
    """One regex for the patterns (``pat`` and ``pat/*``), as ``fnmatch`` reads them."""
    parts = []
    for pat in patterns:
        pat = os.path.normcase(pat.rstrip("/"))
        parts += [fnmatch.translate(pat), fnmatch.translate(pat + "/*")]
    if not parts:
        return None
    return re.compile("|".join(f"(?:{p})" for p in parts))


def discover(
    paths: list[Path], exclude: list[str], root: str, respect_gitignore: bool = True
) -> Discovered:
    """Walk ``paths``; directories are searched, files given by name are always taken.

    A ``mission.moos++`` is pAntler's expanded copy of a mission it launched, and a
    ``targ_*.moos`` (``targ_*.bhv``) beside a ``meta_*.moos`` (``meta_*.bhv``) is what the
    launch script made of the template with nsplug: neither is linted a second time, nor
    is a ``targ_`` file kept where no launch script runs it
    (:func:`_generated_beside_template`). With ``respect_gitignore``, what git ignores is
    not linted (see :mod:`moos_lint.files.gitignore`). A file named on the command line is
    linted even when git ignores it, as ruff does; a folder named there is walked, and
    what is ignored below it is left out.
    """
    patterns = [*DEFAULT_EXCLUDE, *exclude]
    ignorer = Ignorer(root) if respect_gitignore else None
    files: set[str] = set()
    missing: list[str] = []
    folders: dict[str, int | None] = {}
    decided: list[str] = []  # files whose text decided whether they are linted
    for given in paths:
        p = os.path.abspath(given)
        if not os.path.isdir(p):  # a file given by name: its folder tells whether it exists
            folders.setdefault(os.path.dirname(p), _mtime(os.path.dirname(p)))
        else:
            folders.setdefault(p, _mtime(p))  # before os.walk lists it
        if not os.path.lexists(p):
            missing.append(str(given))
            continue
        if not os.path.isdir(p):
            # (a template's suffix is shared with other tools' files: a Unity ``.meta``)
            foreign = p.lower().endswith(TEMPLATE_SUFFIXES) and kind_of(p) is None
            if not module_definition(p) and not foreign:
                files.add(p)
            continue
        seen_dirs: set[tuple[int, int]] = set()
        frames: dict[str, Frame] = {}
        for dirpath, dirnames, filenames in os.walk(p, followlinks=True):
            try:
                st = os.stat(dirpath)
            except OSError:
                dirnames[:] = []
                continue
            key = (st.st_dev, st.st_ino)
            if key in seen_dirs:  # a symlink loop
                dirnames[:] = []
                continue
            seen_dirs.add(key)
            rel_dir = os.path.relpath(dirpath, root)  # normalised: a name joins it as is
            prefix = "" if rel_dir == "." else rel_dir + os.sep
            frame = active = None
            if ignorer is not None:
                if dirpath == p:
                    frame = ignorer.start(p)
                else:
                    names = {*dirnames, *filenames}
                    frame = ignorer.enter(frames[os.path.dirname(dirpath)], dirpath, names)
                active = frame if frame.layers else None
            keep = []
            for d in sorted(dirnames):
                rel = prefix + d
                if _excluded(rel, d, patterns):
                    continue
                if active is not None and ignored(active, os.path.join(dirpath, d), True):
                    continue
                if kind_of(d) in ("moos", "bhv"):
                    # A directory named like a mission file: report it, do not descend.
                    files.add(os.path.join(dirpath, d))
                    continue
                keep.append(d)
                sub = os.path.join(dirpath, d)
                folders.setdefault(sub, _mtime(sub))  # before os.walk lists it
            dirnames[:] = keep
            if frame is not None and keep:
                frames[dirpath] = frame
            present = set(filenames)
            outputs = _nsplug_outputs(dirpath, present, decided)
            for f in filenames:
                # (a template named for no kind is read to know its kind)
                named = os.path.join(dirpath, f) if f.lower().endswith(TEMPLATE_SUFFIXES) else f
                if kind_of(named) is None:
                    continue
                if f.endswith("++"):
                    continue  # pAntler's copy of a mission it launched (``clean.sh`` removes it)
                made = _generated_beside_template(f, present)
                if made is None:  # a ``targ_`` file on its own: its text decides
                    decided.append(os.path.join(dirpath, f))
                    made = not _holds_directives(os.path.join(dirpath, f))
                if made or f in outputs:
                    continue  # nsplug's output of a template
                if f.lower().endswith(".def") and module_definition(os.path.join(dirpath, f)):
                    continue  # a Windows DLL's exports (``proj.def``), not nsplug definitions
                rel = prefix + f
                if _excluded(rel, f, patterns):
                    continue
                full = os.path.join(dirpath, f)
                if active is not None and ignored(active, full, False):
                    continue
                files.add(full)
    inputs = sorted({*ignorer.inputs, *decided} if ignorer is not None else decided)
    return Discovered(sorted(files), missing, folders, inputs)


def _generated_beside_template(name: str, present: set[str]) -> bool | None:
    """Whether ``name`` is a ``targ_`` file that nsplug made (``present``: its folder's file
    names); None when its text decides. MOOS-IvP's launch scripts write ``nsplug
    meta_vehicle.moos targ_$VNAME.moos``:

    - beside a ``meta_`` template of the same suffix, the findings are the template's,
      reported there. A kept copy of one (``worked_targ_NOSTROMO.moos``) is one too;
    - beside a launch script (``*.sh``) and no template, it is the mission that folder
      runs, and is linted;
    - with neither (None), it is an output kept away from its mission (with a run's
      results, ``logs/.../dstarlite/targ_artemis.moos``), unless it still holds nsplug's
      directives (:func:`_holds_directives`): what the template's ``#ifdef`` branches
      left out of that one expansion (the blocks of the planners it did not launch) is
      no mistake of its own."""
    if not (name.startswith("targ_") or "_targ_" in name):
        return False
    suffix = os.path.splitext(name)[1]
    if any(p.startswith("meta_") and p.endswith(suffix) for p in present):
        return True
    if any(p.endswith(".sh") for p in present):
        return False
    return None


def _nsplug_outputs(folder: str, present: set[str], decided: list[str]) -> frozenset[str]:
    """The files of ``folder`` that a launch script of the folder writes with nsplug from a
    template in the folder or one below it (``splug META_K200.moos K200.moos``, ``nsplug
    aux_files/META_remus.moos remus.moos``): made at launch, their findings are the
    template's, reported there. The scripts read join ``decided`` (an edit of theirs may
    change what is linted)."""
    if not any(n.endswith(".sh") or "." not in n for n in present):
        return frozenset()
    from moos_lint.files.launch import nsplug_calls, shell_scripts

    scripts = shell_scripts(folder)
    if not scripts:
        return frozenset()
    decided.extend(path for path, _text in scripts)
    out = set()
    for call in nsplug_calls(folder):
        template, output = os.path.relpath(call.template, folder), call.output
        if "$" in template + output or "/" in output or template.startswith(".."):
            continue
        if (
            output in present
            and output != template
            and os.path.isfile(os.path.join(folder, template))
        ):
            out.add(output)
    return frozenset(out)


#: an nsplug directive at the start of a line, which nsplug's output never holds
_DIRECTIVE = re.compile(rb"^[ \t]*#(?:include|define|ifdef|ifndef|elseifdef|else|endif)\b", re.M)


def _holds_directives(path: str) -> bool:
    """Whether a ``targ_`` file still holds nsplug directives: a template named like an
    output, not one. A file that cannot be read is linted, to say so."""
    head = read_head(path, 1 << 20)
    return head is None or _DIRECTIVE.search(head) is not None


#: the statements of a Windows module-definition file (a DLL's ``.def``: ``LIBRARY iMatlab``,
#: ``EXPORTS mexFunction``), which shares the suffix of nsplug's definition files
_MODULE_STATEMENT = re.compile(
    rb"^\s*(?:LIBRARY|EXPORTS|NAME|VERSION|DESCRIPTION|STACKSIZE|HEAPSIZE|SECTIONS)\b"
)


def module_definition(path: str) -> bool:
    """Whether a ``.def`` file is a Windows module definition: its first line that is not
    blank or a ``;`` comment is one of that format's statements."""
    if not path.lower().endswith(".def"):
        return False
    head = read_head(path, 4096)
    if head is None:
        return False
    for line in head.splitlines():
        if line.strip() and not line.lstrip().startswith(b";"):
            return bool(_MODULE_STATEMENT.match(line))
    return False
