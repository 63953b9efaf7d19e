"""A behavior that needs a helm domain variable (`depth`) the helm's `Domain` lines do not give.

## What it does
In a mission (after nsplug expansion, its includes included) that launches
pHelmIvP, reads the helm's decision space from its `Domain` lines
(`Domain = course:0:359:360`) and reports each behavior of its behavior files
whose kind halts the helm without one of those variables: BHV_ConstantDepth,
BHV_GoToDepth and BHV_MaxDepth need `depth`, BHV_ConstantHeading `course`,
BHV_ConstantSpeed and BHV_MaxSpeed `speed` (the catalogue holds each with
the line of MOOS-IvP that checks it). The helm compares domain names in their
case: `Domain = Depth:0:100:101` gives no `depth`, and the finding says so.

Not judged: a mission that launches no helm or more than one, a helm block
without `Domain` lines, one whose `Domain` line holds an nsplug macro or sits
in an `#ifdef` branch (the domain may differ by configuration), a helm whose
`behaviors` file is not known for sure (`targ_$(VNAME).bhv` beside a
template per kind of vehicle), a behavior in an `#ifdef` branch, and
behaviors of kinds the catalogue does not describe or the project defines
itself (its copy may not check).

## Why is this bad?
The behavior checks the domain each time it runs (`onRunState`:
`if(!m_domain.hasDomain("depth")) postEMessage(...)`, BHV_ConstantDepth.cpp).
`postEMessage` posts `BHV_ERROR` and marks the behavior's state bad for good
(IvPBehavior.cpp); the helm engine then halts the helm (HelmEngine.cpp:
`if(!m_bhv_set->stateOK(bhv_ix)) m_helm_report.setHalted(true)`), and
pHelmIvP posts an all-stop (`BehaviorError`, HelmIvP.cpp) at every iteration
after. The usual cause is a surface vehicle's mission given a dive behavior
(`course` and `speed` only), or a domain line copied in another case.

## Example
```moos
ProcessConfig = pHelmIvP
{
  behaviors = bravo.bhv
  Domain    = course:0:359:360
  Domain    = speed:0:4:21
}
```
with `bravo.bhv`:
```
Behavior = BHV_ConstantDepth   // needs `depth`: the helm halts when it runs
{
  name  = dive
  depth = 30
}
```

## How to fix
Give the helm the domain (`Domain = depth:0:100:101`), or take the
behavior out of a vehicle that does not dive.

## Options
None.
"""

from __future__ import annotations

import os

from moos_lint.files.diagnostics import Severity, Subject
from moos_lint.frontends.parsers.nodes import has_macro
from moos_lint.rules.kit.declare import Kind, Scope, rule
from moos_lint.rules.kit.wording import listed
from moos_lint.rules.mission._behaviors import repo_classes
from moos_lint.semantics.mission_model import meta_templates, mission_model


@rule(
    code="M014",
    name="missing-helm-domain",
    severity=Severity.WARNING,
    scope=Scope.MISSION,
    kinds=(Kind.MOOS,),
)
def check(ctx):
    moos = ctx.moos
    if ctx.expansion.incomplete or not moos.is_mission:
        return
    model = mission_model(ctx)
    helms = [p for p in model.processes if p.binary.lower() == "phelmivp"]
    if len(helms) != 1 or helms[0].block is None or not model.behavior_files:
        return
    lines = helms[0].block.get("domain")
    if not lines:
        return
    folder = os.path.dirname(model.path)
    if not all(_one_file(p.value, folder) for p in helms[0].block.get("behaviors")):
        return
    given: dict[str, str] = {}  # each domain name -> where it is given
    for p in lines:
        if p.line.branches or has_macro(p.value):
            return
        # (pHelmIvP's handleConfigDomain: ``,`` read as ``:``, the name first)
        name = p.value.strip().replace(",", ":").split(":", 1)[0].strip()
        given.setdefault(name, f"{_short(p.line.path)}:{p.line.lineno}")
    cat = model.catalogue
    for _path, bf in model.behavior_files:
        for bhv in bf.behaviors:
            kind = bhv.kind.strip()
            info = cat.behavior(kind)
            if info is None or not info.domains or bhv.header.branches:
                continue  # (in an `#ifdef` branch: maybe not in this vehicle's helm)
            for var, evidence in sorted(info.domains.items()):
                if var in given or kind.lower() in repo_classes(ctx):
                    continue  # (the project's own copy of the kind may not check)
                cased = next((n for n in given if n.lower() == var.lower()), None)
                if cased is not None:
                    why = (
                        f"they give `{cased}`, {given[cased]}, and the helm compares domain "
                        "names in their case"
                    )
                else:
                    have = listed([f"`{n}`" for n in given])
                    why = f"only {have}, {given[next(iter(given))]}"
                yield ctx.report(
                    bhv.kind_span,
                    f"{kind} needs the helm domain `{var}`, which {helms[0].name}'s Domain "
                    f"lines do not give ({why}): when the behavior runs, it posts BHV_ERROR "
                    f"and the helm halts, posting an all-stop from then on ({evidence})",
                    line=bhv.header,
                    subject=Subject(key="domain"),
                )


def _one_file(value: str, folder: str) -> bool:
    """Whether a ``behaviors`` value names one file for sure: a name without a macro, or
    nsplug's output ``targ_$(VNAME).bhv`` of the one template of its folder
    (``meta_vehicle.bhv``); not when the folder holds a template per kind of vehicle."""
    name = "".join(value.split()).strip('"')
    if not has_macro(name):
        return True
    base = os.path.basename(name)
    if not base.startswith("targ_") or has_macro(os.path.dirname(name)):
        return False
    where = os.path.join(folder, os.path.dirname(name))
    ext = os.path.splitext(base)[1] or ".bhv"
    return len(meta_templates(where, ext)) == 1


def _short(path: str) -> str:
    return path.replace("\\", "/").rsplit("/", 1)[-1]
