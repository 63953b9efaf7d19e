"""The configuration-hygiene rules (H001-H005) on MOOS-IvP's own files, reviewed by hand.

Each expected finding below was checked against the file (and, for the apps,
against the MOOS-IvP sources). The corpus lives beside the repository in
``../shared/corpus``; the tests skip when it is absent.
"""

from __future__ import annotations

from pathlib import Path

import pytest

from moos_lint.core.config import Settings
from moos_lint.core.engine import lint_files
from moos_lint.files.discovery import discover

CORPUS = Path(__file__).resolve().parents[2] / "shared" / "corpus" / "moos-ivp"
MISSIONS = "ivp/missions"

pytestmark = pytest.mark.skipif(not CORPUS.is_dir(), reason="the MOOS-IvP corpus is not present")


def _findings(paths: list[Path], select: list[str], **options) -> set[tuple[str, int, str]]:
    settings = Settings(root=str(CORPUS), select=select, rule_options=options)
    result = lint_files([str(p) for p in paths], settings)
    assert result.internal_errors == 0
    return {
        (Path(d.span.path).relative_to(CORPUS).as_posix(), d.span.line, d.code)
        for d in result.diagnostics
    }


@pytest.fixture(scope="module")
def corpus():
    files = discover([CORPUS], [], str(CORPUS)).files
    assert len(files) >= 500
    settings = Settings(root=str(CORPUS), select=["H001", "H002", "H004", "H005"])
    result = lint_files(files, settings)
    assert result.internal_errors == 0
    return {
        (Path(d.span.path).relative_to(CORPUS).as_posix(), d.span.line, d.code)
        for d in result.diagnostics
    }


def _of(found: set, code: str) -> set:
    return {f for f in found if f[2] == code}


def test_unlaunched_process_config(corpus):
    assert _of(corpus, "H001") == {
        # block kept for a process the shoreside does not launch
        (f"{MISSIONS}/berta_cmgr/meta_shoreside.moos", 105, "H001"),  # uLoadWatch
        (f"{MISSIONS}/m2_berta/meta_shoreside.moos", 106, "H001"),  # uLoadWatch
        (f"{MISSIONS}/m8_hugo/meta_shoreside.moos", 103, "H001"),  # pMOOSBridge
        (f"{MISSIONS}/t1_field_scope/alpha.moos", 62, "H001"),  # uProcessWatch
    }


def test_unlaunched_process_config_commented_runs():
    """Blocks whose Run line is commented out are switched off on purpose, unless the
    ``commented-runs`` option asks for them."""
    paths = [
        CORPUS / MISSIONS / "m2_berta_otest" / "meta_vehicle.moos",
        CORPUS / MISSIONS / "s1_alpha_msurvey" / "alpha.moos",
        CORPUS / MISSIONS / "t1_alpha" / "alpha.moos",
    ]
    assert _findings(paths, ["H001"]) == set()
    opts = {"unlaunched-process-config": {"commented-runs": True}}
    assert _findings(paths, ["H001"], **opts) == {
        (f"{MISSIONS}/m2_berta_otest/meta_vehicle.moos", 39, "H001"),  # uTimerScript
        (f"{MISSIONS}/s1_alpha_msurvey/alpha.moos", 40, "H001"),  # pMovingSurvey
        (f"{MISSIONS}/t1_alpha/alpha.moos", 54, "H001"),  # iSay
        (f"{MISSIONS}/t1_alpha/alpha.moos", 65, "H001"),  # uTimerScript
    }


def test_missing_process_config(corpus):
    assert _of(corpus, "H002") == {
        # XMODE=M300 launches iM300; plugs.moos has no <iM300> section
        (f"{MISSIONS}/berta_cmgr/meta_vehicle.moos", 33, "H002"),
        (f"{MISSIONS}/m2_berta/meta_vehicle.moos", 33, "H002"),
        # pShare launched; neither the file nor its included plug sections configure it
        (f"{MISSIONS}/m2_berta_pmed/meta_vehicle.moos", 17, "H002"),
        # pOdometry launched without a block
        (f"{MISSIONS}/x1_alpha/alpha.moos", 38, "H002"),
    }


def test_duplicate_behavior_name_respects_exclusive_ifdefs(corpus):
    # m2_berta_detect/meta_vehicle.bhv names two behaviors "loiter", one under
    # `#ifdef MISSION_ROLE SIDE`, the other under `#ifdef MISSION_ROLE MIDDLE`.
    assert _of(corpus, "H004") == set()


def test_unknown_key(corpus):
    # MOOS-IvP's own missions set only keys MOOS reads: `Simulator = true` (in five of
    # them) is the simulate mode CMOOSApp read before MOOS v10, a known global.
    assert _of(corpus, "H005") == set()
    assert "Simulator" in (CORPUS / MISSIONS / "x1_alpha" / "alpha.moos").read_text()


def test_unknown_key_knows_antler_lists():
    # XConfig=1..4 and ExtraProcessParams=HParams name lists in the ANTLER block
    paths = [
        CORPUS / MISSIONS / "u6_alpha/meta_shoreside.moos",
        CORPUS / MISSIONS / "s11_kilo/kilo.moos",
    ]
    assert _findings(paths, ["H005"]) == set()


def test_missing_behavior_file_skips_generated_targets():
    # Every helm in the corpus names alpha.bhv-like files that exist, a
    # targ_$(VNAME).bhv, or targ_alpha.bhv generated from meta_alpha.bhv.
    files = discover([CORPUS], [], str(CORPUS)).files
    opts = {"missing-behavior-file": {"file-params": ["pHelmIvP:behaviors"]}}
    assert _findings([Path(f) for f in files], ["H003"], **opts) == set()


def test_missing_behavior_file_on_a_generated_target(tmp_path):
    # mem1_alpha names targ_alpha.bhv; without its meta_alpha.bhv template beside
    # it the name would be reported.
    src = CORPUS / MISSIONS / "mem1_alpha/meta_alpha.moos"
    assert _findings([src], ["H003"]) == set()
    copy = tmp_path / "meta_alpha.moos"
    copy.write_bytes(src.read_bytes())
    settings = Settings(root=str(tmp_path), select=["H003"])
    result = lint_files([str(copy)], settings)
    assert [d.message.split(":")[0] for d in result.diagnostics] == ["`behaviors = targ_alpha.bhv`"]
