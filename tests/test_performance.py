"""The speed-ups keep their promises: without timing anything.

- the C++ prefilter keeps parsing to the files that mention the MOOS API;
- a run expands and parses a shared behavior file once;
- the result cache skips unchanged files, and notices a changed include, a new
  include, a touched-but-equal file, a corrupt entry; ``--no-cache`` writes nothing;
- ``--jobs 2`` gives the output of ``--jobs 1``;
- ``moos-lint --version`` imports no parser, no libclang and no language server;
- a warm run loads neither the parsers nor the rules, and the stored file list
  notices a new or removed file.
"""

from __future__ import annotations

import fnmatch
import json
import os
import subprocess
import sys
from pathlib import Path

import pytest

from moos_lint import cache as result_cache
from moos_lint import engine, parallel
from moos_lint.cli import main
from moos_lint.config import Settings, resolve_settings
from moos_lint.discovery import _excluded
from moos_lint.output import render
from tests.fixture_expect import FIXTURES

MISSION = """\
ServerPort = 9000
Community = alpha

ProcessConfig = ANTLER
{
  Run = MOOSDB @ NewConsole = false
  Run = pHelmIvP @ NewConsole = false
}

ProcessConfig = pHelmIvP
{
  behaviors = shared.bhv
}
#include plug.moos
"""
PLUG = "ProcessConfig = pLogger\n{\n  AppTick = 4\n}\n"
BEHAVIORS = "initialize DEPLOY = false\n\nBehavior = BHV_Waypoint\n{\n  name = go\n}\n"


def _tree(root: Path) -> Path:
    (root / "a.moos").write_text(MISSION)
    (root / "b.moos").write_text(MISSION.replace("alpha", "bravo"))
    (root / "plug.moos").write_text(PLUG)
    (root / "shared.bhv").write_text(BEHAVIORS)
    return root


def _settings(root: Path) -> Settings:
    return resolve_settings([root], None)


def _json(result) -> list[dict]:
    return json.loads(render("json", result))


# ------------------------------------------------------------------ prefilter and sharing
def test_the_prefilter_keeps_parsing_to_files_that_mention_moos(tmp_path, monkeypatch):
    from moos_lint.cpp import app, parse

    app_dir = tmp_path / "pApp"
    app_dir.mkdir()
    (app_dir / "App.cpp").write_text('bool App::OnStartUp() { Notify("X", 1); return true; }\n')
    (app_dir / "Util.cpp").write_text("int add(int a, int b) { return a + b; }\n")
    (app_dir / "Util.h").write_text("int add(int a, int b);\n")
    decoded, parsed = [], []
    real_decode, real_parse = app.decode, parse.Backend.parse
    monkeypatch.setattr(app, "decode", lambda data, p: decoded.append(p) or real_decode(data, p))
    monkeypatch.setattr(
        parse.Backend, "parse", lambda self, data: parsed.append(data) or real_parse(self, data)
    )
    engine.lint_paths([tmp_path], _settings(tmp_path))
    assert [os.path.basename(p) for p in decoded] == ["App.cpp"]
    assert len(parsed) == 1 and b"Notify" in parsed[0]


def test_the_language_server_reparses_only_changed_cpp(tmp_path, monkeypatch):
    from moos_lint.cpp import app, parse

    monkeypatch.setattr(app, "PARSE_MEMO_SIZE", 8)
    monkeypatch.setattr(app, "_parse_memo", app.OrderedDict())
    folder = tmp_path / "pApp"
    folder.mkdir()
    (folder / "A.cpp").write_text('void a() { Notify("A", 1); }\n')
    (folder / "B.cpp").write_text('void b() { Notify("B", 2); }\n')
    parsed: list[bytes] = []
    real = parse.Backend.parse
    monkeypatch.setattr(
        parse.Backend,
        "parse",
        lambda self, data, old_tree=None: parsed.append(data) or real(self, data, old_tree),
    )
    files = [str(folder / "A.cpp"), str(folder / "B.cpp")]
    first = _json(engine.lint_files(files, _settings(tmp_path)))
    assert len(parsed) == 2
    assert _json(engine.lint_files(files, _settings(tmp_path))) == first
    assert len(parsed) == 2  # nothing changed: nothing reparsed
    (folder / "B.cpp").write_text('void b() { Notify("B", 3); }\n')
    engine.lint_files(files, _settings(tmp_path))
    assert len(parsed) == 3 and b'"B", 3' in parsed[-1]


def test_a_run_expands_a_shared_behavior_file_once(tmp_path, monkeypatch):
    from moos_lint.nsplug import Preprocessor

    _tree(tmp_path)
    expanded: list[str] = []
    real = Preprocessor._expand
    monkeypatch.setattr(
        Preprocessor, "_expand", lambda self, p, m: expanded.append(p) or real(self, p, m)
    )
    settings = _settings(tmp_path)
    settings.select = ["ALL"]  # the mission rules read both missions' behavior files
    result = engine.lint_paths([tmp_path], settings)
    assert any(d.code.startswith("M") for d in result.diagnostics)  # the models were built
    assert sorted(os.path.basename(p) for p in expanded) == [
        "a.moos",
        "b.moos",
        "plug.moos",
        "shared.bhv",
    ]


def test_the_exclude_matcher_agrees_with_fnmatch():
    def reference(rel, name, patterns):
        for pat in patterns:
            pat = pat.rstrip("/")
            if fnmatch.fnmatch(name, pat) or fnmatch.fnmatch(rel, pat):
                return True
            if fnmatch.fnmatch(rel, pat + "/*"):
                return True
        return False

    patterns = [["build", "*.bak", "docs/", "a/b", "x?z", "[ab]*c", "**/gen"], [], [".git"]]
    rels = ["build", "src/build", "build/x.moos", "a/b/c.moos", "xyz", "ab/c", "bc", "q/gen/a"]
    for pats in patterns:
        for rel in rels:
            name = rel.rsplit("/", 1)[-1]
            assert _excluded(rel, name, pats) == reference(rel, name, pats), (rel, pats)


# ------------------------------------------------------------------ the result cache
@pytest.fixture
def tree(tmp_path):
    root = tmp_path / "tree"
    root.mkdir()
    return _tree(root)


@pytest.fixture
def counted(monkeypatch):
    """How many times the engine really lints (the cache did not answer)."""
    calls: list[int] = []
    real = engine.lint_files

    def lint_files(files, *a, **kw):
        calls.append(len(files))
        return real(files, *a, **kw)

    monkeypatch.setattr(engine, "lint_files", lint_files)
    return calls


def _cached(tree: Path, cache_dir: Path):
    return engine.lint_paths([tree], _settings(tree), cache_dir=str(cache_dir))


def test_the_cache_skips_an_unchanged_run(tree, tmp_path, counted):
    store = tmp_path / "cache"
    first = _json(_cached(tree, store))
    assert counted == [4]
    second = _json(_cached(tree, store))
    assert counted == [4], "an unchanged run was linted again"
    assert second == first
    assert [p.name for p in store.glob("run-*.pickle")]


def test_the_cache_notices_a_changed_include(tree, tmp_path, counted):
    store = tmp_path / "cache"
    before = _json(_cached(tree, store))
    # an include of both missions gets a stray brace: a finding appears in plug.moos
    (tree / "plug.moos").write_text(PLUG + "}\n")
    after = _json(_cached(tree, store))
    assert len(counted) == 2
    fresh = _json(engine.lint_paths([tree], _settings(tree)))
    assert after == fresh != before
    assert any(d["path"].endswith("plug.moos") for d in after if d not in before)


def test_the_cache_notices_an_include_that_now_exists(tree, tmp_path, counted):
    store = tmp_path / "cache"
    (tree / "a.moos").write_text(MISSION + "#include extra/more.plug\n")
    before = _json(_cached(tree, store))
    assert any(d["code"] == "P001" for d in before)  # include-not-found
    (tree / "extra").mkdir()
    (tree / "extra" / "more.plug").write_text("// nothing\n")  # not a linted suffix
    after = _json(_cached(tree, store))
    assert len(counted) == 2
    assert not any(d["code"] == "P001" for d in after)


def test_the_stored_file_list_notices_new_and_removed_files(tree, tmp_path, counted):
    store = tmp_path / "cache"
    _cached(tree, store)
    assert list(store.glob("files-*.pickle")), "the discovered files were not kept"
    (tree / "sub").mkdir()
    (tree / "sub" / "c.moos").write_text(MISSION.replace("alpha", "charlie"))
    found = _cached(tree, store).files
    assert str(tree / "sub" / "c.moos") in found
    (tree / "sub" / "deeper").mkdir()
    (tree / "sub" / "deeper" / "d.bhv").write_text(BEHAVIORS)
    assert str(tree / "sub" / "deeper" / "d.bhv") in _cached(tree, store).files
    (tree / "b.moos").unlink()
    found = _cached(tree, store).files
    assert str(tree / "b.moos") not in found
    assert counted == [4, 5, 6, 5]
    # and an unchanged tree reuses the list and the result
    assert _cached(tree, store).files == found
    assert counted == [4, 5, 6, 5]


def test_a_warm_run_loads_no_parser_and_no_rule(tree, tmp_path):
    store = tmp_path / "cache"
    code = (
        "import sys\n"
        "from moos_lint.cli import main\n"
        f"args = ['check', {str(tree)!r}, '--cache-dir', {str(store)!r}, '-q', '--exit-zero']\n"
        "main(args)\n"
        "loaded = ('moos_lint.engine', 'moos_lint.nsplug', 'moos_lint.parsers', "
        "'moos_lint.rules', 'moos_lint.mission_model', 'tree_sitter')\n"
        "print([m for m in sys.modules if m.startswith(loaded)])\n"
    )
    run = [sys.executable, "-c", code]
    first = subprocess.run(run, capture_output=True, text=True, timeout=120)
    assert first.returncode == 0, first.stderr
    assert "moos_lint.engine" in first.stdout  # a cold run lints
    second = subprocess.run(run, capture_output=True, text=True, timeout=120)
    assert second.returncode == 0, second.stderr
    assert second.stdout.strip().endswith("[]"), second.stdout
    # the findings are the same
    assert second.stdout.splitlines()[:-1] == first.stdout.splitlines()[:-1]


def test_a_touched_file_with_the_same_text_keeps_the_entry(tree, tmp_path, counted):
    store = tmp_path / "cache"
    first = _json(_cached(tree, store))
    st = os.stat(tree / "shared.bhv")
    os.utime(tree / "shared.bhv", ns=(st.st_atime_ns, st.st_mtime_ns + 5_000_000_000))
    assert _json(_cached(tree, store)) == first
    assert len(counted) == 1


def test_a_changed_setting_is_another_entry(tree, tmp_path, counted):
    store = tmp_path / "cache"
    _cached(tree, store)
    settings = _settings(tree)
    settings.ignore = ["R"]
    engine.lint_paths([tree], settings, cache_dir=str(store))
    assert len(counted) == 2


def test_a_corrupt_or_partial_entry_is_ignored(tree, tmp_path, counted):
    store = tmp_path / "cache"
    first = _json(_cached(tree, store))
    (entry,) = store.glob("run-*.pickle")
    data = entry.read_bytes()
    for broken in (b"", data[: len(data) // 2], b"not a pickle at all", b"\x80\x04K\x01."):
        entry.write_bytes(broken)
        assert _json(_cached(tree, store)) == first
    assert len(counted) == 5
    # a partial temporary file left by a killed run is harmless too
    (store / ".tmp-x.part").write_bytes(data[:10])
    assert _json(_cached(tree, store)) == first
    assert len(counted) == 5


def test_the_cache_writes_only_its_folder_and_no_cache_writes_nothing(tree, monkeypatch, capsys):
    monkeypatch.delenv(result_cache.ENV_VAR, raising=False)
    monkeypatch.chdir(tree)

    def listing():
        return sorted(str(p.relative_to(tree)) for p in tree.rglob("*"))

    before = listing()
    main(["check", ".", "--no-cache", "--output-format", "json"])
    assert listing() == before
    main(["check", ".", "--output-format", "json"])
    added = sorted(set(listing()) - set(before))
    assert added[0] == ".moos_lint_cache" and all(
        p.startswith(".moos_lint_cache/") for p in added[1:]
    )
    assert (tree / ".moos_lint_cache" / ".gitignore").read_text().strip().endswith("*")
    capsys.readouterr()


def test_cache_dir_in_the_config(tree, tmp_path, monkeypatch):
    monkeypatch.delenv(result_cache.ENV_VAR, raising=False)
    (tree / "moos-lint.toml").write_text('cache-dir = "../elsewhere"\n')
    settings = _settings(tree)
    assert settings.cache_dir == str((tmp_path / "elsewhere").resolve())
    assert result_cache.cache_dir_for(settings) == settings.cache_dir


# ------------------------------------------------------------------ --jobs
@pytest.mark.skipif(not parallel.can_fork(), reason="worker processes need fork")
def test_jobs_2_gives_the_output_of_jobs_1():
    settings = resolve_settings([FIXTURES], None)
    files = engine.discover([FIXTURES], settings.exclude, settings.root).files
    assert parallel.effective_jobs(2, len(files)) == 2  # the pool really runs
    one = render("json", engine.lint_paths([FIXTURES], settings, jobs=1))
    two = render("json", engine.lint_paths([FIXTURES], resolve_settings([FIXTURES], None), jobs=2))
    assert json.loads(two) == json.loads(one)
    assert two == one


def test_small_inputs_stay_in_one_process():
    assert parallel.effective_jobs(8, parallel.MIN_FILES - 1) == 1
    assert parallel.effective_jobs(1, 10_000) == 1


def test_jobs_must_be_positive(capsys):
    with pytest.raises(SystemExit):
        main(["check", ".", "--jobs", "0"])
    assert "--jobs" in capsys.readouterr().err


# ------------------------------------------------------------------ --version
def test_version_imports_no_parser_and_no_server():
    code = (
        "import sys\n"
        "from moos_lint.cli import main\n"
        "try:\n    main(['--version'])\nexcept SystemExit:\n    pass\n"
        "heavy = ('tree_sitter', 'tree_sitter_cpp', 'clang', 'pygls', 'lsprotocol', 'argparse')\n"
        "print([m for m in sys.modules if m.split('.')[0] in heavy])\n"
    )
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=60)
    assert out.returncode == 0, out.stderr
    assert out.stdout.strip().endswith("[]"), out.stdout


def _die(*args):
    """In a worker: die at once, as a crash in a parser would (picklable by name)."""
    os._exit(3)


@pytest.mark.skipif(not parallel.can_fork(), reason="worker processes need fork")
@pytest.mark.parametrize("phase", ["_cpp_folder", "_unit_rules"])
def test_a_dying_worker_never_hangs_the_run(monkeypatch, phase):
    settings = resolve_settings([FIXTURES], None)
    one = render("json", engine.lint_paths([FIXTURES], settings, jobs=1))
    monkeypatch.setattr(parallel, phase, _die)
    two = render("json", engine.lint_paths([FIXTURES], resolve_settings([FIXTURES], None), jobs=2))
    assert two == one


def _shown(path: str) -> list[tuple]:
    from moos_lint.lsp.analysis import analyse

    text = Path(path).read_text(encoding="utf-8", errors="replace")
    found = analyse(path, {path: text}).findings
    return sorted((f.diagnostic.code, f.span.line, f.span.col, f.diagnostic.message) for f in found)


def test_the_server_checks_only_units_that_can_report_in_the_document(monkeypatch):
    """Re-linting a document checks its own unit and the units that include or use it, and
    shows exactly what checking every neighbour shows."""
    from moos_lint.lsp import analysis

    folders = [FIXTURES / "example", *sorted((FIXTURES / "rules").glob("*/fire"))]
    docs = [
        str(p)
        for folder in folders
        for p in sorted(folder.rglob("*"))
        if p.is_file() and analysis.lintable(str(p))
    ]
    assert len(docs) > 50
    fast = {d: _shown(d) for d in docs}
    checked_units: list[int] = []
    real = analysis.lint_files

    def every_unit(files, settings, **kw):
        kw.pop("checked", None)
        checked_units.append(len(files))
        return real(files, settings, **kw)

    monkeypatch.setattr(analysis, "lint_files", every_unit)
    assert {d: _shown(d) for d in docs} == fast
    assert sum(checked_units) > len(docs)  # the documents had neighbours to skip


def test_expansions_kept_across_runs_follow_every_file_they_read(tmp_path, monkeypatch):
    from moos_lint import nsplug
    from moos_lint.nsplug import ExpansionStore, FileCache, Preprocessor

    (tmp_path / "m.moos").write_text("#include plug.moos\nA = 1\n")
    (tmp_path / "plug.moos").write_text("B = 2\n")
    store = ExpansionStore()
    expanded: list[str] = []
    real = Preprocessor._expand

    def counting(self, path, macros):
        expanded.append(os.path.basename(path))
        return real(self, path, macros)

    monkeypatch.setattr(Preprocessor, "_expand", counting)

    def run(texts=None, defines=None):
        def reader(p):
            text = (texts or {}).get(str(p))
            if text is not None:
                from moos_lint.source import SourceFile, split_lines

                return SourceFile(path=p, text=text, lines=split_lines(text))
            return nsplug.read_source(p)

        pre = Preprocessor(defines=defines, cache=FileCache(reader=reader, store=store))
        pre.memo = {}
        return [line.text for line in pre.expand(tmp_path / "m.moos").lines]

    first = run()
    assert run() == first and expanded == ["m.moos"]  # kept
    # an included file edited in the editor, then on disk
    assert "B = 3" in run(texts={str(tmp_path / "plug.moos"): "B = 3\n"})
    assert run() == first and expanded == ["m.moos"] * 3
    (tmp_path / "plug.moos").write_text("B = 4\n")
    assert "B = 4" in run() and len(expanded) == 4
    # other defines are another expansion; a file added to a folder read from re-expands
    run(defines={"X": "1"})
    assert len(expanded) == 5
    run()
    assert len(expanded) == 5
    (tmp_path / "new.txt").write_text("")
    run()
    assert len(expanded) == 6


def _slow_worker(paths):
    """In a worker: the work, late (picklable by name)."""
    import time

    time.sleep(0.2)
    return parallel.cpp_folder_facts(paths)


@pytest.mark.skipif(not parallel.can_fork(), reason="worker processes need fork")
def test_the_main_process_takes_the_cpp_folders_no_worker_started(monkeypatch):
    settings = resolve_settings([FIXTURES], None)
    one = render("json", engine.lint_paths([FIXTURES], settings, jobs=1))
    here: list[str] = []
    real = parallel.cpp_folder_facts

    def counted(paths):
        here.append(paths[0])
        return real(paths)

    monkeypatch.setattr(parallel, "_cpp_folder", _slow_worker)
    monkeypatch.setattr(parallel, "cpp_folder_facts", counted)
    two = render("json", engine.lint_paths([FIXTURES], resolve_settings([FIXTURES], None), jobs=2))
    assert two == one
    assert here, "the main process left every C++ folder to the workers"


def _cli_run(args, cwd):
    return subprocess.run(
        [sys.executable, "-m", "moos_lint", *args],
        capture_output=True,
        text=True,
        timeout=120,
        cwd=cwd,
    )


def test_an_unchanged_run_prints_the_same_report_without_rendering_it(tree, tmp_path):
    store = str(tmp_path / "cache")
    (tree / "plug.moos").write_text(PLUG + "}\n")  # a finding, so exit status 1
    base = ["check", str(tree), "--cache-dir", store]
    first = _cli_run(base, tree)
    assert first.returncode == 1 and "R0" in first.stdout
    code = (
        "import sys\n"
        "before = set(sys.modules)\n"
        "from moos_lint.cli import main\n"
        f"status = main({base!r})\n"
        "heavy = ('moos_lint.diagnostics', 'moos_lint.output.text_format', 'moos_lint.engine', "
        "'dataclasses', 'shutil')\n"
        "print('LOADED', [m for m in set(sys.modules) - before if m.startswith(heavy)], status)\n"
    )
    again = subprocess.run(
        [sys.executable, "-c", code], capture_output=True, text=True, timeout=120, cwd=tree
    )
    report, _, loaded = again.stdout.rpartition("LOADED ")
    assert report == first.stdout
    assert loaded.strip() == "[] 1", loaded  # replayed: nothing rendered, same status
    # other options, formats and folders are other reports
    zero = _cli_run([*base, "--exit-zero"], tree)
    assert zero.returncode == 0 and zero.stdout == first.stdout
    as_json = _cli_run([*base, "--output-format", "json"], tree)
    assert json.loads(as_json.stdout) and as_json.returncode == 1
    elsewhere = _cli_run(base, tmp_path)
    assert elsewhere.stdout != first.stdout  # paths are shown relative to the working folder
    # a path that does not exist is reported, replayed or not
    missing = ["check", str(tree), str(tree / "nope.moos"), "--cache-dir", store]
    assert "nope.moos" in _cli_run(missing, tree).stdout
    assert "nope.moos" in _cli_run(missing, tree).stdout
    # a changed file is linted again, and its report is the fresh one
    (tree / "plug.moos").write_text(PLUG)
    changed = _cli_run(base, tree)
    fresh = _cli_run([*base[:2], "--no-cache"], tree)
    assert changed.stdout == fresh.stdout != first.stdout
    assert changed.returncode == fresh.returncode


def test_the_stored_file_list_ignores_the_folder_around_the_linted_one(tree, tmp_path, monkeypatch):
    from moos_lint import discovery

    walks: list[int] = []
    real = discovery.discover

    def counting(*a, **kw):
        walks.append(1)
        return real(*a, **kw)

    monkeypatch.setattr(discovery, "discover", counting)
    store = tmp_path / "cache"
    _cached(tree, store)
    (tree.parent / "unrelated.txt").write_text("x")  # the folder that holds the tree changes
    _cached(tree, store)
    assert len(walks) == 1
    (tree / "new.moos").write_text(MISSION)
    assert str(tree / "new.moos") in _cached(tree, store).files
    assert len(walks) == 2


def test_rule_workers_take_a_folder_at_a_time():
    settings = resolve_settings([FIXTURES], None)
    result = engine.lint_paths([FIXTURES / "rules"], settings)
    units = result.units
    batches = parallel.rule_batches(units)
    assert sorted(i for b in batches for i in b) == list(range(len(units)))
    for batch in batches:
        assert len({os.path.dirname(units[i].path) for i in batch}) == 1
    assert len(batches) == len({os.path.dirname(u.path) for u in units})


def test_an_edited_cpp_file_is_parsed_incrementally_to_the_same_tree(monkeypatch):
    from moos_lint.cpp import app as cpp_app
    from moos_lint.cpp.parse import backend

    be = backend()
    monkeypatch.setattr(cpp_app, "PARSE_MEMO_SIZE", 8)
    monkeypatch.setattr(cpp_app, "_parse_memo", type(cpp_app._parse_memo)())
    monkeypatch.setattr(cpp_app, "_last_tree", type(cpp_app._last_tree)())
    incremental: list[bool] = []
    real = be.parse

    def spy(data, old_tree=None):
        incremental.append(old_tree is not None)
        return real(data, old_tree)

    monkeypatch.setattr(be, "parse", spy)
    path = str(FIXTURES / "rules" / "yaw-heading-sign" / "fire" / "sim" / "Sim.cpp")
    text = Path(path).read_bytes()
    cut = text.index(b"\n", len(text) // 2) + 1
    versions = [
        text,
        text[:cut] + b"// an edit\n" + text[cut:],  # a valid edit
        text[:cut] + b"void f( {\n" + text[cut:],  # a broken one: parsed afresh
        text[:cut] + b"// fixed\n" + text[cut:],  # and valid again
    ]
    for data in versions:
        tree, matches = cpp_app._parse(be, path, data)
        fresh = real(data)
        assert str(tree.root_node) == str(fresh.root_node)
        assert len(matches) == len(be.matches(fresh))
    # the first parse is fresh; each edit starts incrementally; the broken text is redone
    assert incremental == [False, True, True, False, True]


# ------------------------------------------------------------------ the benchmark script
def test_the_benchmark_prints_every_figure(tmp_path):
    """The shipped benchmark runs end to end on a small tree (the figures are not judged)."""
    tree = tmp_path / "tree"
    tree.mkdir()
    _tree(tree)
    app = tree / "pApp"
    app.mkdir()
    (app / "App.cpp").write_text('bool App::OnStartUp() { Notify("APP_X", 1); return true; }\n')
    before = sorted(p.name for p in tree.rglob("*"))
    out = subprocess.run(
        [sys.executable, "-m", "moos_lint.benchmark", str(tree), "--runs", "5"],
        capture_output=True,
        text=True,
        timeout=300,
    )
    assert out.returncode == 0, out.stderr
    for figure in (
        "cold (default jobs)",
        "cold (-j 1)",
        "warm (cache, nothing changed)",
        "moos-lint --version",
        "floor (read + tree-sitter only)",
        "peak memory (whole tree)",
        "re-lint a.moos",
        "re-lint App.cpp (1 lines)",
    ):
        line = next((ln for ln in out.stdout.splitlines() if ln.strip().startswith(figure)), "")
        assert any(ch.isdigit() for ch in line[len(figure) + 2 :]), (figure, out.stdout)
    assert sorted(p.name for p in tree.rglob("*")) == before  # the tree is not written


def test_a_command_line_lint_pauses_the_cyclic_gc_and_restores_it(tree, monkeypatch, capsys):
    import gc

    seen: list[bool] = []
    real = engine.lint_files

    def lint_files(*a, **kw):
        seen.append(gc.isenabled())
        return real(*a, **kw)

    monkeypatch.setattr(engine, "lint_files", lint_files)
    assert gc.isenabled()
    main(["check", str(tree), "--no-cache", "-q"])
    capsys.readouterr()
    assert seen == [False] and gc.isenabled()


def test_a_run_over_missions_alone_loads_no_cpp_module(tree):
    code = (
        "import sys\n"
        "from moos_lint.cli import main\n"
        f"main(['check', {str(tree)!r}, '--no-cache', '-q', '--exit-zero'])\n"
        "print([m for m in sys.modules if m.startswith(('moos_lint.cpp', 'tree_sitter'))])\n"
    )
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=120)
    assert out.returncode == 0, out.stderr
    assert out.stdout.strip().endswith("[]"), out.stdout


def test_the_server_freezes_its_lifelong_objects_and_still_collects_later_cycles():
    code = (
        "import gc, sys, weakref\n"
        "from moos_lint.lsp.analysis import settle\n"
        "settle()\n"
        "frozen = gc.get_freeze_count()\n"
        "settle()  # only the first call freezes\n"
        "assert gc.get_freeze_count() == frozen > 10_000, frozen\n"
        "assert 'moos_lint.rules.unknown_parameter' in sys.modules\n"
        "class Node:\n    pass\n"
        "a, b = Node(), Node()\n"
        "a.other, b.other = b, a\n"
        "gone = weakref.ref(a)\n"
        "del a, b\n"
        "gc.collect()\n"
        "print(gone() is None)\n"
    )
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=120)
    assert out.returncode == 0, out.stderr
    assert out.stdout.strip() == "True"


def test_the_server_settles_before_it_takes_requests(monkeypatch):
    pytest.importorskip("pygls")
    from moos_lint.lsp import server as lsp_server

    order: list[str] = []

    class Fake:
        def start_io(self):
            order.append("start_io")

    def create(*args, **kwargs):
        order.append("create")
        return Fake()

    monkeypatch.setattr(lsp_server, "create_server", create)
    monkeypatch.setattr(lsp_server, "settle", lambda: order.append("settle"))
    assert lsp_server.serve(catalogue=lsp_server.EMPTY) == 0
    assert order == ["create", "settle", "start_io"]


def test_the_benchmark_runs_the_console_script_pip_installs():
    import tomllib

    from moos_lint import benchmark

    root = Path(__file__).resolve().parents[1]
    data = tomllib.loads((root / "pyproject.toml").read_text(encoding="utf-8"))
    assert data["project"]["scripts"]["moos-lint"] == benchmark.ENTRY_POINT


def test_the_program_flushes_its_report_and_keeps_its_exit_status(tree):
    """``moos-lint`` skips the interpreter's teardown: the report still arrives whole."""
    (tree / "plug.moos").write_text(PLUG + "}\n")  # a finding
    args = [sys.executable, "-m", "moos_lint", "check", str(tree), "--no-cache"]
    env = {k: v for k, v in os.environ.items() if k != "PYTHONUNBUFFERED"}  # buffered, as usual
    json_run = [*args, "--output-format", "json"]
    out = subprocess.run(json_run, capture_output=True, timeout=120, env=env)
    assert out.returncode == 1 and json.loads(out.stdout)
    fresh = _json(engine.lint_paths([tree], _settings(tree)))
    assert json.loads(out.stdout) == fresh
    clean = subprocess.run([*args, "--exit-zero", "-q"], capture_output=True, timeout=120, env=env)
    assert clean.returncode == 0 and b"plug.moos" in clean.stdout
