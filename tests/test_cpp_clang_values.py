"""libclang sharpening the value analysis: ``#ifdef`` as compiled, constants, types.

The apps are in ``fixtures/cpp/clang_values`` (see its README); each test writes
their ``compile_commands.json`` and compares what ``--cpp-backend clang`` reports
with what tree-sitter alone does.
"""

from __future__ import annotations

import json
from pathlib import Path

import pytest

pytest.importorskip("tree_sitter")

from moos_lint.core.config import Settings
from moos_lint.core.engine import lint_files
from tests.test_cpp_clang import require_libclang

ROOT = Path(__file__).resolve().parent.parent / "fixtures" / "cpp" / "clang_values"
FILES = sorted(str(p) for p in ROOT.rglob("*") if p.suffix in (".cpp", ".h"))
APPS = (
    ("iCompass", "Compass.cpp"),
    ("iAttitude", "Attitude.cpp"),
    ("iTypes", "Types.cpp"),
    ("lib_filter", "Filter.cpp"),
)
RULES = ["yaw-in-degrees", "angle-in-degrees", "yaw-heading-sign", "angle-not-wrapped"]
SCALE = "-DOUTPUT_SCALE=57.29577951"  # a conversion factor given by the build


def _db(tmp_path: Path, *flags: str, include: str = "-I../common") -> Path:
    entries = [
        {
            "directory": str(ROOT / app),
            "file": str(ROOT / app / src),
            "arguments": [
                *("c++", "-std=c++17", include, "-I../lib_filter", "-I."),
                *(*flags, "-c", src, "-o", "x.o"),
            ],
        }
        for app, src in APPS
    ]
    (tmp_path / "compile_commands.json").write_text(json.dumps(entries))
    return tmp_path


def _lint(backend: str, db: Path | None = None, rules: list[str] = RULES):
    settings = Settings(root=str(ROOT), cpp_backend=backend)
    settings.compile_commands = str(db) if db else None
    settings.select = rules
    return lint_files(FILES, settings)


def _found(result) -> list[tuple[str, int, str]]:
    return [
        (f"{Path(d.span.path).parent.name}/{Path(d.span.path).name}", d.span.line, d.code)
        for d in result.diagnostics
    ]


def _app(result, folder: str):
    return next(u.cpp for u in result.units if u.cpp is not None and u.cpp.folder.endswith(folder))


@pytest.fixture
def clang(tmp_path):
    """Skip where libclang or the system headers are missing."""
    require_libclang()
    result = _lint("clang", _db(tmp_path, SCALE))
    if _app(result, "iCompass").backend != "clang":
        pytest.skip("no system C++ headers for libclang")
    return result


TREE_SITTER = [
    ("iCompass/Compass.cpp", 10, "U001"),  # both #ifdef branches are read: degrees
    ("iCompass/Compass.cpp", 12, "U001"),  # a debug publication the build leaves out
    ("iTypes/Types.cpp", 8, "U001"),  # a string named `yaw_deg`, taken for an angle
    ("iTypes/Types.cpp", 11, "U003"),
]


def test_tree_sitter_reads_every_branch_and_no_constant_from_elsewhere():
    assert _found(_lint("tree-sitter")) == TREE_SITTER


def test_clang_reads_ifdef_as_compiled(clang, tmp_path):
    found = _found(clang)
    assert not [f for f in found if f[0].startswith("iCompass/")]  # OUTPUT_DEGREES undefined
    compass = _app(clang, "iCompass")
    debug = [p for f in compass.files for p in f.publications if p.name.text == "DEBUG_YAW"]
    assert [p.active for p in debug] == [False]  # compiled out: kept, inactive
    assert "DEBUG_YAW" not in {p.name.text for p in compass.publications}

    defined = _lint("clang", _db(tmp_path, SCALE, "-DOUTPUT_DEGREES"))
    got = [d for d in defined.diagnostics if "iCompass" in d.span.path]
    assert [(d.span.line, d.code) for d in got] == [(10, "U001")]
    assert "yaw * 180 / M_PI at iCompass/Compass.cpp:8" in got[0].message


def test_clang_folds_constants_defined_elsewhere(clang):
    msgs = {d.span.line: d.message for d in clang.diagnostics if "iAttitude" in d.span.path}
    assert sorted(msgs) == [6, 7, 8, 9]  # lines 11-13 stay quiet, and so does 15
    assert "`kRadToDeg` is 180.0 / M_PI, defined at common/Units.h:5" in msgs[6]
    assert "`HALF_TURN_DEG` is 180, defined at common/Units.h:7" in msgs[7]
    assert "`RAD2DEG_FACTOR` is (180.0 / M_PI), defined at common/Units.h:8" in msgs[8]
    assert "`OUTPUT_SCALE` is 57.29577951, defined by a -D flag" in msgs[9]
    assert "degrees per second" in msgs[9]
    pubs = {p.name.text: p.value.abstract for p in _app(clang, "iAttitude").publications}
    assert pubs["ATT_NAV_YAW"].unit == "rad"  # degrees times kDegToRad
    assert pubs["ATT_FILTERED_YAW"].unit is None  # a gain of 2: no conversion
    assert pubs["ATT_DISPLAY_YAW"].unit is None  # not const: never folded


def test_clang_reads_a_library_the_value_flow_reaches_as_compiled(clang, tmp_path):
    """``lib_filter`` never mentions MOOS: its unit is parsed only because
    ``m_filter.yaw()`` is published, and its ``#ifdef`` is read as the database builds it."""
    assert not [d for d in clang.diagnostics if d.span.line == 15]
    built = _lint("clang", _db(tmp_path, SCALE, "-DFILTER_DEGREES"))
    got = [d for d in built.diagnostics if "iAttitude" in d.span.path and d.span.line == 15]
    assert [d.code for d in got] == ["U001"]
    assert "yaw() returns m_yaw * kRadToDeg at lib_filter/Filter.cpp:7" in got[0].message
    assert "defined at common/Units.h:5" in got[0].message


def test_clang_knows_types_and_judges_only_numbers(clang):
    found = [f for f in _found(clang) if f[0].startswith("iTypes/")]
    assert found == [("iTypes/Types.cpp", 11, "U003")]  # the int is judged, the string not
    pubs = {p.name.text: p.value for p in _app(clang, "iTypes").publications}
    assert pubs["TYPES_YAW"].type == "string" and pubs["TYPES_YAW"].abstract is None
    assert pubs["TYPES_PITCH"].type == "integer"
    assert {p.value.type for p in _app(clang, "iAttitude").publications} == {"floating"}


def test_a_unit_libclang_cannot_compile_keeps_the_tree_sitter_reading(clang, tmp_path, capsys):
    """Without the headers (here: the MOOS stand-in) every unit has a fatal error: the
    result is the tree-sitter one, exactly, and libclang's trouble is said once."""
    import moos_lint.frontends.cpp.clang as clang_mod

    clang_mod._warned.clear()
    db = _db(tmp_path, SCALE, include="-Inowhere")
    first = _lint("clang", db, ["ALL"])
    second = _lint("clang", db, ["ALL"])
    plain = _lint("tree-sitter", None, ["ALL"])
    shown = [(d.code, d.span, d.message) for d in plain.diagnostics]
    assert [(d.code, d.span, d.message) for d in first.diagnostics] == shown
    assert [(d.code, d.span, d.message) for d in second.diagnostics] == shown
    assert capsys.readouterr().err.count("headers are missing") == 1
    assert {u.cpp.backend for u in first.units if u.cpp is not None} == {"tree-sitter"}


def test_no_compile_database_keeps_the_tree_sitter_reading(tmp_path, capsys):
    pytest.importorskip("clang.cindex")
    import moos_lint.frontends.cpp.clang as clang_mod

    clang_mod._warned.clear()
    empty = tmp_path / "empty"
    empty.mkdir()
    assert _found(_lint("clang", empty)) == TREE_SITTER
    assert "compile_commands.json" in capsys.readouterr().err


def test_blanking_keeps_directives_and_every_other_byte():
    from moos_lint.frontends.cpp.clang_facts import ClangFacts

    facts = ClangFacts(None, None, lambda path: None)
    facts.skipped_lines = lambda path: {1, 2, 3, 4, 5}  # type: ignore[method-assign]
    data = b"#ifdef A\n  y = y * 180;\n#else\n  # elif B\n#define K 2\nz = 1;\n"
    out = facts.live("x.cpp", data)
    assert len(out) == len(data)
    assert out.split(b"\n") == [
        b"#ifdef A",
        b" " * 14,
        b"#else",
        b"  # elif B",
        b" " * 11,
        b"z = 1;",
        b"",
    ]


# ------------------------------------------------- every value rule, on the model alone

VALUE_CHECKS = (
    "yaw_heading_sign",
    "heading_in_radians",
    "depth_z_sign",
    "latlong_in_radians",
    "yaw_in_degrees",
    "angle_not_wrapped",
    "angle_in_degrees",
)


def _model(active: bool, type_: str | None):
    """One app publishing a break of every value rule, each as ``active`` and ``type_``."""
    import math

    from moos_lint.files.diagnostics import Span
    from moos_lint.frontends.cpp.model import AppModel, CppFile, Name, Publication, Value
    from moos_lint.frontends.cpp.values import AbstractValue

    breaks = {
        "NAV_YAW": AbstractValue(unit="deg"),
        "GPS_YAW": AbstractValue(unit="rad", sense="heading"),
        "NAV_HEADING": AbstractValue(unit="rad"),
        "NAV_Z": AbstractValue(sign="down"),
        "NAV_LAT": AbstractValue(unit="rad"),
        "NAV_ROLL": AbstractValue(unit="rad", range=(0.0, 2 * math.pi)),
        "NAV_PITCH": AbstractValue(unit="deg"),
    }
    span = Span("App.cpp", 1, 1, 1, 2)
    pubs = [
        Publication(
            name=Name(source=f'"{n}"', text=n),
            value=Value(text="v", expanded="v", span=span, type=type_, abstract=v),
            span=span,
            name_span=span,
            function="App::Iterate",
            active=active,
        )
        for n, v in breaks.items()
    ]
    return AppModel(folder=".", files=[CppFile(path="App.cpp", publications=pubs)])


@pytest.mark.parametrize("check", VALUE_CHECKS)
def test_every_value_rule_skips_compiled_out_and_non_numeric_values(check):
    from moos_lint.semantics import cpp_checks

    run = getattr(cpp_checks, check)
    assert list(run(_model(True, None))), "the model holds a break of this rule"
    assert list(run(_model(True, "integer"))) and list(run(_model(True, "floating")))
    assert not list(run(_model(False, None)))  # compiled out
    assert not list(run(_model(True, "string")))
    assert not list(run(_model(True, "bool")))
