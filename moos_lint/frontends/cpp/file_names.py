"""What one read of a C++ file tells the value analysis's repository resolver.

The resolver (:class:`moos_lint.frontends.cpp.values.RepositoryResolver`) looks for a
function's definition, or for the calls of a record's setter, across every C++ file
of the repository. Its index of a file is taken from the bytes alone, in the same read
that prefilters the file (:func:`moos_lint.frontends.cpp.app.read_relevant`): on the
command line, worker processes read the files, so the process that resolves values
needs no read of its own for them.
"""

from __future__ import annotations

import re
from dataclasses import dataclass

from moos_lint.frontends.cpp.names import WORD_BYTES

#: the definition of function ``%s``: its name, its parameter list and its opening brace
DEF_TEMPLATE = rb"(?:::|\b)%s\s*\([^;{}()]*\)\s*(?:const\s*)?(?:override\s*)?\{"
#: the tail of :data:`DEF_TEMPLATE`: a definition's parameter list and opening brace
_DEF_TAIL = re.compile(rb"\([^;{}()]*\)\s*(?:const\s*)?(?:override\s*)?\{")
_SPACE_BYTES = frozenset(b" \t\n\r\f\v")
#: a setter's name (``setPitch``, ``SetDepth``), matched from its ``et`` (a literal first:
#: a pattern that starts with a class is tried at every byte)
_SETTER = re.compile(rb"et(?<=[Ss]et)[A-Z]\w*")
#: a name that :data:`_SETTER` indexes: the resolver asks for these from the index
SETTER_NAME = re.compile(r"^[Ss]et[A-Z]\w*$")


def defined_names(data: bytes) -> set[bytes]:
    """The names ``data`` may define a function of: exactly the word names ``N`` for
    which ``DEF_TEMPLATE % N`` finds a match (each match holds one ``(``, so none hides
    another, and the name is the word just before it, spaces apart)."""
    names: set[bytes] = set()
    for m in _DEF_TAIL.finditer(data):
        end = m.start()
        while end > 0 and data[end - 1] in _SPACE_BYTES:
            end -= 1
        start = end
        while start > 0 and data[start - 1] in WORD_BYTES:
            start -= 1
        if start < end:
            names.add(data[start:end])
    return names


def setter_names(data: bytes) -> frozenset[bytes]:
    """The setter names ``data`` holds (``setPitch`` of ``rec.setPitch(p)``), each the
    longest run of word bytes from its ``set``: a file that holds a call of ``setX``
    holds the name ``setX``."""
    return frozenset(data[m.start() - 1 : m.end()] for m in _SETTER.finditer(data))


@dataclass(frozen=True, slots=True)
class FileNames:
    """One file's index: the names it may define a function of, the setters it names."""

    defined: frozenset[bytes]
    setters: frozenset[bytes]


def file_names(data: bytes) -> FileNames:
    """The index of a file's bytes."""
    return FileNames(frozenset(defined_names(data)), setter_names(data))
