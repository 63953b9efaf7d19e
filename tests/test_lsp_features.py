"""The language server's features, tested without a connection."""

from __future__ import annotations

import shutil
from pathlib import Path

import pytest

pytest.importorskip("lsprotocol")

from lsprotocol import types as lsp

from moos_lint.commands.lsp import features
from moos_lint.commands.lsp.analysis import Collector, _may_include, analyse, settings_for
from moos_lint.commands.lsp.catalogue import Catalogue, Component, ParamInfo, from_app_catalogue
from moos_lint.commands.lsp.documents import (
    DiskReads,
    DocumentStore,
    MemoryReader,
    path_to_uri,
    uri_to_path,
)
from moos_lint.files.diagnostics import Span
from moos_lint.files.source import SourceFile

FIXTURES = Path(__file__).resolve().parent.parent / "fixtures" / "lsp"
CATALOGUE = Catalogue(
    apps=[
        Component(
            "pHelmIvP",
            "The IvP helm.",
            {"behaviors": ParamInfo("behaviors", "The behavior file the helm reads.")},
        ),
        Component("pMarinePID", "A PID controller.", {"speed_factor": ParamInfo("speed_factor")}),
    ],
    behaviors=[Component("BHV_Waypoint", "Visit points.", {"points": ParamInfo("points", "")})],
)


@pytest.fixture
def mission(tmp_path: Path) -> Path:
    for f in FIXTURES.iterdir():
        shutil.copy(f, tmp_path / f.name)
    return tmp_path / "mission.moos"


def lines(text: str) -> list[str]:
    return text.split("\n")


# ------------------------------------------------------------------ positions
def test_columns_follow_the_negotiated_encoding():
    line = "x = 😀é // é"
    idx = line.index("//")
    assert features.to_client(line, idx, "utf-32") == idx
    assert features.to_client(line, idx, "utf-16") == idx + 1  # the emoji is 2 units
    assert features.to_client(line, idx, "utf-8") == idx + 3 + 1
    for enc in ("utf-8", "utf-16", "utf-32"):
        assert features.from_client(line, features.to_client(line, idx, enc), enc) == idx
    assert features.from_client("abc", 99, "utf-16") == 3


def test_an_empty_span_covers_its_lines_text():
    rng = features.span_range(Span("f", 2, 1), ["", "   key = v  "], "utf-16")
    assert (rng.start.character, rng.end.character) == (3, 10)
    rng = features.span_range(Span("f", 9, 1), ["x"], "utf-16")  # past the end: no crash
    assert rng.start.line == 8


# --------------------------------------------------------------- suppressions
@pytest.mark.parametrize(
    ("text", "row", "expect_pos", "expect_text"),
    [
        ("a = 1", 0, (0, 5), "  // moos-lint: ignore[R003]"),
        ("a = 1 ", 0, (0, 6), "// moos-lint: ignore[R003]"),
        ("a = 1  // moos-lint: ignore[R007]", 0, (0, 32), ", R003"),
        ("a = 1  // moos-lint: ignore[]", 0, (0, 28), "R003"),
        ("x\n  #include a.moos", 1, (1, 0), "  // moos-lint: ignore[R003]\n"),
        ("// moos-lint: ignore[R007]\n#ifdef A", 1, (0, 25), ", R003"),
    ],
)
def test_suppression_edit(text, row, expect_pos, expect_text):
    edit = features.suppression_edit(lines(text), row, "R003", "utf-16")
    assert (edit.range.start.line, edit.range.start.character) == expect_pos
    assert edit.range.start == edit.range.end
    assert edit.new_text == expect_text


def test_a_suppression_comment_added_by_the_action_silences_the_finding(mission):
    path = str(mission)
    text = mission.read_text()
    result = analyse(path, {path: text})
    finding = next(f for f in result.findings if f.diagnostic.code == "R003" and not f.via)
    edit = features.suppression_edit(lines(text), finding.span.line - 1, "R003", "utf-16")
    rows = lines(text)
    row = rows[edit.range.start.line]
    rows[edit.range.start.line] = row[: edit.range.start.character] + edit.new_text
    fixed = "\n".join(rows)
    after = analyse(path, {path: fixed})
    codes = sorted((f.span.line, f.diagnostic.code) for f in after.findings if not f.via)
    assert codes == [(13, "R007"), (25, "L001")]


# ---------------------------------------------------------------------- hover
def test_hover_on_a_prefix_and_an_unknown_code():
    text = "a = 1 // moos-lint: ignore[R, nonsense-rule]"
    at_r = features.hover(None, text, lsp.Position(0, text.index("[R") + 1), "utf-16", Catalogue())
    assert "selects" in at_r.contents.value and "brace-on-header" in at_r.contents.value
    col = text.index("nonsense") + 2
    unknown = features.hover(None, text, lsp.Position(0, col), "utf-16", Catalogue())
    assert "names no moos-lint rule" in unknown.contents.value
    assert features.hover(None, text, lsp.Position(0, 1), "utf-16", Catalogue()) is None


def test_hover_on_a_finding_shows_the_rule_page(mission):
    path = str(mission)
    result = analyse(path, {path: mission.read_text()})
    hover = features.hover(result, mission.read_text(), lsp.Position(15, 5), "utf-16", Catalogue())
    assert "**R003 brace-on-header**" in hover.contents.value
    assert "## How to fix" in hover.contents.value


def test_parameter_hover_and_completion_come_from_the_catalogue():
    text = (
        "ProcessConfig = ANTLER\n{\n  Run = pHelmIvP @ NewConsole = false ~ pHelm_A\n}\n"
        "ProcessConfig = pHelm_A\n{\n  behaviors = a.bhv\n  \n}\n"
    )
    hover = features.hover(None, text, lsp.Position(6, 4), "utf-16", CATALOGUE)
    assert "The behavior file the helm reads." in hover.contents.value
    assert features.hover(None, text, lsp.Position(6, 4), "utf-16", Catalogue()) is None
    items = features.completion(text, lsp.Position(7, 2), "utf-16", CATALOGUE)
    assert [i.label for i in items] == ["behaviors"]
    items = features.completion(text, lsp.Position(2, 8), "utf-16", CATALOGUE)
    assert [i.label for i in items] == ["pHelmIvP", "pMarinePID"]
    assert features.completion(text, lsp.Position(6, 16), "utf-16", CATALOGUE) == []
    assert features.completion(text, lsp.Position(7, 2), "utf-16", Catalogue()) == []
    bhv = "Behavior = BHV_Waypoint\n{\n  name = a\n  \n}\n"
    assert [i.label for i in features.completion(bhv, lsp.Position(3, 2), "utf-16", CATALOGUE)] == [
        "points"
    ]


def test_enclosing_header_skips_closed_blocks():
    text = lines("ProcessConfig = A\n{\n  x = 1\n}\nProcessConfig = B {\n  y = 2\n}\nz = 3")
    assert features.enclosing_header(text, 2) == ("processconfig", "A")
    assert features.enclosing_header(text, 5) == ("processconfig", "B")
    assert features.enclosing_header(text, 7) is None


# ----------------------------------------------------------------- definition
def test_definition_follows_tagged_includes(tmp_path: Path):
    (tmp_path / "plugs").mkdir()
    (tmp_path / "plugs" / "parts.def").write_text("<tag><a>\nx = 1\n<tag><b>\ny = 2\n")
    main = tmp_path / "m.moos"
    text = "#include plugs/parts.def <b>\n#include nowhere.def\n#include $(PLUG)\n"
    main.write_text(text)
    result = analyse(str(main), {str(main): text})
    loc = features.definition(
        str(main),
        text,
        lsp.Position(0, 3),
        "utf-16",
        result,
        [],
        lambda p: lines(Path(p).read_text()),
    )
    assert loc.uri == path_to_uri(str(tmp_path / "plugs" / "parts.def"))
    assert loc.range.start.line == 2
    for row in (1, 2):
        assert (
            features.definition(str(main), text, lsp.Position(row, 3), "utf-16", result, [], list)
            is None
        )


# ------------------------------------------------------------ documents, analysis
def test_memory_reader_prefers_editor_text_but_keeps_disk_facts(tmp_path: Path):
    f = tmp_path / "a.moos"
    f.write_bytes("name = caf\xe9\n".encode("latin-1"))
    seen: set[str] = set()
    same = MemoryReader({str(f): "name = café\n"}, seen)(f)
    assert isinstance(same, SourceFile) and same.encoding == "latin-1"
    edited = MemoryReader({str(f): "name = cafe\n"})(f)
    assert edited.text == "name = cafe\n" and edited.encoding == "utf-8"
    assert seen == {str(f)}


def test_disk_reads_are_kept_only_while_the_file_is_unchanged(tmp_path: Path):
    import os

    f = tmp_path / "plug.moos"
    f.write_text("a = 1\n")
    disk = DiskReads(size=2)
    first = disk.read(f)
    assert isinstance(first, SourceFile) and disk.read(f) is first  # unchanged: kept
    st = f.stat()
    f.write_text("a = 2\n")  # same size, and the mtime put back: the ctime still moves
    os.utime(f, ns=(st.st_atime_ns, st.st_mtime_ns))
    again = disk.read(f)
    assert again is not first and again.text == "a = 2\n"
    for name in ("b.moos", "c.moos"):  # the oldest read leaves when the size is reached
        (tmp_path / name).write_text("x\n")
        disk.read(tmp_path / name)
    assert disk.read(f) is not again
    f.unlink()  # a file gone is a read problem, as the engine reports it
    assert not isinstance(disk.read(f), SourceFile)


@pytest.mark.parametrize(
    ("text", "may"),
    [
        ("#include plug.moos\n", True),
        ("  #include <plug.moos> // the vehicle\n", True),
        ("#include $(PLUG)\n", True),  # a macro may name it
        ("#include %(PLUG)\n", True),
        ("#include other.moos\n", False),
        ("// #include plug.moos\n", False),  # not a directive
        ("x = 1\r#include plug.moos\r", True),  # old Mac line ends
        ("#include other.moos\nname = plug.moos\n", False),
        ("", False),
    ],
)
def test_a_neighbour_is_linted_with_a_mission_file_only_when_it_may_include_it(
    tmp_path: Path, text: str, may: bool
):
    f = tmp_path / "mission.moos"
    f.write_text(text)
    assert _may_include(str(f), "plug.moos") is may


def test_unreadable_neighbours_are_kept(tmp_path: Path):
    assert _may_include(str(tmp_path / "gone.moos"), "plug.moos") is True


def test_the_collector_waits_for_every_running_lint():
    import gc

    collector = Collector()
    assert gc.isenabled()
    try:
        with collector.linting():
            assert not gc.isenabled()
            with collector.linting():  # a second document's lint, on another thread
                assert not collector.idle()
            assert not gc.isenabled() and not collector.idle()

        class Node:
            pass

        a, b = Node(), Node()
        a.other, b.other = b, a
        gone = __import__("weakref").ref(a)
        del a, b
        assert gone() is not None  # a cycle: reference counting does not free it
        assert collector.idle() and gc.isenabled()
        assert gone() is None
    finally:
        gc.enable()


def test_uris_and_store():
    assert uri_to_path("untitled:Untitled-1") is None
    assert uri_to_path("file:///tmp/a%20b.moos") == "/tmp/a b.moos"
    assert uri_to_path(path_to_uri("/tmp/a b.moos")) == "/tmp/a b.moos"
    store = DocumentStore()
    assert store.open("untitled:x", "t") is None
    doc = store.open("file:///tmp/m.moos", "text", 1)
    store.record(doc.path, {"/tmp/m.moos", "/tmp/p.moos"}, {"/tmp/p.moos"})
    assert [d.path for d in store.dependents("/tmp/p.moos")] == ["/tmp/m.moos"]
    assert store.includers("/tmp/p.moos") == ["/tmp/m.moos"]
    assert store.close("file:///tmp/m.moos") is doc and store.documents() == []


def test_a_fragment_is_judged_with_the_mission_that_includes_it(mission):
    plug = str(mission.parent / "plug_vehicle.moos")
    texts = {plug: (mission.parent / "plug_vehicle.moos").read_text()}
    result = analyse(plug, texts)
    assert [(f.span.line, f.diagnostic.code) for f in result.findings] == [(2, "R003")]
    assert str(mission) in result.reads
    # the behavior file counts once a rule reads it (the mission model's, here)
    settings, _error = settings_for(plug)
    settings.select = ["M005"]
    result = analyse(plug, texts, settings=settings)
    assert str(mission.parent / "mission.bhv") in result.reads


def test_files_the_engine_does_not_lint_get_no_findings(tmp_path: Path):
    src = tmp_path / "app.txt"
    src.write_text("ProcessConfig = x {\n")
    assert analyse(str(src), {str(src): src.read_text()}).findings == []


def test_a_broken_config_falls_back_to_defaults(tmp_path: Path):
    (tmp_path / "moos-lint.toml").write_text("select = [\n")
    m = tmp_path / "m.moos"
    m.write_text("ProcessConfig = A {\n}\n")
    result = analyse(str(m), {str(m): m.read_text()})
    assert result.config_error and "invalid TOML" in result.config_error
    assert "R003" in [f.diagnostic.code for f in result.findings]


def test_the_rules_app_catalogue_plugs_in():
    from types import SimpleNamespace

    rules_catalogue = SimpleNamespace(
        apps={"phelmivp": SimpleNamespace(name="pHelmIvP", params={"behaviors"}, provenance="x")},
        behaviors={"bhv_loiter": SimpleNamespace(name="BHV_Loiter", params={"polygon"})},
    )
    cat = from_app_catalogue(rules_catalogue)
    assert [c.name for c in cat.apps()] == ["pHelmIvP"]
    assert cat.app("PHELMIVP").param("Behaviors").name == "behaviors"
    assert cat.behavior("bhv_loiter").param("polygon") is not None
    assert from_app_catalogue(object()).empty


def test_a_cpp_document_is_linted_as_the_editor_holds_it(tmp_path: Path):
    """An unsaved edit of a C++ file is what the diagnostics show, not the file on disk."""
    app = tmp_path / "pTrack"
    app.mkdir()
    path = app / "Track.cpp"
    saved = (
        '#include "MOOS/libMOOS/MOOSLib.h"\n'
        "class Track : public CMOOSApp {\n public:\n  bool Iterate();\n  double m_kts;\n};\n"
        'bool Track::Iterate()\n{\n  Notify("TRACK_SPEED", m_kts * 0.514444);\n'
        "  return true;\n}\n"
    )
    path.write_text(saved)
    edited = saved.replace("m_kts * 0.514444", "m_kts")
    codes = lambda result: [f.diagnostic.code for f in result.findings]  # noqa: E731
    assert "C010" not in codes(analyse(str(path), {str(path): saved}))
    assert "C010" in codes(analyse(str(path), {str(path): edited}))
    assert path.read_text() == saved


def test_a_re_lint_sees_the_projects_own_behavior_copies_change(tmp_path: Path):
    """What the project's own copy of a stock behavior reads is kept between re-lints
    only while that copy, and the folders that hold the copies, are unchanged."""
    vendored = FIXTURES.parent / "rules" / "unknown-behavior-parameter" / "quiet" / "vendored"
    root = tmp_path / "vendored"
    shutil.copytree(vendored, root)
    bhv = str(root / "vendored.bhv")
    texts = {bhv: (root / "vendored.bhv").read_text()}

    def codes() -> list[str]:
        return [f.diagnostic.code for f in analyse(bhv, texts).findings]

    assert codes() == []  # the copy reads `active_grade`
    copy = root / "lib_behaviors" / "BHV_AvoidCollision.cpp"
    reads = copy.read_text()
    copy.write_text(reads.replace('"active_grade"', '"other_grade"'))
    assert codes() == ["M004"]  # the copy no longer reads it
    (root / "lib_extra").mkdir()
    (root / "lib_extra" / "BHV_AvoidCollision.cpp").write_text(reads)
    assert codes() == []  # a second copy, in a new folder, reads it
