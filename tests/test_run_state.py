"""What a lint run keeps of its mission models, and when it lets them go."""

from __future__ import annotations

import os

from moos_lint.semantics.run_state import RunMemos


def _norm(path: str) -> str:
    return os.path.normpath(os.path.abspath(path))


def test_a_folders_shared_models_go_once_its_last_unit_is_checked():
    memos = RunMemos()
    a1, a2, b1 = _norm("a/alpha.moos"), _norm("a/bravo.moos"), _norm("b/charlie.moos")
    memos.expect(["a/alpha.moos", "a/bravo.moos", "b/charlie.moos"])
    for path in (a1, a2, b1):
        memos.mission_cores[path] = object()
        memos.external_publishers[path] = {}
    memos.checked("a/alpha.moos")
    assert set(memos.mission_cores) == {a1, a2, b1}  # bravo's model is made from alpha's
    memos.checked("a/bravo.moos")
    assert set(memos.mission_cores) == {b1}
    assert set(memos.external_publishers) == {b1}
    memos.checked("b/charlie.moos")
    assert memos.mission_cores == {} and memos.unchecked == {}


def test_without_expect_the_shared_models_stay():
    """The language server checks only some units: nothing says a folder is done."""
    memos = RunMemos()
    core = _norm("a/alpha.moos")
    memos.mission_cores[core] = object()
    memos.checked("a/alpha.moos")
    assert core in memos.mission_cores
