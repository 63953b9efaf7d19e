"""The benchmark script (scripts/benchmark.py) runs end to end; its figures are not judged."""

from __future__ import annotations

import importlib.util
import os
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

from tests.test_performance import _tree

pytestmark = pytest.mark.perf

ROOT = Path(__file__).resolve().parents[2]
SCRIPT = ROOT / "scripts" / "benchmark.py"


def _load():
    if "benchmark_script" not in sys.modules:  # its dataclasses look their module up
        spec = importlib.util.spec_from_file_location("benchmark_script", SCRIPT)
        module = importlib.util.module_from_spec(spec)
        sys.modules[spec.name] = module
        spec.loader.exec_module(module)
    return sys.modules["benchmark_script"]


def _small_tree(tmp_path: Path) -> Path:
    tree = tmp_path / "tree"
    tree.mkdir()
    _tree(tree)
    app = tree / "pApp"
    app.mkdir()
    (app / "App.cpp").write_text('bool App::OnStartUp() { Notify("APP_X", 1); return true; }\n')
    # a repository's ignore files: the replay watches them too
    (tree / ".git" / "info").mkdir(parents=True)
    (tree / ".git" / "info" / "exclude").write_text("scratch/\n")
    (tree / ".gitignore").write_text("build/\n")
    return tree


def _run(*args: str) -> subprocess.CompletedProcess:
    return subprocess.run(
        [sys.executable, str(SCRIPT), *args], capture_output=True, text=True, timeout=300
    )


def _figure(stdout: str, name: str) -> str:
    line = next((ln for ln in stdout.splitlines() if ln.strip().startswith(name)), "")
    assert line, (name, stdout)
    return line.strip()[len(name) :]


def test_the_benchmark_prints_every_figure_with_its_target(tmp_path):
    tree = _small_tree(tmp_path)
    before = sorted(p.name for p in tree.rglob("*"))
    out = _run(str(tree), "--runs", "1")
    assert out.returncode == 0, out.stderr
    for name in (
        "moos-lint check FILES --no-cache",
        "cold, default jobs",
        "cold, -j 1",
        "floor (start, read, tree-sitter)",
        "cold default / floor",
        "cold default / -j 1",
        "every mission file (4)",
        "worst: ",
        "App.cpp (1 lines)",
        "warm (cache filled, nothing changed)",
        "warm runs replayed",
        "moos-lint --version",
        "peak memory, -j 1 (one process)",
        "x16 time",
        "x16 memory",
    ):
        assert any(ch.isdigit() for ch in _figure(out.stdout, name)), (name, out.stdout)
    # a judged figure carries its ratio and a verdict
    assert _figure(out.stdout, "cold default / floor").split()[-1] in ("pass", "MISS")
    assert _figure(out.stdout, "warm runs replayed").split()[-1] == "pass"
    assert "peer" in _figure(out.stdout, "peer")  # not given: said, not run
    assert "took" in _figure(out.stdout, "load: ")  # how busy the machine was
    assert sorted(p.name for p in tree.rglob("*")) == before  # the tree is not written


@pytest.mark.skipif(shutil.which("node") is None, reason="needs node")
def test_the_peer_runs_on_the_same_mission_files(tmp_path):
    tree = _small_tree(tmp_path)
    peer = tmp_path / "peer"
    server = peer / "packages" / "server" / "src"
    server.mkdir(parents=True)
    seen = tmp_path / "seen.txt"
    # a stand-in for the Node server's --check: records its files, one finding on a.moos
    (server / "server.js").write_text(
        "const fs = require('fs');\n"
        "const files = process.argv.slice(process.argv.indexOf('--check') + 1);\n"
        f"fs.writeFileSync({str(seen)!r}, files.join('\\n'));\n"
        "for (const f of files) {\n"
        "  const n = f.endsWith('a.moos') ? 1 : 0;\n"
        "  process.stdout.write(`${f}: ${n} diagnostics\\n`);\n"
        "  if (n) process.stdout.write('  2:12 community expects a name.\\n');\n"
        "}\n"
    )
    out = _run(str(tree), "--runs", "1", "--peer", str(peer), "--only", "missions")
    assert out.returncode == 0, out.stderr
    given = sorted(os.path.basename(p) for p in seen.read_text().splitlines())
    assert given == ["a.moos", "b.moos", "plug.moos", "shared.bhv"]
    assert _figure(out.stdout, "moos-lint / peer, wall").split()[-1] in ("pass", "MISS")
    assert _figure(out.stdout, "findings: moos-lint / peer").split()[-1] == "1"


def test_the_peer_findings_are_read_from_its_check_output():
    bench = _load()
    text = (
        "m/a.moos: 2 diagnostics\n"
        "  3:5 max_speed expects a number > 0.\n"
        "  9:1 points has a malformed point list.\n"
        "m/b.bhv: 0 diagnostics\n"
        "m/c.bhv: 1 diagnostics\n"
        "  4:2 trail_angle expects a number.\n"
    )
    assert bench.peer_findings(text) == {
        (os.path.abspath("m/a.moos"), 3),
        (os.path.abspath("m/a.moos"), 9),
        (os.path.abspath("m/c.bhv"), 4),
    }


def test_the_benchmark_runs_the_console_script_pip_installs():
    import tomllib

    data = tomllib.loads((ROOT / "pyproject.toml").read_text(encoding="utf-8"))
    scripts = data["project"]["scripts"]
    assert scripts["moos-lint"] == _load().ENTRY_POINT
    assert not any("benchmark" in target for target in scripts.values())  # a development script


def test_the_measured_installation_holds_moos_lint_and_its_dependencies_alone(tmp_path):
    inst = _load().clean_install(str(tmp_path))
    probe = (
        "import importlib.util as u, tree_sitter, tree_sitter_cpp, pathspec, moos_lint;"
        "print(u.find_spec('pytest') is None, u.find_spec('typing_extensions') is None)"
    )
    out = subprocess.run(
        [inst.python, "-c", probe], capture_output=True, text=True, env=inst.env, check=True
    )
    assert out.stdout.split() == ["True", "True"]
