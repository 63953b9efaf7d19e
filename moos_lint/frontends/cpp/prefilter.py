"""A bytes prefilter: only files that mention the MOOS API are parsed."""

from __future__ import annotations

import re

#: the MOOS API's names, each a whole word
_WORDS = (
    b"Notify",
    b"Register",
    b"UnRegister",
    b"CMOOSApp",
    b"AppCastingMOOSApp",
    b"CMOOSInstrument",
    b"OnNewMail",
    b"OnStartUp",
    b"GetConfigurationParam",
    b"CMOOSSerialPort",
    b"getBufferDoubleVal",
    b"getBufferDoubleValX",
)

#: ``\b(?:Notify|Register|...)\b|\.Run\s*\(`` as one pattern per name, each literal first
#: (``Notify(?<=\bNotify)\b``): a search skips ahead to a leading literal, but tries an
#: alternation at every byte (40% faster over a repository's C++)
_MOOS_API = (
    *(re.compile(rb"%s(?<=\b%s)\b" % (w, w)) for w in _WORDS),
    re.compile(rb"\.Run\s*\("),
)


#: every match of the pattern holds one of these: a file without any is never searched
_NEEDLES = (
    b"Notify",
    b"Register",
    b"CMOOS",
    b"AppCastingMOOSApp",
    b"OnNewMail",
    b"OnStartUp",
    b"GetConfigurationParam",
    b".Run",
    b"getBufferDoubleVal",
)


def mentions_moos(data: bytes) -> bool:
    """Whether a C++ file mentions any MOOS API (cheap, on bytes)."""
    if not any(needle in data for needle in _NEEDLES):
        return False
    return any(p.search(data) for p in _MOOS_API)
