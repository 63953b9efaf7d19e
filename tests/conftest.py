"""The test session keeps moos-lint's result cache in a temporary folder.

Many tests check that a lint run leaves the linted tree untouched, byte for
byte; the cache (on by default, in ``.moos_lint_cache`` in the project root)
goes to a folder of its own instead, through ``MOOS_LINT_CACHE_DIR``, which
every subprocess inherits. The cache's own tests set their folder explicitly.
"""

from __future__ import annotations

import os
import shutil
import tempfile

_CACHE: str | None = None


def pytest_configure(config):
    global _CACHE
    if "MOOS_LINT_CACHE_DIR" not in os.environ:
        _CACHE = tempfile.mkdtemp(prefix="moos-lint-test-cache-")
        os.environ["MOOS_LINT_CACHE_DIR"] = _CACHE


def pytest_unconfigure(config):
    if _CACHE is not None:
        os.environ.pop("MOOS_LINT_CACHE_DIR", None)
        shutil.rmtree(_CACHE, ignore_errors=True)


def pytest_addoption(parser):
    parser.addoption(
        "--snapshot-update",
        action="store_true",
        default=False,
        help="rewrite the rules' snapshots (fixtures/rules/<rule>/snapshot.txt) from what "
        "the rules report now; review their diff like code",
    )
