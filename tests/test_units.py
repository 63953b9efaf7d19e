"""Angle fields, geometry strings and the fixes of the frames-and-units rules."""

from __future__ import annotations

import math
import os
from pathlib import Path

import pytest

from moos_lint.core.config import Settings
from moos_lint.core.engine import lint_files
from moos_lint.semantics.angles import angle_kind, format_rad, literal_number, wrap_pi
from moos_lint.semantics.geometry import geometry_points, start_pos_points


@pytest.mark.parametrize(
    ("name", "kind"),
    [
        ("NAV_YAW", "yaw"),
        ("start_yaw", "yaw"),
        ("YAW", "yaw"),
        ("NAV_PITCH", "pitch"),
        ("NAV_ROLL", "roll"),
        ("TILT_RADIANS", "radian"),
        ("yaw_pid_kp", None),
        ("YAW_RATE", None),
        ("NAV_HEADING", None),
        ("turn1_rad", None),
        ("maxpitch", None),
        ("PATROLLING", None),
        ("", None),
    ],
)
def test_angle_kind(name, kind):
    assert angle_kind(name) == kind


def test_literals_and_radians():
    assert literal_number(" -90 ") == -90.0
    assert literal_number("1e2") == 100.0
    assert literal_number("$(YAW)") is None
    assert literal_number('"90"') is None
    assert literal_number("90,0") is None
    assert literal_number("nan") is None
    assert format_rad(math.pi / 2) == "1.5708"
    assert format_rad(0.0) == "0"
    assert format_rad(-1e-9) == "0"
    assert wrap_pi(math.radians(270)) == pytest.approx(-math.pi / 2)
    assert wrap_pi(-math.pi) == pytest.approx(math.pi)


@pytest.mark.parametrize(
    ("text", "points"),
    [
        ("60,-40 : 60,-160 : 150,-40", [(60, -40), (60, -160), (150, -40)]),
        ("label,transit:190,25:155,-20", [(190, 25), (155, -20)]),
        ("0,0,5 : 10,10", [(0, 0), (10, 10)]),
        ("pts={-200,-200:30,-60}, label=loiter", [(-200, -200), (30, -60)]),
        ("pts = {60,-40 : 60,-160}", [(60, -40), (60, -160)]),
        ("format=radial, x=75, y=-75, radius=30, pts=8, snap=1", [(75, -75)]),
        ("radial:: x=20, y=-80, radius=20, pts=8", [(20, -80)]),
        ("radial:: x=0,y=-75, radius=20", [(0, -75)]),
        ("radial: 20, -80, 20, 8", [(20, -80)]),
        ("format=lawnmower, x=80, y=-80, width=70, height=30", [(80, -80)]),
        ("x=15, y=0", [(15, 0)]),
        ("x=380, y=-240,lwidth=1,lcolor=yellow", [(380, -240)]),
        # forms that are not understood, or not known yet, are never guessed
        ("$(START_POS)", None),
        ("radial:: $(LOITER_POS), radius=20", None),
        ("format=lawnmower, x=$(X), y=10", None),
        ("oval: 1,2, rad=15", None),
        ("pylon: x1=0, y1=0, x2=900, y2=0", None),
        ("format=zigzag, x=10, y=10", None),
        ("start", None),
        ("present_position", None),
        ("3:4", None),
        ("60,-40 : north", None),
        ("", None),
    ],
)
def test_geometry_points(text, points):
    assert geometry_points(text) == points


def test_start_pos():
    assert start_pos_points("x=0, y=-20, heading=180, speed=0") == [(0, -20)]
    assert start_pos_points("80,0, 180, 0") == [(80, 0)]
    assert start_pos_points("$(START_POS), 180, 0") is None
    assert start_pos_points("heading=180") is None


def _lint(tmp_path: Path, name: str, text: str, code: str, defines=None):
    path = tmp_path / name
    path.write_text(text, encoding="utf-8")
    settings = Settings(root=str(tmp_path), select=[code], defines=dict(defines or {}))
    result = lint_files([str(path)], settings)
    assert result.internal_errors == 0
    return [d for d in result.diagnostics if d.code == code]


def test_yaw_fix_replaces_the_literal(tmp_path):
    text = (
        "ProcessConfig = uTimerScript\n"
        "{\n"
        "  event = var=NAV_YAW, val=270, time=10\n"
        "  START_YAW = 90\n"
        "}\n"
    )
    found = _lint(tmp_path, "a.moos", text, "U001")
    assert [d.span.line for d in found] == [3, 4]
    first, second = found
    assert "270·π/180 = 4.7124 rad" in first.message
    assert "-1.5708 rad wrapped to ±π" in first.message
    (edit,) = first.fix.edits
    assert (edit.span.line, edit.span.col, edit.span.end_col) == (3, 28, 31)
    assert edit.text == "-1.5708"
    line = text.splitlines()[2]
    assert line[edit.span.col - 1 : edit.span.end_col - 1] == "270"
    (edit,) = second.fix.edits
    assert (edit.span.col, edit.span.end_col, edit.text) == (15, 17, "1.5708")


def test_yaw_fix_in_a_behavior_file(tmp_path):
    text = "initialize DEPLOY=false, NAV_YAW=-180\n"
    (found,) = _lint(tmp_path, "a.bhv", text, "U001")
    (edit,) = found.fix.edits
    assert (edit.span.col, edit.span.end_col) == (34, 38)
    assert edit.text == "3.1416"


def test_no_fix_when_the_value_comes_from_a_macro(tmp_path):
    text = "ProcessConfig = uSim\n{\n  START_YAW = $(YAW)\n}\n"
    (found,) = _lint(tmp_path, "a.moos", text, "U001", {"YAW": "90"})
    assert found.fix is None
    assert "1.5708" in found.message


def test_wrap_fix(tmp_path):
    text = "initialize NAV_YAW=4.71\n"
    (found,) = _lint(tmp_path, "a.bhv", text, "U002")
    assert found.fix.edits[0].text == "-1.5732"


def test_radian_value_from_a_degree_fix_is_quiet(tmp_path):
    # What U001's fix writes for 180 degrees (3.1416) is not "unwrapped".
    text = "initialize NAV_YAW=3.1416, NAV_PITCH=-3.1416\n"
    assert _lint(tmp_path, "a.bhv", text, "U002") == []


_PITCHED_APP = """\
#include "MOOS/libMOOS/MOOSLib.h"
class Tilt : public CMOOSInstrument
{
  bool Iterate();
  double m_pitch;
};
bool Tilt::Iterate()
{
  Notify("TILT_PITCH", m_pitch * 180.0 / M_PI);
  return true;
}
int main(int argc, char *argv[])
{
  Tilt app;
  app.Run("iTilt", argv[1]);
}
"""


@pytest.mark.parametrize(
    ("select", "extend", "options", "missions"),
    [
        (None, [], {}, False),  # the default: C++ only
        (None, [], {"in-missions": True}, True),
        (None, ["U003"], {}, True),  # named by a selector: as when it was opt-in
        (["angle-in-degrees"], [], {}, True),
        (["ALL"], [], {}, True),
        (["U"], [], {}, True),
    ],
)
def test_angle_in_degrees_checks_missions_when_asked(tmp_path, select, extend, options, missions):
    (tmp_path / "iTilt").mkdir()
    (tmp_path / "iTilt" / "Tilt.cpp").write_text(_PITCHED_APP)
    (tmp_path / "a.moos").write_text("ProcessConfig = uTimerScript\n{\n  START_PITCH = 15\n}\n")
    settings = Settings(
        root=str(tmp_path),
        select=select,
        extend_select=extend,
        rule_options={"angle-in-degrees": options} if options else None,
    )
    paths = [str(tmp_path / "a.moos"), str(tmp_path / "iTilt" / "Tilt.cpp")]
    result = lint_files(paths, settings)
    assert result.internal_errors == 0
    found = sorted(os.path.basename(d.span.path) for d in result.diagnostics if d.code == "U003")
    assert found == (["Tilt.cpp", "a.moos"] if missions else ["Tilt.cpp"])
