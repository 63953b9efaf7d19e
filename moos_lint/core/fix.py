"""Applying fixes: ``moos-lint check --fix`` and ``--diff``.

A finding may carry a :class:`~moos_lint.files.diagnostics.Fix`: edits that replace
spans of text. Fixes are applied in passes, in memory: each pass applies every
fix whose edits overlap no edit already taken in that pass (a fix is all or
nothing), then the files are linted again from the new text, until a pass
changes nothing (at most :data:`MAX_PASSES`). Only then is anything written,
and only with ``--fix``:

* each changed file is written atomically (a temporary file in the same folder,
  then ``os.replace``), keeping its mode; a symbolic link stays a link to the
  file it names, which is what is rewritten;
* the file keeps its encoding (UTF-8, or latin-1 for files that were read as
  latin-1), its byte-order mark and its line endings (LF, CRLF or CR; an edit's
  own text uses the line ending of the line it lands on);
* a file whose text does not change is never written; a fix whose new text
  the file's encoding cannot hold is skipped.
"""

from __future__ import annotations

import contextlib
import difflib
import os
import re
import tempfile
from collections.abc import Callable
from dataclasses import dataclass, field
from pathlib import Path

from moos_lint.core.result import Result
from moos_lint.files.diagnostics import Diagnostic, Edit, Fix
from moos_lint.files.source import ReadProblem, SourceFile, decode, read_source
from moos_lint.frontends.nsplug import FileCache

MAX_PASSES = 10
_LINE_END = re.compile(r"\r\n|\r|\n")


@dataclass
class Document:
    """A file's text as it is being fixed, with what is needed to write it back."""

    path: str
    original: bytes
    text: str  # without the BOM
    encoding: str
    bom: bool

    def encode(self, text: str | None = None) -> bytes:
        data = (self.text if text is None else text).encode(self.encoding)
        return (b"\xef\xbb\xbf" + data) if self.bom else data

    @property
    def changed(self) -> bool:
        return self.encode() != self.original


def load_document(path: str) -> Document | None:
    """A document for ``path``, or None when it is not a text file moos-lint could read."""
    try:
        with open(path, "rb") as fh:
            data = fh.read()
    except OSError:
        return None
    src = decode(data, Path(path))
    if isinstance(src, ReadProblem):
        return None
    return Document(path, data, src.text, src.encoding, src.bom)


def _line_starts(text: str) -> list[tuple[int, int]]:
    """For each line: (offset of its first character, offset of its line end)."""
    out: list[tuple[int, int]] = []
    pos = 0
    for m in _LINE_END.finditer(text):
        out.append((pos, m.start()))
        pos = m.end()
    if pos < len(text) or not out:
        out.append((pos, len(text)))
    return out


def _offset(lines: list[tuple[int, int]], text_len: int, line: int, col: int) -> int | None:
    """The text offset of 1-based (line, col); a column past the end clamps to the line end."""
    if line == len(lines) + 1 and col == 1:
        return text_len  # just past the last line: a whole-line deletion of the last line
    if not 1 <= line <= len(lines) or col < 1:
        return None
    start, end = lines[line - 1]
    return min(start + col - 1, end)


def _newline_at(text: str, lines: list[tuple[int, int]], line: int) -> str:
    if 1 <= line <= len(lines):
        end = lines[line - 1][1]
        m = _LINE_END.match(text, end)
        if m:
            return m.group()
    m = _LINE_END.search(text)
    return m.group() if m else "\n"


def _resolve(
    doc: Document, edit: Edit, lines: list[tuple[int, int]]
) -> tuple[int, int, str] | None:
    s = edit.span
    start = _offset(lines, len(doc.text), s.line, s.col)
    end = _offset(lines, len(doc.text), s.end_line, s.end_col)
    if start is None or end is None or end < start:
        return None
    text = edit.text
    if "\n" in text or "\r" in text:
        text = _LINE_END.sub(_newline_at(doc.text, lines, s.line), text)
    try:
        text.encode(doc.encoding)
    except UnicodeEncodeError:
        return None
    return start, end, text


def _overlaps(a: tuple[int, int], b: tuple[int, int]) -> bool:
    if a == b:
        return True  # two insertions at one point, or one span replaced twice
    return a[0] < b[1] and b[0] < a[1]


@dataclass
class PassResult:
    applied: list[Diagnostic] = field(default_factory=list)
    skipped: list[Diagnostic] = field(default_factory=list)
    changed: bool = False  # some document's text changed


def apply_fixes(diagnostics: list[Diagnostic], docs: dict[str, Document]) -> PassResult:
    """Apply, in ``docs``, every fix that does not collide with one taken before it.

    Fixes are taken in the order of their findings. Edits identical to an edit
    already taken (two findings offering the same fix) are applied once.
    """
    out = PassResult()
    taken: dict[str, list[tuple[int, int, str]]] = {}
    line_cache: dict[str, list[tuple[int, int]]] = {}
    for d in diagnostics:
        fix: Fix | None = d.fix
        if fix is None or not fix.edits:
            continue
        resolved: list[tuple[str, tuple[int, int, str]]] = []
        ok = True
        for edit in fix.edits:
            path = edit.span.path
            if path not in docs:
                doc = load_document(path)
                if doc is None:
                    ok = False
                    break
                docs[path] = doc
            doc = docs[path]
            if path not in line_cache:
                line_cache[path] = _line_starts(doc.text)
            r = _resolve(doc, edit, line_cache[path])
            if r is None:
                ok = False
                break
            resolved.append((path, r))
        if ok:
            fresh: list[tuple[str, tuple[int, int, str]]] = []
            for path, r in resolved:
                mine = taken.get(path, [])
                if r in mine or any(r == f for _, f in fresh):
                    continue  # the very same edit: apply it once
                if any(_overlaps(r[:2], t[:2]) for t in mine) or any(
                    p == path and _overlaps(r[:2], f[:2]) for p, f in fresh
                ):
                    ok = False
                    break
                fresh.append((path, r))
        if not ok:
            out.skipped.append(d)
            continue
        for path, r in fresh:
            taken.setdefault(path, []).append(r)
        out.applied.append(d)
    for path, edits in taken.items():
        doc = docs[path]
        text = doc.text
        for start, end, new in sorted(edits, key=lambda e: (e[0], e[1]), reverse=True):
            text = text[:start] + new + text[end:]
        if text != doc.text:
            out.changed = True
        doc.text = text
    return out


class OverlayReader:
    """Reads files from disk, except those being fixed, which come from memory."""

    def __init__(self, docs: dict[str, Document]):
        self.docs = docs

    def __call__(self, path: Path) -> SourceFile | ReadProblem:
        return self.in_memory(path) or read_source(path)

    def in_memory(self, path: Path) -> SourceFile | ReadProblem | None:
        """The fixed text of a file being fixed; None for any other file."""
        doc = self.docs.get(os.path.normpath(os.path.abspath(path)))
        return decode(doc.encode(), path) if doc is not None else None


@dataclass
class FixOutcome:
    result: object  # the engine Result of the last lint, on the fixed text
    docs: dict[str, Document]
    fixed: int  # findings whose fix was applied
    passes: int

    @property
    def changed(self) -> list[Document]:
        return [d for _, d in sorted(self.docs.items()) if d.changed]


def fix_until_stable(
    lint: Callable[[FileCache], Result],
    first: Result | None = None,
    max_passes: int = MAX_PASSES,
) -> FixOutcome:
    """Lint, apply the fixes, lint again ... until a pass applies nothing.

    ``lint(cache)`` runs the linter reading files through ``cache``; ``first``
    is the result of a lint already done on the files as they are on disk.
    """
    docs: dict[str, Document] = {}
    result = first if first is not None else lint(FileCache(OverlayReader(docs)))
    fixed = 0
    passes = 0
    while passes < max_passes:
        fixable = [d for d in result.diagnostics if d.fix is not None]
        if not fixable:
            break
        step = apply_fixes(fixable, docs)
        if not step.changed:
            break
        passes += 1
        fixed += len(step.applied)
        result = lint(FileCache(OverlayReader(docs)))
    return FixOutcome(result, docs, fixed, passes)


def unified_diff(doc: Document, display: str) -> str:
    """A unified diff of ``doc`` from its bytes on disk to its fixed text."""
    old = decode(doc.original, Path(doc.path))
    old_text = old.text if isinstance(old, SourceFile) else ""
    diff = difflib.unified_diff(
        old_text.splitlines(keepends=True),
        doc.text.splitlines(keepends=True),
        fromfile=f"a/{display}",
        tofile=f"b/{display}",
    )
    out = []
    for line in diff:
        if not line.endswith(("\n", "\r")):
            line += "\n\\ No newline at end of file\n"
        out.append(line)
    return "".join(out)


def write_atomic(doc: Document) -> None:
    """Replace the file with the document's bytes, atomically."""
    data = doc.encode()
    target = os.path.realpath(doc.path)  # through a symlink: replace the file, keep the link
    folder = os.path.dirname(target) or "."
    try:
        mode = os.stat(target).st_mode & 0o7777
    except OSError:  # a new file: the permissions open() would give it
        umask = os.umask(0)
        os.umask(umask)
        mode = 0o666 & ~umask
    fd, tmp = tempfile.mkstemp(prefix=".moos-lint-", suffix=".tmp", dir=folder)
    try:
        with os.fdopen(fd, "wb") as fh:
            fh.write(data)
            fh.flush()
            os.fsync(fh.fileno())
        os.chmod(tmp, mode)
        os.replace(tmp, target)
    except BaseException:
        with contextlib.suppress(OSError):
            os.unlink(tmp)
        raise
