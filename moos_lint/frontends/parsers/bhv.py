"""The ``.bhv`` reader, as the IvP helm's Populator_BehaviorSet reads files.

- A line ending in ``\\`` is joined to the next one.
- A leading ``{`` or ``}`` and a trailing ``{`` are split off as lines of their own
  (not on lines starting with ``//`` or ``#``).
- ``//`` starts a comment anywhere; ``#`` is *not* a comment.
- A line the state machine does not expect fails the whole behavior set; a line
  that is still an unexpanded nsplug macro (``$(OFFSETS)``, given by the launch
  script) is not judged.
- ``Behavior = KIND`` lines in exclusive ``#ifdef`` branches followed by one
  shared ``{ ... }`` body (valid after nsplug) are alternatives sharing the body.
"""

from __future__ import annotations

import dataclasses
import re
from collections.abc import Iterable

from moos_lint.frontends.nsplug import Expansion, Line
from moos_lint.frontends.parsers.nodes import (
    Behavior,
    BehaviorFile,
    BhvParam,
    Initialize,
    SetBlock,
    conflict_marker,
    has_macro,
)

_BEHAVIOR = re.compile(r"^behavior\s*=\s*(\S*)\s*$", re.IGNORECASE)
_INIT = re.compile(r"^(initialize_?)( +)(.*)$", re.IGNORECASE)
_SET = re.compile(r"^set\s+(\S+?)\s*=\s*(.*)$", re.IGNORECASE)


_BHV_HEADER = re.compile(r"^\s*(?:behavior\s*=|set\s+\S+\s*=|initialize_?\s)", re.IGNORECASE)
_PROCESS_CONFIG = re.compile(r"^\s*processconfig\s*=", re.IGNORECASE)


#: a line shaped like one of a behavior file: a brace, a `Behavior`/`Behaviour` header,
#: `initialize`, `set`, or `key = value`
_SHAPED = re.compile(r"\s*(?:[{}]|behav|initiali|set\s|[\w.]+\s*=)", re.IGNORECASE)


def shaped_like_behaviors(texts: Iterable[str]) -> bool:
    """Whether any of the lines ``texts`` is shaped like a line of a behavior file. A
    `.bhv` file with nothing of the kind is none (nsplug's test inputs, notes on its
    directives): no helm loads it."""
    return any(_SHAPED.match(text) for text in texts)


def is_behavior_fragment(expansion: Expansion) -> bool:
    """A ``.plug`` fragment written for a behavior file: ``Behavior =``, ``set MODE =``
    or ``initialize`` lines, no ``ProcessConfig``. MOOS-IvP missions include such plugs
    from their behavior templates (``#include plugs/bhv_hsline.plug``)."""
    found = False
    for line in expansion.lines:
        if _PROCESS_CONFIG.match(line.text):
            return False
        found = found or bool(_BHV_HEADER.match(line.text))
    return found


def _pieces(line: Line) -> list[tuple[Line, str, int]]:
    """Brace splitting: yields (line, text piece, offset of the piece in line.text)."""
    text = line.text
    stripped = text.strip()
    offset = len(text) - len(text.lstrip())
    if stripped.startswith(("//", "#")) or len(stripped) <= 1:
        return [(line, stripped, offset)]
    out: list[tuple[Line, str, int]] = []
    if stripped[0] in "{}":
        out.append((line, stripped[0], offset))
        rest = stripped[1:]
        offset += 1 + (len(rest) - len(rest.lstrip()))
        stripped = rest.strip()
    tail = None
    if len(stripped) > 1 and stripped.endswith("{"):
        tail = (line, "{", offset + len(stripped) - 1)
        stripped = stripped[:-1].rstrip()
    if stripped:
        out.append((line, stripped, offset))
    if tail:
        out.append(tail)
    return out


def _joined(lines: list[Line]) -> list[Line]:
    """Join lines ending in a backslash with the next one (fileBufferSlash).

    The expansion's lines are shared (every reader of the file, the language
    server's later runs): a joined line is a new one, never an edited one.
    """
    out: list[Line] = []
    carry: Line | None = None
    for line in lines:
        if carry is not None:
            carry = Line(
                carry.text[:-1] + line.text.strip(),
                carry.raw,
                carry.path,
                carry.lineno,
                carry.chain,
                carry.branches,
                carry.facts,
            )
        else:
            carry = line
        trimmed = carry.text.rstrip()
        if trimmed.endswith("\\"):
            if trimmed != carry.text:
                carry = dataclasses.replace(carry, text=trimmed)
            continue
        out.append(carry)
        carry = None
    if carry is not None:
        out.append(carry)
    return out


def parse_bhv(expansion: Expansion) -> BehaviorFile:
    bf = BehaviorFile(path=expansion.path, expansion=expansion, lines=expansion.lines)
    state = "top"  # top | bhv-wait | bhv | set-wait | set | set-else | skip
    behavior: Behavior | None = None
    setblock: SetBlock | None = None
    alternatives: list[Behavior] = []  # the behavior and its exclusive alternatives
    skip_depth = 0
    for line in _joined(expansion.lines):
        for src, piece, offset in _pieces(line):
            cut = piece.find("//")
            text = (piece if cut < 0 else piece[:cut]).strip()
            if state == "set-else":
                # An optional else-value ends at the first blank or comment line.
                if not text:
                    state = "top"
                    continue
                if setblock is not None and not _is_keyword(text):
                    setblock.else_value = text
                    state = "top"
                    continue
                state = "top"
            if not text:
                continue
            if state == "skip":
                if text == "{":
                    skip_depth += 1
                elif text == "}":
                    skip_depth -= 1
                    if skip_depth == 0:
                        state = "top"
                continue
            if state == "bhv-wait":
                if text == "{":
                    state = "bhv"
                    continue
                m = _BEHAVIOR.match(text)
                if (
                    m
                    and m.group(1)
                    and behavior is not None
                    and all(src.excludes(b.header) for b in alternatives)
                ):
                    # `Behavior =` chosen in exclusive #ifdef branches, the body shared
                    alt = Behavior(m.group(1), src, src.text.find(m.group(1), offset))
                    alt.params = behavior.params
                    bf.behaviors.append(alt)
                    alternatives.append(alt)
                    continue
                bf.invalid.append((src, "expected `{` to open the Behavior block"))
                state = "top"
            if state == "bhv":
                assert behavior is not None
                if text == "}":
                    for b in alternatives:
                        b.closed = True
                    state = "top"
                    continue
                if text == "{" or _BEHAVIOR.match(text):
                    bf.unclosed.append(behavior.header)
                    state = "top"
                    if text == "{":
                        continue
                else:
                    param = _bhv_param(src, text, offset)
                    if param is None and has_macro(text):
                        continue  # the macro's value (given at launch) supplies the line
                    if param is None:
                        why = "a Behavior block line needs the form `parameter = value`"
                        bf.invalid.append((src, _CONFLICT if conflict_marker(text) else why))
                    else:
                        behavior.params.append(param)
                    continue
            if state == "set-wait":
                if text == "{":
                    state = "set"
                    continue
                bf.invalid.append((src, "expected `{` to open the set block"))
                state = "top"
            if state == "set":
                assert setblock is not None
                if text == "}":
                    state = "set-else"
                    continue
                if text.startswith("}"):
                    setblock.else_value = text[1:].strip() or None
                    state = "top"
                    continue
                setblock.conditions.append((text, src))
                continue
            # top level
            m = _BEHAVIOR.match(text)
            if m and m.group(1):
                behavior = Behavior(m.group(1), src, src.text.find(m.group(1), offset))
                bf.behaviors.append(behavior)
                alternatives = [behavior]
                state = "bhv-wait"
                continue
            if m:
                bf.invalid.append((src, "`Behavior =` needs a behavior type"))
                continue
            m = _INIT.match(text)
            if m:
                _initialize(bf, src, m, offset)
                continue
            if text.lower().startswith("initialize"):
                bf.invalid.append(
                    (src, "`initialize` must be followed by a space (a tab fails the file)")
                )
                continue
            m = _SET.match(text)
            if m:
                setblock = SetBlock(m.group(1), m.group(2).strip(), src)
                bf.sets.append(setblock)
                state = "set-wait"
                continue
            if text == "{":
                state, skip_depth = "skip", 1
                continue
            if text.startswith("#"):
                bf.invalid.append(
                    (src, "`#` is not a comment in a behavior file: the helm rejects this line")
                )
                continue
            if has_macro(text):
                continue  # a line an nsplug macro supplies at launch: not known here
            if conflict_marker(text):
                bf.invalid.append((src, _CONFLICT))
                continue
            bf.invalid.append((src, "the helm does not understand this line"))
    if state in ("bhv", "bhv-wait") and behavior is not None:
        bf.unclosed.append(behavior.header)
    return bf


_CONFLICT = "a merge-conflict marker: the file was committed mid-merge"


def _is_keyword(text: str) -> bool:
    low = text.lower()
    return low.startswith(("behavior", "initialize", "set ", "{", "}"))


def _bhv_param(line: Line, text: str, offset: int) -> BhvParam | None:
    eq = text.find("=")
    if eq <= 0:
        return None
    key = text[:eq].strip()
    value = text[eq + 1 :].strip()
    if not key:
        return None
    base = line.text.find(text, offset)
    base = offset if base < 0 else base
    key_start = base
    vrel = text.find(value, eq + 1) if value else eq + 1
    return BhvParam(key, value, line, key_start, base + vrel, base + vrel + len(value))


def split_commas(text: str) -> list[tuple[str, int]]:
    """Split on commas outside double quotes and braces, as MOOS-IvP's ``parseStringQ``
    (lib_mbutil/MBUtils.cpp) does: ``RESCUE_REGION = pts={-262,-182:-82,-537}`` is one
    pair; returns (piece, offset)."""
    out, start, quoted, braces = [], 0, False, 0
    for i, ch in enumerate(text):
        if ch == '"':
            quoted = not quoted
        elif ch == "{":  # (counted inside quotes too, as parseStringQ does)
            braces += 1
        elif ch == "}":
            braces = max(0, braces - 1)
        elif ch == "," and not quoted and not braces:
            out.append((text[start:i], start))
            start = i + 1
    out.append((text[start:], start))
    return out


def _initialize(bf: BehaviorFile, line: Line, m: re.Match, offset: int) -> None:
    deferred = m.group(1).endswith("_")
    body = m.group(3)
    base = line.text.find(body, offset) if body else -1
    base = offset if base < 0 else base
    for piece, rel in split_commas(body):
        var, eq, value = piece.partition("=")
        if not eq or not var.strip() or not value.strip() or any(c.isspace() for c in var.strip()):
            bf.invalid.append((line, f"`initialize` needs `VAR=VALUE` pairs: `{piece.strip()}`"))
            continue
        vs = base + rel + (len(var) - len(var.lstrip()))
        bf.initializes.append(Initialize(var.strip(), value.strip(), line, deferred, vs))
