"""The MOOS Conventions' process-name prefix (section 4.1), as one fact for every check.

A process is named ``i``, ``p`` or ``u`` (instrument, pure process, utility)
followed by an upper-case letter or a digit: ``iGPS``, ``pHelmIvP``, ``uXMS``,
``p2BTracker`` (a digit begins a word as well as a capital does). Both the
mission check (Run lines, aliases, blocks) and the C++ check (an app's own
name) word what is wrong with a name the same way, and say it truly: a name
such as ``pmidca`` starts with a prefix letter and lacks only the upper-case
letter after it (the message says which letter is missing, not what was meant:
the first letter may begin a word).
"""

from __future__ import annotations

import re

#: a name that follows the convention
PREFIXED = re.compile(r"^[ipu][A-Z0-9]")
_WORD = re.compile(r"\w+", re.ASCII)
#: the words for a name without any prefix
NO_PREFIX = "does not start with `i`, `p` or `u` and an upper-case letter"


def placeholder(name: str) -> bool:
    """Whether an app's name is a template's placeholder, in capitals with an underscore
    (``add_executable(MOOSAPPFACTORY_NAME ...)`` in the template an app generator fills):
    the app it becomes is named when it is generated."""
    return "_" in name and name.isupper() and _WORD.fullmatch(name) is not None


def prefix_problem(name: str, missing: str = NO_PREFIX) -> str:
    """What is wrong with ``name``'s prefix, to follow the name in a message (``missing``:
    the words for a name with no prefix at all); the name does not match :data:`PREFIXED`."""
    if len(name) > 1 and name[0] in "ipu" and name[1].islower() and _WORD.fullmatch(name):
        return f"starts with `{name[0]}`, but no upper-case letter follows it"
    return missing


def acronym(app: str) -> str:
    """The prefix a MOOS-IvP app gives the variables it names after itself: its first
    letter and its capitals, upper case (uFldRescueMgr: ``UFRM_``, uSimMarine: ``USM_``,
    uFldShoreBroker: ``UFSB_``); empty for a name of fewer than two capitals."""
    letters = app[:1] + "".join(c for c in app[1:] if c.isupper())
    return letters.upper() if len(letters) > 2 else ""


def own_prefixes(app: str) -> set[str]:
    """The prefixes of the variables an app most likely names after itself: its acronym
    (:func:`acronym`) and its name without the ``i``/``p``/``u`` letter, whole and by words
    (pOdometry: ``ODOMETRY``; pGenPath: ``GPP``... ``GENPATH``, ``GEN_PATH``); none shorter
    than three letters."""
    stem = app[1:] if PREFIXED.match(app) else app
    words = re.findall(r"[A-Z]+(?![a-z])|[A-Z]?[a-z]+|\d+", stem)
    out = {acronym(app), stem.upper(), "_".join(words).upper()}
    return {p for p in out if len(p) >= 3}
