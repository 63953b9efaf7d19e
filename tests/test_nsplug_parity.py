"""nsplug parity: nsplug's own test suites, run through `moos-lint expand`.

The cases are files of the MOOS-IvP repository (GPL), never copied here: the
test reads them from a MOOS-IvP checkout named by ``MOOS_IVP_TREE`` and skips
without one. ``testcases2`` is run as its ``verify.sh`` runs it: each
``File: NAME`` section is written out line by line (as ``read -r`` and an
unquoted ``echo`` do), the ``Args:`` line of a ``*_beg.txt`` file gives the
command-line arguments, and the result must equal ``*_tar.txt`` under
``diff -B -b``. The older ``testcases`` set has no expected files; its
``#ifdef`` suites print ``PASS`` or ``FAIL`` lines, and no ``FAIL`` may be left.

Run: ``MOOS_IVP_TREE=/path/to/moos-ivp python -m pytest tests/test_nsplug_parity.py``
"""

from __future__ import annotations

import contextlib
import io
import os
from pathlib import Path

import pytest

from moos_lint.commands.cli import main

TREE = os.environ.get("MOOS_IVP_TREE", "")
APP = Path(TREE) / "ivp" / "src" / "app_nsplug" if TREE else None
pytestmark = pytest.mark.skipif(
    APP is None or not (APP / "testcases2").is_dir(),
    reason="set MOOS_IVP_TREE to a MOOS-IvP checkout to run nsplug's own test suites",
)


def split_cases(folder: Path) -> dict[str, list[str]]:
    """The files verify.sh writes from every ``test*.txt`` (name -> lines)."""
    files: dict[str, list[str]] = {}
    for test in sorted(folder.glob("test*.txt")):
        current = None
        for raw in test.read_text(encoding="utf-8", errors="replace").splitlines():
            line = raw.strip(" \t")  # read -r strips the IFS blanks at both ends
            if not line.strip() or line.startswith("//"):
                continue
            if line.startswith("File:"):
                current = line[len("File:") :].strip()
                files.setdefault(current, [])
            elif current:
                files[current].append(" ".join(line.split()))  # echo $line
    return files


def expand(path: Path, args: list[str]) -> str:
    argv = ["expand", path.name]
    for a in args:
        if a in ("--lenient", "-l"):
            argv.append("--lenient")
        elif a.startswith("-"):
            continue  # -f, --strict: no effect on the output
        else:
            argv += ["--define", a]
    out = io.StringIO()
    here = os.getcwd()
    os.chdir(path.parent)  # nsplug looks for includes in the folder it runs in
    try:
        with contextlib.redirect_stdout(out), contextlib.redirect_stderr(io.StringIO()):
            main(argv)
    finally:
        os.chdir(here)
    return out.getvalue()


def _diff_b_B(text: str) -> list[str]:
    """Lines as ``diff -B -b`` compares them: blank runs squeezed, blank lines ignored."""
    return [" ".join(line.split()) for line in text.splitlines() if line.strip()]


def _cases() -> list[str]:
    if APP is None or not (APP / "testcases2").is_dir():
        return []
    return sorted(n for n in split_cases(APP / "testcases2") if n.endswith("_beg.txt"))


@pytest.mark.parametrize("beg", _cases())
def test_testcases2(beg, tmp_path):
    files = split_cases(APP / "testcases2")
    lines = files[beg]
    assert lines and lines[0].startswith("Args:"), beg
    args = lines[0][len("Args:") :].split()
    for name, body in files.items():  # verify.sh writes every file in its folder
        (tmp_path / name).write_text("\n".join(body) + "\n", encoding="utf-8")
    src = tmp_path / beg
    src.write_text("\n".join(lines[1:]) + "\n", encoding="utf-8")
    target = "\n".join(files[beg.replace("_beg.txt", "_tar.txt")])
    assert _diff_b_B(expand(src, args)) == _diff_b_B(target)


@pytest.mark.parametrize("name", ["test_ifdef.txt", "test_nested.txt"])
def test_testcases_pass_fail(name, tmp_path):
    text = (APP / "testcases" / name).read_text(encoding="utf-8", errors="replace")
    src = tmp_path / name
    src.write_text(text, encoding="utf-8")
    out = expand(src, [])
    assert "PASS" in out
    assert [line for line in out.splitlines() if "FAIL" in line] == []
