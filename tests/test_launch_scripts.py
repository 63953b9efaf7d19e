"""What moos-lint reads of the scripts beside a mission (as text, never run)."""

from __future__ import annotations

import subprocess
import sys

from moos_lint.files.launch import (
    antler_overrides,
    made_by_scripts,
    patch_launches,
    script_launches,
    script_names,
    scripts_beside,
    vehicle_names,
)


def test_files_a_launch_writes_or_cleans_away(tmp_path):
    (tmp_path / "init_field.sh").write_text(
        "#!/bin/bash\n"
        "gen_obstacles --amt=5 > obstacles.txt\n"
        'echo "$NAME" >> "logs/names.txt"\n'
        "# a comment > not_written.txt\n"
    )
    (tmp_path / "clean.sh").write_text("rm -rf $VERBOSE *~ *.moos++ targ_* results.dat\n")
    made = made_by_scripts(str(tmp_path))
    assert {"obstacles.txt", "names.txt", "results.dat"} <= made
    assert "not_written.txt" not in made
    assert not any("*" in m or m.startswith(("-", "$")) for m in made)
    # an edited script is read again
    (tmp_path / "clean.sh").write_text("rm -f vpositions.txt\n")
    assert "vpositions.txt" in made_by_scripts(str(tmp_path))
    assert "results.dat" not in made_by_scripts(str(tmp_path))


def test_nsplug_writes_its_output_also_from_a_scripts_folder(tmp_path):
    """``scripts/launch.sh`` running ``nsplug bhv.meta current.bhv`` makes current.bhv
    beside the templates; an output named by a shell variable is not known, and nsplug
    takes its template and output only as its first two arguments (main.cpp: an option
    first makes ``moos.meta`` the output of no template, and ``last.moos`` a macro)."""
    (tmp_path / "scripts").mkdir()
    (tmp_path / "scripts" / "launch.sh").write_text(
        "#!/bin/bash\n"
        "nsplug bhv.meta current.bhv -f ${FLAGS}\n"
        "nsplug 'first.meta' 'last.moos' -f WARP=$W\n"
        "nsplug -i moos.meta 'never.moos' -f WARP=$W\n"
        "nsplug meta_vehicle.moos targ_$VNAME.moos\n"
    )
    made = made_by_scripts(str(tmp_path))
    assert {"current.bhv", "last.moos"} <= made
    assert not any("$" in m for m in made)
    assert "bhv.meta" not in made and "moos.meta" not in made and "never.moos" not in made


def test_a_launched_script_and_the_scripts_beside_a_mission(tmp_path):
    mission = tmp_path / "m.moos"
    mission.write_text("")
    (tmp_path / "iSonar.py").write_text('comms.run("localhost", 9000, "iSonarV2")\n')
    (tmp_path / "notes.txt").write_text("")
    assert scripts_beside(str(mission)) == frozenset({"isonar"})
    assert "isonarv2" in (script_names(str(mission), "./iSonar.py") or ())
    assert script_names(str(mission), "pHelmIvP") is None  # a compiled program
    assert script_names(str(mission), "./missing.py") is None


def test_programs_a_script_or_a_patch_starts_with_the_mission(tmp_path):
    (tmp_path / "meta_shoreside.moos").write_text("ServerPort = 9000\n")
    (tmp_path / "launch.sh").write_text(
        "pAntler targ_shoreside.moos >& /dev/null &\n"
        '"$TRAFFIC_BIN" targ_shoreside.moos --alias=pTrafficManager &\n'
        "uCommand targ_commander_${VTEAM}.moos\n"
        "uMAC targ_$VNAME.moos\n"
    )
    (tmp_path / "logging.xmoos").write_text(
        "ProcessConfig = ANTLER\n{\n  Run = pLogger @ NewConsole = false\n"
        "  Run = ../bin/uTimerScript @ NewConsole = false ~ uTimerScript_PING\n}\n"
    )
    mission = str(tmp_path / "meta_shoreside.moos")
    assert script_launches(str(tmp_path), mission) == {"pantler", "ptrafficmanager", "umac"}
    assert patch_launches(str(tmp_path)) == {"plogger", "utimerscript", "utimerscript_ping"}


def test_a_script_without_a_suffix_and_commands_after_a_semicolon(tmp_path):
    """``script-200`` (no suffix, no ``#!``) runs pAntler and then the helm by hand on the
    output ``splug`` (nsplug's name before 2011) writes from the template: both start
    with the template too. A note or a data file without a suffix is no script."""
    (tmp_path / "script-200").write_text(
        "pAntler K200.moos &; sleep 1; pHelmIvP K200.moos ../missions/200-loiter.bhv &\n"
    )
    (tmp_path / "Expand.sh").write_text("#!/bin/sh\n\nsplug META_K200.moos K200.moos\n")
    (tmp_path / "waypoints").write_text("uSimMarine K300.moos\n")
    assert script_launches(str(tmp_path), "K200.moos") == {"pantler", "phelmivp"}
    # (and splug itself, which reads the template)
    assert {"pantler", "phelmivp"} <= script_launches(str(tmp_path), "META_K200.moos")
    assert script_launches(str(tmp_path), "K300.moos") == frozenset()
    assert "K200.moos" in made_by_scripts(str(tmp_path))  # made at launch, absent at rest


def test_keys_a_script_gives_pantler_for_the_mission(tmp_path):
    (tmp_path / "launch_alpha.sh").write_text(
        'COMMUNITY="alpha"\npAntler $COMMUNITY.moos --MOOSTimeWarp=$TIME_WARP >& /dev/null &\n'
    )
    (tmp_path / "launch_shore.sh").write_text(
        "$BIN/pAntler targ_shoreside.moos --LatOrigin=43.8 --LongOrigin=-70.3 &\n"
        "uMAC targ_shoreside.moos --MOOSTimeWarp=2\n"  # not pAntler: no copy is made
    )
    folder = str(tmp_path)
    assert antler_overrides(folder, str(tmp_path / "alpha.moos")) == {"moostimewarp"}
    assert antler_overrides(folder, str(tmp_path / "meta_shoreside.moos")) == {
        "moostimewarp",  # `$COMMUNITY.moos` may be any mission of the folder
        "latorigin",
        "longorigin",
    }
    (tmp_path / "launch_alpha.sh").write_text("pAntler alpha.moos >& /dev/null &\n")
    assert antler_overrides(folder, str(tmp_path / "shoreside.moos")) == set()


def test_vehicle_names_a_script_sets(tmp_path):
    (tmp_path / "launch.sh").write_text(
        'VNAME1="henry"   # the first vehicle\n'
        "  export VNAME2=gilda\n"
        "SHORE_VNAME='shoreside';\n"
        "VNAME=$1\n"  # a name given at run time: none known
        'VNAME="${ARGI#--vname=}"\n'
        'VNAME3="two words"\n'
        'VNAMES="abe:ben"  # a shoreside\'s list of its vehicles\n'
        "VNAMES=$VNAME1:$VNAME2\n"  # names given elsewhere
        "nsplug meta_vehicle.moos targ_$VNAME1.moos VNAME=$VNAME1\n"
    )
    (tmp_path / "notes.txt").write_text('VNAME="not_a_script"\n')
    assert vehicle_names(str(tmp_path)) == {"henry", "gilda", "shoreside", "abe", "ben"}


def test_programs_a_cmake_harness_starts_with_the_mission(tmp_path):
    (tmp_path / "alpha.moos").write_text("ServerPort = 9000\n")
    (tmp_path / "run_test.cmake").write_text(
        "EXECUTE_PROCESS( COMMAND uMissionTester alpha.moos\n"
        "    WORKING_DIRECTORY ${TEST_DIR} )\n"
        "EXECUTE_PROCESS( COMMAND alogcheck -i alpha.chk ${LOG_FILE} )\n"
    )
    (tmp_path / "CMakeLists.txt").write_text(
        "add_test(NAME beta COMMAND ${BIN}/pAntler beta.moos)\n"
        "add_test(NAME other COMMAND uSimMarine other.moos)\n"
    )
    assert script_launches(str(tmp_path), str(tmp_path / "alpha.moos")) == {"umissiontester"}
    assert script_launches(str(tmp_path), str(tmp_path / "beta.moos")) == {"pantler"}


def test_a_script_line_of_any_length_is_read_in_one_pass(tmp_path):
    """A self-extracting script holds one line of a payload: it is read in linear time
    (in a child process with a deadline, so that a regression fails, not hangs)."""
    (tmp_path / "install.sh").write_text("payload " + "A" * 300_000 + "\n")
    script = (
        "import sys\nfrom moos_lint.files.launch import script_launches\n"
        "print(sorted(script_launches(sys.argv[1], sys.argv[1] + '/m.moos')))"
    )
    done = subprocess.run(
        [sys.executable, "-c", script, str(tmp_path)], capture_output=True, text=True, timeout=60
    )
    assert done.returncode == 0 and done.stdout.strip() == "[]"


def test_a_run_lists_a_folders_scripts_once_and_the_next_run_again(tmp_path):
    """Within a lint run (``read_once``) a folder's scripts are listed and stamped once,
    however many missions and rules ask; the next run sees a script added or edited."""
    from moos_lint.files.launch import nsplug_calls, read_once

    (tmp_path / "launch.sh").write_text("nsplug m.moos a.moos\n")
    with read_once():
        assert [c.output for c in nsplug_calls(str(tmp_path))] == ["a.moos"]
        (tmp_path / "launch_b.sh").write_text("nsplug m.moos b.moos\n")
        assert [c.output for c in nsplug_calls(str(tmp_path))] == ["a.moos"]
    assert [c.output for c in nsplug_calls(str(tmp_path))] == ["a.moos", "b.moos"]
