"""Patterns written literal first find exactly what their plain spelling finds.

A pattern that starts with ``\\b`` (or a lookbehind, or an alternation) is tried
at every position of the text; one that starts with a literal skips ahead to
it. The patterns searched over whole C++ files are therefore written literal
first (``else(?<=\\belse)`` for ``\\belse``), which is 6 to 25 times faster on a
repository's files. Each is checked here against its plain spelling, on a table
of cases and on random strings made of the pieces that matter to it.
"""

from __future__ import annotations

import random
import re

import pytest

from moos_lint.frontends.cpp import app, extract, prefilter
from moos_lint.frontends.cpp.values import field_write_pattern
from moos_lint.rules.kit import file_wide
from moos_lint.rules.mission import _behaviors
from moos_lint.semantics import catalogue

pytestmark = pytest.mark.perf

PLAIN_MOOS_API = re.compile(
    rb"\b(?:Notify|Register|UnRegister|CMOOSApp|AppCastingMOOSApp|CMOOSInstrument|"
    rb"OnNewMail|OnStartUp|GetConfigurationParam|CMOOSSerialPort)\b|\.Run\s*\("
)
PLAIN_NED = re.compile(
    rb"(?<![A-Za-z])[Nn]ed(?![a-z])|(?<![A-Z])NED(?![a-z])|(?<![A-Za-z])down\b|_down\b|Down\b"
)

# (name, fast pattern, plain spelling, the pieces random texts are made of)
PAIRS = [
    (
        "DELEGATE",
        catalogue.DELEGATE,
        re.compile(
            r"(?:\belse\s*\{?\s*(?://[^\n]*\s*)*|\bbool\s+"
            r"|\bif\s*(?=\([^\"\n]*\bparam\b)\((?:[^\"()\n]|\([^\"()\n]*\))*\)\s*\{?\s*)"
            r"handled\s*=\s*[\w>.-]+\(\s*param\b",
            re.M,
        ),
        [
            *["else", "xelse", "_else", " ", "\n", "{", "//c\n"],
            *["handled = f(param", "handled=g.h(", "bool ", "xbool ", "if", "xif"],
            *["(", ")", "k.count(param)", '"', "param"],
        ],
    ),
    (
        "GetValue",
        file_wide._GET_VALUE,
        re.compile(r"\bGetValue\s*\(\s*\"([A-Za-z0-9_]+)\"", re.ASCII),
        ["GetValue", "xGetValue", "_GetValue", " ", '("', '( "KEY"', "KEY", '"', "\u00e9", "\t"],
    ),
    (
        "add_connection",
        app._LINK_CALL,
        re.compile(rb"\b(add_(?:any|udp|tcp|serial)_connection)[ \t]*\("),
        [b"add_", b"xadd_", b"_add_", b"udp_connection", b"any_connection (", b"tcp", b" ", b"("],
    ),
    (
        "BHV class",
        _behaviors._CLASS,
        re.compile(rb"\bclass\s+(BHV_\w+)\s*(?::|\{)"),
        [b"class", b"xclass", b"_class", b" ", b" BHV_Loiter", b"BHV_", b"Loiter", b":", b"{"],
    ),
    (
        "field write",
        field_write_pattern(["nav_x", "m_nav_x", "nav"]),
        re.compile(rb"\b(?:nav_x|m_nav_x|nav)\s*=(?!=)"),
        [b"nav_x", b"m_", b"nav", b"_x", b"x", b" ", b"=", b"==", b"+=", b".", b"->"],
    ),
]


@pytest.mark.parametrize(("name", "fast", "plain", "pieces"), PAIRS, ids=[p[0] for p in PAIRS])
def test_a_literal_first_pattern_finds_what_its_plain_spelling_finds(name, fast, plain, pieces):
    rnd = random.Random(name)
    join = "" if isinstance(pieces[0], str) else b""
    found = 0
    for _ in range(20000):
        text = join.join(rnd.choice(pieces) for _ in range(rnd.randint(1, 12)))
        want = [(m.span(), m.groups()) for m in plain.finditer(text)]
        assert [(m.span(), m.groups()) for m in fast.finditer(text)] == want, text
        found += bool(want)
    assert found > 200  # the texts do hold matches, near misses among them


@pytest.mark.parametrize(
    ("data", "named"),
    [
        (b"m_ned.z = -depth;", True),
        (b"PoseNED p;", True),
        (b"local_position_ned_t pos;", True),
        (b"Ned frame", True),
        (b"pos_down = 3;", True),
        (b"down = 3;", True),
        (b"moveDown ();", True),
        (b"planned = aligned;", False),
        (b"NEDs", False),
        (b"countdown = 3;", False),
        (b"downstream", False),
        (b"", False),
    ],
)
def test_the_ned_prefilter_table(data, named):
    assert extract.may_name_ned(data) is named
    assert bool(PLAIN_NED.search(data)) is named


def test_the_ned_prefilter_agrees_with_its_plain_spelling():
    rnd = random.Random(7)
    pieces = [b"n", b"N", b"e", b"E", b"d", b"D", b"ned", b"NED", b"Ned", b"own", b"down"]
    pieces += [b"Down", b"_", b"a", b"A", b" ", b"x", b"s"]
    for _ in range(50000):
        text = b"".join(rnd.choice(pieces) for _ in range(rnd.randint(1, 8)))
        assert extract.may_name_ned(text) is bool(PLAIN_NED.search(text)), text


def test_the_moos_api_prefilter_agrees_with_its_plain_spelling():
    rnd = random.Random(11)
    pieces = [b"Notify", b"Register", b"Un", b"CMOOSApp", b"CMOOS", b"OnNewMail", b"OnStartUp"]
    pieces += [b"Serial", b"Port", b"AppCasting", b"MOOSApp", b"x", b"_", b" ", b"(", b".Run", b"m"]
    found = 0
    for _ in range(50000):
        text = b"".join(rnd.choice(pieces) for _ in range(rnd.randint(1, 6)))
        want = bool(PLAIN_MOOS_API.search(text))
        assert prefilter.mentions_moos(text) is want, text
        found += want
    assert found > 5000


def test_the_upper_casing_words_are_what_the_plain_pattern_finds():
    plain = re.compile(rb"(?i)\w*upper\w*")
    rnd = random.Random(5)
    pieces = [b"upper", b"UPPER", b"uPpEr", b"Upp", b"er", b"pper", b"u", b"x", b"_", b" ", b"("]
    pieces += [b"1", b"\xc3\xa9", b"::to"]
    found = 0
    for _ in range(50000):
        text = b"".join(rnd.choice(pieces) for _ in range(rnd.randint(1, 10)))
        want = [m.span() for m in plain.finditer(text)]
        assert list(extract.upper_words(text)) == want, text
        found += bool(want)
    assert found > 10000
    data = b"MOOSToUpper(m_var); std::transform(a, b, c, ::toupper); upperupper x"
    assert [data[s:e] for s, e in extract.upper_words(data)] == [
        b"MOOSToUpper",
        b"toupper",
        b"upperupper",
    ]
