"""The project boundary: what a report may show of the files a run read.

moos-lint reads what nsplug and the apps would read: a file included from an
``-I`` folder or a sibling tree is part of the mission's model, so the
findings about the project's own files stay right. A report never shows text
of a file outside the project root, though (the CI log of a public repository
is public, and a pull request can ``#include /etc/passwd``):

* a finding located in a file whose real path lies outside the root is not
  listed; each such file is summed up once, by its path and a count
  (:attr:`Result.outside`); like the file, they are no part of the project's
  result (the exit status, a baseline), which the project cannot fix;
* a linted path that is a link to a file outside the project is not linted
  (:func:`split_linted`; :attr:`Result.outside_links`, one note each);
* a message about a file inside never quotes an outside file's text: a word
  (three or more word characters) that outside files hold, no file inside
  does and moos-lint itself does not know (its own code and stock catalogue:
  the words of its messages, MOOS's public names) is shown as ``…``; a fix
  that would carry such a word, or that edits a file outside, is dropped.

The root is :func:`moos_lint.files.project.project_root`, compared by real path
(:func:`moos_lint.files.project.real_within`), so a link inside the project that
points out of it is outside.
"""

from __future__ import annotations

import functools
import os
import re
from collections.abc import Iterable, Mapping
from pathlib import Path

from moos_lint.files.diagnostics import Diagnostic
from moos_lint.files.project import is_within

#: The code the reports give the summary of a file outside the project (never a rule's).
OUTSIDE_CODE = "L901"
OUTSIDE_NAME = "outside-project"
HIDDEN = "…"

_WORD = re.compile(r"\w{3,}")


class Boundary:
    """Which paths lie inside a project root (by real path; answers are kept)."""

    def __init__(self, root: str) -> None:
        self.root = os.path.abspath(root)
        self._real_root = os.path.realpath(self.root)
        self._known: dict[str, bool] = {}
        self._folders: dict[str, str] = {}

    def inside(self, path: str) -> bool:
        hit = self._known.get(path)
        if hit is None:
            hit = self._known[path] = is_within(self._real(path), self._real_root)
        return hit

    def _real(self, path: str) -> str:
        """``os.path.realpath(path)``, resolving each folder once: the real path of a file
        that is not a link is its folder's real path joined with its name."""
        if os.path.islink(path):
            return os.path.realpath(path)
        folder, name = os.path.split(os.path.abspath(path))
        real = self._folders.get(folder)
        if real is None:
            real = self._folders[folder] = os.path.realpath(folder)
        return os.path.join(real, name)


def split_linted(files: Iterable[str], boundary: Boundary) -> tuple[list[str], list[str]]:
    """The files to lint, and the linted paths that are links to files outside."""
    inside: list[str] = []
    outside: list[str] = []
    for path in files:
        (inside if boundary.inside(path) else outside).append(path)
    return inside, outside


def apply(
    diagnostics: list[Diagnostic], boundary: Boundary, texts: Mapping[str, str]
) -> tuple[list[Diagnostic], dict[str, int]]:
    """The findings a report may list, and the count of hidden ones per outside file.

    ``texts``: every file the run read, by path (what messages may quote).
    """
    kept: list[Diagnostic] = []
    hidden: dict[str, int] = {}
    for d in diagnostics:
        if boundary.inside(d.span.path):
            kept.append(d)
        else:
            hidden[d.span.path] = hidden.get(d.span.path, 0) + 1
    outside = [text for path, text in texts.items() if not boundary.inside(path)]
    if outside and kept:
        inside = [text for path, text in texts.items() if boundary.inside(path)]
        leaked = _leaked_words(kept, outside, inside)
        if leaked:
            for d in kept:
                _redact(d, leaked)
    for d in kept:
        if d.fix is not None and not all(boundary.inside(e.span.path) for e in d.fix.edits):
            d.fix = None
    return kept, dict(sorted(hidden.items()))


def _said(d: Diagnostic) -> list[str]:
    """The text a report shows of a finding, besides its place: message, notes and fix."""
    said = [d.message, *d.notes]
    if d.fix is not None:
        said += [d.fix.message, *(e.text for e in d.fix.edits)]
    return said


def _leaked_words(kept: list[Diagnostic], outside: list[str], inside: list[str]) -> set[str]:
    """The words the findings say that outside files hold and no inside file does."""
    said = {w for d in kept for text in _said(d) for w in _WORD.findall(text)}
    if not said:
        return set()
    held_outside = {w for text in outside for w in _WORD.findall(text) if w in said}
    held_outside -= _own_words()
    leaked = set()
    for word in held_outside:
        pattern = re.compile(rf"(?<!\w){re.escape(word)}(?!\w)")
        if not any(word in text and pattern.search(text) for text in inside):
            leaked.add(word)
    return leaked


@functools.lru_cache(maxsize=1)
def _own_words() -> frozenset[str]:
    """The words of moos-lint's own code and stock catalogue: public, never a leak."""
    package = Path(__file__).resolve().parent
    words: set[str] = set()
    for path in (*package.rglob("*.py"), package / "catalogue" / "stock.json"):
        try:
            words.update(_WORD.findall(path.read_text(encoding="utf-8", errors="replace")))
        except OSError:
            continue
    return frozenset(words)


def _redact(d: Diagnostic, leaked: set[str]) -> None:
    def hide(text: str) -> str:
        return _WORD.sub(lambda m: HIDDEN if m.group(0) in leaked else m.group(0), text)

    d.message = hide(d.message)
    d.notes = [hide(n) for n in d.notes]
    if d.fix is not None:
        carried = [d.fix.message, *(e.text for e in d.fix.edits)]
        if any(hide(text) != text for text in carried):
            d.fix = None


def summary(path: str, count: int) -> str:
    """The one line a report gives a file outside the project with hidden findings."""
    return (
        f"{count} finding{'s' if count != 1 else ''} in this file, outside the project, not shown"
    )


LINK_NOTE = "a link to a file outside the project: not linted"


def notes(result) -> list[tuple[str, str]]:
    """(path, text) of every note a report gives about the boundary, in path order."""
    out = [(p, summary(p, n)) for p, n in getattr(result, "outside", {}).items()]
    out += [(p, LINK_NOTE) for p in getattr(result, "outside_links", [])]
    return sorted(out)
