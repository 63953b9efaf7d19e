"""The replay of an unchanged run (:mod:`moos_lint.speed.replay`): light, and never stale.

A second identical ``moos-lint check`` prints the first one's report before
argparse loads; anything the report depends on (a linted or included file, a
new file, a config file, the environment, the working folder, moos-lint's own
code) sends the run back to the normal path, which prints the fresh report.
"""

from __future__ import annotations

import json
import os
import subprocess
import sys
from pathlib import Path

import pytest

import moos_lint
from moos_lint.commands.cli import main
from moos_lint.core import engine
from moos_lint.speed import replay
from tests.test_performance import BEHAVIORS, MISSION, PLUG

#: modules the replay must not load (the built-in SHA-256 it may)
HEAVY = (
    "json",
    "re",
    "argparse",
    "pathlib",
    "pickle",
    "hashlib",
    "hmac",
    "_hashlib",
    "moos_lint.speed.cache",
    "moos_lint.core.config",
)


@pytest.fixture
def tree(tmp_path, monkeypatch):
    root = tmp_path / "tree"
    root.mkdir()
    (root / "a.moos").write_text(MISSION)
    (root / "plug.moos").write_text(PLUG + "}\n")  # a stray brace: a finding
    (root / "shared.bhv").write_text(BEHAVIORS)
    monkeypatch.delenv("MOOS_LINT_CACHE_DIR", raising=False)
    monkeypatch.delenv("GITHUB_ACTIONS", raising=False)
    monkeypatch.setenv("XDG_CACHE_HOME", str(tmp_path / "user-cache"))
    monkeypatch.chdir(root)
    return root


def replay_entries(tree: Path) -> list[Path]:
    return list((tree.parent / "user-cache" / "moos-lint" / "replay").glob("replay-*.rec"))


def _run(argv: list[str], capsys) -> tuple[int, str]:
    status = main(list(argv))
    return status, capsys.readouterr().out


def _replayed(argv: list[str], capsys) -> tuple[int, str] | None:
    """What the replay alone prints for ``argv`` (None: it leaves the run to the normal path)."""
    status = replay.replay(list(argv))
    out = capsys.readouterr().out
    if status is None:
        assert out == ""  # a miss prints nothing
        return None
    return status, out


def _fresh(argv: list[str], capsys) -> tuple[int, str]:
    return _run([*argv, "--no-cache"], capsys)


def test_an_unchanged_run_is_replayed_before_argparse_loads(tree):
    code = (
        "import sys\n"
        "before = set(sys.modules)\n"  # (site hooks may import some)
        "from moos_lint.commands.cli import main\n"
        "status = main(['check', '.'])\n"
        "new = set(sys.modules) - before\n"
        f"heavy = {HEAVY!r}\n"
        "print('LOADED', sorted(m for m in new if m in heavy), status)\n"
    )

    def run():
        out = subprocess.run(
            [sys.executable, "-c", code], capture_output=True, text=True, timeout=120, cwd=tree
        )
        assert out.returncode == 0, out.stderr
        return out.stdout.rpartition("LOADED ")

    report, _, loaded = run()
    assert "argparse" in loaded and loaded.strip().endswith(" 1")  # the first run lints
    again, _, loaded = run()
    assert loaded.strip() == "[] 1", loaded
    assert again == report and "R0" in report
    assert replay_entries(tree)
    assert not (tree / ".moos_lint_cache").exists()


def test_the_replay_prints_what_the_normal_run_prints(tree, capsys):
    for argv in (
        ["check", "."],
        ["."],
        [],
        ["check", ".", "--output-format", "json"],
        ["check", ".", "--statistics", "--exit-zero"],
        ["check", "a.moos", "-q"],
    ):
        first = _run(argv, capsys)
        assert _replayed(argv, capsys) == first == _fresh(argv, capsys), argv


def test_a_repository_with_ignore_files_is_replayed_and_watches_them(tree, capsys):
    """The ignore files that decided what was walked (``.gitignore``, ``.git/info/exclude``)
    are kept in an entry too (the result cache gives their stamps as JSON lists)."""
    (tree / ".git" / "info").mkdir(parents=True)
    (tree / ".git" / "info" / "exclude").write_text("scratch/\n")
    (tree / ".gitignore").write_text("build/\n")
    (tree / "build").mkdir()
    (tree / "build" / "stale.moos").write_text("ProcessConfig = pHelmIvP\n{\n")
    argv = ["check", "."]
    before = _run(argv, capsys)
    assert replay_entries(tree)
    assert _replayed(argv, capsys) == before == _fresh(argv, capsys)
    (tree / ".gitignore").write_text("# build/ is linted now\n")
    assert _replayed(argv, capsys) is None
    after = _run(argv, capsys)
    assert after != before and "stale.moos" in after[1]
    assert _replayed(argv, capsys) == after


@pytest.mark.parametrize(
    "change",
    [
        "edit a linted file",
        "edit an included file",
        "add a mission",
        "add a config file",
        "add a pyproject.toml above",
        "delete a linted file",
    ],
)
def test_a_change_sends_the_run_back_to_the_normal_path(tree, capsys, change):
    argv = ["check", "."]
    before = _run(argv, capsys)
    assert _replayed(argv, capsys) == before
    if change == "edit a linted file":
        (tree / "a.moos").write_text(MISSION + "ProcessConfig = uTimerScript\n{\n")
    elif change == "edit an included file":
        (tree / "plug.moos").write_text(PLUG)
    elif change == "add a mission":
        (tree / "b.moos").write_text("ProcessConfig = pHelmIvP\n{\n")
    elif change == "add a config file":
        (tree / "moos-lint.toml").write_text('ignore = ["R"]\n')
    elif change == "add a pyproject.toml above":
        (tree.parent / "pyproject.toml").write_text('[tool.moos-lint]\nignore = ["R"]\n')
    elif change == "delete a linted file":
        (tree / "shared.bhv").unlink()
    assert _replayed(argv, capsys) is None
    after = _run(argv, capsys)
    assert after == _fresh(argv, capsys)
    assert after != before
    assert _replayed(argv, capsys) == after  # and the fresh report is kept in its turn


def test_a_file_whose_name_is_not_utf8_is_watched_and_shown_by_its_own_name(tree, capsysbinary):
    odd = os.path.join(os.fsencode(tree), b"plug_caf\xe9.moos")  # a Latin-1 name
    with open(odd, "wb") as fh:
        fh.write(b"ProcessConfig = uXMS\n{\n}\n}\n")  # a stray brace: a finding there
    argv = ["check", "."]

    def lint():
        status = main(list(argv))
        return status, capsysbinary.readouterr().out

    before = lint()
    assert b"plug_caf\xe9.moos:4" in before[1]  # the name as the file system holds it
    status = replay.replay(list(argv))
    assert (status, capsysbinary.readouterr().out) == before  # watched by its own bytes
    with open(odd, "ab") as fh:
        fh.write(b"}\n")  # a second stray brace
    assert replay.replay(list(argv)) is None
    after = lint()
    assert b"plug_caf\xe9.moos:5" in after[1]


def test_a_touched_file_is_checked_by_content_then_replayed_again(tree, capsys):
    argv = ["check", "."]
    before = _run(argv, capsys)
    st = os.stat(tree / "shared.bhv")
    os.utime(tree / "shared.bhv", ns=(st.st_atime_ns, st.st_mtime_ns + 5_000_000_000))
    assert _replayed(argv, capsys) is None  # (mtime, size) changed: the cache compares content
    assert _run(argv, capsys) == before
    assert _replayed(argv, capsys) == before


def test_another_command_line_folder_or_environment_is_not_replayed(tree, capsys, monkeypatch):
    argv = ["check", "."]
    _run(argv, capsys)
    assert _replayed(["check", ".", "--exit-zero"], capsys) is None
    monkeypatch.setenv("GITHUB_ACTIONS", "true")  # the default format becomes github
    assert _replayed(argv, capsys) is None
    assert "::error" in _run(argv, capsys)[1] or "::warning" in _run(argv, capsys)[1]
    monkeypatch.delenv("GITHUB_ACTIONS")
    sub = tree / "sub"
    sub.mkdir()
    monkeypatch.chdir(sub)
    assert _replayed(["check", ".."], capsys) is None


def test_changed_moos_lint_code_is_not_replayed(tree, capsys, monkeypatch, tmp_path):
    own = tmp_path / "own"
    own.mkdir()
    (own / "rule.py").write_text("x = 1\n")
    monkeypatch.setattr(replay, "_PACKAGE", str(own))
    argv = ["check", "."]
    before = _run(argv, capsys)
    assert _replayed(argv, capsys) == before
    (own / "rule.py").write_text("x = 22\n")
    assert _replayed(argv, capsys) is None


def test_a_corrupt_unsealed_or_misshapen_entry_is_a_miss(tree, capsys):
    from moos_lint.speed.cache_files import seal, user_key

    argv = ["check", "."]
    before = _run(argv, capsys)
    (entry,) = replay_entries(tree)
    data = entry.read_bytes()
    head, _, body = data.partition(b"\n")
    key = user_key(create=False)
    fields = body.split(b"\0")
    assert fields[1] == b"1"  # the status
    misshapen = [
        b"\0".join([fields[0], b"2", *fields[2:]]),  # a status the run never gives
        b"\0".join([*fields[:2], b"-1", *fields[3:]]),  # a negative count
        b"\0".join([*fields[:2], b"x", *fields[3:]]),  # a count that is no number
        b"\0".join(fields[:-3] + fields[-1:]),  # a stamp short
        b"\0".join([b"[]", *fields[1:]]),  # another identity
        json.dumps({"identity": [], "files": [], "text": "R0", "status": 1}).encode(),
        b"[1, 2]",
    ]
    for broken in (
        b"",
        data[: len(data) // 2],
        b"not an entry",
        b"\xe9\x00",
        body,  # the entry without its seal
        head + b"\n" + body.replace(b"R0", b"X0"),  # text changed after sealing
        seal(b"k" * 32, entry.name, body),  # sealed under another key
        *(seal(key, entry.name, m) for m in misshapen),  # sealed, but not the layout
    ):
        entry.write_bytes(broken)
        assert _replayed(argv, capsys) is None
        assert _run(argv, capsys) == before


def test_no_entry_without_the_cache(tree, capsys):
    _run(["check", ".", "--no-cache"], capsys)
    assert not (tree / ".moos_lint_cache").exists()
    assert not (tree.parent / "user-cache").exists()
    assert _replayed(["check", "."], capsys) is None


def test_a_report_written_to_a_file_is_written_again(tree, capsys):
    argv = ["check", ".", "-o", "report.txt", "--output-format", "json"]
    # the first run creates report.txt in the linted folder, which changes the folder
    for _ in range(2):
        status, out = _run(argv, capsys)
    report = (tree / "report.txt").read_text(encoding="utf-8")
    assert out == "" and '"code"' in report
    (tree / "report.txt").write_text("stale\n", encoding="utf-8")
    assert _replayed(argv, capsys) == (status, "")
    assert (tree / "report.txt").read_text(encoding="utf-8") == report


def test_the_entry_is_found_from_the_cache_dir_option_and_the_environment(
    tree, capsys, monkeypatch, tmp_path
):
    store = tmp_path / "store"
    argv = ["check", ".", "--cache-dir", str(store)]
    before = _run(argv, capsys)
    assert list(store.glob("replay-*.rec"))
    assert _replayed(argv, capsys) == before
    monkeypatch.setenv("MOOS_LINT_CACHE_DIR", str(tmp_path / "env-store"))
    argv = ["check", "."]
    before = _run(argv, capsys)
    assert list(Path(tmp_path / "env-store").glob("replay-*.rec"))
    assert _replayed(argv, capsys) == before


def test_a_list_of_files_as_pre_commit_passes_them(tree, capsys):
    argv = ["check", "a.moos", "plug.moos", "shared.bhv"]
    before = _run(argv, capsys)
    assert _replayed(argv, capsys) == before
    assert _replayed(["check", "a.moos", "shared.bhv"], capsys) is None  # another list
    (tree / "shared.bhv").write_text(BEHAVIORS + "\nBehavior = BHV_Loiter\n{\n")
    assert _replayed(argv, capsys) is None
    assert _run(argv, capsys) == _fresh(argv, capsys) != before


def test_a_second_checkout_of_the_same_version_lints_afresh(tree, tmp_path):
    """The replay is keyed on where moos-lint is installed: another checkout of the same
    version (its code edited, say) never prints the report the first checkout left."""
    import shutil

    checkout = tmp_path / "checkout"
    package = Path(moos_lint.__file__).resolve().parent
    shutil.copytree(package, checkout / "moos_lint", ignore=shutil.ignore_patterns("__pycache__"))
    linted = tmp_path / "linted-by-the-second-checkout"
    engine_file = Path(engine.__file__).resolve().relative_to(package)
    with open(checkout / "moos_lint" / engine_file, "a", encoding="utf-8") as fh:
        fh.write(f"\nopen({str(linted)!r}, 'w').close()  # this checkout lints\n")

    def run(pythonpath: str | None) -> subprocess.CompletedProcess:
        env = {k: v for k, v in os.environ.items() if k != "PYTHONPATH"}
        if pythonpath:
            env["PYTHONPATH"] = pythonpath
        cmd = [sys.executable, "-m", "moos_lint", "check", "."]
        return subprocess.run(cmd, capture_output=True, text=True, timeout=120, cwd=tree, env=env)

    first = run(None)
    assert first.returncode == 1 and "R0" in first.stdout, first.stderr
    assert replay_entries(tree)  # an entry to replay
    assert not linted.exists()
    second = run(str(checkout))
    assert second.returncode == 1, second.stderr
    assert linted.exists(), "the second checkout printed the first checkout's stored report"
    assert second.stdout == first.stdout
