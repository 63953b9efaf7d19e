"""Every real MOOS-IvP mission and behavior file is read without an internal error.

The corpus (the public MOOS-IvP repository's .moos and .bhv files) lives beside
the repository in ``../shared/corpus``; the test skips when it is absent.
"""

from __future__ import annotations

from collections import Counter
from pathlib import Path

import pytest

from moos_lint.core.config import Settings
from moos_lint.core.engine import lint_files
from moos_lint.files.discovery import discover

CORPUS = Path(__file__).resolve().parents[2] / "shared" / "corpus" / "moos-ivp"

pytestmark = pytest.mark.skipif(not CORPUS.is_dir(), reason="the MOOS-IvP corpus is not present")


@pytest.fixture(scope="module")
def corpus_result():
    files = discover([CORPUS], [], str(CORPUS)).files
    settings = Settings(root=str(CORPUS), select=["ALL"])
    return files, lint_files(files, settings)


def test_every_file_is_read_without_internal_errors(corpus_result):
    files, result = corpus_result
    assert len(files) >= 500
    assert result.internal_errors == 0
    assert not [d for d in result.diagnostics if d.code in ("L900", "R001")]


def test_engine_rules_on_the_corpus_match_hand_review():
    """Findings of the reader and nsplug rules, each reviewed by hand against the file."""
    files = discover([CORPUS], [], str(CORPUS)).files
    select = ["R", "P", "B"]
    result = lint_files(files, Settings(root=str(CORPUS), select=select))
    found = Counter(
        (str(Path(d.span.path).relative_to(CORPUS)), d.code) for d in result.diagnostics
    )
    # A single '/' is not a comment, but this first line has no '=': MOOS drops it unread.
    assert found[("MOOS_Jul2724/MOOSMatlab/iMatlab/iMatlab.moos", "R007")] == 0
    # The shoreside defines uProcessWatch itself and also includes the plug's block.
    key = ("ivp/missions-minicourse/lab_charlie_dana_baseline/meta_shoreside.moos", "R011")
    assert found[key] == 1
    # plugs.moos has no <tag><iM300> section.
    assert found[("ivp/missions/m2_berta/meta_vehicle.moos", "P007")] == 1
    # The mission includes plugs that are not in its folder.
    assert found[("ivp/missions/m9_indigo/meta_shoreside.moos", "P001")] == 3
    # `#BUTTON_FOUR = ...` is a live key, not a comment and not a directive.
    assert found[("ivp/missions/u6_alpha/meta_shoreside.moos", "R007")] == 1
    assert found[("ivp/missions/u6_alpha/meta_shoreside.moos", "P003")] == 0
    # nsplug's own test file documents its directives in prose; nothing in it is shaped
    # like a behavior file's line, and no helm loads it: the nsplug rules leave it alone.
    notes = "ivp/src/app_nsplug/testcases/meta_vehicle.bhv"
    assert [k for k in found if k[0] == notes] == []
    # No flagship mission has a structural error.
    flagship = [k for k in found if k[0].startswith("ivp/missions/s1_alpha/")]
    assert flagship == []
