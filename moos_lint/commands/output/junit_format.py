"""JUnit XML, for CI systems that show test reports (colcon / ament, Jenkins, GitLab).

One ``<testsuite>`` named ``moos-lint``; every linted file is a test case,
``classname`` the file's path. A clean file is a passing case; a file with
findings has one failing case per finding (``name`` = ``CODE:line:col``), so
each finding shows up on its own. A run that found nothing to lint is one
skipped case whose message says so.
"""

from __future__ import annotations

import re
import xml.etree.ElementTree as ET

from moos_lint.commands.output import inert, shown_path
from moos_lint.files.boundary import OUTSIDE_NAME, notes

TYPE_CHECKING = False  # typing itself is not imported at run time
if TYPE_CHECKING:
    from moos_lint.core.result import Result

# Characters XML 1.0 does not allow, even escaped.
_INVALID_XML = re.compile("[\x00-\x08\x0b\x0c\x0e-\x1f\ufffe\uffff\ud800-\udfff]")


def _clean(text: str) -> str:
    return _INVALID_XML.sub("\ufffd", text)


def render(result: Result, cwd: str, **_kw) -> str:
    by_file: dict[str, list] = {}
    for path in result.files:
        by_file.setdefault(path, [])
    for d in result.diagnostics:
        by_file.setdefault(d.span.path, []).append(d)
    n_fail = len(result.diagnostics)
    boundary_notes = notes(result)
    n_skipped = len(boundary_notes) + len(result.warnings)
    n_tests = sum(max(len(v), 1) for v in by_file.values()) + n_skipped
    suites = ET.Element(
        "testsuites", name="moos-lint", tests=str(n_tests), failures=str(n_fail), errors="0"
    )
    suite = ET.SubElement(
        suites,
        "testsuite",
        name="moos-lint",
        tests=str(n_tests),
        failures=str(n_fail),
        errors="0",
        skipped=str(n_skipped),
        time="0",
    )
    for w in result.warnings:  # (nothing was linted: a skipped case says why)
        case = ET.SubElement(suite, "testcase", classname="moos-lint", name="moos-lint", time="0")
        ET.SubElement(case, "skipped", message=_clean(w))
    for path in sorted(by_file):
        shown = _clean(shown_path(path, cwd))
        diags = by_file[path]
        if not diags:
            ET.SubElement(suite, "testcase", classname=shown, name="moos-lint", time="0")
            continue
        for d in diags:
            s = d.span
            case = ET.SubElement(
                suite,
                "testcase",
                classname=shown,
                name=f"{d.code}:{s.line}:{s.col}",
                file=shown,
                line=str(s.line),
                time="0",
            )
            failure = ET.SubElement(
                case,
                "failure",
                message=_clean(f"{d.code} [{d.name}] {d.message}"),
                type=d.severity.value,
            )
            body = [f"{shown}:{s.line}:{s.col}: {d.code} [{d.name}] {inert(d.message)}"]
            body += [f"included from {shown_path(c.path, cwd)}:{c.line}" for c in d.chain]
            failure.text = _clean("\n".join(body))
    for path, note in boundary_notes:  # a file outside the project: not shown
        shown = _clean(shown_path(path, cwd))
        case = ET.SubElement(suite, "testcase", classname=shown, name=OUTSIDE_NAME, time="0")
        ET.SubElement(case, "skipped", message=_clean(note))
    ET.indent(suites)
    return '<?xml version="1.0" encoding="UTF-8"?>\n' + ET.tostring(suites, "unicode") + "\n"
