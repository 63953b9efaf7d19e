"""Linting runs nothing from the linted repository and writes nothing into it.

A linted tree may hold build files, scripts, Python modules and a
compile_commands.json. moos-lint reads mission, behavior and C++ files; it never
runs CMake, make, a script, or a plugin that a repository's configuration names
(an unknown configuration key is an error). Only ``--fix`` writes files; every
other command leaves the tree byte-for-byte and mtime-for-mtime as it was.
"""

from __future__ import annotations

import hashlib
import json
import os
import re
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

from tests.fixture_expect import FIXTURES

TIMEOUT = 180


def run_cli(*args: str, cwd: Path, timeout: float = TIMEOUT) -> subprocess.CompletedProcess:
    env = {k: v for k, v in os.environ.items() if k not in ("GITHUB_ACTIONS", "GITLAB_CI")}
    return subprocess.run(
        [sys.executable, "-m", "moos_lint", *args],
        cwd=cwd,
        env=env,
        stdin=subprocess.DEVNULL,
        capture_output=True,
        text=True,
        timeout=timeout,
    )


def snapshot(root: Path) -> dict[str, tuple]:
    """Every entry under ``root``: its type, mode, mtime and, for files, a hash of its bytes."""
    out: dict[str, tuple] = {}
    for dirpath, dirnames, filenames in os.walk(root):
        for name in dirnames + filenames:
            path = os.path.join(dirpath, name)
            st = os.lstat(path)
            digest = None
            if os.path.isfile(path) and not os.path.islink(path):
                with open(path, "rb") as fh:
                    digest = hashlib.sha256(fh.read()).hexdigest()
            elif os.path.islink(path):
                digest = os.readlink(path)
            out[os.path.relpath(path, root)] = (st.st_mode, st.st_mtime_ns, st.st_size, digest)
    return out


def traps(tree: Path, markers: Path) -> None:
    """Files that leave a marker in ``markers`` if anything runs or imports them."""
    markers.mkdir(exist_ok=True)

    def mark(name: str) -> str:
        return str(markers / name)

    (tree / "CMakeLists.txt").write_text(
        f'cmake_minimum_required(VERSION 3.5)\nfile(WRITE "{mark("cmake")}" "ran")\n'
    )
    (tree / "Makefile").write_text(f"all:\n\ttouch {mark('make')}\n")
    for script in ("build.sh", "launch.sh", "clean.sh"):
        path = tree / script
        path.write_text(f"#!/bin/sh\ntouch {mark(script)}\n")
        path.chmod(0o755)
    for module in ("evil_plugin", "moos_lint_plugin", "plugins"):
        (tree / f"{module}.py").write_text(
            f"open({mark(module)!r}, 'w').write('imported')\ndef check(ctx):\n    return []\n"
        )
    (tree / "compile_commands.json").write_text(
        json.dumps(
            [
                {
                    "directory": str(tree),
                    "command": f"touch {mark('compile-command')}",
                    "file": "pApp/App.cpp",
                }
            ]
        )
    )
    app = tree / "pApp"
    app.mkdir(exist_ok=True)
    (app / "App.cpp").write_text(
        '#include "App.h"\n'
        "bool App::OnNewMail(MOOSMSG_LIST &NewMail) { return true; }\n"
        'bool App::OnStartUp() { Register("NAV_X", 0); Notify("DESIRED_SPEED", 1.0); '
        "return true; }\n"
    )
    (app / "App.h").write_text(
        '#include "MOOS/libMOOS/MOOSLib.h"\nclass App : public CMOOSApp {};\n'
    )
    (app / "CMakeLists.txt").write_text(f'execute_process(COMMAND touch "{mark("cmake-app")}")\n')


def check_help() -> str:
    proc = subprocess.run(
        [sys.executable, "-m", "moos_lint", "check", "--help"],
        capture_output=True,
        text=True,
        timeout=60,
    )
    return proc.stdout


def output_formats() -> list[str]:
    """Every output format that ``moos-lint check --help`` offers."""
    m = re.search(r"--output-format \{([^}]*)\}", check_help())
    assert m, "check --help lists no output formats"
    return m.group(1).split(",")


@pytest.fixture(scope="module")
def tree(tmp_path_factory):
    root = tmp_path_factory.mktemp("side-effects")
    tree = root / "tree"
    shutil.copytree(FIXTURES, tree, symlinks=True)
    traps(tree, root / "markers")
    return tree


def test_check_writes_nothing_in_any_output_format(tree):
    markers = tree.parent / "markers"
    before = snapshot(tree)
    help_text = check_help()
    runs = [["check", ".", "--output-format", fmt] for fmt in output_formats()]
    runs += [
        ["check", ".", "--statistics", "--select", "ALL"],
        ["check", "example/alpha.moos", "--context"],
        ["check", "--show-settings"],
        ["expand", "example/alpha.moos"],
        ["rules"],
    ]
    if "--diff" in help_text:  # prints the fixes, writes nothing
        runs.append(["check", ".", "--diff"])
    assert len(runs) >= 7
    for args in runs:
        proc = run_cli(*args, cwd=tree)
        assert proc.returncode in (0, 1), (args, proc.stderr[-2000:])
        assert "Traceback" not in proc.stderr, (args, proc.stderr[-2000:])
        assert snapshot(tree) == before, f"`moos-lint {' '.join(args)}` changed the linted tree"
        assert sorted(os.listdir(markers)) == [], f"`moos-lint {' '.join(args)}` ran something"


def test_the_report_file_is_the_only_file_written(tree, tmp_path):
    before = snapshot(tree)
    report = tmp_path / "report.json"
    proc = run_cli("check", ".", "--output-format", "json", "-o", str(report), cwd=tree)
    assert proc.returncode == 1, proc.stderr
    assert json.loads(report.read_text(encoding="utf-8"))
    assert snapshot(tree) == before
    assert os.listdir(tmp_path) == ["report.json"]


@pytest.mark.parametrize(
    ("name", "text"),
    [
        ("moos-lint.toml", 'plugins = ["evil_plugin"]\n'),
        (".moos-lint.toml", 'plugin = "evil_plugin:check"\n'),
        ("moos-lint.toml", '[plugins]\nevil = "evil_plugin"\n'),
        ("pyproject.toml", '[tool.moos-lint]\nplugins = ["evil_plugin"]\n'),
        ("pyproject.toml", '[tool.moos-lint]\nselect = ["ALL"]\nload-plugins = ["evil_plugin"]\n'),
    ],
)
def test_a_config_naming_plugins_is_rejected_and_nothing_runs(tmp_path, name, text):
    tree = tmp_path / "repo"
    tree.mkdir()
    traps(tree, tmp_path / "markers")
    (tree / name).write_text(text)
    (tree / "m.moos").write_text("ServerPort = 9000\n}\n")
    proc = run_cli("check", ".", cwd=tree, timeout=60)
    assert proc.returncode == 2, proc.stdout + proc.stderr
    assert "unknown key" in proc.stderr and name in proc.stderr
    assert "Traceback" not in proc.stderr
    assert proc.stdout == ""  # nothing was linted
    assert os.listdir(tmp_path / "markers") == []
    assert not (tree / "__pycache__").exists()
