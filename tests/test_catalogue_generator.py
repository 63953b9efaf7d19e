"""The catalogue generator reads a key's value form from the shape of its parser's branch."""

from __future__ import annotations

import pytest

from scripts.generate_catalogue import _guard_form, _words_or_number

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


def read(text: str) -> tuple[str, list[list[str]]] | None:
    lines = text.splitlines()
    return _words_or_number(lines, 1, lines[0][lines[0].index('")') + 1 :])


def form_of(text: str) -> str | None:
    got = read(text)
    return None if got is None else got[0]


def test_words_then_a_number_then_a_rejection():
    assert form_of(RESET_MAX) == "enum_or_uint:any|unlimited|nolimit"
    assert form_of(RETRACTIONS) == "enum_or_number:true|false"
    positive = RESET_MAX.replace("atoi(value.c_str()) >= 0", "atof(value.c_str()) > 0")
    assert form_of(positive) == "enum_or_positive:any|unlimited|nolimit"


def test_words_one_branch_takes_together_are_stored_alike():
    # one branch's `||` of words sets one value; words in branches of their own may not
    assert read(RESET_MAX) == (
        "enum_or_uint:any|unlimited|nolimit",
        [["any", "unlimited", "nolimit"]],
    )
    assert read(RETRACTIONS) == ("enum_or_number:true|false", [])


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


def guard_form_of(text: str) -> str | None:
    lines = text.splitlines()
    return _guard_form(lines, 1, lines[0][lines[0].index('")') + 1 :])


@pytest.mark.parametrize(
    ("branch", "form"),
    [
        # BHV_PeriodicSurface's period: a number above 0
        (
            '  if(g_param == "period") {\n'
            "    double dval = atof(g_val.c_str());\n"
            "    if((dval <= 0) || (!isNumber(g_val)))\n"
            "      return(false);\n",
            "positive",
        ),
        # BHV_HeadingChange's heading_delta: 1 up to but not 360
        (
            '  if(param == "heading_delta") {\n'
            "    double dval = atof(val.c_str());\n"
            "    if((dval < 1) || (dval >= 360) || (!isNumber(val)))\n"
            "      return(false);\n",
            "range:[1,360)",
        ),
        # the test of the number first, on one line with its rejection
        (
            '  else if(param == "swing_time") {\n    if(!isNumber(val)) return(false);\n',
            "number",
        ),
        # a guard without !isNumber lets a word through as 0: not read
        (
            '  if(param == "repeat") {\n'
            "    int ival = atoi(val.c_str());\n"
            "    if(ival < 0)\n"
            "      return(false);\n",
            None,
        ),
        # a bound on another variable than the value's: not read
        (
            '  if(param == "depth") {\n'
            "    double dval = atof(val.c_str());\n"
            "    if((m_max < 0) || (!isNumber(val)))\n"
            "      return(false);\n",
            None,
        ),
    ],
)
def test_guard_forms(branch, form):
    assert guard_form_of(branch) == form


SET_PARAM = """bool BHV_Waypoint::setParam(string param, string param_val)
{
  double dval = atof(param_val.c_str());
  string param_val_lower = tolower(param_val);

  if((param == "radius") || (param == "capture_radius")) {
    if(dval <= 0)
      return(false);
    m_capture_radius = dval;
    return(true);
  }
  else if(param == "nm_radius") {
    if(dval < 0)
      return(false);
    m_nm_radius = dval;
    return(true);
  }
  else if(param == "patience") {
    if((dval < 1) || (dval > 99) || !isNumber(param_val))
      return(false);
    m_patience = dval;
    return(true);
  }
"""


@pytest.mark.parametrize(
    ("key", "form"),
    [
        # the number read before the branches; a word reads as 0, which `<= 0` rejects
        ("radius", "positive"),
        ("capture_radius", "positive"),  # the branch's other key
        # `< 0` lets a word through as 0: not read
        ("nm_radius", None),
        ("patience", "range:[1,99]"),
    ],
)
def test_guard_forms_of_a_number_read_before_the_branches(key, form):
    """BHV_Waypoint, BHV_Loiter and BHV_PeriodicSpeed read ``dval`` once, at the top of
    setParam, and guard it in each key's branch."""
    lines = SET_PARAM.splitlines()
    n = next(i for i, line in enumerate(lines, 1) if f'"{key}")' in line)
    text = lines[n - 1]
    assert _guard_form(lines, n, text[text.index(f'"{key}"') + len(key) + 2 :]) == form
