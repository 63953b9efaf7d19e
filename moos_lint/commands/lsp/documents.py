"""The editor's open documents, and which of them depends on which file.

The engine reads every file through a :class:`~moos_lint.frontends.nsplug.FileCache`; the
reader made here serves an open document's in-memory (unsaved) text and falls
back to the disk for every other file. Each lint of a document records every
file it read, so that an edit to an included fragment or a behavior file
re-lints the open missions that use it.
"""

from __future__ import annotations

import os
import threading
from collections import OrderedDict
from collections.abc import Callable
from dataclasses import dataclass, field
from pathlib import Path
from urllib.parse import quote, unquote, urlparse

from moos_lint.files.source import ReadProblem, SourceFile, decode, read_source


def norm(path: str | Path) -> str:
    return os.path.normpath(os.path.abspath(path))


def uri_to_path(uri: str) -> str | None:
    """The local file a ``file:`` URI names, or None for any other URI."""
    try:
        parts = urlparse(uri)
    except ValueError:
        return None
    if parts.scheme != "file":
        return None
    path = unquote(parts.path)
    if os.name == "nt" and len(path) > 2 and path[0] == "/" and path[2] == ":":
        path = path[1:]  # pragma: no cover
    if not path:
        return None
    return norm(path)


def path_to_uri(path: str) -> str:
    return "file://" + quote(Path(path).as_posix(), safe="/:")


@dataclass(slots=True)
class Document:
    uri: str
    path: str
    text: str
    version: int | None = None
    #: every file the last lint of this document read (itself included)
    reads: set[str] = field(default_factory=set)
    #: the files its own nsplug expansion pulled in with ``#include``
    includes: set[str] = field(default_factory=set)


class DiskReads:
    """The files read from disk, kept while they are unchanged: a re-lint reads the
    mission files beside a document again at every edit, and almost all of them
    are as they were.

    A kept read is served while the file's (mtime, ctime, size, inode) are those
    taken just before it was read (any write changes the ctime, even one that
    puts the mtime back); the file is stat'ed at each call, never trusted
    without. Only decoded text is kept, never a read that failed.
    """

    def __init__(self, size: int = 512) -> None:
        self.size = size
        self._lock = threading.Lock()
        self._kept: OrderedDict[str, tuple[tuple[int, int, int, int], SourceFile]] = OrderedDict()

    def read(self, path: Path) -> SourceFile | ReadProblem:
        key = os.fspath(path)
        try:
            st = os.stat(key)
        except OSError:
            return read_source(path)  # (the problem, as the engine reports it)
        stamp = (st.st_mtime_ns, st.st_ctime_ns, st.st_size, st.st_ino)
        with self._lock:
            hit = self._kept.get(key)
            if hit is not None and hit[0] == stamp:
                self._kept.move_to_end(key)
                return hit[1]
        src = read_source(path)
        if isinstance(src, SourceFile):
            with self._lock:
                self._kept[key] = (stamp, src)
                self._kept.move_to_end(key)
                while len(self._kept) > self.size:
                    self._kept.popitem(last=False)
        return src


class MemoryReader:
    """A FileCache reader: ``texts`` (path -> editor text) first, then the disk.

    Every path asked for is added to ``seen``. A document whose text equals the
    file on disk is served from the disk read, which keeps what only the bytes
    tell (the encoding, a byte-order mark). :meth:`in_memory` answers for the
    documents whose text differs from the disk's (the C++ reader asks it).
    """

    def __init__(
        self,
        texts: dict[str, str],
        seen: set[str] | None = None,
        disk: Callable[[Path], SourceFile | ReadProblem] = read_source,
    ) -> None:
        self.texts, self.seen, self.disk = texts, seen, disk

    def __call__(self, path: Path) -> SourceFile | ReadProblem:
        return self.in_memory(path) or self.disk(path)

    def in_memory(self, path: Path) -> SourceFile | ReadProblem | None:
        key = norm(path)
        if self.seen is not None:
            self.seen.add(key)
        text = self.texts.get(key)
        if text is None:
            return None
        on_disk = self.disk(path)
        if isinstance(on_disk, SourceFile) and on_disk.text == text:
            return None
        return decode(text.encode("utf-8", "surrogatepass"), path)


class DocumentStore:
    """Open documents by path. Safe to use from the server thread and lint threads."""

    def __init__(self) -> None:
        self._docs: dict[str, Document] = {}
        self._lock = threading.Lock()

    def open(self, uri: str, text: str, version: int | None = None) -> Document | None:
        path = uri_to_path(uri)
        if path is None:
            return None
        with self._lock:
            doc = self._docs.get(path)
            if doc is None:
                doc = Document(uri, path, text, version)
                self._docs[path] = doc
            else:
                doc.uri, doc.text, doc.version = uri, text, version
            return doc

    def update(self, uri: str, text: str, version: int | None) -> Document | None:
        return self.open(uri, text, version)

    def close(self, uri: str) -> Document | None:
        path = uri_to_path(uri)
        if path is None:
            return None
        with self._lock:
            return self._docs.pop(path, None)

    def get(self, path: str) -> Document | None:
        with self._lock:
            return self._docs.get(norm(path))

    def by_uri(self, uri: str) -> Document | None:
        path = uri_to_path(uri)
        return self.get(path) if path else None

    def texts(self) -> dict[str, str]:
        """A snapshot of every open document's text, by path."""
        with self._lock:
            return {p: d.text for p, d in self._docs.items()}

    def documents(self) -> list[Document]:
        with self._lock:
            return list(self._docs.values())

    def record(self, path: str, reads: set[str], includes: set[str]) -> None:
        with self._lock:
            doc = self._docs.get(path)
            if doc is not None:
                doc.reads, doc.includes = set(reads), set(includes)

    def dependents(self, path: str) -> list[Document]:
        """Other open documents whose last lint read ``path``."""
        key = norm(path)
        with self._lock:
            return [d for p, d in self._docs.items() if p != key and key in d.reads]

    def includers(self, path: str) -> list[str]:
        """Open documents whose own expansion includes ``path``."""
        key = norm(path)
        with self._lock:
            return sorted(p for p, d in self._docs.items() if p != key and key in d.includes)
