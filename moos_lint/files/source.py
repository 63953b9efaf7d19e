"""Reading files from disk the way a linter must: safely, and never blocking.

Only regular files are read (never a FIFO, a device or a directory), text is
decoded as UTF-8 with a latin-1 fallback, and every failure becomes a
:class:`ReadProblem` instead of an exception.
"""

from __future__ import annotations

import os
import stat
from dataclasses import dataclass
from pathlib import Path

#: Files larger than this are not read at all (a mission file is a few KB).
MAX_FILE_BYTES = 64 * 1024 * 1024


@dataclass(slots=True)
class ReadProblem:
    """Why a file could not be read as text."""

    kind: str  # "unreadable" | "not-text" | "not-regular" | "too-large"
    message: str


class SourceFile:
    """One file's text, split into lines on first use, with how it was decoded.

    The lines are split only when something reads them: most C++ files a run reads
    are only searched and parsed as a whole, and their lines would double the
    memory their text takes.
    """

    __slots__ = ("_lines", "bom", "encoding", "newline", "path", "text")

    def __init__(
        self,
        path: str | Path,
        text: str,
        encoding: str = "utf-8",
        bom: bool = False,
        newline: str = "\n",
        lines: list[str] | None = None,
    ):
        self.path = path
        self.text = text
        self.encoding = encoding
        self.bom = bom
        self.newline = newline
        self._lines = lines

    @property
    def lines(self) -> list[str]:
        if self._lines is None:
            self._lines = split_lines(self.text)
        return self._lines

    @lines.setter
    def lines(self, value: list[str]) -> None:
        self._lines = value

    def _fields(self) -> tuple:
        return (self.path, self.text, self.encoding, self.bom, self.newline, self.lines)

    def __eq__(self, other: object) -> bool:
        if not isinstance(other, SourceFile):
            return NotImplemented
        return self._fields() == other._fields()

    # mutable, as a dataclass would be: never a dict key
    __hash__ = None  # type: ignore[assignment]

    def __repr__(self) -> str:
        return f"SourceFile(path={self.path!r}, encoding={self.encoding!r}, {len(self.text)} chars)"

    # A stored result (the cache) keeps the text only: the lines are split again on first use.
    def __getstate__(self) -> tuple:
        lines = self._lines
        if lines is not None and lines == split_lines(self.text):
            lines = None
        return (self.path, self.text, self.encoding, self.bom, self.newline, lines)

    def __setstate__(self, state: tuple) -> None:
        self.path, self.text, self.encoding, self.bom, self.newline, self._lines = state

    def line(self, lineno: int) -> str:
        """The text of 1-based line ``lineno`` ('' when out of range)."""
        lines = self.lines
        if 1 <= lineno <= len(lines):
            return lines[lineno - 1]
        return ""


def split_lines(text: str) -> list[str]:
    """Split like MOOS readers do: on LF, CRLF or a bare CR; no line ends kept."""
    if "\r" in text:
        text = text.replace("\r\n", "\n").replace("\r", "\n")
    lines = text.split("\n")
    if lines and lines[-1] == "":
        lines.pop()
    return lines


def _newline_of(text: str) -> str:
    if "\r\n" in text:
        return "\r\n"
    if "\r" in text:
        return "\r"
    return "\n"


def decode(data: bytes, path: str | Path) -> SourceFile | ReadProblem:
    """Decode bytes as a text file, or say why they are not text."""
    if b"\x00" in data[:8192] or b"\x00" in data:
        return ReadProblem("not-text", "file contains NUL bytes: it is binary, not a text file")
    bom = data.startswith(b"\xef\xbb\xbf")
    if bom:
        data = data[3:]
    try:
        text = data.decode("utf-8")
        encoding = "utf-8"
    except UnicodeDecodeError:
        text = data.decode("latin-1")
        encoding = "latin-1"
    return SourceFile(
        path=path,
        text=text,
        encoding=encoding,
        bom=bom,
        newline=_newline_of(text),
    )


def read_source(path: str | Path) -> SourceFile | ReadProblem:
    """Read a regular file as text without ever blocking or raising."""
    data = read_bytes(path)
    if isinstance(data, ReadProblem):
        return data
    return decode(data, path)


#: the journal of reads, while one is kept (see :func:`keep_journal`)
_journal: dict[str, tuple[tuple[int, int] | None, str]] | None = None


def keep_journal() -> None:
    """Note every file read from now on: its (mtime, size) just before the read and a
    hash of the bytes read (see :func:`content_digest`). The result cache stores a
    result with what its files were when they were read, not when it is stored."""
    global _journal
    _journal = {}


def take_journal() -> dict[str, tuple[tuple[int, int] | None, str]]:
    """The reads noted since :func:`keep_journal` (and stop noting)."""
    global _journal
    out, _journal = _journal or {}, None
    return out


def journal_size() -> int:
    """How many reads are noted so far (0 when no journal is kept)."""
    return 0 if _journal is None else len(_journal)


def journal_since(size: int) -> list[tuple[str, tuple[tuple[int, int] | None, str]]]:
    """The reads noted after the first ``size`` (a forked worker sends them back)."""
    if _journal is None:
        return []
    return list(_journal.items())[size:]


def merge_journal(entries: list[tuple[str, tuple[tuple[int, int] | None, str]]]) -> None:
    """Add the reads a worker process noted (the first read of a file wins)."""
    if _journal is not None:
        for path, noted in entries:
            _journal.setdefault(path, noted)


def content_digest(data: bytes | ReadProblem) -> str:
    """A hash of a file's bytes; for a file that could not be read, why it could not."""
    if not isinstance(data, bytes):
        return f"unread:{data.kind}"
    from hashlib import blake2b

    return blake2b(data, digest_size=20).hexdigest()


def digest_now(path: str | Path) -> str:
    """:func:`content_digest` of the file as it is now (not noted in the journal)."""
    return content_digest(_read_bytes(Path(path))[0])


def read_bytes(path: str | Path) -> bytes | ReadProblem:
    """Read a regular file's bytes without ever blocking or raising (noted in the
    journal, when one is kept)."""
    data, stamp = _read_bytes(path)
    if _journal is not None:
        key = os.fspath(path)
        if key not in _journal:  # the first read is the one the result is made of
            _journal[key] = (stamp, content_digest(data))
    return data


def read_head(path: str | Path, limit: int) -> bytes | None:
    """Up to ``limit`` bytes of a regular file, never blocking or raising; None for what
    is not a readable regular file (a FIFO or a device under a MOOS file's name, a
    folder). For the files read to learn something about others (launch scripts, ignore
    files, a template's kind), which are not linted themselves: not journaled."""
    try:
        fd = os.open(path, os.O_RDONLY | getattr(os, "O_NONBLOCK", 0))
    except OSError:
        return None
    try:
        if not stat.S_ISREG(os.fstat(fd).st_mode):
            return None
        chunks = []
        left = limit
        while left > 0:
            chunk = os.read(fd, min(left, 1 << 20))
            if not chunk:
                break
            chunks.append(chunk)
            left -= len(chunk)
        return b"".join(chunks)
    except OSError:
        return None
    finally:
        os.close(fd)


def _read_bytes(path: str | Path) -> tuple[bytes | ReadProblem, tuple[int, int] | None]:
    """The bytes (or the problem) and the file's (mtime, size) just before they were read.

    The file is judged by ``stat`` before it is opened: what is not a regular file (a
    device under a MOOS file's name) is never opened."""
    try:
        st = os.stat(path)
    except OSError as exc:
        return ReadProblem("unreadable", f"cannot read file: {exc.strerror or exc}"), None
    stamp = (st.st_mtime_ns, st.st_size)
    if stat.S_ISDIR(st.st_mode):
        return ReadProblem("not-regular", "is a directory, not a file"), stamp
    if not stat.S_ISREG(st.st_mode):
        why = "is not a regular file (device, FIFO or socket): not read"
        return ReadProblem("not-regular", why), stamp
    if st.st_size > MAX_FILE_BYTES:
        why = f"file is {st.st_size} bytes, over the {MAX_FILE_BYTES} byte limit"
        return ReadProblem("too-large", why), stamp
    try:
        # O_NONBLOCK guards against a file replaced by a FIFO after the stat.
        fd = os.open(path, os.O_RDONLY | getattr(os, "O_NONBLOCK", 0))
    except OSError as exc:
        return ReadProblem("unreadable", f"cannot read file: {exc.strerror or exc}"), stamp
    try:
        # os.read, not a file object. One byte more than the size is asked for: a
        # shorter answer is the whole file, and no call is needed to see its end (a
        # lint reads thousands of files). A file replaced by a FIFO since the stat
        # reads as empty (O_NONBLOCK); the stamp is the stat's.
        want = st.st_size + 1
        first = os.read(fd, want)
        if len(first) < want:
            return first, stamp
        chunks = [first]  # the file grew since the stat
        left = MAX_FILE_BYTES + 1 - len(first)
        while left > 0:
            chunk = os.read(fd, min(left, 1 << 20))
            if not chunk:
                break
            chunks.append(chunk)
            left -= len(chunk)
    except OSError as exc:
        return ReadProblem("unreadable", f"cannot read file: {exc.strerror or exc}"), stamp
    finally:
        os.close(fd)
    return b"".join(chunks), stamp
