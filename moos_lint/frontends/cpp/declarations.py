"""Functions the repository declares itself, found by name in the bytes of its C++ files.

A call's meaning may hang on which function it reaches: a repository that declares
its own ``LatLong2LocalUTM(double Lat, double Lon, double &x, double &y)`` does not
follow CMOOSGeodesy's order. Only files whose bytes hold the name are decoded.
"""

from __future__ import annotations

import re
from collections.abc import Callable, Iterable

#: a declaration or definition's parameter list: ``NAME(double a, double &b, ...)`` with a
#: type in front of the first parameter (a call passes expressions, not typed names)
_DECLARATION = rb"\b%s\s*\(\s*((?:const\s+)?(?:double|float|long\s+double|int|auto)\b[^;{()]*)\)"


def parameter_names(
    names: Iterable[str], paths: Iterable[str], read: Callable[[str], object]
) -> dict[str, list[list[str]]]:
    """For each of ``names``, the parameter names of every declaration of a function so
    named in ``paths``, in order (``[["Lat", "Lon", "x", "y"]]``)."""
    wanted = {n: re.compile(_DECLARATION % re.escape(n.encode())) for n in names}
    out: dict[str, list[list[str]]] = {}
    for path in paths:
        data = read(path)
        if not isinstance(data, bytes):
            continue
        for name, pattern in wanted.items():
            if name.encode() not in data:
                continue
            for m in pattern.finditer(data):
                params = m.group(1).decode("utf-8", "replace").split(",")
                out.setdefault(name, []).append([_last_word(p) for p in params])
    return out


def _last_word(parameter: str) -> str:
    """A parameter's name: its last word, before any default value."""
    words = re.findall(r"[A-Za-z_]\w*", parameter.split("=")[0])
    return words[-1] if words else ""
