"""Whether MOOS-IvP's geometry parsers read a polygon, point list or point.

A port of ``string2Poly``, ``string2SegList`` and ``string2Point``
(``lib_geometry/XYFormatUtilsPoly.cpp``, ``XYFormatUtilsSegl.cpp``,
``XYFormatUtilsPoint.cpp``), of ``XYPolygon::determine_convexity`` and of the
``lib_mbutil`` helpers they use (``isNumber``, ``biteString``,
``parseString``, ``stripBlankEnds``), for the forms ported exactly:

- polygons: the standard ``pts={x,y:x,y:...}, label=...`` form and the
  abbreviated ``x,y : x,y : label,foo`` form;
- point lists: the same two forms, with ``pts:`` / ``points:`` prefixes;
- points: ``x,y``, ``x:y``, ``x=..,y=..`` and ``x,y:label,foo``.

Every other form (``format=radial``, ``radial:``, ``ellipse:``, ``wedge:``,
``pylon:``, ``oval:``, ``zigzag:``, ``lawnmower:``, edge ``tags=``, ...) and
any value holding a macro is :data:`UNKNOWN`. A polygon whose convexity
depends on a floating-point rounding (a vertex all but on an edge's line) is
also unknown: the verdict must not rest on how the app was compiled.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from fractions import Fraction

from moos_lint.semantics.mbutil import (
    bite,
    bite_x,
    is_number,
    parse_string,
    strip_blank_ends,
    tolower,
)

VALID = "valid"
INVALID = "invalid"
UNKNOWN = "unknown"


@dataclass(frozen=True)
class Verdict:
    status: str
    reason: str = ""


class _Unknown(Exception):
    """A form the port does not follow."""


# --------------------------------------------------------------- lib_mbutil
# (the ports live in moos_lint.semantics.mbutil)


def atof(s: str) -> Fraction:
    """``atof`` of a string :func:`is_number` accepts, exactly."""
    s = s.lstrip(" \t\n\r\v\f")
    sign = 1
    if s[:1] in "+-" and s[:1]:
        sign = -1 if s[0] == "-" else 1
        s = s[1:]
    body = ""
    for c in s:
        if "0" <= c <= "9" or (c == "." and "." not in body):
            body += c
        else:
            break
    if not body.strip("."):
        return Fraction(0)
    whole, _dot, frac = body.partition(".")
    value = Fraction(int(whole or "0")) + (
        Fraction(int(frac), 10 ** len(frac)) if frac else Fraction(0)
    )
    return sign * value


def _coord(s: str) -> Fraction:
    value = atof(s)
    if abs(value) > 10**12:
        raise _Unknown  # far beyond any mission; keeps the double arithmetic exact enough
    return value


# --------------------------------------------------------------- XYObject


_OBJECT_PARAMS = {
    "label",
    "vertex_size",
    "vertex_color",
    "type",
    "msg",
    "id",
    "time",
    "duration",
    "dur",
    "edge_size",
    "edge_color",
    "label_color",
    "fill_color",
    "fill_transparency",
    "source",
    "vsource",
}


@dataclass
class _Shape:
    xs: list[Fraction] = field(default_factory=list)
    ys: list[Fraction] = field(default_factory=list)
    active: bool = True

    def set_param(self, param: str, value: str) -> bool:
        """``XYObject::set_param``: whether the key is one of its own."""
        if param in _OBJECT_PARAMS:
            return True
        if param == "active" and tolower(value) in ("true", "false"):
            self.active = tolower(value) == "true"
            return True
        return False

    def add(self, x: Fraction, y: Fraction) -> None:
        self.xs.append(x)
        self.ys.append(y)

    def size(self) -> int:
        return len(self.xs)

    def seglist_valid(self) -> bool:
        return not (self.size() == 0 and self.active)


# --------------------------------------------------------------- convexity


def _sign(y: float, y3: float) -> int:
    return 0 if y > y3 else 1 if y < y3 else 2


def _side(x1: float, y1: float, x2: float, y2: float, x3: float, y3: float) -> int:
    """``XYPolygon::side`` in double arithmetic, as the C++ computes it.

    Raises :class:`_Unknown` where the answer could depend on rounding: the
    point is all but on the line and one of the steps is inexact (a build that
    fuses multiply-adds could then answer otherwise).
    """
    if x1 == x2:
        if y1 == y2:
            return 2
        return 0 if x3 > x1 else 1 if x3 < x1 else 2
    rise = y2 - y1
    run = x2 - x1
    m = rise / run
    mx2 = m * x2
    b = y2 - mx2
    mx3 = m * x3
    y = mx3 + b
    if not all(math.isfinite(v) for v in (rise, run, m, mx2, b, mx3, y)):
        raise _Unknown
    tol = 1e-12 * (abs(mx3) + abs(mx2) + abs(y2) + abs(b) + abs(y3) + abs(rise))
    if abs(y - y3) > tol:
        return _sign(y, y3)
    F = Fraction
    exact = (
        F(rise) == F(y2) - F(y1)
        and F(run) == F(x2) - F(x1)
        and F(m) * F(run) == F(rise)
        and F(mx2) == F(m) * F(x2)
        and F(b) == F(y2) - F(mx2)
        and F(mx3) == F(m) * F(x3)
        and F(y) == F(mx3) + F(b)
    )
    if not exact:
        raise _Unknown
    return _sign(y, y3)


#: more vertices than this: not judged (the check is quadratic)
MAX_VERTICES = 400


def is_convex(xs: list[Fraction], ys: list[Fraction]) -> bool:
    """``XYPolygon::determine_convexity`` then ``is_convex()``."""
    n = len(xs)
    if n < 3:
        return False
    if n > MAX_VERTICES:
        raise _Unknown
    fx = [float(x) for x in xs]
    fy = [float(y) for y in ys]
    for ix in range(n):
        ixx = 0 if ix == n - 1 else ix + 1
        state = -1
        fresh = True
        for j in range(n):
            if j in (ix, ixx):
                continue
            s = _side(fx[ix], fy[ix], fx[ixx], fy[ixx], fx[j], fy[j])
            if s != 2:
                if fresh:
                    state, fresh = s, False
                elif s != state:
                    state = -1
        if state == -1:
            return False
    return True


# --------------------------------------------------------------- polygons


@dataclass
class _Poly(_Shape):
    convex: bool = False
    why: str = ""


def _pts_vertices(shape: _Shape, pstr: str, allow_xy_keys: bool) -> str:
    """The vertices of a ``pts={...}`` body; the reason it fails, or ''."""
    for n, piece in enumerate(parse_string(pstr, ":"), 1):
        vertex = strip_blank_ends(piece)
        xstr, vertex = bite_x(vertex, ",")
        ystr, vertex = bite_x(vertex, ",")
        if allow_xy_keys:
            if xstr.startswith("x="):
                xstr = bite_x(xstr, "=")[1]
            if ystr.startswith("y="):
                ystr = bite_x(ystr, "=")[1]
        if not is_number(xstr) or not is_number(ystr):
            return _vertex_why(n, piece, xstr, ystr)
        shape.add(_coord(xstr), _coord(ystr))
    return ""


def _vertex_why(n: int, piece: str, xstr: str, ystr: str) -> str:
    piece = strip_blank_ends(piece)
    if not piece:
        return f"vertex {n} is empty"
    if not ystr:
        return f"vertex {n} `{piece}` has no y"
    bad = xstr if not is_number(xstr) else ystr
    return f"vertex {n} `{piece}`: `{bad}` is not a number"


def _z_why(n: int, piece: str, zstr: str) -> str:
    return f"vertex {n} `{strip_blank_ends(piece)}`: `{zstr}` is not a number"


def _standard_poly(s: str) -> _Poly:
    """``stringStandard2Poly``."""
    poly = _Poly()
    rest = strip_blank_ends(s)
    saw_pts = False
    while rest:
        left, rest = bite(rest, "=")
        left = strip_blank_ends(left)
        rest = strip_blank_ends(rest)
        if left == "pts":
            saw_pts = True
            pstr, rest = bite_x(rest, "}")
            if not pstr or pstr[0] != "{":
                return _Poly(why="`pts=` is not followed by `{`")
            pstr = pstr[1:]
            if rest:
                if rest[0] != ",":
                    return _Poly(why="`pts={...}` is not followed by a comma")
                rest = rest[1:]
            why = _pts_vertices(poly, pstr, allow_xy_keys=False)
            if why:
                return _Poly(why=why)
        else:
            right, rest = bite(rest, ",")
            rest = strip_blank_ends(rest)
            poly.set_param(left, strip_blank_ends(right))
    poly.convex = is_convex(poly.xs, poly.ys)
    if poly.convex:
        return poly
    null = _Poly(why=_convex_why(poly.size()) if saw_pts else "")
    if not poly.active:
        null.active = False
    return null


def _abbreviated_poly(s: str) -> _Poly:
    """``stringAbbreviated2Poly``."""
    poly = _Poly()
    for n, piece in enumerate(parse_string(s, ":"), 1):
        left, rest = bite_x(strip_blank_ends(piece), ",")
        left = tolower(left)
        if poly.set_param(left, rest):
            continue
        ystr, zstr = bite_x(rest, ",")
        if zstr and not is_number(zstr):
            return _Poly(why=_z_why(n, piece, zstr))
        if not is_number(left) or not is_number(ystr):
            return _Poly(why=_vertex_why(n, piece, left, ystr))
        poly.add(_coord(left), _coord(ystr))
    poly.convex = is_convex(poly.xs, poly.ys)
    poly.why = _convex_why(poly.size())
    return poly


def _convex_why(size: int) -> str:
    if size == 0:
        return "no vertices"
    if size < 3:
        word = "vertex" if size == 1 else "vertices"
        return f"only {size} {word}: a polygon needs 3"
    return "the polygon is not convex"


_POLY_FORMATS = ("radial", "ellipse", "wedge", "piewedge", "rangewedge", "pylon", "oval")


def _has_macro(s: str) -> bool:
    return "$(" in s or "%(" in s or "$[" in s or "\x00" in s


def _string2poly(s: str) -> _Poly:
    """``string2Poly`` for the forms ported; raises :class:`_Unknown` for others."""
    if _has_macro(s):
        raise _Unknown
    s = strip_blank_ends(s)
    standard = _standard_poly(s)
    if standard.active is False and standard.size() == 0:
        return standard  # valid(): an inactive polygon without vertices
    if standard.convex:
        return standard
    if "format" in s:
        nw = s.replace(" ", "").replace("\t", "")
        if any("format=" + f in nw for f in _POLY_FORMATS):
            raise _Unknown
    if any(s.startswith(f + ":") for f in _POLY_FORMATS):
        raise _Unknown
    got = _abbreviated_poly(s)
    if standard.why and not got.convex and "pts" in s:
        got.why = standard.why
    return got


def convex_polygon(value: str) -> Verdict:
    """Whether ``string2Poly(value).is_convex()``."""
    try:
        poly = _string2poly(value)
    except _Unknown:
        return Verdict(UNKNOWN)
    if poly.convex:
        return Verdict(VALID)
    return Verdict(INVALID, poly.why or "no vertices")


def polygon_size(value: str) -> int | None:
    """``string2Poly(value).size()``, None when unknown."""
    try:
        return _string2poly(value).size()
    except _Unknown:
        return None


# --------------------------------------------------------------- point lists


def _standard_segl(s: str) -> tuple[_Shape, str]:
    """``stringStandard2SegList``."""
    segl = _Shape()
    rest = s
    while rest:
        left, rest = bite_x(rest, "=")
        if left == "tags":
            raise _Unknown
        if left == "pts":
            pstr, rest = bite_x(rest, "}")
            if not pstr or pstr[0] != "{":
                return _Shape(), "`pts=` is not followed by `{`"
            pstr = pstr[1:]
            if rest:
                if rest[0] != ",":
                    return _Shape(), "`pts={...}` is not followed by a comma"
                rest = rest[1:]
            why = _pts_vertices(segl, pstr, allow_xy_keys=True)
            if why:
                return _Shape(), why
        else:
            right, rest = bite_x(rest, ",")
            segl.set_param(left, right)
    return segl, ""


def _abbreviated_segl(s: str) -> tuple[_Shape, str]:
    """``stringAbbreviated2SegList``."""
    if s.startswith("pts:"):
        s = s[4:]
    if s.startswith("points:"):
        s = s[7:]
    segl = _Shape()
    for n, piece in enumerate(parse_string(s, ":"), 1):
        left, rest = bite(strip_blank_ends(piece), ",")
        left = tolower(strip_blank_ends(left))
        rest = strip_blank_ends(rest)
        if segl.set_param(left, rest):
            continue
        ystr, zstr = bite(rest, ",")
        ystr, zstr = strip_blank_ends(ystr), strip_blank_ends(zstr)
        if zstr and not is_number(zstr):
            return _Shape(), _z_why(n, piece, zstr)
        if not is_number(left) or not is_number(ystr):
            return _Shape(), _vertex_why(n, piece, left, ystr)
        segl.add(_coord(left), _coord(ystr))
    return segl, ""


_SEGL_FORMATS = ("zigzag", "lawnmower", "bowtie")


def _string2segl(s: str) -> tuple[_Shape, str]:
    """``string2SegList`` for the forms ported."""
    if _has_macro(s):
        raise _Unknown
    segl, why = _standard_segl(s)
    if segl.seglist_valid():
        return segl, ""
    if "format" in s:
        nw = s.replace(" ", "").replace("\t", "")
        if any("format=" + f in nw for f in _SEGL_FORMATS):
            raise _Unknown
    if s.startswith(("zigzag:", "lawnmower:")):
        raise _Unknown
    got, why2 = _abbreviated_segl(s)
    return got, (why if why and "pts" in s else why2)


def seglist_size(value: str) -> tuple[int, str] | None:
    """``string2SegList(value).size()`` and why it is empty; None when unknown."""
    try:
        segl, why = _string2segl(value)
    except _Unknown:
        return None
    return segl.size(), why


def waypoints(value: str) -> Verdict:
    """BHV_Waypoint ``points``/``polygon``: ``empty``, ``start``, a point list or a polygon."""
    if tolower(value) in ("empty", "start"):
        return Verdict(VALID)
    got = seglist_size(value)
    if got is None:
        return Verdict(UNKNOWN)
    size, why = got
    if size:
        return Verdict(VALID)
    psize = polygon_size(value)
    if psize is None:
        return Verdict(UNKNOWN)
    if psize:
        return Verdict(VALID)
    return Verdict(INVALID, why or "no points")


# --------------------------------------------------------------- points


def _string2point(s: str) -> bool:
    """``string2Point(s).valid()``."""
    if _has_macro(s):
        raise _Unknown
    for sep in (",", ":"):
        x, y = bite_x(s, sep)
        if is_number(x) and is_number(y):
            return True
    # stringStandard2Point: valid once x= and y= are given (any text)
    x = y = ""
    for piece in parse_string(s, ","):
        param, value = bite_x(piece, "=")
        param = tolower(param)
        if param == "x":
            x = value
        elif param == "y":
            y = value
    if x and y:
        return True
    # stringAbbreviated2Point: any `x,y` or `x,y,z` piece
    shape = _Shape()
    for piece in parse_string(s, ":"):
        param, value = bite_x(piece, ",")
        if shape.set_param(param, value):
            continue
        xstr, ystr, zstr = param, value, ""
        if "," in ystr:
            ystr, zstr = bite_x(value, ",")
        if is_number(xstr) and is_number(ystr) and (is_number(zstr) or zstr == ""):
            return True
    return False


def point(value: str, words: tuple[str, ...] = ()) -> Verdict:
    """Whether ``string2Point(value).valid()`` (or ``value`` lower-cased is one of ``words``)."""
    if words and tolower(value) in words:
        return Verdict(VALID)
    try:
        ok = _string2point(value)
    except _Unknown:
        return Verdict(UNKNOWN)
    if ok:
        return Verdict(VALID)
    return Verdict(INVALID, "no `x,y` point")


def judge(form: str, value: str) -> Verdict:
    """The verdict for one of the geometry forms of the catalogue."""
    try:
        if form == "convex_polygon":
            return convex_polygon(value)
        if form == "waypoints":
            return waypoints(value)
        if form == "point":
            return point(value)
        if form.startswith("point|"):
            return point(value, tuple(form.split("|")[1:]))
    except (ValueError, ArithmeticError, RecursionError):
        return Verdict(UNKNOWN)
    return Verdict(UNKNOWN)


GEOMETRY_FORMS = ("convex_polygon", "waypoints", "point")


def is_geometry_form(form: str) -> bool:
    return form in GEOMETRY_FORMS or form.startswith("point|")


__all__ = [
    "INVALID",
    "UNKNOWN",
    "VALID",
    "Verdict",
    "convex_polygon",
    "is_geometry_form",
    "judge",
    "point",
    "waypoints",
]
