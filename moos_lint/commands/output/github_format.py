"""GitHub Actions workflow commands: one ``::error``/``::warning``/``::notice`` per finding.

GitHub shows each as an annotation on the pull request's changed lines. This
format is chosen automatically when ``GITHUB_ACTIONS=true`` and no
``--output-format`` is given.
"""

from __future__ import annotations

from moos_lint.commands.output import display_path
from moos_lint.files.boundary import OUTSIDE_CODE, OUTSIDE_NAME, notes
from moos_lint.files.diagnostics import Severity

COMMANDS = {Severity.ERROR: "error", Severity.WARNING: "warning", Severity.INFO: "notice"}


def escape_data(text: str) -> str:
    """Escape a command's message, as the Actions toolkit does."""
    return text.replace("%", "%25").replace("\r", "%0D").replace("\n", "%0A")


def escape_property(text: str) -> str:
    """Escape a command property value: also ``:`` and ``,``."""
    return escape_data(text).replace(":", "%3A").replace(",", "%2C")


def render(result, cwd: str, **_kw) -> str:
    out = [f"::warning::{escape_data(w)}" for w in result.warnings]
    for d in result.diagnostics:
        s = d.span
        props = [
            ("file", display_path(s.path, cwd).replace("\\", "/")),
            ("line", str(s.line)),
            ("col", str(s.col)),
        ]
        if s.end_line > s.line:
            props.append(("endLine", str(s.end_line)))
        elif s.end_col > s.col:
            props.append(("endColumn", str(s.end_col)))
        props.append(("title", f"{d.code} {d.name}"))
        message = d.message
        for site in reversed(d.chain):
            message += f"\nincluded from {display_path(site.path, cwd)}:{site.line}"
        head = ",".join(f"{k}={escape_property(v)}" for k, v in props)
        out.append(f"::{COMMANDS[d.severity]} {head}::{escape_data(message)}")
    for path, note in notes(result):  # no file= : the file is not in the repository
        text = f"{display_path(path, cwd)}: {note}"
        out.append(f"::notice title={OUTSIDE_CODE} {OUTSIDE_NAME}::{escape_data(text)}")
    return "".join(line + "\n" for line in out)
