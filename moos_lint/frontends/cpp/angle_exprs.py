"""Reading value expressions of C++ for angles, headings, depths and positions.

The expressions are the ``expanded`` text of :class:`~moos_lint.frontends.cpp.model.Value`:
local variables are replaced by what they were assigned, and wraps found on
the way are written ``__wrap_pi(...)`` / ``__wrap_2pi(...)``.
"""

from __future__ import annotations

import math
import re

from moos_lint.frontends.cpp.extract import WRAP_2PI, WRAP_PI
from moos_lint.frontends.cpp.names import axis_word, last_word, words

PI = r"(?:M_PI|\bPI\b|\bpi\b|3\.14\d*)"
#: heading-ish identifiers (a word of the name)
HEADING_WORD = r"\w*(?:heading|Heading|HEADING|hdg|Hdg|HDG)\w*"
_TERM = r"[A-Za-z_][\w.]*(?:(?:->|\.)\w+)*(?:\(\s*\))?"
DEG2RAD_CALLS = ("MOOSDeg2Rad", "degToRadians", "deg2rad", "DEG2RAD", "degToRad", "deg_to_rad")
RAD2DEG_CALLS = (
    "MOOSRad2Deg",
    "radToDegrees",
    "rad2deg",
    "RAD2DEG",
    "radToDeg",
    "rad_to_deg",
    "radToHeading",
)
_DEG2RAD = re.compile(
    r"(?:" + "|".join(DEG2RAD_CALLS) + r")\s*\(|"
    r"\*\s*\(?\s*" + PI + r"\s*/\s*180|" + PI + r"\s*/\s*180|/\s*180(?:\.0*)?\s*\*\s*" + PI
)
_RAD2DEG = re.compile(
    r"(?:" + "|".join(RAD2DEG_CALLS) + r")\s*\(|180(?:\.0*)?\s*/\s*" + PI + r"|57\.29"
)
_INV_TRIG = re.compile(r"\b(?:std::)?(?:atan2|atan|asin|acos)f?\s*\(")
_ARITH = re.compile(r"(?<![eE(,=\s])\s*[-+*/]\s*(?!=)|[^\s(,=]\s+[-+*/]\s")


def is_yaw_var(name: str) -> bool:
    return axis_word(name) == "YAW"


def is_heading_var(name: str) -> bool:
    return axis_word(name) in ("HEADING", "HDG")


def is_z_var(name: str) -> bool:
    """``NAV_Z``, ``Z``, or the known end of a name built on a prefix (``prefix + "_Z"``);
    not a one-letter word inside another name."""
    return last_word(name) == "Z" and (len(words(name)) > 1 or name == "Z" or name.startswith("_"))


def is_latlong_var(name: str) -> bool:
    return last_word(name) in ("LAT", "LON", "LONG", "LATITUDE", "LONGITUDE")


#: the last words of a speed (``NAV_SPEED``, ``GPS_SOG``, ``WATER_STW``)
SPEED_WORDS = ("SPEED", "SOG", "STW")
#: words that name a speed's unit in a variable's own name (``SPEED_KNOTS``)
SPEED_UNIT_WORDS = {"KNOTS", "KNOT", "KTS", "KN", "KMH", "KPH", "KMPH", "MPH"}


def is_speed_var(name: str) -> bool:
    """A speed in metres per second by its name: ``NAV_SPEED``, ``GPS_SOG``; not one whose
    name gives it another unit (``SPEED_KNOTS``: non-si-unit's business)."""
    ws = [w.upper() for w in words(name)]
    return bool(ws) and ws[-1] in SPEED_WORDS and not SPEED_UNIT_WORDS & set(ws)


def is_other_angle_var(name: str) -> bool:
    return axis_word(name) in ("ROLL", "PITCH")


def is_depth_var(name: str) -> bool:
    return last_word(name) == "DEPTH"


_ANGLE_WORDS = {"YAW", "PITCH", "ROLL", "TURN", "HEADING", "HDG"}

#: the actuators of the MOOS Conventions, each a quantity of its own
_ACTUATOR_WORDS = {"THRUST", "RUDDER", "ELEVATOR"}


def quantity(name: str) -> str | None:
    """The kind of quantity a variable holds by its name's last word, as a message names
    it: an angle (a heading, yaw, pitch or roll: one kind, since a sensor mounted on its
    side publishes one axis under another's name), a speed, a depth or height, a position
    (x, y, latitude, longitude: NED and ENU exchange x and y), each actuator; None for any
    other name (a rate, an error, a count)."""
    ws = [w.upper() for w in words(name)]
    if not ws:
        return None
    if is_heading_var(name) or is_yaw_var(name) or is_other_angle_var(name):
        return "an angle"
    if is_speed_var(name):
        return "a speed"
    if is_depth_var(name) or is_z_var(name) or ws[-1] == "ALTITUDE":
        return "a depth or height"
    if is_latlong_var(name) or (len(ws) > 1 and ws[-1] in ("X", "Y")):
        return "a position"
    if ws[-1] in _ACTUATOR_WORDS:
        return f"the {ws[-1].lower()}"
    return None


def is_rate_var(name: str) -> bool:
    """An angular rate: a gyro axis (``IMU_GYRO_Z``) or an angle's ``RATE`` (``YAW_RATE``)."""
    ws = [w.upper() for w in words(name)]
    if any(w in ("GYRO", "GYR") for w in ws):
        return True
    return len(ws) > 1 and ws[-1] == "RATE" and ws[-2] in _ANGLE_WORDS


def strip_calls(expr: str, names: set[str] | frozenset[str]) -> str:
    """``expr`` with each call to one of ``names`` (its arguments included) replaced by ``W``."""
    out = expr
    for _ in range(20):
        m = re.search(r"\b(" + "|".join(map(re.escape, sorted(names))) + r")\s*\(", out)
        if not m:
            break
        depth, i = 0, m.end() - 1
        while i < len(out):
            if out[i] == "(":
                depth += 1
            elif out[i] == ")":
                depth -= 1
                if depth == 0:
                    break
            i += 1
        out = out[: m.start()] + "W" + out[i + 1 :]
    return out


def outer_wrap(expr: str) -> str | None:
    """ "pi" or "2pi" when the whole expression is one wrap call, else None."""
    e = _strip_outer_parens(expr.strip())
    for kind, names in (("pi", WRAP_PI), ("2pi", WRAP_2PI)):
        m = re.match(r"^(?:" + "|".join(map(re.escape, sorted(names))) + r")\s*\(", e)
        if m and _strip_calls_all(e) == "W":
            return kind
    m = re.match(r"^(?:std::)?fmod\s*\((.*),\s*(.*)\)$", e, re.S)
    if m and _TWO_PI_RE.search(m.group(2)) and _strip_calls_all(e) == "W":
        return "2pi"
    return None


_TWO_PI_RE = re.compile(r"2(?:\.0*)?\s*\*\s*" + PI + r"|M_2PI|TWO_PI")


def _strip_calls_all(expr: str) -> str:
    return strip_calls(expr, {*WRAP_PI, *WRAP_2PI, "fmod", "std::fmod"})


def _strip_outer_parens(e: str) -> str:
    while e.startswith("(") and e.endswith(")") and _balanced(e[1:-1]):
        e = e[1:-1].strip()
    return e


def _balanced(s: str) -> bool:
    d = 0
    for ch in s:
        d += ch == "("
        d -= ch == ")"
        if d < 0:
            return False
    return d == 0


def has_arithmetic(expr: str) -> bool:
    """Binary arithmetic (or a degrees-to-radians call) outside any wrap."""
    e = _strip_outer_parens(strip_calls(expr, {*WRAP_PI, *WRAP_2PI}).strip())
    if re.search(r"(?:" + "|".join(DEG2RAD_CALLS) + r")\s*\(", e):
        return True
    e = re.sub(r"\w+\s*\([^()]*\)", "F", e)  # other calls are opaque
    e = re.sub(r"^[\s(]*-", "", e)  # a leading negation keeps ±π
    e = re.sub(r"(?<=[(,])\s*-", "", e)
    e = re.sub(r"->", ".", e)
    e = re.sub(r"\d\.?\d*[eE][-+]\d+", "1", e)
    return bool(re.search(r"[\w)\]]\s*[-+*/]\s*[\w(.]", e))


def converts_to_degrees(expr: str) -> bool:
    return bool(_RAD2DEG.search(expr))


def converts_to_radians(expr: str) -> bool:
    return bool(_DEG2RAD.search(expr))


def looks_radian(expr: str) -> str | None:
    """Why the value is in radians (a short reason), or None."""
    if converts_to_degrees(expr):
        return None
    if _INV_TRIG.search(expr):
        return "an inverse trigonometric result (radians)"
    if converts_to_radians(expr):
        return "converted to radians"
    if re.search(r"\bheadingToRadians\s*\(", expr):
        return "converted to radians"
    e = _strip_outer_parens(expr.strip())
    m = re.fullmatch(r"-?\s*(" + _TERM + r")", e)
    if m and re.search(r"(?:^|[_.>])(?:m_)?(?:yaw|Yaw|YAW)\b|_rad\b|Rad\b|_rads\b", m.group(1)):
        return f"`{m.group(1)}` holds radians"
    if re.search(PI, expr) and not re.search(r"\b180\b", expr):
        return "an expression in π"
    return None


def heading_to_rad_without_minus(expr: str) -> re.Match | None:
    """A heading turned into radians as ``+heading·π/180`` (no minus sign before it)."""
    patterns = [
        r"(?P<h>" + HEADING_WORD + r")\s*\*\s*\(?\s*" + PI + r"\s*/\s*180(?:\.0*)?",
        r"(?P<h>" + HEADING_WORD + r")\s*/\s*180(?:\.0*)?\s*\*\s*" + PI,
        r"\(?\s*"
        + PI
        + r"\s*/\s*180(?:\.0*)?\s*\)?\s*\*\s*(?P<h>"
        + HEADING_WORD
        + r")\b(?!\s*\()",
        r"(?:" + "|".join(DEG2RAD_CALLS) + r")\s*\(\s*(?P<h>"
        r"(?:angle180|angle360)?\s*\(?\s*" + HEADING_WORD + r"\s*\)?)\s*\)",
    ]
    for pat in patterns:
        for m in re.finditer(pat, expr):
            if _negated(expr, m.start(), m.start("h")):
                continue
            return m
    return None


def _negated(expr: str, start: int, hstart: int) -> bool:
    """A minus sign right before the conversion (through parentheses) or before the heading."""
    inner = expr[start:hstart]
    if re.search(r"-\s*\(?\s*$", inner):
        return True
    i = start - 1
    while i >= 0 and expr[i] in " (\t":
        i -= 1
    if i >= 0 and expr[i] == "-":
        return True
    # (-heading) * M_PI / 180
    j = hstart - 1
    while j >= 0 and expr[j] in " (\t":
        j -= 1
    return j >= 0 and expr[j] == "-"


def depth_without_negation(expr: str) -> str | None:
    """The depth term when the value is a depth as is (``m_depth``, ``rec.getDepth()``)."""
    e = _strip_outer_parens(expr.strip())
    m = re.fullmatch(r"\+?\s*(" + _TERM + r")", e)
    if (
        m
        and re.search(r"depth|Depth|DEPTH", m.group(1))
        and not re.search(
            r"(?:z|Z)", re.sub(r"depth|Depth|DEPTH", "", m.group(1)).replace("get", "")
        )
    ):
        return m.group(1)
    return None


def heading_term(expr: str) -> str | None:
    """The value is taken from a heading / hdg / deg name without conversion."""
    if converts_to_radians(expr) or re.search(PI, expr):
        return None
    e = _strip_outer_parens(expr.strip())
    m = re.fullmatch(r"-?\s*(" + _TERM + r")", e)
    if m and re.search(r"heading|Heading|HEADING|hdg|Hdg|HDG|_deg\b|Deg\b|degrees", m.group(1)):
        return m.group(1)
    m = re.fullmatch(r"(?:angle360|angle180)\s*\((.*)\)", e)
    if m:
        return "angle360/angle180 (degrees)"
    return None


def literal_over_two_pi(number: float | None) -> bool:
    return number is not None and abs(number) > 2 * math.pi + 1e-9


# -- one angle, two units ---------------------------------------------------------

#: calls that keep an angle in its unit and only wrap it (their argument is the angle)
_WRAPS = frozenset({*WRAP_PI, *WRAP_2PI, "angle180", "angle360"})
_PI_FACTOR = re.compile(
    PI + r"|\(?\s*4(?:\.0*)?\s*\*\s*(?:std::)?atan\s*\(\s*1(?:\.0*)?\s*\)\s*\)?"
)
_180 = re.compile(r"180(?:\.0*)?[fF]?")
_DEG_PER_RAD = re.compile(r"57\.29\d*[fF]?")  # 180/π written out
_RAD_PER_DEG = re.compile(r"0?\.01745\d*[fF]?")  # π/180 written out


def _call_of(e: str, names) -> tuple[str, str] | None:
    """(name, argument) when ``e`` is one call of one of ``names`` with one argument."""
    m = re.match(r"(?:std::)?(\w+)\s*\(", e)
    if m is None or m.group(1) not in names or not e.endswith(")"):
        return None
    inner = e[m.end() : -1]
    if not _balanced(inner) or _top_level(inner, ","):
        return None
    return m.group(1), inner.strip()


def _top_level(e: str, chars: str) -> list[int]:
    """Where ``chars`` stand in ``e`` outside parentheses and brackets (a sign that follows
    an operator, or opens the expression, is not a binary operator: left out)."""
    found, depth, prev = [], 0, ""
    for i, ch in enumerate(e):
        if ch in "([":
            depth += 1
        elif ch in ")]":
            depth -= 1
        elif depth == 0 and ch in chars:
            unary = ch in "+-" and (not prev or prev in "(*/+-,=<>!?:" or e[i - 1 : i + 1] == "e-")
            if not unary and not (ch == "-" and e[i : i + 2] == "->"):
                found.append(i)
        if not ch.isspace():
            prev = ch
    return found


def _unsigned(e: str) -> tuple[int, str]:
    """``e`` without its outer parentheses and leading minus signs, and the sign they made."""
    sign = 1
    while True:
        e = _strip_outer_parens(e.strip())
        if e.startswith("-") and not _top_level(e[1:], "+-"):
            sign, e = -sign, e[1:]
        elif e.startswith("+") and not _top_level(e[1:], "+-"):
            e = e[1:]
        else:
            return sign, e


#: the calls that turn an angle into the other unit -> the unit they give
_CONVERSIONS = {
    **{name: "rad" for name in (*DEG2RAD_CALLS, "radians")},
    **{name: "deg" for name in (*RAD2DEG_CALLS, "degrees")},
}


def angle_conversion(expr: str) -> tuple[int, str, str | None]:
    """What a published angle is made of: ``(sign, angle, conversion)``, wraps left out.
    ``conversion`` is ``"rad"`` for ``angle·π/180`` (``MOOSDeg2Rad(angle)``, ``π/180·angle``),
    ``"deg"`` for ``angle·180/π``, None when the value is ``angle`` itself; ``sign`` is -1
    when a minus sign (or a ``-180``) stands before it. ``angle`` is the expression's text
    without spaces: ``-(angle360(h*180/M_PI))`` gives ``(-1, "h", "deg")``."""
    sign, e = _unsigned(expr)
    conversion = None
    while True:  # (each step takes a call or factors off: ``e`` gets shorter)
        wrap = _call_of(e, _WRAPS)
        if wrap is not None:
            e = wrap[1]
        elif conversion is not None:
            break  # (after the conversion, only wraps are taken off)
        elif (call := _call_of(e, _CONVERSIONS)) is not None:
            conversion, e = _CONVERSIONS[call[0]], call[1]
        elif (product := _product(e)) is not None:
            s, conversion, e = product
            sign *= s
        else:
            break
        s, e = _unsigned(e)
        sign *= s
    return sign, re.sub(r"\s+", "", e), conversion


def _factors(e: str) -> list[tuple[str, str]] | None:
    """``e``'s factors, each with the operator before it (``*`` for the first), when ``e``
    is a product or quotient; None when it has a top-level sum or condition."""
    if _top_level(e, "+-?"):
        return None
    out, start, op = [], 0, "*"
    for at in [*_top_level(e, "*/"), len(e)]:
        out.append((op, e[start:at]))
        op = e[at] if at < len(e) else op
        start = at + 1
    return out


def _product(e: str) -> tuple[int, str, str] | None:
    """``(sign, conversion, angle)`` when ``e`` is ``angle`` times π/180 or 180/π (in any
    order of its factors), else None."""
    factors: list[tuple[str, str]] = []  # (op, factor), products in parentheses opened
    flip = {"*": "/", "/": "*"}
    for op, part in _factors(e) or ():
        s, f = _unsigned(part)
        if s < 0:
            factors.append(("*", "-1"))
        inner = _constant_factors(f)
        if inner is None:
            factors.append((op, f))
        else:  # `(M_PI/180.0)`: its factors, turned over under a division
            factors.extend((o if op == "*" else flip[o], x) for o, x in inner)
    sign, pi, deg, rest = 1, 0, 0, []
    for op, f in factors:
        up = 1 if op == "*" else -1
        if f.startswith("-"):
            sign, f = -sign, f.lstrip("-").strip()
        if f == "1":
            continue
        if _PI_FACTOR.fullmatch(f):
            pi += up
        elif _180.fullmatch(f):
            deg += up
        elif _DEG_PER_RAD.fullmatch(f):
            deg, pi = deg + up, pi - up
        elif _RAD_PER_DEG.fullmatch(f):
            deg, pi = deg - up, pi + up
        elif up == 1:
            rest.append(f)
        else:
            return None
    if len(rest) != 1:
        return None
    if (pi, deg) == (1, -1):
        return sign, "rad", rest[0]
    if (pi, deg) == (-1, 1):
        return sign, "deg", rest[0]
    return None


def _constant_factors(e: str) -> list[tuple[str, str]] | None:
    """The factors of ``e`` when it is a product of numbers and π only (``M_PI/180.0``)."""
    factors = _factors(e)
    if factors is None or len(factors) < 2:
        return None
    out = [(op, _strip_outer_parens(f.strip())) for op, f in factors]
    constant = re.compile(r"-?[\d.]+[fF]?")
    if all(_PI_FACTOR.fullmatch(f.lstrip("-")) or constant.fullmatch(f) for _op, f in out):
        return out
    return None
