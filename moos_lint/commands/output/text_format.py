"""Human-readable output: a header line, the source line with a caret, the include chain."""

from __future__ import annotations

from collections import Counter

from moos_lint.commands.output import inert, shown_path
from moos_lint.commands.output.color import Palette
from moos_lint.files.boundary import notes

TYPE_CHECKING = False  # typing itself is not imported at run time
if TYPE_CHECKING:
    from moos_lint.core.result import Result

MAX_EXCERPT = 160


def _excerpt(text: str, col: int, end_col: int, end_line_same: bool) -> tuple[str, str]:
    text = text.replace("\t", " ")
    start = max(col - 1, 0)
    width = max((end_col - col) if end_line_same else len(text) - start, 1)
    if len(text) > MAX_EXCERPT:
        lo = max(0, start - 40)
        text = ("…" if lo else "") + text[lo : lo + MAX_EXCERPT] + "…"
        start = start - lo + (1 if lo else 0)
        width = min(width, MAX_EXCERPT - start + 1)
    return text, " " * start + "^" * max(1, min(width, len(text) - start if text else 1))


def render(
    result: Result,
    cwd: str,
    *,
    statistics: bool = False,
    quiet: bool = False,
    color: bool = False,
    **_kw,
) -> str:
    out: list[str] = []
    pal = Palette(color)
    for d in result.diagnostics:
        s = d.span
        where = pal.location(shown_path(s.path, cwd), s.line, s.col)
        out.append(f"{where} {pal.code(d.code)} [{d.name}] {inert(d.message)}")
        src = result.sources.get(s.path)
        if src is not None and 1 <= s.line <= len(src.lines):
            text, caret = _excerpt(src.lines[s.line - 1], s.col, s.end_col, s.end_line == s.line)
            num = str(s.line)
            pad = " " * len(num)
            bar = pal.gutter("|")
            out.append(f"  {pad} {bar}")
            out.append(f"  {pal.gutter(num)} {bar} {text}")
            out.append(f"  {pad} {bar} {pal.caret(caret)}")
        for site in reversed(d.chain):
            out.append(f"  = included from {shown_path(site.path, cwd)}:{site.line}")
        out.append("")
    for path, note in notes(result):
        out.append(f"note: {shown_path(path, cwd)}: {note}")
    if statistics:
        counts = Counter((d.code, d.name) for d in result.diagnostics)
        for (code, name), n in sorted(counts.items(), key=lambda kv: (-kv[1], kv[0])):
            out.append(f"{n:6d}  {code}  {name}")
    if not quiet:
        n = len(result.diagnostics)
        files = len(result.files)
        if n:
            out.append(f"Found {n} finding{'s' if n != 1 else ''} in {files} file(s).")
        else:
            out.append(f"All checks passed ({files} file(s)).")
        hidden = result.baselined
        if hidden:
            out.append(f"{hidden} older finding(s) hidden by the baseline.")
    return "\n".join(out) + ("\n" if out else "")
