"""The speed-ups keep their promises: without timing anything.

- the result cache skips an unchanged run and notices every changed input (a
  changed include, a new include, new and removed files, settings), keeps an
  entry for a touched-but-equal file, ignores a corrupt one; ``--no-cache``
  writes nothing;
- ``--jobs 2`` gives the output of ``--jobs 1``, and a dying worker never hangs
  the run;
- the language server's narrowed re-lint shows what a full one shows, and the
  expansions it keeps across runs see every change to what they read;
- an unchanged run prints the same report and exit status again;
- the program's report arrives whole.

How the speed is had (which modules load, the collector, the memos, the worker
scheduling, the benchmark) is pinned by the ``perf`` suite in tests/perf/.
"""

from __future__ import annotations

import fnmatch
import json
import os
import subprocess
import sys
from pathlib import Path

import pytest

from moos_lint.commands.cli import main
from moos_lint.commands.output import render
from moos_lint.core import engine
from moos_lint.core.config import Settings, resolve_settings
from moos_lint.files.discovery import _excluded
from moos_lint.speed import cache as result_cache
from moos_lint.speed import parallel
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


def _cached(tree: Path, cache_dir: Path, settings=None):
    settings = settings or _settings(tree)
    folder = result_cache.cache_folder(settings, [tree], str(cache_dir))
    return result_cache.cached_lint([tree], settings, context=False, jobs=1, folder=folder)


def test_the_cache_skips_an_unchanged_run(tree, tmp_path, counted):
    store = tmp_path / "cache"
    first = _json(_cached(tree, store))
    assert counted == [4]
    second = _json(_cached(tree, store))
    assert counted == [4], "an unchanged run was linted again"
    assert second == first
    assert [p.name for p in store.glob("run-*.json")]


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


def test_the_cache_notices_a_changed_launched_script(tmp_path, counted):
    """A script a mission launches decides which blocks it reads (what it quotes)."""
    (tmp_path / "m.moos").write_text(
        "ServerPort = 9000\nCommunity = abe\n\nProcessConfig = ANTLER\n{\n"
        "  Run = MOOSDB @ NewConsole = false\n  Run = ./iDyn2.py @ NewConsole = false\n}\n\n"
        "ProcessConfig = iDyn\n{\n  AppTick = 4\n}\n"
    )
    script = tmp_path / "iDyn2.py"
    script.write_text('NAME = "iDyn"\n')
    store = tmp_path / "cache"
    assert not any(d["code"] == "H001" for d in _json(_cached(tmp_path, store)))
    script.write_text('NAME = "iDynamics"\n')  # it reads another block now
    after = _json(_cached(tmp_path, store))
    assert len(counted) == 2
    assert [d["code"] for d in after if d["code"] == "H001"] == ["H001"]


def test_the_cache_notices_a_changed_ignore_file(tmp_path, counted):
    """An ignore file above the mission decides whether a missing behavior file is kept
    out of the repository on purpose."""
    project = tmp_path / "project"
    mission = project / "missions" / "m.moos"
    mission.parent.mkdir(parents=True)
    (project / ".git").mkdir()
    (project / ".gitignore").write_text("*.bhv\n")
    mission.write_text(
        "ServerPort = 9000\nCommunity = abe\n\nProcessConfig = ANTLER\n{\n"
        "  Run = MOOSDB @ NewConsole = false\n  Run = pHelmIvP @ NewConsole = false\n}\n\n"
        "ProcessConfig = pHelmIvP\n{\n  behaviors = abe.bhv\n}\n"
    )
    store = tmp_path / "cache"
    settings = resolve_settings([project], None)
    assert not any(d["code"] == "H003" for d in _json(_cached(project, store, settings)))
    (project / ".gitignore").write_text("*.log\n")  # behavior files are committed now
    after = _json(_cached(project, store, settings))
    assert len(counted) == 2
    assert [d["code"] for d in after if d["code"] == "H003"] == ["H003"]


def test_the_cache_notices_a_changed_launch_script_in_the_folder_above(tmp_path, counted):
    """A launch script above the linted folder that runs nsplug on one of its templates
    decides where nsplug looks for the template's includes (its working folder)."""
    project = tmp_path / "project"
    (project / ".git").mkdir(parents=True)
    bhvs = project / "bhvs"
    (bhvs / "plugs").mkdir(parents=True)
    (bhvs / "meta_loiter.bhv").write_text("#include bhvs/plugs/plug_return.bhv\n")
    (bhvs / "plugs" / "plug_return.bhv").write_text("initialize RETURN = false\n")
    script = project / "launch.sh"
    script.write_text("nsplug bhvs/meta_loiter.bhv targ_abe.bhv -f\n")
    store = tmp_path / "cache"
    settings = resolve_settings([bhvs], None)
    assert not any(d["code"] == "P001" for d in _json(_cached(bhvs, store, settings)))
    script.write_text("nsplug meta_loiter.bhv targ_abe.bhv -f\n")  # run from elsewhere now
    after = _json(_cached(bhvs, store, settings))
    assert len(counted) == 2
    assert [d["code"] for d in after if d["code"] == "P001"] == ["P001"]


def test_the_stored_file_list_notices_new_and_removed_files(tree, tmp_path, counted):
    store = tmp_path / "cache"
    _cached(tree, store)
    assert list(store.glob("files-*.json")), "the discovered files were not kept"
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
    _cached(tree, store, settings)
    assert len(counted) == 2


def test_a_corrupt_or_partial_entry_is_ignored(tree, tmp_path, counted):
    store = tmp_path / "cache"
    first = _json(_cached(tree, store))
    (entry,) = store.glob("run-*.json")
    data = entry.read_bytes()
    head, _, body = data.partition(b"\n")
    broken_entries = (
        b"",
        data[: len(data) // 2],
        b"not json at all",
        b"\x80\x04K\x01.",
        body,  # unsealed
        head + b"\n" + body + b" ",  # changed after sealing (still valid JSON)
    )
    for broken in broken_entries:
        entry.write_bytes(broken)
        assert _json(_cached(tree, store)) == first
    assert len(counted) == 1 + len(broken_entries)
    # a partial temporary file left by a killed run is harmless too
    (store / ".tmp-x.part").write_bytes(data[:10])
    assert _json(_cached(tree, store)) == first
    assert len(counted) == 1 + len(broken_entries)


def test_the_cache_writes_only_its_folder_and_no_cache_writes_nothing(
    tree, tmp_path, monkeypatch, capsys
):
    monkeypatch.delenv("MOOS_LINT_CACHE_DIR", raising=False)
    user = tmp_path / "user-cache"
    monkeypatch.setenv("XDG_CACHE_HOME", str(user))
    monkeypatch.chdir(tree)

    def listing(root):
        return sorted(str(p.relative_to(root)) for p in root.rglob("*"))

    before = listing(tree)
    main(["check", ".", "--no-cache", "--output-format", "json"])
    assert listing(tree) == before and not user.exists()
    main(["check", ".", "--output-format", "json"])
    assert listing(tree) == before
    written = listing(user)
    assert "moos-lint/key" in written
    assert (user / "moos-lint" / "key").stat().st_mode & 0o777 == 0o600
    runs = [p for p in written if p.endswith(".json") and "/run-" in p]
    assert len(runs) == 1 and runs[0].count("/") == 2  # moos-lint/<project>/run-KEY.json
    capsys.readouterr()


def test_cache_dir_in_the_config_stays_in_the_project(tree, tmp_path, monkeypatch):
    from moos_lint.core.config import ConfigError

    monkeypatch.delenv("MOOS_LINT_CACHE_DIR", raising=False)
    (tree / "moos-lint.toml").write_text('cache-dir = "../elsewhere"\n')
    with pytest.raises(ConfigError, match="cache-dir"):
        _settings(tree)
    (tree / "moos-lint.toml").write_text('cache-dir = ".cache/moos-lint"\n')
    settings = _settings(tree)
    assert settings.cache_dir == str((tree / ".cache" / "moos-lint").resolve())
    folder = result_cache.cache_folder(settings, [tree], None)
    assert folder is not None and folder.path == settings.cache_dir


# ------------------------------------------------------------------ --jobs
def _fixture_report(jobs: int) -> str:
    """The JSON report of the fixtures, linted with ``jobs`` processes (fresh settings;
    one job: no worker module at all)."""
    settings = resolve_settings([FIXTURES], None)
    workers = parallel if jobs > 1 else None
    return render("json", engine.lint_paths([FIXTURES], settings, jobs=jobs, parallel=workers))


@pytest.mark.skipif(not parallel.can_fork(), reason="worker processes need fork")
def test_jobs_2_gives_the_output_of_jobs_1():
    settings = resolve_settings([FIXTURES], None)
    files = engine.discover([FIXTURES], settings.exclude, settings.root).files
    assert parallel.effective_jobs(2, len(files)) == 2  # the pool really runs
    one = _fixture_report(jobs=1)
    two = _fixture_report(jobs=2)
    assert json.loads(two) == json.loads(one)
    assert two == one


def test_jobs_must_be_positive(capsys):
    with pytest.raises(SystemExit):
        main(["check", ".", "--jobs", "0"])
    assert "--jobs" in capsys.readouterr().err


def _die(*args):
    """In a worker: die at once, as a crash in a parser would (picklable by name)."""
    os._exit(3)


@pytest.mark.skipif(not parallel.can_fork(), reason="worker processes need fork")
@pytest.mark.parametrize("phase", ["_cpp_folder", "_unit_rules"])
def test_a_dying_worker_never_hangs_the_run(monkeypatch, phase):
    one = _fixture_report(jobs=1)
    monkeypatch.setattr(parallel, phase, _die)
    two = _fixture_report(jobs=2)
    assert two == one


_RULE_BATCHES_DONE: list[int] = []


def _die_after_one(b, batch):
    """In a rule worker: check one folder, then die part way through the next."""
    if _RULE_BATCHES_DONE:
        os._exit(3)
    _RULE_BATCHES_DONE.append(b)
    return _REAL_UNIT_RULES(b, batch)


_REAL_UNIT_RULES = parallel._unit_rules


@pytest.mark.skipif(not parallel.can_fork(), reason="worker processes need fork")
def test_a_rule_worker_that_dies_part_way_keeps_what_it_wrote(monkeypatch):
    """The folders a dying rule worker finished count; the one it died in is checked again
    by the main process, and the output is that of one process."""
    one = _fixture_report(jobs=1)
    monkeypatch.setattr(parallel, "_unit_rules", _die_after_one)
    two = _fixture_report(jobs=2)
    assert two == one
    assert not _RULE_BATCHES_DONE  # the worker's count stayed in the worker


@pytest.mark.skipif(not parallel.can_fork(), reason="worker processes need fork")
def test_each_rule_folder_is_taken_once_from_the_queue():
    n = 1000
    queue = parallel._task_queue(n)
    r, w = os.pipe()
    pid = os.fork()
    if pid == 0:  # a second process takes from the same queue
        status = 1
        try:
            got = b"".join(b.to_bytes(4, "little") for b in parallel._take(queue))
            os.write(w, got)
            status = 0
        finally:
            os._exit(status)
    os.close(w)
    here = list(parallel._take(queue))
    os.waitpid(pid, 0)
    there_bytes = b""
    while chunk := os.read(r, 65536):
        there_bytes += chunk
    os.close(r)
    os.close(queue)
    there = [
        int.from_bytes(there_bytes[i : i + 4], "little") for i in range(0, len(there_bytes), 4)
    ]
    assert sorted(here + there) == list(range(n))


@pytest.mark.skipif(not parallel.can_fork(), reason="worker processes need fork")
def test_a_system_without_a_task_pipe_checks_every_unit_here(monkeypatch):
    one = _fixture_report(jobs=1)

    def full(n):
        raise BlockingIOError(11, "Resource temporarily unavailable")

    monkeypatch.setattr(parallel, "_task_queue", full)
    two = _fixture_report(jobs=2)
    assert two == one


def _no_locks(*args, **kwargs):
    raise OSError(38, "Function not implemented")  # sem_open without /dev/shm


@pytest.mark.skipif(not parallel.can_fork(), reason="worker processes need fork")
@pytest.mark.parametrize("missing", ["Claims", "pool"])
def test_a_system_without_process_locks_runs_in_one_process(monkeypatch, missing):
    """Where a pool or its shared claims cannot be made (no ``/dev/shm`` in a container),
    ``--jobs 2`` gives the output of one process, with no traceback."""
    one = _fixture_report(jobs=1)
    if missing == "pool":
        monkeypatch.setattr("concurrent.futures.ProcessPoolExecutor", _no_locks)
    else:
        monkeypatch.setattr(parallel, "Claims", _no_locks)
    two = _fixture_report(jobs=2)
    assert two == one


def _shown(path: str) -> list[tuple]:
    from moos_lint.commands.lsp.analysis import analyse

    text = Path(path).read_text(encoding="utf-8", errors="replace")
    found = analyse(path, {path: text}).findings
    return sorted((f.diagnostic.code, f.span.line, f.span.col, f.diagnostic.message) for f in found)


def test_the_server_checks_only_units_that_can_report_in_the_document(monkeypatch):
    """Re-linting a document checks its own unit and the units that include or use it, and
    shows exactly what checking every neighbour shows."""
    from moos_lint.commands.lsp import analysis

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


def test_expansions_kept_across_runs_see_every_change_to_what_they_read(tmp_path):
    """The language server keeps expansions between runs: an edit in the editor or on
    disk, other defines, or an include that now exists is seen at once."""
    from moos_lint.files.source import SourceFile, split_lines
    from moos_lint.frontends import nsplug
    from moos_lint.frontends.nsplug import ExpansionStore, FileCache, Preprocessor

    mission = "#include plug.moos\n#include later.moos\nA = $(X)\n"
    (tmp_path / "m.moos").write_text(mission)
    plug = tmp_path / "plug.moos"
    plug.write_text("B = 2\n")
    store = ExpansionStore()

    def run(texts=None, defines=None) -> list[str]:
        def reader(p):
            text = (texts or {}).get(str(p))
            if text is not None:
                return SourceFile(path=p, text=text, lines=split_lines(text))
            return nsplug.read_source(p)

        pre = Preprocessor(defines=defines, cache=FileCache(reader=reader, store=store))
        pre.memo = {}
        return [line.text for line in pre.expand(tmp_path / "m.moos").lines]

    first = run()
    assert "B = 2" in first and "A = 7" not in first
    assert run() == first
    assert "B = 3" in run(texts={str(plug): "B = 3\n"})  # edited in the editor
    assert run() == first
    plug.write_text("B = 4\n")  # edited on disk
    assert "B = 4" in run()
    assert "A = 7" in run(defines={"X": "7"}) and "A = 7" not in run()
    (tmp_path / "later.moos").write_text("C = 5\n")  # an include that now exists
    assert "C = 5" in run()


def _cli_run(args, cwd):
    return subprocess.run(
        [sys.executable, "-m", "moos_lint", *args],
        capture_output=True,
        text=True,
        timeout=120,
        cwd=cwd,
    )


def test_an_unchanged_run_prints_the_same_report_and_status(tree, tmp_path):
    store = str(tmp_path / "cache")
    (tree / "plug.moos").write_text(PLUG + "}\n")  # a finding, so exit status 1
    base = ["check", str(tree), "--cache-dir", store]
    first = _cli_run(base, tree)
    assert first.returncode == 1 and "R0" in first.stdout
    again = _cli_run(base, tree)
    assert again.stdout == first.stdout and again.returncode == 1
    # other options, formats and folders are other reports
    zero = _cli_run([*base, "--exit-zero"], tree)
    assert zero.returncode == 0 and zero.stdout == first.stdout
    as_json = _cli_run([*base, "--output-format", "json"], tree)
    assert json.loads(as_json.stdout) and as_json.returncode == 1
    elsewhere = _cli_run(base, tmp_path)
    assert elsewhere.stdout != first.stdout  # paths are shown relative to the working folder
    # a path that does not exist is a usage error, replayed or not
    missing = ["check", str(tree), str(tree / "nope.moos"), "--cache-dir", store]
    for _ in range(2):
        proc = _cli_run(missing, tree)
        assert proc.returncode == 2 and "nope.moos" in proc.stderr
    # a changed file is linted again, and its report is the fresh one
    (tree / "plug.moos").write_text(PLUG)
    changed = _cli_run(base, tree)
    fresh = _cli_run([*base[:2], "--no-cache"], tree)
    assert changed.stdout == fresh.stdout != first.stdout
    assert changed.returncode == fresh.returncode


# ------------------------------------------------------------------ the program's exit


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
