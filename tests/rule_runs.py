"""Lint one rule's fixture folder the way the rule tests do, once per test session.

A rule's fixtures are in ``fixtures/rules/<rule>/{fire,quiet}/``; each folder
is linted as one run with the rule's ``moos-lint.toml`` when it has one (else
the rule alone, rooted at the rule's folder). The runs are kept: the
expectation tests and the snapshot tests read the same findings.
"""

from __future__ import annotations

import functools
from dataclasses import dataclass

from moos_lint.core.config import Settings, load_config
from moos_lint.core.engine import Result, lint_files
from moos_lint.core.fix import FixOutcome, fix_until_stable
from moos_lint.core.registry import Rule, get_rule
from tests.fixture_expect import RULE_FIXTURES, linted_files

FOLDERS = ("fire", "quiet")


def settings_for(rule: Rule) -> Settings:
    cfg = RULE_FIXTURES / rule.name / "moos-lint.toml"
    if cfg.exists():
        settings = load_config(cfg)
    else:
        settings = Settings(root=str(RULE_FIXTURES / rule.name))
    if settings.select is None:
        settings.select = [rule.code]
    return settings


@dataclass(frozen=True)
class FolderRun:
    """One fixture folder linted, and then fixed in memory as ``check --fix`` would."""

    rule: Rule
    kind: str  # "fire" or "quiet"
    files: tuple[str, ...]
    result: Result
    fixed: FixOutcome

    @property
    def findings(self):
        """This rule's findings (the folder may select other rules too), in report order."""
        return [d for d in self.result.diagnostics if d.code == self.rule.code]


@functools.cache
def _run(code: str, kind: str) -> FolderRun:
    rule = get_rule(code)
    files = [str(p) for p in linted_files(RULE_FIXTURES / rule.name / kind)]

    def lint(cache=None) -> Result:
        return lint_files(files, settings_for(rule), cache=cache)

    result = lint()
    # the real `--fix` loop (moos_lint.core.fix), in memory: nothing is written
    fixed = fix_until_stable(lint, first=result)
    return FolderRun(rule, kind, tuple(files), result, fixed)


def folder_run(rule: Rule, kind: str) -> FolderRun:
    return _run(rule.code, kind)
