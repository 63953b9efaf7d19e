"""The ``.moos`` reader, as CMOOSFileReader, CProcessConfigReader and pAntler read files.

- ``//`` starts a comment and nothing else does (``#Run = pX`` is a live line
  with the key ``#Run``); only the first pair of double quotes protects a ``//``.
- Keys and ProcessConfig names compare without regard to case or spaces.
- ``ProcessConfig = NAME`` must be followed by a line that starts with ``{``;
  the first line that starts with ``}`` ends the block.
- A block that goby's MOOS apps read with protobuf's text format (the
  catalogue's text-format apps, or a block whose lines are mostly
  ``key: value`` / ``name {``) runs to the last ``}`` before the next
  ``ProcessConfig`` line and is read by :mod:`moos_lint.frontends.parsers.protobuf_text`.
"""

from __future__ import annotations

import re
from dataclasses import replace

from moos_lint.frontends.nsplug import Expansion, Line
from moos_lint.frontends.parsers.nodes import (
    Block,
    MoosFile,
    Param,
    antler_runs,
    has_macro,
    parse_run,
)
from moos_lint.frontends.parsers.protobuf_text import looks_like_text_format, read_block

#: a line that is one nsplug macro and nothing else (``$(RUN)``): the launch script gives it
_MACRO_ALONE = re.compile(r"[$%]\([A-Za-z0-9_]+\)")


def strip_comment(text: str) -> str:
    """Cut a trailing ``//`` comment; the first ``"..."`` pair protects its content."""
    cut = text.find("//")
    if cut < 0:
        return text
    q1 = text.find('"')
    if q1 != -1 and q1 < cut:
        q2 = text.find('"', q1 + 1)
        if q2 != -1 and q2 > cut:
            nxt = text.find("//", q2 + 1)
            return text if nxt < 0 else text[:nxt]
    return text[:cut]


def is_comment(text: str) -> bool:
    return text.lstrip().startswith("//")


def looks_commented(text: str) -> bool:
    """A line a reader takes for a comment and MOOS does not: it starts with ``#`` or a
    single ``/`` (only ``//`` starts a comment; nsplug directives are gone by now)."""
    text = text.lstrip()
    return text.startswith("#") or (text.startswith("/") and not text.startswith("//"))


def block_comments(lines: list[Line]) -> list[tuple[int, int, int]]:
    """The C block comments of a file, which MOOS does not know: for each ``/*`` line (with
    no ``*/`` after it) that a later ``*/`` line closes, (the opening line's index, the
    closing line's index, the block depth at the opening line: 0 at the top of the file)."""
    out: list[tuple[int, int, int]] = []
    if not any("/*" in line.text for line in lines):
        return out
    start: int | None = None
    depth = opened_at = 0
    for i, line in enumerate(lines):
        text = strip_comment(line.text).strip()
        if start is None:
            if text.startswith("/*") and "*/" not in text[2:]:
                start, opened_at = i, depth
        elif "*/" in text:
            out.append((start, i, opened_at))
            start = None
            continue
        if text == "{":
            depth += 1
        elif text == "}":
            depth = max(0, depth - 1)
    return out


def split_param(line: Line) -> Param | None:
    """``key = value`` on one line, or None when the line has no ``=``."""
    text = strip_comment(line.text)
    eq = text.find("=")
    if eq < 0:
        return None
    key_part = text[:eq]
    key = key_part.strip()
    key_start = len(key_part) - len(key_part.lstrip())
    rest = text[eq + 1 :]
    value = rest.strip()
    value_start = eq + 1 + (len(rest) - len(rest.lstrip()))
    return Param(key, value, line, key_start, value_start, value_start + len(value))


def _header_name(param: Param) -> tuple[str, bool] | None:
    """The block name when ``param`` is a ``ProcessConfig = NAME`` header."""
    if param.lkey != "processconfig":
        return None
    value = param.value
    brace = "{" in value
    if brace:
        value = value.split("{", 1)[0]
    return "".join(value.split()), brace


def _text_format_end(lines: list[Line], start: int, name: str) -> int | None:
    """The index of the line closing a protobuf-text block opened at ``lines[start]``.

    goby's apps read up to the next line naming ``ProcessConfig`` and cut at the
    last ``}`` before it. None when the block does not read as protobuf text.
    """
    from moos_lint.frontends.text_format_apps import text_format_app

    stop = len(lines)
    for i in range(start + 1, len(lines)):
        if "processconfig" in lines[i].text.lower():
            stop = i
            break
    close = None
    for i in range(stop - 1, start, -1):
        if "}" in strip_comment(lines[i].text).split("#", 1)[0]:
            close = i
            break
    if close is None:
        return None
    body = lines[start + 1 : close]
    known = text_format_app(name) is not None
    return close if looks_like_text_format(body, known) else None


def _read_text_block(block: Block, lines: list[Line], start: int, close: int) -> None:
    block.text_format = True
    block.open = lines[start]
    block.close = lines[close]
    body = list(lines[start + 1 : close])
    last = lines[close]
    cut = last.text.rfind("}")
    if last.text[:cut].strip():  # fields before the final "}" on its line
        body.append(replace(last, text=last.text[:cut], raw=last.raw))
    block.text_fields, block.text_errors = read_block(body)


def parse_moos(expansion: Expansion) -> MoosFile:
    """Build the model of one preprocessed ``.moos`` file."""
    mf = MoosFile(path=expansion.path, expansion=expansion, lines=expansion.lines)
    current: Block | None = None  # the open block
    pending: Block | None = None  # a header waiting for its "{"
    lines = expansion.lines
    skip_to = -1
    for index, line in enumerate(lines):
        if index <= skip_to:
            continue
        stripped = line.text.strip()
        if not stripped or stripped.startswith("//"):
            continue
        if pending is not None:
            if stripped.startswith("{"):
                close = _text_format_end(lines, index, pending.name)
                if close is not None:
                    _read_text_block(pending, lines, index, close)
                    pending, skip_to = None, close
                    continue
                pending.open = line
                current, pending = pending, None
                continue
            mf.headers_without_block.append(pending.header)  # type: ignore[arg-type]
            pending = None
        if stripped.startswith("}"):
            if current is None:
                mf.stray_closers.append(line)
            else:
                current.close = line
                current = None
            continue
        if stripped.startswith("{"):
            if strip_comment(stripped)[1:].strip():
                # `{ configuration block`: MOOS opens a block only right after a header;
                # elsewhere this is a line it drops
                mf.malformed.append(line)
                continue
            if current is not None and current.header is not None:
                mf.unclosed_blocks.append(current)
            current = Block(name="", header=None, open=line)
            mf.orphan_blocks.append(current)
            continue
        param = split_param(line)
        if param is None:
            # a line that is still an nsplug macro gets its text at launch: not judged
            if has_macro(stripped):
                if current is not None and _MACRO_ALONE.fullmatch(strip_comment(stripped).strip()):
                    current.macro_lines.append(line)
            elif "[" not in stripped and "]" not in stripped:
                mf.malformed.append(line)
            continue
        header = _header_name(param)
        if header is not None:
            name, brace = header
            if current is not None:
                # MOOS reads this header as a parameter of the block left open (a block
                # without a header of its own is no app's: orphan-block reports it)
                if current.header is not None:
                    mf.unclosed_blocks.append(current)
                current = None
            block = Block(name=name, header=line, brace_on_header=brace)
            block.name_start = line.text.find(name[:1], param.value_start) if name else 0
            if block.name_start < 0:
                block.name_start = param.value_start
            mf.blocks.append(block)
            if brace:
                # MOOS never finds this block; read on as if it were well formed.
                block.open = line
                current = block
            else:
                pending = block
            continue
        if current is not None:
            param.block = current
            current.params.append(param)
        elif param.key:
            mf.globals.append(param)
        else:
            mf.malformed.append(line)
    if pending is not None and pending.header is not None:
        mf.headers_without_block.append(pending.header)
    if current is not None and current.header is not None:
        mf.unclosed_blocks.append(current)
    return mf


__all__ = ["antler_runs", "looks_commented", "parse_moos", "parse_run"]
