"""The C++ value analysis: units, senses, ranges and signs of what apps publish."""

from __future__ import annotations

import math

import pytest

from moos_lint.cpp.app import parse_folder
from moos_lint.cpp.values import (
    AbstractValue,
    RepositoryResolver,
    neg,
    range_text,
    resolve_pending,
    to_rad,
    within_pi,
)
from moos_lint.source import SourceFile


def published(code: str) -> dict[str, AbstractValue]:
    files = parse_folder({"app/App.cpp": SourceFile("app/App.cpp", code)})
    return {p.name.last: p.value.abstract for f in files for p in f.publications}


def test_heading_in_360_made_a_yaw_lies_in_minus_two_pi():
    h = AbstractValue(unit="deg", sense="heading", range=(0.0, 360.0))
    y = neg(to_rad(h, "conv"))
    assert (y.unit, y.sense) == ("rad", "yaw")
    assert within_pi(y.range) is False
    assert range_text(y.range, y.unit) == "[-2π, 0]"


def test_wrap_loops_and_angle180_keep_yaw_within_pi():
    v = published(
        """
        bool A::Iterate() {
          double h = m_raw_heading_deg;
          while (h > 180) h -= 360;
          while (h < -180) h += 360;
          Notify("A_YAW", -h * M_PI / 180.0);
          Notify("B_YAW", -degToRadians(angle180(m_raw_heading_deg)));
          double y = atan2(m_dy, m_dx);
          if (y < 0) y += 2 * M_PI;
          Notify("C_YAW", y);
          return true;
        }
        """
    )
    assert v["A_YAW"].unit == "rad" and within_pi(v["A_YAW"].range)
    assert v["B_YAW"].sense == "yaw" and within_pi(v["B_YAW"].range)
    assert v["C_YAW"].range == pytest.approx((0.0, 2 * math.pi))


def test_constants_fold_to_conversions_and_define_factors():
    v = published(
        """
        #define R2D (180.0/M_PI)
        bool A::Iterate() {
          Notify("P_PITCH", m_p * R2D);
          Notify("Q_PITCH", m_p * 57.2957795);
          Notify("R_PITCH", m_p / 180.0 * M_PI);
          Notify("S_PITCH", m_p * 100.0);
          return true;
        }
        """
    )
    assert v["P_PITCH"].unit == "deg"
    assert v["Q_PITCH"].unit == "deg"
    assert v["R_PITCH"].unit == "rad"
    assert v["S_PITCH"].unit is None  # another scale: unknown, never reported


def test_mail_units_flow_through_members_set_in_another_method():
    v = published(
        """
        bool A::OnNewMail(MOOSMSG_LIST &NewMail) {
          for (p = NewMail.begin(); p != NewMail.end(); p++)
            if (p->GetKey() == "NAV_DEPTH") m_d = p->GetDouble();
          return true;
        }
        bool A::Iterate() { Notify("X_Z", m_d); return true; }
        """
    )
    assert v["X_Z"].sign == "down"
    assert any("NAV_DEPTH read by mail" in w for w in v["X_Z"].why)


def test_a_library_file_is_parsed_only_when_a_flow_reaches_it(tmp_path):
    lib = tmp_path / "lib" / "Filter.cpp"
    other = tmp_path / "lib" / "Other.cpp"
    lib.parent.mkdir()
    lib.write_text("double Filter::pitch() const { return asin(m_s) * 180 / M_PI; }\n")
    other.write_text("double Other::roll() const { return 1.0; }\n")
    v = published('bool A::Iterate() { Notify("IMU_PITCH", m_filter.pitch()); return true; }')
    pending = v["IMU_PITCH"]
    assert pending.pending == "pitch"
    read = []

    def reader(path):
        read.append(path)
        with open(path, "rb") as f:
            return f.read()

    resolver = RepositoryResolver([str(lib), str(other)], reader)
    out = resolve_pending(pending, resolver)
    assert out.unit == "deg"
    assert any("pitch() returns" in w and "Filter.cpp:1" in w for w in out.why)
    assert list(resolver.parsed) == [str(lib)]  # the other file is read, never parsed


def test_unknown_stays_unknown():
    v = published('bool A::Iterate() { Notify("A_YAW", m_device.attitude()); return true; }')
    resolver = RepositoryResolver([], lambda p: b"")
    assert not resolve_pending(v["A_YAW"], resolver).known
