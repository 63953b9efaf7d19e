"""Ports of the MOOS-IvP string helpers (``lib_mbutil/MBUtils.cpp``) that app and
behavior parsers use on configuration values, to the letter: what they accept
is what moos-lint may call valid.
"""

from __future__ import annotations

#: the words ``setBooleanOnString`` accepts (lower-cased first by most callers)
BOOLEAN_WORDS = frozenset({"true", "false", "on", "off", "yes", "no", "toggle"})
#: the words it stores alike: true, and false (MBUtils.cpp, setBooleanOnString)
BOOLEAN_GROUPS = (frozenset({"true", "on", "yes"}), frozenset({"false", "off", "no"}))


def strip_blank_ends(s: str) -> str:
    """``stripBlankEnds``: tabs and blanks in front; also CR, LF and NUL behind."""
    return s.lstrip(" \t").rstrip(" \t\r\n\x00")


def tolower(s: str) -> str:
    """``tolower``: ASCII letters only."""
    return "".join(chr(ord(c) + 32) if "A" <= c <= "Z" else c for c in s)


def bite(s: str, sep: str) -> tuple[str, str]:
    """``biteString``: (front, rest) split at the first ``sep``."""
    i = s.find(sep)
    if i < 0:
        return s, ""
    return s[:i], s[i + 1 :]


def bite_x(s: str, sep: str) -> tuple[str, str]:
    """``biteStringX``: ``biteString`` with blank ends stripped from both parts."""
    front, rest = bite(s, sep)
    return strip_blank_ends(front), strip_blank_ends(rest)


def parse_string(s: str, sep: str) -> list[str]:
    """``parseString``: no trailing empty piece, an empty string gives none."""
    if not s:
        return []
    parts = s.split(sep)
    if parts[-1] == "":
        parts.pop()
    return parts


def is_number(s: str) -> bool:
    """``isNumber`` (blank ends allowed): digits, one ``.``, ``-`` only in front."""
    s = strip_blank_ends(s)
    if len(s) > 1 and s[0] == "+":
        s = s[1:]
    digits = dots = 0
    for c in s:
        if "0" <= c <= "9":
            digits += 1
        elif c == ".":
            dots += 1
            if dots > 1:
                return False
        elif c == "-":
            if digits or dots:
                return False
        else:
            return False
    return digits > 0


def var_data_pair(s: str) -> tuple[str, str] | None:
    """``setVarDataPairOnString`` (``lib_mbutil/VarDataPairUtils.cpp``), how a behavior's
    flag is read: a ``@``/``<``/``>`` post tag and a ``#`` destination tag in front and an
    ``[if]`` condition behind are set aside, and the rest is split at its first ``=``
    (``VAR=VALUE``); None when either side is empty (the flag is rejected)."""
    s = strip_blank_ends(s)
    if not s:
        return None
    if s[0] in "@<>":
        _, s = bite_x(s, " ")
    if s[:1] == "#":
        _, s = bite_x(s, "#")
        _, s = bite_x(s, " ")
    if "[if]" in s:
        s = s[: s.rfind("[if]")]
    var, val = bite_x(s, "=")
    return (var, val) if var and val else None
