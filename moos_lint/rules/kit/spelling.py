"""How far apart two spellings are, for rules that suggest the name meant."""

from __future__ import annotations

import re
from collections.abc import Callable, Iterable


def typos(a: str, b: str) -> int:
    """Letters inserted, deleted, replaced or swapped to make ``a`` into ``b`` (no case)."""
    a, b = a.lower(), b.lower()
    prev2: list[int] = []
    prev = list(range(len(b) + 1))
    for i, ca in enumerate(a, 1):
        cur = [i]
        for j, cb in enumerate(b, 1):
            d = min(prev[j] + 1, cur[j - 1] + 1, prev[j - 1] + (ca != cb))
            if i > 1 and j > 1 and ca == b[j - 2] and a[i - 2] == cb:
                d = min(d, prev2[j - 2] + 1)
            cur.append(d)
        prev2, prev = prev, cur
    return prev[-1]


def misspelling_of(name: str, candidates: Iterable[str], most: int) -> str | None:
    """The one candidate ``name`` is at most ``most`` typos from (``RETRUN`` for
    ``RETURN``), when exactly one is; ``name`` itself and wildcards are not compared."""
    near = [
        c
        for c in candidates
        if c != name and "*" not in c and abs(len(c) - len(name)) <= most and typos(c, name) <= most
    ]
    return near[0] if len(near) == 1 else None


def slip(written: str, meant: str) -> bool:
    """Whether ``meant`` is ``written`` with a slip of the keyboard undone, so that a
    fix may respell one as the other: the same letters but for case and underscores
    (``resetmax``, ``reset_max``), one letter inserted, deleted, replaced or two
    swapped (``ouptut``), or two slips in a name of twelve letters or more
    (``SUMARRY_WAIT``) that leave no short word another word. A close name that
    differs by more is another key: a hint may name it, but writing it in would set
    what the author did not mean (``MODBUS_PORT`` is no misspelt ``MOOS_PORT``,
    ``southbound`` no ``outbound``, ``TRY_SHORE_PORT`` no ``TRY_SHORE_HOST``)."""
    a, b = written.lower(), meant.lower()
    if a.replace("_", "") == b.replace("_", ""):
        return True
    n = typos(a, b)
    if n <= 1:
        return True
    if n > 2 or min(len(a), len(b)) < 12:
        return False
    words_a, words_b = a.split("_"), b.split("_")
    if len(words_a) != len(words_b):
        return False
    pairs = zip(words_a, words_b, strict=True)
    return all(min(len(x), len(y)) >= 7 or typos(x, y) < 2 for x, y in pairs)


_DIGITS = re.compile(r"[0-9]+")


def sized_like(wanted: Iterable[str]) -> Callable[[str], bool]:
    """Whether a candidate may be a typo of one of the ``wanted`` names by its size
    alone: as many ``_``-separated words, and a length two letters or fewer away (a typo
    of a word, as :meth:`VariableSpeller.meant` takes one, changes no more)."""
    sizes: dict[int, set[int]] = {}
    for w in wanted:
        sizes.setdefault(w.count("_"), set()).add(len(w))

    def fits(candidate: str) -> bool:
        near = sizes.get(candidate.count("_"), ())
        return any(abs(len(candidate) - n) <= 2 for n in near)

    return fits


class VariableSpeller:
    """Finds the MOOS variable of a set that a name is a typo from (:meth:`meant`),
    through an index by the words the two names share, so that many names are
    checked against many candidates in time linear in both."""

    def __init__(self, candidates: Iterable[str]) -> None:
        self._index: dict[tuple[int, int, tuple[str, ...]], list[str]] = {}
        for c in candidates:
            if len(c) > 4:
                for key in self._keys(c):
                    self._index.setdefault(key, []).append(c)

    @staticmethod
    def _keys(name: str) -> list[tuple[int, int, tuple[str, ...]]]:
        w = name.upper().split("_")
        return [(len(w), i, tuple(w[:i] + w[i + 1 :])) for i in range(len(w))]

    def meant(self, name: str) -> str | None:
        """The one candidate ``name`` is a typo from, if any: the names have the same
        ``_``-separated words but one, and that word has a letter left out, added or
        changed or two swapped (``RETRUN``, ``MOOS_MANUAL_OVERIDE``, ``NAV_LON``), its
        letters in another order (``SBR_RANGE_REQUEST``), or two such typos in a word of
        six letters or more. Not typos: a name that differs only in case (the
        variable-name-case rule's), or in a number (``VEHICLE_1``, ``VEHICLE_2``: another
        vehicle), or in a word of one or two letters (``NAV_X``, ``NAV_Y``), a letter
        changed in a word of four letters or fewer (``SET_POS``, ``GET_POS``), a short
        word for another (``TERM_NEG``, ``TERM_NUM``); names of four letters or fewer are
        not compared."""
        if len(name) <= 4:
            return None
        near = {
            c for key in self._keys(name) for c in self._index.get(key, ()) if _word_typo(name, c)
        }
        return near.pop() if len(near) == 1 else None


def _word_typo(a: str, b: str) -> bool:
    wa, wb = a.upper().split("_"), b.upper().split("_")
    if len(wa) != len(wb):
        return False
    diff = [(x, y) for x, y in zip(wa, wb, strict=True) if x != y]
    if len(diff) != 1:
        return False
    x, y = diff[0]
    if min(len(x), len(y)) < 3 or _DIGITS.findall(x) != _DIGITS.findall(y):
        return False  # `NAV_X` and `NAV_Y`, `GROUP_A` and `GROUP_B`: other names
    anagram = sorted(x) == sorted(y)
    if len(x) == len(y) < 5 and not anagram:
        return False  # a letter changed in a short word makes another word: `SET`, `GET`
    d = typos(x, y)
    return d <= 1 or (d == 2 and (anagram or min(len(x), len(y)) >= 6))


def cased_like(written: str, word: str) -> str:
    """``word`` (a lower-case name MOOS compares without regard to case) in the letter
    case of ``written``, the spelling it would replace: ``CoomsTick`` gives ``commstick``
    as ``CommsTick``, ``APPTIK`` gives ``apptick`` as ``APPTICK``. The letters the two
    share keep the user's case; the others are lower case, but for a first letter
    where the user's is a capital."""
    if not any(c.isupper() for c in written):
        return word
    if not any(c.islower() for c in written):
        return word.upper()
    import difflib  # (only when a suggestion is made)

    out: list[str] = []
    ops = difflib.SequenceMatcher(None, written.lower(), word, autojunk=False).get_opcodes()
    for tag, i1, i2, j1, j2 in ops:
        if tag == "equal" or (tag == "replace" and i2 - i1 == j2 - j1):
            out.extend(
                w.upper() if c.isupper() else w
                for c, w in zip(written[i1:i2], word[j1:j2], strict=True)
            )
        else:
            out.append(word[j1:j2])
    cased = "".join(out)
    if written[0].isupper() and cased[:1].islower():  # `Apptick2` gives `MaxApptick`
        cased = cased[0].upper() + cased[1:]
    return cased
