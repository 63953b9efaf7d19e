"""Make the README's picture of ``moos-lint graph``: ``python scripts/screenshot_graph.py``.

Draws ``fixtures/graph/harbour.moos`` with the installed ``moos-lint`` and takes
a screenshot of the page with headless Chromium (``chromium`` on the PATH, or
``--browser``), written to ``docs/graph.png``. Run it again after changing the
page (``moos_lint/commands/graph_html.py``) and commit the picture.
"""

from __future__ import annotations

import argparse
import shutil
import subprocess
import sys
import tempfile
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
MISSION = ROOT / "fixtures" / "graph" / "harbour.moos"
OUT = ROOT / "docs" / "graph.png"
#: what Chromium needs to start headless without a display, a sandbox or the network
FLAGS = [
    "--headless",
    "--no-sandbox",
    "--disable-gpu",
    "--disable-quic",
    "--no-first-run",
    "--disable-background-networking",
    "--disable-component-update",
    "--disable-sync",
    "--hide-scrollbars",
]


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--browser", default=shutil.which("chromium") or "chromium")
    parser.add_argument("--mission", type=Path, default=MISSION)
    parser.add_argument("--output", type=Path, default=OUT)
    parser.add_argument("--size", default="2160,980", help="window WIDTH,HEIGHT")
    args = parser.parse_args()
    with tempfile.TemporaryDirectory() as tmp:
        page = Path(tmp) / "graph.html"
        subprocess.run(
            [sys.executable, "-m", "moos_lint", "graph", str(args.mission), "-o", str(page)],
            check=True,
        )
        args.output.parent.mkdir(parents=True, exist_ok=True)
        subprocess.run(
            [
                args.browser,
                *FLAGS,
                f"--user-data-dir={Path(tmp) / 'profile'}",
                f"--window-size={args.size}",
                f"--screenshot={args.output.resolve()}",
                page.as_uri(),
            ],
            check=True,
            capture_output=True,
        )
    print(f"wrote {args.output}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
