"""Small helpers shared by rule modules."""

from __future__ import annotations

import re
from collections.abc import Iterator

from moos_lint.files.diagnostics import Diagnostic
from moos_lint.frontends.nsplug import derived
from moos_lint.frontends.parsers.bhv import shaped_like_behaviors


def problem_findings(ctx, kind: str) -> Iterator[Diagnostic]:
    """Report the preprocessor's problems of one kind; none in a `.bhv` file that holds
    nothing shaped like a behavior file's line (nsplug's own test inputs and notes on
    its directives, which no helm loads)."""
    problems = [prob for prob in ctx.expansion.problems if prob.kind == kind]
    if not problems:
        return
    if ctx.bhv is not None and not derived(
        ctx.expansion, "written-as-behaviors", lambda: _written_as_behaviors(ctx)
    ):
        return
    fragment = ctx.unit.path in ctx.run.included_elsewhere
    for prob in problems:
        if fragment and kind == "include-not-found":
            continue  # judged where nsplug really runs: in the files that include it
        yield ctx.report(prob.span, prob.message, chain=prob.chain)


def _written_as_behaviors(ctx) -> bool:
    """Whether the `.bhv` file, as written (before nsplug, which may stop early), has a
    line shaped like a behavior file's, or an `#include` (of the behaviors it gathers)."""
    source = ctx.expansion.sources.get(ctx.unit.path)
    if source is None:
        return True
    lines = source.text.splitlines()
    return shaped_like_behaviors(lines) or any(_INCLUDE.match(line) for line in lines)


#: an nsplug include line
_INCLUDE = re.compile(r"\s*#include\b")
