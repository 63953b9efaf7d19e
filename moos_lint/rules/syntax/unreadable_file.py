"""A file that cannot be read, or is not text.

## What it does
Reports a mission, fragment or behavior file that moos-lint could not read:
it does not exist any more, permissions forbid reading it, it is a directory
or a device, or it holds binary data (NUL bytes).

## Why is this bad?
MOOS reads the same file at launch. If the linter cannot read it as text,
neither can pAntler, the apps or the helm: the mission will not start, or
will start without its configuration.

## Example
A file named `alpha.moos` that is really a compiled binary, or a directory
named `survey.moos`.

## How to fix
Check the path, the permissions and the contents; exclude files that are not
mission files with `exclude` in the configuration.

## Options
None.
"""

from moos_lint.files.diagnostics import Severity, Span
from moos_lint.rules.kit.declare import Kind, Scope, rule


@rule(
    code="R001",
    name="unreadable-file",
    severity=Severity.ERROR,
    scope=Scope.FILE,
    kinds=(Kind.MOOS, Kind.BHV),
)
def check(ctx):
    problem = ctx.expansion.read_problem
    if problem is not None:
        yield ctx.report(Span(ctx.path, 1, 1), problem.message)
