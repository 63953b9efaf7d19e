"""A file named in a launched app's block (the helm's `behaviors`) that does not exist.

## What it does
In a mission (a `.moos` file with an ANTLER block, after nsplug expansion),
looks at the blocks of launched processes and reports a file parameter whose
file does not exist. By default these are pHelmIvP's `behaviors = FILE` and
uFldObstacleSim's `obstacle_file = FILE`. A relative name is looked up in
the folder of the mission file: the launch scripts start pAntler there, and
both apps open the name relative to their working folder.

## Why is this bad?
pHelmIvP reports "Could not find File: FILE" as a configuration warning,
posts `IVPHELM_STATE = MALCONFIG` and never takes control of the vehicle. uFldObstacleSim
reports "Error reading: FILE" and simulates no obstacles.

## Example
```moos
ProcessConfig = pHelmIvP
{
  behaviors = alhpa.bhv    // the file is alpha.bhv
}
```

## How to fix
Correct the file name, or add the file next to the mission.

## Options
- `file-params` (list of strings, default
  `["pHelmIvP:behaviors", "uFldObstacleSim:obstacle_file"]`): the parameters
  to check, as `PROGRAM:parameter`. The program is the one the Run line starts
  (an alias such as `pHelmIvP ~ pHelmIvP_Standby` is followed to its block).

A relative name is looked up from every folder the mission may be launched
from: the mission's own folder and its parents up to the project root
(launch scripts run `pAntler targs/targ_abe.moos` from the mission folder,
and the helm then opens `targs/targ_abe.bhv` from there).

A file that does not exist at rest but that a launch script beside the
mission makes with nsplug (`nsplug meta_vehicle.bhv targ_$VNAME.bhv`, for
`behaviors = targ_$(VNAME).bhv` or `targ_henry.bhv`) is reported when every
such command reads a template that does not exist (a template renamed or
never committed): nsplug then fails, and the helm finds no behavior file.
The script's names are read from the mission folder, up to its first `cd`.

MOOS-IvP caveats, deliberately not reported:
- a name holding an unexpanded `$(X)` macro (`targ_$(VNAME).bhv`: the launch
  script sets VNAME), or a `~` or `${X}`, unless the script's template is
  missing (above);
- a name `targ_*.EXT` that does not exist when a `meta_*.EXT` file with the
  same extension sits in the same folder: MOOS-IvP launch scripts generate
  the `targ_` files from the `meta_` templates with nsplug
  (`nsplug meta_vehicle.bhv targ_$VNAME.bhv`), so the file appears at launch;
- a file that a shell script of those folders writes (`gen_obstacles ... >
  obstacles.txt`) or removes (`rm -f obstacles.txt` in `clean.sh`): the launch
  makes it, so it is absent at rest (the scripts are read as text, never run);
- a file the project's `.gitignore` (or `.ignore`) leaves out where the mission
  would find it (`*.bhv`): behavior files deployed to the vehicle or written by
  a tool, kept out of the repository on purpose;
- pMarineViewer's `tiff_file`: the viewer looks for it in the MOOS-IvP data
  folder and in IVP_IMAGE_DIRS, not only next to the mission;
- any file named by the template of another generator, a mission with
  `{{NAME}}` placeholders (`speed = {{SPEED}}`): a script fills it in and
  writes the mission, with its behavior file, where it launches it.
"""

import fnmatch
import glob
import os
import re

from moos_lint.files.diagnostics import Severity
from moos_lint.files.gitignore import ignored_file
from moos_lint.files.launch import (
    find_relative,
    launch_folders,
    made_by_scripts,
    nsplug_calls,
    project_folder,
)
from moos_lint.frontends.parsers.nodes import has_macro, has_placeholder
from moos_lint.rules.hygiene._shared import exclusive, names_match
from moos_lint.rules.kit.declare import Scope, rule

FILE_PARAMS = ["pHelmIvP:behaviors", "uFldObstacleSim:obstacle_file"]


def _params(option) -> dict[str, set[str]]:
    out: dict[str, set[str]] = {}
    for item in option:
        app, sep, key = str(item).partition(":")
        if sep and app.strip() and key.strip():
            out.setdefault(app.strip().lower(), set()).add(key.strip().lower())
    return out


def _generated(folder: str, name: str) -> bool:
    """``targ_X.ext`` made by the launch script from a ``meta_*.ext`` template beside it."""
    base = os.path.basename(name)
    if not base.startswith("targ_"):
        return False
    ext = os.path.splitext(base)[1]
    where = os.path.join(folder, os.path.dirname(name))
    return bool(glob.glob(os.path.join(glob.escape(where), "meta_*" + ext)))


#: a macro of a name: nsplug's ``$(VNAME)`` in a mission, the shell's ``$VNAME`` or
#: ``${VNAME}`` in a launch script
_MACRO = re.compile(r"\$(?:\([^)]*\)|\{[^}]*\}|\[[^\]]*\]|\w+)")


def _missing_template(folder: str, name: str) -> str | None:
    """What is wrong when every launch-script ``nsplug TEMPLATE OUTPUT`` of ``folder``
    that writes ``name`` reads a template that does not exist (None when none writes it,
    or one template exists, is made at launch, or is named by a variable)."""
    wanted = _MACRO.sub("*", os.path.basename(name))
    calls = [
        c for c in nsplug_calls(folder) if fnmatch.fnmatchcase(wanted, _MACRO.sub("*", c.output))
    ]
    if not calls:
        return None
    made = made_by_scripts(folder)
    for call in calls:
        template = call.template
        if "$" in template or "`" in template or os.path.basename(template) in made:
            return None
        if os.path.exists(template):
            return None
    first = calls[0]
    return (
        f"{os.path.basename(first.script)}:{first.line} makes it with nsplug from "
        f"`{os.path.relpath(first.template, folder)}`, which does not exist"
    )


@rule(
    code="H003",
    name="missing-behavior-file",
    severity=Severity.ERROR,
    scope=Scope.MISSION,
    options={"file-params": FILE_PARAMS},
)
def check(ctx):
    wanted = _params(ctx.options.get("file-params", FILE_PARAMS))
    folders = launch_folders(ctx.unit.path, project_folder(ctx.settings, ctx.unit.path))
    seen: set[int] = set()
    for run in ctx.moos.runs:
        keys = wanted.get(run.program.lower())
        if not keys or not run.name or has_macro(run.name):
            continue
        for block in ctx.moos.blocks:
            if block.header is None or id(block) in seen or not names_match(block.name, run.name):
                continue
            if exclusive(block.header, run.param.line, ctx.expansion):
                continue
            seen.add(id(block))
            for p in block.params:
                if p.lkey not in keys:
                    continue
                name = "".join(p.value.split())  # MOOS drops every blank of a config line
                if len(name) >= 2 and name[0] == name[-1] == '"':
                    name = name[1:-1]
                if not name:
                    continue
                if find_relative(name, folders) or _templated(ctx):
                    continue
                missing = _missing_template(folders[0], name)
                if missing is not None:
                    yield ctx.report(
                        p.value_span,
                        f"`{p.key} = {name}`: {missing}, so the file is never made",
                        line=p.line,
                    )
                    continue
                if has_macro(name) or "~" in name or "${" in name:
                    continue
                if any(_generated(f, name) for f in folders):
                    continue
                if any(os.path.basename(name) in made_by_scripts(f) for f in folders):
                    continue  # a launch script writes it (and the clean script removes it)
                if _kept_out(name, folders):
                    continue  # git ignores it: kept out of the repository on purpose
                where = "next to the mission"
                if len(folders) > 1:
                    where += (
                        f" nor in the {len(folders) - 1} folder(s) above it up to the project root"
                    )
                yield ctx.report(
                    p.value_span,
                    f"`{p.key} = {name}`: no such file {where} ({os.path.basename(ctx.unit.path)})",
                    line=p.line,
                )


def _templated(ctx) -> bool:
    """Whether the mission is the template of another generator (``speed = {{SPEED}}``):
    the script that fills it in writes the mission, and the files it names, where it
    launches it. (Asked only of a file name not found: most missions have none.)"""
    return any(has_placeholder(line.text) for line in ctx.expansion.lines)


def _kept_out(name: str, folders: list[str]) -> bool:
    """Whether the project ignores the file where the mission would find it first
    (``*.bhv`` in a ``.gitignore``: behavior files deployed to the vehicle, or written by
    a tool, and never committed)."""
    if os.path.isabs(name):
        return False
    path = os.path.normpath(os.path.join(os.path.abspath(folders[0]), name))
    return ignored_file(path, os.path.abspath(folders[-1]))
