"""What moos-lint reads of the scripts beside a mission (as text, never run)."""

from __future__ import annotations

from moos_lint.files.launch import made_by_scripts, script_names, scripts_beside


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


def test_a_launched_script_and_the_scripts_beside_a_mission(tmp_path):
    mission = tmp_path / "m.moos"
    mission.write_text("")
    (tmp_path / "iSonar.py").write_text('comms.run("localhost", 9000, "iSonarV2")\n')
    (tmp_path / "notes.txt").write_text("")
    assert scripts_beside(str(mission)) == frozenset({"isonar"})
    assert "isonarv2" in (script_names(str(mission), "./iSonar.py") or ())
    assert script_names(str(mission), "pHelmIvP") is None  # a compiled program
    assert script_names(str(mission), "./missing.py") is None
