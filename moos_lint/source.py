"""Reading files from disk the way a linter must: safely, and never blocking.

Only regular files are read (never a FIFO, a device or a directory), text is
decoded as UTF-8 with a latin-1 fallback, and every failure becomes a
:class:`ReadProblem` instead of an exception.
"""

from __future__ import annotations

import os
import stat
from dataclasses import dataclass, field
from pathlib import Path

#: Files larger than this are not read at all (a mission file is a few KB).
MAX_FILE_BYTES = 64 * 1024 * 1024


@dataclass(slots=True)
class ReadProblem:
    """Why a file could not be read as text."""

    kind: str  # "unreadable" | "not-text" | "not-regular" | "too-large"
    message: str


@dataclass(slots=True)
class SourceFile:
    """One file's text, split into lines, with how it was decoded."""

    path: str | Path
    text: str
    encoding: str = "utf-8"
    bom: bool = False
    newline: str = "\n"
    lines: list[str] = field(default_factory=list)

    # A stored result (the cache) keeps the text only: the lines are split again on first use.
    def __getstate__(self) -> tuple:
        lines = None if self.lines == split_lines(self.text) else self.lines
        return (self.path, self.text, self.encoding, self.bom, self.newline, lines)

    def __setstate__(self, state: tuple) -> None:
        self.path, self.text, self.encoding, self.bom, self.newline, lines = state
        if lines is not None:
            self.lines = lines

    def __getattr__(self, name: str):
        if name == "lines":  # not restored yet
            self.lines = split_lines(self.text)
            return self.lines
        raise AttributeError(name)

    def line(self, lineno: int) -> str:
        """The text of 1-based line ``lineno`` ('' when out of range)."""
        if 1 <= lineno <= len(self.lines):
            return self.lines[lineno - 1]
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
        lines=split_lines(text),
    )


def read_source(path: str | Path) -> SourceFile | ReadProblem:
    """Read a regular file as text without ever blocking or raising."""
    data = read_bytes(path)
    if isinstance(data, ReadProblem):
        return data
    return decode(data, path)


def read_bytes(path: str | Path) -> bytes | ReadProblem:
    """Read a regular file's bytes without ever blocking or raising."""
    try:
        st = os.stat(path)
    except OSError as exc:
        return ReadProblem("unreadable", f"cannot read file: {exc.strerror or exc}")
    if stat.S_ISDIR(st.st_mode):
        return ReadProblem("not-regular", "is a directory, not a file")
    if not stat.S_ISREG(st.st_mode):
        return ReadProblem(
            "not-regular", "is not a regular file (device, FIFO or socket): not read"
        )
    if st.st_size > MAX_FILE_BYTES:
        return ReadProblem(
            "too-large", f"file is {st.st_size} bytes, over the {MAX_FILE_BYTES} byte limit"
        )
    try:
        # O_NONBLOCK guards against a file replaced by a FIFO after the stat.
        fd = os.open(path, os.O_RDONLY | getattr(os, "O_NONBLOCK", 0))
    except OSError as exc:
        return ReadProblem("unreadable", f"cannot read file: {exc.strerror or exc}")
    try:
        st = os.fstat(fd)
        if not stat.S_ISREG(st.st_mode):
            return ReadProblem("not-regular", "is not a regular file: not read")
        # os.read, not a file object: most files come in one call, as large as the file
        chunks = []
        left = MAX_FILE_BYTES + 1
        while left > 0:
            chunk = os.read(fd, min(left, max(st.st_size + 1, 65536)))
            if not chunk:
                break
            chunks.append(chunk)
            left -= len(chunk)
    except OSError as exc:
        return ReadProblem("unreadable", f"cannot read file: {exc.strerror or exc}")
    finally:
        os.close(fd)
    return chunks[0] if len(chunks) == 1 else b"".join(chunks)
