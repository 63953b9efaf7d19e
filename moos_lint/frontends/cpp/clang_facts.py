"""What libclang knows of each file, for the value analysis (``--cpp-backend clang``).

:mod:`moos_lint.frontends.cpp.clang` parses translation units with the compile
database; this module keeps, of each unit, what the value analysis asks:

- **the code as compiled**: the lines of each project file inside a
  preprocessor region the unit skipped (``#ifdef`` with the macro undefined,
  ``#if 0``). :meth:`ClangFacts.live` blanks them (the directives stay), so the
  tree-sitter reading sees neither their assignments, conversions and returns,
  nor their ``#define``\\ s and calls;
- **constants**: the folded value of an identifier tree-sitter cannot resolve (a
  ``const``/``constexpr`` variable or an enum value from another folder's
  header, a macro from a header or a ``-D`` flag), with where it is defined;
- **types**: the type of a published expression (integer, floating, string, bool)
  and its folded value when it is a constant.

Positions are those of the tree-sitter reading (0-based rows, byte columns), which
blanking keeps. A file no parsed unit includes has no facts: it is read with
tree-sitter alone, as without libclang.
"""

from __future__ import annotations

import ctypes
import os
import re
from collections.abc import Callable, Iterable
from typing import Any

from moos_lint.files.suffixes import is_cpp_source
from moos_lint.frontends.cpp.values import define_const, place

#: the conditional directives a skipped region starts and ends with (kept when blanking)
_CONDITIONALS = (b"if", b"ifdef", b"ifndef", b"elif", b"elifdef", b"elifndef", b"else", b"endif")


def _key(path: str) -> str:
    return os.path.realpath(path)


_RANGE_LIST: list[Any] = []  # the ``CXSourceRangeList`` structure, made once


class Unit:
    """One parsed translation unit: its skipped lines per project file, and the files it holds."""

    def __init__(self, ci: Any, path: str, tu: Any, within: Callable[[str], bool]):
        self.path = path
        self.tu = tu
        self.files: set[str] = {_key(path)}
        for inc in tu.get_includes():
            name = inc.include.name if inc.include is not None else None
            if name and within(name):
                self.files.add(_key(name))
        self.skipped: dict[str, set[int]] = {}
        for start, end, name in _skipped_ranges(ci, tu):
            if within(name):
                # the directives on the first and last lines stay; what lies between is dead
                self.skipped.setdefault(_key(name), set()).update(range(start + 1, end))


def _skipped_ranges(ci: Any, tu: Any) -> Iterable[tuple[int, int, str]]:
    """(first line, last line, file) of each region the preprocessor skipped."""
    lib = ci.conf.lib
    if not hasattr(lib, "clang_getAllSkippedRanges"):
        return []
    if not _RANGE_LIST:

        class RangeList(ctypes.Structure):
            _fields_ = [("count", ctypes.c_uint), ("ranges", ctypes.POINTER(ci.SourceRange))]

        lib.clang_getAllSkippedRanges.argtypes = [ci.TranslationUnit]
        lib.clang_getAllSkippedRanges.restype = ctypes.POINTER(RangeList)
        lib.clang_disposeSourceRangeList.argtypes = [ctypes.POINTER(RangeList)]
        _RANGE_LIST.append(RangeList)
    found = lib.clang_getAllSkippedRanges(tu)
    if not found:
        return []
    out = []
    try:
        for i in range(found.contents.count):
            r = found.contents.ranges[i]
            f = r.start.file
            if f is not None:
                out.append((r.start.line, r.end.line, f.name))
    finally:
        lib.clang_disposeSourceRangeList(found)
    return out


class ClangFacts:
    """The facts of the units parsed so far, and lookups in them.

    ``scope`` (set with :meth:`focus`) is the units of the app being read: its files
    are as compiled into that app. Out of scope (a library file the value flow
    reaches), a file's skipped lines are those every parsed unit including it skipped.
    """

    def __init__(self, ci: Any, evaluate: Any, parse: Callable[[str], Unit | None]):
        self.ci = ci
        self.evaluate = evaluate  # :class:`moos_lint.frontends.cpp.clang._Eval`
        self.parse = parse
        self.scope: list[Unit] = []
        self._own: dict[str, Unit | None] = {}  # a source's own unit, parsed on demand
        #: what the units parsed so far skipped, by file: kept after the units are let go
        self._skipped: dict[str, list[set[int]]] = {}

    def add(self, unit: Unit) -> None:
        """Note what ``unit`` skipped, for the files read out of any app's scope."""
        for f in unit.files:
            self._skipped.setdefault(f, []).append(unit.skipped.get(f, set()))

    def focus(self, units: list[Unit]) -> None:
        """Read the next files as compiled into ``units``; let the units before go."""
        for u in self.scope:
            if u not in units:
                u.tu = None  # a unit's AST is large: keep only the app's being read
        self.scope = units

    # -- the code as compiled
    def skipped_lines(self, path: str) -> set[int]:
        """The lines of ``path`` the preprocessor skipped (1-based), as compiled into the
        app in scope; else in every unit parsed so far that includes the file (a
        library source no unit includes is parsed on its own, when it is in the
        database)."""
        key = _key(path)
        mine = [u.skipped.get(key, set()) for u in self.scope if key in u.files]
        if not mine:
            mine = self._skipped.get(key, [])
            if not mine and self._own_unit(path) is not None:
                mine = self._skipped.get(key, [])
        return set.intersection(*mine) if mine else set()

    def live(self, path: str, data: bytes) -> bytes:
        """``data`` with the lines the compiler skipped blanked (same bytes per line)."""
        dead = self.skipped_lines(path)
        if not dead:
            return data
        lines = data.split(b"\n")
        for n in dead:
            if 0 < n <= len(lines):
                line = lines[n - 1]
                if not _is_conditional(line):
                    lines[n - 1] = b" " * len(line)
        return b"\n".join(lines)

    # -- lookups at a position
    def _unit_for(self, path: str) -> Any:
        key = _key(path)
        for u in self.scope:
            if key in u.files and u.tu is not None:
                return u.tu
        own = self._own_unit(path)
        return own.tu if own is not None else None

    def _own_unit(self, path: str) -> Unit | None:
        key = _key(path)
        if key not in self._own:
            self._own[key] = None
            if is_cpp_source(path) and not any(key in u.files for u in self.scope):
                unit = self.parse(path)
                if unit is not None:
                    for old in self._own.values():
                        if old is not None:
                            old.tu = None  # one library unit at a time
                    self.add(unit)
                    self._own[key] = unit
        own = self._own[key]
        return own if own is not None and own.tu is not None else None

    def _cursor(self, path: str, row: int, col: int) -> Any:
        tu = self._unit_for(path)
        if tu is None:
            return None
        ci = self.ci
        try:
            cf = tu.get_file(path)
            loc = ci.SourceLocation.from_position(tu, cf, row + 1, col + 1)
            return ci.Cursor.from_location(tu, loc)
        except Exception:
            return None

    def constant(self, path: str, row: int, col: int, name: str) -> tuple[float, str] | None:
        """The value of the constant ``name`` used at (``row``, ``col``), and where it is
        defined; None when it is not a constant (a variable, a function-like macro)."""
        try:
            return self._constant(path, row, col, name)
        except Exception:  # a cursor kind these bindings do not know, a broken unit
            return None

    def _constant(self, path: str, row: int, col: int, name: str) -> tuple[float, str] | None:
        c = self._cursor(path, row, col)
        if c is None or c.spelling != name:
            return None
        ref = c.referenced
        if ref is None:
            return None
        ck = self.ci.CursorKind
        value: float | None = None
        shown = ""
        if ref.kind == ck.ENUM_CONSTANT_DECL:
            value = float(ref.enum_value)
            shown = f"{value:g}"
        elif ref.kind == ck.VAR_DECL and ref.type.is_const_qualified():
            value = self.evaluate.number(ref)
            words = [t.spelling for t in ref.get_tokens()]
            shown = " ".join(words[words.index("=") + 1 :]) if "=" in words else ""
        elif ref.kind == ck.MACRO_DEFINITION and not _builtin(self.ci, ref):
            shown = _object_macro(ref)
            value = define_const(shown, {}) if shown else None
        if value is None:
            return None
        loc = ref.location
        where = (
            f"at {place(loc.file.name, loc.line)}"
            if loc.file is not None
            else "by a -D flag of the compile database"
        )
        shown = re.sub(r"\(\s+", "(", re.sub(r"\s+\)", ")", " ".join(shown.split())))
        shown = shown if shown and len(shown) <= 40 else f"{value:g}"
        return value, f"`{name}` is {shown}, defined {where}"

    def argument(
        self, path: str, row: int, col: int, index: int
    ) -> tuple[str | None, float | None]:
        """The type (integer, floating, string, bool) and folded value of argument
        ``index`` of the call whose ``(`` is at (``row``, ``col``)."""
        try:
            c = self._cursor(path, row, col)
            if c is None or c.kind != self.ci.CursorKind.CALL_EXPR:
                return None, None
            args = list(c.get_arguments())
            if index >= len(args):
                return None, None
            return _kind(self.ci, args[index]), self.evaluate.number(args[index])
        except Exception:  # a cursor kind these bindings do not know, a broken unit
            return None, None


def _builtin(ci: Any, ref: Any) -> bool:
    """A macro the compiler predefines (``__DBL_MAX__``): no file, and no -D flag either."""
    lib = ci.conf.lib
    f = getattr(lib, "clang_Cursor_isMacroBuiltin", None)
    if f is None:
        return False
    f.argtypes = [ci.Cursor]
    f.restype = ctypes.c_uint
    return bool(f(ref))


def _object_macro(ref: Any) -> str:
    """The replacement of an object-like macro (``#define K (180.0 / M_PI)``); ``""`` for a
    function-like one (``#define RAD2DEG(x) ...``: its ``(`` touches the name)."""
    tokens = list(ref.get_tokens())
    if len(tokens) < 2:
        return ""
    name, first = tokens[0], tokens[1]
    if first.spelling == "(" and first.extent.start.offset == name.extent.end.offset:
        return ""
    return " ".join(t.spelling for t in tokens[1:])


def _is_conditional(line: bytes) -> bool:
    s = line.lstrip()
    if not s.startswith(b"#"):
        return False
    word = s[1:].lstrip().split(None, 1)
    return bool(word) and word[0].split(b"(")[0] in _CONDITIONALS


_INTEGERS = (
    "CHAR_U",
    "UCHAR",
    "USHORT",
    "UINT",
    "ULONG",
    "ULONGLONG",
    "CHAR_S",
    "SCHAR",
    "SHORT",
    "INT",
    "LONG",
    "LONGLONG",
    "ENUM",
)


def _kind(ci: Any, arg: Any) -> str | None:
    """The type of an expression before the implicit conversions of the call."""
    x = arg
    while x.kind == ci.CursorKind.UNEXPOSED_EXPR:
        kids = list(x.get_children())
        if len(kids) != 1:
            break
        x = kids[0]
    t = x.type.get_canonical()
    tk = t.kind.name
    if tk == "BOOL":
        return "bool"
    if tk in ("FLOAT", "DOUBLE", "LONGDOUBLE", "FLOAT128", "HALF"):
        return "floating"
    if tk in _INTEGERS:
        return "integer"
    spelled = t.spelling
    if "basic_string" in spelled or "string_view" in spelled:
        return "string"
    if tk in ("POINTER", "CONSTANTARRAY", "INCOMPLETEARRAY"):
        inner = t.get_pointee() if tk == "POINTER" else t.element_type
        if inner.kind.name in ("CHAR_S", "CHAR_U", "SCHAR", "UCHAR"):
            return "string"
    return None
