"""libclang deep mode (``--cpp-backend clang``): ``#ifdef`` as compiled, constants, types.

It sharpens the tree-sitter reading, never replaces it (:func:`sharpen`): the
translation units of the apps that publish or register are parsed with their
flags from a ``compile_commands.json``, and each such app is read again with
what libclang knows of its files (:mod:`moos_lint.frontends.cpp.clang_facts`):
the regions the preprocessor skipped are blanked before tree-sitter parses, and
the value analysis asks for constants and types at the positions tree-sitter
found (``Cursor.from_location``); whole ASTs are never walked in Python. When
libclang, the compilation database or the headers are missing, moos-lint says
so once on stderr and keeps the tree-sitter results.
"""

from __future__ import annotations

import ctypes
import os
import shutil
import subprocess
import sys
from collections.abc import Callable
from functools import lru_cache
from typing import TYPE_CHECKING, Any

from moos_lint.files.project import is_within
from moos_lint.files.suffixes import is_cpp_source
from moos_lint.frontends.cpp.model import AppModel, CppFile

if TYPE_CHECKING:
    from moos_lint.core.config import Settings
    from moos_lint.files.source import SourceFile
    from moos_lint.frontends.cpp.clang_facts import ClangFacts

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


def _parser(ci: Any, db: Any, inc: str | None, within: Callable[[str], bool]):
    """A function parsing one source of the compile database into a :class:`Unit`, or
    None (not in the database, or libclang cannot read it: said once)."""
    from moos_lint.frontends.cpp.clang_facts import Unit

    index = ci.Index.create()
    options = ci.TranslationUnit.PARSE_DETAILED_PROCESSING_RECORD  # for the skipped regions
    tried: set[str] = set()

    def parse(path: str) -> Unit | None:
        if path in tried:
            return None
        tried.add(path)
        cmds = db.getCompileCommands(path)
        if not cmds:
            return None
        args = _args(cmds[0], path)
        if inc:
            args += ["-isystem", inc]
        try:
            tu = index.parse(path, args, options=options)
        except ci.TranslationUnitLoadError:
            warn_once("tu:" + path, f"libclang could not parse {path}; using tree-sitter for it")
            return None
        fatal = [d for d in tu.diagnostics if d.severity >= ci.Diagnostic.Fatal]
        if fatal:
            warn_once(
                "fatal",
                f"libclang: {fatal[0].spelling} in {fatal[0].location.file}: headers are missing, "
                "so C++ is read with tree-sitter where libclang cannot see the code",
            )
            return None
        try:
            return Unit(ci, path, tu, within)
        except Exception as exc:  # a unit whose includes or skipped regions cannot be read
            warn_once("tu:" + path, f"libclang could not read {path} ({exc}); using tree-sitter")
            return None

    return parse


def sharpen(
    apps: list[AppModel], sources: dict[str, SourceFile], settings: Settings
) -> ClangFacts | None:
    """Read the apps again as compiled, with what libclang knows (skipped regions,
    constants, types), and return those facts for the rest of the value analysis.

    Only apps that publish or subscribe are compiled, each from its own sources in the
    compile database. An app none of whose units libclang can parse keeps its
    tree-sitter reading, untouched; without libclang or a database every app does
    (said once on stderr), and None is returned.
    """
    from moos_lint.frontends.cpp.app import link_apps, parse_folder
    from moos_lint.frontends.cpp.clang_facts import ClangFacts

    ci = load_cindex()
    if ci is None:
        return None
    db_dir = find_compile_commands(settings, [a.folder for a in apps])
    if db_dir is None:
        warn_once(
            "no-db",
            "--cpp-backend clang needs a compile_commands.json (give it with --compile-commands "
            "or configure with -DCMAKE_EXPORT_COMPILE_COMMANDS=ON); "
            "reading C++ with tree-sitter only",
        )
        return None
    try:
        db = ci.CompilationDatabase.fromDirectory(db_dir)
    except ci.CompilationDatabaseError:
        warn_once("no-db", f"cannot read {db_dir}/compile_commands.json; using tree-sitter only")
        return None
    inc = system_include()
    if inc is None:
        warn_once(
            "no-headers",
            "no system compiler include folder found (gcc -print-file-name=include): "
            "libclang may not find <stddef.h>",
        )
    root = os.path.realpath(settings.project_root or settings.root)

    def within(name: str) -> bool:
        return is_within(os.path.realpath(name), root)

    facts = ClangFacts(ci, _Eval(ci), _parser(ci, db, inc, within))
    changed = False
    for app in apps:
        if not any(f.publications or f.subscriptions for f in app.files):
            continue
        facts.focus([])  # the last app's units go before this app's are parsed
        units = [u for f in app.files if is_cpp_source(f.path) for u in [facts.parse(f.path)] if u]
        if not units:
            continue
        for u in units:
            facts.add(u)
        facts.focus(units)
        before = {f.path: f for f in app.files}
        mine = {p: s for p, s in sources.items() if p in before}
        app.files = parse_folder(mine, facts)
        for f in app.files:
            _keep_compiled_out(f, before.get(f.path), facts)
        app.backend = "clang"
        changed = True
    facts.focus([])
    if changed:
        link_apps(apps)
    return facts


def _keep_compiled_out(f: CppFile, first: CppFile | None, facts: ClangFacts) -> None:
    """The publications and subscriptions of the tree-sitter reading that the compiler
    skipped, kept as inactive (no rule sees them)."""
    if first is None:
        return
    dead = facts.skipped_lines(f.path)
    if not dead:
        return
    for p in first.publications:
        if p.span.line in dead:
            p.active = False
            f.publications.append(p)
    for s in first.subscriptions:
        if s.span.line in dead:
            s.active = False
            f.subscriptions.append(s)
