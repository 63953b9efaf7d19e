"""nsplug semantics: directives, macros, conditions, includes, tags and the source map."""

from __future__ import annotations

from pathlib import Path

import pytest

from moos_lint.frontends.nsplug import MAX_INCLUDE_DEPTH, Preprocessor, expand_text


def write(tmp_path: Path, name: str, text: str) -> Path:
    path = tmp_path / name
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text(text, encoding="utf-8")
    return path


def nsplug(path: Path, **defines: str) -> str:
    return expand_text(Preprocessor(defines=defines, mode="nsplug").expand(path))


def test_macros_and_defaults(tmp_path):
    f = write(
        tmp_path,
        "m.moos",
        "#define WARP 10\n"
        "a = $(WARP) %(NAME)\n"
        "b = $(SPD=1.5) $(EMPTY:=2) $(EMPTY=3)\n"
        "c = $(UNDEF) $(WARP)\n",
    )
    out = nsplug(f, NAME="abe", EMPTY="")
    lines = out.splitlines()
    assert lines[0] == "a = 10 ABE"
    assert lines[1] == "b = 1.5 2 "
    # nsplug leaves a line with an undefined macro completely unexpanded
    assert lines[2] == "c = $(UNDEF) $(WARP)"


def test_lenient_expands_what_it_can(tmp_path):
    f = write(tmp_path, "m.moos", "#define WARP 10\nc = $(UNDEF) $(WARP)\n")
    pre = Preprocessor(mode="nsplug")
    pre.lenient = True
    assert expand_text(pre.expand(f)) == "c = $(UNDEF) 10\n"


def test_define_forms(tmp_path):
    f = write(tmp_path, "m.moos", "#define $(PORT)   9001\n#define SIM\nx = $(PORT)|$(SIM)|\n")
    assert nsplug(f) == "x = 9001||\n"


@pytest.mark.parametrize(
    ("defines", "expected"),
    [
        ({"VNAME": "abe"}, "one"),
        ({"VNAME": "ben"}, "two"),
        ({"VNAME": "cal"}, "three"),
        ({}, "three"),
    ],
)
def test_ifdef_chain(tmp_path, defines, expected):
    f = write(
        tmp_path,
        "m.moos",
        "#ifdef VNAME abe\none\n#elseifdef VNAME ben\ntwo\n#else\nthree\n#endif\n",
    )
    assert nsplug(f, **defines) == expected + "\n"


def test_ifdef_value_may_name_a_macro_and_conditions_combine(tmp_path):
    f = write(
        tmp_path,
        "m.moos",
        "#define LEAD abe\n"
        "#ifdef VNAME LEAD\nlead\n#endif\n"
        "#ifdef VNAME ben || SIM\nor\n#endif\n"
        "#ifdef VNAME abe && SIM\nand\n#endif\n"
        "#ifndef SHORE\nnot-shore\n#endif\n",
    )
    assert nsplug(f, VNAME="abe") == "lead\nnot-shore\n"
    assert nsplug(f, VNAME="abe", SIM="") == "lead\nand\nnot-shore\n"


def test_comment_on_condition_is_part_of_the_value(tmp_path):
    f = write(tmp_path, "m.moos", "#ifdef VNAME abe // c\nyes\n#endif\n")
    exp = Preprocessor(defines={"VNAME": "abe"}, mode="nsplug").expand(f)
    assert expand_text(exp) == ""
    assert [p.kind for p in exp.problems] == ["comment-in-condition"]


def test_mixed_and_or_is_false(tmp_path):
    f = write(tmp_path, "m.moos", "#ifdef A || B && C\nyes\n#endif\n")
    assert nsplug(f, A="1", B="1", C="1") == ""


def test_unknown_directive_passes_through(tmp_path):
    f = write(tmp_path, "m.moos", "#fidef X\nkeep\n")
    exp = Preprocessor(mode="nsplug").expand(f)
    assert expand_text(exp) == "#fidef X\nkeep\n"
    assert exp.problems[0].kind == "unknown-directive"


def test_include_search_order_and_source_map(tmp_path):
    write(tmp_path, "mission/plug.moos", "from-mission-folder\n")
    write(tmp_path, "lib/plug.moos", "from-path\n")
    write(tmp_path, "lib/only.moos", "line1\nline2\n")
    main = write(tmp_path, "mission/m.moos", "#include plug.moos\n#include only.moos\nend\n")
    pre = Preprocessor(include_paths=[tmp_path / "lib"], mode="lint")
    exp = pre.expand(main)
    assert [ln.text for ln in exp.lines] == ["from-mission-folder", "line1", "line2", "end"]
    line2 = exp.lines[2]
    assert line2.path.endswith("only.moos") and line2.lineno == 2
    assert [(Path(s.path).name, s.line) for s in line2.chain] == [("m.moos", 2)]


def test_include_of_including_files_folder(tmp_path):
    write(tmp_path, "plugs/a.plug", "#include b.plug\n")
    write(tmp_path, "plugs/b.plug", "deep\n")
    main = write(tmp_path, "m.moos", "#include plugs/a.plug\n")
    exp = Preprocessor().expand(main)
    assert [ln.text for ln in exp.lines] == ["deep"]
    assert len(exp.lines[0].chain) == 2


def test_include_tags(tmp_path):
    write(tmp_path, "plugs.moos", "<tag><one>\n#skipped\nA = 1\n<tag><two>\nB = 2\n")
    main = write(tmp_path, "m.moos", "#include plugs.moos <two>\n#include plugs.moos <nope>\n")
    exp = Preprocessor().expand(main)
    assert [ln.text for ln in exp.lines] == ["B = 2"]
    assert [p.kind for p in exp.problems] == ["unknown-include-tag"]


def test_include_loop_and_missing_are_problems_not_crashes(tmp_path):
    write(tmp_path, "a.moos", "#include b.moos\n#include missing.moos\n")
    write(tmp_path, "b.moos", "#include a.moos\nx = 1\n")
    exp = Preprocessor().expand(tmp_path / "a.moos")
    assert sorted(p.kind for p in exp.problems) == ["include-cycle", "include-not-found"]
    assert [ln.text for ln in exp.lines] == ["x = 1"]


def test_missing_absolute_include_is_reported_only_inside_the_missions_folder(tmp_path):
    inside = tmp_path / "mission" / "plugs" / "gone.moos"
    outside = tmp_path / "vehicle" / "plug_iGPS.moos"  # the vehicle computer's own file
    top = write(tmp_path, "mission/a.moos", f"#include {inside}\n#include {outside}\nx = 1\n")
    exp = Preprocessor().expand(top)
    missing = [p for p in exp.problems if p.kind == "include-not-found"]
    assert [p.span.line for p in missing] == [1]
    assert exp.incomplete


def test_deep_include_chain_does_not_recurse(tmp_path):
    for i in range(1200):
        write(tmp_path, f"f{i}.plug", f"#include f{i + 1}.plug\n")
    write(tmp_path, "f1200.plug", "bottom = 1\n")
    exp = Preprocessor().expand(tmp_path / f"f{1200 - MAX_INCLUDE_DEPTH}.plug")
    assert [ln.text for ln in exp.lines] == ["bottom = 1"]
    assert len(exp.lines[0].chain) == MAX_INCLUDE_DEPTH
    # Deeper than the limit: a problem at the include that goes too deep, no crash.
    exp = Preprocessor().expand(tmp_path / "f0.plug")
    assert exp.lines == []
    assert [(p.kind, Path(p.span.path).name) for p in exp.problems] == [
        ("include-cycle", f"f{MAX_INCLUDE_DEPTH}.plug")
    ]


def test_lint_mode_keeps_every_branch_of_an_unknown_condition(tmp_path):
    f = write(
        tmp_path,
        "m.moos",
        "#ifdef VNAME abe\na\n#elseifdef VNAME ben\nb\n#else\nc\n#endif\n"
        "#define KNOWN 1\n#ifdef KNOWN\nd\n#else\ne\n#endif\n",
    )
    exp = Preprocessor(mode="lint").expand(f)
    texts = [ln.text for ln in exp.lines]
    assert texts == ["a", "b", "c", "d"]
    a, b, c, d = exp.lines
    assert a.excludes(b) and b.excludes(c) and a.excludes(c)
    assert not a.excludes(d) and not d.excludes(a)


def test_lint_mode_define_in_unknown_branch_is_unknown(tmp_path):
    f = write(
        tmp_path,
        "m.moos",
        "#ifdef VNAME abe\n#define POS 0,0\n#else\n#define POS 9,9\n#endif\nstart = $(POS)\n",
    )
    exp = Preprocessor(mode="lint").expand(f)
    assert exp.lines[-1].text == "start = $(POS)"
    known = Preprocessor(defines={"VNAME": "abe"}, mode="lint").expand(f)
    assert known.lines[-1].text == "start = 0,0"


def test_unbalanced_and_unclosed(tmp_path):
    f = write(tmp_path, "m.moos", "#endif\n#else\n#ifdef X\nx\n")
    kinds = [p.kind for p in Preprocessor().expand(f).problems]
    assert kinds == ["unbalanced-conditional", "unbalanced-conditional", "unclosed-conditional"]


def test_span_maps_expanded_text_back(tmp_path):
    f = write(tmp_path, "m.moos", "#define V alpha\n  Community = $(V)  \n")
    line = Preprocessor().expand(f).lines[0]
    assert line.text == "  Community = alpha  "
    span = line.span(line.text.index("Community"), line.text.index("Community") + 9)
    assert (span.line, span.col, span.end_col) == (2, 3, 12)


def _include_bomb(folder: Path, fan_out: int = 10, levels: int = 8) -> Path:
    """A mission whose include tree multiplies: ``fan_out ** levels`` leaf copies."""
    (folder / f"l{levels}.inc").write_text("// leaf\nAppTick = 4\n")
    for i in range(levels - 1, 0, -1):
        (folder / f"l{i}.inc").write_text(f"#include l{i + 1}.inc\n" * fan_out)
    top = folder / "bomb.moos"
    top.write_text("ServerPort = 9000\n#include l1.inc\n")
    return top


def test_an_include_bomb_stops_at_its_budget(tmp_path, monkeypatch):
    import moos_lint.frontends.nsplug as nsplug

    monkeypatch.setattr(nsplug, "MAX_EXPANDED_LINES", 5_000)
    exp = Preprocessor().expand(_include_bomb(tmp_path))
    assert exp.incomplete
    [problem] = [p for p in exp.problems if p.kind == "include-cycle"]
    assert "more than 5,000 lines" in problem.message
    assert problem.span.path.endswith(".inc") and problem.span.line >= 1
    assert len(exp.lines) < 5_000


def test_a_macro_that_grows_without_bound_stops(tmp_path):
    big = "x" * 200_000
    (tmp_path / "m.moos").write_text(
        f"#define BIG {big}\nServerPort = 9000\nKey = {'$(BIG)' * 100}\nAfter = 1\n"
    )
    exp = Preprocessor().expand(tmp_path / "m.moos")
    [problem] = [p for p in exp.problems if p.kind == "include-cycle"]
    assert (problem.span.line, "macros that grow without bound" in problem.message) == (3, True)
    assert all(len(line.text) < 2**21 for line in exp.lines)


def test_the_cli_reports_an_include_bomb(tmp_path, monkeypatch, capsys):
    import moos_lint.frontends.nsplug as nsplug
    from moos_lint.commands.cli import main

    monkeypatch.setattr(nsplug, "MAX_EXPANDED_LINES", 5_000)
    top = _include_bomb(tmp_path)
    monkeypatch.chdir(tmp_path)
    assert main(["check", "--no-cache", "--select", "P002", "-q", str(top)]) == 1
    out = capsys.readouterr().out
    assert (
        out.startswith("l") and "P002 [include-cycle]" in out and "included from bomb.moos:2" in out
    )
