"""A bytes prefilter: only files that mention the MOOS API are parsed."""

from __future__ import annotations

import re

_MOOS_API = re.compile(
    rb"\b(?:Notify|Register|UnRegister|CMOOSApp|AppCastingMOOSApp|CMOOSInstrument|"
    rb"OnNewMail|OnStartUp|GetConfigurationParam|CMOOSSerialPort)\b|\.Run\s*\("
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
)


def mentions_moos(data: bytes) -> bool:
    """Whether a C++ file mentions any MOOS API (cheap, on bytes)."""
    if not any(needle in data for needle in _NEEDLES):
        return False
    return _MOOS_API.search(data) is not None
