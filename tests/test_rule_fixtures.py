"""Every rule fires on its `fire` fixtures exactly where they say, and stays quiet on `quiet`.

The inline ``expect:`` markers pin where each finding is; the rule's snapshot
(tests/test_rule_snapshots.py) pins everything else about it.
"""

from __future__ import annotations

import pytest

from moos_lint.core.registry import all_rules
from tests.fixture_expect import RULE_FIXTURES, expectations, linted_files
from tests.rule_runs import folder_run

RULES = all_rules()


def _findings(rule, kind: str) -> set[tuple[str, int, str]]:
    run = folder_run(rule, kind)
    assert run.result.internal_errors == 0, [d.message for d in run.result.diagnostics]
    return {(d.span.path, d.span.line, d.code) for d in run.findings}


@pytest.mark.parametrize("rule", RULES, ids=[r.name for r in RULES])
def test_fires_where_marked(rule):
    folder = RULE_FIXTURES / rule.name / "fire"
    assert linted_files(folder), f"{rule.name} has no fixtures that fire in {folder}"
    expected = {e for e in expectations(folder) if e[2] == rule.code}
    assert expected, f"{rule.name}: fire fixtures carry no `expect: {rule.code}` marker"
    assert _findings(rule, "fire") == expected


@pytest.mark.parametrize("rule", RULES, ids=[r.name for r in RULES])
def test_quiet_fixtures_stay_quiet(rule):
    folder = RULE_FIXTURES / rule.name / "quiet"
    assert linted_files(folder), f"{rule.name} has no fixtures that stay quiet in {folder}"
    assert _findings(rule, "quiet") == set()
