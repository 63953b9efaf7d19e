"""The language server's help spells a key's value form out in words."""

from __future__ import annotations

from moos_lint.commands.lsp.catalogue import form_text


def test_words_or_a_number():
    assert form_text("enum_or_uint:any|unlimited|nolimit") == (
        "`any` or `unlimited` or `nolimit`, or a whole number, 0 or more"
    )


def test_a_list_of_words():
    assert form_text("enum:left|right") == "one of `left` or `right`"


def test_known_and_unknown_forms():
    assert form_text("positive") == "a number greater than 0"
    assert form_text("something_new") == "something_new"


def test_bounded_numbers_are_spelt_out():
    assert form_text("range:[1,360)") == "a number in [1, 360)"
    assert form_text("clip:0,") == "a number; one below 0 is taken as 0"
    assert form_text("clip:0,100") == "a number; one below 0 is taken as 0, one above 100 as 100"
    assert form_text("clip:,5") == "a number; one above 5 is taken as 5"
