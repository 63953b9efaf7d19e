"""What pShare sends between communities, by route, across the project's missions.

pShare's ``output`` sends a variable on a route (``route=multicast_8``,
``localhost:9201``); a community whose ``input`` listens on that route receives
it, under the name the share gives it (Share.cpp, ``AddRoute``: ``src_name``,
``dest_name``, ``route``; or ``SRC->[DEST:]ROUTE``). A mission that waits for
a variable may receive it from a mission in another folder of the project (one
launcher community starting every buoy), when a route ties the two.
"""

from __future__ import annotations

import os
import re

from moos_lint.files.source import read_bytes
from moos_lint.files.walk import project_walk
from moos_lint.frontends.nsplug import parsed
from moos_lint.frontends.parsers.moos import parse_moos
from moos_lint.frontends.parsers.nodes import Block, has_macro
from moos_lint.semantics.run_state import RunView
from moos_lint.semantics.variables import app_of

_OUTPUT_LINE = re.compile(rb"(?im)^[ \t]*output[ \t]*=")
_NAME = re.compile(r"[A-Za-z_][\w.\-]*")


def _route(text: str) -> str:
    return "".join(text.split()).lower()


def output_shares(value: str) -> list[tuple[str, tuple[str, ...]]]:
    """The (name it arrives under, routes) of each share of a pShare ``output`` value;
    shares whose names or routes hold a macro or a wildcard are left out."""
    if "->" not in value:
        return _keyed_share(value)
    out: list[tuple[str, tuple[str, ...]]] = []
    for share in value.split(","):
        src, arrow, rest = share.partition("->")
        if arrow and not has_macro(share):
            found = _arrow_share(src.strip().split(":", 1)[0], rest)
            if found is not None:
                out.append(found)
    return out


def _keyed_share(value: str) -> list[tuple[str, tuple[str, ...]]]:
    """``src_name=X, dest_name=Y, route=R1 & R2``."""
    fields: dict[str, str] = {}
    for part in value.split(","):
        key, eq, val = part.partition("=")
        if eq:
            fields[key.strip().lower()] = val.strip()
    name = fields.get("dest_name") or fields.get("src_name", "")
    routes = tuple(_route(r) for r in fields.get("route", "").split("&") if r.strip())
    if _NAME.fullmatch(name) and routes and not has_macro(value):
        return [(name, routes)]
    return []


def _arrow_share(src: str, rest: str) -> tuple[str, tuple[str, ...]] | None:
    """``SRC->[DEST:]ROUTE & ROUTE``: a route is ``HOST:PORT`` or ``multicast_N``."""
    routes: list[str] = []
    dest = src
    for i, piece in enumerate(rest.split("&")):
        fields = piece.strip().split(":")
        named = len(fields) == 3 or (
            len(fields) == 2 and fields[1].strip().lower().startswith("multicast")
        )
        if named:
            if i == 0:
                dest = fields[0].strip()
            fields = fields[1:]
        routes.append(_route(":".join(fields)))
    if _NAME.fullmatch(dest) and routes:
        return dest, tuple(routes)
    return None


def input_routes(block: Block) -> set[str]:
    """The routes a pShare block listens on (``input = route=localhost:9201 & multicast_8``)."""
    found: set[str] = set()
    for param in block.get("input"):
        value = param.value
        if has_macro(value):
            continue
        for piece in value.split(","):
            key, eq, val = piece.partition("=")
            text = val if eq and key.strip().lower() == "route" else piece
            found.update(_route(r) for r in text.split("&") if r.strip() and "=" not in r)
    return found


def shared_out(run: RunView) -> dict[str, frozenset[str]]:
    """Route -> the variables the missions under the project root send on it with pShare
    (by the name they arrive under), once per run. Only a file with an ``output`` line
    is expanded and parsed."""
    memo = run.memos.shared_out
    if memo is not None:
        return memo
    found: dict[str, set[str]] = {}
    for folder, names in project_walk(os.path.abspath(run.settings.root)):
        for name in names:
            if not name.endswith(".moos"):
                continue
            path = os.path.join(folder, name)
            data = read_bytes(path)
            if not isinstance(data, bytes) or not _OUTPUT_LINE.search(data):
                continue
            exp = run.preprocessor.expand(path)
            if exp.read_problem is not None:
                continue
            moos = parsed(exp, parse_moos)
            aliases = {r.name.lower(): r.binary for r in moos.runs if r.name}
            for block in moos.blocks:
                if not block.name or app_of(block.name, aliases) != "pshare":
                    continue
                for param in block.get("output"):
                    for var, routes in output_shares(param.value):
                        for route in routes:
                            found.setdefault(route, set()).add(var)
    run.memos.shared_out = out = {r: frozenset(v) for r, v in found.items()}
    return out


def received(run: RunView, routes: set[str], var: str) -> bool:
    """Whether a mission of the project sends ``var`` with pShare on one of ``routes``."""
    if not routes:
        return False
    sent = shared_out(run)
    return any(var in sent.get(r, ()) for r in routes)


__all__ = ["input_routes", "output_shares", "received", "shared_out"]
