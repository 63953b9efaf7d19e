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
from moos_lint.frontends.nsplug import derived, parsed
from moos_lint.frontends.parsers.moos import parse_moos
from moos_lint.frontends.parsers.nodes import Block, MoosFile, has_macro
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


def pshare_routes(moos: MoosFile) -> tuple[set[str], set[str]]:
    """The routes the pShare processes a mission launches listen on, and those they send
    on (worked out once per expansion: every mission of a folder asks about each other
    one). The block of a pShare no Run line starts shares nothing."""
    return derived(moos.expansion, "pshare-routes", lambda: _pshare_routes(moos))


def _pshare_routes(moos: MoosFile) -> tuple[set[str], set[str]]:
    aliases = {r.name.lower(): r.binary for r in moos.runs if r.name}
    ins: set[str] = set()
    outs: set[str] = set()
    for block in moos.blocks:
        if block.lname not in aliases or app_of(block.name, aliases) != "pshare":
            continue
        ins |= input_routes(block)
        for param in block.get("output"):
            for _var, routes in output_shares(param.value):
                outs.update(routes)
    return ins, outs


def share_partners(run: RunView, path: str, moos: MoosFile) -> list[tuple[str, MoosFile, str]]:
    """The missions of ``path``'s folder that pShare ties to it: ``(path, mission, route)``
    for each whose pShare listens on a route this one sends on, or sends on one this one
    listens on. Missions in other folders are not looked at: a route such as
    ``localhost:9200`` names a port of one machine, which unrelated missions of a
    project reuse. nsplug's outputs (``targ_*.moos``) pair only with each other. Worked
    out once per mission and run: each rule that compares missions asks."""
    from moos_lint.semantics.mission_model import missions_beside

    ins, outs = pshare_routes(moos)
    if not ins and not outs:
        return []
    me = os.path.normpath(os.path.abspath(path))
    memo = run.memos.share_partners
    known = memo.get(me)
    if known is not None:
        return known
    generated = os.path.basename(me).startswith("targ_")
    found: list[tuple[str, MoosFile, str]] = []
    for cand in missions_beside(run, os.path.dirname(me), generated):
        if cand == me:
            continue
        exp = run.preprocessor.expand(cand)
        if exp.read_problem is not None:
            continue
        other = parsed(exp, parse_moos)
        if not other.is_mission:
            continue
        their_ins, their_outs = pshare_routes(other)
        common = sorted((outs & their_ins) | (ins & their_outs))
        if common:
            found.append((cand, other, common[0]))
    memo[me] = found
    return found


__all__ = [
    "input_routes",
    "output_shares",
    "pshare_routes",
    "received",
    "share_partners",
    "shared_out",
]
