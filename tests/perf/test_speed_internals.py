"""How the speed is had: the ``perf`` suite.

These tests pin the machinery behind moos-lint's speed rather than what a user
sees: which modules a command loads, the collector pause and ``gc.freeze``,
the parse and expansion memos, the C++ prefilter, how work is spread over
worker processes, and the benchmark script. They fail when a speed-up is lost
or changes shape, even when the output stays right (the promises a user relies
on are in tests/test_performance.py and stay in the main suite).

They run with everything else (``python -m pytest``); ``-m perf`` runs them
alone, ``-m "not perf"`` leaves them out.
"""

from __future__ import annotations

import os
import subprocess
import sys
from pathlib import Path

import pytest

from moos_lint.commands.cli import main
from moos_lint.commands.output import render
from moos_lint.core import engine
from moos_lint.core.config import resolve_settings
from moos_lint.speed import parallel
from tests.fixture_expect import FIXTURES
from tests.test_performance import MISSION, PLUG, _cached, _cli_run, _json, _settings, _tree

pytestmark = pytest.mark.perf


@pytest.fixture
def tree(tmp_path):
    root = tmp_path / "tree"
    root.mkdir()
    return _tree(root)


def test_the_prefilter_keeps_parsing_to_files_that_mention_moos(tmp_path, monkeypatch):
    from moos_lint.frontends.cpp import app, parse

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
    from moos_lint.frontends.cpp import app, parse

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


def test_the_language_server_keeps_an_unchanged_neighbours_share_of_the_tables(
    tmp_path, monkeypatch
):
    from moos_lint.frontends.cpp import app, extract, values

    monkeypatch.setattr(app, "PARSE_MEMO_SIZE", 8)
    monkeypatch.setattr(app, "_parse_memo", app.OrderedDict())
    folder = tmp_path / "pApp"
    folder.mkdir()
    (folder / "A.cpp").write_text('void A::a() { m_var = "A_OUT"; Notify(m_var, 1); }\n')
    (folder / "B.cpp").write_text('void A::b() { m_var = "B_OUT"; Notify("B", 2); }\n')
    tabled: list[str] = []
    parted: list[str] = []
    real_tables, real_part = extract._name_tables, values._names_nmea
    monkeypatch.setattr(
        extract, "_name_tables", lambda pf: tabled.append(pf.path) or real_tables(pf)
    )
    monkeypatch.setattr(values, "_names_nmea", lambda data: parted.append(data) or real_part(data))
    files = [str(folder / "A.cpp"), str(folder / "B.cpp")]
    first = _json(engine.lint_files(files, _settings(tmp_path)))
    assert len(tabled) == len(parted) == 2
    (folder / "A.cpp").write_text('void A::a() { m_var = "A_OUT"; Notify(m_var, 1); } // x\n')
    second = _json(engine.lint_files(files, _settings(tmp_path)))
    assert [os.path.basename(p) for p in tabled[2:]] == ["A.cpp"]
    assert len(parted) == 3
    # the folder's tables merge as one pass over its files: A's member value comes first
    assert first == second
    pa, pb = (app._parse_memo[k] for k in list(app._parse_memo)[-2:])
    merged = extract.collect_tables(sorted([pa, pb], key=lambda pf: pf.path))
    assert merged.assigns["m_var"] == ["A_OUT", "B_OUT"]


def test_a_run_expands_a_shared_behavior_file_once(tmp_path, monkeypatch):
    from moos_lint.frontends.nsplug import Preprocessor

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


def test_a_warm_run_loads_no_parser_and_no_rule(tree, tmp_path):
    store = tmp_path / "cache"
    code = (
        "import sys\n"
        "from moos_lint.commands.cli import main\n"
        f"args = ['check', {str(tree)!r}, '--cache-dir', {str(store)!r}, '-q', '--exit-zero']\n"
        "main(args)\n"
        "loaded = ('moos_lint.core.engine', 'moos_lint.frontends.nsplug', "
        "'moos_lint.frontends.parsers', "
        "'moos_lint.rules', 'moos_lint.semantics.mission_model', 'tree_sitter')\n"
        "print([m for m in sys.modules if m.startswith(loaded)])\n"
    )
    run = [sys.executable, "-c", code]
    first = subprocess.run(run, capture_output=True, text=True, timeout=120)
    assert first.returncode == 0, first.stderr
    assert "moos_lint.core.engine" in first.stdout  # a cold run lints
    second = subprocess.run(run, capture_output=True, text=True, timeout=120)
    assert second.returncode == 0, second.stderr
    assert second.stdout.strip().endswith("[]"), second.stdout
    # the findings are the same
    assert second.stdout.splitlines()[:-1] == first.stdout.splitlines()[:-1]


def test_small_inputs_stay_in_one_process():
    assert parallel.effective_jobs(8, parallel.MIN_FILES - 1) == 1
    assert parallel.effective_jobs(1, 10_000) == 1


def test_default_jobs_leave_busy_cpus_alone(monkeypatch):
    monkeypatch.setattr(parallel, "default_jobs", lambda: 4)
    monkeypatch.setattr(parallel, "can_fork", lambda: True)
    monkeypatch.setattr(parallel, "busy_cpus", lambda: 3)
    assert parallel.effective_jobs(None, 10_000) == 1  # one idle CPU: one process
    monkeypatch.setattr(parallel, "busy_cpus", lambda: 9)
    assert parallel.effective_jobs(None, 10_000) == 1
    monkeypatch.setattr(parallel, "busy_cpus", lambda: 1)
    assert parallel.effective_jobs(None, 10_000) == 3
    assert parallel.effective_jobs(4, 10_000) == 4  # asked for: as asked, whatever the load


def test_busy_cpus_reads_the_running_tasks(monkeypatch, tmp_path):
    import builtins

    real_open = builtins.open
    fake = tmp_path / "loadavg"

    def fake_open(path, *a, **k):
        return real_open(fake if path == "/proc/loadavg" else path, *a, **k)

    monkeypatch.setattr(builtins, "open", fake_open)
    fake.write_text("0.50 0.40 0.30 3/120 4567\n")
    assert parallel.busy_cpus() == 2  # three running, this process one of them
    fake.write_text("garbage\n")
    assert parallel.busy_cpus() == 0  # not known: as if idle
    fake.unlink()
    assert parallel.busy_cpus() == 0


def test_version_imports_no_parser_and_no_server():
    code = (
        "import sys\n"
        "from moos_lint.commands.cli import main\n"
        "try:\n    main(['--version'])\nexcept SystemExit:\n    pass\n"
        "heavy = ('tree_sitter', 'tree_sitter_cpp', 'clang', 'pygls', 'lsprotocol', 'argparse')\n"
        "print([m for m in sys.modules if m.split('.')[0] in heavy])\n"
    )
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=60)
    assert out.returncode == 0, out.stderr
    assert out.stdout.strip().endswith("[]"), out.stdout


def test_a_kept_expansion_is_expanded_again_only_when_what_it_read_changes(tmp_path, monkeypatch):
    from moos_lint.frontends import nsplug
    from moos_lint.frontends.nsplug import ExpansionStore, FileCache, Preprocessor

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
                from moos_lint.files.source import SourceFile, split_lines

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
    return parallel.cpp_folder_facts(paths), []


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
    two = render(
        "json",
        engine.lint_paths(
            [FIXTURES], resolve_settings([FIXTURES], None), jobs=2, parallel=parallel
        ),
    )
    assert two == one
    assert here, "the main process left every C++ folder to the workers"


def test_the_stored_file_list_ignores_the_folder_around_the_linted_one(tree, tmp_path, monkeypatch):
    from moos_lint.files import discovery

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
    from moos_lint.frontends.cpp import app as cpp_app
    from moos_lint.frontends.cpp.extract import ParsedFile
    from moos_lint.frontends.cpp.parse import backend

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

    def kinds(pf):
        return [len(x) for x in (pf.calls, pf.cmps, pf.asgs, pf.strings, pf.functions)]

    for data in versions:
        pf = cpp_app._parse(be, path, data)
        fresh_tree = real(data)
        fresh = ParsedFile(path, data, fresh_tree, be.matches(fresh_tree))
        assert str(pf.tree.root_node) == str(fresh.tree.root_node)
        assert kinds(pf) == kinds(fresh)
    # the first parse is fresh; each edit starts incrementally; the broken text is redone
    assert incremental == [False, True, True, False, True]


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
        "from moos_lint.commands.cli import main\n"
        f"main(['check', {str(tree)!r}, '--no-cache', '-q', '--exit-zero'])\n"
        "print([m for m in sys.modules if m.startswith(('moos_lint.frontends.cpp', "
        "'tree_sitter'))])\n"
    )
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=120)
    assert out.returncode == 0, out.stderr
    assert out.stdout.strip().endswith("[]"), out.stdout


def test_the_server_freezes_its_lifelong_objects_and_still_collects_later_cycles():
    code = (
        "import gc, sys, weakref\n"
        "from moos_lint.commands.lsp.analysis import settle\n"
        "settle()\n"
        "frozen = gc.get_freeze_count()\n"
        "settle()  # only the first call freezes\n"
        "assert gc.get_freeze_count() == frozen > 10_000, frozen\n"
        "assert 'moos_lint.rules.mission.unknown_parameter' in sys.modules\n"
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
    from moos_lint.commands.lsp import server as lsp_server

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


def test_a_replayed_run_loads_nothing_to_render_its_report(tree, tmp_path):
    store = str(tmp_path / "cache")
    (tree / "plug.moos").write_text(PLUG + "}\n")  # a finding, so exit status 1
    base = ["check", str(tree), "--cache-dir", store]
    first = _cli_run(base, tree)
    assert first.returncode == 1 and "R0" in first.stdout
    code = (
        "import sys\n"
        "before = set(sys.modules)\n"
        "from moos_lint.commands.cli import main\n"
        f"status = main({base!r})\n"
        "heavy = ('moos_lint.files.diagnostics', 'moos_lint.commands.output.text_format', "
        "'moos_lint.core.engine', "
        "'dataclasses', 'shutil')\n"
        "print('LOADED', [m for m in set(sys.modules) - before if m.startswith(heavy)], status)\n"
    )
    again = subprocess.run(
        [sys.executable, "-c", code], capture_output=True, text=True, timeout=120, cwd=tree
    )
    report, _, loaded = again.stdout.rpartition("LOADED ")
    assert report == first.stdout
    assert loaded.strip() == "[] 1", loaded  # replayed: nothing rendered, same status
