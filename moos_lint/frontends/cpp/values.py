"""The value analysis: what unit, sense, range and sign a C++ expression carries.

Each expression of interest (what an app publishes) gets an :class:`AbstractValue`,
computed over the tree-sitter tree: the conversion helpers of MOOS and MOOS-IvP
(:mod:`moos_lint.frontends.cpp.facts`), π/180 arithmetic, inverse trigonometry, negation,
wraps (helpers, ``fmod``, wrap loops and one-sided wrap ``if``s), the units of the
variables read by mail, NMEA fields, and hints in names and same-line comments.
Values flow through locals, through the members assigned in any method of the
folder's classes and through the returns of the folder's functions. A call the
folder does not define stays *pending* under its name, with what was applied to
it, and is resolved across the repository when the apps are linked
(:func:`resolve_pending`). What cannot be known stays unknown: rules report only
known facts.
"""

from __future__ import annotations

import math
import os
import re
from collections import OrderedDict
from collections.abc import Callable, Iterable, Iterator
from dataclasses import dataclass, replace
from typing import Any, Protocol

from moos_lint.frontends.cpp import facts, fields
from moos_lint.frontends.cpp.file_names import (
    DEF_TEMPLATE,
    SETTER_NAME,
    FileNames,
    file_names,
)
from moos_lint.frontends.cpp.names import (
    callee_name,
    displacement_axis,
    function_declarator,
    mail_key_of,
    node_text,
    strip,
)

Range = tuple[float, float]
_EPS = 1e-3


@dataclass(frozen=True, slots=True)
class AbstractValue:
    """What is known of a value. ``None`` fields are unknown."""

    unit: str | None = None  # "deg" | "rad" | "deg/s" | "rad/s" | "m/s" | "kn" | "km/h" | "mph"
    sense: str | None = None  # "heading" (clockwise from north) | "yaw" | "math"
    range: Range | None = None  # in the value's own unit
    sign: str | None = None  # "down" (a depth) | "up" (a Z)
    const: float | None = None
    scale: float = 1.0  # a numeric factor not yet settled (``x * 180`` before ``/ M_PI``)
    why: tuple[str, ...] = ()  # the chain of reasons, source first
    pending: str | None = None  # the function whose return this is, to resolve later
    ops: tuple[tuple[str, Any], ...] = ()  # applied to the pending value, in order
    hint: bool = False  # the unit comes from a name or a comment only
    #: the array an element was read from (``data[0]``), to judge its siblings alike
    origin: str | None = None
    #: for a variable passed to a function defined elsewhere (``pending`` is ``name#index``):
    #: its value before the call, kept when that function turns out not to set it
    fallback: Any = None
    #: a field of an NMEA speed sentence: (its unit if it is read as a speed, the sentence)
    nmea_speed: tuple[str, str] | None = None
    #: a field of an NMEA position sentence read as it is written (ddmm.mmmm): the sentence
    nmea_position: str | None = None
    #: for a method called on an object whose class is declared (``record.getPitch()`` of
    #: a ``NodeRecord& record``): that class, whose setter alone gives the getter's value
    #: (:meth:`RepositoryResolver.set_by`)
    receiver: str | None = None

    @property
    def known(self) -> bool:
        return self.unit is not None or self.sign is not None or self.sense is not None

    def because(self, step: str) -> AbstractValue:
        return replace(self, why=(*self.why, step)) if step not in self.why else self

    @property
    def explanation(self) -> str:
        """The reasons, source first; of several steps at one place, the last says it all."""
        steps = [w for w in self.why if w]
        places = [_place_of(w) for w in steps]
        steps = [  # "`x` set at L" says less than another step at L (a mail read, a getter)
            w
            for w, p in zip(steps, places, strict=True)
            if not (" set at " in w and places.count(p) > 1)
        ]
        kept = []
        for i, w in enumerate(steps):
            p = _place_of(w)
            later = [x for x in steps[i + 1 :] if p and _place_of(x) == p]
            if later and not all(x.startswith(_PASSED) for x in later):
                continue
            # an argument passed where it is read (``f(atof(s))``): where it comes from
            # says more than the call it goes through
            if w.startswith(_PASSED) and p and any(_place_of(x) == p for x in steps[:i]):
                continue
            kept.append(w)
        return "; ".join(kept[-3:])


UNKNOWN = AbstractValue()
_PASSED = "passed to "
_AT = re.compile(r" at (\S+:\d+)\b")


def _place_of(step: str) -> str | None:
    m = _AT.search(step)
    return m.group(1) if m else None


def constant(c: float, why: str = "") -> AbstractValue:
    return AbstractValue(const=c, range=(c, c), why=(why,) if why else ())


def settle(v: AbstractValue, why: str = "") -> AbstractValue:
    """Apply a pending numeric factor: a degree/radian conversion or a loss of the unit."""
    s = v.scale
    if s == 1.0 or v.const is not None:
        return v
    v = replace(v, scale=1.0)
    if s < 0:
        return neg(settle(replace(v, scale=-s), why))
    if abs(s - facts.RAD2DEG) < 1e-3 * facts.RAD2DEG:
        return to_deg(v, why)
    if abs(s - facts.DEG2RAD) < 1e-3 * facts.DEG2RAD:
        return to_rad(v, why)
    if (v.unit is None or v.hint) and v.pending is None:
        raw = _raw_conversion(s)
        if raw is not None:  # a raw reading in hundredths of a degree, in radians
            to, res = raw  # (the reading's resolution keeps what it is: a heading stays one)
            rng = (v.range[0] * res, v.range[1] * res) if v.range else None
            v = replace(v, unit=None, hint=False, range=rng)
            return to_rad(v, why) if to == "rad" else to_deg(v, why)
    if v.pending is not None:
        return replace(v, ops=(*v.ops, ("scale", s)))
    rng = (v.range[0] * s, v.range[1] * s) if v.range else None
    unit = _speed_scaled(v, s)
    out = replace(
        v, unit=unit, range=rng, sense=None, hint=False, why=(), nmea_speed=None, nmea_position=None
    )
    if unit in facts.SPEED_UNITS and why:
        out = out.because(f"{why} converts to {speed_label(unit)}")
    return out


def _raw_conversion(s: float) -> tuple[str, float] | None:
    """A factor that turns a raw reading in a decimal fraction of a unit into the other
    angle unit in one product (``raw / 100.0 * (M_PI / 180.0)``: hundredths of a degree
    into radians): ``("rad", 0.01)`` there; None for any other factor."""
    for to, factor in (("rad", facts.DEG2RAD), ("deg", facts.RAD2DEG)):
        for k in (1, 2, 3, 4):
            for resolution in (10.0**k, 10.0**-k):
                if abs(s - factor * resolution) < 1e-3 * factor * resolution:
                    return to, resolution
    return None


def _speed_scaled(v: AbstractValue, s: float) -> str | None:
    """The unit of a speed ``v`` times ``s``: a conversion to metres per second from the
    unit it has (``kts * 0.514444``, ``kmh / 3.6``), or from metres per second (or a value
    of unknown unit) to knots or miles an hour by their factors (``* 1.94384``); any other
    factor leaves no unit known. Only from metres per second is ``* 3.6`` km/h."""
    unit = v.unit if v.unit in facts.SPEED_UNITS or v.unit == "m/s" else None
    if unit is None and v.nmea_speed is not None:
        unit = v.nmea_speed[0]
    if unit in facts.SPEED_UNITS and _near(s, facts.SPEED_UNITS[unit]):
        return "m/s"
    if unit in (None, "m/s") and v.unit in (None, "m/s"):
        for to, factor in facts.SPEED_UNITS.items():
            if (to != "km/h" or unit == "m/s") and _near(s, 1.0 / factor):
                return to
    return None


def _near(a: float, b: float) -> bool:
    """Equal to the precision a conversion factor is written with (1.944, 0.5144)."""
    return abs(a - b) < 5e-4 * abs(b)


def neg(v: AbstractValue) -> AbstractValue:
    v = settle(v)
    if v.const is not None:
        return constant(-v.const)
    if v.pending is not None:
        return replace(v, ops=(*v.ops, ("neg", None)))
    flip = {"heading": "yaw", "yaw": "heading"}
    rng = (-v.range[1], -v.range[0]) if v.range else None
    sign = {"down": "up", "up": "down"}.get(v.sign) if v.sign else None
    return replace(v, range=rng, sense=flip.get(v.sense) if v.sense else None, sign=sign)


def to_rad(v: AbstractValue, why: str) -> AbstractValue:
    v = settle(v)
    if v.pending is not None:
        return replace(v, ops=(*v.ops, ("rad", why)))
    unit: str | None = "rad/s" if v.unit in ("deg/s", "rad/s") else "rad"
    if v.unit in ("rad", "rad/s"):
        unit = None  # converting radians again: nothing certain
    rng = (v.range[0] * facts.DEG2RAD, v.range[1] * facts.DEG2RAD) if v.range else None
    out = replace(v, unit=unit, range=rng, const=None, hint=False, nmea_position=None)
    return out.because(why) if why else out


def to_deg(v: AbstractValue, why: str) -> AbstractValue:
    v = settle(v)
    if v.pending is not None:
        return replace(v, ops=(*v.ops, ("deg", why)))
    unit: str | None = "deg/s" if v.unit in ("rad/s", "deg/s") else "deg"
    if v.unit in ("deg", "deg/s"):
        unit = None
    rng = (v.range[0] * facts.RAD2DEG, v.range[1] * facts.RAD2DEG) if v.range else None
    out = replace(v, unit=unit, range=rng, const=None, hint=False, nmea_position=None)
    return out.because(why) if why else out


def wrapped(v: AbstractValue, rng: Range, unit: str | None, why: str) -> AbstractValue:
    v = settle(v)
    if v.pending is not None:
        return replace(v, ops=(*v.ops, ("wrap", (rng, unit, why))))
    out = replace(v, range=rng, const=None, unit=unit or v.unit)
    return out.because(why) if why else out


#: how a quarter turn added to a math angle is said in a value's reasons
QUARTER_TURN = "still counter-clockwise"


def shift(v: AbstractValue, c: float) -> AbstractValue:
    """``v + c`` for a constant ``c``."""
    v = settle(v)
    if v.const is not None:
        return constant(v.const + c)
    if c == 0:
        return v
    if v.pending is not None:
        return replace(v, ops=(*v.ops, ("shift", c)))
    rng = (v.range[0] + c, v.range[1] + c) if v.range else None
    turn = 360.0 if v.unit in ("deg",) else 2 * math.pi
    if v.sense == "math" and v.unit in ("deg", "rad") and abs(abs(c) - turn / 4) < _EPS:
        # ``θ + 90`` counts counter-clockwise still, from south (``θ − 90``: from north);
        # a heading is ``90 − θ``, whose minus sign the analysis does not follow
        quarter = f"{c:+g}°" if v.unit == "deg" else ("+π/2" if c > 0 else "−π/2")
        return replace(v, range=rng).because(f"{quarter} turns it, {QUARTER_TURN}")
    sense = v.sense if abs(math.remainder(c, turn)) < _EPS else None
    return replace(v, range=rng, sense=sense)


def join(a: AbstractValue, b: AbstractValue) -> AbstractValue:
    """Either value (branches, several assignments): what both agree on."""
    if a.const is not None and b.const is None:
        a, b = b, a
    if b.const is not None and a.const is None:  # a constant (an initial 0) takes any unit
        rng = (min(a.range[0], b.const), max(a.range[1], b.const)) if a.range else None
        return replace(a, range=rng)
    origin = a.origin if a.origin == b.origin else None
    if a.pending is not None or b.pending is not None:
        return a if a == b else replace(UNKNOWN, origin=origin)
    if a.const is not None and b.const is not None:
        return (
            constant(a.const)
            if a.const == b.const
            else AbstractValue(range=(min(a.const, b.const), max(a.const, b.const)))
        )
    rng = None
    if a.range and b.range:
        rng = (min(a.range[0], b.range[0]), max(a.range[1], b.range[1]))
    return AbstractValue(
        unit=a.unit if a.unit == b.unit else None,
        sense=a.sense if a.sense == b.sense else None,
        range=rng,
        sign=a.sign if a.sign == b.sign else None,
        why=a.why if a.unit == b.unit else (),
        hint=a.hint and b.hint,
        origin=origin,
        nmea_speed=a.nmea_speed if a.nmea_speed == b.nmea_speed else None,
        nmea_position=a.nmea_position if a.nmea_position == b.nmea_position else None,
    )


def _join_all(values: Iterable[AbstractValue]) -> AbstractValue | None:
    """The join of ``values``, or None when there is none."""
    out: AbstractValue | None = None
    for v in values:
        out = v if out is None else join(out, v)
    return out


def add(a: AbstractValue, b: AbstractValue, minus: bool) -> AbstractValue:
    a, b = settle(a), settle(b)
    if b.const is not None:
        return shift(a, -b.const if minus else b.const)
    b2 = neg(b) if minus else b
    if a.const is not None:
        return shift(b2, a.const)
    if _opaque(b) and (a.unit is not None or a.pending is not None):
        return offset(a)  # ``yaw_deg + m_correction``: still degrees
    if _opaque(a) and (b.unit is not None or b.pending is not None):
        return offset(b2)
    # ``m_filter.getYaw() + m_heading_correction``: the getter, resolved later, decides
    # if it turns out in the unit the correction's name gives
    if a.pending is not None and b.pending is None and b.hint and b.unit is not None:
        return replace(a, ops=(*a.ops, ("offset", b.unit)))
    if b.pending is not None and a.pending is None and a.hint and a.unit is not None:
        return replace(b2, ops=(*b2.ops, ("offset", a.unit)))
    if a.pending is not None or b.pending is not None:
        return UNKNOWN
    if a.unit is None or a.unit != b2.unit:
        return UNKNOWN
    rng = (a.range[0] + b2.range[0], a.range[1] + b2.range[1]) if a.range and b2.range else None
    return AbstractValue(
        unit=a.unit,
        sense=a.sense if a.sense == b2.sense else None,
        range=rng,
        why=a.why,
        hint=a.hint or b2.hint,
    )


def _atan2_frame(written: list[str], shown: list[str]) -> tuple[str | None, str]:
    """The frame of ``atan2`` over a displacement on the local grid (its arguments as
    ``written``, locals replaced by what they were set to; as ``shown`` in the code):
    ``atan2(Δy, Δx)`` is the math angle (from east, counter-clockwise), ``atan2(Δx, Δy)``
    a heading (from north, clockwise); None when the names do not tell. With the call as
    a reason quotes it."""
    axes = tuple(displacement_axis(w) for w in written)
    call = f"atan2({', '.join(brief(' '.join(a.split())) for a in shown)})"
    if axes == ("north", "east"):
        return "math", f"{call}, north over east,"
    if axes == ("east", "north"):
        return "heading", f"{call}, east over north,"
    return None, "atan2()"


def _opaque(v: AbstractValue) -> bool:
    """A value of which nothing is known (a member the configuration sets, a device field)."""
    return v.unit is None and v.const is None and v.pending is None and v.range is None


def offset(v: AbstractValue) -> AbstractValue:
    """``v`` plus a value of which nothing is known: of the same unit (a sum of two angles
    is an angle in the unit of each) and sense, of unknown sign and range."""
    v = settle(v)
    if v.pending is not None:
        return replace(v, ops=(*v.ops, ("offset", None)))
    # an angle from east plus an unknown offset may be turned to north (``θ + m_rot``);
    # a position field plus anything is being turned into decimal degrees
    sense = None if v.sense == "math" else v.sense
    return replace(v, range=None, sign=None, const=None, sense=sense, nmea_position=None)


def apply_ops(base: AbstractValue, ops: tuple[tuple[str, Any], ...]) -> AbstractValue:
    """A resolved pending value with what the caller applied to it."""
    v = base
    for op, arg in ops:
        if op == "neg":
            v = neg(v)
        elif op == "rad":
            v = to_rad(v, arg)
        elif op == "deg":
            v = to_deg(v, arg)
        elif op == "wrap":
            v = wrapped(v, arg[0], arg[1], arg[2])
        elif op == "shift":
            v = shift(v, arg)
        elif op == "offset":  # plus a term of unknown value (of ``arg``'s unit if given)
            v = settle(v)
            if arg is not None and v.unit != arg:
                return UNKNOWN
            v = offset(v)
        elif op == "scale":
            v = settle(replace(v, scale=arg))
    return settle(v)


# -- describing values --------------------------------------------------------


def range_text(rng: Range | None, unit: str | None) -> str:
    if rng is None:
        return "?"
    lo, hi = rng
    if unit in ("rad", "rad/s"):

        def f(x: float) -> str:
            if not math.isfinite(x):
                return "∞" if x > 0 else "-∞"
            k = x / math.pi
            if abs(k) < _EPS:
                return "0"
            if abs(k - round(k)) < _EPS:
                n = round(k)
                return {1: "π", -1: "-π"}.get(n, f"{n}π")
            return f"{x:.3g}"

        if abs(lo + hi) < _EPS and abs(hi - math.pi) < _EPS:
            return "±π"
        return f"[{f(lo)}, {f(hi)}]"
    return f"[{lo:g}, {hi:g}]"


def within_pi(rng: Range | None) -> bool | None:
    if rng is None or not all(map(math.isfinite, rng)):
        return None if rng is None else False
    return rng[0] >= -math.pi - _EPS and rng[1] <= math.pi + _EPS


def place(path: str, line: int) -> str:
    """``folder/File.cpp:12``: short enough for a message, long enough to find."""
    parts = path.replace("\\", "/").split("/")
    return f"{'/'.join(parts[-2:])}:{line}"


# -- hints in names and comments -------------------------------------------------

_RAD_NAME = re.compile(r"(?:^|_)rads?(?:_|$)|[a-z0-9]Rads?(?:[A-Z_]|$)|radian", re.I)
#: (``dps`` as a word, not the start of ``dpsi``, a rate of ψ)
_RATE_DEG_NAME = re.compile(
    r"(?i:(?:^|_)dps(?:_|$)|deg_?per_?s|degs?_?s(?:ec)?\b|DegPerSec)|[a-z0-9]Dps(?:[A-Z_]|$)"
)
_DEG_NAME = re.compile(r"(?:^|_)deg(?:ree)?s?(?:_|$)|[a-z0-9]Deg(?:ree)?s?(?:[A-Z_]|$)|degree")
_HEADING_NAME = re.compile(r"heading|hdg|compass", re.I)
#: the words of a device's resolution constant (``EULER_DIV_DEG``, ``LSB_PER_RAD``)
_SCALE_WORDS = {"DIV", "PER", "LSB", "SCALE", "RES", "RESOLUTION", "COUNTS"}
_UNIT_WORDS = {"DEG": "deg", "DEGS": "deg", "DEGREE": "deg", "DEGREES": "deg"}
_UNIT_WORDS.update({"RAD": "rad", "RADS": "rad", "RADIAN": "rad", "RADIANS": "rad"})


def _scale_unit(name: str) -> str | None:
    """The angle unit a raw reading is scaled to by a resolution constant named like
    ``BNO055_EULER_DIV_DEG`` (16 counts a degree): a scale word, then the unit last.
    A conversion constant (``DEG_TO_RAD``) has no scale word and is not one."""
    words = re.findall(r"[A-Z]+[a-z0-9]*|[a-z0-9]+", name.rsplit("::", 1)[-1])
    upper = [w.upper() for w in words]
    if len(upper) < 2 or not _SCALE_WORDS & set(upper[:-1]):
        return None
    return _UNIT_WORDS.get(upper[-1])


_DEPTH_NAME = re.compile(r"depth", re.I)
#: NED as a word of a name or type (``m_ned.z``, ``PoseNED``, ``local_position_ned_t``),
#: not inside one (``planned``, ``aligned``)
_NED_WORD = re.compile(r"(?<![A-Z])NED(?![a-z])|(?<![A-Za-z])[Nn]ed(?![a-z])")
_SIGN_NAME = re.compile(r"polarity|(?:^|_)sign(?:_|$)|Sign$|(?:^|_)dir(?:ection)?(?:_|$)", re.I)
_COMMENT_UNIT = re.compile(
    r"//.*?\b(deg(?:rees?)?\s*/\s*s(?:ec)?|rad(?:ians?)?\s*/\s*s(?:ec)?|"
    r"deg(?:rees?)?|rad(?:ians?)?)\b|//.*?(°)",
    re.I,
)


def ned_z_name(name: str) -> bool:
    """``m_ned.z``, ``ned_down``, ``pos_down``: a NED z (positive down) by its name."""
    return bool(
        (_NED_WORD.search(name) or re.search(r"down", name, re.I))
        and re.search(r"(?:^|[._>])(?:m_)?(?:pos_?)?(?:z|down|d)$", name, re.I)
    )


def _reads_number(n: Any) -> bool:
    """Whether ``n`` reads a message's number (``msg.GetDouble()``, ``p->GetDoubleValue()``)."""
    n = strip(n)
    if n is None or n.type != "call_expression":
        return False
    fn = n.child_by_field_name("function")
    return (
        fn is not None
        and fn.type == "field_expression"
        and text(fn.child_by_field_name("field")) in ("GetDouble", "GetDoubleValue")
    )


def _variable_value(var: str | None, why: str) -> AbstractValue:
    """What :data:`facts.MAIL_UNITS` says of MOOS variable ``var``, read as ``why`` says."""
    fact = facts.MAIL_UNITS.get(var) if var is not None else None
    if fact is None:
        return UNKNOWN
    unit, sense, rng, sign = fact
    return AbstractValue(unit=unit, sense=sense, range=rng, sign=sign, why=(why,))


def name_hint(name: str) -> AbstractValue:
    """What an identifier's name says of its unit (``m_heading``, ``pitch_rad``)."""
    base = name.rsplit(".", 1)[-1].rsplit(">", 1)[-1]
    base = re.sub(r"^m_?(?=[A-Za-z])", "", base) if base.startswith("m_") else base
    why = f"`{name}` says so by its name"
    if _RAD_NAME.search(base):
        return AbstractValue(unit="rad", hint=True, why=(why,))
    if _RATE_DEG_NAME.search(base):
        return AbstractValue(unit="deg/s", hint=True, why=(why,))
    if _HEADING_NAME.search(base) and not re.search(r"yaw", base, re.I):
        return AbstractValue(unit="deg", sense="heading", hint=True, why=(why,))
    if _DEG_NAME.search(base):
        return AbstractValue(unit="deg", hint=True, why=(why,))
    if ned_z_name(name):
        return AbstractValue(sign="down", hint=True, why=(f"`{name}` is a NED z, positive down",))
    if _DEPTH_NAME.search(base) and not re.search(r"(?:^|_)z(?:_|$)", base, re.I):
        return AbstractValue(sign="down", hint=True, why=(f"`{name}` is a depth",))
    speed = speed_name_unit(base)
    if speed is not None:
        return AbstractValue(unit=speed, hint=True, why=(why,))
    return UNKNOWN


#: the words of a name that give a speed's unit (``speed_kts``, ``dSpeedKnots``, ``sog_kmh``)
_SPEED_NAME_WORDS = {
    "kts": "kn",
    "knot": "kn",
    "knots": "kn",
    "kmh": "km/h",
    "kph": "km/h",
    "kmph": "km/h",
    "mph": "mph",
}
#: ``kn`` alone may be anything (a gain); beside one of these words it is knots (``sog_kn``)
_SPEED_WORDS = {"speed", "spd", "sog", "stw", "vel", "velocity"}
_NAME_WORDS = re.compile(r"[A-Z]+(?![a-z])|[A-Z]?[a-z]+|\d+")


def speed_name_unit(name: str) -> str | None:
    """The speed unit other than metres per second that a name says (``kts`` → knots)."""
    words = [w.lower() for w in _NAME_WORDS.findall(name.rsplit("::", 1)[-1])]
    for w in words:
        unit = _SPEED_NAME_WORDS.get(w)
        if unit is not None:
            return unit
    if "kn" in words and _SPEED_WORDS & set(words):
        return "kn"
    return None


def _speed_named(key: str, v: AbstractValue) -> bool:
    """Whether ``key``'s name gives the unit of a speed whose value says none but an
    NMEA field's angle hint (``double dbl_kts = atof(flds[7].c_str())``)."""
    return v.hint and v.unit == "deg" and v.nmea_speed is None and speed_name_unit(key) is not None


def _heading_named(key: str, v: AbstractValue) -> AbstractValue:
    """``v`` kept in ``key``: an angle in degrees whose turning sense only a hint gives
    (an NMEA field, a device's angle), kept in a variable named a heading, turns as a
    heading does (``double heading = atof(rmc[8].c_str())``: the RMC track angle is
    degrees clockwise from north, as every NMEA 0183 angle is)."""
    if not (v.hint and v.unit == "deg" and v.sense is None and v.pending is None):
        return v
    hint = name_hint(key)
    if hint.sense != "heading" or hint.unit != "deg":
        return v
    return replace(v, sense="heading").because(hint.why[0])


def comment_hint(line: str) -> AbstractValue:
    m = _COMMENT_UNIT.search(line)
    if not m:
        return UNKNOWN
    word = (m.group(1) or "deg").lower().replace(" ", "")
    unit = "deg" if word.startswith("deg") or word == "°" else "rad"
    if "/" in word:
        unit += "/s"
    return AbstractValue(
        unit=unit, hint=True, why=(f"the comment says `{m.group(0)[2:].strip()}`",)
    )


#: a speed unit in a declaration's comment (``/**< Speed over the ground in kph */``)
_COMMENT_SPEED = re.compile(
    r"\b(?:(knots?|kts)|(kph|km\s*/\s*h|kmh|kilomet(?:er|re)s?\s*(?:per|/)\s*hour)|"
    r"(mph|miles\s*(?:per|an|/)\s*hour))\b",
    re.I,
)
_COMMENT_DEG = re.compile(r"\bdeg(?:rees?|s)?\b|°", re.I)
_COMMENT_RAD = re.compile(r"\brad(?:ians?|s)?\b", re.I)


def declaration_hint(comment: str, where: str) -> AbstractValue | None:
    """The unit a field's declaration comment gives (``double pitch; // degrees``,
    ``double speed; /**< Speed over the ground in kph */``): one angle unit or one speed
    unit, never both kinds nor two of a kind; None otherwise."""
    body = comment.strip().lstrip("/*!<").rstrip("*/").strip()
    if not body:
        return None
    deg, rad = _COMMENT_DEG.search(body), _COMMENT_RAD.search(body)
    speeds = {next(i for i, g in enumerate(m.groups()) if g) for m in _COMMENT_SPEED.finditer(body)}
    found = [u for u in (deg and "deg", rad and "rad") if u] + [
        ("kn", "km/h", "mph")[i] for i in speeds
    ]
    if len(found) != 1:
        return None
    unit = found[0]
    if unit in ("deg", "rad"):
        v = comment_hint("// " + body)  # (a rate: degrees per second)
        if v.unit is None or v.unit.split("/")[0] != unit:
            return None
        unit = v.unit
    why = f"{where} is declared with the comment `{brief(body, 50)}`"
    return AbstractValue(unit=unit, hint=True, why=(why,))


#: a field's declaration with a comment after it on its line (``double roll, pitch; // deg``)
_FIELD_LINE = (
    rb"^[^\n;{}]*?\b(?:%s)\s*(?:\[[^\]\n]*\])?\s*(?:=[^;\n]*)?(?:,[^;\n]*)?;"
    rb"[ \t]*(//[^\n]*|/\*.*?\*/)"
)


#: words that may stand before a name in a class's body without declaring it
_NOT_TYPES = frozenset({"return", "delete", "throw", "case", "else", "goto", "co_return"})

#: in a pending field ``.Outer>member.field``: the field of member ``member`` of class
#: ``Outer`` (the member's class read from Outer's declaration in the repository)
MEMBER_MARK = ">"


def class_body(data: bytes, cls: str) -> tuple[int, int] | None:
    """Where the body of class or struct ``cls`` lies in ``data`` (``struct cls {...}``
    or ``typedef struct {...} cls;``), braces counted (comments and strings are not
    told apart): (start, end) offsets, or None."""
    key = cls.encode()
    if key not in data:
        return None
    name = re.escape(key)
    m = None
    for keyword in (b"class", b"struct"):  # each literal first: an alternation is tried
        found = re.search(keyword + rb"\s+" + name + rb"\b[^;{}()]*\{", data)  # at every byte
        if found is not None and (m is None or found.start() < m.start()):
            m = found
    if m is not None:
        depth, i = 1, m.end()
        while i < len(data) and depth:
            c = data[i]
            depth += (c == 0x7B) - (c == 0x7D)
            i += 1
        return (m.end(), i - 1) if depth == 0 else None
    m = re.search(rb"\}\s*" + name + rb"\s*;", data)
    if m is None or b"typedef" not in data[: m.start()]:
        return None
    depth, i = 1, m.start() - 1
    while i >= 0 and depth:
        c = data[i]
        depth += (c == 0x7D) - (c == 0x7B)
        i -= 1
    return (i + 2, m.start()) if depth == 0 else None


#: calls whose first string argument formats the ones after it
_FORMAT_CALLS = {
    "printf",
    "fprintf",
    "sprintf",
    "snprintf",
    "MOOSTrace",
    "MOOSFormat",
    "reportEvent",
    "reportRunWarning",
    "format",
}
_CONVERSION = re.compile(r"%[-+ #0]*(?:\d+|\*)?(?:\.(?:\d+|\*))?(?:hh|h|ll|l|L|z|j|t)?([a-zA-Z%])")
_UNIT_WORD = r"(deg(?:rees?)?(?:\s*/\s*s(?:ec)?)?|rad(?:ians?)?(?:\s*/\s*s(?:ec)?)?|°)"
#: a label before the value: ``Yaw (deg):``, ``pitch [rad] =``, ``roll in degrees:``
_UNIT_BEFORE = re.compile(
    rf"(?:[(\[]\s*{_UNIT_WORD}\s*[)\]]|\bin\s+{_UNIT_WORD})\s*[:=]?\s*$", re.I
)
#: a unit right after the value: ``%f deg``, ``<< " rad"``
_UNIT_AFTER = re.compile(rf"^\s*{_UNIT_WORD}(?![A-Za-z])", re.I)
_SEPARATORS = re.compile(r"[,;|\t\n]|\\n|\\t")


def unit_label(unit: str) -> str:
    return {
        "deg": "degrees",
        "rad": "radians",
        "deg/s": "degrees per second",
        "rad/s": "radians per second",
    }.get(unit, unit)


def _label_unit(before: str, after: str) -> str | None:
    """The unit that the text around a printed value names."""
    before = _SEPARATORS.split(before)[-1]
    after = _SEPARATORS.split(after)[0]
    m = _UNIT_BEFORE.search(before) or _UNIT_AFTER.search(after)
    if not m:
        return None
    word = next(g for g in m.groups() if g).lower().replace(" ", "")
    unit = "deg" if word.startswith("deg") or word == "°" else "rad"
    return unit + "/s" if "/" in word else unit


def _string_text(n: Any) -> str | None:
    if n is None:
        return None
    if n.type == "concatenated_string":
        parts = [_string_text(c) for c in n.named_children]
        return None if any(p is None for p in parts) else "".join(p for p in parts if p)
    if n.type != "string_literal":
        return None
    return "".join(
        text(c) for c in n.named_children if c.type in ("string_content", "escape_sequence")
    )


def _print_labels(root: Any) -> Iterator[tuple[str, str, Any]]:
    """(variable, unit, node) for each variable printed next to a unit label."""
    stack = [root]
    while stack:
        x = stack.pop()
        stack.extend(x.named_children)
        if x.type == "call_expression":
            if callee_name(x.child_by_field_name("function")) not in _FORMAT_CALLS:
                continue
            args = x.child_by_field_name("arguments")
            argv = [a for a in args.named_children if a.type != "comment"] if args else []
            fmt_at = next((i for i, a in enumerate(argv) if _string_text(a) is not None), None)
            if fmt_at is None:
                continue
            fmt = _string_text(argv[fmt_at]) or ""
            convs = [m for m in _CONVERSION.finditer(fmt) if m.group(1) != "%"]
            values = argv[fmt_at + 1 :]
            for k, m in enumerate(convs):
                if k >= len(values) or m.group(1) not in "fFeEgG":
                    continue
                var = strip(values[k])
                if var is None or var.type not in ("identifier", "field_expression"):
                    continue
                start = convs[k - 1].end() if k else 0
                end = convs[k + 1].start() if k + 1 < len(convs) else len(fmt)
                unit = _label_unit(fmt[start : m.start()], fmt[m.end() : end])
                if unit:
                    yield _target(var), unit, x
        elif x.type == "binary_expression" and text(x.child_by_field_name("operator")) == "<<":
            parent = x.parent
            if (
                parent is not None
                and parent.type == "binary_expression"
                and text(parent.child_by_field_name("operator")) == "<<"
            ):
                continue  # the chain is read from its top
            chain: list[Any] = []
            y = x
            while y.type == "binary_expression" and text(y.child_by_field_name("operator")) == "<<":
                chain.append(strip(y.child_by_field_name("right")))
                y = strip(y.child_by_field_name("left"))
            chain.append(y)
            chain.reverse()
            for k, var in enumerate(chain):
                if var is None or var.type not in ("identifier", "field_expression") or k == 0:
                    continue
                before = _string_text(chain[k - 1])
                after = _string_text(chain[k + 1]) if k + 1 < len(chain) else None
                unit = _label_unit(before or "", after or "")
                if unit:
                    yield _target(var), unit, x


# -- the evaluator ------------------------------------------------------------


text = node_text


_NMEA = re.compile(rb'"\$?(?:[A-Z]{2})?(?:' + "|".join(facts.NMEA_SENTENCES).encode() + rb')[",]')
#: a literal that names a field of a ``KEY=value,...`` report (MOOS-IvP's
#: ``tokStringParse(report, "HDG", ',', '=')``), not an NMEA sentence
_KEY_OF_REPORT = re.compile(rb"tok(?:String|Double)Parse\s*\([^;]*?$")


#: a device of :data:`facts.DEGREE_DEVICES` named in a file's code: ``iOS5000``,
#: ``CiOS5000``, ``os5000::``, ``"OS5000"`` (the name starts a word, after an app's ``i``
#: or a class's ``C`` or ``Ci``, and no digit follows it)
_DEVICES = [
    (
        re.compile(rb"(?i)" + pattern.encode()),  # the name alone: a quick first look
        re.compile(
            rb"(?i)(?:^|[^a-z0-9]|(?<![a-z0-9])(?:c|i|ci))" + pattern.encode() + rb"(?![0-9])"
        ),
        why,
    )
    for pattern, why in facts.DEGREE_DEVICES.items()
]


def _names_device(data: bytes) -> tuple[str, str] | None:
    """The device of :data:`facts.DEGREE_DEVICES` that ``data`` names, if one."""
    for name, pattern, why in _DEVICES:
        if name.search(data) and pattern.search(data):
            return why
    return None


def _names_nmea(data: bytes) -> bool:
    """Whether ``data`` names an NMEA 0183 sentence (``"$GPRMC"``, ``"HDT"``), a report's
    ``"HDG"`` key aside."""
    for m in _NMEA.finditer(data):
        line_start = data.rfind(b"\n", 0, m.start()) + 1
        if not _KEY_OF_REPORT.search(data, line_start, m.start()):
            return True
    return False


_PASS_THROUGH = {
    "round",
    "floor",
    "ceil",
    "static_cast",
    "double",
    "float",
    "lround",
    "trunc",
    "fabs",
    "abs",
}
MAX_DEPTH = 12


@dataclass
class FilePart:
    """What one file gives its folder's look-ups (:class:`Folder`): kept on the file, which
    the language server keeps while its bytes are unchanged."""

    nmea: bool
    nmea_speed: bool
    device: tuple[str, str] | None  # a device of facts.DEGREE_DEVICES the file names
    members: list[Any]  # the assignments to members, globals and constants
    functions: list[tuple[str, Any]]  # (short name, definition)


def _folder_part(pf: Any) -> FilePart:
    if pf.folder_part is None:
        pf.folder_part = FilePart(
            _names_nmea(pf.data),
            bool(_SPEED_SENTENCE.search(pf.data)),
            _names_device(pf.data),
            [a for a in pf.asgs if a.fn is None or not _declared_local(pf, a)],
            [(name, fn) for fn in pf.functions if (name := _function_short_name(fn))],
        )
    return pf.folder_part


class Folder:
    """What evaluation may look up across the files of one folder (or one library file)."""

    def __init__(self, files: list[Any]):
        self.files = files
        self.members: dict[str, list[tuple[Any, Any]]] = {}
        self.functions: dict[str, list[tuple[Any, Any]]] = {}
        self.defines: dict[str, str] = {}
        self.nmea: set[str] = set()
        #: the files that name an NMEA speed sentence (:func:`_nmea_speed` looks only there)
        self.nmea_speed: set[str] = set()
        #: the files that name a device of facts.DEGREE_DEVICES -> (field, why)
        self.devices: dict[str, tuple[str, str]] = {}
        for pf in files:
            part = _folder_part(pf)
            if part.nmea:
                self.nmea.add(pf.path)
            if part.device is not None:
                self.devices[pf.path] = part.device
            if part.nmea_speed:
                self.nmea_speed.add(pf.path)
            self.defines.update(pf.defines)
            for a in part.members:
                self.members.setdefault(a.target, []).append((pf, a))
            for name, fn in part.functions:
                self.functions.setdefault(name, []).append((pf, fn))
        self.memo: dict[tuple, Any] = {}  # AbstractValue, or None where a flow is unknown
        self._calls: dict[str, list[tuple[Any, Any]]] | None = None
        self._printed: dict[tuple[int | None, str], list[tuple[str, str]]] | None = None
        #: function id -> variable -> the calls passing it (:func:`_calls_passing`)
        self.passing: dict[int, dict[str, list[tuple[Any, str, int]]]] = {}
        self._member_types: dict[str, str | None] | None = None

    def member_type(self, name: str) -> str | None:
        """The class a member or global ``name`` of the folder is declared of."""
        if self._member_types is None:
            self._member_types = {}
            for pf in self.files:
                for n, t in fields.declarations(pf.tree.root_node):
                    cls = fields.type_name(t)
                    if self._member_types.get(n, cls) != cls:
                        cls = None  # declared of two classes: unknown
                    self._member_types[n] = cls
        return self._member_types.get(name)

    def printed(self) -> dict[tuple[int | None, str], list[tuple[str, str]]]:
        """(function id for a local or None, variable) -> the units its print labels name."""
        if self._printed is None:
            self._printed = {}
            for pf in self.files:
                for var, unit, node in _print_labels(pf.tree.root_node):
                    at = place(pf.path, node.start_point[0] + 1)
                    why = f"printed as {unit_label(unit)} at {at}"
                    fn = pf.function_of(node)
                    local = fn is not None and (
                        var in pf.local.get(fn.id, {}) or _is_param(fn, var)
                    )
                    where = fn.id if local else None
                    self._printed.setdefault((where, var), []).append((unit, why))
                    copied = _copy_of(pf, fn, var) if local else None
                    if copied is not None:  # ``double roll = m_roll; printf("%f deg", roll)``
                        why = f"printed as {unit_label(unit)} through `{var}` at {at}"
                        self._printed.setdefault((None, copied), []).append((unit, why))
        return self._printed

    def calls(self, name: str) -> list[tuple[Any, Any]]:
        """The calls of function ``name`` in the folder (indexed on first use)."""
        if self._calls is None:
            self._calls = {}
            for pf in self.files:
                stack = [pf.tree.root_node]
                while stack:
                    n = stack.pop()
                    if n.type == "call_expression":
                        fn = n.child_by_field_name("function")
                        self._calls.setdefault(callee_name(fn), []).append((pf, n))
                    stack.extend(n.named_children)
        return self._calls.get(name, [])


def _copy_of(pf: Any, fn: Any, var: str) -> str | None:
    """The member or global that local ``var`` of ``fn`` is only ever a copy of."""
    asgs = pf.local.get(fn.id, {}).get(var, [])
    sources = set()
    for a in asgs:
        rhs = strip(a.rhs)
        if a.op != "=" or rhs is None or rhs.type not in ("identifier", "field_expression"):
            return None
        src = _target(rhs)
        if not src or src in pf.local.get(fn.id, {}) or _is_param(fn, src):
            return None
        sources.add(src)
    return sources.pop() if len(sources) == 1 else None


def _declared_local(pf: Any, a: Any) -> bool:
    cands = pf.local.get(a.fn.id, {}).get(a.target, []) if a.fn is not None else []
    if any(c.node.type == "init_declarator" for c in cands):
        return True
    return _is_param(a.fn, a.target)


def _owner(fn: Any) -> str | None:
    """The class function definition ``fn`` is a method of (``Owner::name(...) {...}``, or
    a definition inside the class's body), by name; None for a free function."""
    decl = fn.child_by_field_name("declarator")
    return fields.enclosing_class(decl) if decl is not None else None


def _function_short_name(fn: Any) -> str:
    decl = function_declarator(fn)
    if decl is None:
        return ""
    return re.split(r"::", re.sub(r"\s+", "", text(decl.child_by_field_name("declarator"))))[-1]


def _is_param(fn: Any, key: str) -> bool:
    if fn is None:
        return False
    decl = function_declarator(fn)
    params = decl.child_by_field_name("parameters") if decl is not None else None
    for p in params.named_children if params is not None else ():
        d = p.child_by_field_name("declarator")
        while d is not None and d.type not in ("identifier",):
            nxt = d.child_by_field_name("declarator")
            if nxt is None:
                nxt = next((c for c in d.named_children if c.type == "identifier"), None)
            d = nxt
        if d is not None and text(d) == key:
            return True
    return False


def _param_index(fn: Any, key: str) -> int | None:
    decl = function_declarator(fn)
    params = decl.child_by_field_name("parameters") if decl is not None else None
    plist = [
        p for p in (params.named_children if params is not None else ()) if p.type != "comment"
    ]
    for i, p in enumerate(plist):
        d = p.child_by_field_name("declarator")
        while d is not None and d.type != "identifier":
            nxt = d.child_by_field_name("declarator")
            if nxt is None:
                nxt = next((c for c in d.named_children if c.type == "identifier"), None)
            d = nxt
        if d is not None and text(d) == key:
            return i
    return None


def _inside(n: Any, outer: Any) -> bool:
    return outer.start_byte <= n.start_byte and n.end_byte <= outer.end_byte


class Compiled(Protocol):
    """What a compiler front end knows that the tree-sitter reading does not
    (:class:`moos_lint.frontends.cpp.clang_facts.ClangFacts`)."""

    def constant(self, path: str, row: int, col: int, name: str) -> tuple[float, str] | None:
        """The folded value of the constant ``name`` used at (``row``, byte ``col``), with
        where it is defined; None when it is no constant."""
        ...

    def live(self, path: str, data: bytes) -> bytes:
        """``data`` with what the compiler skipped blanked."""
        ...


class Evaluator:
    """Abstract values of expressions of one folder. ``compiled`` (libclang's facts, or
    None) resolves the constants the folder does not define."""

    def __init__(self, folder: Folder, library: bool = False, compiled: Compiled | None = None):
        self.folder = folder
        self.compiled = compiled
        self._stack: set[tuple] = set()
        #: reading a library file on its own: a field of its classes that the file never
        #: writes is looked for where the repository writes it (:func:`_field_pending`)
        self.library = library

    @staticmethod
    def in_degrees(value: float, why: str) -> AbstractValue:
        """A number written in degrees, for the reason given (a turn: ``90``)."""
        return AbstractValue(unit="deg", const=float(value), why=(why,))

    def of(self, pf: Any, node: Any, depth: int = 0) -> AbstractValue:
        try:
            v = settle(self._eval(pf, node, depth))
        except RecursionError:
            return UNKNOWN
        if v.pending is not None and v.pending.startswith(".") and not v.ops and node is not None:
            # a field: if the repository's writes say nothing, its name, comment or label
            base = v.fallback if v.fallback is not None else UNKNOWN
            h = self._hint(pf, node, base) if base.unit is None else None
            return replace(v, fallback=h) if h is not None else v
        if v.unit is None and v.const is None and v.pending is None and node is not None:
            h = self._hint(pf, node, v)
            if h is not None:
                return h
        return v

    def degree_term(self, pf: Any, node: Any) -> AbstractValue | None:
        """A term of a sum or difference known to be in degrees (not by a name alone), when
        no term is in radians: ``90 - (heading + offset)`` is in degrees whatever the
        offset is, as far as a sine is concerned (a sum with degrees in it is not radians)."""
        terms: list[Any] = []
        stack = [node]
        while stack:
            n = strip(stack.pop())
            if n is None:
                continue
            if n.type == "binary_expression" and node_text(n.child_by_field_name("operator")) in (
                "+",
                "-",
            ):
                stack += [n.child_by_field_name("left"), n.child_by_field_name("right")]
            elif n.type == "unary_expression" and node_text(n.child_by_field_name("operator")) in (
                "-",
                "+",
            ):
                stack.append(n.child_by_field_name("argument"))
            else:
                terms.append(n)
        if len(terms) < 2:
            return None
        found = None
        for t in terms:
            v = self.of(pf, t)
            if v.unit == "rad":
                return None  # radians and degrees mixed: which one is wrong is not known
            if found is None and v.unit == "deg" and not v.hint:
                found = v.because(f"a term of `{brief(node_text(node))}`")
        return found

    def _hint(self, pf: Any, node: Any, v: AbstractValue) -> AbstractValue | None:
        """The unit a same-line comment or a print label gives ``node``'s value."""
        row = node.start_point[0]
        if row < len(pf.spans.lines):
            line = pf.spans.lines[row].decode("utf-8", "replace")
            h = comment_hint(line)
            if h.known:
                return replace(h, range=v.range, sign=v.sign or h.sign)
        printed = self._printed(pf, strip(node))
        if printed is not None:
            return replace(printed, range=v.range, sign=v.sign)
        return None

    def _printed(self, pf: Any, n: Any) -> AbstractValue | None:
        """The unit a format string or a stream label gives the variable ``n`` where the app
        prints it (``printf("Yaw (deg): %f", yaw)``, ``ss << yaw << " deg"``): a hint, used
        only when nothing else is known of the value."""
        if n is None or n.type not in ("identifier", "field_expression"):
            return None
        key = _target(n)
        fnode = pf.function_of(n)
        local = fnode is not None and (key in pf.local.get(fnode.id, {}) or _is_param(fnode, key))
        labels = self.folder.printed().get((fnode.id if local else None, key))
        if not labels:
            return None
        units = {u for u, _w in labels}
        if len(units) != 1:
            return None  # printed with different units: no hint
        unit, why = labels[0]
        return AbstractValue(unit=unit, hint=True, why=(why,))

    # -- expressions
    def _eval(self, pf: Any, n: Any, depth: int) -> AbstractValue:
        n = strip(n)
        if n is None or depth > MAX_DEPTH:
            return UNKNOWN
        t = n.type
        if t == "number_literal":
            try:
                return constant(float(re.sub(r"[fFlLuU]+$", "", text(n))))
            except ValueError:
                return UNKNOWN
        if t == "field_expression" and text(n.child_by_field_name("field")) == "m_dfVal":
            # CMOOSMsg's value as a public member (core MOOS, Comms/MOOSMsg.h), as old
            # apps read it: ``if(msg.m_sKey == "NAV_YAW") m_yaw = msg.m_dfVal;`` (a field
            # of that name outside such a branch is read as any other field)
            mail = self._mail(pf, n)
            if mail.known:
                return mail
        if t in ("identifier", "field_expression", "qualified_identifier"):
            return self._name(pf, n, depth)
        if t == "unary_expression":
            op = text(n.child_by_field_name("operator"))
            arg = self._eval(pf, n.child_by_field_name("argument"), depth + 1)
            if op == "-":
                return neg(arg)
            return arg if op == "+" else UNKNOWN
        if t == "binary_expression":
            return self._binary(pf, n, depth)
        if t == "assignment_expression" and text(n.child_by_field_name("operator")) == "=":
            # ``m_yaw = m_pitch = 0.``: a chained assignment's value is its right side's
            return self._eval(pf, n.child_by_field_name("right"), depth + 1)
        if t == "conditional_expression":
            return join(
                settle(self._eval(pf, n.child_by_field_name("consequence"), depth + 1)),
                settle(self._eval(pf, n.child_by_field_name("alternative"), depth + 1)),
            )
        if t == "cast_expression":
            return self._eval(pf, n.child_by_field_name("value"), depth + 1)
        if t == "call_expression":
            return self._call(pf, n, depth)
        if t == "subscript_expression":
            arr = strip(n.child_by_field_name("argument"))
            v = self._eval(pf, arr, depth + 1)
            idx = n.child_by_field_name("indices")
            key = _target(arr) if arr is not None else ""
            if (
                key
                and idx is not None
                and all(c.type == "number_literal" for c in idx.named_children)
            ):
                fnode = pf.function_of(n)
                if not v.known and fnode is not None and _is_param(fnode, key):
                    v = self._callback_reading(pf, fnode, n, key, idx.named_children) or v
                v = replace(v, origin=f"{pf.path}#{fnode.id if fnode else 0}#{key}")
            return v
        return UNKNOWN

    def _callback_reading(
        self, pf: Any, fnode: Any, n: Any, key: str, indices: list[Any]
    ) -> AbstractValue | None:
        """``data[1]`` of a parameter of a function that a device library is constructed
        with as its data callback (:data:`facts.LIBRARY_CALLBACKS`): the reading the
        library hands it there, as a hint."""
        if len(indices) != 1:
            return None
        try:
            index = int(text(indices[0]), 0)
        except ValueError:
            return None
        fn = _function_short_name(fnode)
        given = self._once(("callback", fn), lambda: self._callback_of(fn), None) if fn else None
        if given is None:
            return None
        lib, where = given
        _arg, elements, unit, what = facts.LIBRARY_CALLBACKS[lib]
        if index not in elements:
            return None
        why = f"`{brief(text(n), 30)}`, a reading {lib} hands {fn}() ({where}): {what}"
        return AbstractValue(unit=unit, hint=True, why=(why,))

    def _callback_of(self, fn: str) -> tuple[str, str] | None:
        """The device library (of :data:`facts.LIBRARY_CALLBACKS`) that the folder constructs
        with function ``fn`` as its data callback, and where; None when none is."""
        for lib, (arg, _elements, _unit, _what) in facts.LIBRARY_CALLBACKS.items():
            for f in self.folder.files:
                at = _callback_given(f.data, lib, arg, fn)
                if at is not None:
                    return lib, place(f.path, f.data.count(b"\n", 0, at) + 1)
        return None

    def _binary(self, pf: Any, n: Any, depth: int) -> AbstractValue:
        v = self._arith(pf, n, depth)
        s = v.scale
        if v.const is None and (
            abs(s - facts.RAD2DEG) < 1e-3 * facts.RAD2DEG
            or abs(s - facts.DEG2RAD) < 1e-3 * facts.DEG2RAD
            or (
                s != 1.0 and (v.unit is None or v.hint) and v.pending is None and _raw_conversion(s)
            )
        ):
            v = settle(v, f"{brief(text(n))} at {_at(pf, n)}")
        elif v.const is None and s != 1.0 and v.pending is None and _speed_scaled(v, s):
            v = settle(v, f"`{brief(text(n))}` at {_at(pf, n)}")
        return v

    def _kept(
        self, pf: Any, n: Any, args: list, bounds: tuple[int | None, int | None], depth: int
    ) -> AbstractValue:
        """A :data:`facts.KEEPS_UNIT` call: its first argument's value, rounded or clipped
        to the bounds it is given (``vclip(yaw, -M_PI, M_PI)``)."""
        v = settle(self._eval(pf, args[0], depth + 1))
        lo_hi = []
        for i in bounds:
            c = (
                settle(self._eval(pf, args[i], depth + 1)).const
                if i is not None and i < len(args)
                else None
            )
            lo_hi.append(c)
        lo, hi = lo_hi
        if v.const is not None or bounds == (None, None):
            return v
        if v.pending is not None:
            # (a value still to be resolved is clipped once it is: to both bounds, or to
            # a range we cannot say)
            if lo is None or hi is None:
                return UNKNOWN
            return wrapped(v, (lo, hi), None, f"{brief(text(n), 40)} at {_at(pf, n)}")
        rng = v.range
        if lo is not None or hi is not None:
            old_lo, old_hi = rng if rng else (-math.inf, math.inf)
            rng = (
                max(old_lo, lo) if lo is not None else old_lo,
                min(old_hi, hi) if hi is not None else old_hi,
            )
            why = f"{brief(text(n), 40)} at {_at(pf, n)}"
            return replace(v, range=rng).because(why) if v.known else replace(v, range=rng)
        return v

    def _arith(self, pf: Any, n: Any, depth: int) -> AbstractValue:
        op = text(n.child_by_field_name("operator"))
        left = self._eval(pf, n.child_by_field_name("left"), depth + 1)
        rnode = strip(n.child_by_field_name("right"))
        right = self._eval(pf, rnode, depth + 1)
        if op in ("*", "/") and left.unit is None and rnode is not None:
            # a raw reading scaled by a factor named in degrees per second (``raw / LSB_PER_DPS``)
            rname = _target(rnode) if rnode.type != "number_literal" else ""
            if rname and _RATE_DEG_NAME.search(rname):
                return AbstractValue(
                    unit="deg/s",
                    hint=True,
                    why=(f"scaled by `{rname}` (degrees per second) at {_at(pf, n)}",),
                )
            # a raw reading scaled by a resolution named in degrees (``raw / EULER_DIV_DEG``)
            unit = _scale_unit(rname) if rname else None
            if unit is not None:
                label = "degrees" if unit == "deg" else "radians"
                return AbstractValue(
                    unit=unit,
                    hint=True,
                    why=(f"scaled by `{rname}` ({label}) at {_at(pf, n)}",),
                )
        if op in ("+", "-"):
            return add(left, right, op == "-")
        if op == "*":
            # a sign factor (``m_RollPolarity * roll``) keeps the unit, not the sense
            lnode = strip(n.child_by_field_name("left"))
            for factor, other in ((lnode, right), (rnode, left)):
                fname = _target(factor) if factor is not None else ""
                if fname and _SIGN_NAME.search(fname) and other.const is None:
                    o = settle(other)
                    rng = None
                    if o.range:
                        m = max(abs(o.range[0]), abs(o.range[1]))
                        rng = (-m, m)
                    return replace(o, sense=None, sign=None, range=rng)
            if right.const is not None:
                return _scaled(left, right.const, right.why)
            if left.const is not None:
                return _scaled(right, left.const, left.why)
            return UNKNOWN  # a product of two quantities: no unit we can name
        if op == "/":
            if right.const is not None and right.const != 0:
                return _scaled(left, 1.0 / right.const, right.why)
            if left.const is not None and right.const is not None:
                return UNKNOWN
            return UNKNOWN
        return UNKNOWN

    def _call(self, pf: Any, n: Any, depth: int) -> AbstractValue:
        fn = n.child_by_field_name("function")
        args = _arguments(n)
        name = callee_name(fn)
        bare = re.sub(r"^std::", "", name)
        at = place(pf.path, n.start_point[0] + 1)
        known = facts.LIBRARY_ANGLES.get(name)
        if known is not None:
            return AbstractValue(
                unit=known[0],
                sense=known[1],
                range=known[2],
                why=(f"{name}() at {at}: {known[3]}",),
            )
        # (an app's own function of a helper's name is read as written: ``angleDiff``)
        if name in facts.HELPERS and args and name not in self.folder.functions:
            unit_in, unit_out, rng, sense = facts.HELPERS[name]
            arg = self._eval(pf, args[0], depth + 1)
            why = f"{name}() at {at}"
            if unit_in == "deg" and unit_out == "rad":
                v = to_rad(arg, why)
            elif unit_in == "rad" and unit_out == "deg":
                v = to_deg(arg, why)
            else:
                v = settle(arg) if unit_in is not None else AbstractValue()
                if v.pending is None:
                    v = replace(v, unit=unit_out, const=None, hint=False).because(why)
            if rng is not None:  # (a value still to be resolved keeps why it is wrapped)
                v = wrapped(v, rng, unit_out, why if v.pending is not None else "")
            if sense is not None and v.pending is None:
                v = replace(v, sense=sense if sense != "math" else "math")
            return v
        if args and (re.match(facts.DEG2RAD_NAME, name) or re.match(facts.RAD2DEG_NAME, name)):
            arg = self._eval(pf, args[0], depth + 1)
            why = f"{name}() at {at}"
            return to_rad(arg, why) if re.match(facts.DEG2RAD_NAME, name) else to_deg(arg, why)
        trig = bare[:-1] if bare.endswith("f") and bare[:-1] in facts.INVERSE_TRIG else bare
        if trig in facts.INVERSE_TRIG:
            sense, called = None, f"{trig}()"
            if trig == "atan2" and len(args) == 2:
                written = [self._written_as(pf, a) for a in args]
                sense, called = _atan2_frame(written, [text(a) for a in args])
            return AbstractValue(
                unit="rad",
                range=facts.INVERSE_TRIG[trig],
                sense=sense,
                why=(f"{called} at {at}",),
            )
        if bare in ("fmod", "fmodf", "remainder") and len(args) == 2:
            x = settle(self._eval(pf, args[0], depth + 1))
            c = settle(self._eval(pf, args[1], depth + 1)).const
            if c is None or c <= 0:
                return replace(x, range=None)
            rng = (-c / 2, c / 2) if bare == "remainder" else (0.0, c)
            if bare != "remainder" and self._not_positive(pf, args[0], x, depth):
                rng = (-c, 0.0)  # C's fmod keeps the sign of what it divides
            k = c / math.pi
            shown = f"{round(k)}π" if abs(k - round(k)) < _EPS and round(k) > 1 else f"{c:g}"
            # modulo a turn or half a turn (2π or π, 360 or 180): the unit that turn is in
            unit = x.unit or _full_turn(c) or _full_turn(2 * c)
            return wrapped(x, rng, unit, f"{bare}(·, {shown}) at {at}")
        if name in _PASS_THROUGH and args:
            return self._eval(pf, args[0], depth + 1)
        if name in facts.KEEPS_UNIT and args:
            return self._kept(pf, n, args, facts.KEEPS_UNIT[name], depth)
        if name in facts.TEXT_TO_NUMBER:
            speed = _nmea_speed(n, args) if pf.path in self.folder.nmea_speed else None
            if pf.path in self.folder.nmea:
                # (a part of a field, ``f.substr(0, 2)``, is not the field as written)
                sentence = _sentence_of(n) if not _PART_OF_TEXT.search(text(n)) else None
                return AbstractValue(
                    unit="deg",
                    hint=True,
                    why=(f"{_NMEA_FIELD} read with {name}() at {at}{_NMEA_ANGLES}",),
                    nmea_speed=speed,
                    nmea_position=sentence if sentence in facts.NMEA_POSITION_SENTENCES else None,
                )
            if speed is not None:
                why = f"{_NMEA_FIELD} read with {name}() at {at}"
                return AbstractValue(nmea_speed=speed, why=(why,))
            device = self.folder.devices.get(pf.path)
            if device is not None:
                field, angles = device
                why = f"{field} read with {name}() at {at}; {angles}"
                return AbstractValue(unit="deg", hint=True, why=(why,))
            return UNKNOWN
        if _reads_number(n):
            return self._mail(pf, n)
        if name in facts.BUFFER_READS and facts.BUFFER_READS[name] is None and args:
            return self._buffer_read(pf, n, args[0])
        if not name or name in ("c_str", "size", "length", "GetTime", "MOOSTime"):
            return UNKNOWN
        own = self.folder.functions.get(name)
        if own:
            return self._returns(name, own, depth)
        receiver = self.object_class(pf, fn) if fn.type == "field_expression" else None
        pending = AbstractValue(
            pending=name, why=(f"{brief(text(n), 40)} at {at}",), receiver=receiver
        )
        # a library class's method is what the library says, even where the repository
        # defines one of that name on a class of its own; known now, before a name that
        # keeps it says otherwise
        method = library_method(pending) if receiver else None
        return replace(method, receiver=receiver) if method is not None else pending

    def _not_positive(self, pf: Any, arg: Any, x: AbstractValue, depth: int) -> bool:
        """Whether ``x``, the value of argument ``arg``, is known to be negative (or 0): by
        its range, or for a variable by the ``if`` it is used in (``if (psi < 0)``)."""
        if x.const is not None:
            return x.const < 0
        if x.range is not None:
            return x.range[0] < 0 and x.range[1] <= 0
        arg = strip(arg)
        if arg is None or arg.type != "identifier":
            return False
        probe = replace(x, range=(-math.inf, math.inf))
        probe = _narrowed(self, pf, pf.function_of(arg), arg, text(arg), probe, depth)
        return probe.range is not None and probe.range[1] <= 0

    def object_class(self, pf: Any, fn: Any) -> str | None:
        """The class of the object method ``fn`` (a field expression) is called on
        (``record`` of ``record.getX``): see :meth:`receiver_class`."""
        return self.receiver_class(pf.function_of(fn), fn)

    def receiver_class(self, fnode: Any, fn: Any, depth: int = 0) -> str | None:
        """The class of the object of field expression ``fn`` in function ``fnode``: a
        local, a parameter or a member declared of one class (:meth:`class_of`), or what a
        library's method returns (``packet.orientationEuler()`` of an ``XsDataPacket``,
        :data:`facts.LIBRARY_RETURNS`); else None."""
        obj = strip(fn.child_by_field_name("argument"))
        if obj is None or depth > 4:
            return None
        if obj.type == "identifier":
            return self.class_of(fnode, text(obj), fn, depth + 1)
        return self._library_return(fnode, obj, depth + 1)

    def _library_return(self, fnode: Any, call: Any, depth: int) -> str | None:
        """The library class that method call ``call`` returns, when the class of the
        object it is called on is known (:data:`facts.LIBRARY_RETURNS`); else None."""
        inner = call.child_by_field_name("function") if call.type == "call_expression" else None
        if inner is None or inner.type != "field_expression":
            return None
        method = inner.child_by_field_name("field")
        cls = self.receiver_class(fnode, inner, depth) if method is not None else None
        return facts.LIBRARY_RETURNS.get((cls, text(method))) if cls else None

    def class_of(self, fnode: Any, name: str, use: Any, depth: int = 0) -> str | None:
        """The class variable ``name`` is declared of at node ``use`` of function ``fnode``:
        a local or parameter in scope there, else a member or global of the folder; for a
        local declared ``auto``, the library class its initialiser returns."""
        found = fields.declared_type(fnode, name, use) or self.folder.member_type(name)
        if found is None and depth <= 4 and fnode is not None and b"auto" in fnode.text:
            value = fields.auto_value(fnode, name)
            if value is not None:
                found = self._library_return(fnode, value, depth + 1)
        return found

    def _once(self, key: tuple, compute: Callable[[], Any], on_cycle: Any = UNKNOWN) -> Any:
        """``compute()``, once per folder and ``key``; ``on_cycle`` when asked again while it
        is being computed (a flow that reaches itself)."""
        memo = self.folder.memo
        if key in memo:
            return memo[key]
        if key in self._stack:
            return on_cycle
        self._stack.add(key)
        try:
            out = compute()
        finally:
            self._stack.discard(key)
        memo[key] = out
        return out

    def _returns(self, name: str, defs: list[tuple[Any, Any]], depth: int) -> AbstractValue:
        def values() -> Iterator[AbstractValue]:
            for pf, fn in defs:
                for r in _returns_of(fn):
                    expr = r.named_children[0] if r.named_children else None
                    if expr is None:
                        continue
                    v = settle(self._eval(pf, expr, depth + 1))
                    field = v.pending is not None and v.pending.startswith(".")
                    if (v.known and v.pending is None) or field:
                        v = v.because(f"{name}() returns {brief(text(expr))} at {_at(pf, r)}")
                    yield v

        return self._once(("fn", name), lambda: _join_all(values()) or UNKNOWN)

    def _mail(self, pf: Any, n: Any) -> AbstractValue:
        """What the message read at ``n`` holds: the variable its branch tests for."""
        var = mail_key_of(n)
        at = place(pf.path, n.start_point[0] + 1)
        return _variable_value(var, f"{var} read by mail at {at}")

    def _hoisted_mail(self, pf: Any, rhs: Any, use: Any) -> AbstractValue | None:
        """A message's number read into a local before the tests of its key, as MOOS-IvP's
        app template does (``double dval = msg.GetDouble();`` then ``if(key == "NAV_HEADING")
        m_heading = dval;``): read at ``use``, it is the variable that branch tests for.
        None when ``rhs`` is no such read (or the read's own branch names its variable)."""
        if not _reads_number(rhs) or mail_key_of(rhs) is not None:
            return None
        v = self._mail(pf, use)
        return v if v.known else None

    def _buffer_read(self, pf: Any, call: Any, var: Any) -> AbstractValue:
        """A MOOS variable read from the helm's information buffer (``getBufferDoubleVal(
        "NAV_HEADING", ok)``): what :data:`facts.MAIL_UNITS` says of it."""
        name = _string_text(strip(var))
        return _variable_value(name, f"{name} read from the helm's buffer at {_at(pf, call)}")

    # -- names
    def _written_as(self, pf: Any, n: Any) -> str:
        """An argument's text, or for a local set once before it (``double y = y2 - y1``),
        the text it was set to."""
        n = strip(n)
        if n is None:
            return ""
        if n.type == "identifier":
            fnode = pf.function_of(n)
            sets = pf.local.get(fnode.id, {}).get(text(n), []) if fnode is not None else []
            if len(sets) == 1 and sets[0].op == "=" and sets[0].node.start_byte < n.start_byte:
                return text(sets[0].rhs)
        return text(n)

    def _name(self, pf: Any, n: Any, depth: int) -> AbstractValue:
        key = _target(n)
        if not key:
            return UNKNOWN
        if key in facts.PI_NAMES:
            return constant(facts.PI_NAMES[key])
        if re.search(facts.ZERO_NAME, key):
            return constant(0.0)
        fnode = pf.function_of(n)
        if fnode is not None:
            local = self._local(pf, fnode, n, key, depth)
            if local is not None:
                return _narrowed(self, pf, fnode, n, key, local, depth)
        v = _narrowed(self, pf, fnode, n, key, self._member(key, depth), depth)
        if not v.known and v.const is None and v.pending is None:
            d = self.folder.defines.get(key)
            if d is not None:
                c = define_const(d, self.folder.defines)
                if c is not None:
                    return constant(c)
            if self.compiled is not None:
                found = self._compiled_constant(pf, n, key)
                if found is not None:
                    return found
            return self._field_pending(pf, fnode, n, key) or name_hint(key)
        return v

    def ned_down(self, pf: Any, left: Any) -> bool:
        """Whether the left side of an assignment is a NED z (positive down): by its name
        (``m_ned_z``, ``ned.down``) or as the ``z`` / ``down`` field of a NED type
        (``mavlink_local_position_ned_t sp; sp.z``)."""
        left = strip(left)
        if left is None or left.type not in ("identifier", "field_expression"):
            return False
        if ned_z_name(_target(left)):
            return True
        if left.type != "field_expression":
            return False
        obj = strip(left.child_by_field_name("argument"))
        field = text(left.child_by_field_name("field"))
        if obj is None or obj.type != "identifier" or field.lower() not in ("z", "down", "d"):
            return False
        cls = self.class_of(pf.function_of(left), text(obj), left)
        return bool(cls and _NED_WORD.search(cls))

    def _field_pending(self, pf: Any, fnode: Any, n: Any, key: str) -> AbstractValue | None:
        """A struct field the folder never writes, to look for where the repository does:
        ``att.yaw`` / ``p->yaw`` of a local, parameter or member declared of a class, and,
        in a library file read alone, a bare field of the class whose method reads it."""
        if n.type == "field_expression":
            obj = strip(n.child_by_field_name("argument"))
            if obj is not None and obj.type == "field_expression":
                # ``m_gps->fix.speed``: a field of member ``fix`` of m_gps's class, whose
                # class the repository's declaration of that class gives
                inner = strip(obj.child_by_field_name("argument"))
                member = text(obj.child_by_field_name("field"))
                if inner is None or inner.type != "identifier" or not member:
                    return None
                outer = self.class_of(fnode, text(inner), n)
                field = text(n.child_by_field_name("field"))
                if outer is None or not field:
                    return None
                return AbstractValue(
                    pending=f".{outer}{MEMBER_MARK}{member}.{field}",
                    why=(f"`{brief(text(n), 30)}`, a field of {outer}::{member}, at {_at(pf, n)}",),
                )
            if obj is None or obj.type != "identifier":
                return None
            cls = self.class_of(fnode, text(obj), n)
            if cls is None:  # ``auto x = p->getX(); x.yaw``: of the class getX returns
                getter = fields.auto_getter(fnode, text(obj))
                cls = f"{getter}()" if getter else None
            field = text(n.child_by_field_name("field"))
        elif n.type == "identifier" and self.library:
            cls, field = fields.enclosing_class(n), key
        else:
            return None
        if not field:
            return None
        known = library_field(pf, cls, field)
        if known is not None:  # a library struct's field (MAVLink's decoded messages)
            return AbstractValue(
                unit=known[0],
                sense=known[1],
                range=known[2],
                why=(f"`{brief(text(n), 30)}`, a field of {cls}, at {_at(pf, n)}: {known[3]}",),
            )
        hint = name_hint(key)
        anywhere: AbstractValue | None = hint if hint.known else None
        if cls:
            aliases = [field]
            if b"union" in pf.data:  # (most files declare none: no walk of their tree)
                aliases.extend(fields.union_aliases(pf.tree.root_node, cls, field))
            whose = f"what {cls} returns" if cls.endswith("()") else cls
            anywhere = AbstractValue(
                pending=f".{cls}.{'|'.join(aliases)}",
                why=(f"`{brief(text(n), 30)}`, a field of {whose}, at {_at(pf, n)}",),
                fallback=anywhere,
            )
        if n.type == "field_expression":
            # ``read_euler_deg(&e); ... e.pitch``: what that call sets the field to, before
            # what any writer of the class's field may set it to
            setter = self._field_setter(fnode, n, text(obj))
            if setter is not None:
                call, name, index = setter
                return AbstractValue(
                    pending=f"{name}#{index}.{field}",
                    why=(f"{brief(text(call))} at {_at(pf, call)}",),
                    fallback=anywhere,
                )
        return anywhere if cls else None

    def _field_setter(self, fnode: Any, use: Any, obj: str) -> tuple[Any, str, int] | None:
        """The last call before ``use`` in ``fnode`` that is handed ``obj`` (``&obj``, or
        ``obj`` by reference) to fill in, with its callee and the argument's index."""
        if fnode is None:  # (an expression outside any function)
            return None
        for call, name, index in reversed(_calls_passing(fnode, obj, self.folder.passing)):
            if call.end_byte <= use.start_byte and name and name not in _NOT_SETTERS:
                return call, name, index
        return None

    def _compiled_constant(self, pf: Any, n: Any, key: str) -> AbstractValue | None:
        """A constant defined where tree-sitter does not look (another folder's header, a
        ``-D`` flag), as the compiler folds it."""
        at = n
        if n.type == "field_expression":
            at = n.child_by_field_name("field")
        elif n.type == "qualified_identifier":
            at = n.child_by_field_name("name")
        if at is None or self.compiled is None:
            return None
        row, col = at.start_point
        found = self.compiled.constant(pf.path, row, col, key)
        return constant(found[0], found[1]) if found is not None else None

    def _local(self, pf: Any, fnode: Any, use: Any, key: str, depth: int) -> AbstractValue | None:
        cands = pf.local.get(fnode.id, {}).get(key, [])
        declared = any(a.node.type == "init_declarator" for a in cands)
        before = [
            a for a in cands if a.node.start_byte < use.start_byte and not _inside(use, a.node)
        ]
        out = self._out_call(pf, fnode, use, key, before, declared, depth)
        if out is not None:
            return out
        return self._assigned(pf, fnode, use, key, before, declared, depth)

    def _assigned(
        self, pf: Any, fnode: Any, use: Any, key: str, before: list, declared: bool, depth: int
    ) -> AbstractValue | None:
        if not before:
            if declared:
                return UNKNOWN
            if _is_param(fnode, key):
                return self._param(fnode, key, depth)
            return None  # a member or a global
        state: AbstractValue | None = None
        for a in before:
            cond = _guard(a.node, fnode)
            if a.op == "=" and cond is not None:
                a = _as_compound(a, key)  # ``yaw = yaw + 2*M_PI`` as ``yaw += 2*M_PI``
            if a.op == "=":
                v = self._hoisted_mail(pf, a.rhs, use)
                v = settle(self._eval(pf, a.rhs, depth + 1)) if v is None else v
                if (
                    v.pending is not None or _parsed_text(a.rhs, v) or _speed_named(key, v)
                ) and name_hint(key).known:
                    # an opaque getter, or a number parsed from a device's text, kept in a
                    # variable that names its unit (``double dfHeading = atof(field)``)
                    v = name_hint(key)
                elif v.sign is None and v.const is None and _DEPTH_NAME.search(key):
                    # a depth worked out from a pressure (``double depth = (p - p0) / rho_g``)
                    hint = name_hint(key)
                    v = hint if hint.sign == "down" else v
                else:
                    v = _heading_named(key, v)
                if cond is not None and state is not None and not _inside(use, cond):
                    state = join(state, v)
                else:
                    state = v
                continue
            if state is not None:
                base = state
            elif declared:
                base = UNKNOWN
            elif _is_param(fnode, key):  # a parameter changed in place (``hdg -= 360``)
                base = self._param(fnode, key, depth)
            else:
                base = self._member(key, depth)
            state = self._compound(pf, a, base, cond, key, depth)
        return state

    def _out_call(
        self, pf: Any, fnode: Any, use: Any, key: str, before: list, declared: bool, depth: int
    ) -> AbstractValue | None:
        """The value a call sets local ``key`` to through a reference or pointer argument
        (``getAttitude(roll, pitch, yaw)``, ``read(&yaw)``), when the last such call comes
        after the last assignment before ``use``; None when no call sets it."""
        after = before[-1].node.end_byte if before else 0
        for call, name, index in reversed(_calls_passing(fnode, key, self.folder.passing)):
            if not (after <= call.start_byte and call.end_byte <= use.start_byte):
                continue
            own = self.folder.functions.get(name)
            at = _at(pf, call)
            if facts.BUFFER_READS.get(name) == index:
                argv = call.child_by_field_name("arguments").named_children
                v = self._buffer_read(pf, call, argv[0]) if argv else UNKNOWN
            elif own:
                v = self.out_param(name, own, index, depth)
                if v is None:
                    continue  # the function does not set this argument
                v = v.because(f"{name}() sets `{key}` at {at}")
            elif name in _NOT_SETTERS or not name or _by_value(name):
                continue
            else:
                prior = self._assigned(pf, fnode, call, key, before, declared, depth)
                v = AbstractValue(
                    pending=f"{name}#{index}",
                    why=(f"{brief(text(call))} at {at}",),
                    fallback=prior if prior is not None else UNKNOWN,
                )
            cond = _guard(call, fnode)
            if cond is not None and not _inside(use, cond) and v.pending is None:
                prior = self._assigned(pf, fnode, call, key, before, declared, depth)
                if prior is not None and (prior.known or prior.const is not None):
                    v = join(prior, v)
            return v
        return None

    def _member_set_by_calls(self, key: str, depth: int) -> AbstractValue:
        """A member never assigned but passed to functions of the folder that set it
        (``getAttitude(m_roll, m_pitch, m_yaw)`` in one method, published in another)."""

        def values() -> Iterator[AbstractValue]:
            for pf in self.folder.files:
                for fnode in pf.functions:
                    if key in pf.local.get(fnode.id, {}) or _is_param(fnode, key):
                        continue  # a local of that name
                    for call, name, index in _calls_passing(fnode, key, self.folder.passing):
                        own = self.folder.functions.get(name)
                        if not own:
                            continue  # a function we cannot see may or may not set it
                        v = self.out_param(name, own, index, depth + 1)
                        if v is not None:
                            yield v.because(f"{name}() sets `{key}` at {_at(pf, call)}")

        return self._once(("member-out", key), lambda: _join_all(values()) or UNKNOWN)

    def out_param(self, name: str, defs: list[tuple[Any, Any]], index: int, depth: int):
        """What function ``name`` sets its ``index``-th argument to (a non-const reference or
        pointer parameter), or None when no definition sets it."""

        def values() -> Iterator[AbstractValue]:
            for pf, fn in defs:
                found = _out_param(fn, index)
                if found is None:
                    continue
                pname, pointer = found
                if pointer:
                    for rhs in _pointer_writes(fn, pname):
                        yield settle(self._eval(pf, rhs, depth + 1)).because(
                            f"{name}() sets `*{pname}` to {brief(text(rhs))} at {_at(pf, rhs)}"
                        )
                    continue
                writes = [a for a in pf.local.get(fn.id, {}).get(pname, []) if a.op]
                body = fn.child_by_field_name("body")
                if not writes or body is None or not body.children:
                    continue
                v = self._assigned(pf, fn, body.children[-1], pname, writes, False, depth + 1)
                if v is not None:
                    last = writes[-1]
                    step = f"{name}() sets `{pname}`: {brief(text(last.node))}"
                    yield settle(v).because(f"{step} at {_at(pf, last.node)}")

        return self._once(("out", name, index), lambda: _join_all(values()), on_cycle=None)

    def out_field(self, name: str, defs: list[tuple[Any, Any]], index: int, field: str, depth: int):
        """What function ``name`` sets field ``field`` of its ``index``-th argument to
        (``p->yaw = ...`` for a pointer, ``s.yaw = ...`` for a reference), or None."""

        def values() -> Iterator[AbstractValue]:
            for pf, fn in defs:
                found = _out_param(fn, index)
                if found is None:
                    continue
                pname = found[0]
                for node, rhs in _param_field_writes(fn, pname, field):
                    yield settle(self._eval(pf, rhs, depth + 1)).because(
                        f"{name}() sets `{brief(text(node.child_by_field_name('left')), 30)}` "
                        f"to {brief(text(rhs))} at {_at(pf, rhs)}"
                    )

        return self._once(("field", name, index, field), lambda: _join_all(values()), on_cycle=None)

    def _param(self, fnode: Any, key: str, depth: int) -> AbstractValue:
        """A parameter: what the folder's calls of the function pass for it."""
        name = _function_short_name(fnode)
        index = _param_index(fnode, key)
        pkey = ("param", name, index)
        if index is None or pkey in self._stack or depth > MAX_DEPTH // 2:
            return name_hint(key)
        self._stack.add(pkey)
        out: AbstractValue | None = None
        try:
            for cpf, call in self.folder.calls(name):
                args = _arguments(call)
                if index < len(args):
                    v = settle(self._eval(cpf, args[index], depth + 1))
                    if not v.known:
                        continue  # a call we cannot read says nothing against the others
                    v = v.because(f"{_PASSED}{name}() at {_at(cpf, call)}")
                    out = v if out is None else join(out, v)
        finally:
            self._stack.discard(pkey)
        if out is None or not (out.known or out.pending or out.const is not None):
            return name_hint(key)
        return out

    def _compound(
        self, pf: Any, a: Any, base: AbstractValue, cond: Any, key: str, depth: int
    ) -> AbstractValue:
        rhs = settle(self._eval(pf, a.rhs, depth + 1))
        op = a.op[:-1]
        if op in ("+", "-") and rhs.const is not None and cond is not None:
            step = rhs.const if op == "+" else -rhs.const
            w = _wrap_step(base, cond, key, step, self, pf, depth)
            if w is not None:
                return w
        if op in ("+", "-"):
            return add(base, rhs, op == "-")
        if op in ("*", "/") and rhs.const is not None and rhs.const != 0:
            return settle(_scaled(base, rhs.const if op == "*" else 1 / rhs.const, rhs.why))
        return UNKNOWN

    def _member(self, key: str, depth: int) -> AbstractValue:
        asgs = self.folder.members.get(key)
        if not asgs:
            return self._member_set_by_calls(key, depth)

        def plain() -> Iterator[AbstractValue]:
            for pf, a in asgs:
                if a.op != "=":
                    continue
                v = settle(self._eval(pf, a.rhs, depth + 1))
                if _speed_named(key, v):
                    v = name_hint(key)
                else:
                    v = _heading_named(key, v)
                if v.known and v.pending is None and a.fn is not None:
                    v = v.because(f"`{key}` set at {place(pf.path, a.node.start_point[0] + 1)}")
                yield v

        def compute() -> AbstractValue:
            out = _join_all(plain())
            for pf, a in asgs:
                if a.op == "=" or out is None:
                    continue
                cond = _guard(a.node, a.fn) if a.fn is not None else None
                out = self._compound(pf, a, out, cond, key, depth)
            return out or UNKNOWN

        return self._once(("member", key), compute)


def _at(pf: Any, n: Any) -> str:
    return place(pf.path, n.start_point[0] + 1)


def brief(s: str, n: int = 48) -> str:
    """An expression for a message: call arguments elided, one line, at most ``n`` characters."""
    s = " ".join(s.split())
    for _ in range(8):
        brief = re.sub(r"(\w)\((?!\.\.\.\))[^()]+\)", r"\1(...)", s)
        if brief == s:
            break
        s = brief
    return s if len(s) <= n else s[: n - 1] + "…"


def _scaled(v: AbstractValue, c: float, why: tuple[str, ...] = ()) -> AbstractValue:
    """``v`` times ``c``; ``why``: where ``c`` comes from (a constant libclang folded)."""
    if v.const is not None:
        out = constant(v.const * c)
        return replace(out, why=(*v.why, *why)) if v.why or why else out
    out = replace(v, scale=v.scale * c)
    return replace(out, why=(*out.why, *why)) if why else out


#: the wording of an NMEA field's reason (:func:`speed_unit` rewords it for a speed)
_NMEA_FIELD = "an NMEA field"
_NMEA_ANGLES = "; NMEA 0183 angles are degrees"
#: the speed sentences, named anywhere in a file (which then is looked at more closely)
_SPEED_SENTENCE = re.compile("|".join(facts.NMEA_SPEED_FIELDS).encode())
_SENTENCES = "|".join(dict.fromkeys((*facts.NMEA_SENTENCES, *facts.NMEA_SPEED_FIELDS)))
#: a sentence named in a condition (``flds[0] == "$GPRMC"``, ``key == "VTG"``)
_SENTENCE_IN_TEXT = re.compile(r"\b(?:\$?[A-Z]{2})?(" + _SENTENCES + r")\b")
#: a sentence in a function's name, in capitals (``handleMsgGPRMC``, ``parseVTG``)
_SENTENCE_IN_NAME = re.compile(_SENTENCES)
_FIELD_INDEX = re.compile(r"\[\s*(\d+)\s*\]|[(,]\s*(\d+)\s*[,)]")
#: a part of a text taken (``f.substr(0, 2)``, ``s.mid(2)``), not a whole field
_PART_OF_TEXT = re.compile(r"\b(?:substr|substring|mid)\s*\(")


def _sentence_of(call: Any) -> str | None:
    """The one NMEA sentence the code around ``call`` handles: named in the condition of
    an ``if`` whose branch holds it, or else in the name of its function
    (``handleGPRMC``); None where none or several are."""
    p, child = call.parent, call
    while p is not None and p.type != "function_definition":
        if p.type == "if_statement" and child == p.child_by_field_name("consequence"):
            found = set(_SENTENCE_IN_TEXT.findall(text(p.child_by_field_name("condition"))))
            if found:
                return found.pop() if len(found) == 1 else None
        p, child = p.parent, p
    if p is None:
        return None
    found = set(_SENTENCE_IN_NAME.findall(_function_short_name(p)))
    return found.pop() if len(found) == 1 else None


def _nmea_speed(call: Any, args: list[Any]) -> tuple[str, str] | None:
    """For a number parsed from text where the code handles one NMEA speed sentence (see
    :func:`_sentence_of`), the unit the field has when it is a speed, and the sentence;
    None elsewhere."""
    sentence = _sentence_of(call)
    fields_of = facts.NMEA_SPEED_FIELDS.get(sentence or "")
    if fields_of is None:
        return None
    m = _FIELD_INDEX.search(text(args[0])) if args else None
    index = int(m.group(1) or m.group(2)) if m else None
    if fields_of and index not in fields_of:
        return None  # VTG, VHW: a field that is not a speed we know the unit of
    return (fields_of.get(index, "kn") if index is not None else "kn"), str(sentence)


def speed_unit(v: AbstractValue) -> tuple[str, list[str]] | None:
    """The speed unit other than metres per second that ``v`` is in, with the reasons,
    source first: its unit, or the NMEA speed field it was read from (whose angle hint
    then says nothing); None when neither."""
    if v.unit in facts.SPEED_UNITS:
        return v.unit, list(v.why)
    if v.nmea_speed is None or not (v.unit is None or (v.unit == "deg" and v.hint)):
        return None
    unit, sentence = v.nmea_speed
    field = f"a field of NMEA's {sentence} sentence, in {speed_label(unit)},"
    steps = [w.replace(_NMEA_ANGLES, "").replace(_NMEA_FIELD, field) for w in v.why]
    return unit, steps


def nmea_position(v: AbstractValue) -> tuple[str, list[str]] | None:
    """For a value read from a field of an NMEA position sentence as it is written
    (ddmm.mmmm, with nothing done to it but a sign), the sentence and the reasons, source
    first; None for any other."""
    if v.nmea_position is None:
        return None
    field = f"a field of NMEA's {v.nmea_position} sentence"
    return v.nmea_position, [w.replace(_NMEA_ANGLES, "").replace(_NMEA_FIELD, field) for w in v.why]


def speed_label(unit: str) -> str:
    return {"kn": "knots", "km/h": "km/h", "mph": "miles an hour", "m/s": "m/s"}.get(unit, unit)


def _parsed_text(rhs: Any, v: AbstractValue) -> bool:
    """Whether ``rhs`` is a number parsed from text (``atof(...)``, ``std::stod(...)``) of
    which nothing is known: a value that only its variable's name describes."""
    n = strip(rhs)
    if n is None or n.type != "call_expression" or v.known or v.const is not None:
        return False
    return callee_name(n.child_by_field_name("function")) in facts.TEXT_TO_NUMBER


def _as_compound(a: Any, key: str) -> Any:
    """``key = key + c`` / ``key = key - c`` as ``key += c`` / ``key -= c``; else ``a``."""
    rhs = strip(a.rhs)
    if rhs is None or rhs.type != "binary_expression":
        return a
    op = text(rhs.child_by_field_name("operator"))
    left = strip(rhs.child_by_field_name("left"))
    if op not in ("+", "-") or left is None or _target(left) != key:
        return a
    return replace(a, op=op + "=", rhs=rhs.child_by_field_name("right"))


def _target(n: Any) -> str:
    if n.type in ("identifier",):
        return text(n)
    if n.type == "field_expression":
        obj = n.child_by_field_name("argument")
        if obj is not None and text(obj) == "this":
            return text(n.child_by_field_name("field"))
        return text(n)
    if n.type == "qualified_identifier":
        name = n.child_by_field_name("name")
        return text(name) if name is not None else ""
    return ""


#: calls that read their arguments and never set them
_NOT_SETTERS = {
    "Notify",
    "printf",
    "fprintf",
    "sprintf",
    "snprintf",
    "MOOSTrace",
    "reportEvent",
    "reportRunWarning",
    "reportConfigWarning",
    "doubleToString",
    "doubleToStringX",
    "intToString",
    "to_string",
    "push_back",
    "emplace_back",
    "insert",
    "fabs",
    "abs",
    "sqrt",
    "pow",
    "sin",
    "cos",
    "tan",
    "isnan",
    "isfinite",
    "min",
    "max",
}


def _by_value(name: str) -> bool:
    """Whether ``name`` is a function of a library the analysis knows that takes its
    arguments by value (``degToRadians(hdg)``, ``angle360(h)``, ``atan2(dy, dx)``): a call
    of it never sets a variable handed to it."""
    bare = re.sub(r"^std::", "", name)
    return (
        name in facts.HELPERS
        or name in facts.KEEPS_UNIT
        or bare in _PASS_THROUGH
        or bare in facts.MATH_BY_VALUE
        or bare.rstrip("f") in facts.INVERSE_TRIG
        or bare in facts.TEXT_TO_NUMBER
        or bool(re.match(facts.DEG2RAD_NAME, name) or re.match(facts.RAD2DEG_NAME, name))
    )


def _calls_passing(fnode: Any, key: str, memo: dict) -> list[tuple[Any, str, int]]:
    """The calls in ``fnode`` that pass ``key`` (or ``&key``) as an argument, in order:
    (call, callee, argument index). ``memo`` keeps each function's calls by variable."""
    calls = memo.get(fnode.id)
    if calls is None:
        calls = memo[fnode.id] = _calls_by_argument(fnode)
    return calls.get(key, [])


def _calls_by_argument(fnode: Any) -> dict[str, list[tuple[Any, str, int]]]:
    found: dict[str, list[tuple[Any, str, int]]] = {}
    body = fnode.child_by_field_name("body")
    stack = [body] if body is not None else []
    while stack:
        x = stack.pop()
        if x.type in ("lambda_expression", "function_definition", "class_specifier"):
            continue
        if x.type == "call_expression":
            args = x.child_by_field_name("arguments")
            argv = [a for a in args.named_children if a.type != "comment"] if args else []
            for i, a in enumerate(argv):
                a = strip(a)
                if a is None:
                    continue
                if a.type == "pointer_expression" and text(a).startswith("&"):
                    a = strip(a.child_by_field_name("argument"))
                if a is not None and a.type == "identifier":
                    name = callee_name(x.child_by_field_name("function"))
                    found.setdefault(text(a), []).append((x, name, i))
        stack.extend(x.named_children)
    for calls in found.values():
        calls.sort(key=lambda c: c[0].start_byte)
    return found


def _out_param(fn: Any, index: int) -> tuple[str, bool] | None:
    """The ``index``-th parameter of ``fn`` when the function may set it: its name, and
    whether it is a pointer (else a non-const reference)."""
    decl = function_declarator(fn)
    params = decl.child_by_field_name("parameters") if decl is not None else None
    plist = [
        p for p in (params.named_children if params is not None else ()) if p.type != "comment"
    ]
    if index >= len(plist):
        return None
    p = plist[index]
    d = p.child_by_field_name("declarator")
    if d is None or d.type not in ("reference_declarator", "pointer_declarator"):
        return None
    if any(c.type == "type_qualifier" and text(c) == "const" for c in p.children):
        return None
    pointer = d.type == "pointer_declarator"
    while d is not None and d.type != "identifier":
        nxt = d.child_by_field_name("declarator")
        if nxt is None:
            nxt = next((c for c in d.named_children if c.type == "identifier"), None)
        d = nxt
    return (text(d), pointer) if d is not None else None


def _assignments(fn: Any) -> list[Any]:
    """The plain ``x = y`` assignments in ``fn``'s own body (not in a lambda or a nested
    function or class), in source order."""
    out = []
    body = fn.child_by_field_name("body")
    stack = [body] if body is not None else []
    while stack:
        x = stack.pop()
        if x.type in ("lambda_expression", "function_definition", "class_specifier"):
            continue
        if x.type == "assignment_expression" and text(x.child_by_field_name("operator")) == "=":
            out.append(x)
        stack.extend(x.named_children)
    out.sort(key=lambda a: a.start_byte)
    return out


def _pointer_writes(fn: Any, pname: str) -> list[Any]:
    """Right sides of ``*p = x`` and ``p[0] = x`` in ``fn``."""
    out = []
    for x in _assignments(fn):
        left = strip(x.child_by_field_name("left"))
        target = None
        if left is not None and left.type == "pointer_expression" and text(left).startswith("*"):
            target = strip(left.child_by_field_name("argument"))
        elif left is not None and left.type == "subscript_expression":
            idx = left.child_by_field_name("indices") or left.child_by_field_name("index")
            if idx is not None and text(idx).strip("[] ") == "0":
                target = strip(left.child_by_field_name("argument"))
        if target is not None and target.type == "identifier" and text(target) == pname:
            out.append(x.child_by_field_name("right"))
    return out


def _param_field_writes(fn: Any, pname: str, field: str) -> list[tuple[Any, Any]]:
    """``(assignment, right side)`` of ``pname->field = x`` and ``pname.field = x`` in ``fn``."""
    out = []
    for x in _assignments(fn):
        left = strip(x.child_by_field_name("left"))
        if left is None or left.type != "field_expression":
            continue
        obj = strip(left.child_by_field_name("argument"))
        if obj is not None and obj.type == "pointer_expression":
            obj = strip(obj.child_by_field_name("argument"))  # ``(*p).yaw``
        ours = obj is not None and obj.type == "identifier" and text(obj) == pname
        if ours and text(left.child_by_field_name("field")) == field:
            out.append((x, x.child_by_field_name("right")))
    return out


def _returns_of(fn: Any) -> list[Any]:
    body = fn.child_by_field_name("body")
    out = []
    stack = [body] if body is not None else []
    while stack:
        x = stack.pop()
        if x.type == "return_statement":
            out.append(x)
            continue
        if x.type in ("lambda_expression", "function_definition", "class_specifier"):
            continue
        stack.extend(x.named_children)
    return out


def _guard(n: Any, fnode: Any) -> Any:
    """The ``if``/``while`` statement ``n`` is conditional on (within its function)."""
    p = n.parent
    while p is not None and p != fnode:
        if p.type in ("if_statement", "while_statement", "for_statement", "do_statement"):
            return p
        p = p.parent
    return None


def _wrap_step(
    base: AbstractValue,
    stmt: Any,
    key: str,
    step: float,
    ev: Evaluator,
    pf: Any,
    depth: int,
) -> AbstractValue | None:
    """``if (x < b) x += c`` / ``while (x > b) x -= c``: the range after it."""
    compared = _compared(stmt, key, ev, pf, depth)
    if compared is None:
        return None
    op, bound = compared
    loop = stmt.type in ("while_statement", "for_statement", "do_statement")
    lo, hi = base.range if base.range else (-math.inf, math.inf)
    turn = _full_turn(step)
    if not loop and turn is not None and not math.isfinite(lo) and not math.isfinite(hi):
        # a value of unknown range wrapped by one turn, once: the author takes it to be
        # within a turn of the wrap, so the range is the turn the ``if`` names
        # (``if (yaw < 0) yaw += 2*M_PI``: [0, 2π)), and a turn of 2π says radians
        if op in ("<", "<=") and step > 0:
            new = (bound, bound + step)
        elif op in (">", ">=") and step < 0:
            new = (bound + step, bound)
        else:
            return None
        why = f"wrapped by `{brief(text(stmt).split(chr(10))[0], 40)}` at {_at(pf, stmt)}"
        return wrapped(base, new, base.unit or turn, why)
    if op in ("<", "<=") and step > 0:
        if lo >= bound:
            return base
        new = (
            (bound, max(hi, bound + step))
            if loop
            else (min(lo + step, bound), max(hi, bound + step))
        )
        if not loop and not math.isfinite(lo):
            new = (-math.inf, max(hi, bound + step))
    elif op in (">", ">=") and step < 0:
        if hi <= bound:
            return base
        new = (
            (min(lo, bound + step), bound)
            if loop
            else (min(lo, bound + step), max(hi + step, bound))
        )
        if not loop and not math.isfinite(hi):
            new = (min(lo, bound + step), math.inf)
    else:
        return None
    why = f"wrapped by `{brief(text(stmt).split(chr(10))[0], 40)}` at {_at(pf, stmt)}"
    return (
        replace(base, range=new, const=None).because(why)
        if base.known
        else replace(base, range=new, const=None)
    )


def _compared(stmt: Any, key: str, ev: Evaluator, pf: Any, depth: int) -> tuple[str, float] | None:
    """``(op, bound)`` when ``stmt``'s condition is ``key op bound`` (or ``bound op key``,
    turned round) with a constant bound and op one of ``< <= > >=``."""
    cond = stmt.child_by_field_name("condition")
    if cond is None:
        return None
    c = strip(cond.named_children[0] if cond.type == "condition_clause" else cond)
    while c is not None and c.type == "parenthesized_expression":
        c = strip(c)
    if c is None or c.type != "binary_expression":
        return None
    op = text(c.child_by_field_name("operator"))
    left, right = strip(c.child_by_field_name("left")), strip(c.child_by_field_name("right"))
    if left is None or right is None:
        return None
    if _target(left) == key:
        bound = settle(ev._eval(pf, right, depth + 1)).const
    elif _target(right) == key:
        bound = settle(ev._eval(pf, left, depth + 1)).const
        op = _TURNED.get(op, op)
    else:
        return None
    if bound is None or op not in _TURNED:
        return None
    return op, bound


_TURNED = {"<": ">", "<=": ">=", ">": "<", ">=": "<="}
_NEGATED = {"<": ">=", "<=": ">", ">": "<=", ">=": "<"}


def _narrowed(
    ev: Evaluator, pf: Any, fnode: Any, use: Any, key: str, v: AbstractValue, depth: int
) -> AbstractValue:
    """``v`` (the value of ``key`` at ``use``) within the bounds of the ``if``s ``use`` is
    in a branch of: in ``if (y > M_PI) out = y - 2*M_PI; else out = y;`` the first ``y``
    is above π and the second not. Only a known range is narrowed, and not past a write
    to ``key`` inside the ``if``."""
    if v.range is None or v.const is not None or fnode is None:
        return v
    lo, hi = v.range
    child, p = use, use.parent
    while p is not None and p != fnode:
        if p.type == "if_statement":
            taken = (
                True
                if child == p.child_by_field_name("consequence")
                else False
                if child == p.child_by_field_name("alternative")
                else None
            )
            compared = _compared(p, key, ev, pf, depth) if taken is not None else None
            if compared is not None and not _written_before(p, use, key):
                op, bound = compared if taken else (_NEGATED[compared[0]], compared[1])
                if op in (">", ">="):
                    lo = max(lo, bound)
                else:
                    hi = min(hi, bound)
        child, p = p, p.parent
    if (lo, hi) == v.range or lo > hi:
        return v
    return replace(v, range=(lo, hi))


def _written_before(stmt: Any, use: Any, key: str) -> bool:
    """Whether ``key`` may be written inside ``stmt`` before ``use``."""
    src = stmt.text[: use.start_byte - stmt.start_byte].decode("utf-8", "replace")
    name = re.escape(key.rsplit(".", 1)[-1])
    return bool(
        re.search(rf"(?<![\w.])(?:\+\+|--)?{name}\s*(?:\+\+|--|[-+*/]?=(?!=))", src)
        or re.search(rf"[&(,]\s*&?\s*{name}\s*[,)]", src)
    )


def _full_turn(step: float) -> str | None:
    """The unit a wrap step of one full turn says (2π: radians, 360: degrees), else None."""
    if abs(abs(step) - 2 * math.pi) < 1e-3:
        return "rad"
    return "deg" if abs(abs(step) - 360.0) < 1e-9 else None


def define_const(val: str, defines: dict[str, str], depth: int = 0) -> float | None:
    """The number a ``#define`` stands for: a literal, π, or π/180 and 180/π forms."""
    v = val.strip()
    while v.startswith("(") and v.endswith(")"):
        v = v[1:-1].strip()
    try:
        return float(re.sub(r"[fFlL]$", "", v))
    except ValueError:
        pass
    if v in facts.PI_NAMES:
        return facts.PI_NAMES[v]
    if v in defines and depth < 4:
        return define_const(defines[v], defines, depth + 1)
    m = re.fullmatch(r"\(?\s*([\w.]+)\s*\)?\s*([*/])\s*\(?\s*([\w.]+)\s*\)?", v)
    if m:
        a = define_const(m.group(1), defines, depth + 1)
        b = define_const(m.group(3), defines, depth + 1)
        if a is not None and b is not None:
            return a * b if m.group(2) == "*" else (a / b if b else None)
    return None


# -- the repository: pending calls and consumers ---------------------------------


def resolve_pending(v: AbstractValue, resolver: Any) -> AbstractValue:
    """A pending value with its function's return resolved across the repository."""
    if v.pending is None:
        return v
    # (a library class's method is known where it is called: :meth:`Evaluator._call`)
    base = resolver(v.pending, v.receiver) if v.receiver else resolver(v.pending)
    if v.pending.startswith(".") and (base is None or not base.known):
        # a field the repository never writes (or not in a way we can read): its name,
        # or the comment or print label where the app reads it
        first = v.pending.split("|")[0]
        before = v.fallback if v.fallback is not None else name_hint(first)
        if not before.known and isinstance(resolver, RepositoryResolver):
            declared = resolver.declared(v.pending)
            if declared is not None:
                before = declared
        out = apply_ops(before, v.ops)
        return replace(out, why=(*out.why, *v.why[1:])) if out.known else UNKNOWN
    if "#" in v.pending and (base is None or not base.known):
        # an argument the function does not set (or one we cannot see): as before the call
        before = v.fallback if v.fallback is not None else UNKNOWN
        return apply_ops(resolve_pending(before, resolver), v.ops)
    if (base is None or not base.known) and isinstance(resolver, RepositoryResolver):
        base = resolver.set_by(v.pending, v.receiver) or base  # a getter through its setter
    if base is None or not base.known:
        base = name_hint(v.pending)  # a getter defined nowhere in the repository
    out = apply_ops(base, v.ops)
    if not out.known:
        return UNKNOWN
    if not base.known:  # known by what was done to it (a conversion, a wrap): their reasons
        return (
            out
            if out.why
            else replace(out, why=tuple(s for _op, s in v.ops if isinstance(s, str) and s))
        )
    return replace(out, why=(*base.why, *v.why[1:]))


#: a getter's name (``getPitch``, ``GetDepth``): its setter is ``setPitch`` / ``SetDepth``
_GETTER_NAME = re.compile(r"^(get|Get)([A-Z]\w*)$")
_WORD = re.compile(rb"\w+")


_CLASS_HEAD = re.compile(rb"\b(?:class|struct)\s+(\w+)[^;{}()]*\{")
_LAST_WORD = re.compile(rb"(\w+)\s*$")


def _owners_of(name: bytes, data: bytes) -> set[str]:
    """The classes ``data`` defines a method ``name`` of, as far as its bytes tell: the
    qualifier of ``Owner::name(...) {``, or for a definition inside a class body the
    class whose head comes last before it (a guess: it only orders the reads)."""
    out: set[str] = set()
    for m in re.finditer(DEF_TEMPLATE % re.escape(name), data):
        if data.startswith(b"::", m.start()):  # ``Owner::name(...) {``
            q = _LAST_WORD.search(data, max(0, m.start() - 200), m.start())
            if q is not None:
                out.add(q.group(1).decode("utf-8", "replace"))
            continue
        last = None
        for c in _CLASS_HEAD.finditer(data, 0, m.start()):
            last = c
        if last is not None:
            out.add(last.group(1).decode("utf-8", "replace"))
    return out


#: How many parsed files a :class:`RepositoryResolver` keeps. A syntax tree takes a few
#: hundred KB of the heap, and a resolution asks again for one of the last few files it
#: parsed (on the MOOS-IvP tree: 13 files parsed, 11 of the 13 asked again after at
#: most 3 others); an older one is parsed again if asked for.
KEEP_PARSED = 4


class RepositoryResolver:
    """Resolves a function's return value by its name across the repository's C++ files.

    Each file is indexed once (:mod:`~moos_lint.frontends.cpp.file_names`: the names
    it may define, the setters it names), from ``known`` (the index its first read made)
    or from a read of its own; a file is parsed only when a pending value names a
    function it may define. Only the index is kept, not the files' bytes, and only the
    last :data:`KEEP_PARSED` parsed files.
    """

    def __init__(
        self,
        paths: list[str],
        read: Any,
        compiled: Compiled | None = None,
        known: dict[str, FileNames] | None = None,
    ):
        self.paths = paths
        self.read = read
        self.compiled = compiled
        self.known = known or {}
        #: each file's index (in the order of :attr:`all_paths`), once it is read
        self._names: list[FileNames] = []
        self.cache: dict[str, AbstractValue | None] = {}
        #: the last parsed files (:data:`KEEP_PARSED`), by path
        self.parsed: OrderedDict[str, Any] = OrderedDict()
        #: every file parsed so far
        self.parsed_once: set[str] = set()
        self._index: dict[bytes, list[int]] | None = None
        #: class -> the files that name it, for :meth:`_field` (read again when asked: a
        #: class many files name would otherwise keep all their bytes)
        self._naming: dict[str, list[str]] = {}
        self._all: list[str] | None = None
        #: classes whose fields are waited for, and setters of awaited getters (see
        #: :meth:`expect`): the words whose files the one read of every file finds
        self._expected: set[str] = set()
        #: the functions the values wait for (see :meth:`expect`), and the classes whose
        #: methods they are (``NodeRecord`` for ``NodeRecord::getHeading``): a value such
        #: a method returns often waits for a field of its class, and the files naming
        #: each are found in one read, with the first class asked for (:meth:`_field`)
        self._wanted: set[bytes] = set()
        self._owners: set[str] = set()
        #: the unit each field's declaration gives (see :meth:`declared`)
        self._declared: dict[str, AbstractValue | None] = {}
        #: the class each function returns (see :meth:`returned_class`)
        self._returned: dict[str, str | None] = {}

    @property
    def all_paths(self) -> list[str]:
        """The C++ files, then the C files of the same tree (device libraries are often C)."""
        if self._all is None:
            self._all = [*self.paths, *c_sources(self.paths)]
        return self._all

    def _data(self, path: str) -> bytes:
        raw = self.read(path)
        return raw if isinstance(raw, bytes) else b""

    def _candidates(self, name: str) -> list[tuple[str, bytes | None]]:
        """The files that may define ``name`` (in path order), with their bytes when read."""
        key = name.encode()
        if _WORD.fullmatch(key) is None:  # not a plain word: search every file's bytes
            pattern = re.compile(DEF_TEMPLATE % re.escape(key))
            out: list[tuple[str, bytes | None]] = []
            for path in self.all_paths:
                data = self._data(path)
                if key in data and pattern.search(data):
                    out.append((path, data))
            return out
        paths = self.all_paths
        if self._index is None:
            self._read_all()
        assert self._index is not None
        return [(paths[i], None) for i in self._index.get(key, [])]

    def expect(self, values: Iterable[AbstractValue]) -> None:
        """Note the classes whose fields ``values`` wait for, so that the one read of
        every file that indexes the functions also finds the files naming them."""
        for first in values:
            v: AbstractValue | None = first
            while v is not None:
                if v.pending and v.pending.startswith("."):
                    cls = v.pending.split(".", 2)[1]
                    if not cls.endswith("()"):  # (a getter's class is known once it is read)
                        self._expected.add(cls)
                elif v.pending:
                    self._wanted.add(v.pending.partition("#")[0].encode())
                    getter = _GETTER_NAME.match(v.pending)
                    if getter is not None:  # (see :meth:`set_by`)
                        self._expected.add(
                            getter.expand(r"set\2" if v.pending[0] == "g" else r"Set\2")
                        )
                v = v.fallback if isinstance(v.fallback, AbstractValue) else None

    def _read_all(self) -> None:
        """Index every file: the names it may define a function of (from what its first
        read noted, else read here), and whether it names each expected class (for
        :meth:`_field`)."""
        wanted = self._wanted
        expected = self._expected - set(self._naming)
        setters = {c for c in expected if SETTER_NAME.match(c)}
        byte_keys = self._naming_of(expected - setters)
        self._index = {}
        for i, path in enumerate(self.all_paths):
            names = self.known.get(path)
            data = None
            if names is None:
                data = self._data(path)
                names = file_names(data)
            self._names.append(names)
            for n in names.defined:
                self._index.setdefault(n, []).append(i)
            owned = names.defined & wanted if wanted else ()
            if byte_keys or owned:
                data = self._data(path) if data is None else data
                for key, paths in byte_keys:
                    if key in data:
                        paths.append(path)
                for n in owned:
                    self._owners.update(_owners_of(n, data))
        for cls in setters:
            self._naming[cls] = self._setter_files(cls.encode())

    def _naming_of(self, classes: set[str]) -> list[tuple[bytes, list[str]]]:
        """Start :attr:`_naming` for ``classes``: once the files are indexed, the setters
        among them are found in the index; for the others, (the class's bytes, its list
        to fill) is returned, to look for in the files' bytes."""
        out = []
        for cls in sorted(classes):
            if self._index is not None and SETTER_NAME.match(cls):
                self._naming[cls] = self._setter_files(cls.encode())
                continue
            self._naming[cls] = []
            out.append((cls.encode(), self._naming[cls]))
        return out

    def _setter_files(self, key: bytes) -> list[str]:
        """The files whose index names setter ``key``."""
        paths = self.all_paths
        return [paths[i] for i, names in enumerate(self._names) if key in names.setters]

    def _find_naming(self, classes: set[str]) -> None:
        """One read of every file: which of ``classes`` each names (for :meth:`_field`)."""
        keys = self._naming_of(classes)
        if not keys:
            return
        for path in self.all_paths:
            data = self._data(path)
            for key, paths in keys:
                if key in data:
                    paths.append(path)

    def __call__(self, name: str, receiver: str | None = None) -> AbstractValue | None:
        """What function ``name`` returns (``name#i``: what it sets its argument ``i``
        to; ``.Class.field``: what the repository writes to that field). ``receiver``:
        the class a method is called on, when declared: where the repository defines the
        method on that class, those definitions alone give the value, not a method of the
        same name on another class; where it does not (a method of a base class), every
        definition does."""
        key = f"{name}@{receiver}" if receiver and not name.startswith(".") else name
        if key in self.cache:
            return self.cache[key]
        self.cache[key] = None  # recursion guard
        if name.startswith("."):  # ``.Class.field|alias``: where the repository writes it
            self.cache[name] = self._field(name)
            return self.cache[name]
        fname, _, index = name.partition(
            "#"
        )  # ``getAttitude#2``: what it sets its third argument to
        name = fname
        out: AbstractValue | None = None
        found_own = False  # a definition on the receiver's class was found
        for path, data in self._candidates(name):
            pf = self._parse(path, data)
            if pf is None:
                continue
            folder = Folder([pf])
            defs = folder.functions.get(name)
            if not defs:
                continue
            mine = [d for d in defs if _owner(d[1]) == receiver] if receiver and not index else []
            if mine:
                if not found_own:  # other classes' definitions read before do not count
                    out = None
                found_own, defs = True, mine
            elif found_own:
                continue  # only the receiver's own definitions count now
            if index:
                at, _, field = index.partition(".")  # ``read#0.p``: the field ``p`` it sets
                ev = Evaluator(folder, library=True, compiled=self.compiled)
                if field:
                    w = ev.out_field(name, defs, int(at), field, 0)
                else:
                    w = ev.out_param(name, defs, int(at), 0)
                if w is None:
                    continue
                v = w
            else:
                v = Evaluator(folder, library=True, compiled=self.compiled)._returns(name, defs, 0)
            if v.pending is not None and v.pending != name:
                v = resolve_pending(v, self)
            if v.known:
                out = v if out is None else join(out, v)
        self.cache[f"{name}#{index}" if index else key] = out
        return out

    def _field(self, pending: str) -> AbstractValue | None:
        """What the repository writes to field ``.Class.name|alias`` (the join of every
        write; None when it writes it nowhere we can read)."""
        _, cls, names_text = pending.split(".", 2)
        if cls.endswith("()") or MEMBER_MARK in cls:  # of what a function returns, of a
            real = self._through_getter(pending)  # member: a field of that one's class
            return self(real) if real else None
        names = set(names_text.split("|"))
        wrote = field_write_pattern(names)
        out: AbstractValue | None = None
        for path in self._files_naming(cls):  # a file that never names it cannot write it
            data = None
            if path not in self.parsed_once:  # a file parsed before is not searched
                data = self._data(path)
                if not wrote.search(data):
                    continue
            pf = self._parse(path, data)
            if pf is None:
                continue
            ev = Evaluator(Folder([pf]), library=True, compiled=self.compiled)
            for node, rhs in fields.field_writes(pf, cls, names):
                v = settle(ev._eval(pf, rhs, 0))
                copied = v.pending is not None and v.pending.startswith(f".{cls}.")
                if copied and names & set(str(v.pending).split(".", 2)[2].split("|")):
                    continue  # a copy from another object of the class
                if v.pending is not None:
                    v = resolve_pending(v, self)
                if v.known:
                    left = node.child_by_field_name("left")
                    field = text(left.child_by_field_name("field") or left)
                    first = names_text.split("|")[0]
                    alias = f" (the storage of `{first}`)" if field != first else ""
                    v = v.because(
                        f"`{brief(text(left), 30)}`{alias} set to {brief(text(rhs))} "
                        f"at {_at(pf, node)}"
                    )
                out = v if out is None else join(out, v)
                if not out.known and out.const is None:
                    return None  # a write we cannot read: the field stays unknown
        return out if out is not None and out.known else None

    def _files_naming(self, cls: str) -> list[str]:
        """The files whose bytes name class ``cls``: found with the one read of every file
        that indexes the functions when it is still to come, else in a read of their own
        (with the classes of the awaited methods, :attr:`_owners`)."""
        if cls not in self._naming and self._index is None:
            self._expected.add(cls)
            self._read_all()
        if cls not in self._naming:
            self._find_naming({cls} | (self._owners - set(self._naming)))
        return self._naming[cls]

    def set_by(self, getter: str, receiver: str | None = None) -> AbstractValue | None:
        """What getter ``getX`` returns, read from what the repository gives its setter
        ``setX``: the join of the argument of every call of ``setX`` (``record.setPitch(
        angle180(p))``), each known or a constant. A record class defined outside the
        repository (MOOS-IvP's ``NodeRecord``) or one whose setter stores its parameter is
        read so. ``receiver``: the class the getter is called on, when declared; a call on
        an object declared of another class is not its setter's (a repository's own
        ``NodeRecord6DOF`` parser beside the simulator's ``NodeRecord``). None when
        ``getter`` is not named ``getX`` / ``GetX``, the repository never calls the setter,
        a call passes it another number of arguments, or one passes a value we cannot read
        (a write we cannot read leaves the value unknown)."""
        m = _GETTER_NAME.match(getter)
        if m is None:
            return None
        setter = ("set" if m.group(1) == "get" else "Set") + m.group(2)
        key = f"={setter}@{receiver or ''}"
        if key in self.cache:
            return self.cache[key]
        self.cache[key] = None  # recursion guard
        out: AbstractValue | None = None
        ranges: set[Range | None] = set()
        files = self._files_naming(setter)
        if len(files) > KEEP_PARSED:  # a setter called all over a tree (MOOS-IvP's own
            return None  # NodeRecord) is one some caller sets from what it cannot read
        for path in files:
            pf = self._parse(path, None)
            if pf is None:
                continue
            folder = Folder([pf])
            ev = Evaluator(folder, library=True, compiled=self.compiled)
            for cpf, call in folder.calls(setter):
                fn = call.child_by_field_name("function")
                if receiver and fn.type == "field_expression":
                    cls = ev.object_class(cpf, fn)
                    if cls is not None and cls != receiver:
                        continue  # another class's setter of the same name
                args = _arguments(call)
                if len(args) != 1:
                    return None
                v = settle(ev._eval(cpf, args[0], 0))
                if v.pending is not None:
                    v = resolve_pending(v, self)
                if not v.known and v.const is None:
                    return None
                if v.known:
                    v = v.because(f"{brief(text(call))} at {_at(cpf, call)}")
                ranges.add(v.range)
                out = v if out is None else join(out, v)
        if out is None or not out.known:
            return None
        if len(ranges) > 1:  # calls of several ranges: the reasons name one, so claim none
            out = replace(out, range=None)
        self.cache[key] = out
        return out

    def _through_getter(self, pending: str) -> str | None:
        """``.getX().field`` (a field of what ``getX`` returns) as ``.Class.field``, of the
        class ``getX`` returns, and ``.Outer>member.field`` of the class ``Outer`` declares
        ``member`` of; None when that class is not known."""
        _, getter, names_text = pending.split(".", 2)
        if MEMBER_MARK in getter:
            outer, _, member = getter.partition(MEMBER_MARK)
            real = self.member_class(outer, member)
        else:
            real = self.returned_class(getter.removesuffix("()"))
        return f".{real}.{names_text}" if real else None

    def _in_class_bodies(
        self, cls: str, pattern: re.Pattern[bytes]
    ) -> Iterator[tuple[str, bytes, re.Match[bytes]]]:
        """Each match of ``pattern`` in the body of a declaration of class ``cls`` in the
        repository: (path, the file's bytes, the match)."""
        for path in self._files_naming(cls):
            data = self._data(path)
            at = class_body(data, cls)
            if at is not None:
                for m in pattern.finditer(data, at[0], at[1]):
                    yield path, data, m

    def member_class(self, cls: str, member: str) -> str | None:
        """The class member ``member`` of class ``cls`` is declared of (``GPSFix`` for
        ``class GPSService { public: GPSFix fix; ... }``), read from the body of every
        declaration of ``cls`` in the repository; None when none says, or two differ."""
        key = f"{cls}{MEMBER_MARK}{member}"
        if key not in self._returned:
            found: set[str | None] = set()
            declared = re.compile(
                rb"([A-Za-z_][\w:]*(?:\s*<[^;{}()]*>)?)[\s*&]+"
                + re.escape(member.encode())
                + rb"\s*(?:=[^;]*)?;"
            )
            for _path, _data, m in self._in_class_bodies(cls, declared):
                word = m.group(1).decode("utf-8", "replace")
                if word not in _NOT_TYPES:  # (``return fix;`` in an inline method)
                    found.add(fields.type_name(word))
            self._returned[key] = found.pop() if len(found) == 1 else None
        return self._returned[key]

    def returned_class(self, name: str) -> str | None:
        """The class that every definition of function ``name`` in the repository returns
        (``UniHeadingAData`` for ``const UniHeadingAData& getUniHeadingA() const``); None
        when none is found, one returns no class, or two return different ones."""
        if name not in self._returned:
            found: set[str | None] = set()
            for path, data in self._candidates(name):
                pf = self._parse(path, data)
                for fn in pf.functions if pf is not None else ():
                    if _function_short_name(fn) == name:
                        t = fn.child_by_field_name("type")
                        found.add(fields.type_name(text(t)) if t is not None else None)
            self._returned[name] = found.pop() if len(found) == 1 else None
        return self._returned[name]

    def declared(self, pending: str) -> AbstractValue | None:
        """The unit the comment on field ``.Class.name|alias``'s declaration gives (a
        device library's ``double pitch; // degrees``): the same in every declaration
        found in the class's body, else None. Once per field."""
        if pending not in self._declared:
            self._declared[pending] = self._declared_now(pending)
        return self._declared[pending]

    def _declared_now(self, pending: str) -> AbstractValue | None:
        _, cls, names_text = pending.split(".", 2)
        if cls.endswith("()") or MEMBER_MARK in cls:
            real = self._through_getter(pending)
            return self.declared(real) if real else None
        names = b"|".join(re.escape(n.encode()) for n in names_text.split("|") if n)
        if not names:
            return None
        pattern = re.compile(_FIELD_LINE % names, re.M | re.S)
        found: AbstractValue | None = None
        for path, data, m in self._in_class_bodies(cls, pattern):
            line = data.count(b"\n", 0, m.start(1)) + 1
            where = f"`{cls}::{names_text.split('|')[0]}` ({os.path.basename(path)}:{line})"
            v = declaration_hint(m.group(1).decode("utf-8", "replace"), where)
            if v is None or (found is not None and found.unit != v.unit):
                return None
            found = found or v
        return found

    def _parse(self, path: str, data: bytes | None) -> Any:
        """The parsed file (None if it cannot be parsed); ``data``: its bytes, if read."""
        if path in self.parsed:
            self.parsed.move_to_end(path)
            return self.parsed[path]
        from moos_lint.frontends.cpp.extract import ParsedFile
        from moos_lint.frontends.cpp.parse import backend

        be = backend()
        if data is None:
            data = self._data(path)
        try:
            text_ = data.decode("utf-8", "replace").replace("\r\n", "\n").replace("\r", "\n")
            blob = text_.encode("utf-8")
            if self.compiled is not None:
                blob = self.compiled.live(path, blob)
            tree = be.parse(blob)
            pf = ParsedFile(path, blob, tree, be.matches(tree))
        except Exception:
            pf = None
        self.parsed[path] = pf
        self.parsed_once.add(path)
        while len(self.parsed) > KEEP_PARSED:
            self.parsed.popitem(last=False)
        return pf


def _arguments(call: Any) -> list[Any]:
    """A call's arguments (its comments left out)."""
    return [a for a in call.child_by_field_name("arguments").named_children if a.type != "comment"]


def _callback_given(data: bytes, lib: str, arg: int, fn: str) -> int | None:
    """Where ``data`` constructs ``lib`` with function ``fn`` (``&App::fn`` or ``fn``,
    bound or not) as its argument ``arg``: the offset of the construction, or None."""
    name = lib.encode()
    if name not in data or fn.encode() not in data:
        return None
    for m in re.finditer(rb"\b%s\s*\(" % re.escape(name), data):
        depth, start, args, i = 1, m.end(), [], m.end()
        while i < len(data) and depth:
            c = data[i : i + 1]
            if c in b"([{":
                depth += 1
            elif c in b")]}":
                depth -= 1
            elif c == b"," and depth == 1:
                args.append(data[start:i])
                start = i + 1
            elif c == b";":
                break
            i += 1
        if depth:
            continue
        args.append(data[start : i - 1])
        if arg < len(args) and re.search(rb"(?:::|\b)%s\b" % re.escape(fn.encode()), args[arg]):
            return m.start()
    return None


def library_method(v: AbstractValue) -> AbstractValue | None:
    """What :data:`facts.LIBRARY_METHODS` says of pending method ``v`` called on an object
    of class ``v.receiver`` (``euler.pitch()`` of an ``XsEuler``), or None."""
    known = facts.LIBRARY_METHODS.get((v.receiver or "", v.pending or ""))
    if known is None:
        return None
    called = v.why[0] if v.why else f"{v.pending}()"
    why = f"{called}, a method of {v.receiver}: {known[3]}"
    return AbstractValue(unit=known[0], sense=known[1], range=known[2], why=(why,))


def library_field(pf: Any, cls: str | None, field: str) -> tuple | None:
    """What :data:`facts.LIBRARY_FIELDS` says of field ``field`` of class ``cls`` in file
    ``pf``: by the class's own name, or by its namespace's when the file names that
    namespace (``IMC::``)."""
    if not cls:
        return None
    known = facts.LIBRARY_FIELDS.get((cls, field))
    if known is not None:
        return known
    for (qualified, name), fact in facts.LIBRARY_FIELDS.items():
        ns, sep, short = qualified.rpartition("::")
        if sep and name == field and short == cls and (ns + "::").encode() in pf.data:
            return fact
    return None


def field_write_pattern(names: Iterable[str]) -> re.Pattern[bytes]:
    """A write to any of ``names`` (``\\bname\\s*=(?!=)``), each name written literal first
    (``name(?<=\\bname)``): a pattern that starts with ``\\b`` is tried at every byte."""
    words = sorted(re.escape(n.encode()) for n in names)
    return re.compile(rb"(?:%s)\s*=(?!=)" % b"|".join(w + rb"(?<=\b%s)" % w for w in words))


def c_sources(paths: list[str]) -> list[str]:
    """The C files (``.c``) of the tree that holds ``paths``: a C++ app's device library is
    often C (the Xsens SDK's ``xseuler.c``). Hidden folders are skipped; the files are only
    read when a field's writes are looked for (:meth:`RepositoryResolver._field`)."""
    import os

    dirs = {os.path.dirname(p) for p in paths}
    if not dirs:
        return []
    try:
        root = os.path.commonpath(sorted(dirs))
    except ValueError:
        return []
    out: list[str] = []
    for here, subdirs, files in os.walk(root):
        subdirs[:] = sorted(d for d in subdirs if not d.startswith("."))
        out.extend(os.path.join(here, f) for f in sorted(files) if f.endswith(".c"))
    return out


def link_values(
    apps: list[Any],
    paths: list[str],
    compiled: Compiled | None = None,
    names: dict[str, FileNames] | None = None,
) -> None:
    """Finish the values the apps publish with what only the repository knows.

    Calls to functions defined outside an app's folder are resolved by name across
    ``paths`` (a file is parsed only when it may define one), and a variable that
    another app converts from degrees on arrival (``MOOSDeg2Rad(msg.GetDouble())``)
    is taken to be published in degrees when its producer's value is unknown. The
    arguments of ``sin``, ``cos`` and ``tan`` are finished too; one read by mail of a
    variable the repository's apps publish, not known to be in degrees, is unknown.
    ``compiled``: libclang's facts (:class:`Compiled`), for the files it parsed.
    ``names``: the index of the files already read (see :class:`RepositoryResolver`).
    """
    from moos_lint.files.source import read_bytes

    consumers: dict[str, tuple[str, Any, str]] = {}
    for app in apps:
        for f in app.files:
            for var, span, helper in f.consumed_degrees:
                consumers.setdefault(var, (app.folder, span, helper))
    trig = [t.value for app in apps for f in app.files for t in f.trig_uses]
    angle_args = [t.value for app in apps for f in app.files for t in f.angle_arguments]
    waiting = [
        v.abstract
        for v in [*(pub.value for app in apps for pub in app.publications), *trig, *angle_args]
        if v is not None and v.abstract and v.abstract.pending
    ]
    resolver: RepositoryResolver | None = None
    if waiting:
        resolver = RepositoryResolver(sorted(paths), read_bytes, compiled, names)
        resolver.expect(waiting)
    for app in apps:
        for pub in app.publications:
            v = pub.value.abstract if pub.value is not None else None
            if v is None:
                continue
            if v.pending is not None and resolver is not None:
                v = resolve_pending(v, resolver)
            if v.unit is None and v.const is None and pub.name.text in consumers:
                folder, span, helper = consumers[pub.name.text]
                if folder != app.folder:
                    v = replace(
                        v,
                        unit="deg",
                        why=(
                            f"{place(span.path, span.line)} converts it with {helper}() on arrival",
                        ),
                    )
            pub.value.abstract = v
    # a variable the repository's own apps publish with a value not known to be in
    # degrees carries what they publish, not what the conventions say it holds
    not_degrees = {
        pub.name.text
        for app in apps
        for pub in app.publications
        if pub.name.text
        and (pub.value is None or pub.value.abstract is None or pub.value.abstract.unit != "deg")
    }
    for value in trig:  # the arguments of sin, cos and tan (trig-of-degrees)
        if value.abstract is not None and value.abstract.pending and resolver is not None:
            value.abstract = resolve_pending(value.abstract, resolver)
        if value.abstract is not None and mail_source(value.abstract) in not_degrees:
            value.abstract = UNKNOWN
    # the arguments of the angle functions (angle-argument-unit): a variable read by mail
    # that the repository's own apps publish in a unit not known to be the same is unknown
    published: dict[str, set[str | None]] = {}
    for app in apps:
        for pub in app.publications:
            if pub.name.text:
                a = pub.value.abstract if pub.value is not None else None
                published.setdefault(pub.name.text, set()).add(a.unit if a else None)
    for value in angle_args:
        if value.abstract is not None and value.abstract.pending and resolver is not None:
            value.abstract = resolve_pending(value.abstract, resolver)
        source = mail_source(value.abstract) if value.abstract is not None else None
        if source in published and published[source] != {value.abstract.unit}:
            value.abstract = UNKNOWN
    _siblings(apps)


_MAIL_STEP = re.compile(r"^(\S+) read by mail at ")


def mail_source(v: AbstractValue) -> str | None:
    """The MOOS variable whose mail a value's unit comes from (its first reason), if any."""
    m = _MAIL_STEP.match(v.why[0]) if v.why else None
    return m.group(1) if m else None


def _siblings(apps: list[Any]) -> None:
    """Angles read from the same array as one proved in degrees are degrees too.

    A device reports its Euler angles in one unit: when one of ``data[0]``,
    ``data[1]``, ``data[2]`` is shown to be degrees (a consumer converts it), so are
    the others published from that array.
    """
    from moos_lint.frontends.cpp.angle_exprs import is_heading_var, is_other_angle_var, is_yaw_var

    def angle(name: str) -> bool:
        return is_yaw_var(name) or is_other_angle_var(name)

    proved: dict[str, tuple[str, AbstractValue]] = {}
    pubs = [p for a in apps for p in a.publications if p.value is not None and p.value.abstract]
    for p in pubs:
        v = p.value.abstract
        name = p.name.last
        if v.origin and v.unit == "deg" and not v.hint and (angle(name) or is_heading_var(name)):
            proved.setdefault(v.origin, (name, v))
    for p in pubs:
        v = p.value.abstract
        if v.origin in proved and v.unit is None and v.const is None and angle(p.name.last):
            other, ov = proved[v.origin]
            if other == p.name.last:
                continue
            array = v.origin.rsplit("#", 1)[-1]
            p.value.abstract = replace(
                v,
                unit="deg",
                why=(f"read from the same `{array}[]` as `{other}`", *ov.why[-1:]),
            )
