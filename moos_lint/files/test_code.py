"""Test programs and test inputs: files whose names are chosen to exercise code.

A core MOOS test program registers for ``la``, ``di`` and ``da`` because its
help text tells the tester to post them (``testing/QueueTest.cpp``); a pShare
test mission launches ``pShare ~ ShareA`` and ``~ ShareB``
(``pshare_test_scripts/``); CMake builds a MOOSDB test as ``app_test``. The
naming conventions are for the programs and missions a robot runs; these names
are dummies, and the naming rules leave such files alone (the rules about what
MOOS does with a file still read them).

A file is test code by its folder, never by its own name: ``sonar_test.moos``
and ``IMUTest.moos`` are most often missions run in the field to test a sensor.
"""

from __future__ import annotations

import os
import re

#: folders that hold tests, as named (compared in lower case)
TEST_FOLDERS = frozenset(
    {"test", "tests", "testing", "testcases", "unittest", "unittests", "unit_tests"}
)
#: a folder of test scripts (``pshare_test_scripts``)
_TEST_SCRIPTS = re.compile(r"(?:^|[_-])tests?[_-]scripts?$", re.IGNORECASE)


def is_test_code(path: str, root: str | None = None) -> bool:
    """Whether ``path`` is a test program or test input: a folder of its path below
    ``root`` (the project's root; without it, the file's own folder) holds tests."""
    path = os.path.abspath(path)
    if root:
        rel = os.path.relpath(os.path.dirname(path), os.path.abspath(root))
        if rel.startswith(".."):
            return False
    else:
        rel = os.path.basename(os.path.dirname(path))
    return any(f.lower() in TEST_FOLDERS or _TEST_SCRIPTS.search(f) for f in rel.split(os.sep) if f)
