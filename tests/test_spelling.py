"""The spelling helpers rules share (``rules.kit.spelling``)."""

from __future__ import annotations

import pytest

from moos_lint.rules.kit.spelling import cased_like, misspelling_of, typos


@pytest.mark.parametrize(
    ("written", "key", "shown"),
    [
        ("CoomsTick", "commstick", "CommsTick"),
        ("APPTIK", "apptick", "APPTICK"),
        ("capture_raduis", "capture_radius", "capture_radius"),
        ("Apptick2", "maxapptick", "MaxApptick"),
        ("Capture_Raduis", "capture_radius", "Capture_Radius"),
        ("verbos", "verbose", "verbose"),
    ],
)
def test_a_suggested_key_takes_the_case_it_replaces(written, key, shown):
    """MOOS and the helm compare keys without regard to case: a suggestion (and the fix)
    keeps the user's capitals rather than the catalogue's lower case."""
    assert cased_like(written, key) == shown
    assert cased_like(written, key).lower() == key


def test_typos_count_swaps_as_one():
    assert typos("RETRUN", "RETURN") == 1
    assert typos("deploy", "DEPLOY") == 0
    assert misspelling_of("RETRUN", ["RETURN", "DEPLOY"], 1) == "RETURN"
    assert misspelling_of("RETRUN", ["RETURN", "RETRUNS"], 1) is None
