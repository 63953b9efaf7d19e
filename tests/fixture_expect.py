"""Read the expectations written inside fixture files.

A fire fixture marks each line where a finding is expected:

    Run = pShare ~ ShareA       // expect: R010
    // expect+1: P006
    #ifdef VNAME abe // c

``expect: CODE`` is for its own line; ``expect+N: CODE`` for the line N below.
A file that cannot carry comments (binary data) has a sidecar ``NAME.expect``
holding ``LINE CODE`` lines. Files whose name starts with ``_`` are only
included by other fixtures, never linted on their own.
"""

from __future__ import annotations

import re
from pathlib import Path

FIXTURES = Path(__file__).resolve().parent.parent / "fixtures"
RULE_FIXTURES = FIXTURES / "rules"
_MARK = re.compile(r"expect(?:\+(\d+))?:\s*([A-Z][0-9]{3}(?:\s*,\s*[A-Z][0-9]{3})*)")
LINTED_SUFFIXES = (".moos", ".moos++", ".plug", ".def", ".bhv", ".cpp", ".cc", ".cxx", ".h", ".hpp")


def expectations(folder: Path) -> set[tuple[str, int, str]]:
    """Every (path, line, code) expected by the files under ``folder``."""
    out: set[tuple[str, int, str]] = set()
    for path in sorted(folder.rglob("*")):
        if not path.is_file():
            continue
        if path.suffix == ".expect":
            target = path.with_suffix("")
            for row in path.read_text(encoding="utf-8").split("\n"):
                if row.strip():
                    line, code = row.split()
                    out.add((str(target), int(line), code))
            continue
        data = path.read_bytes()
        if b"\x00" in data:
            continue
        for i, text in enumerate(data.decode("utf-8", "replace").splitlines(), 1):
            for m in _MARK.finditer(text):
                offset = int(m.group(1) or 0)
                for code in m.group(2).split(","):
                    out.add((str(path), i + offset, code.strip()))
    return out


def linted_files(folder: Path) -> list[Path]:
    return sorted(
        p
        for p in folder.rglob("*")
        if (p.is_file() or p.is_dir())
        and p.name.lower().endswith(LINTED_SUFFIXES)
        and not p.name.startswith("_")
        and not any(part.startswith("_") for part in p.relative_to(folder).parts[:-1])
    )
