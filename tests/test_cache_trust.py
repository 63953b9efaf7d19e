"""Nothing a repository commits can run code, forge a report or make moos-lint write.

Each test drives the real command line (``python -m moos_lint``) with the real
cache location: ``HOME`` points at a temporary folder and ``XDG_CACHE_HOME``
is unset, so the cache goes where a user's run keeps it
(``~/.cache/moos-lint``), never to a developer's own cache.
"""

from __future__ import annotations

import json
import os
import pickle
import shlex
import shutil
import subprocess
import sys
import zlib
from hashlib import sha256
from pathlib import Path

import pytest

from moos_lint import __version__
from tests.unprivileged import tree_listing, unprivileged

TIMEOUT = 120
MISSION = """ServerHost = localhost
ServerPort = 9000
Community  = alpha

ProcessConfig = ANTLER
{
  Run = MOOSDB @ NewConsole = false
}

ProcessConfig = pLogger {
  AsyncLog = true
}
"""
#: a line moos-lint reports (R012 malformed-line), for the edit made during a run
MALFORMED = "this line is not a MOOS line\n"

#: a run of the real command line, the engine's lint counted (``LINTED`` on stderr)
PROBE = """
import sys
from moos_lint.core import engine
real = engine.lint_files
def lint_files(*a, **kw):
    print("LINTED", file=sys.stderr)
    return real(*a, **kw)
engine.lint_files = lint_files
from moos_lint.commands.cli import main
sys.exit(main(sys.argv[1:]))
"""


class World:
    def __init__(self, tmp_path: Path) -> None:
        self.home = tmp_path / "home"
        self.home.mkdir()
        self.tree = tmp_path / "work" / "repo"
        self.tree.mkdir(parents=True)
        (self.tree / "alpha.moos").write_text(MISSION)
        self.marker = tmp_path / "ran"
        self.cache = self.home / ".cache" / "moos-lint"

    def env(self) -> dict[str, str]:
        drop = ("GITHUB_ACTIONS", "GITLAB_CI", "MOOS_LINT_CACHE_DIR", "XDG_CACHE_HOME")
        env = {k: v for k, v in os.environ.items() if k not in drop}
        env["HOME"] = str(self.home)
        return env

    def cli(self, *args: str, cwd: Path | None = None, probe: bool = False):
        head = ["-c", PROBE] if probe else ["-m", "moos_lint"]
        proc = subprocess.run(
            [sys.executable, *head, *args],
            cwd=cwd or self.tree,
            env=self.env(),
            stdin=subprocess.DEVNULL,
            capture_output=True,
            text=True,
            timeout=TIMEOUT,
        )
        assert "Traceback" not in proc.stderr, proc.stderr
        return proc

    def entries(self) -> list[Path]:
        return sorted(p for p in self.cache.rglob("*") if p.suffix in (".json", ".rec"))


@pytest.fixture
def world(tmp_path):
    return World(tmp_path)


def listing(root: Path) -> list[str]:
    return sorted(str(p.relative_to(root)) for p in root.rglob("*"))


class Payload:
    """A pickle that runs a command when it is loaded."""

    def __init__(self, marker: Path) -> None:
        self.marker = marker

    def __reduce__(self):
        return (os.system, (f"touch {self.marker}",))


def hostile_entries(world: World) -> list[bytes]:
    """What a pull request can commit under a cache entry's name."""
    fake_replay = {
        "identity": [],
        "files": [],
        "dirs": [],
        "exist": [],
        "text": "forged\n",
        "status": 0,
    }
    return [
        pickle.dumps(Payload(world.marker)),
        b"\x80\x04corrupt",
        b"moos-lint-entry 3 " + b"0" * 64 + b"\n" + json.dumps(fake_replay).encode(),
        json.dumps(fake_replay).encode(),
        b"{",
    ]


def old_names(world: World, argv: list[str]) -> list[str]:
    """The names the earlier pickle and marshal cache used (computable from the path)."""
    tree = str(world.tree)
    files_key = sha256(json.dumps([__version__, 2, [tree], [], tree]).encode()).hexdigest()[:40]
    return [
        f"files-{files_key}.pickle",
        f"run-{files_key}.pickle",
        f"out-{files_key[:24]}-{files_key[:24]}.pickle",
        f"replay-{zlib.crc32(chr(0).join(argv).encode()):08x}.marshal",
    ]


def test_committed_pickles_and_corrupt_entries_under_every_name_are_inert(world):
    argv = ["check", "."]
    fresh = world.cli(*argv, "--no-cache")
    assert fresh.returncode == 1 and "R003" in fresh.stdout
    first = world.cli(*argv)
    assert (first.returncode, first.stdout) == (fresh.returncode, fresh.stdout)
    new_names = world.entries()
    kinds = {p.name.split("-")[0] for p in new_names}
    assert kinds == {"run", "files", "out", "replay"}, new_names
    in_tree = world.tree / ".moos_lint_cache"
    in_tree.mkdir()
    for payload in hostile_entries(world):
        for name in old_names(world, argv):
            (in_tree / name).write_bytes(payload)
        for path in new_names:
            path.write_bytes(payload)
        for args in (argv, [*argv, "--exit-zero"], [*argv, "--output-format", "json"]):
            proc = world.cli(*args)
            fresh = world.cli(*args, "--no-cache")
            assert (proc.returncode, proc.stdout) == (fresh.returncode, fresh.stdout), payload
            assert not world.marker.exists(), "a cache entry ran code"


def test_a_crafted_replay_entry_forges_no_report_and_writes_no_file(world, monkeypatch):
    from moos_lint.speed import replay
    from moos_lint.speed.cache_files import seal, user_key

    victim = world.home / "notes.txt"
    victim.write_text("mine\n")
    argv = ["check", "."]
    real = world.cli(*argv)  # the user's own entries, and the key
    assert real.returncode == 1
    monkeypatch.chdir(world.tree)
    for name, value in world.env().items():
        monkeypatch.setenv(name, value)
    monkeypatch.delenv("XDG_CACHE_HOME", raising=False)
    monkeypatch.delenv("GITHUB_ACTIONS", raising=False)
    name = replay.entry_name(argv)
    entry_path = world.cache / "replay" / name
    assert entry_path.exists()
    forged = {
        "identity": replay.identity(argv),
        "files": [],
        "dirs": [],
        "exist": [],
        "text": "All checks passed (forged)\n",
        "status": 0,
    }
    with_file = dict(forged, output_file=str(victim))
    body = replay.encode(**forged)
    attempts = [
        body,  # not sealed
        seal(os.urandom(32), name, body),  # sealed under a key of the attacker's
        seal(user_key(create=False), name, json.dumps(with_file).encode()),  # not the layout
    ]
    # and the earlier format, in the tree, at the name it used
    import marshal

    old = dict(forged, identity=[], output_file=str(victim))
    (world.tree / ".moos_lint_cache").mkdir()
    for attempt in attempts:
        entry_path.write_bytes(attempt)
        for old_name in old_names(world, argv):
            (world.tree / ".moos_lint_cache" / old_name).write_bytes(marshal.dumps(old))
        proc = world.cli(*argv)
        assert (proc.returncode, proc.stdout) == (1, real.stdout)
        assert "forged" not in proc.stdout
        assert victim.read_text() == "mine\n"


def test_a_replayed_report_goes_where_the_command_line_says(world):
    argv = ["check", ".", "-o", "report.txt"]
    for _ in range(3):  # lint, cache, replay
        proc = world.cli(*argv)
        assert proc.returncode == 1 and proc.stdout == ""
    report = (world.tree / "report.txt").read_text()
    assert "R003" in report
    (world.tree / "report.txt").write_text("stale\n")
    assert world.cli(*argv, probe=True).stderr == ""  # replayed: nothing linted
    assert (world.tree / "report.txt").read_text() == report


def _git(tree: Path, *args: str) -> None:
    subprocess.run(
        ["git", "-c", "user.name=t", "-c", "user.email=t@t", *args],
        cwd=tree,
        check=True,
        capture_output=True,
        timeout=60,
    )


@pytest.mark.skipif(shutil.which("git") is None, reason="needs git")
@pytest.mark.parametrize("index_version", ["2", "4"])
def test_cache_entries_that_git_tracks_are_never_read(world, index_version):
    tree = world.tree
    _git(tree, "init", "-q")
    (tree / "moos-lint.toml").write_text('cache-dir = ".lintcache"\n')
    first = world.cli("check", ".", probe=True)
    assert "LINTED" in first.stderr
    assert list((tree / ".lintcache").glob("run-*.json"))
    again = world.cli("check", ".", "--exit-zero", probe=True)
    assert "LINTED" not in again.stderr  # the entries are used while git does not track them
    _git(tree, "add", "-f", ".")
    _git(tree, "update-index", "--index-version", index_version)
    _git(tree, "commit", "-qm", "cache")
    tracked = world.cli("check", ".", "-q", probe=True)  # another command line: no replay
    assert "LINTED" in tracked.stderr
    assert tracked.stdout and tracked.returncode == 1
    status = subprocess.run(
        ["git", "status", "--porcelain"], cwd=tree, capture_output=True, text=True, timeout=60
    )
    assert status.stdout == "", "a tracked cache entry was rewritten"


def test_a_config_cache_dir_outside_the_project_is_an_error(world):
    (world.tree / "moos-lint.toml").write_text('cache-dir = "../outside/deep"\n')
    before = listing(world.tree.parent)
    proc = world.cli("check", ".")
    assert proc.returncode == 2 and "cache-dir" in proc.stderr and "moos-lint.toml" in proc.stderr
    assert listing(world.tree.parent) == before
    # the command line may name any folder
    elsewhere = world.tree.parent / "outside"
    (world.tree / "moos-lint.toml").write_text("")
    proc = world.cli("check", ".", "--cache-dir", str(elsewhere))
    assert proc.returncode == 1 and list(elsewhere.glob("run-*.json"))


@pytest.mark.parametrize(
    "path",
    ["missons/alpha.moos", "missons", "/nonexistent-moos-lint-path", "/nonexistent/deep/x.moos"],
)
def test_a_path_that_does_not_exist_is_a_usage_error_and_creates_nothing(world, path):
    top = sorted(os.listdir("/"))
    tree, home = listing(world.tree), listing(world.home)
    for extra in ([], ["--exit-zero"], ["--output-format", "sarif", "--exit-zero"]):
        proc = world.cli("check", path, *extra)
        assert proc.returncode == 2, proc.stdout + proc.stderr
        assert f"{path}: no such file or directory" in proc.stderr
        assert proc.stdout == ""
    assert listing(world.tree) == tree
    assert listing(world.home) == home
    assert sorted(os.listdir("/")) == top


def test_a_lone_file_outside_any_project_gets_no_cache_beside_it(world, tmp_path):
    lone = tmp_path / "downloads"
    lone.mkdir()
    (lone / "mission.moos").write_text(MISSION)
    before = listing(lone)
    top = sorted(os.listdir("/"))
    proc = world.cli("check", str(lone / "mission.moos"), cwd=world.home)
    assert proc.returncode == 1
    assert listing(lone) == before
    assert sorted(os.listdir("/")) == top
    assert [p.name.split("-")[0] for p in world.entries()].count("run") == 1


def test_no_cache_without_a_home(world):
    env = world.env()
    env["HOME"] = "/"
    top = sorted(os.listdir("/"))
    proc = subprocess.run(
        [sys.executable, "-m", "moos_lint", "check", "."],
        cwd=world.tree,
        env=env,
        capture_output=True,
        text=True,
        timeout=TIMEOUT,
    )
    assert proc.returncode == 1 and "R003" in proc.stdout
    assert sorted(os.listdir("/")) == top


def test_a_read_only_tree_lints_normally():
    # as a user who cannot write the tree, even when the tests run as root
    with unprivileged() as user:
        tree = user.root / "repo"
        tree.mkdir()
        (tree / "alpha.moos").write_text(MISSION)
        (tree / "moos-lint.toml").write_text('cache-dir = ".lintcache"\n')
        fresh = user.cli("check", ".", "--no-cache", cwd=tree)
        assert fresh.returncode == 1 and "alpha.moos:10:1: R003" in fresh.stdout, fresh
        for p in (tree, *tree.iterdir()):
            p.chmod(p.stat().st_mode & ~0o222)
        before = tree_listing(tree)
        for _ in range(2):
            proc = user.cli("check", ".", cwd=tree)
            assert (proc.returncode, proc.stdout) == (fresh.returncode, fresh.stdout)
        assert tree_listing(tree) == before


def test_a_key_that_is_not_private_is_never_used(world):
    assert world.cli("check", ".").returncode == 1
    key = world.cache / "key"
    key.chmod(0o644)  # readable by others: anyone could seal entries
    for entry in world.entries():
        entry.unlink()
    proc = world.cli("check", ".", probe=True)
    assert "LINTED" in proc.stderr and proc.returncode == 1
    assert world.entries() == []


EDIT_DURING_RUN = """
import sys
from moos_lint.speed import cache
real = cache.store
def store(*a, **kw):
    with open("alpha.moos", "a") as fh:  # saved after the lint read it, before the store
        fh.write(MALFORMED)
    return real(*a, **kw)
cache.store = store
from moos_lint.commands.cli import main
sys.exit(main(["check", "."]))
""".replace("MALFORMED", repr(MALFORMED))


def test_a_file_saved_during_a_run_is_reported_by_the_next_run(world):
    before = world.cli("check", ".", "--no-cache")
    assert "R012" not in before.stdout
    during = subprocess.run(
        [sys.executable, "-c", EDIT_DURING_RUN],
        cwd=world.tree,
        env=world.env(),
        capture_output=True,
        text=True,
        timeout=TIMEOUT,
    )
    assert during.stdout == before.stdout  # the run reports what it read
    assert not [p for p in world.entries() if p.name.startswith("run-")]  # and stores nothing
    after = world.cli("check", ".")
    fresh = world.cli("check", ".", "--no-cache")
    assert "R012" in after.stdout
    assert (after.returncode, after.stdout) == (fresh.returncode, fresh.stdout)
    assert world.cli("check", ".").stdout == fresh.stdout  # and is kept in its turn


def test_the_seal_is_rfc_2104_hmac_sha256():
    import hmac

    from moos_lint.speed.cache_files import mac, seal, unseal

    for key in (b"k" * 32, b"", b"x" * 64, b"y" * 100):
        for body in (b"", b"{}", os.urandom(5000)):
            want = hmac.new(key, b"run-1.json\0" + body, "sha256").hexdigest()
            assert mac(key, "run-1.json", body) == want
            assert unseal(key, "run-1.json", seal(key, "run-1.json", body)) == body
            assert unseal(key, "run-2.json", seal(key, "run-1.json", body)) is None


def test_the_suite_never_sees_a_developers_cache():
    assert "moos-lint-test-cache-" in os.environ["XDG_CACHE_HOME"]
    assert "MOOS_LINT_CACHE_DIR" not in os.environ


def test_entries_that_are_links_devices_or_fifos_are_never_read(world):
    (world.tree / "moos-lint.toml").write_text('cache-dir = ".lintcache"\n')
    first = world.cli("check", ".")
    entries = list((world.tree / ".lintcache").glob("*.json"))
    assert entries
    for i, entry in enumerate(entries):
        entry.unlink()
        if i % 2:
            os.symlink("/dev/zero", entry)
        else:
            os.mkfifo(entry)
    proc = world.cli("check", ".", "--exit-zero")  # (would block or never end if read)
    assert proc.returncode == 0 and proc.stdout == first.stdout


def _read_only_mount(tree: Path) -> list[str] | None:
    """A command prefix that runs a program with ``tree`` mounted read-only, or None.

    A read-only bind mount in a private mount namespace binds root too, so this
    checks the read-only tree where dropping privileges is not possible.
    """
    if not shutil.which("unshare") or not hasattr(os, "geteuid") or os.geteuid() != 0:
        return None
    t = shlex.quote(str(tree))
    script = f'mount --bind {t} {t} && mount -o remount,bind,ro {t} {t} && exec "$@"'
    prefix = ["unshare", "-m", "sh", "-c", script, "sh"]
    probe = subprocess.run(
        [*prefix, "sh", "-c", f"! touch {t}/.probe 2>/dev/null"],
        capture_output=True,
        timeout=30,
    )
    return prefix if probe.returncode == 0 else None


def test_a_tree_mounted_read_only_lints_normally(tmp_path):
    tree = tmp_path / "repo"
    tree.mkdir()
    (tree / "alpha.moos").write_text(MISSION)
    (tree / "moos-lint.toml").write_text('cache-dir = ".lintcache"\n')
    prefix = _read_only_mount(tree)
    if prefix is None:
        pytest.skip("no read-only bind mount here (needs root and unshare)")
    env = {k: v for k, v in os.environ.items() if k not in ("GITHUB_ACTIONS", "GITLAB_CI")}
    env["HOME"] = str(tmp_path / "home")
    env["XDG_CACHE_HOME"] = str(tmp_path / "home" / ".cache")
    cmd = [sys.executable, "-m", "moos_lint", "check", "."]
    fresh = subprocess.run([*cmd, "--no-cache"], cwd=tree, env=env, capture_output=True, text=True)
    assert fresh.returncode == 1 and "alpha.moos:10:1: R003" in fresh.stdout, fresh
    before = tree_listing(tree)
    for _ in range(2):
        proc = subprocess.run(
            [*prefix, *cmd], cwd=tree, env=env, capture_output=True, text=True, timeout=120
        )
        assert "Traceback" not in proc.stderr, proc.stderr
        assert (proc.returncode, proc.stdout) == (fresh.returncode, fresh.stdout)
    assert tree_listing(tree) == before
