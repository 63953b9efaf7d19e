"""A `moos-lint:` suppression comment that suppresses nothing.

## What it does
Reports a rule code or name in a `// moos-lint: ignore[...]`,
`disable[...]` or `file-ignore[...]` comment that matched no finding, and
selectors that name no rule at all.

## Why is this bad?
Stale suppressions hide future problems: the line they once excused has been
fixed or moved, but a new problem of the same kind there would be silenced.
An unknown code in a suppression is usually a typo that suppresses nothing.

## Example
```moos
ProcessConfig = pLogger   // moos-lint: ignore[brace-on-header]
{
}
```

## How to fix
Delete the suppression (or just the codes that suppress nothing).

## Options
None.
"""

from moos_lint.diagnostics import Severity
from moos_lint.registry import Kind, Scope, is_valid_selector, matches, rule


@rule(
    code="L001",
    name="unused-suppression",
    severity=Severity.WARNING,
    scope=Scope.PROJECT,
    kinds=(Kind.MOOS, Kind.BHV),
)
def check(ctx):
    # Project rules run after every other finding was matched against suppressions.
    run = ctx.run
    for path, sups in sorted(run.suppressions.items()):
        in_mission = path in run.mission_files
        for sup in sups:
            for sel in sup.selectors:
                if sel in sup.used:
                    continue
                if not is_valid_selector(sel):
                    msg = f"`{sel}` names no moos-lint rule"
                else:
                    ran = [
                        r
                        for r in run.rules
                        if matches(sel, r)
                        and r.scope is not Scope.PROJECT
                        and (in_mission or r.scope is not Scope.MISSION)
                    ]
                    if not ran:
                        continue  # the rule did not run on this file: we cannot tell
                    msg = f"unused suppression: `{sel}` suppressed nothing here"
                yield ctx.report(sup.span, msg)
