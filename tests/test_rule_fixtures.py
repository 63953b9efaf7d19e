"""Every rule fires on its `fire` fixtures exactly where they say, and stays quiet on `quiet`."""

from __future__ import annotations

from pathlib import Path

import pytest

from moos_lint.config import Settings, load_config
from moos_lint.engine import lint_files
from moos_lint.registry import all_rules
from tests.fixture_expect import RULE_FIXTURES, expectations, linted_files

RULES = all_rules()


def _settings(rule) -> Settings:
    cfg = RULE_FIXTURES / rule.name / "moos-lint.toml"
    if cfg.exists():
        settings = load_config(cfg)
    else:
        settings = Settings(root=str(RULE_FIXTURES / rule.name))
    if settings.select is None:
        settings.select = [rule.code]
    return settings


def _findings(rule, folder: Path) -> set[tuple[str, int, str]]:
    files = [str(p) for p in linted_files(folder)]
    result = lint_files(files, _settings(rule))
    assert result.internal_errors == 0, [d.message for d in result.diagnostics]
    return {(d.span.path, d.span.line, d.code) for d in result.diagnostics if d.code == rule.code}


@pytest.mark.parametrize("rule", RULES, ids=[r.name for r in RULES])
def test_fires_where_marked(rule):
    folder = RULE_FIXTURES / rule.name / "fire"
    assert linted_files(folder), f"{rule.name} has no fixtures that fire in {folder}"
    expected = {e for e in expectations(folder) if e[2] == rule.code}
    assert expected, f"{rule.name}: fire fixtures carry no `expect: {rule.code}` marker"
    assert _findings(rule, folder) == expected


@pytest.mark.parametrize("rule", RULES, ids=[r.name for r in RULES])
def test_quiet_fixtures_stay_quiet(rule):
    folder = RULE_FIXTURES / rule.name / "quiet"
    assert linted_files(folder), f"{rule.name} has no fixtures that stay quiet in {folder}"
    assert _findings(rule, folder) == set()
