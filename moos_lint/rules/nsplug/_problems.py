"""Small helpers shared by rule modules."""

from __future__ import annotations

from collections.abc import Iterator

from moos_lint.files.diagnostics import Diagnostic


def problem_findings(ctx, kind: str) -> Iterator[Diagnostic]:
    """Report the preprocessor's problems of one kind."""
    fragment = ctx.unit.path in ctx.run.included_elsewhere
    for prob in ctx.expansion.problems:
        if prob.kind == kind:
            if fragment and kind == "include-not-found":
                continue  # judged where nsplug really runs: in the files that include it
            yield ctx.report(prob.span, prob.message, chain=prob.chain)
