"""Angle fields and their literal values, as the frames-and-units rules see them.

The MOOS convention (2007): angles are radians wrapped to ±π; the only
exception is *heading*, which is in degrees. MOOS-IvP keeps NAV_YAW, NAV_PITCH
and the NODE_REPORT ``YAW`` in radians, while every helm and behavior heading is
in degrees. This module finds the places where a mission or behavior file gives
a literal value to an angle field:

- a ``.moos`` parameter whose key names an angle (``START_YAW = 0.5``);
- a uTimerScript event ``event = var=NAV_YAW, val=1.2, time=10``;
- a flag ``endflag = NAV_YAW = 1.2`` (any parameter whose key ends in ``flag``,
  in a behavior or a ``.moos`` block);
- a pMarineViewer button or action ``button_one = LABEL # NAV_YAW=1.2``;
- a behavior-file ``initialize NAV_YAW=1.2``;
- a behavior parameter whose key names an angle.

A name is an angle field when its *last* word (words split on ``_`` and other
non-alphanumerics) is ``YAW``, ``PITCH``, ``ROLL`` or ``RADIANS``. So
``NAV_YAW`` and ``START_YAW`` are, while ``YAW_PID_KP`` (a gain),
``YAW_RATE`` and ``NAV_HEADING`` are not, and neither is a ``_RAD`` suffix:
in MOOS-IvP that is a radius (``turn1_rad = 20`` in a behavior is metres).
Values with a macro (``$(X)``, ``$[X]``), quoted strings and anything that is
not one plain number are not literals and are left alone. So is a parameter
whose line comment says it is in degrees (``pose_yaw = -90  // degrees``): an
app's configuration key is read in the unit the app documents.
"""

from __future__ import annotations

import functools
import math
import re
from collections.abc import Iterator
from dataclasses import dataclass

from moos_lint.files.diagnostics import Edit, Fix, Span
from moos_lint.frontends.nsplug import Line, derived
from moos_lint.frontends.parsers.bhv import split_commas

#: the last word of a field name -> the kind of angle it holds
ANGLE_WORDS = {
    "yaw": "yaw",
    "pitch": "pitch",
    "roll": "roll",
    "radians": "radian",
}

#: Configuration keys that MOOS-IvP documents in degrees although their name
#: says pitch (pMarinePID's maximum pitch, turned into radians inside the app).
DEGREE_CONFIG_KEYS = frozenset({"maxpitch", "max_pitch"})

#: pMarineViewer parameters that post ``VAR=VALUE`` pairs separated by ``#``.
_VIEWER_POSTS = re.compile(r"^(button_[a-z]+|action\+?|(left|right)_context\[[^\]]*\])$")

_NUMBER = re.compile(r"^[+-]?(\d+\.?\d*|\.\d+)([eE][+-]?\d+)?$")
_WORD_SPLIT = re.compile(r"[^A-Za-z0-9]+")

#: Values this close to ±π still count as wrapped (a rounded π, 3.1416, is fine).
WRAP_TOLERANCE = 1e-3


@functools.lru_cache(maxsize=4096)  # (a handful of names, asked for thousands of times)
def angle_kind(name: str) -> str | None:
    """``"yaw"``, ``"pitch"``, ``"roll"`` or ``"radian"`` when ``name`` is an angle field."""
    words = [w for w in _WORD_SPLIT.split(name.strip()) if w]
    if not words:
        return None
    return ANGLE_WORDS.get(words[-1].lower())


def literal_number(text: str) -> float | None:
    """The value of a plain numeric literal, or None (macros, strings, lists...)."""
    text = text.strip()
    if not _NUMBER.match(text):
        return None
    try:
        value = float(text)
    except ValueError:  # pragma: no cover - the pattern only admits floats
        return None
    return value if math.isfinite(value) else None


def wrap_pi(rad: float) -> float:
    """``rad`` wrapped to (-π, π]."""
    out = math.remainder(rad, 2 * math.pi)
    if out <= -math.pi:
        out += 2 * math.pi
    return out


def format_rad(rad: float) -> str:
    """A radian value rounded to 4 decimals, without trailing zeros."""
    text = f"{rad:.4f}".rstrip("0").rstrip(".")
    return "0" if text in ("-0", "") else text


def degrees_to_radians(literal: str, value: float) -> tuple[str, str]:
    """The radian text for a value read as degrees, and how it was worked out."""
    raw = math.radians(value)
    wrapped = wrap_pi(raw)
    new = format_rad(wrapped)
    how = f"{literal}·π/180 = {format_rad(raw)} rad"
    if abs(wrapped - raw) > 1e-9:
        how += f", {new} rad wrapped to ±π"
    return new, how


@dataclass(frozen=True, slots=True)
class AngleValue:
    """A literal value given to an angle field."""

    name: str  # the field: a MOOS variable or a configuration key
    kind: str  # yaw | pitch | roll | radian
    literal: str  # the number as written
    value: float
    line: Line
    start: int  # index of the literal in line.text
    where: str  # how it is given: "parameter", "uTimerScript event", "flag", "initialize", ...
    config_key: bool  # the name is an app's configuration key, not a MOOS variable

    @property
    def span(self) -> Span:
        return self.line.span(self.start, self.start + len(self.literal))

    def fix(self, new_text: str, message: str) -> Fix | None:
        """Replace the literal, when it sits in the file exactly as written."""
        span = self.span
        if span.line != span.end_line:
            return None
        if self.line.text == self.line.raw:
            written = self.line.raw[span.col - 1 : span.end_col - 1]
        else:  # a macro or a joined line: only when the literal maps back unambiguously
            if self.line.raw.count(self.literal) != 1:
                return None
            written = self.line.raw[span.col - 1 : span.end_col - 1]
        if written != self.literal:
            return None
        return Fix(message, (Edit(span, new_text),))


def _make(name, value_text, line, start, where, config_key) -> AngleValue | None:
    kind = angle_kind(name)
    if kind is None:
        return None
    if config_key and "".join(name.split()).lower() in DEGREE_CONFIG_KEYS:
        return None
    literal = value_text.strip()
    number = literal_number(literal)
    if number is None:
        return None
    lead = len(value_text) - len(value_text.lstrip())
    return AngleValue(name.strip(), kind, literal, number, line, start + lead, where, config_key)


def _assignment(text: str, base: int, line: Line, where: str) -> AngleValue | None:
    """``VAR = VALUE`` (a flag or a posting), ``base`` = index of ``text`` in line.text."""
    var, eq, val = text.partition("=")
    if not eq:
        return None
    return _make(var, val, line, base + len(var) + 1, where, config_key=False)


def _timer_event(text: str, base: int, line: Line) -> AngleValue | None:
    """uTimerScript ``var=NAME, val=VALUE, time=T``."""
    var = None
    val: tuple[str, int] | None = None
    for piece, off in split_commas(text):
        key, eq, value = piece.partition("=")
        if not eq:
            continue
        k = key.strip().lower()
        if k == "var":
            var = value.strip()
        elif k == "val":
            val = (value, base + off + len(key) + 1)
    if not var or val is None:
        return None
    return _make(var, val[0], line, val[1], "uTimerScript event", config_key=False)


def _viewer_posts(key: str, text: str, base: int, line: Line) -> Iterator[AngleValue]:
    """pMarineViewer ``LABEL # VAR=VAL # VAR=VAL`` (buttons) or ``VAR=VAL # ...``."""
    offset = 0
    pieces = text.split("#")
    for i, piece in enumerate(pieces):
        here = offset
        offset += len(piece) + 1
        if i == 0 and key.startswith("button_"):
            continue  # the button's label
        found = _assignment(piece, base + here, line, "pMarineViewer posting")
        if found is not None:
            yield found


#: a line comment's word that gives the value's unit as degrees (``// Angles in degrees``)
_DEGREES_NOTE = re.compile(r"\bdeg(?:rees?|s)?\b|°", re.IGNORECASE)


def _param_values(key: str, value: str, base: int, line: Line) -> Iterator[AngleValue]:
    found = _make(key, value, line, base, "parameter", config_key=True)
    if found is not None:
        # an app's own key whose line says it is in degrees (a library's mounting pose,
        # `pose_yaw = -90 // degrees`): the app reads it in the unit it documents
        comment = line.text.find("//")
        if comment < 0 or not _DEGREES_NOTE.search(line.text, comment):
            yield found
        return
    if "=" not in value:  # no posting, flag or event in it
        return
    lkey = "".join(key.split()).lower()
    if lkey == "event":
        found = _timer_event(value, base, line)
        if found is not None:
            yield found
    elif lkey.endswith("flag"):
        found = _assignment(value, base, line, "flag")
        if found is not None:
            yield found
    elif _VIEWER_POSTS.match(lkey):
        yield from _viewer_posts(lkey, value, base, line)


def angle_values(ctx) -> Iterator[AngleValue]:
    """Every literal angle value in the unit (``.moos`` or ``.bhv``); found once per unit."""
    return iter(derived(ctx.expansion, "angle_values", lambda: tuple(_angle_values(ctx))))


def _angle_values(ctx) -> Iterator[AngleValue]:
    if ctx.moos is not None:
        for p in ctx.moos.all_params:
            yield from _param_values(p.key, p.value, p.value_start, p.line)
    if ctx.bhv is not None:
        for init in ctx.bhv.initializes:
            text = init.line.text
            vstart = text.find(init.value, init.var_start + len(init.var))
            if vstart >= 0:
                found = _make(init.var, init.value, init.line, vstart, "initialize", False)
                if found is not None:
                    yield found
        for behavior in ctx.bhv.behaviors:
            for bp in behavior.params:
                yield from _param_values(bp.key, bp.value, bp.value_start, bp.line)
