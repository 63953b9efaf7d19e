"""A mission's `KEY = NAME` line, where KEY renames what an app of the repository publishes."""

from __future__ import annotations

from moos_lint.core.config import Settings
from moos_lint.core.engine import lint_files

APP = """
#include "MOOS/libMOOS/MOOSLib.h"
class Drive : public CMOOSApp {
 public:
  bool OnStartUp();
  bool Iterate();
  std::string m_prefix;
  std::string m_out_var;
  double m_yaw;
};
Drive::Drive() { m_prefix = "THRUST"; m_out_var = "DRIVE_YAW"; }
bool Drive::OnStartUp() {
  STRING_LIST params;
  m_MissionReader.GetConfiguration(GetAppName(), params);
  for (STRING_LIST::iterator p = params.begin(); p != params.end(); p++) {
    std::string param = tolower(biteStringX(*p, '='));
    std::string value = *p;
    if (param == "prefix")
      m_prefix = value;
    else if (param == "out_var")
      m_out_var = toupper(value);
  }
  return true;
}
bool Drive::Iterate() {
  Notify(m_prefix + "_LEFT", 1.0);
  Notify(m_out_var, m_yaw * 180 / M_PI);
  return true;
}
int main(int argc, char* argv[]) { Drive d; d.Run("pDrive", argv[1]); return 0; }
"""

MISSION = """
ProcessConfig = pDrive
{
  prefix = MOTOR
  out_var = DRIVE_YAW_DEG
}
ProcessConfig = pOther
{
  prefix = MOTOR
}
"""


def test_keys_that_rename_a_publication_are_checked_at_the_mission(tmp_path):
    (tmp_path / "pDrive").mkdir()
    (tmp_path / "pDrive" / "Drive.cpp").write_text(APP)
    (tmp_path / "drive.moos").write_text(MISSION)
    files = [str(tmp_path / "pDrive" / "Drive.cpp"), str(tmp_path / "drive.moos")]
    result = lint_files(files, Settings(root=str(tmp_path), select=["N005", "N006"]))
    found = [
        (d.code, d.span.line, d.message)
        for d in result.diagnostics
        if d.span.path.endswith(".moos")
    ]
    assert [(code, line) for code, line, _m in found] == [("N005", 4), ("N006", 5)]
    message = found[0][2]
    assert "`MOTOR_LEFT` names the actuator `MOTOR`" in message
    assert "pDrive publishes `MOTOR_LEFT` under `prefix` + `_LEFT`" in message
    assert "(default `THRUST_LEFT`, Drive.cpp:26)" in message
    # the value the app publishes under the key is known: degrees
    assert "under `out_var` (default `DRIVE_YAW`, degrees, Drive.cpp:27)" in found[1][2]
    # a block of another app with the same key says nothing
    assert all(line != 10 for _c, line, _m in found)


def test_an_app_that_upper_cases_the_configured_name_is_left_alone(tmp_path):
    from moos_lint.files.source import SourceFile
    from moos_lint.frontends.cpp.app import parse_folder

    code = """
    bool R::OnStartUp() {
      STRING_LIST params;
      m_MissionReader.GetConfiguration(GetAppName(), params);
      for (STRING_LIST::iterator p = params.begin(); p != params.end(); p++) {
        std::string param = tolower(biteStringX(*p, '='));
        std::string value = *p;
        if (param == "a_var") m_a = value;
        else if (param == "b_var") { value = toupper(value); m_b = value; }
        else if (param == "c_var") {
          m_c = value;
          std::transform(m_c.begin(), m_c.end(), m_c.begin(), ::toupper);
        }
        else if (param == "d_var") m_d = MOOSToUpper(value);
        else if (param == "e_var") m_e = value;
      }
      return true;
    }
    bool R::Iterate() {
      Notify(m_a, 1.0); Notify(m_b, 1.0); Notify(m_c, 1.0); Notify(m_d, 1.0); Notify(m_e, 1.0);
      return true;
    }
    """
    files = parse_folder({"r/R.cpp": SourceFile("r/R.cpp", code)})
    upper = {p.name.config_key: p.name.config_upper for f in files for p in f.publications}
    assert upper == {"a_var": False, "b_var": True, "c_var": True, "d_var": True, "e_var": False}
