"""The folders a mission may be launched from, and what the scripts beside it say.

pAntler, the helm and every MOOS app open relative paths (``behaviors =
targs/targ_abe.bhv``, ``obstacle_file = ...``) from the folder they were started
in, not from the mission file's folder. Launch scripts run ``pAntler
targs/targ_abe.moos`` from the mission folder, so a path inside a generated
mission is often relative to a parent of the file's folder. The plausible
launch folders of a mission file are its own folder and its parents up to the
project root (see :mod:`moos_lint.files.project`): a relative path is missing only
when none of them holds it.
"""

from __future__ import annotations

import contextlib
import functools
import os
import re
import threading
from collections.abc import Callable, Iterator

from moos_lint.files.nsplug_calls import NsplugCall, calls_in
from moos_lint.files.project import is_within, vcs_top
from moos_lint.files.source import read_head
from moos_lint.files.stamps import file_stamp, folder_mtime
from moos_lint.files.suffixes import script_stem

TYPE_CHECKING = False  # typing itself is not imported at run time
if TYPE_CHECKING:
    from typing import TypeVar

    _T = TypeVar("_T")


def project_folder(settings, path: str) -> str:
    """The project root for a file: the config's folder, the checkout's top, or the
    working folder holding the file (the file's own folder otherwise)."""
    config = getattr(settings, "config_path", None)
    if config:
        return os.path.dirname(os.path.abspath(config))
    path = os.path.abspath(path)
    top = _checkout_top(path if os.path.isdir(path) else os.path.dirname(path))
    if top is not None:
        return top
    here = os.getcwd()
    if is_within(path, here):
        return here
    return os.path.dirname(os.path.abspath(path))


def launch_folders(path: str, root: str) -> list[str]:
    """The file's folder, then each parent up to ``root`` (when the file lies under it)."""
    here = os.path.dirname(os.path.abspath(path))
    out = [here]
    root = os.path.abspath(root)
    if not is_within(here, root):
        return out
    while here != root:
        parent = os.path.dirname(here)
        if parent == here:
            break
        here = parent
        out.append(here)
    return out


def find_relative(name: str, folders: list[str]) -> str | None:
    """The first ``folder/name`` that exists, or None."""
    if os.path.isabs(name):
        return name if os.path.exists(name) else None
    for folder in folders:
        candidate = os.path.join(folder, name)
        if os.path.exists(candidate):
            return candidate
    return None


_NSPLUG_PATH = re.compile(r"(?:--path=|--path\s+|(?<!\S)-p\s+)([^\s;|&]+)")
_SCRIPT_BYTES = 256 * 1024


@functools.lru_cache(maxsize=256)
def script_include_paths(folder: str) -> tuple[str, ...]:
    """The ``--path`` folders the folder's launch scripts hand nsplug.

    Launch scripts (``*.sh`` beside a mission) run ``nsplug meta_x.moos targ_x.moos
    --path=../shared_plugins`` from their own folder; includes the template cannot
    find beside itself come from there. The scripts are read as text, never run;
    a path holding a shell variable is not followed.
    """
    out: list[str] = []
    try:
        names = sorted(os.listdir(folder))
    except OSError:
        return ()
    for name in names:
        if not name.endswith(".sh"):
            continue
        path = os.path.join(folder, name)
        data = read_head(path, _SCRIPT_BYTES)
        if data is None:
            continue
        text = data.decode("utf-8", "replace")
        for line in text.replace("\\\n", " ").splitlines():
            code = line.split("#", 1)[0]
            if "nsplug" not in code:
                continue
            for m in _NSPLUG_PATH.finditer(code):
                for part in m.group(1).strip("\"'").split(":"):
                    if not part or "$" in part or "`" in part:
                        continue
                    where = os.path.normpath(os.path.join(folder, part))
                    if os.path.isdir(where) and where not in out:
                        out.append(where)
    return tuple(out)


def scripts_beside(path: str) -> frozenset[str]:
    """The lower-case stems of the scripts in the folder of ``path`` (``iSonar`` for
    ``iSonar.py``): programs a mission may start (``Run = ./iSonar.py``), each reading
    the block of its stem. Listed again when the folder changes."""
    folder = os.path.dirname(os.path.abspath(path))
    return _scripts_in(folder, folder_mtime(folder))


@functools.lru_cache(maxsize=256)
def _scripts_in(folder: str, _mtime: object) -> frozenset[str]:
    try:
        names = os.listdir(folder)
    except OSError:
        return frozenset()
    stems = (script_stem(n) for n in names)
    return frozenset(s.lower() for s in stems if s)


_QUOTED = re.compile(rb"""["']([A-Za-z_][\w.\-]{0,63})["']""")


def script_names(mission: str, program: str) -> frozenset[str] | None:
    """The lower-case words a launched script quotes (``'iPydyna'``): the MOOS name it
    connects as and the blocks it reads are among them. ``program`` is the Run line's
    program, found from the mission's folder; None when no such script is there. The
    script is read as text, never run."""
    if script_stem(program.replace("\\", "/").rsplit("/", 1)[-1]) is None:
        return None
    path = os.path.join(os.path.dirname(os.path.abspath(mission)), program)
    try:
        st = os.stat(path)
    except OSError:
        return None
    return _quoted_in(path, st.st_mtime_ns, st.st_size)


@functools.lru_cache(maxsize=256)
def _quoted_in(path: str, _mtime: int, _size: int) -> frozenset[str] | None:
    data = read_head(path, _SCRIPT_BYTES)
    if data is None:
        return None
    return frozenset(m.group(1).decode("ascii", "replace").lower() for m in _QUOTED.finditer(data))


_REDIRECT = re.compile(r">>?[ \t]*[\"']?([\w./-]+)")
_RM = re.compile(r"(?:^|[;&|][ \t]*)rm[ \t]+([^\n;&|]*)", re.M)


def shell_scripts(folder: str) -> tuple[tuple[str, str], ...]:
    """``(path, text)`` of each shell script of ``folder``, by name: ``*.sh``, and a file
    without a suffix that starts with ``#!`` or runs pAntler (``script-200``: ``pAntler
    K200.moos &; pHelmIvP K200.moos ...``). Read as text, never run, and kept while every
    script keeps its (mtime, size) (the language server asks again at each edit of a
    mission of the folder)."""
    return _texts(folder, ".sh") + _plain_scripts(folder)


#: a command line of a script without a suffix: it runs pAntler
_RUNS_ANTLER = re.compile(r"(?:^|[;&|])[ \t]*(?:\S*/)?pAntler\b", re.M)


def _plain_scripts(folder: str) -> tuple[tuple[str, str], ...]:
    """The files of ``folder`` without a suffix (no ``.`` in the name, not a README) that
    are shell scripts: they start with ``#!``, or run pAntler."""
    texts = _named_texts(
        folder, "plain", lambda n: "." not in n and not n.lower().startswith("readme")
    )
    return tuple(
        (path, text)
        for path, text in texts
        if "\x00" not in text and (text.startswith("#!") or _RUNS_ANTLER.search(text))
    )


def notes(folder: str) -> tuple[tuple[str, str], ...]:
    """``(path, text)`` of each note of ``folder`` (``README``, ``*.md``, ``*.txt``): the
    steps a person runs by hand are often written there (``$ uPokeDB WPT_REQUEST=true``)."""
    return _texts(folder, (".md", ".txt", ".markdown"), readme=True)


def _texts(
    folder: str, suffix: str | tuple[str, ...], readme: bool = False
) -> tuple[tuple[str, str], ...]:
    """``(path, text)`` of each file of ``folder`` whose name ends in ``suffix`` (or, with
    ``readme``, starts with ``README`` in any case), by name, kept while every one keeps
    its (mtime, size)."""
    return _named_texts(
        folder,
        (suffix, readme),
        lambda n: n.endswith(suffix) or (readme and n.lower().startswith("readme")),
    )


def _named_texts(
    folder: str, kind: object, keep: Callable[[str], bool]
) -> tuple[tuple[str, str], ...]:
    """``(path, text)`` of each regular file of ``folder`` whose name ``keep`` accepts, by
    name, kept while every one keeps its (mtime, size); ``kind`` names ``keep`` (the
    same for the same files), for :func:`read_once`."""

    def read() -> tuple[tuple[str, str], ...]:
        stamps = []
        for n in sorted(n for n in _listing(folder) if keep(n)):
            path = os.path.join(folder, n)
            stamp = _once(("stamp", path), functools.partial(file_stamp, path))
            if stamp is not None:
                stamps.append((path, *stamp))
        return _read_scripts(tuple(stamps))

    return _once(("texts", folder, kind), read)


#: per thread (the language server may lint in two at once): what was listed, stamped
#: and looked for during a lint run, while :func:`read_once` holds
_ONCE = threading.local()


@contextlib.contextmanager
def read_once() -> Iterator[None]:
    """Within it, each folder's scripts and notes are listed and stamped once: a lint run
    asks for them many times (each mission of a folder, each rule), and what it reads
    does not change under it. Outside it, at every ask (an edit is seen at the next)."""
    outer = getattr(_ONCE, "memo", None)
    if outer is None:
        _ONCE.memo = {}
    try:
        yield
    finally:
        if outer is None:
            _ONCE.memo = None


def _once(key: tuple, compute: Callable[[], _T]) -> _T:
    """``compute()``, once per ``key`` while :func:`read_once` holds."""
    memo = getattr(_ONCE, "memo", None)
    if memo is None:
        return compute()
    if key not in memo:
        memo[key] = compute()
    return memo[key]


def _checkout_top(folder: str) -> str | None:
    """:func:`vcs_top` of ``folder``, looked for once per folder during a run."""
    return _once(("top", folder), lambda: vcs_top(folder))


def _listing(folder: str) -> list[str]:
    def names() -> list[str]:
        try:
            return os.listdir(folder)
        except OSError:
            return []

    return _once(("list", folder), names)


@functools.lru_cache(maxsize=256)
def _read_scripts(stamps: tuple[tuple[str, int, int], ...]) -> tuple[tuple[str, str], ...]:
    out = []
    for path, _mtime, _size in stamps:
        data = read_head(path, _SCRIPT_BYTES)
        if data is not None:
            out.append((path, data.decode("utf-8", "replace")))
    return tuple(out)


def made_by_scripts(folder: str) -> frozenset[str]:
    """The names of the files the folder's shell scripts (and those of its ``scripts``
    folder) write (``> obstacles.txt``, nsplug's output: ``nsplug bhv.meta current.bhv``) or
    clean away (``rm -f obstacles.txt``): files that a launch makes, absent at rest."""
    return _made_by(shell_scripts(folder) + shell_scripts(os.path.join(folder, "scripts")))


@functools.lru_cache(maxsize=256)
def _made_by(scripts: tuple[tuple[str, str], ...]) -> frozenset[str]:
    # nsplug's outputs, wherever the script runs it (only their names are compared)
    out = {
        os.path.basename(call.output)
        for call in calls_in(scripts, past_folder_change=True)
        if "$" not in call.output
    }
    for _path, text in scripts:
        for line in text.splitlines():
            if ">" not in line and "rm" not in line:
                continue  # most lines: neither pattern can match
            code = line.split("#", 1)[0]
            out.update(os.path.basename(m.group(1)) for m in _REDIRECT.finditer(code))
            for m in _RM.finditer(code):
                for word in m.group(1).split():
                    word = word.strip("\"'")
                    if word and not word.startswith(("-", "$")) and "*" not in word:
                        out.add(os.path.basename(word))
    out.discard("")
    out.discard("/dev/null")
    out.discard("null")
    return frozenset(out)


#: a launch script's assignment of a vehicle's name, a word written out: ``VNAME1="henry"``,
#: ``export VNAME=abe``, or of a list of them, ``:`` between (a shoreside's
#: ``VNAMES="abe:ben"``); ``VNAME=$1`` and ``VNAME="${ARGI#--vname=}"`` name none
_VEHICLE_NAME_SET = re.compile(
    r"^[ \t]*(?:export[ \t]+)?\w*VNAME\w*=([\"']?)([A-Za-z][\w-]*(?::[A-Za-z][\w-]*)*)\1"
    r"[ \t]*(?:[;&#]|$)",
    re.M,
)


def vehicle_names(folder: str) -> frozenset[str]:
    """The vehicle names the folder's shell scripts give their ``VNAME`` variables, as
    written (``VNAME1="henry"``, each of ``VNAMES="abe:ben"``): what nsplug puts in
    ``$(VNAME)``. Read as text, never run."""
    return _vehicle_names(shell_scripts(folder))


@functools.lru_cache(maxsize=256)
def _vehicle_names(scripts: tuple[tuple[str, str], ...]) -> frozenset[str]:
    return frozenset(
        name
        for _path, text in scripts
        for m in _VEHICLE_NAME_SET.finditer(text)
        for name in m.group(2).split(":")
    )


def nsplug_calls(folder: str) -> tuple[NsplugCall, ...]:
    """Each nsplug command of the folder's own shell scripts, with its macros (see
    :mod:`moos_lint.files.nsplug_calls`), up to the first command of a script that
    changes folder (a launch script runs from the mission folder: its relative names are
    read from there). Read as text, never run."""
    return calls_in(shell_scripts(folder))


def nsplug_working_folders(folder: str) -> tuple[str, ...]:
    """The folder above ``folder`` when one of its launch scripts runs nsplug on a
    template of ``folder`` (``nsplug bhvs/meta_heron.bhv targ_heron.bhv`` in the mission
    folder): nsplug looks for includes in the folder it runs in, not the template's
    (Expander.cpp), so the template's ``#include bhvs/plug_return.bhv`` is found there."""
    parent = os.path.dirname(folder)
    if not parent or parent == folder:
        return ()
    for call in nsplug_calls(parent):
        if os.path.dirname(call.template) == folder:
            return (parent,)
    return ()


_PATCH_RUN = re.compile(r"^[ \t]*run[ \t]*=[ \t]*([^@~\s]+)[^~\n]*(?:~[ \t]*(\S+))?", re.I | re.M)


def patch_launches(folder: str) -> frozenset[str]:
    """The lower-case names that the ``Run`` lines of the nspatch patch files (``*.xmoos``)
    of ``folder`` launch, aliases included: ``nspatch --stem=meta_shoreside.moos
    full-logging.xmoos`` overwrites or augments the stem's blocks, its ANTLER block too
    (moos-ivp ``app_nspatch``). Read as text, never run."""
    return _patch_runs(_texts(folder, ".xmoos"))


@functools.lru_cache(maxsize=256)
def _patch_runs(patches: tuple[tuple[str, str], ...]) -> frozenset[str]:
    out: set[str] = set()
    for _path, text in patches:
        for m in _PATCH_RUN.finditer(text):
            out.add(m.group(1).rsplit("/", 1)[-1].lower())
            if m.group(2):
                out.add(m.group(2).lower())
    return frozenset(out)


#: a shell command given a mission file: its program (first word) and its words
#: a command, at the start of a line or after `;`, `&` or `|` (``pAntler a.moos &; pHelmIvP
#: a.moos``)
_STARTS_MISSION = re.compile(r"(?:^|(?<=[;&|]))[ \t]*([^\s;&|#]+)([^\n;&|#]*)", re.M)
_MOOS_SUFFIX = re.compile(r"\.moos\b")
_ARG_CHARS = frozenset("abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789_.${}-/")
_ALIAS_ARG = re.compile(r"--alias=[\"']?([A-Za-z_][\w\-]*)")


def script_launches(folder: str, mission: str) -> frozenset[str]:
    """The lower-case names of the processes the shell scripts of ``folder`` start with
    the file ``mission`` or an nsplug output of it written by a script of the folder
    (``uMAC targ_shoreside.moos`` for ``meta_shoreside.moos``,
    ``"$BIN" targ_shoreside.moos --alias=pTraffic``): the program's own name, and the name
    ``--alias=`` gives it. Read as text, never run."""
    name = os.path.basename(mission)
    started = (*_started(shell_scripts(folder)), *_cmake_started(cmake_scripts(folder)))
    # nsplug's outputs of the mission (``nsplug META_K200.moos K200.moos``)
    outputs = {
        os.path.basename(call.output)
        for call in nsplug_calls(folder)
        if os.path.basename(call.template) == name
    }
    return frozenset(
        p for p, arg in started if _names_mission(arg, name) or os.path.basename(arg) in outputs
    )


def antler_overrides(folder: str, mission: str) -> frozenset[str]:
    """The lower-case keys the shell scripts of ``folder`` give pAntler on its command line
    when they launch ``mission`` (``pAntler $COMMUNITY.moos --MOOSTimeWarp=$TIME_WARP``):
    pAntler writes a copy of the mission with each ``--KEY=value`` line in place of the
    file's own (``mission.moos++``, MOOSFileReader's MakeOverloadedCopy), so what the file
    says of those keys is not what runs. A ``.moos`` argument built from a shell variable
    may name the mission. Read as text, never run."""
    name = os.path.basename(mission)
    return frozenset(
        key for arg, key in _antler_overloads(shell_scripts(folder)) if _may_name(arg, name)
    )


#: a ``--KEY=value`` word of a command line
_OVERLOAD = re.compile(r"(?:^|\s)--([A-Za-z]\w*)=")


@functools.lru_cache(maxsize=256)
def _antler_overloads(scripts: tuple[tuple[str, str], ...]) -> tuple[tuple[str, str], ...]:
    """``(mission argument, key)`` of each ``--KEY=value`` a script gives pAntler."""
    out: set[tuple[str, str]] = set()
    for _path, text in scripts:
        for m in _STARTS_MISSION.finditer(text):
            if _program_name(m.group(1)) != "pantler":
                continue
            args = m.group(2)
            mission = _mission_arg(args)
            if mission is not None:
                out.update((mission, k.lower()) for k in _OVERLOAD.findall(args))
    return tuple(sorted(out))


#: a shell variable in a word (``$COMMUNITY``, ``${VNAME}``, ``$(VNAME)``)
_SHELL_VAR = re.compile(r"\$(?:\{\w+\}|\(\w+\)|\w+)")


def _may_name(arg: str, mission: str) -> bool:
    """Whether a script's ``.moos`` argument is, or may be (a part of it a shell variable),
    ``mission`` or nsplug's output of it."""
    if _names_mission(arg, mission):
        return True
    base = os.path.basename(arg)
    if "$" not in base:
        return False
    pattern = ".*".join(re.escape(part) for part in _SHELL_VAR.split(base))
    if re.fullmatch(pattern, mission):
        return True
    stem = mission[len("meta_") :] if mission.startswith("meta_") else None
    return stem is not None and re.fullmatch(pattern, "targ_" + stem) is not None


def cmake_scripts(folder: str) -> tuple[tuple[str, str], ...]:
    """``(path, text)`` of each CMake file of ``folder`` (``*.cmake``, ``CMakeLists.txt``):
    a test harness may start a program with a mission (MOOS-IvP's nightly tests run
    ``EXECUTE_PROCESS( COMMAND uMissionTester alpha.moos ...)``). Read as text, never run."""
    return (*_texts(folder, ".cmake"), *_texts(folder, "CMakeLists.txt"))


#: a CMake ``COMMAND`` (``execute_process``, ``add_test``, ``add_custom_command``): its
#: program and its words, up to the closing parenthesis or the line's end
_CMAKE_COMMAND = re.compile(r"\bCOMMAND[ \t]+([^\s()]+)([^()\n]*)", re.I)


@functools.lru_cache(maxsize=256)
def _cmake_started(scripts: tuple[tuple[str, str], ...]) -> tuple[tuple[str, str], ...]:
    out: set[tuple[str, str]] = set()
    for _path, text in scripts:
        for m in _CMAKE_COMMAND.finditer(text):
            mission = _mission_arg(m.group(2))
            program = _program_name(m.group(1))
            if mission is not None and program is not None:
                out.add((program, mission))
    return tuple(sorted(out))


def _names_mission(arg: str, mission: str) -> bool:
    """Whether a script's ``.moos`` argument is ``mission`` or nsplug's output of it: the
    same name, or ``targ_X`` for the template ``meta_X`` (``targ_$VNAME.moos`` may be any)."""
    arg = os.path.basename(arg)
    if arg == mission:
        return True
    if not mission.startswith("meta_") or not arg.startswith("targ_"):
        return False
    literal = re.split(r"\$", arg[len("targ_") :], maxsplit=1)
    stem = mission[len("meta_") : -len(".moos")]
    if len(literal) == 1:
        return literal[0] == stem + ".moos"
    return stem.startswith(literal[0])  # ``targ_$(VNAME)``, ``targ_shore_${N}``: may be


@functools.lru_cache(maxsize=256)
def _started(scripts: tuple[tuple[str, str], ...]) -> tuple[tuple[str, str], ...]:
    out: set[tuple[str, str]] = set()
    for _path, text in scripts:
        for m in _STARTS_MISSION.finditer(text):
            args = m.group(2)
            mission = _mission_arg(args)
            if mission is None:
                continue
            program = _program_name(m.group(1))
            if program is not None:
                out.add((program, mission))
            out.update((a.lower(), mission) for a in _ALIAS_ARG.findall(args))
    return tuple(sorted(out))


_PROGRAM = re.compile(r"[A-Za-z_][\w\-]*")


def _program_name(word: str) -> str | None:
    """The lower-case program a command's first word names (``"$BIN_DIR/pAntler"``:
    ``pantler``), or None when it is no plain name (``$BIN``)."""
    program = word.strip("\"'").rsplit("/", 1)[-1]
    return program.lower() if _PROGRAM.fullmatch(program) else None


def _mission_arg(args: str) -> str | None:
    """The first ``*.moos`` word of a command's arguments (``targ_$VNAME.moos``), found
    from its suffix back, in one pass (a script may hold a line of any length)."""
    found = _MOOS_SUFFIX.search(args)
    if found is None:
        return None
    start = found.start()
    while start > 0 and args[start - 1] in _ARG_CHARS:
        start -= 1
    return args[start : found.end()] if start < found.start() else None
