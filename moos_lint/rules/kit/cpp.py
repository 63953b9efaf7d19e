"""Glue between the C++ checks and moos-lint's rules."""

from __future__ import annotations

from collections.abc import Callable, Iterator
from typing import Any

from moos_lint.files.diagnostics import Diagnostic


def cpp_findings(ctx: Any, check: Callable[..., Any], **kw: Any) -> Iterator[Diagnostic]:
    """Run a check of :mod:`moos_lint.semantics.cpp_checks` on the unit's app model."""
    app = ctx.unit.cpp
    if app is None:
        return
    for span, message, *fix in check(app, **kw):
        yield ctx.report(span, message, fix=fix[0] if fix else None)
