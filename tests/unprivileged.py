"""The real ``moos-lint`` run by a user without privileges, in a folder that user can read.

File permissions do not bind root: a test of a read-only tree or an unreadable
file proves nothing when it runs as root, as CI does. As root, the command is
run as ``nobody`` (through ``setpriv``, else ``runuser``); as anyone else, as
that user. The test's files live in a fresh folder of the system's temporary
folder, open to others (pytest's own temporary folders are private), with a
home the runner can write for its cache. A test skips only when no tool can
drop the privileges or that user cannot start moos-lint's Python.
"""

from __future__ import annotations

import os
import shutil
import subprocess
import sys
import tempfile
from collections.abc import Iterator
from contextlib import contextmanager
from pathlib import Path

import pytest

#: the uid and gid of ``nobody``
NOBODY = 65534


def _drop_privileges() -> list[str] | None:
    """The command prefix that runs a program without root's privileges, or None."""
    if not hasattr(os, "geteuid") or os.geteuid() != 0:
        return []
    if shutil.which("setpriv"):
        return ["setpriv", f"--reuid={NOBODY}", f"--regid={NOBODY}", "--clear-groups"]
    if shutil.which("runuser"):
        return ["runuser", "-u", "nobody", "--"]
    return None


class Runner:
    """``moos-lint`` as the unprivileged user, with ``home`` as its home and cache."""

    def __init__(self, root: Path, prefix: list[str]) -> None:
        self.root = root
        self.home = root / "home"
        self.prefix = prefix

    def env(self) -> dict[str, str]:
        drop = ("GITHUB_ACTIONS", "GITLAB_CI", "MOOS_LINT_CACHE_DIR", "XDG_CACHE_HOME")
        env = {k: v for k, v in os.environ.items() if k not in drop}
        env["HOME"] = str(self.home)
        env["XDG_CACHE_HOME"] = str(self.home / ".cache")
        return env

    def python(self, *args: str, cwd: Path, timeout: float = 120) -> subprocess.CompletedProcess:
        return subprocess.run(
            [*self.prefix, sys.executable, *args],
            cwd=cwd,
            env=self.env(),
            stdin=subprocess.DEVNULL,
            capture_output=True,
            text=True,
            timeout=timeout,
        )

    def cli(self, *args: str, cwd: Path, timeout: float = 120) -> subprocess.CompletedProcess:
        proc = self.python("-m", "moos_lint", *args, cwd=cwd, timeout=timeout)
        assert "Traceback" not in proc.stderr, proc.stderr
        return proc


@contextmanager
def unprivileged() -> Iterator[Runner]:
    """A :class:`Runner` over a fresh folder others can read (removed afterwards)."""
    prefix = _drop_privileges()
    if prefix is None:
        pytest.skip("running as root, and neither setpriv nor runuser is installed")
    root = Path(tempfile.mkdtemp(prefix="moos-lint-test-"))
    try:
        root.chmod(0o755)
        runner = Runner(root, prefix)
        runner.home.mkdir()
        if prefix:
            os.chown(runner.home, NOBODY, NOBODY)
        probe = runner.python("-c", "import moos_lint", cwd=root, timeout=60)
        if probe.returncode != 0:
            pytest.skip(
                f"the unprivileged user cannot run moos-lint's Python: {probe.stderr[-300:]}"
            )
        yield runner
    finally:
        for folder, dirs, files in os.walk(root):
            for name in (*dirs, *files):
                p = os.path.join(folder, name)
                if not os.path.islink(p):
                    os.chmod(p, 0o700)
        shutil.rmtree(root, ignore_errors=True)


def tree_listing(root: Path) -> list[tuple[str, int, int]]:
    """Every path under ``root`` with its size and modification time, to prove nothing changed."""
    out = []
    for p in sorted(root.rglob("*")):
        st = p.lstat()
        out.append((str(p.relative_to(root)), st.st_size, st.st_mtime_ns))
    return out
