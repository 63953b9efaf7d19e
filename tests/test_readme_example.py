"""The README opens with a real run: its example output is what ``moos-lint`` prints."""

from __future__ import annotations

import os
import re
import subprocess
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent


def test_the_first_example_is_the_real_output():
    text = (ROOT / "README.md").read_text(encoding="utf-8")
    block = re.search(
        r"<!-- example:start -->\n```console\n\$ (moos-lint [^\n]*)\n(.*?)```\n"
        r"<!-- example:end -->",
        text,
        re.S,
    )
    assert block, "the README's first example is missing"
    command, shown = block.group(1).split(), block.group(2)
    assert text.index("<!-- example:start -->") < 2000  # on the first screen
    env = {k: v for k, v in os.environ.items() if k not in ("FORCE_COLOR", "GITHUB_ACTIONS")}
    proc = subprocess.run(
        [sys.executable, "-m", "moos_lint", *command[1:], "--no-cache"],
        cwd=ROOT,
        capture_output=True,
        text=True,
        env=env,
    )
    assert proc.returncode == 1
    assert proc.stdout == shown
    assert proc.stdout.count(": M") == 2  # two mistakes
