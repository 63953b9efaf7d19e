"""The C++ value analysis: units, senses, ranges and signs of what apps publish."""

from __future__ import annotations

import math
import re
from pathlib import Path

import pytest

from moos_lint.files.source import SourceFile
from moos_lint.frontends.cpp.app import parse_folder, read_relevant
from moos_lint.frontends.cpp.file_names import DEF_TEMPLATE, defined_names, setter_names
from moos_lint.frontends.cpp.values import (
    AbstractValue,
    RepositoryResolver,
    name_hint,
    neg,
    range_text,
    resolve_pending,
    to_rad,
    within_pi,
)


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


def test_a_branch_narrows_the_value_its_if_compares():
    v = published(
        """
        bool A::Iterate() {
          double y = atan2(m_dy, m_dx) + M_PI / 2;
          double out;
          if (y > M_PI)
            out = y - 2 * M_PI;
          else
            out = y;
          Notify("A_YAW", out);
          double w = atan2(m_dy, m_dx) + M_PI / 2;
          double o2 = 0;
          if (w > M_PI) {
            w = atan2(m_a, m_b);
            o2 = w;
          }
          Notify("B_YAW", o2);
          return true;
        }
        """
    )
    assert v["A_YAW"].range == pytest.approx((-math.pi, math.pi))
    assert v["B_YAW"].range == pytest.approx((-math.pi, math.pi))  # w is written in the if


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


def test_a_number_read_before_the_key_tests_is_the_variable_of_the_branch_using_it():
    # MOOS-IvP's app template reads ``dval`` once, above the tests of the key
    v = published(
        """
        bool A::OnNewMail(MOOSMSG_LIST &NewMail) {
          for (p = NewMail.begin(); p != NewMail.end(); p++) {
            CMOOSMsg &msg = *p;
            string key = msg.GetKey();
            double dval = msg.GetDouble();
            if (key == "NAV_DEPTH") m_d = dval;
            else if (key == "NAV_HEADING") m_h = dval;
            else if (key == "ODD_THING") m_o = dval;
            m_any = dval;
          }
          return true;
        }
        bool A::Iterate() {
          Notify("X_Z", m_d); Notify("X_HDG", m_h); Notify("X_ODD", m_o); Notify("X_ANY", m_any);
          return true;
        }
        """
    )
    assert v["X_Z"].sign == "down"
    assert (v["X_HDG"].unit, v["X_HDG"].sense) == ("deg", "heading")
    assert any("NAV_HEADING read by mail" in w for w in v["X_HDG"].why)
    assert all(v[k] is None or not v[k].known for k in ("X_ODD", "X_ANY"))


def test_old_apps_mail_taken_by_peekmail_is_the_variable_it_names():
    v = published(
        """
        bool A::OnNewMail(MOOSMSG_LIST &NewMail) {
          CMOOSMsg Msg;
          if (m_Comms.PeekMail(NewMail, "NAV_DEPTH", Msg)) m_d = Msg.m_dfVal;
          if (PeekMail(NewMail, "NAV_YAW", Msg) && !Msg.IsSkewed(MOOSTime())) {
            double dfVal = Msg.m_dfVal;
            m_y = dfVal;
          }
          return true;
        }
        bool A::Iterate() { Notify("X_Z", m_d); Notify("X_YAW", m_y); return true; }
        """
    )
    assert v["X_Z"].sign == "down"
    assert (v["X_YAW"].unit, v["X_YAW"].sense) == ("rad", "yaw")


def test_fmod_by_a_turn_wraps_radians_keeping_the_sign_of_what_it_divides():
    v = published(
        """
        bool A::Iterate() {
          double psi = m_psi, out, deg;
          if (psi < 0) out = fmod(psi, 2*M_PI) + 2*M_PI;
          else out = fmod(psi, 2*M_PI);
          Notify("A_YAW", out);
          if (psi < 0) Notify("B_YAW", fmod(psi, 2*M_PI));
          Notify("C_HEADING", fmod(m_course, 360.0));
          return true;
        }
        """
    )
    assert v["A_YAW"].unit == "rad"
    assert v["A_YAW"].range == pytest.approx((0.0, 2 * math.pi))
    assert v["B_YAW"].range == pytest.approx((-2 * math.pi, 0.0))
    assert v["C_HEADING"].unit == "deg"


def test_a_variable_handed_to_a_math_function_keeps_its_value():
    v = published(
        """
        bool A::Iterate() {
          double yaw = -m_nav_heading_deg * M_PI / 180.0;
          double s = sin(yaw) + sqrt(fabs(yaw)) + fmod(yaw, 1.0);
          Notify("A_YAW", yaw);
          return true;
        }
        """
    )
    assert v["A_YAW"].unit == "rad"


@pytest.mark.parametrize(
    ("name", "unit"),
    [("dpsi", None), ("m_dpsi", None), ("gyro_z_dps", "deg/s"), ("m_gyroDps", "deg/s")],
)
def test_dps_names_a_rate_in_degrees_only_as_a_word(name, unit):
    assert name_hint(name).unit == unit


def test_a_quarter_turn_keeps_a_math_angle_counter_clockwise_and_qualifiers_name_nothing():
    v = published(
        """
        bool A::Iterate() {
          double dy = m_y2 - m_y1, dx = m_x2 - m_x1;
          double h = atan2(dy, dx) * 180 / M_PI;
          Notify("HEADING_ESTIMATE", h + 90);
          Notify("GPS_HDG_FILTERED", 90 - h);
          return true;
        }
        """
    )
    assert v["HEADING_ESTIMATE"].sense == "math"
    assert any("still counter-clockwise" in w for w in v["HEADING_ESTIMATE"].why)
    assert v["GPS_HDG_FILTERED"].unit == "deg" and v["GPS_HDG_FILTERED"].sense is None


def test_a_library_file_is_parsed_only_when_a_flow_reaches_it(tmp_path):
    lib = tmp_path / "lib" / "Filter.cpp"
    other = tmp_path / "lib" / "Other.cpp"
    lib.parent.mkdir()
    lib.write_text("double Filter::pitch() const { return asin(m_s) * 180 / M_PI; }\n")
    other.write_text("double Other::roll() const { return 1.0; }\n")
    v = published('bool A::Iterate() { Notify("IMU_PITCH", m_filter.pitch()); return true; }')
    pending = v["IMU_PITCH"]
    assert pending.pending == "pitch"
    resolver = RepositoryResolver([str(lib), str(other)], _reader())
    out = resolve_pending(pending, resolver)
    assert out.unit == "deg"
    assert any("pitch() returns" in w and "Filter.cpp:1" in w for w in out.why)
    assert list(resolver.parsed) == [str(lib)]  # the other file is read, never parsed


def test_the_resolver_keeps_its_last_parsed_files_and_parses_an_older_one_again(
    tmp_path, monkeypatch
):
    from moos_lint.frontends.cpp import values

    monkeypatch.setattr(values, "KEEP_PARSED", 2)
    libs = []
    for i, angle in enumerate(("pitch", "roll", "yaw")):
        lib = tmp_path / f"L{i}.cpp"
        lib.write_text(f"double L{i}::{angle}() const {{ return asin(m_s) * 180 / M_PI; }}\n")
        libs.append(str(lib))
    resolver = RepositoryResolver(libs, lambda p: Path(p).read_bytes())
    first = resolver("pitch")
    assert first is not None and first.unit == "deg"
    for name in ("roll", "yaw"):
        assert resolver(name).unit == "deg"
    assert list(resolver.parsed) == libs[1:]  # the oldest went
    assert resolver.parsed_once == set(libs)
    resolver.cache.clear()
    again = resolver("pitch")  # parsed again, to the same value
    assert again == first
    assert list(resolver.parsed) == [libs[2], libs[0]]


def test_the_definition_index_names_exactly_what_the_per_name_search_finds():
    data = (
        b"double A::pitch (int x) const {\n"
        b"void roll\n(\n) override { if (x) { b(1); } }\n"
        b"int  yaw2(double v){ return g(v) ; }\n"
        b"x.heading() {}  ::depth() {} caf\xc3\xa9(){} speed(a(b)) {} alt(); {}\n"
    )
    words = set(re.findall(rb"\w+", data))
    for w in sorted(words):
        expected = re.search(DEF_TEMPLATE % re.escape(w), data) is not None
        assert (w in defined_names(data)) == expected, w
    assert {b"pitch", b"roll", b"yaw2", b"heading", b"depth", b"if"} <= defined_names(data)
    assert not {b"speed", b"alt", b"b", b"g"} & defined_names(data)


def test_unknown_stays_unknown():
    v = published('bool A::Iterate() { Notify("A_YAW", m_device.attitude()); return true; }')
    resolver = RepositoryResolver([], lambda p: b"")
    assert not resolve_pending(v["A_YAW"], resolver).known


def test_out_parameters_carry_what_the_function_sets():
    v = published(
        """
        void Imu::getAttitude(double& roll, double& pitch, double& yaw) {
          roll = asin(m_q) * 180.0 / M_PI;
          yaw = atan2(m_a, m_b);
          yaw *= 57.2957795;
        }
        void readOut(float* out) { *out = atan2(m_a, m_b) * 180 / M_PI; }
        void show(double v) { printf("%f", v); }
        void keep(const double& v, double* w) { m_last = v; }
        bool Imu::Iterate() {
          double r, p, y;
          getAttitude(r, p, y);
          Notify("IMU_YAW", y);
          Notify("IMU_ROLL", r);
          Notify("IMU_PITCH", p);
          float q;
          readOut(&q);
          Notify("IMU2_PITCH", q);
          double z = atan2(m_a, m_b);
          show(z);
          keep(z, &z);
          Notify("Z_YAW", z);
          return true;
        }
        """
    )
    assert v["IMU_YAW"].unit == "deg"
    assert any("getAttitude() sets `y`" in w for w in v["IMU_YAW"].why)
    assert v["IMU_ROLL"].unit == "deg"
    assert not v["IMU_PITCH"].known  # the function never sets it
    assert v["IMU2_PITCH"].unit == "deg"
    assert v["Z_YAW"].unit == "rad"  # passed by value, or to a pointer never written


def test_an_out_parameter_set_in_another_file_resolves_there(tmp_path):
    lib = tmp_path / "lib" / "Ahrs.cpp"
    lib.parent.mkdir()
    lib.write_text(
        "void Ahrs::euler(float* r, float* p, float* y) {\n"
        "  *y = atan2(m_a, m_b) * 57.29578f;\n}\n"
        "void Ahrs::log(double v) { m_v = v; }\n"
    )
    v = published(
        """
        bool A::Iterate() {
          float r, p, y;
          m_ahrs.euler(&r, &p, &y);
          Notify("AHRS_YAW", y);
          double w = atan2(m_a, m_b);
          m_ahrs.log(w);
          Notify("W_YAW", w);
          return true;
        }
        """
    )
    assert v["AHRS_YAW"].pending == "euler#2"
    resolver = RepositoryResolver([str(lib)], lambda p: Path(p).read_bytes())
    out = resolve_pending(v["AHRS_YAW"], resolver)
    assert out.unit == "deg" and any("Ahrs.cpp:2" in w for w in out.why)
    kept = resolve_pending(v["W_YAW"], resolver)  # log() sets nothing: as before the call
    assert kept.unit == "rad"


def test_print_labels_hint_a_unit_only_where_nothing_else_is_known():
    v = published(
        r"""
        bool Imu::Iterate() {
          double r = m_dev.r;
          double p = m_dev.p;
          double y = m_dev.y;
          double z = atan2(m_a, m_b);
          printf("Roll: %f deg, Pitch (deg): %.2f\n", r, p);
          MOOSTrace("yaw %f rad z [deg] %f\n", y, z);
          Notify("IMU_ROLL", r);
          Notify("IMU_PITCH", p);
          Notify("IMU_YAW", y);
          Notify("Z_YAW", z);
          Notify("G_ROLL", m_groll);
          Notify("T_ROLL", m_troll);
          return true;
        }
        bool Imu::buildReport() {
          m_msgs << "Gyro roll (deg/s): " << m_groll << endl;
          m_msgs << "Roll: " << m_troll << " deg" << endl;
          m_msgs << "Roll: " << m_troll << " rad" << endl;
          return true;
        }
        """
    )
    assert (v["IMU_ROLL"].unit, v["IMU_ROLL"].hint) == ("deg", True)
    assert v["IMU_PITCH"].unit == "deg" and "printed as degrees" in v["IMU_PITCH"].why[0]
    assert v["IMU_YAW"].unit == "rad"
    assert v["Z_YAW"].unit == "rad" and not v["Z_YAW"].hint  # the value wins over its label
    assert v["G_ROLL"].unit == "deg/s"
    assert not v["T_ROLL"].known  # printed with two units: no hint


def test_a_table_of_names_gives_each_of_its_names():
    files = parse_folder(
        {
            "app/App.cpp": SourceFile(
                "app/App.cpp",
                """
                static const char* kNames[] = {"THRUST_L", "MOTOR_RIGHT"};
                const std::string kAngles[3] = {"ROV_ROLL", "ROV_PITCH", "ROV_YAW"};
                bool A::Iterate() {
                  for (int i = 0; i < 2; i++) Notify(kNames[i], m_cmd[i]);
                  Notify(kAngles[2], m_yaw * 180 / M_PI);
                  return true;
                }
                """,
            )
        }
    )
    pubs = [(p.name.text, p.value.abstract) for f in files for p in f.publications]
    assert [name for name, _v in pubs] == ["THRUST_L", "MOTOR_RIGHT", "ROV_YAW"]
    assert pubs[2][1].unit == "deg"


def test_a_member_set_through_an_out_parameter_in_another_method():
    v = published(
        """
        void Ahrs::euler(double& roll, double& yaw) {
          roll = m_r;
          yaw = atan2(m_a, m_b) * 180.0 / M_PI;
        }
        bool A::OnNewMail(MOOSMSG_LIST& mail) { m_ahrs.euler(m_roll, m_yaw); return true; }
        bool A::Iterate() {
          Notify("A_YAW", m_yaw);
          Notify("A_ROLL", m_roll);
          return true;
        }
        """
    )
    assert v["A_YAW"].unit == "deg"
    assert any("euler() sets `m_yaw`" in w for w in v["A_YAW"].why)
    assert not v["A_ROLL"].known


def _write(tmp_path, files: dict[str, str]) -> list[str]:
    """Write ``files`` (relative path -> text) under ``tmp_path``: their paths."""
    paths = []
    for name, code in files.items():
        p = tmp_path / name
        p.parent.mkdir(parents=True, exist_ok=True)
        p.write_text(code)
        paths.append(str(p))
    return paths


def test_a_member_class_is_read_from_its_class_declaration(tmp_path):
    header = tmp_path / "GPSService.h"
    header.write_text(
        "class GPSService {\n public:\n  GPSFix fix;\n"
        "  GPSFix get() const { return fix; }\n  const nmea::GPSFix *last = nullptr;\n};\n"
    )
    resolver = RepositoryResolver([str(header)], _reader())
    assert resolver.member_class("GPSService", "fix") == "GPSFix"
    assert resolver.member_class("GPSService", "last") == "GPSFix"
    assert resolver.member_class("GPSService", "speed") is None


def _reader(reads: list[str] | None = None):
    """A resolver's file reader, noting each path it reads in ``reads``."""

    def reader(path):
        if reads is not None:
            reads.append(path)
        with open(path, "rb") as f:
            return f.read()

    return reader


def _resolve_in(tmp_path, files: dict[str, str], pending: AbstractValue) -> AbstractValue:
    paths = _write(tmp_path, files)
    return resolve_pending(pending, RepositoryResolver(sorted(paths), _reader()))


EULER_H = """
struct Euler {
  double roll() const { return m_roll; }
  double yaw() const { return m_yaw; }
  union {
    struct { double m_x; double m_y; double m_z; };
    struct { double m_roll; double m_pitch; double m_yaw; };
  };
};
"""


def test_a_field_written_through_a_typed_pointer_in_a_c_file_resolves_there(tmp_path):
    v = published('bool A::Iterate() { Notify("IMU_ROLL", m_e.roll()); return true; }')
    c_file = """
    void Euler_set(struct Euler* e, double q) {
      e->m_x = rad2deg(atan2(q, 1.0));
      e->m_y = 0.0;
    }
    void Euler_copy(struct Euler* e, const struct Euler* o) { e->m_x = o->m_x; }
    void Other_set(struct Other* o, double r) { o->m_x = r; }
    """
    out = _resolve_in(tmp_path, {"lib/euler.h": EULER_H, "lib/euler.c": c_file}, v["IMU_ROLL"])
    assert out.unit == "deg"
    assert any("the storage of `m_roll`" in w and "euler.c:3" in w for w in out.why)


def test_a_field_with_one_unknown_writer_stays_unknown(tmp_path):
    v = published('bool A::Iterate() { Notify("IMU_YAW", m_e.yaw()); return true; }')
    c_file = """
    void Euler_set(struct Euler* e, double q) { e->m_z = atan2(q, 1.0) * 180 / M_PI; }
    void Euler_put(Euler& e, double z) { e.m_yaw = z; }
    """
    out = _resolve_in(tmp_path, {"lib/euler.h": EULER_H, "lib/euler.c": c_file}, v["IMU_YAW"])
    assert not out.known


def test_a_struct_filled_by_reference_in_another_file():
    code = """
    struct Attitude { double pitch; };
    bool A::Iterate() {
      Attitude att;
      readAttitude(att);
      Notify("AHRS_PITCH", att.pitch);
      return true;
    }
    """
    v = published(code)["AHRS_PITCH"]
    # what the call that fills it sets the field to, else what any writer of the field does
    assert v.pending == "readAttitude#0.pitch"
    assert v.fallback is not None and v.fallback.pending == ".Attitude.pitch"


def test_the_call_that_fills_a_struct_decides_among_its_fields_writers(tmp_path):
    v = published(
        """
        bool A::Iterate() {
          orient_euler_deg(&m_e);
          Notify("IMU_EULER_P", m_e.p);
          return true;
        }
        """
    )["IMU_EULER_P"]
    c_file = """
    #define DIV_DEG (16.0)
    #define DIV_RAD (900.0)
    struct orient_euler_t { double p; };
    int orient_euler_deg(struct orient_euler_t *e) { e->p = raw_p() / DIV_DEG; return 0; }
    int orient_euler_rad(struct orient_euler_t *e) { e->p = raw_p() / DIV_RAD; return 0; }
    """
    out = _resolve_in(tmp_path, {"lib/orient.c": c_file}, v)
    assert out.unit == "deg" and "orient_euler_deg() sets `e->p`" in out.explanation


def test_a_member_printed_through_a_local_copy_takes_its_label():
    v = published(
        r"""
        bool Imu::Iterate() {
          Notify("IMU_ROLL", m_roll);
          Notify("IMU_PITCH", m_pitch);
          return true;
        }
        bool Imu::buildReport() {
          double roll = m_roll;
          double pitch = MOOSRad2Deg(m_pitch);
          m_msgs << "Roll (deg): " << roll << " Pitch (deg): " << pitch << endl;
          return true;
        }
        """
    )
    assert v["IMU_ROLL"].unit == "deg" and "through `roll`" in v["IMU_ROLL"].why[0]
    assert not v["IMU_PITCH"].known  # a converted copy says nothing of the member


def test_ned_is_a_word_of_a_name_not_letters_inside_one():
    from moos_lint.frontends.cpp.values import ned_z_name

    assert ned_z_name("m_ned.z") and ned_z_name("poseNED.z") and ned_z_name("ned_down")
    assert not ned_z_name("m_planned.z") and not ned_z_name("aligned_z")
    assert not ned_z_name("PLANNED_Z")


def test_a_raw_reading_scaled_by_a_resolution_named_in_degrees_is_degrees():
    v = published(
        """
        #define EULER_DIV_DEG (16.0)
        #define EULER_DIV_RAD (900.0)
        #define DEG_TO_RAD (0.01745329)
        bool A::Iterate() {
          m_Comms.Notify("IMU_PITCH", raw_pitch / EULER_DIV_DEG);
          m_Comms.Notify("IMU_ROLL", raw_roll / EULER_DIV_RAD);
          m_Comms.Notify("IMU_YAW", raw_yaw * DEG_TO_RAD);
          return true;
        }
        """
    )
    assert v["IMU_PITCH"].unit == "deg" and "EULER_DIV_DEG" in v["IMU_PITCH"].explanation
    assert v["IMU_ROLL"].unit == "rad"
    # a conversion constant is no resolution: the arithmetic decides (radians from degrees)
    assert v["IMU_YAW"].unit != "deg"


def test_the_classes_of_the_awaited_methods_are_searched_in_one_read(tmp_path):
    """Values wait for ``getHeading`` and ``toLat``, methods of NodeRecord and Geo that
    return a field: the files naming either class are found in one read, not one each."""
    files = {
        "lib/NodeRecord.h": "class NodeRecord {\n public:\n"
        "  double getHeading() const { return m_heading; }\n  double m_heading;\n};\n",
        "lib/NodeRecord.cpp": "void NodeRecord::set(double h) { m_heading = h * 180 / M_PI; }\n",
        "geo/Geo.h": "struct Geo {\n  double toLat() const { return m_lat; }\n"
        "  double m_lat;\n};\n",
        "geo/Geo.cpp": "void Geo::init(double d) { m_lat = d * 180 / M_PI; }\n",
        "app/Other.cpp": "int other() { return 1; }\n",
    }
    paths = _write(tmp_path, files)
    reads: list[str] = []
    resolver = RepositoryResolver(sorted(paths), _reader(reads))
    waiting = [AbstractValue(pending="getHeading"), AbstractValue(pending="toLat")]
    resolver.expect(waiting)
    outs = [resolve_pending(v, resolver) for v in waiting]
    assert [o.unit for o in outs] == ["deg", "deg"]
    # the index, the files naming either class; then each method's file and each file
    # writing its field, read to be parsed
    assert len(reads) == 2 * len(paths) + 4, reads


@pytest.mark.parametrize(
    ("comment", "unit"),
    [
        ("// degrees", "deg"),
        ("/**< Speed over the ground in kph */", "km/h"),
        ("/**< Speed over the ground in knots */", "kn"),
        ("//!< rate, deg/s", "deg/s"),
        ("// radians", "rad"),
        ("// in m/s", None),  # no unit of the rules: nothing to say
        ("// degrees or radians, as configured", None),
        ("/**< Speed in knots, or km/h when set so */", None),
        ("// the number of the sentence", None),
    ],
)
def test_a_declaration_comment_gives_one_unit(comment, unit):
    from moos_lint.frontends.cpp.values import declaration_hint

    v = declaration_hint(comment, "`Fix::x` (fix.h:3)")
    assert (v.unit if v is not None else None) == unit
    if v is not None:
        assert v.hint and "fix.h:3" in v.why[0]


def test_class_body_of_a_struct_and_of_a_typedef():
    from moos_lint.frontends.cpp.values import class_body

    data = b"struct A { int x; struct { int y; } in; };\ntypedef struct _B { double s; } B;\n"
    start, end = class_body(data, "A")
    assert data[start:end] == b" int x; struct { int y; } in; "
    start, end = class_body(data, "B")
    assert data[start:end] == b" double s; "
    assert class_body(data, "C") is None


SIM_ENGINE = """
void SimEngine::propagatePitch(NodeRecord& record, double dt, double rate)
{
  double new_pitch = angle180(record.getPitch() + rate * dt);
  record.setPitch(new_pitch);
}
"""


def test_a_getter_of_a_record_defined_elsewhere_is_what_its_setter_is_given(tmp_path):
    v = published('bool A::Iterate() { Notify("NAV_PITCH", m_record.getPitch()); return true; }')
    assert v["NAV_PITCH"].pending == "getPitch"
    out = _resolve_in(tmp_path, {"sim/SimEngine.cpp": SIM_ENGINE}, v["NAV_PITCH"])
    assert out.unit == "deg"
    assert out.why[-1].startswith("record.setPitch(...) at ") and "SimEngine.cpp:5" in out.why[-1]


def test_a_setter_given_a_value_we_cannot_read_leaves_its_getter_unknown(tmp_path):
    v = published('bool A::Iterate() { Notify("NAV_PITCH", m_record.getPitch()); return true; }')
    parse = "void load(NodeRecord& r, string s) { r.setPitch(atof(s.c_str())); r.setPitch(0); }"
    files = {"sim/SimEngine.cpp": SIM_ENGINE, "lib/parse.cpp": parse}
    assert not _resolve_in(tmp_path, files, v["NAV_PITCH"]).known


def test_the_index_of_the_first_read_spares_the_resolver_its_own(tmp_path):
    """The files' index, made where they were first read (``read_relevant``), is the
    resolver's: a setter is found in it without a read of every file, to the same value."""
    v = published('bool A::Iterate() { Notify("NAV_PITCH", m_record.getPitch()); return true; }')
    files = {
        "sim/SimEngine.cpp": SIM_ENGINE,
        "sim/Other.cpp": "void f(NodeRecord& r) { r.setPitchRate(1); }\n",
        "app/Main.cpp": "int main() { return 0; }\n",
    }
    paths = _write(tmp_path, files)
    names: dict = {}
    read_relevant(paths, names=names)
    assert set(names) == set(paths)
    reads: list[str] = []
    resolver = RepositoryResolver(sorted(paths), _reader(reads), None, names)
    resolver.expect([v["NAV_PITCH"]])
    out = resolve_pending(v["NAV_PITCH"], resolver)
    assert out.unit == "deg"
    assert reads == [str(tmp_path / "sim/SimEngine.cpp")]  # read once, to be parsed
    assert out == _resolve_in(tmp_path, files, v["NAV_PITCH"])


def test_a_file_names_a_setter_by_its_whole_name():
    data = b"r.setPitch(p); q.SetDepth(d); resetYaw(); m_setHeadingRate = 1; setup();"
    assert setter_names(data) == {
        b"setPitch",
        b"SetDepth",
        b"setYaw",
        b"setHeadingRate",
    }


def test_a_setter_call_on_another_class_is_not_the_getters(tmp_path):
    """``m_record`` is a NodeRecord: a call of ``setPitch`` on an object declared of another
    class is not its setter's, and its unreadable value leaves the getter known; on an
    object whose class is not declared (``auto``) it may be, and leaves it unknown."""
    app = """
    class A : public CMOOSApp { NodeRecord m_record; };
    bool A::Iterate() { Notify("NAV_PITCH", m_record.getPitch()); return true; }
    """
    v = published(app)
    assert v["NAV_PITCH"].pending == "getPitch" and v["NAV_PITCH"].receiver == "NodeRecord"
    other = "Record6DOF load(string s) { Record6DOF r; r.setPitch(atof(s.c_str())); return r; }"
    files = {"sim/SimEngine.cpp": SIM_ENGINE, "lib/parse.cpp": other}
    assert _resolve_in(tmp_path / "a", files, v["NAV_PITCH"]).unit == "deg"
    unknown = "void load(string s) { auto r = parse(s); r.setPitch(atof(s.c_str())); }"
    files = {"sim/SimEngine.cpp": SIM_ENGINE, "lib/parse.cpp": unknown}
    assert not _resolve_in(tmp_path / "b", files, v["NAV_PITCH"]).known


def test_a_library_class_method_is_what_the_library_says(tmp_path):
    """``euler.pitch()`` of an ``XsEuler`` is the Xsens SDK's degrees, known where it is
    called (before a name it is kept in says otherwise), even where the repository defines
    a ``pitch()`` of its own class in radians; a method of another class is still read
    from the repository."""
    app = """
    class A : public CMOOSApp { Attitude m_att; };
    void A::onPacket(const XsDataPacket& packet) {
      XsEuler euler = packet.orientationEuler();
      Notify("IMU_PITCH", euler.pitch());
      Notify("ATT_PITCH", m_att.pitch());
    }
    """
    v = published(app)
    assert v["IMU_PITCH"].pending is None and v["IMU_PITCH"].receiver == "XsEuler"
    assert v["ATT_PITCH"].receiver == "Attitude"
    own = "double Attitude::pitch() const { return asin(m_q); }"
    out = _resolve_in(tmp_path, {"lib/Attitude.cpp": own}, v["IMU_PITCH"])
    assert (out.unit, out.range) == ("deg", (-90.0, 90.0)) and "XsEuler" in out.why[0]
    assert _resolve_in(tmp_path, {"lib/Attitude.cpp": own}, v["ATT_PITCH"]).unit == "rad"


def test_a_library_method_returns_a_library_class_through_a_chain_or_an_auto():
    """``packet->orientationEuler().yaw()`` and ``auto e = packet.orientationEuler()``: the
    class of what an ``XsDataPacket``'s ``orientationEuler`` returns is ``XsEuler`` (a fact
    of the library); the same method of an app's own class gives no class, and an ``auto``
    that names itself ends."""
    app = """
    class A : public CMOOSApp { Frame m_frame; };
    void A::onPacket(const XsDataPacket* packet) {
      Notify("A_PITCH", packet->orientationEuler(XDI_CoordSysEnu).pitch());
      const auto& e = packet->orientationEuler();
      Notify("B_ROLL", e.roll());
      Notify("C_PITCH", m_frame.orientationEuler().pitch());
      auto loop = loop.orientationEuler();
      Notify("D_PITCH", loop.pitch());
    }
    """
    v = published(app)
    assert v["A_PITCH"].receiver == v["B_ROLL"].receiver == "XsEuler"
    assert v["C_PITCH"].receiver is None and v["D_PITCH"].receiver is None


def test_a_method_of_the_receivers_class_is_not_mixed_with_another_classs(tmp_path):
    """``m_att.pitch()`` of an ``Attitude``: the repository's ``Attitude::pitch`` gives the
    value (here one it cannot read), not ``Euler::pitch`` in degrees; a class that defines
    no ``pitch`` of its own (it inherits it) takes every definition, as before."""
    app = """
    class A : public CMOOSApp { Attitude m_att; Derived m_der; };
    bool A::Iterate() {
      Notify("ATT_PITCH", m_att.pitch());
      Notify("DER_PITCH", m_der.pitch());
      return true;
    }
    """
    v = published(app)
    files = {
        "lib/Euler.cpp": "double Euler::pitch() const { return asin(m_s) * 180.0 / M_PI; }",
        "lib/Attitude.h": "class Attitude {\n public:\n"
        "  double pitch() const { return atof(m_text.c_str()); }\n};\n",
    }
    assert not _resolve_in(tmp_path / "a", files, v["ATT_PITCH"]).known
    assert _resolve_in(tmp_path / "b", files, v["DER_PITCH"]).unit == "deg"


def test_setters_of_several_ranges_give_no_range(tmp_path):
    v = published('bool A::Iterate() { Notify("NAV_YAW", m_record.getYaw()); return true; }')
    code = """
    void turn(NodeRecord& record, double new_heading) {
      record.setYaw(-degToRadians(angle180(new_heading)));
    }
    void reverse(NodeRecord& record) {
      double new_yaw = MOOSDeg2Rad(record.getHeading()) + M_PI;
      record.setYaw(new_yaw);
    }
    """
    out = _resolve_in(tmp_path, {"sim/SimEngine.cpp": code}, v["NAV_YAW"])
    assert out.unit == "rad" and out.range is None


def test_each_branch_declares_its_own_message_of_its_own_type():
    code = """
    #include <IMC/Base/Message.hpp>
    void Bridge::on(IMC::Message* m) {
      if (m->getId() == 1) {
        GpsFix* msg = dynamic_cast<IMC::GpsFix*>(m);
        Notify("A_LAT", msg->lat);
      }
      if (m->getId() == 2) {
        EstimatedState* msg = dynamic_cast<IMC::EstimatedState*>(m);
        Notify("NAV_LAT", msg->lat);
      }
    }
    """
    v = published(code)
    assert v["NAV_LAT"].unit == "rad" and "EstimatedState" in v["NAV_LAT"].why[0]
    assert v["A_LAT"].pending == ".GpsFix.lat"


def test_a_library_class_by_its_namespace_only_where_the_file_names_it():
    own = (
        "struct EstimatedState { double lat; };\n"
        'void A::f(EstimatedState* s) { Notify("NAV_LAT", s->lat); }'
    )
    assert not published(own)["NAV_LAT"].known
    imc = own.replace(
        "struct EstimatedState { double lat; };", "using namespace IMC::Spec; // IMC::"
    )
    assert published(imc)["NAV_LAT"].unit == "rad"


def test_a_chained_assignment_gives_each_member_its_right_side():
    code = """
    A::A() { m_yaw = m_pitch = 0.; }
    void A::f(double h, double p) { m_yaw = MOOSDeg2Rad(h); m_pitch = MOOSDeg2Rad(p); }
    bool A::Iterate() { Notify("NAV_YAW", m_yaw); Notify("NAV_PITCH", m_pitch); return true; }
    """
    v = published(code)
    assert v["NAV_YAW"].unit == "rad" and v["NAV_PITCH"].unit == "rad"


@pytest.mark.parametrize(
    ("names", "device"),
    [
        ("class CiOS5000 : public CMOOSInstrument {};", True),
        ("void iOS5000_Hover::parseLine(string msg) {}", True),
        ("bool os5000::ParseNMEAString(string s) {}", True),
        ('reportRunWarning("Line from an OS4000 unit");', True),
        ("int dos5000 = 0; int OS50001 = 0;", False),
        ("class Compass {};", False),
    ],
)
def test_a_text_field_of_a_device_named_in_the_file_is_degrees(names, device):
    code = (
        names
        + """
    void A::f(char* s) {
      double p = atof(s);
      Notify("COMPASS_PITCH", p);
    }
    """
    )
    v = published(code)["COMPASS_PITCH"]
    assert (v.unit == "deg" and v.hint) is device
    if device:
        assert "OceanServer OS5000" in v.explanation


def test_a_member_set_to_a_sum_ending_in_a_literal_gives_the_name_s_end():
    code = """
    void A::prefixes(std::string pre) {
      m_pitch_name = pre + "PITCH";
      m_any = pre;
      m_two = pre + "ROLL";
      m_two = pre + "PITCH";
    }
    void A::f(double p) {
      Notify(m_pitch_name, p * 180 / M_PI);
      Notify(m_any, p);
      Notify(m_two, p);
    }
    """
    files = parse_folder({"app/App.cpp": SourceFile("app/App.cpp", code)})
    names = [(p.name.source, p.name.last) for f in files for p in f.publications]
    assert names == [("m_pitch_name", "PITCH"), ("m_any", ""), ("m_two", "")]


def test_a_behavior_s_buffer_reads_carry_what_the_variable_is():
    code = """
    IvPFunction* BHV_A::onRunState() {
      bool ok;
      double h = getBufferDoubleVal("NAV_HEADING", ok);
      double y = 0, other = 0;
      getBufferDoubleValX("NAV_YAW", y);
      getBufferDoubleValX("MY_ANGLE", other);
      double s = sin(h) + sin(y) + sin(other) + sin(getBufferDoubleVal("NAV_PITCH"));
      return 0;
    }
    """
    files = parse_folder({"lib_bhv_a/BHV_A.cpp": SourceFile("lib_bhv_a/BHV_A.cpp", code)})
    uses = {t.value.text: t.value.abstract for f in files for t in f.trig_uses}
    assert uses["h"].unit == "deg" and uses["h"].sense == "heading"
    assert "helm's buffer" in uses["h"].explanation
    assert uses["y"].unit == "rad"
    assert uses["other"].unit is None
    assert uses['getBufferDoubleVal("NAV_PITCH")'].unit == "rad"
