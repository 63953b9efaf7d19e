"""How far apart two spellings are, for rules that suggest the name meant."""

from __future__ import annotations

from collections.abc import Iterable


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
