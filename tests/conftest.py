"""The test session never sees a developer's own cache, nor writes into it.

moos-lint keeps its cache in the user's cache folder (``$XDG_CACHE_HOME/moos-lint``,
``~/.cache/moos-lint`` by default). The session points ``XDG_CACHE_HOME`` at a
temporary folder of its own, which every subprocess inherits, and drops
``MOOS_LINT_CACHE_DIR``, so every test runs with the cache where a user's run
keeps it (and where the cache's own tests look for it).
"""

from __future__ import annotations

import os
import shutil
import tempfile

_CACHE: str | None = None
_SAVED: dict[str, str | None] = {}


def pytest_configure(config):
    global _CACHE
    _CACHE = tempfile.mkdtemp(prefix="moos-lint-test-cache-")
    for name in ("XDG_CACHE_HOME", "MOOS_LINT_CACHE_DIR"):
        _SAVED[name] = os.environ.pop(name, None)
    os.environ["XDG_CACHE_HOME"] = _CACHE


def pytest_unconfigure(config):
    for name, value in _SAVED.items():
        if value is None:
            os.environ.pop(name, None)
        else:
            os.environ[name] = value
    if _CACHE is not None:
        shutil.rmtree(_CACHE, ignore_errors=True)


def pytest_addoption(parser):
    parser.addoption(
        "--snapshot-update",
        action="store_true",
        default=False,
        help="rewrite the rules' snapshots (fixtures/rules/<rule>/snapshot.txt) from what "
        "the rules report now; review their diff like code",
    )
