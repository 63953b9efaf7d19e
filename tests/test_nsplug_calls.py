"""The nsplug commands moos-lint reads in launch scripts, with the macros each gives."""

from __future__ import annotations

import os

from moos_lint.files.launch import made_by_scripts, nsplug_calls


def _calls(folder, text: str, name: str = "launch.sh"):
    (folder / name).write_text(text)
    return nsplug_calls(str(folder))


def test_macros_of_continued_lines_with_their_values(tmp_path):
    (call,) = _calls(
        tmp_path,
        "#!/bin/bash\n"
        "nsplug meta_vehicle.moos targ_$VNAME.moos -f WARP=$TIME_WARP \\\n"
        '    VNAME=$VNAME  VTYPE="kayak"  SIM   \\\n'
        "    --path=../plugs > /dev/null 2>&1\n",
    )
    assert call.line == 2
    assert call.template == os.path.join(str(tmp_path), "meta_vehicle.moos")
    assert call.output == "targ_$VNAME.moos"
    assert dict(call.macros) == {
        "WARP": None,
        "VNAME": None,
        "VTYPE": "kayak",
        "SIM": "<defined>",
    }
    assert not call.strict and not call.lenient


def test_a_variable_holding_only_options_is_read(tmp_path):
    calls = _calls(
        tmp_path,
        'NSFLAGS="--strict --force"\n'
        "NSFLAGS=\n"
        'if [ "$1" = "-i" ]; then NSFLAGS="-i -f"; fi\n'
        "nsplug meta.bhv targ.bhv $NSFLAGS VNAME=abe\n"
        "nsplug meta.bhv targ2.bhv ${LENIENT} VNAME=ben\n"
        "LENIENT=--lenient\n",
    )
    assert [(c.strict, c.lenient, dict(c.macros or {})) for c in calls] == [
        (True, False, {"VNAME": "abe"}),
        (False, True, {"VNAME": "ben"}),
    ]


def test_arguments_that_may_define_any_macro(tmp_path):
    calls = _calls(
        tmp_path,
        'MACROS="VNAME=abe WARP=1"\n'
        "nsplug meta.moos a.moos $MACROS\n"
        'nsplug meta.moos b.moos "$@"\n'
        "nsplug meta.moos c.moos --macros=vehicle.def\n"
        "nsplug meta.moos d.moos $UNSET\n"
        "nsplug meta.moos e.moos ${NAME}_PORT=9001\n",
    )
    assert [c.output for c in calls] == ["a.moos", "b.moos", "c.moos", "d.moos", "e.moos"]
    assert all(c.macros is None for c in calls)


def test_commands_in_a_line_and_what_is_no_call(tmp_path):
    calls = _calls(
        tmp_path,
        "nsplug meta.moos a.moos A=1 && pAntler a.moos & sleep 1; splug old.moos b.moos B\n"
        "echo nsplug meta.moos x.moos   # nsplug meta.moos y.moos\n"
        "nsplug -f meta.moos z.moos\n"  # nsplug takes the template only as its first argument
        "nsplug $META w.moos\n"  # a template named by a variable: a call, its path not known
        "nsplug meta.moos 'unclosed.moos\n"
        "cat <<EOF\n"
        "  nsplug meta.moos usage.moos VNAME=abe\n"
        "EOF\n"
        "cd ../other\n"
        "nsplug meta.moos later.moos\n",
    )
    assert [(c.output, dict(c.macros or {})) for c in calls] == [
        ("a.moos", {"A": "1"}),
        ("b.moos", {"B": "<defined>"}),
        ("w.moos", {}),
    ]
    assert calls[-1].template.endswith("$META")


def test_outputs_after_a_change_of_folder_are_made_at_launch(tmp_path):
    (tmp_path / "launch.sh").write_text(
        "nsplug meta.moos here.moos\ncd sub\nnsplug meta_sub.moos there.moos\n"
    )
    assert [c.output for c in nsplug_calls(str(tmp_path))] == ["here.moos"]
    made = made_by_scripts(str(tmp_path))
    assert {"here.moos", "there.moos"} <= made


def test_scripts_are_read_again_when_edited(tmp_path):
    assert [c.output for c in _calls(tmp_path, "nsplug m.moos a.moos\n")] == ["a.moos"]
    assert [c.output for c in _calls(tmp_path, "nsplug m.moos bb.moos X\n")] == ["bb.moos"]
