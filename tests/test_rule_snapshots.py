"""Every finding of every rule's fixtures matches the rule's reviewed snapshot.

A change to a rule's message, span, severity or fix changes its snapshot
(``fixtures/rules/<rule>/snapshot.txt``, see tests/rule_snapshot.py) and fails
here with the diff. When the change is meant, rewrite the snapshots with

    python -m pytest tests/test_rule_snapshots.py --snapshot-update

and review their diff like code.
"""

from __future__ import annotations

import pytest

from moos_lint.core.fix import apply_fixes
from moos_lint.core.registry import all_rules
from tests.fixture_expect import FIXTURES, RULE_FIXTURES
from tests.rule_runs import FOLDERS, folder_run
from tests.rule_snapshot import SNAPSHOT_NAME, UPDATE_COMMAND, diff, render, snapshot_path

RULES = all_rules()
REPO = FIXTURES.parent
IDS = [r.name for r in RULES]


def _runs(rule):
    return {kind: folder_run(rule, kind) for kind in FOLDERS}


@pytest.mark.parametrize("rule", RULES, ids=IDS)
def test_findings_match_the_snapshot(rule, request):
    actual = render(rule, _runs(rule))
    assert str(REPO) not in actual, "a machine path would make the snapshot differ elsewhere"
    path = snapshot_path(rule)
    stored = path.read_text(encoding="utf-8") if path.exists() else None
    if request.config.getoption("snapshot_update"):
        if stored != actual:
            path.write_text(actual, encoding="utf-8", newline="\n")
        return
    if stored is None:
        pytest.fail(f"{rule.name} has no snapshot {path.name}: write it with `{UPDATE_COMMAND}`")
    if stored != actual:
        pytest.fail(
            f"{rule.name}: its findings differ from {path.parent.name}/{SNAPSHOT_NAME}.\n"
            f"If the change is meant, run `{UPDATE_COMMAND}` and review the diff.\n\n"
            + diff(stored, actual, f"{path.parent.name}/{SNAPSHOT_NAME}"),
            pytrace=False,
        )


@pytest.mark.parametrize("rule", RULES, ids=IDS)
def test_fixes_are_snapshotted_exactly_for_fixable_rules(rule):
    """A fixable rule has a fixture its fix rewrites; any other rule offers no fix."""
    runs = _runs(rule)
    offered = [d for run in runs.values() for d in run.findings if d.fix is not None]
    if not rule.fixable:
        assert not offered, f"{rule.name} offers fixes but is not declared `fixable=True`"
        return
    fire = runs["fire"]
    # (applied alone, through the fix code `--fix` runs; nothing is written)
    rewriting = [d for d in fire.findings if d.fix is not None and apply_fixes([d], {}).changed]
    assert rewriting, (
        f"{rule.name} is fixable, but none of its fire findings offers a fix that changes "
        "the file: add a fire fixture where its fix applies"
    )
    assert fire.fixed.changed, f"{rule.name}: `check --fix` changes none of its fixtures"


def test_every_snapshot_belongs_to_a_rule():
    names = {r.name for r in RULES}
    stray = sorted(p.parent.name for p in RULE_FIXTURES.glob(f"*/{SNAPSHOT_NAME}"))
    assert [n for n in stray if n not in names] == []
