"""The spelling helpers rules share (``rules.kit.spelling``)."""

from __future__ import annotations

import pytest

from moos_lint.rules.kit.spelling import (
    VariableSpeller,
    cased_like,
    misspelling_of,
    slip,
    typos,
)


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


@pytest.mark.parametrize(
    ("written", "meant", "fixable"),
    [
        ("ouptut", "output", True),  # two letters swapped
        ("CommsTic", "CommsTick", True),
        ("resetmax", "reset_max", True),  # only an underscore
        ("MAX_RUDDER", "maxrudder", True),
        ("SUMARRY_WAIT", "SUMMARY_WAIT", True),  # two slips in a long key
        ("CommunTick", "CommsTick", False),  # two in a short one
        ("MODBUS_PORT", "MOOS_PORT", False),  # another word
        ("southbound", "outbound", False),
        ("TRY_SHORE_PORT", "TRY_SHORE_HOST", False),
        ("thrust_mapping", "thrust_map", False),
    ],
)
def test_a_respelling_is_a_fix_only_for_a_slip(written, meant, fixable):
    """A close key is named in the message either way; it is written into the file
    only when it undoes a slip of the keyboard."""
    assert slip(written, meant) is fixable


@pytest.mark.parametrize(
    ("name", "known", "meant"),
    [
        ("RETRUN", "RETURN", "RETURN"),
        ("MOOS_MANUAL_OVERIDE", "MOOS_MANUAL_OVERRIDE", "MOOS_MANUAL_OVERRIDE"),
        ("SBR_RANGE_REQUEST", "BRS_RANGE_REQUEST", "BRS_RANGE_REQUEST"),  # letters reordered
        ("NAV_LONG", "NAV_LON", "NAV_LON"),
        ("LOITER_UPDTAES", "LOITER_UPDATES", "LOITER_UPDATES"),
        ("STATION_KEPE_REQ", "STATION_KEEP_REQ", "STATION_KEEP_REQ"),
        ("TERM_NEG_EVIDENCE", "TERM_NUM_EVIDENCE", None),  # a short word for another
        ("LOITER_REGION_2", "LOITER_REGION_1", None),  # another number
        ("Deploy", "DEPLOY", None),  # letter case only: variable-name-case's
        ("STOP", "SOTP", None),  # four letters: not compared
        ("RETURN_NOW", "RETURNNOW", None),  # another count of words
        ("SURVEY_DONE", "SURVEY_GONE_NOW", None),
        ("NAV_Y", "NAV_X", None),  # a word of one letter
        ("GROUP_AB", "GROUP_AC", None),
        ("SET_POS", "GET_POS", None),  # a letter changed in a short word
        ("DEPLOI", "DEPLOY", "DEPLOY"),  # in a longer one
        ("WPT_STAT", "WPT_STATE", "WPT_STATE"),
    ],
)
def test_a_variable_a_typo_away(name, known, meant):
    assert VariableSpeller([known, "DEPLOY_ALL", "NAV_X"]).meant(name) == meant


def test_a_typo_of_two_variables_names_neither():
    speller = VariableSpeller(["RETURN_UPDATE", "RETURN_UPDATER"])
    assert speller.meant("RETURN_UPDATEE") is None
    assert VariableSpeller(["DEPLOY", "DEPLOY"]).meant("DEPLOI") == "DEPLOY"
