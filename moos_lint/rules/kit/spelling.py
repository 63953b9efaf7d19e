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
