"""Rule docs: complete, and the generated pages in rules/ are up to date."""

from __future__ import annotations

from pathlib import Path

import pytest

from moos_lint.commands.rule_page import missing_sections, render_rule_page
from moos_lint.core.registry import CODE_RE, NAME_RE, all_rules
from scripts.docs import main as docs_main

ROOT = Path(__file__).resolve().parent.parent
RULES = all_rules()


@pytest.mark.parametrize("rule", RULES, ids=[r.name for r in RULES])
def test_rule_has_every_doc_section(rule):
    assert missing_sections(rule) == [], f"{rule.name} docs lack sections"
    assert CODE_RE.match(rule.code) and NAME_RE.match(rule.name)


def test_codes_and_names_are_unique():
    assert len({r.code for r in RULES}) == len(RULES)
    assert len({r.name for r in RULES}) == len(RULES)


def test_rule_pages_are_current(capsys):
    status = docs_main([str(ROOT / "rules"), "--check"])
    out = capsys.readouterr().out
    assert status == 0, f"run `python3 scripts/docs.py rules`:\n{out}"


def test_page_renders_metadata():
    page = render_rule_page(RULES[0])
    assert page.startswith(f"# {RULES[0].code} {RULES[0].name}")
    assert "## How to fix" in page
