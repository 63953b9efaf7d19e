"""The catalogue generator reads a key's value form from the shape of its parser's branch."""

from __future__ import annotations

import pytest

from scripts.generate_catalogue import _words_or_number

RESET_MAX = """\
    else if(param == "reset_max") {
      string str = tolower(value);
      if((str == "any") || (str == "unlimited") || (str == "nolimit"))
        m_reset_forever = true;
      else if(isNumber(value) && (atoi(value.c_str()) >= 0)) {
        m_reset_max = atoi(value.c_str());
        m_reset_forever = false;
      }
      else
        reportConfigWarning("Invalid reset_max parameter value: " + value);
    }
"""

RETRACTIONS = """\
    else if(param == "allow_retractions") {
      if(tolower(value) == "true")
        m_allow_retractions = -1;
      else if(tolower(value) == "false")
        m_allow_retractions = 0;
      else if(isNumber(value))
        m_allow_retractions = atof(value.c_str());
      else
        return(false);
    }
"""


def form_of(text: str) -> str | None:
    lines = text.splitlines()
    return _words_or_number(lines, 1, lines[0][lines[0].index('")') + 1 :])


def test_words_then_a_number_then_a_rejection():
    assert form_of(RESET_MAX) == "enum_or_uint:any|unlimited|nolimit"
    assert form_of(RETRACTIONS) == "enum_or_number:true|false"
    positive = RESET_MAX.replace("atoi(value.c_str()) >= 0", "atof(value.c_str()) > 0")
    assert form_of(positive) == "enum_or_positive:any|unlimited|nolimit"


@pytest.mark.parametrize(
    "change",
    [
        # no final `else`: any other value is silently kept
        ("      else\n        reportConfigWarning(", "      reportConfigWarning("),
        # the final `else` accepts the value
        ('reportConfigWarning("Invalid reset_max parameter value: " + value);', "m_other = value;"),
        # compared without tolower with upper-case words
        ('(str == "any")', '(value == "ANY")'),
        # the number test is of another variable
        ("isNumber(value)", "isNumber(other)"),
        # the words come after the number
        (
            'if((str == "any")',
            'if(isNumber(value))\n        m_x = 1;\n      else if((str == "any")',
        ),
    ],
)
def test_any_other_shape_is_no_form(change):
    old, new = change
    assert old in RESET_MAX
    assert form_of(RESET_MAX.replace(old, new, 1)) is None
