"""An Antler `Run` line with options after its `~` alias, which pAntler ignores.

## What it does
Reports a `Run` line in the ANTLER block with text after the alias that
follows its `~`: `Run = pX @ NewConsole = false ~ pX_2, ExtraProcessParams = P`,
or the same without the comma (`~ pX_2 ExtraProcessParams = P`).

## Why is this bad?
pAntler reads a Run line in three parts (`CreateMOOSProcess`, pAntler's
Antler.cpp): the program is the text before the first `@`, the options
(`NewConsole`, `ExtraProcessParams`, `XConfig`, `InhibitMOOSParams`, `PATH`)
are the text between the `@` and the first `~`, and the MOOS name is the
first comma-separated word after the `~`. What follows the alias's comma is
never read: the extra parameters are not passed, the console options not
used, and nothing says so. Without the comma it is worse: pAntler reads the
line with its spaces removed, so the process connects under a name such as
`pX_2ExtraProcessParams=P` and reads a ProcessConfig block of that name,
which no mission has.

## Example
```moos
ProcessConfig = ANTLER
{
  Run = pSonarDetect @ NewConsole = false ~ pSonarDetect_sim, ExtraProcessParams = SimParams
  SimParams = --verbose
}
```

## How to fix
Put every option between the `@` and the `~` (the fix moves them there):
```moos
  Run = pSonarDetect @ NewConsole = false, ExtraProcessParams = SimParams ~ pSonarDetect_sim
```

## Options
None.
"""

from moos_lint.files.diagnostics import Edit, Fix, Severity
from moos_lint.frontends.parsers.nodes import has_macro
from moos_lint.rules.kit.declare import Scope, rule


@rule(
    code="R015",
    name="run-option-after-alias",
    severity=Severity.WARNING,
    scope=Scope.FILE,
    fixable=True,
)
def check(ctx):
    for run in ctx.moos.runs:
        alias, comma, rest = run.alias_text.partition(",")
        words = alias.split()
        if not run.has_at or not words:
            continue
        if comma and rest.strip():
            ignored = rest.strip()
            how = "reads no more than the first word after the `~` (the MOOS name)"
        elif len(words) > 1 and "=" in alias:
            ignored = " ".join(words[1:])
            how = (
                f"reads the line with its spaces removed, so the process connects as `{run.alias}`"
            )
        else:
            continue
        fix = None
        if "=" in ignored:
            why = f"pAntler reads options only between the `@` and the `~`, and {how}"
            if not has_macro(run.param.value):
                options = run.options_text.strip()
                moved = ", ".join(p.strip() for p in ignored.split(",") if p.strip())
                text = f"{run.binary} @ {options + ', ' if options else ''}{moved} ~ {words[0]}"
                fix = Fix("move the options before the `~`", (Edit(run.param.value_span, text),))
        else:
            why = f"pAntler {how}: one Run line launches one process"
        yield ctx.report(
            run.param.value_span,
            f"`{ignored}` comes after the alias `{words[0]}`: {why}",
            line=run.param.line,
            fix=fix,
        )
