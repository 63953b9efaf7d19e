"""Which apps read their ProcessConfig block as protobuf text, and what that text may hold.

goby's MOOS apps (pAcommsHandler, iFrontSeat, ...) parse their block with
protobuf's text format (``key: value``, nested ``name { ... }``, ``#``
comments), not MOOS's ``key = value`` lines. The ``.moos`` reader must know
which apps those are to read a file as the apps do, so this fact sits at the
front end, below the catalogue, which re-exports it. The data,
``goby.json`` beside this module, is generated from goby's ``.proto`` files
by :mod:`moos_lint.semantics.catalogue.goby`, with the goby commit and each
message's file as provenance. goby 2 and goby 3 ship the same apps with different
schemas (goby 3's ``driver_cfg`` holds the ``driver_type`` that goby 2 reads at the
top of the block), so an app has one configuration message per release: a project
may build either, and a field is unknown only when no release declares it.
"""

from __future__ import annotations

import json
import os
from dataclasses import dataclass, field, replace
from functools import lru_cache

GOBY = os.path.join(os.path.dirname(__file__), "goby.json")


@dataclass(frozen=True)
class TextFormatApp:
    """An app that reads its ProcessConfig block with protobuf's text format."""

    name: str
    message: str  # the full name of its configuration message
    provenance: str
    #: the same app in the other goby releases (each with its own message), newest last
    releases: tuple[TextFormatApp, ...] = ()

    @property
    def all_releases(self) -> tuple[TextFormatApp, ...]:
        """This release's app, then the others'."""
        return (self, *self.releases)


@dataclass(frozen=True)
class TextFormatSchema:
    """Protobuf messages and enums: ``messages[name]`` maps each field to its type."""

    messages: dict[str, dict[str, str]]
    extensions: dict[str, dict[str, str]]
    enums: dict[str, tuple[str, ...]]
    sources: dict[str, str]
    #: top-of-file keys the apps read into their configuration -> where it is declared
    moos_globals: dict[str, str] = field(default_factory=dict)


@lru_cache(maxsize=1)
def _goby() -> tuple[dict[str, TextFormatApp], TextFormatSchema]:
    try:
        with open(GOBY, encoding="utf-8") as fh:
            data = json.load(fh)
    except (OSError, ValueError):
        return {}, TextFormatSchema({}, {}, {}, {})
    labels = [_label(source) for source in data.get("sources", [])]
    apps = {}
    for name, versions in data.get("apps", {}).items():
        each = []
        for d in versions:
            label = labels[d["from"]] if d.get("from", 0) < len(labels) else "goby"
            each.append(TextFormatApp(name, d["message"], f"{label} {d.get('source', '')}".strip()))
        if each:
            apps[name.lower()] = replace(each[0], releases=tuple(each[1:]))
    msgs = data.get("messages", {})
    schema = TextFormatSchema(
        messages={k: dict(v.get("fields", {})) for k, v in msgs.items()},
        extensions={k: dict(v.get("extensions", {})) for k, v in msgs.items()},
        enums={k: tuple(v.get("values", ())) for k, v in data.get("enums", {}).items()},
        sources={k: str(v.get("source", "")) for k, v in msgs.items()},
        moos_globals={str(k): str(v) for k, v in data.get("moos_globals", {}).items()},
    )
    return apps, schema


def _label(source: dict) -> str:
    """``goby3 2603ff12``: the repository's name and the commit the data was read at."""
    repository = str(source.get("repository", "")).rstrip("/").rsplit("/", 1)[-1] or "goby"
    return f"{repository} {str(source.get('commit', ''))[:8]}".strip()


def text_format_app(name: str) -> TextFormatApp | None:
    """The text-format app a block or binary name stands for (``iFrontSeat_bluefin`` too)."""
    apps = _goby()[0]
    low = name.lower().strip()
    if low in apps:
        return apps[low]
    head = low.split("_", 1)[0]
    return apps.get(head) if head != low else None


def text_format_schema() -> TextFormatSchema:
    return _goby()[1]


__all__ = ["GOBY", "TextFormatApp", "TextFormatSchema", "text_format_app", "text_format_schema"]
