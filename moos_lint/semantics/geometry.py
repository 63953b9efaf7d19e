"""Local-grid coordinates in MOOS-IvP geometry strings.

Only the forms MOOS-IvP's geometry library (``string2Poly``, ``string2Point``,
``string2SegList``) and uSimMarine's ``start_pos`` read, and only when every
part is understood; anything else gives ``None`` (never a guess):

- vertex lists ``60,-40 : 60,-160 : 150,-160``, optionally with ``x,y,z``
  vertices and abbreviated properties (``label,A : 40,-270 : ...``);
- ``pts={60,-40 : 60,-160}, label=foo``;
- keyed forms with a centre or a point: ``x=75, y=-75, ...``, optionally
  ``format=radial|ellipse|lawnmower|...`` or prefixed ``radial::``,
  ``ellipse::``;
- the short radial form ``radial: 20, -80, 20, 8``;
- uSimMarine ``start_pos``: ``x=0, y=-20, heading=180`` or ``80, 0, 180, 0``.

Values holding a macro (``$(X)``, ``%(X)``, ``$[X]``) are unknown.
"""

from __future__ import annotations

import math
import re

Point = tuple[float, float]

_NUMBER = re.compile(r"^[+-]?(\d+\.?\d*|\.\d+)([eE][+-]?\d+)?$")
_PTS = re.compile(r"\bpts\s*=\s*\{([^{}]*)\}", re.IGNORECASE)
_PREFIX = re.compile(r"^(radial|ellipse|wedge|piewedge|rangewedge)\s*::", re.IGNORECASE)
#: formats whose x= and y= give the centre of the shape
_CENTRED = {"radial", "ellipse", "wedge", "piewedge", "rangewedge", "lawnmower", "bowtie"}


def _num(text: str) -> float | None:
    text = text.strip()
    if not _NUMBER.match(text):
        return None
    value = float(text)
    return value if math.isfinite(value) else None


def _unknown(text: str) -> bool:
    return "$(" in text or "%(" in text or "$[" in text


def _vertex(text: str) -> Point | None:
    """``x,y`` or ``x,y,z`` (all numbers)."""
    parts = text.split(",")
    if len(parts) not in (2, 3):
        return None
    nums = [_num(p) for p in parts]
    if any(n is None for n in nums):
        return None
    return nums[0], nums[1]  # type: ignore[return-value]


def _vertex_list(text: str, allow_props: bool) -> list[Point] | None:
    """``x,y : x,y : ...``; abbreviated ``name,value`` properties are skipped."""
    out: list[Point] = []
    for piece in text.split(":"):
        piece = piece.strip()
        if not piece:
            continue
        pt = _vertex(piece)
        if pt is not None:
            out.append(pt)
            continue
        head = piece.split(",", 1)[0].strip()
        if allow_props and re.fullmatch(r"[A-Za-z_][A-Za-z_0-9]*", head) and "," in piece:
            continue  # e.g. label,transit
        return None
    return out or None


def _keyed(text: str) -> dict[str, str] | None:
    """``k=v, k=v``: None unless every piece is a ``k=v`` pair."""
    out: dict[str, str] = {}
    for piece in text.split(","):
        key, eq, value = piece.partition("=")
        if not eq or not key.strip():
            return None
        out.setdefault(key.strip().lower(), value.strip())
    return out


def _xy(pairs: dict[str, str]) -> list[Point] | None:
    x, y = _num(pairs.get("x", "")), _num(pairs.get("y", ""))
    if x is None or y is None:
        return None
    return [(x, y)]


def geometry_points(value: str) -> list[Point] | None:
    """The local-grid points a geometry string names (vertices, centre or point)."""
    text = value.strip()
    if not text or _unknown(text):
        return None
    m = _PTS.search(text)
    if m:
        return _vertex_list(m.group(1), allow_props=False)
    m = _PREFIX.match(text)
    if m:
        pairs = _keyed(text[m.end() :])
        return _xy(pairs) if pairs is not None else None
    if re.match(r"^radial\s*:", text, re.IGNORECASE):
        parts = text.split(":", 1)[1].split(",")
        if len(parts) >= 4:
            x, y = _num(parts[0]), _num(parts[1])
            if x is not None and y is not None:
                return [(x, y)]
        return None
    if "=" in text:
        pairs = _keyed(text)
        if pairs is None:
            return None
        fmt = pairs.get("format")
        if fmt is not None and fmt.lower() not in _CENTRED:
            return None
        return _xy(pairs)
    return _vertex_list(text, allow_props=True)


def start_pos_points(value: str) -> list[Point] | None:
    """uSimMarine ``start_pos``: ``x=..,y=..,heading=..`` or positional ``x,y,hdg,spd,dep``."""
    text = value.strip()
    if not text or _unknown(text):
        return None
    x = y = None
    for i, piece in enumerate(text.split(",")):
        key, eq, val = piece.partition("=")
        if not eq:
            key, val = ("x", "y", "heading", "speed", "depth")[i] if i < 5 else "", key
        key = key.strip().lower()
        if key == "x":
            x = _num(val)
        elif key == "y":
            y = _num(val)
    if x is None or y is None:
        return None
    return [(x, y)]
