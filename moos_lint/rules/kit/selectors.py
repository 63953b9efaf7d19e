"""Rule selectors: ``ALL``, a code, a code prefix (``M``, ``M0``), or a rule name.

Kept apart from the registry so that what matches findings by selector (the
suppression comments) does not load the rules.
"""

from __future__ import annotations

import re

_PREFIX = re.compile(r"[A-Z][0-9]{0,3}")


def selects(selector: str, code: str, name: str) -> bool:
    """Whether ``selector`` selects the rule with this code and name."""
    if selector.upper() == "ALL":
        return True
    if selector == name:
        return True
    s = selector.upper()
    return bool(_PREFIX.fullmatch(s)) and code.startswith(s)


__all__ = ["selects"]
