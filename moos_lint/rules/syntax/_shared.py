"""Helpers shared by the syntax rules.

- :func:`example_file`: a `.moos` file that is no mission (no ANTLER block, no
  key outside a block) and that no mission of the run includes: an app's
  example configuration, such as `src/iGPS/iGPS.moos`, or a menu of its
  alternative presets. No mission reads it, so the rules about how a mission's
  lines shadow one another leave it alone.
"""

from __future__ import annotations

from typing import Any


def example_file(ctx: Any) -> bool:
    """Whether the unit is an app's example blocks, alone in a file no mission reads."""
    moos = ctx.moos
    return (
        not moos.is_mission and not moos.globals and ctx.unit.path not in ctx.run.included_elsewhere
    )


__all__ = ["example_file"]
