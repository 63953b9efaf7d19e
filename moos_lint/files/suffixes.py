"""The file names moos-lint reads, by kind: the one definition every layer uses.

Suffixes compare without regard to case (``Foo.CPP`` is C++, ``M.MOOS`` a
mission), as the file discovery always has.
"""

from __future__ import annotations

import enum


class Kind(enum.Enum):
    """The kind of a linted file, which says the reader it goes to."""

    MOOS = "moos"  # .moos, .moos++, .plug, .def
    BHV = "bhv"
    CPP = "cpp"  # C++ sources of MOOS apps


#: missions and their fragments (nsplug plugs and definition files)
MOOS_SUFFIXES = (".moos", ".moos++", ".plug", ".def")
#: helm behavior files
BHV_SUFFIXES = (".bhv",)
#: nsplug templates named for no kind (``moos.meta``, ``ecomapper_bhv.meta``: launch
#: scripts run ``nsplug moos.meta targ.moos``); their text says which kind they are
TEMPLATE_SUFFIXES = (".meta",)
#: C++ translation units
CPP_SOURCE_SUFFIXES = (".cpp", ".cc", ".cxx")
#: C++ headers
CPP_HEADER_SUFFIXES = (".h", ".hpp")
#: every C++ file moos-lint reads
CPP_SUFFIXES = CPP_SOURCE_SUFFIXES + CPP_HEADER_SUFFIXES
#: programs an interpreter runs: pAntler starts ``Run = ./iSonar.py`` like any program,
#: and such a script (pymoos, python-moos, a shell wrapper) reads the block of its stem
SCRIPT_SUFFIXES = (".py", ".sh", ".bash", ".pl", ".rb", ".js", ".lua", ".jar")


def script_stem(program: str) -> str | None:
    """``iSonar`` for a script ``iSonar.py`` (no folder); None for any other program."""
    if "." not in program:  # (most programs: one test)
        return None
    low = program.lower()
    for suffix in SCRIPT_SUFFIXES:
        if low.endswith(suffix) and len(program) > len(suffix):
            return program[: -len(suffix)]
    return None


def is_cpp(path: str) -> bool:
    """Whether the file is C++ (a source or a header)."""
    return path.lower().endswith(CPP_SUFFIXES)


def is_cpp_source(path: str) -> bool:
    """Whether the file is a C++ translation unit (not a header)."""
    return path.lower().endswith(CPP_SOURCE_SUFFIXES)


__all__ = [
    "BHV_SUFFIXES",
    "CPP_HEADER_SUFFIXES",
    "CPP_SOURCE_SUFFIXES",
    "CPP_SUFFIXES",
    "MOOS_SUFFIXES",
    "SCRIPT_SUFFIXES",
    "TEMPLATE_SUFFIXES",
    "Kind",
    "is_cpp",
    "is_cpp_source",
    "script_stem",
]
