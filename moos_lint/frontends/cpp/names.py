"""Small readers of C++ syntax shared by the extractor and the value analysis.

The words of a MOOS variable name, which names the value analysis computes a
value for, and the mail key a branch of a mail handler tests.
"""

from __future__ import annotations

import re
from typing import Any

_VALUED_WORDS = {
    "YAW",
    "HEADING",
    "HDG",
    "PITCH",
    "ROLL",
    "Z",
    "DEPTH",
    "LAT",
    "LON",
    "LONG",
    "LATITUDE",
    "LONGITUDE",
    "RATE",
    "SPEED",
    "SOG",
    "STW",
}
_RATE_WORDS = {"GYRO", "GYR", "RATE"}
#: the bytes of a C++ word (``\w`` on bytes), for scans that walk a word byte by byte
WORD_BYTES = frozenset(b"abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789_")
#: string comparisons a mail handler tests a message's key with
MAIL_COMPARES = {"MOOSStrCmp", "MOOSStrCmpi", "strcmp", "strcasecmp", "IsName"}
#: ``m_Comms.PeekMail(NewMail, "KEY", Msg)``: the mail of one key taken from the list
#: (core MOOS, Comms/MOOSCommClient.h), in old apps the test of a message's key
PEEK_MAIL = {"PeekMail", "PeekAndCheckMail"}
#: the calls that test which variable a message is
_KEY_TESTS = frozenset(MAIL_COMPARES | PEEK_MAIL)


def words(name: str) -> list[str]:
    return [w for w in re.split(r"[^A-Za-z0-9]+", name) if w]


def last_word(name: str) -> str:
    w = words(name)
    return w[-1].upper() if w else ""


#: the axes of an Euler triple by their short names (``IMU_EULER_P``, ``EULER_PSI``)
_EULER_AXES = {
    "R": "ROLL",
    "P": "PITCH",
    "Y": "YAW",
    "H": "HEADING",
    "PHI": "ROLL",
    "THETA": "PITCH",
    "PSI": "YAW",
}


#: words after a quantity that say how it was got, not what it is (``HEADING_ESTIMATE``,
#: ``NAV_YAW_FILTERED``, ``PITCH_AVG``)
_QUALIFIERS = frozenset(
    {
        "EST",
        "ESTIMATE",
        "ESTIMATED",
        "FILT",
        "FILTERED",
        "UNFILTERED",
        "SMOOTHED",
        "AVG",
        "AVERAGE",
        "MEAN",
        "MEAS",
        "MEASURED",
        "GT",
    }
)


def axis_word(name: str) -> str:
    """The last word of ``name`` (before words that only qualify it: ``HEADING`` for
    ``HEADING_ESTIMATE``), an Euler axis spelled out: ``PITCH`` for ``IMU_EULER_P``."""
    w = [x.upper() for x in words(name)]
    while len(w) >= 2 and w[-1] in _QUALIFIERS:
        w.pop()
    if len(w) >= 2 and w[-2] == "EULER" and w[-1] in _EULER_AXES:
        return _EULER_AXES[w[-1]]
    return w[-1] if w else ""


def valued_name(name: str) -> bool:
    """Whether the analysis computes the value published under ``name`` (by its last word)."""
    return axis_word(name) in _VALUED_WORDS or any(x.upper() in _RATE_WORDS for x in words(name))


def node_text(n: Any) -> str:
    return n.text.decode("utf-8", "replace") if n is not None else ""


def strip(n: Any) -> Any:
    while n is not None and n.type == "parenthesized_expression" and n.named_child_count == 1:
        n = n.named_children[0]
    return n


def function_declarator(fn: Any) -> Any:
    """The ``function_declarator`` of a function definition (or declaration): below the
    pointers and references of its return type (``const T& get() const``, whose reference
    declarator names its declarator by no field); None when there is none."""
    decl = fn.child_by_field_name("declarator")
    while decl is not None and decl.type != "function_declarator":
        inner = decl.child_by_field_name("declarator")
        if inner is None and decl.type == "reference_declarator" and decl.named_children:
            inner = decl.named_children[-1]
        decl = inner
    return decl


def callee_name(fn: Any) -> str:
    """The called function's own name: ``Notify`` for ``m_Comms.Notify`` or ``A::Notify``."""
    t = fn.type
    if t == "identifier":
        return node_text(fn)
    if t == "field_expression":
        return node_text(fn.child_by_field_name("field"))
    if t in ("qualified_identifier", "template_function"):
        name = fn.child_by_field_name("name")
        return callee_name(name) if name is not None else ""
    return ""


def mail_key_of(n: Any) -> str | None:
    """The MOOS variable a ``msg.GetDouble()`` reads: the literal its branch compares the key to."""
    p, child = n.parent, n
    while p is not None and p.type != "function_definition":
        if p.type == "if_statement" and child == p.child_by_field_name("consequence"):
            lit = key_literal(p.child_by_field_name("condition"))
            if lit is not None:
                return lit
        p, child = p.parent, p
    return None


def key_literal(cond: Any) -> str | None:
    """The string literal a condition compares with (``key == "X"``, ``MOOSStrCmp(k, "X")``),
    or the key whose mail it takes (``PeekMail(NewMail, "X", msg)``)."""
    if cond is None:
        return None
    stack = [cond]
    while stack:
        x = stack.pop()
        if x.type == "binary_expression" and node_text(x.child_by_field_name("operator")) == "==":
            for side in ("left", "right"):
                s = strip(x.child_by_field_name(side))
                if s is not None and s.type == "string_literal":
                    return _literal(s)
        if (
            x.type == "call_expression"
            and callee_name(x.child_by_field_name("function")) in _KEY_TESTS
        ):
            for a in x.child_by_field_name("arguments").named_children:
                if a.type == "string_literal":
                    return _literal(a)
        if x.type in ("binary_expression", "parenthesized_expression", "condition_clause"):
            stack.extend(x.named_children)
    return None


def _literal(s: Any) -> str | None:
    parts = [node_text(c) for c in s.named_children if c.type == "string_content"]
    return "".join(parts) if parts else None


#: the words of a variable's name that say which coordinate of the local grid, or of
#: latitude/longitude, it holds
_AXIS_WORDS = {
    "lat": "lat",
    "latitude": "lat",
    "lon": "lon",
    "long": "lon",
    "lng": "lon",
    "longitude": "lon",
    "x": "east",
    "e": "east",
    "east": "east",
    "easting": "east",
    "eastings": "east",
    "y": "north",
    "n": "north",
    "north": "north",
    "northing": "north",
    "northings": "north",
}
#: a coordinate glued to a short word: ``lx``, ``dfy``, ``xpos``, ``ypos``
_GLUED_AXIS = re.compile(
    r"^(?:l|d|df|dbl|p|pos|cur|nav|loc|local|utm|grid|new|tmp)?([xy])"
    r"(?:pos|loc|local|utm|grid|coord)?$"
)
_NAME_WORDS = re.compile(r"[A-Z]?[a-z]+|[A-Z]+(?![a-z])|\d+")


def axis_of(expression: str) -> str | None:
    """What a variable named like ``expression``'s last name holds: ``lat``, ``lon``,
    ``north`` or ``east``; None when its name does not say, or says two things
    (``latlon_vec``, ``n_x``)."""
    names = re.findall(r"[A-Za-z_]\w*", re.sub(r"\[[^\]]*\]|\([^()]*\)", "", expression))
    if not names:
        return None
    said = set()
    for word in _NAME_WORDS.findall(names[-1]):
        word = word.lower()
        glued = _GLUED_AXIS.match(word)
        axis = _AXIS_WORDS.get(glued.group(1) if glued else word)
        if axis:
            said.add(axis)
    return said.pop() if len(said) == 1 else None


#: words that make a coordinate a displacement between two points: ``dx``, ``delta_y``,
#: ``dist_x``, ``dis_y``
_DELTA_WORDS = {"d", "delta", "diff", "dist", "dis", "distance", "offset", "rel", "relative"}


def displacement_axis(expression: str) -> str | None:
    """The local-grid axis (``east`` or ``north``) of a displacement written as a
    difference of two coordinates named alike (``m_nav_y - m_start_y``) or as a name that
    says so (``dx``, ``delta_y``); None for anything else (a magnetometer's ``mag_y``, a
    body-frame ``x``, whose frame a name does not tell)."""
    expr = expression.strip()
    while expr.startswith("(") and expr.endswith(")") and _balanced(expr[1:-1]):
        expr = expr[1:-1].strip()
    parts = _top_level_minus(expr)
    if len(parts) == 2:
        axes = {axis_of(p) for p in parts}
        axis = axes.pop() if len(axes) == 1 else None
        return axis if axis in ("east", "north") else None
    if not re.fullmatch(r"[A-Za-z_][\w.>-]*", expr):
        return None
    name = re.findall(r"[A-Za-z_]\w*", expr)[-1]
    said = [w.lower() for w in _NAME_WORDS.findall(name)]
    glued = [_GLUED_AXIS.match(w) for w in said]
    delta = any(w in _DELTA_WORDS for w in said) or any(
        g is not None and g.group(0).startswith("d") and len(g.group(0)) == 2 for g in glued
    )
    axis = axis_of(expr)
    return axis if delta and axis in ("east", "north") else None


def _balanced(text: str) -> bool:
    depth = 0
    for ch in text:
        depth += (ch == "(") - (ch == ")")
        if depth < 0:
            return False
    return depth == 0


def _top_level_minus(expr: str) -> list[str]:
    """``a - b`` split at its one top-level binary minus (else the whole)."""
    depth, cuts = 0, []
    for i, ch in enumerate(expr):
        depth += (ch in "([") - (ch in ")]")
        if (
            ch == "-"
            and depth == 0
            and i > 0
            and expr[i - 1] not in "-+*/(<=e"
            and (i + 1 >= len(expr) or expr[i + 1] != ">")
        ):
            cuts.append(i)
        elif ch in "+*/" and depth == 0:
            return [expr]
    if len(cuts) != 1:
        return [expr]
    return [expr[: cuts[0]].strip(), expr[cuts[0] + 1 :].strip()]
