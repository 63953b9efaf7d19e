"""Helpers for the rules that judge a condition's word against what a mission posts."""

from __future__ import annotations

import re

from moos_lint.semantics.mbutil import is_number
from moos_lint.semantics.variables import PUBLISH

#: a relation after the variable's name in a condition, and the word it compares with
_RELATION = re.compile(r'\s*(==|!=|=)\s*("[^"]*"|[^\s()"]+)')
#: what ends a posted value: a button's next pair, a flag's condition, a block's brace
_VALUE_END = re.compile(r"#|\[if\]|\{|//")
_EVENT_VAL = re.compile(r"\bval\s*=\s*([^,]*)", re.IGNORECASE)
#: publishers whose value is written in the mission (the others may post anything)
_WRITTEN = ("config", "behavior")


def all_written(publishers) -> bool:
    """Whether every publisher is a line of the mission whose value is written out (not
    an app, a poke or another community, which may post anything)."""
    return all(p.how in _WRITTEN and p.line is not None for p in publishers)


def compared(ref) -> tuple[str, str, int] | None:
    """(relation, word, start of the word in the line) of a condition's ``VAR op word``,
    when the word is text (not a number, a variable's macro or a run-time placeholder)."""
    end = ref.start + len(ref.name)
    m = _RELATION.match(ref.line.text, end)
    if m is None:
        return None
    word, start = m.group(2), m.start(2)
    if word.startswith('"'):
        word, start = word[1:-1], start + 1
    if not word or "$" in word or is_number(word):  # lib_logic's test (ParseNode.cpp)
        return None
    return m.group(1), word, start


def compared_once(ref, seen: set[tuple[str, int, int]]) -> tuple[str, str, int] | None:
    """:func:`compared`, once per place: a behavior file that several missions load (or a
    line reached twice) is judged once within a check; ``seen`` holds the places so far."""
    found = compared(ref)
    if found is None:
        return None
    key = (ref.line.path, ref.line.lineno, found[2])
    if key in seen:
        return None
    seen.add(key)
    return found


def posted_values(model, with_sets: bool = True) -> dict[str, list[str | None]]:
    """Variable -> the values the mission's own lines post to it (None: a value that is
    not written out). Without ``with_sets``, the helm's set blocks are left out."""
    out: dict[str, list[str | None]] = {}
    for ref in model.refs:
        if ref.role == PUBLISH and (with_sets or ref.param != "set"):
            out.setdefault(ref.name, []).append(value_after(ref))
    if with_sets:
        for _path, bf in model.behavior_files:
            for sb in bf.sets:
                if sb.else_value is not None:
                    out.setdefault(sb.mode_var, []).append(clean(sb.else_value))
    return out


def value_after(ref) -> str | None:
    """The value a ``VAR = value`` (or a uTimerScript ``var=VAR, val=value``) posts."""
    text = ref.line.text
    m = re.match(r"\s*=\s*", text[ref.start + len(ref.name) :])
    if m is not None:
        rest = text[ref.start + len(ref.name) + m.end() :]
        if rest.startswith('"') and '"' in rest[1:]:  # quoted: a `#` inside is the value's
            return clean(rest[: rest.index('"', 1) + 1])
        cut = _VALUE_END.search(rest)
        return clean(rest[: cut.start()] if cut else rest)
    if ref.param == "event":
        v = _EVENT_VAL.search(text)
        return clean(v.group(1)) if v else None
    return None


def clean(value: str) -> str | None:
    value = value.strip()
    if len(value) >= 2 and value[0] == value[-1] == '"':
        value = value[1:-1]
    return None if not value or "$" in value else value
