"""Property-based fuzzing of the readers, the nsplug preprocessor and the rules.

Inputs: random text built from MOOS, nsplug and behavior-file tokens; small
random projects whose files include each other (loops, tags, missing files);
mutations of the project's fixtures; and mutations of the real MOOS-IvP files
in ``../shared/corpus/moos-ivp`` beside the repository, when they are there.

Invariants: no exception escapes and no rule crashes (no internal error);
every finding and include site lies inside its file (line 1..number of lines,
or 1 for an empty or unread file; columns within the line); every output
format renders; linting the same input twice gives the same findings.

The normal test run uses a bounded, derandomized profile (a few thousand
examples). ``MOOS_LINT_FUZZ=long`` selects the long profile (random seeds,
50 times the examples, over 100,000 in all); see README, "Fuzzing".
"""

from __future__ import annotations

import os
import tempfile
from pathlib import Path

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from moos_lint.commands.output import FORMATS, render
from moos_lint.core.config import Settings
from moos_lint.core.engine import INTERNAL_ERROR, Result, lint_files
from moos_lint.files.diagnostics import Diagnostic
from moos_lint.files.source import SourceFile, decode
from moos_lint.frontends.nsplug import Preprocessor, expand_text
from tests.fixture_expect import FIXTURES, LINTED_SUFFIXES

LONG = os.environ.get("MOOS_LINT_FUZZ", "") == "long"
SCALE = 50 if LONG else 1
CORPUS = Path(__file__).resolve().parents[2] / "shared" / "corpus" / "moos-ivp"
_HEALTH = [HealthCheck.too_slow, HealthCheck.data_too_large, HealthCheck.filter_too_much]

settings.register_profile(
    "moos-lint-bounded",
    deadline=None,
    derandomize=True,  # the same examples on every run: the normal suite stays deterministic
    database=None,
    print_blob=True,
    suppress_health_check=_HEALTH,
)
settings.register_profile(
    "moos-lint-long",
    deadline=None,
    database=None,
    print_blob=True,
    suppress_health_check=_HEALTH,
)
PROFILE = settings.get_profile("moos-lint-long" if LONG else "moos-lint-bounded")


def budget(n: int) -> settings:
    """``n`` examples in the bounded profile, ``n * SCALE`` in the long one."""
    return settings(PROFILE, max_examples=n * SCALE)


# ---------------------------------------------------------------- strategies
TOKENS = [
    "#include ",
    "#include a.plug",
    "#include b.plug <tag1>",
    "#include m.moos",
    "#include $(PLUG)",
    '#include "a.plug"',
    "#define ",
    "#define PLUG a.plug",
    "#ifdef ",
    "#ifdef VNAME abe",
    "#ifndef ",
    "#elseifdef ",
    "#else",
    "#endif",
    "<tag><tag1>",
    "<tag>",
    "ProcessConfig = ",
    "ProcessConfig = ANTLER",
    "ProcessConfig = pHelmIvP {",
    "Run = ",
    "Run = pLogger @ NewConsole = false ~ pLog",
    "ServerPort = 9000",
    "Community = $(VNAME)",
    "LatOrigin = 43.825",
    "NAV_HEADING = ",
    "Behavior = BHV_Waypoint",
    "Behavior = ",
    "set MODE = ACTIVE",
    "initialize DEPLOY = false",
    "initialize_ ",
    "condition = ",
    "endflag = ",
    "polygon = 0,0:10,0",
    "{",
    "}",
    "=",
    "//",
    "// moos-lint: ignore[ALL]",
    "// moos-lint: disable[R]",
    "// moos-lint: enable[R]",
    "// moos-lint: file-ignore[",
    "$(",
    "%(",
    "$(VNAME)",
    "$(X=1)",
    "$(X:=)",
    ")",
    "(",
    "[",
    "]",
    '"',
    "\\",
    "@",
    "~",
    ",",
    ":",
    "||",
    "&&",
    "#",
    "é",
    "\u200b",
    "\t",
    " ",
    "  ",
    "\n",
    "\r\n",
    "\r",
]
BYTE_TOKENS = [t.encode("utf-8") for t in TOKENS] + [b"\x00", b"\xff", b"\xe9", b"\xef\xbb\xbf"]

token_text = st.lists(st.sampled_from(TOKENS) | st.text(max_size=6), max_size=60).map("".join)
line_text = st.lists(st.sampled_from(TOKENS) | st.text(max_size=8), max_size=6).map("".join)
file_text = st.lists(line_text, max_size=25).map("\n".join)
raw_bytes = st.lists(st.sampled_from(BYTE_TOKENS) | st.binary(max_size=8), max_size=60).map(
    b"".join
)
#: each example renders its findings in one output format; together they cover them all
formats = st.sampled_from(FORMATS)
NAMES = ("m.moos", "a.plug", "b.plug", "c.bhv", "d.def")


@st.composite
def projects(draw) -> dict[str, bytes]:
    """A few files that may include each other, possibly with bad bytes or line ends."""
    files: dict[str, bytes] = {}
    for name in draw(st.lists(st.sampled_from(NAMES), min_size=1, max_size=4, unique=True)):
        text = draw(file_text)
        data = text.encode("utf-8")
        if draw(st.booleans()):
            data = draw(raw_bytes) + data
        files[name] = data
    return files


@st.composite
def mutations(draw, data: bytes) -> bytes:
    """``data`` after a few random edits: inserts, deletes, duplicated or swapped lines."""
    for _ in range(draw(st.integers(1, 6))):
        n = len(data)
        at = draw(st.integers(0, n))
        op = draw(st.sampled_from(("insert", "delete", "dup-line", "swap-lines", "truncate")))
        if op == "insert":
            data = (
                data[:at] + draw(st.sampled_from(BYTE_TOKENS) | st.binary(max_size=4)) + data[at:]
            )
        elif op == "delete":
            data = data[:at] + data[at + draw(st.integers(1, 40)) :]
        elif op == "truncate":
            data = data[:at]
        else:
            lines = data.split(b"\n")
            i = draw(st.integers(0, len(lines) - 1))
            j = draw(st.integers(0, len(lines) - 1))
            if op == "dup-line":
                lines.insert(j, lines[i])
            else:
                lines[i], lines[j] = lines[j], lines[i]
            data = b"\n".join(lines)
    return data


def _files(root: Path, limit: int | None = None) -> list[Path]:
    if not root.is_dir():
        return []
    found = sorted(
        p
        for p in root.rglob("*")
        if p.is_file() and p.name.lower().endswith(LINTED_SUFFIXES) and p.stat().st_size < 200_000
    )
    return found[:limit] if limit else found


FIXTURE_FILES = [p for p in _files(FIXTURES) if "bad-input" not in p.parts]
CORPUS_FILES = _files(CORPUS)


# ---------------------------------------------------------------- invariants
def _lines(result: Result, path: str) -> list[str] | None:
    src = result.sources.get(path)
    return src.lines if src is not None else None


def _check_span(result: Result, d: Diagnostic, linted: set[str]) -> None:
    s = d.span
    lines = _lines(result, s.path)
    if lines is None:  # a file that could not be read: only line 1
        assert s.path in linted, d
        assert (s.line, s.end_line) == (1, 1), d
        return
    n = max(1, len(lines))
    assert 1 <= s.line <= s.end_line <= n, (d, n)
    text = lines[s.line - 1] if lines else ""
    assert 1 <= s.col <= len(text) + 1, (d, len(text))
    end_text = lines[s.end_line - 1] if lines else ""
    assert 1 <= s.end_col <= len(end_text) + 1, (d, len(end_text))
    if s.end_line == s.line:
        assert s.col <= s.end_col, d
    for site in d.chain:
        site_lines = _lines(result, site.path)
        assert site_lines is not None and 1 <= site.line <= len(site_lines), d
    if d.fix is not None:
        for edit in d.fix.edits:
            e = edit.span
            edit_lines = _lines(result, e.path)
            assert edit_lines is not None and 1 <= e.line <= len(edit_lines), d
            assert 1 <= e.col <= len(edit_lines[e.line - 1]) + 1, d
            if e.end_line == len(edit_lines) + 1:  # deleting the last line whole
                assert e.end_col == 1, d
            else:
                assert e.line <= e.end_line <= len(edit_lines), d
                assert 1 <= e.end_col <= len(edit_lines[e.end_line - 1]) + 1, d
            assert (e.line, e.col) <= (e.end_line, e.end_col), d


def _digest(result: Result) -> list[tuple]:
    return [(d.code, d.span, d.message, d.chain, d.fix, d.severity) for d in result.diagnostics]


def lint_and_check(
    root: Path, names: list[str], fmt: str, include_paths: list[str] | None = None
) -> Result:
    """Lint ``names`` under ``root`` twice with every rule on; check the invariants."""
    files = [str(root / n) for n in names]

    def once() -> Result:
        s = Settings(root=str(root), select=["ALL"], include_paths=list(include_paths or []))
        return lint_files(files, s)

    result = once()
    crashes = [d.message for d in result.diagnostics if d.code == INTERNAL_ERROR]
    assert result.internal_errors == 0 and not crashes, crashes
    linted = set(files)
    for d in result.diagnostics:
        _check_span(result, d, linted)
    assert isinstance(render(fmt, result, cwd=str(root)), str)
    assert _digest(once()) == _digest(result), "linting the same input twice differs"
    return result


def write_project(root: Path, files: dict[str, bytes]) -> list[str]:
    for name, data in files.items():
        (root / name).write_bytes(data)
    return sorted(files)


# ---------------------------------------------------------------- properties
@budget(300)
@given(text=token_text)
def test_preprocessor_on_random_text(text):
    """Both nsplug modes on one file of random tokens; the source map stays in the file."""
    with tempfile.TemporaryDirectory() as tmp:
        path = Path(tmp) / "m.moos"
        path.write_text(text, encoding="utf-8", newline="")
        src = decode(path.read_bytes(), path)
        for mode in ("lint", "nsplug"):
            pre = Preprocessor(mode=mode, defines={"VNAME": "abe"})
            exp = pre.expand(path)
            if not isinstance(src, SourceFile):  # binary: reported, never expanded
                assert exp.read_problem is not None and exp.lines == []
                continue
            n = len(src.lines)
            assert isinstance(expand_text(exp), str)
            for line in exp.lines:
                assert 1 <= line.lineno <= n
                s = line.span()
                assert 1 <= s.col <= s.end_col <= len(src.lines[s.line - 1]) + 1
            for prob in exp.problems:
                assert 1 <= prob.span.line <= max(n, 1)


@budget(400)
@given(text=file_text, fmt=formats)
def test_mission_reader_and_rules_on_random_text(text, fmt):
    with tempfile.TemporaryDirectory() as tmp:
        root = Path(tmp)
        (root / "m.moos").write_text(text, encoding="utf-8", newline="")
        (root / "c.bhv").write_text(text, encoding="utf-8", newline="")
        lint_and_check(root, ["c.bhv", "m.moos"], fmt)


@budget(500)
@given(files=projects(), fmt=formats)
def test_random_projects_with_includes(files, fmt):
    with tempfile.TemporaryDirectory() as tmp:
        root = Path(tmp)
        lint_and_check(root, write_project(root, files), fmt)


@budget(300)
@given(data=raw_bytes, fmt=formats)
def test_random_bytes(data, fmt):
    with tempfile.TemporaryDirectory() as tmp:
        root = Path(tmp)
        lint_and_check(root, write_project(root, {"m.moos": data, "c.bhv": data}), fmt)


@st.composite
def mutated_file(draw, pool: list[Path]) -> tuple[Path, bytes, str]:
    path = draw(st.sampled_from(pool))
    return path, draw(mutations(path.read_bytes())), draw(formats)


def _lint_mutated(path: Path, data: bytes, fmt: str) -> None:
    """The mutated file stands in for the original: its includes still find the originals."""
    with tempfile.TemporaryDirectory() as tmp:
        root = Path(tmp)
        (root / path.name).write_bytes(data)
        lint_and_check(root, [path.name], fmt, include_paths=[str(path.parent)])


@pytest.mark.skipif(not FIXTURE_FILES, reason="no fixtures")
@budget(500)
@given(case=mutated_file(FIXTURE_FILES))
def test_mutated_fixtures(case):
    _lint_mutated(*case)


@pytest.mark.skipif(not CORPUS_FILES, reason="the MOOS-IvP corpus is not beside the repository")
@budget(200)
@given(case=mutated_file(CORPUS_FILES or [Path(__file__)]))
def test_mutated_corpus_files(case):
    _lint_mutated(*case)


# ---------------------------------------------------------------- C++
CPP_TOKENS = [
    '#include "MOOS/libMOOS/MOOSLib.h"\n',
    "class App : public CMOOSApp {\n",
    "class Inst : public AppCastingMOOSInstrument {\n",
    "bool App::OnNewMail(MOOSMSG_LIST &NewMail) {\n",
    "bool App::OnStartUp() {\n",
    "bool App::Iterate() {\n",
    "for(p = NewMail.begin(); p != NewMail.end(); p++) {\n",
    "CMOOSMsg &msg = *p;\n",
    'if(msg.GetKey() == "NAV_HEADING")',
    "string key = msg.GetKey();\n",
    "m_heading = msg.GetDouble();\n",
    'Register("NAV_X", 0);\n',
    'Notify("DESIRED_HEADING", ',
    'Notify("NAV_YAW", ',
    'Notify("NAV_Z", ',
    'Notify("NAV_LAT", ',
    "Notify(m_prefix + ",
    'm_MissionReader.GetConfigurationParam("speed", m_speed);\n',
    "CMOOSSerialPort m_port;\n",
    "int main(int argc, char *argv[]) {\n",
    "App app; app.Run(",
    "angle360(",
    "angle180(",
    "degToRadians(",
    "radToDegrees(",
    "M_PI",
    "180",
    "* M_PI / 180.0",
    "-m_heading",
    "m_depth",
    "#if 0\n",
    "#else\n",
    "#endif\n",
    '#define NAME "pApp"\n',
    "template<typename T>",
    "::",
    "{",
    "}",
    "(",
    ")",
    ";",
    ",",
    "=",
    '"',
    "'",
    "\\",
    "//",
    "/*",
    "*/",
    'R"(',
    ')"',
    "\n",
    "\t",
    " ",
]
cpp_text = st.lists(st.sampled_from(CPP_TOKENS) | st.text(max_size=4), max_size=80).map("".join)


@budget(300)
@given(cpp=cpp_text, header=cpp_text, fmt=formats)
def test_cpp_extraction_on_random_text(cpp, header, fmt):
    """The C++ reader: tree-sitter, the extraction and the C++ rules on random code."""
    with tempfile.TemporaryDirectory() as tmp:
        root = Path(tmp)
        files = {"App.cpp": cpp.encode("utf-8"), "App.h": header.encode("utf-8")}
        lint_and_check(root, write_project(root, files), fmt)
