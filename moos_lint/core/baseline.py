"""Baselines: adopt moos-lint on an existing repository, then only hear about new findings.

``moos-lint check --write-baseline FILE`` records today's findings, counted per
file and rule; ``moos-lint check --baseline FILE`` then reports only what is
new. Counting per file and rule (not per line) means edits that move lines do
not bring old findings back.

The file is JSON, paths relative to the project root (see
:func:`moos_lint.core.context.project_root`) with ``/`` separators, so one baseline
works on every clone::

    {
      "moos-lint-baseline": 1,
      "files": {
        "missions/alpha/alpha.moos": {
          "R003": ["ProcessConfig = pLogger {"],
          "R012": ["just a note", "another note"]
        }
      }
    }

Each rule lists the text of the lines its findings were on (trimmed): the
*number* of entries is the allowance; the texts decide *which* findings are the
new ones when a file has more findings of a rule than allowed. Findings whose
line text matches a recorded entry are taken as old (each entry matches once);
of the rest, the last ones in the file are reported, as many as exceed the
allowance.

Writing a baseline again replaces the entries of the files and rules of that
run (findings that are gone are pruned), keeps those of files the run did not
lint and of rules that did not run, and drops files that no longer exist.
"""

from __future__ import annotations

import json
import os
from collections import Counter
from collections.abc import Sequence
from dataclasses import dataclass, field

from moos_lint.files.diagnostics import INTERNAL_ERROR, Diagnostic

FORMAT_KEY = "moos-lint-baseline"
FORMAT_VERSION = 1
MAX_SNIPPET = 120


class BaselineError(Exception):
    """A baseline file that cannot be read, or is not a moos-lint baseline."""


@dataclass
class Baseline:
    root: str
    #: relative path -> rule code -> line texts
    files: dict[str, dict[str, list[str]]] = field(default_factory=dict)

    def allowed(self, rel: str, code: str) -> list[str]:
        return self.files.get(rel, {}).get(code, [])

    @property
    def total(self) -> int:
        return sum(len(v) for codes in self.files.values() for v in codes.values())


def relative(path: str, root: str) -> str:
    try:
        rel = os.path.relpath(path, root)
    except ValueError:  # another drive
        rel = path
    return rel.replace(os.sep, "/")


def snippet(d: Diagnostic, sources) -> str:
    src = sources.get(d.span.path) if sources else None
    text = src.line(d.span.line).strip() if src is not None else ""
    return text[:MAX_SNIPPET]


def load(path: str, root: str) -> Baseline:
    if os.path.exists(path) and not os.path.isfile(path):
        raise BaselineError(f"{path}: cannot read baseline: not a regular file")
    try:
        with open(path, encoding="utf-8") as fh:
            data = json.load(fh)
    except OSError as exc:
        raise BaselineError(f"{path}: cannot read baseline: {exc.strerror or exc}") from exc
    except (UnicodeDecodeError, json.JSONDecodeError) as exc:
        raise BaselineError(f"{path}: not a moos-lint baseline (invalid JSON: {exc})") from exc
    if not isinstance(data, dict) or data.get(FORMAT_KEY) != FORMAT_VERSION:
        raise BaselineError(f"{path}: not a moos-lint baseline (version {FORMAT_VERSION})")
    files = data.get("files", {})
    ok = isinstance(files, dict) and all(
        isinstance(codes, dict)
        and all(isinstance(v, list) and all(isinstance(x, str) for x in v) for v in codes.values())
        for codes in files.values()
    )
    if not ok:
        raise BaselineError(f"{path}: malformed baseline: `files` must map paths to rule lists")
    return Baseline(root=root, files=files)


def _groups(diags: list[Diagnostic], root: str) -> dict[tuple[str, str], list[Diagnostic]]:
    groups: dict[tuple[str, str], list[Diagnostic]] = {}
    for d in diags:
        groups.setdefault((relative(d.span.path, root), d.code), []).append(d)
    return groups


def new_findings(
    diags: list[Diagnostic], baseline: Baseline, sources
) -> tuple[list[Diagnostic], int]:
    """The findings the baseline does not cover, and how many it hid."""
    report: set[int] = set()
    for (rel, code), group in _groups(diags, baseline.root).items():
        if code == INTERNAL_ERROR:
            report.update(id(d) for d in group)
            continue
        recorded = baseline.allowed(rel, code)
        excess = len(group) - len(recorded)
        if excess <= 0:
            continue
        pool = Counter(recorded)
        unmatched = []
        for d in sorted(group, key=lambda d: d.sort_key):
            text = snippet(d, sources)
            if pool[text] > 0:
                pool[text] -= 1
            else:
                unmatched.append(d)
        report.update(id(d) for d in unmatched[-excess:])
    kept = [d for d in diags if id(d) in report]
    return kept, len(diags) - len(kept)


def build(
    diags: list[Diagnostic],
    root: str,
    sources,
    *,
    previous: Baseline | None = None,
    linted: Sequence[str] = (),
    ran_codes: set[str] | None = None,
) -> Baseline:
    """A baseline of ``diags``, merged into ``previous`` (see the module docs)."""
    files: dict[str, dict[str, list[str]]] = {}
    linted_rel = {relative(p, root) for p in linted}
    if previous is not None:
        for rel, codes in previous.files.items():
            if not os.path.exists(os.path.join(root, rel)):
                continue  # the file is gone
            for code, texts in codes.items():
                if rel in linted_rel and (ran_codes is None or code in ran_codes):
                    continue  # re-recorded below
                files.setdefault(rel, {})[code] = list(texts)
    for (rel, code), group in _groups(diags, root).items():
        if code == INTERNAL_ERROR:
            continue
        texts = [snippet(d, sources) for d in sorted(group, key=lambda d: d.sort_key)]
        files.setdefault(rel, {})[code] = texts
    return Baseline(root=root, files=files)


def dump(baseline: Baseline) -> str:
    files = {
        rel: {code: baseline.files[rel][code] for code in sorted(baseline.files[rel])}
        for rel in sorted(baseline.files)
        if baseline.files[rel]
    }
    data = {FORMAT_KEY: FORMAT_VERSION, "files": files}
    return json.dumps(data, indent=2, ensure_ascii=False) + "\n"


def write(path: str, baseline: Baseline) -> None:
    """Write the baseline file (atomically)."""
    from moos_lint.core.fix import Document, write_atomic

    text = dump(baseline)
    doc = Document(path, b"", text, "utf-8", False)
    write_atomic(doc)
