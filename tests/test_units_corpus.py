"""The frames-and-units rules (U001-U005) on the real MOOS-IvP missions.

MOOS-IvP's own missions give yaw in radians, headings in degrees, a valid
origin and small local coordinates, so the rules must stay silent on them. With
tightened options the same runs show that the rules really read the corpus'
forms (origins, vertex lists, op_vertex ...): every finding below was checked
by hand against its file. The corpus lives beside the repository in
``../shared/corpus``; the tests skip when it is absent.
"""

from __future__ import annotations

from pathlib import Path

import pytest

from moos_lint.core.config import Settings
from moos_lint.core.engine import lint_files
from moos_lint.files.discovery import discover

CORPUS = Path(__file__).resolve().parents[2] / "shared" / "corpus" / "moos-ivp"
UNITS = ["U001", "U002", "U003", "U004", "U005"]

pytestmark = pytest.mark.skipif(not CORPUS.is_dir(), reason="the MOOS-IvP corpus is not present")


def _lint(options: dict | None = None, select: list[str] | None = None):
    files = discover([CORPUS], [], str(CORPUS)).files
    settings = Settings(root=str(CORPUS), select=select or UNITS)
    settings.rule_options = options or {}
    result = lint_files(files, settings)
    assert result.internal_errors == 0
    return [
        (d.code, str(Path(d.span.path).relative_to(CORPUS)), d.span.line)
        for d in result.diagnostics
        if d.code in UNITS
    ]


def test_flagship_missions_are_clean():
    # U003 checks missions only when a selector names it: selected here so it does.
    assert _lint() == []


def test_missing_origin_where_the_apps_need_one():
    # Pretend the relay, plotting and pShare apps convert lat/long: exactly the three
    # missions without an origin are reported, at their first such Run line. The
    # indigo shoreside has no origin line either, but includes plugs that cannot be
    # followed (the origin is unknown there, not missing).
    needs = ["pLogger", "pShare", "uPlotViewer", "pXRelay", "pHelmIvP"]
    found = _lint({"latlong-origin": {"needs-origin": needs}}, ["U004"])
    assert found == [
        (
            "U004",
            "MOOS_Jul2724/MOOSEssentials/Essentials/pShare/pshare_test_scripts/pShareTest.moos",
            7,
        ),
        ("U004", "ivp/missions/plotview/meta_plotting.moos", 15),
        ("U004", "ivp/missions/xrelay/xrelay.moos", 12),
    ]


def test_work_area_reads_real_geometry():
    # The indigo missions draw an operating area whose two far corners,
    # (-100,-430) and (380,-240), lie 441 m and 449 m from the origin.
    found = _lint({"outside-work-area": {"max-distance": 440}}, ["U005"])
    assert found == [
        ("U005", "ivp/missions/m9_indigo/hotel.moos", 255),
        ("U005", "ivp/missions/m9_indigo/hotel.moos", 256),
        ("U005", "ivp/missions/s9_indigo/indigo.moos", 217),
        ("U005", "ivp/missions/s9_indigo/indigo.moos", 218),
    ]
    # The hand-written survey path of s8_hotel (a vertex list whose farthest vertex,
    # (-90,-420), is 429.5 m away) and its copy in ufld_hazard_sensor come in once the
    # limit drops below it.
    found = _lint({"outside-work-area": {"max-distance": 429}}, ["U005"])
    assert ("U005", "ivp/missions/s8_hotel/hotel.bhv", 27) in found
    assert ("U005", "ivp/missions/ufld_hazard_sensor/meta_archie.bhv", 21) in found
