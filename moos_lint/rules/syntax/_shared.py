"""Helpers shared by the syntax rules.

- :func:`example_file`: a `.moos` file that is no mission (no ANTLER block, no
  key outside a block) and that no mission of the run includes: an app's
  example configuration, such as `src/iGPS/iGPS.moos`, or a menu of its
  alternative presets. No mission reads it, so the rules about how a mission's
  lines shadow one another leave it alone.
- :func:`source_page`: such a file named after the folder it sits in
  (`src/uFldHazardSensor/uFldHazardSensor.moos`): the page kept beside an app's
  or a behavior's source, whatever its lines look like.
"""

from __future__ import annotations

import os
from typing import Any


def example_file(ctx: Any) -> bool:
    """Whether the unit is an app's example blocks, alone in a file no mission reads."""
    moos = ctx.moos
    return (
        not moos.is_mission and not moos.globals and ctx.unit.path not in ctx.run.included_elsewhere
    )


def source_page(ctx: Any) -> bool:
    """Whether the unit is an example file named after its folder (an app's source)."""
    path = ctx.unit.path
    stem = os.path.splitext(os.path.basename(path))[0]
    folder = os.path.basename(os.path.dirname(os.path.abspath(path)))
    return stem.lower() == folder.lower() and example_file(ctx)


__all__ = ["example_file", "source_page"]
