"""unknown-behavior (M003): its option, which the fixtures cannot show."""

from __future__ import annotations

from moos_lint.core.config import Settings
from moos_lint.core.engine import lint_files

BHV = "Behavior = BHV_Teleport\n{\n  name = beam\n}\n\nBehavior = BHV_Loitr\n{\n  name = orbit\n}\n"


def _lint(tmp_path, **opts) -> list[str]:
    (tmp_path / "m.bhv").write_text(BHV)
    settings = Settings(root=str(tmp_path), select=["M003"], rule_options=opts)
    result = lint_files([str(tmp_path / "m.bhv")], settings)
    assert result.internal_errors == 0
    return [d.message.split(":")[0] for d in result.diagnostics]


def test_a_kind_close_to_none_is_reported_only_with_all_kinds(tmp_path):
    assert _lint(tmp_path) == ["`BHV_Loitr`"]
    assert _lint(tmp_path, **{"unknown-behavior": {"all-kinds": True}}) == [
        "`BHV_Teleport`",
        "`BHV_Loitr`",
    ]
