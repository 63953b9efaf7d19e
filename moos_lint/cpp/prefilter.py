"""A bytes prefilter: only files that mention the MOOS API are parsed."""

from __future__ import annotations

import re

CPP_SUFFIXES = (".cpp", ".cc", ".cxx", ".h", ".hpp")

_MOOS_API = re.compile(
    rb"\b(?:Notify|Register|UnRegister|CMOOSApp|AppCastingMOOSApp|CMOOSInstrument|"
    rb"OnNewMail|OnStartUp|GetConfigurationParam|CMOOSSerialPort)\b|\.Run\s*\("
)


def mentions_moos(data: bytes) -> bool:
    """Whether a C++ file mentions any MOOS API (cheap, on bytes)."""
    return _MOOS_API.search(data) is not None
