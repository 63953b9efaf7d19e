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
