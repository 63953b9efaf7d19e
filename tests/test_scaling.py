"""No rule is quadratic in a file's size.

Every rule is timed on generated inputs of ``SMALL`` and of ten times as many
blocks (a mission, a behavior file, a C++ app) that give it work of every kind
it does: duplicate and conditional blocks, launch lines, variables passed
between apps, angles, behaviors, publications. Ten times the input may take
about ten times as long; the check allows 25 times (and a floor for rules too
quick to time), so it catches a rule that is quadratic (a hundred times), not
a slow machine. The suite runs 500 and 5,000 blocks;
``MOOS_LINT_SCALING_BLOCKS=2000`` runs 2,000 and 20,000 (about two minutes).
"""

from __future__ import annotations

import gc
import os
import time
from pathlib import Path

import pytest

from moos_lint.core.config import Settings
from moos_lint.core.engine import Context, LintRun, _empty_unit
from moos_lint.core.registry import Scope, all_rules

SMALL = int(os.environ.get("MOOS_LINT_SCALING_BLOCKS", "500"))
BIG = 10 * SMALL
FACTOR = 25
#: a rule this quick on the small input is timed against this much instead
FLOOR = 0.005


def mission(n: int) -> str:
    """A mission of about ``n`` blocks (``ProcessConfig`` and behavior-like blocks)."""
    out = [
        "ServerHost = localhost\nServerPort = 9000\nCommunity = alpha\n",
        "LatOrigin = 43.825300\nLongOrigin = -70.330400\nMOOSTimeWarp = 1\n",
        "ProcessConfig = ANTLER\n{\n  MSBetweenLaunches = 200\n",
        "  Run = MOOSDB @ NewConsole = false\n",
    ]
    for i in range(0, n, 4):
        out.append(f"  Run = pApp{i} @ NewConsole = false ~ pApp{i}\n")
        out.append(f"  Run = uTimerScript @ NewConsole = false ~ uTimerScript_{i}\n")
    out.append("  Run = pHelmIvP @ NewConsole = false\n  Run = pEchoVar @ NewConsole = false\n}\n")
    out.append("ProcessConfig = pHelmIvP\n{\n  AppTick = 4\n  behaviors = big.bhv\n}\n")
    out.append("ProcessConfig = pEchoVar\n{\n  AppTick = 4\n")
    for i in range(n):
        out.append(f"  echo = NAV_HEADING_{i} -> DESIRED_heading_{i}\n")
    out.append("}\n")
    for i in range(n):
        kind = i % 8
        if kind == 0:
            out.append(f"ProcessConfig = pApp{i}\n{{\n  AppTick = 4\n  heading = 370\n}}\n")
        elif kind == 1:
            out.append(f"ProcessConfig = uTimerScript_{i - 1}\n{{\n")
            out.append(f"  event = var=NAV_HEADING_{i}, val=3.5, time=0\n  yaw = 90\n}}\n")
        elif kind == 2:  # a second block for an earlier name, and one name many times
            name = f"pApp{i - 2}" if i % 16 == 2 else "pDuplicate"
            out.append(f"ProcessConfig = {name}\n{{\n  AppTick = 4\n}}\n")
        elif kind == 3:  # blocks in exclusive branches
            out.append(f"#ifdef SIM_{i}\nProcessConfig = pX{i}\n{{\n}}\n#else\n")
            out.append(f"ProcessConfig = pX{i}\n{{\n  depth = -5\n}}\n#endif\n")
        elif kind == 4:
            out.append(f"ProcessConfig = iGPS{i} {{\n  Port = /dev/ttyUSB{i}\n")
            out.append("  nav_x = 1e9\n  unknownkey = 1\n}\n")
        elif kind == 5:
            out.append(f"ProcessConfig = pLogger\n{{\n  Log = DESIRED_heading_{i} @ 0\n")
            out.append(f"  // moos-lint: ignore[R999]\n  AsyncLog = true   // {'x' * 40}\n}}\n")
        elif kind == 6:
            out.append(f"ProcessConfig = uSimMarine_{i}\n{{\n  start_heading = 7\n")
            out.append("  start_x = 0\n  start_y = 0\n  thrust_map = 0:0, 20:1\n}\n")
        else:
            # a misspelt global: still reported in a mission that launches unknown apps
            out.append(f"MOOSTimeWrap = {i}\nProcessConfig = pBad{i}\n{{\n  x = 1\n  }}\n}}\n")
    out += ["ProcessConfig = pDuplicate\n{\n}\n"] * n  # one name, many blocks
    return "".join(out)


def behaviors(n: int) -> str:
    """A behavior file of about ``n`` behaviors."""
    out = ["initialize DEPLOY = false\ninitialize RETURN = false\n\n"]
    for i in range(n):
        # every tenth name is used twice; no name starts with another one
        name = f"wpt_{i - 1 if i % 10 == 9 else i}_end"
        out.append(f"Behavior = BHV_Waypoint\n{{\n  name = {name}\n  pwt = 100\n")
        out.append(f"  condition = MODE_{i} == true\n  updates = WPT_UPDATE_{i}\n")
        out.append(f"  endflag = DONE_{i} = true\n  speed = 1.2\n  heading = 400\n")
        out.append("  points = 0,0:10,10:20,0\n  bogus_param = 1\n}\n\n")
    return "".join(out)


def cpp_app(n: int) -> dict[str, str]:
    """A MOOS app whose OnNewMail, OnStartUp and Iterate make about ``n`` calls each."""
    header = """\
#include "MOOS/libMOOS/App/MOOSApp.h"
class Compass : public CMOOSApp
{
public:
  bool OnNewMail(MOOSMSG_LIST &NewMail);
  bool Iterate();
  bool OnConnectToServer();
protected:
  double m_heading;
};
"""
    body = ['#include "Compass.h"\n#include <cmath>\n\nbool Compass::OnConnectToServer()\n{\n']
    body += [f'  Register("IN_{i}", 0);\n' for i in range(n)]
    body.append("  return true;\n}\n\nbool Compass::OnNewMail(MOOSMSG_LIST &NewMail)\n{\n")
    body.append("  for (auto &msg : NewMail) {\n    std::string key = msg.GetKey();\n")
    body += [f'    if (key == "IN_{i}") m_heading = msg.GetDouble();\n' for i in range(n)]
    body.append("  }\n  return true;\n}\n\nbool Compass::Iterate()\n{\n")
    for i in range(n):
        if i % 3 == 0:
            body.append(f'  Notify("DESIRED_HEADING_{i}", m_heading * M_PI / 180.0);\n')
        elif i % 3 == 1:
            body.append(f'  Notify("NAV_YAW_{i}", m_heading);\n')
        else:
            body.append(f'  Notify("out_{i}", 7.5);\n')
    body.append("  return true;\n}\n")
    main = '#include "Compass.h"\nint main(int argc, char *argv[])\n{\n  Compass app;\n'
    main += '  app.Run("pCompass", "pCompass.moos");\n  return 0;\n}\n'
    return {"Compass.h": header, "Compass.cpp": "".join(body), "main.cpp": main}


def write_inputs(folder: Path, n: int) -> list[str]:
    folder.mkdir()
    (folder / "big.moos").write_text(mission(n))
    (folder / "big.bhv").write_text(behaviors(n))
    app = folder / "pCompass"
    app.mkdir()
    for name, text in cpp_app(n).items():
        (app / name).write_text(text)
    return [str(folder / "big.moos"), str(folder / "big.bhv"), *(str(p) for p in app.iterdir())]


def rule_times(files: list[str], root: str) -> tuple[dict[str, float], set[str]]:
    """Each rule's time on the inputs (processor time, which other work on the machine
    does not inflate: the best of two, after a first untimed pass that builds the
    models the rules share), and the codes found."""
    from moos_lint.semantics.cpp_units import build_cpp_units

    settings = Settings(root=root)
    rules = all_rules()
    run = LintRun(settings, rules)
    run.units = [run.build_unit(p) for p in files if not p.endswith((".cpp", ".h"))]
    run.units += build_cpp_units(run, [p for p in files if p.endswith((".cpp", ".h"))])
    for unit in run.units:
        run.included_elsewhere.update(p for p in unit.expansion.sources if p != unit.path)
    times: dict[str, float] = {}
    found: set[str] = set()
    for r in rules:
        targets = [u for u in run.units if r in run._rules_for(u)]
        if r.scope is Scope.PROJECT:
            targets = [_empty_unit()]
        best = float("inf")
        for attempt in range(3):
            started = time.process_time()
            for unit in targets:
                ctx = Context(r, unit, settings, run, settings.options_for(r.name))
                found.update(d.code for d in r.check(ctx) or ())
            if attempt:
                best = min(best, time.process_time() - started)
        times[r.code] = best
    return times, found


@pytest.fixture(scope="module")
def timings(tmp_path_factory) -> tuple[dict[str, float], dict[str, float], set[str]]:
    base = tmp_path_factory.mktemp("scaling")
    small = write_inputs(base / "small", SMALL)
    big = write_inputs(base / "big", BIG)
    enabled = gc.isenabled()
    gc.disable()
    try:
        small_times, found = rule_times(small, str(base / "small"))
        big_times, _ = rule_times(big, str(base / "big"))
    finally:
        if enabled:
            gc.enable()
    return small_times, big_times, found


@pytest.mark.parametrize("rule", all_rules(), ids=lambda r: r.name)
def test_rule_time_grows_linearly(rule, timings):
    small, big, _ = timings
    allowed = FACTOR * max(small[rule.code], FLOOR)
    assert big[rule.code] <= allowed, (
        f"{rule.name}: {small[rule.code]:.4f} s on {SMALL:,} blocks, "
        f"{big[rule.code]:.4f} s on {BIG:,}"
    )


def test_the_inputs_give_the_rules_work(timings):
    """The generated inputs make the rules report (the check times real work)."""
    *_, found = timings
    expected = {"H001", "H002", "H004", "H005", "M001", "M004", "M005", "N003", "R003"}
    assert expected | {"R006", "R011", "U001"} <= found
