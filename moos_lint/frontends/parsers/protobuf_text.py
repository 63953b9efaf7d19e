"""The reader of ProcessConfig blocks written in protobuf's text format.

goby's MOOS apps (``GobyMOOSApp``: pAcommsHandler, iFrontSeat, pTranslator, ...)
read their block themselves: everything from the ``ProcessConfig = NAME`` line
to the next line naming ``ProcessConfig``, cut to the text between the first
``{`` and the last ``}``, with every ``//`` turned into ``#``, is handed to
protobuf's ``TextFormat::Parser``. Inside such a block:

- a field is ``name: value`` or ``name { ... }`` (``name: { ... }`` and
  ``< ... >`` too), several may share a line, ``,`` or ``;`` may follow one;
- ``[a.b.ext]`` names an extension field; ``[v1, v2]`` is a list of values;
- ``#`` (and ``//``) start a comment; strings are quoted with ``"`` or ``'``.

:func:`read_block` parses the lines into :class:`~moos_lint.frontends.parsers.nodes.TextField`
trees and records the syntax errors protobuf would report, each at its line.
:func:`looks_like_text_format` is the hint for apps the catalogue does not
know: a block whose lines are mostly ``key: value`` or ``name {``.
"""

from __future__ import annotations

import re

from moos_lint.frontends.nsplug import Line
from moos_lint.frontends.parsers.nodes import TextField

_PUNCT = "{}<>[]:,;"
_WORD = re.compile(r"(?:[$%]\([^)\n]*\)|[^\s{}<>\[\]:,;#\"'/]|/(?!/))+")
_IDENT = re.compile(r"^[A-Za-z_][A-Za-z0-9_]*$")
_FIELD_LINE = re.compile(r"^\s*(?:\[[\w.]+\]|[A-Za-z_]\w*)\s*(?::|\{|<)")
_QUOTED = re.compile(r"\"[^\"]*\"|'[^']*'")
#: a nested message on one line, ``common { verbosity: DEBUG2 }``: no MOOS line looks so
_ONE_LINE_MESSAGE = re.compile(r"^[A-Za-z_]\w*\s*\{[^{}=]*:[^{}=]*\}$")


class _Tok:
    __slots__ = ("end", "kind", "line", "start", "text")

    def __init__(self, text: str, line: Line, start: int, end: int, kind: str) -> None:
        self.text, self.line, self.start, self.end, self.kind = text, line, start, end, kind


def _tokens(lines: list[Line], errors: list) -> list[_Tok]:
    out: list[_Tok] = []
    for line in lines:
        text = line.text
        i, n = 0, len(text)
        while i < n:
            c = text[i]
            if c.isspace():
                i += 1
            elif c == "#" or text.startswith("//", i):
                break
            elif c in _PUNCT:
                out.append(_Tok(c, line, i, i + 1, "punct"))
                i += 1
            elif c in "\"'":
                j = i + 1
                while j < n and text[j] != c:
                    j += 2 if text[j] == "\\" else 1
                if j >= n:
                    errors.append((line, i, n, "string not closed on its line"))
                    break
                out.append(_Tok(text[i : j + 1], line, i, j + 1, "string"))
                i = j + 1
            else:
                m = _WORD.match(text, i)
                if m is None or m.end() == i:  # a lone "/" before "//" cannot happen
                    i += 1
                    continue
                out.append(_Tok(m.group(), line, i, m.end(), "word"))
                i = m.end()
    return out


class _Parser:
    def __init__(self, toks: list[_Tok], errors: list) -> None:
        self.toks = toks
        self.i = 0
        self.errors = errors

    def peek(self) -> _Tok | None:
        return self.toks[self.i] if self.i < len(self.toks) else None

    def error(self, tok: _Tok, message: str) -> None:
        self.errors.append((tok.line, tok.start, tok.end, message))
        # resume at the first token of a later line, or at a `}` closing an open field
        line = tok.line
        depth = 0
        while self.i < len(self.toks) and self.toks[self.i].line is line:
            t = self.toks[self.i]
            if t.kind == "punct" and t.text in "{<":
                depth += 1
            elif t.kind == "punct" and t.text in "}>":
                if depth == 0:
                    return
                depth -= 1
            self.i += 1

    def message(self, closer: str | None, opener: _Tok | None) -> list[TextField]:
        fields: list[TextField] = []
        while True:
            tok = self.peek()
            if tok is None:
                if opener is not None:
                    self.errors.append(
                        (opener.line, opener.start, opener.end, f"`{opener.text}` is never closed")
                    )
                return fields
            if tok.text == closer and tok.kind == "punct":
                self.i += 1
                return fields
            if tok.kind == "punct" and tok.text in "}>":
                self.i += 1
                self.errors.append((tok.line, tok.start, tok.end, f"`{tok.text}` closes no `{{`"))
                continue
            if tok.kind == "punct" and tok.text in ",;":
                self.i += 1
                continue
            field = self.field()
            if field is not None:
                fields.append(field)

    def field(self) -> TextField | None:
        first = self.toks[self.i]
        if first.kind == "punct" and first.text == "[":
            j = self.i + 1
            if (
                j + 1 < len(self.toks)
                and self.toks[j].kind == "word"
                and self.toks[j + 1].text == "]"
            ):
                name, ext, start_tok = self.toks[j].text, True, first
                self.i = j + 2
            else:
                self.error(first, "an extension name needs the form `[package.name]`")
                return None
        elif first.kind == "word" and _IDENT.match(first.text):
            name, ext, start_tok = first.text, False, first
            self.i += 1
        else:
            self.error(
                first, "protobuf text needs `name: value` or `name { ... }` here (a field name)"
            )
            return None
        nxt = self.peek()
        colon = nxt is not None and nxt.kind == "punct" and nxt.text == ":"
        if colon:
            self.i += 1
            nxt = self.peek()
        if nxt is not None and nxt.kind == "punct" and nxt.text in "{<":
            self.i += 1
            closer = "}" if nxt.text == "{" else ">"
            children = self.message(closer, nxt)
            end = self.toks[self.i - 1] if self.i else nxt
            return TextField(name, start_tok.line, start_tok.start, end.end, None, children, ext)
        if not colon:
            where = nxt or start_tok
            self.error(where, f"`{name}` needs `: value` or `{{ ... }}` after it")
            return None
        after = self.toks[self.i + 1] if self.i + 1 < len(self.toks) else None
        if (
            nxt is None
            or (nxt.kind == "word" and after is not None and after.text == ":")
            or (
                nxt.line is not start_tok.line
                and (nxt.kind == "punct" or (after is not None and after.text in "{<"))
            )
        ):
            self.error(start_tok, f"`{name}:` has no value")
            return None
        if nxt.kind == "punct" and nxt.text == "[":
            return self.list_value(name, start_tok, ext)
        if nxt.kind == "punct":
            self.error(nxt, f"`{name}:` needs a value before `{nxt.text}`")
            return None
        self.i += 1
        value = nxt.text
        if nxt.kind == "string":  # adjacent strings concatenate
            while (p := self.peek()) is not None and p.kind == "string":
                self.i += 1
        elif value == "-" and (p := self.peek()) is not None and p.kind == "word":
            self.i += 1
            value += p.text
        return TextField(name, start_tok.line, start_tok.start, nxt.end, value, None, ext)

    def list_value(self, name: str, start_tok: _Tok, ext: bool) -> TextField | None:
        open_tok = self.toks[self.i]
        self.i += 1
        values: list[str] = []
        while (tok := self.peek()) is not None:
            self.i += 1
            if tok.kind == "punct" and tok.text == "]":
                return TextField(
                    name, start_tok.line, start_tok.start, tok.end, ", ".join(values), None, ext
                )
            if tok.kind == "punct" and tok.text == ",":
                continue
            if tok.kind == "punct" and tok.text in "{<":
                self.message("}" if tok.text == "{" else ">", tok)
                continue
            values.append(tok.text)
        self.errors.append((open_tok.line, open_tok.start, open_tok.end, "`[` is never closed"))
        return None


def read_block(lines: list[Line]) -> tuple[list[TextField], list[tuple[Line, int, int, str]]]:
    """The fields of a text-format block body and its syntax errors (line, start, end, why)."""
    errors: list[tuple[Line, int, int, str]] = []
    toks = _tokens(lines, errors)
    fields = _Parser(toks, errors).message(None, None)
    return fields, errors


def looks_like_text_format(lines: list[Line], known_app: bool) -> bool:
    """Whether a block body reads as protobuf text rather than MOOS ``key = value`` lines.

    An app the catalogue knows reads text format: its block is read so unless
    ``key = value`` lines outnumber the field lines (an older version of the app).
    For any other block, field lines must be most of its lines, or all of them when
    one is a whole nested message (``common { verbosity: DEBUG2 }``).
    """
    if not known_app:  # a field line holds `:`, `{` or `<`: most blocks have no two such
        maybe = 0
        for line in lines:
            t = line.text
            if "{" in t:  # (a nested message may be the whole body)
                maybe = 2
                break
            if ":" in t or "<" in t:
                maybe += 1
                if maybe == 2:
                    break
        if maybe < 2:
            return False
    fields = moos = other = whole = 0
    for line in lines:
        text = _QUOTED.sub('""', line.text).split("#", 1)[0].split("//", 1)[0].strip()
        if not text or text in ("{", "}"):
            continue
        if "=" in text:  # `key = value`, or `POINT:NAME=x` (a MOOS line with a colon)
            moos += 1
        elif _FIELD_LINE.match(text):
            fields += 1
            whole += bool(_ONE_LINE_MESSAGE.match(text))
        elif not text.startswith("}"):
            other += 1
    if known_app:
        return fields >= moos
    if whole and not moos and not other:
        return True
    return fields >= 2 and fields > moos + other
