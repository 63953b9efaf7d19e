"""Concise output: one line per finding, ``path:line:col: CODE [name] message``."""

from __future__ import annotations

from collections import Counter

from moos_lint.commands.output import shown_path
from moos_lint.commands.output.color import Palette
from moos_lint.files.boundary import notes


def render(result, cwd: str, *, statistics: bool = False, color: bool = False, **_kw) -> str:
    pal = Palette(color)
    out = [
        f"{pal.location(shown_path(d.span.path, cwd), d.span.line, d.span.col)} "
        f"{pal.code(d.code)} [{d.name}] {_one_line(d.message)}"
        for d in result.diagnostics
    ]
    out += [f"note: {shown_path(path, cwd)}: {note}" for path, note in notes(result)]
    if statistics:
        counts = Counter((d.code, d.name) for d in result.diagnostics)
        for (code, name), n in sorted(counts.items(), key=lambda kv: (-kv[1], kv[0])):
            out.append(f"{n:6d}  {code}  {name}")
    return "".join(line + "\n" for line in out)


def _one_line(text: str) -> str:
    return " ".join(text.split()) if ("\n" in text or "\r" in text) else text
