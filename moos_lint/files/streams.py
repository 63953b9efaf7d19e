"""Writing a report to standard output, whatever the names of the files it shows.

A file name that is not UTF-8 reaches Python as a string with lone surrogates
(``os.fsdecode``); printing it as text would fail. It is written as the bytes
the file system holds, as ``ls`` shows it. Only ``sys`` is imported: the replay
of an unchanged run uses this before anything else loads.
"""

from __future__ import annotations

import sys


def write_stdout(text: str) -> None:
    """Write ``text`` to standard output; file names that are not UTF-8 as their bytes."""
    out = sys.stdout
    try:
        out.write(text)
        return
    except UnicodeEncodeError:  # (nothing was written: the text is encoded whole first)
        pass
    encoding = out.encoding or "utf-8"
    try:
        data = text.encode(encoding, "surrogateescape")
    except UnicodeEncodeError:  # a terminal whose encoding lacks other characters
        data = text.encode(encoding, "backslashreplace")
    out.flush()
    out.buffer.write(data)
    out.buffer.flush()
