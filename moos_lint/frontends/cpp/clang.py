"""libclang deep mode (``--cpp-backend clang``): types, constant folding, ``#ifdef`` as compiled.

It refines the tree-sitter model, never replaces it: only the translation units
the fast path found relevant are parsed (with their flags from a
``compile_commands.json``), and the cursor is looked up at each call position
tree-sitter found (``Cursor.from_location``); whole ASTs are never walked in
Python. When libclang, the compilation database or the system headers are
missing, moos-lint says so once on stderr and keeps the tree-sitter results.
"""

from __future__ import annotations

import ctypes
import os
import shutil
import subprocess
import sys
from functools import lru_cache
from typing import TYPE_CHECKING, Any

from moos_lint.files.project import is_within
from moos_lint.files.suffixes import is_cpp_source
from moos_lint.frontends.cpp.model import AppModel, Publication, Subscription

if TYPE_CHECKING:
    from moos_lint.core.config import Settings

_warned: set[str] = set()


def warn_once(key: str, message: str) -> None:
    if key not in _warned:
        _warned.add(key)
        print(f"moos-lint: warning: {message}", file=sys.stderr)


def load_cindex() -> Any | None:
    try:
        import clang.cindex as ci
    except ImportError:
        warn_once(
            "no-libclang",
            "--cpp-backend clang needs libclang (pip install 'moos-lint[clang]'); "
            "reading C++ with tree-sitter only",
        )
        return None
    try:
        ci.conf.lib  # noqa: B018  (loads the shared library)
    except Exception as exc:  # a broken install: no libclang.so
        warn_once("no-libclang", f"libclang cannot be loaded ({exc}); reading C++ with tree-sitter")
        return None
    return ci


def find_compile_commands(settings: Settings, folders: list[str]) -> str | None:
    """The folder holding compile_commands.json: given, else at or above the linted code,
    up to the project root and never above it (a database above is no part of the project)."""
    given = settings.compile_commands
    if given:
        folder = os.path.dirname(given) if given.endswith(".json") else given
        return folder if os.path.isfile(os.path.join(folder, "compile_commands.json")) else None
    root = os.path.abspath(settings.project_root or settings.root)
    starts = [root, *folders]
    for start in starts:
        here = os.path.abspath(start)
        if not is_within(here, root):
            continue
        while True:
            for sub in ("", "build"):
                if os.path.isfile(os.path.join(here, sub, "compile_commands.json")):
                    return os.path.join(here, sub)
            parent = os.path.dirname(here)
            if here == root or parent == here:
                break
            here = parent
    return None


@lru_cache(maxsize=1)
def system_include() -> str | None:
    """The compiler's own include folder (stddef.h ...), which the libclang wheel lacks."""
    for cc in ("gcc", "cc", "clang"):
        exe = shutil.which(cc)
        if not exe:
            continue
        try:
            out = subprocess.run(
                [exe, "-print-file-name=include"], capture_output=True, text=True, timeout=10
            ).stdout.strip()
        except (OSError, subprocess.SubprocessError):
            continue
        if os.path.isabs(out) and os.path.isfile(os.path.join(out, "stddef.h")):
            return out
    return None


#: The flags that shape how a file parses, each with its value joined (``-DX=1``) or as
#: the next argument (``-D X``). Nothing else a repository's compile database holds
#: reaches libclang: not ``-include``, plugins (``-fplugin``, ``-Xclang``), module
#: caches, output or dependency files.
_PARSE_FLAGS = ("-isystem", "-I", "-D", "-U", "-std")
_FOLDER_FLAGS = ("-isystem", "-I")


def _args(cmd: Any, path: str) -> list[str]:
    """The parse-shaping flags of a compile command (see ``_PARSE_FLAGS``), relative
    folders made absolute against the command's directory."""
    return parse_flags(list(cmd.arguments)[1:], cmd.directory)


def parse_flags(arguments: list[str], directory: str) -> list[str]:
    """The flags of ``arguments`` that libclang may see, in their joined form."""
    out: list[str] = []
    it = iter(arguments)
    for a in it:
        flag = next((f for f in _PARSE_FLAGS if a.startswith(f)), None)
        if flag is None:
            continue
        value = a[len(flag) :]
        if flag == "-std":
            if value.startswith("="):
                value = value[1:]
            elif value:  # -stdlib=..., not -std
                continue
        if not value:
            value = next(it, "")
            if not value:
                continue
        if flag in _FOLDER_FLAGS:
            value = os.path.join(directory, value)
            out += [flag, value] if flag == "-isystem" else [flag + value]
        elif flag == "-std":
            out.append(f"-std={value}")
        else:
            out.append(flag + value)
    return out


class _Eval:
    """``clang_Cursor_Evaluate``, which the Python bindings do not wrap."""

    def __init__(self, ci: Any):
        lib = ci.conf.lib
        self.ok = all(
            hasattr(lib, f)
            for f in (
                "clang_Cursor_Evaluate",
                "clang_EvalResult_getKind",
                "clang_EvalResult_getAsDouble",
                "clang_EvalResult_getAsLongLong",
                "clang_EvalResult_dispose",
            )
        )
        if not self.ok:
            return
        lib.clang_Cursor_Evaluate.argtypes = [ci.Cursor]
        lib.clang_Cursor_Evaluate.restype = ctypes.c_void_p
        lib.clang_EvalResult_getKind.argtypes = [ctypes.c_void_p]
        lib.clang_EvalResult_getKind.restype = ctypes.c_int
        lib.clang_EvalResult_getAsDouble.argtypes = [ctypes.c_void_p]
        lib.clang_EvalResult_getAsDouble.restype = ctypes.c_double
        lib.clang_EvalResult_getAsLongLong.argtypes = [ctypes.c_void_p]
        lib.clang_EvalResult_getAsLongLong.restype = ctypes.c_longlong
        lib.clang_EvalResult_dispose.argtypes = [ctypes.c_void_p]
        self.lib = lib

    def number(self, cursor: Any) -> float | None:
        if not self.ok:
            return None
        res = self.lib.clang_Cursor_Evaluate(cursor)
        if not res:
            return None
        try:
            kind = self.lib.clang_EvalResult_getKind(res)
            if kind == 1:  # CXEval_Int
                return float(self.lib.clang_EvalResult_getAsLongLong(res))
            if kind == 2:  # CXEval_Float
                return float(self.lib.clang_EvalResult_getAsDouble(res))
            return None
        finally:
            self.lib.clang_EvalResult_dispose(res)


def _byte_col(line_text: str, col: int) -> int:
    return len(line_text[: col - 1].encode("utf-8")) + 1


def enrich(apps: list[AppModel], settings: Settings) -> None:
    """Refine the app models with libclang; warn once and keep them as they are on failure."""
    ci = load_cindex()
    if ci is None:
        return
    folders = [a.folder for a in apps]
    db_dir = find_compile_commands(settings, folders)
    if db_dir is None:
        warn_once(
            "no-db",
            "--cpp-backend clang needs a compile_commands.json (give it with --compile-commands "
            "or configure with -DCMAKE_EXPORT_COMPILE_COMMANDS=ON); "
            "reading C++ with tree-sitter only",
        )
        return
    try:
        db = ci.CompilationDatabase.fromDirectory(db_dir)
    except ci.CompilationDatabaseError:
        warn_once("no-db", f"cannot read {db_dir}/compile_commands.json; using tree-sitter only")
        return
    inc = system_include()
    if inc is None:
        warn_once(
            "no-headers",
            "no system compiler include folder found (gcc -print-file-name=include): "
            "libclang may not find <stddef.h>",
        )
    index = ci.Index.create()
    ev = _Eval(ci)
    for app in apps:
        _enrich_app(ci, index, db, inc, ev, app)


def _enrich_app(ci: Any, index: Any, db: Any, inc: str | None, ev: _Eval, app: AppModel) -> None:
    calls: dict[str, list[Publication | Subscription]] = {}
    for f in app.files:
        items: list[Publication | Subscription] = [*f.publications, *f.subscriptions]
        if items:
            calls[f.path] = items
    if not calls:
        return
    done: set[str] = set()
    units = [f.path for f in app.files if is_cpp_source(f.path)]
    for path in units:
        cmds = db.getCompileCommands(path)
        if not cmds:
            continue
        args = _args(cmds[0], path)
        if inc:
            args += ["-isystem", inc]
        try:
            tu = index.parse(path, args)
        except ci.TranslationUnitLoadError:
            warn_once("tu:" + path, f"libclang could not parse {path}; using tree-sitter for it")
            continue
        fatal = [d for d in tu.diagnostics if d.severity >= ci.Diagnostic.Fatal]
        if fatal:
            warn_once(
                "fatal",
                f"libclang: {fatal[0].spelling} in {fatal[0].location.file}: headers are missing, "
                "so C++ is read with tree-sitter where libclang cannot see the code",
            )
            continue
        app.backend = "clang"
        for fpath, items in calls.items():
            if fpath in done:
                continue
            cf = tu.get_file(fpath)
            if cf is None:
                continue
            done.add(fpath)
            try:
                with open(fpath, encoding="utf-8", errors="replace") as fh:
                    lines = fh.read().split("\n")
            except OSError:
                continue
            for item in items:
                _lookup(ci, tu, cf, lines, item, ev)


def _lookup(ci: Any, tu: Any, cf: Any, lines: list[str], item: Any, ev: _Eval) -> None:
    span = item.name_span
    if span.line > len(lines):
        return
    text = lines[span.line - 1]
    paren = text.rfind("(", 0, span.col - 1)
    if paren < 0:
        return
    loc = ci.SourceLocation.from_position(tu, cf, span.line, _byte_col(text, paren + 1))
    cursor = ci.Cursor.from_location(tu, loc)
    if cursor is None:
        return
    if cursor.kind in (ci.CursorKind.COMPOUND_STMT, ci.CursorKind.TRANSLATION_UNIT):
        item.active = False  # compiled out by #if / #ifdef
        return
    if cursor.kind != ci.CursorKind.CALL_EXPR or not isinstance(item, Publication):
        return
    args = list(cursor.get_arguments())
    if len(args) < 2 or item.value is None:
        return
    decl = cursor.referenced
    if decl is not None:
        params = list(decl.get_arguments())
        if len(params) >= 2:
            spelled = params[1].type.get_canonical().spelling
            item.value.type = (
                "string"
                if "basic_string" in spelled or "char" in spelled
                else (spelled.replace("const ", "").strip())
            )
    number = ev.number(args[1])
    if number is not None and item.value.number is None:
        item.value.number = number
