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
}
_RATE_WORDS = {"GYRO", "GYR", "RATE"}
#: the bytes of a C++ word (``\w`` on bytes), for scans that walk a word byte by byte
WORD_BYTES = frozenset(b"abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789_")
#: string comparisons a mail handler tests a message's key with
MAIL_COMPARES = {"MOOSStrCmp", "MOOSStrCmpi", "strcmp", "strcasecmp", "IsName"}


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


def axis_word(name: str) -> str:
    """The last word of ``name``, an Euler axis spelled out: ``PITCH`` for ``IMU_EULER_P``."""
    w = [x.upper() for x in words(name)]
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
    """The string literal a condition compares with (``key == "X"``, ``MOOSStrCmp(k, "X")``)."""
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
            and callee_name(x.child_by_field_name("function")) in MAIL_COMPARES
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
