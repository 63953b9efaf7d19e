"""The naming rules (N001-N006) on MOOS-IvP's own missions, checked by hand.

Every finding below was read against the mission and the app sources: the
rules must keep finding exactly these, and nothing else, in the corpus.
"""

from __future__ import annotations

from pathlib import Path

import pytest

from moos_lint.core.config import Settings
from moos_lint.core.engine import lint_paths

CORPUS = Path(__file__).resolve().parents[2] / "shared" / "corpus" / "moos-ivp"
CODES = ["N001", "N002", "N003", "N004", "N005", "N006"]

pytestmark = pytest.mark.skipif(not CORPUS.is_dir(), reason="MOOS-IvP corpus not available")


@pytest.fixture(scope="module")
def findings() -> dict[str, set[tuple[str, int, int]]]:
    settings = Settings(root=str(CORPUS))
    settings.select = list(CODES)
    result = lint_paths([CORPUS], settings)
    assert result.internal_errors == 0
    out: dict[str, set[tuple[str, int, int]]] = {code: set() for code in CODES}
    for d in result.diagnostics:
        rel = Path(d.span.path).resolve().relative_to(CORPUS.resolve()).as_posix()
        out[d.code].add((rel, d.span.line, d.span.col))
    return out


def test_process_name_prefix(findings):
    # Every mission's programs and aliases carry a prefix. The only unprefixed
    # aliases are in the pShare test script of MOOS core, test code the rule
    # leaves alone unless asked (`check-tests`).
    assert findings["N001"] == set()


def test_test_code_is_checked_when_asked():
    settings = Settings(root=str(CORPUS))
    settings.select = ["N001"]
    settings.rule_options["process-name-prefix"] = {"check-tests": True}
    folder = CORPUS / "MOOS_Jul2724" / "MOOSEssentials" / "Essentials" / "pShare"
    result = lint_paths([folder / "pshare_test_scripts"], settings)
    assert {(d.span.line, d.span.col) for d in result.diagnostics} == {(7, 37), (8, 37)}


def test_duplicate_process_name(findings):
    lab = "ivp/missions-minicourse/lab_henry_gilda_baseline"
    assert findings["N002"] == {
        (f"{lab}/meta_vehicle.moos", 25, 9),  # pRealm, first on line 15
        (f"{lab}/meta_shoreside.moos", 22, 9),  # pRealm, first on line 16
        # (the nsplug outputs of those two templates, kept in the repository beside them,
        # are not walked: their findings are the templates')
        ("ivp/missions/s5_echo/echo.moos", 27, 9),  # pLogger, first on line 23
    }


def test_variable_name_case(findings):
    # `# use_refinery=true` is split off by pMarineViewer as its own variable;
    # uXMS registers `IMS_*` literally. (`(alpha = one) or (bravo = two)` in three
    # behavior files is a placeholder nothing posts, beside a side that holds.)
    assert findings["N003"] == {
        # (line 191 posts `use_refinery` too: one finding per name and file)
        ("ivp/missions/m2_berta/meta_shoreside.moos", 190, 61),
        ("ivp/missions/m9_indigo/hotel.moos", 138, 9),
        ("ivp/missions/s9_indigo/indigo.moos", 103, 9),
    }


def test_units_sensors_and_actuators_are_quiet(findings):
    # MOOS-IvP names no variable after a unit and uses only the standard
    # actuators; its interface apps take no published names from their blocks.
    assert findings["N004"] == set()
    assert findings["N005"] == set()
    assert findings["N006"] == set()


def test_flagship_missions_are_clean(findings):
    clean = {
        "ivp/missions/s1_alpha/alpha.moos",
        "ivp/missions/s1_alpha/alpha.bhv",
        "ivp/missions/m2_berta/meta_vehicle.moos",
        "ivp/missions/m2_berta/meta_vehicle.bhv",
        "ivp/missions/m8_hugo/meta_surfacecraft.moos",
        "ivp/missions/xrelay/xrelay.moos",
    }
    for path in clean:
        assert (CORPUS / path).is_file(), path
    hits = {f[0] for code in CODES for f in findings[code]}
    assert not clean & hits
