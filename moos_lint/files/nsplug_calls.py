"""The nsplug command lines of a folder's launch scripts, with their arguments.

A launch script makes the mission with ``nsplug meta_vehicle.moos targ_abe.moos
$NSFLAGS WARP=$TIME_WARP VNAME=abe ...``: every ``NAME=value`` or bare ``NAME``
after the two file names defines a macro for that run (nsplug's ``main.cpp``),
and ``--strict``, ``--lenient``, ``--path`` change how it expands. The scripts
are read as text, never run. An argument whose words cannot be read from the
script (``$MACROS``, ``"$@"``, ``--macros=file``) may define any macro: the
call's macros are then not known.
"""

from __future__ import annotations

import functools
import os
import re
from dataclasses import dataclass


@dataclass(frozen=True)
class NsplugCall:
    """One ``nsplug TEMPLATE OUTPUT ...`` command of a shell script."""

    script: str
    line: int
    #: the template's path (the script's folder joined with the name it gives, which may
    #: hold a shell expansion: ``$META``)
    template: str
    output: str
    #: the macros the call defines, each with its value (None: a shell expansion, whose
    #: value is not known; ``<defined>`` for a bare ``NAME``, as nsplug stores it); None
    #: when an argument may define others
    macros: tuple[tuple[str, str | None], ...] | None
    #: ``--strict``: nsplug stops at a line with a macro left over
    strict: bool
    #: ``--lenient``: such a line keeps the macros it could expand
    lenient: bool


#: a command that changes the script's folder: later relative names are not known
CHANGES_FOLDER = re.compile(r"(?:^|[;&|(][ \t]*)(?:cd|pushd|popd)\b")


@functools.lru_cache(maxsize=256)
def calls_in(
    scripts: tuple[tuple[str, str], ...], past_folder_change: bool = False
) -> tuple[NsplugCall, ...]:
    """Each nsplug command of the scripts (``(path, text)``, each run from its own
    folder), up to the first command of a script that changes folder: a relative name
    after it is not known. ``past_folder_change``: every command, for what only the
    names of the files matter to (the outputs a launch makes)."""
    out: list[NsplugCall] = []
    for path, text in scripts:
        if "splug" not in text:
            continue
        assigned = _assignments(text)
        for lineno, line in _logical_lines(text):
            if not past_folder_change and CHANGES_FOLDER.search(line.split("#", 1)[0]):
                break
            if "splug" not in line:
                continue
            words = _words(line)
            if words is None:
                continue
            for args in _commands_of(words):
                call = _call(path, lineno, args, assigned)
                if call is not None:
                    out.append(call)
    return tuple(out)


#: nsplug's value of a macro given as a bare ``NAME`` (on its command line, or
#: ``#define NAME`` with no value)
DEFINED = "<defined>"
#: ``NAME=value`` at the start of a line: a shell variable's assignment
_ASSIGNMENT = re.compile(r"^[ \t]*(?:export[ \t]+|local[ \t]+)?(\w+)\+?=(.*)$", re.M)
#: the start of a here-document, and the word that ends it
_HEREDOC = re.compile(r"<<-?[ \t]*[\"']?(\w+)[\"']?")
#: words before a command that are not the command
_PREFIXES = frozenset({"then", "do", "else", "elif", "if", "while", "until", "!", "time", "exec"})
_SEPARATORS = frozenset({";", "&", "&&", "|", "||", ";;", "(", ")", "{", "}"})
#: options of nsplug that take no argument and define nothing
_PLAIN_OPTIONS = frozenset({"-f", "--force", "-i", "--interactive", "-I", "--impatient"})
_PLAIN_OPTIONS |= frozenset({"-t", "--terminal"})
#: a shell variable's value, written as a whole word
_VARIABLE = re.compile(r"^\$(?:\{(\w+)\}|(\w+))$")


def _logical_lines(text: str) -> list[tuple[int, str]]:
    """The script's lines with ``\\``-continued lines joined, each with its first line's
    number; here-documents left out."""
    out: list[tuple[int, str]] = []
    pending: list[str] = []
    start = 0
    heredoc: str | None = None  # the word that ends the here-document being read
    for lineno, line in enumerate(text.splitlines(), 1):
        if heredoc is not None:
            if line.strip() == heredoc:
                heredoc = None
            continue  # a here-document's text (a usage message), no command
        if "<<" in line and (m := _HEREDOC.search(line)) is not None:
            heredoc = m.group(1)
        if not pending:
            start = lineno
        if line.endswith("\\"):
            pending.append(line[:-1])
            continue
        pending.append(line)
        out.append((start, " ".join(pending)))
        pending = []
    if pending:
        out.append((start, " ".join(pending)))
    return out


def _words(line: str) -> list[str] | None:
    """The line's shell words (quotes removed) and operators, comments dropped; None
    when the shell quoting cannot be read (an unclosed quote)."""
    out: list[str] = []
    for m in _TOKEN.finditer(line):
        word, operator, comment, stray = m.groups()
        if word is not None:
            out.append(_QUOTED.sub(_unquote, word) if _QUOTES & set(word) else word)
        elif operator is not None:
            out.append(operator)
        elif comment is not None:
            break
        elif stray is not None:
            return None
    return out


def _unquote(m: re.Match) -> str:
    single, double, escaped = m.groups()
    if single is not None:
        return single
    if double is not None:
        return _ESCAPED.sub(r"\1", double)
    return escaped


_PART = r"""(?:[^\s;&|()<>'"\\]|\\.|'[^']*'|"(?:[^"\\]|\\.)*")"""
#: a shell word (not starting a comment), a run of operators, a comment, a stray quote
_TOKEN = re.compile(rf"\s*(?:((?!#){_PART}+)|([;&|()<>]+)|(#.*)|(\S))")
_QUOTED = re.compile(r"""'([^']*)'|"((?:[^"\\]|\\.)*)"|\\(.)""")
_ESCAPED = re.compile(r"\\(.)")
_QUOTES = frozenset("'\"\\")


def _commands_of(words: list[str]) -> list[list[str]]:
    """The argument lists (the program first) of the nsplug commands among ``words``."""
    out: list[list[str]] = []
    command: list[str] = []
    skip_next = False
    for word in [*words, ";"]:
        if skip_next:
            skip_next = False
            continue
        if word in _SEPARATORS:
            if command and os.path.basename(command[0]) in ("nsplug", "splug"):
                out.append(command)
            command = []
        elif set(word) <= set("<>&"):
            skip_next = True  # a redirection and its file
            if command and command[-1].isdigit():
                command.pop()  # the descriptor before ``>``
        elif command or word not in _PREFIXES:
            command.append(word)
    return out


def _call(
    script: str, lineno: int, args: list[str], assigned: dict[str, list[str]]
) -> NsplugCall | None:
    """The call of ``args`` (``nsplug IN OUT ...``): nsplug takes its first argument as
    the template and its second as the output only there, never after an option
    (``main.cpp``: ``setInFile(argv[1])``, ``setOutFile(argv[2])``)."""
    if len(args) < 3 or args[1].startswith("-") or args[2].startswith("-"):
        return None
    macros: dict[str, str | None] | None = {}
    strict = lenient = False
    words = list(args[3:])
    expanded_from: set[str] = set()
    i = 0
    while i < len(words):
        word = words[i]
        i += 1
        var = _VARIABLE.match(word)
        if var is not None:
            name = var.group(1) or var.group(2)
            values = assigned.get(name)
            if name in expanded_from or not values:
                macros = None
                continue
            expanded_from.add(name)
            # the value's words, split again as the shell splits an unquoted expansion
            split = [_words(v) for v in values]
            flags = [f for ws in split for w in (["$"] if ws is None else ws) for f in w.split()]
            if any(not f.startswith("-") for f in flags):
                macros = None  # the variable may hold macros: not known which
                continue
            words[i:i] = flags  # options only (``NSFLAGS="-s -f"``): any of them
            continue
        if word in ("-s", "--strict"):
            strict = True
        elif word in ("-l", "--lenient"):
            lenient = True
        elif word in ("-p", "--path"):
            i += 1
        elif word in _PLAIN_OPTIONS or word.startswith(("--path=", "--tag=")):
            pass
        elif word.startswith("-") or "$" in word.split("=", 1)[0] or "`" in word:
            macros = None  # ``--macros=file``, ``-x``, a macro named by a variable
        elif macros is not None:
            name, eq, value = word.partition("=")
            known = not any(c in word for c in "$`*?[")
            macros[name.strip()] = (value.strip() if eq else DEFINED) if known else None
    return NsplugCall(
        script,
        lineno,
        os.path.normpath(os.path.join(os.path.dirname(script), args[1])),
        args[2],
        None if macros is None else tuple(sorted(macros.items())),
        strict,
        lenient,
    )


def _assignments(text: str) -> dict[str, list[str]]:
    """Each shell variable's assigned values in the script, as written."""
    out: dict[str, list[str]] = {}
    for m in _ASSIGNMENT.finditer(text):
        out.setdefault(m.group(1), []).append(m.group(2).split("#", 1)[0].strip())
    return out
