"""Generate the catalogue of goby's MOOS apps from goby's ``.proto`` sources.

Usage::

    python -m moos_lint.semantics.catalogue.goby GOBY_SRC [GOBY3_SRC] [-o
    moos_lint/frontends/goby.json]
        [--commit SHA ...] [--repository URL ...]

Each ``SRC`` is a work tree of a goby release: https://github.com/GobySoft/goby
(goby 2) and https://github.com/GobySoft/goby3, whose apps keep their names but
not their schemas (goby 3 moved ``driver_type`` into ``driver_cfg`` and its
messages into ``goby.apps.moos.protobuf``). ``--commit`` and ``--repository``
are given once per tree, in order (the commit is read from the tree's ``.git``
when it has one). An app's block is judged against every release's message, and a
field is unknown only when none declares it. goby's MOOS
apps (``GobyMOOSApp``) read their ``ProcessConfig`` block with protobuf's text
format into one configuration message (``pAcommsHandlerConfig``,
``iFrontSeatConfig``, ...). This step reads every ``.proto`` file of the tree
(messages, nested messages, enums, ``extend`` blocks) and writes, for each app,
its root message and every message and enum reachable from it, each with the
file it comes from, and the top-of-file keys the apps also read (fields marked
``(goby.field).moos_global = "log_path"``). :mod:`moos_lint.frontends.parsers.protobuf_text` checks
a
block against it.
"""

from __future__ import annotations

import argparse
import json
import os
import re
import sys

from moos_lint.frontends.text_format_apps import GOBY

#: app name -> (root message, the app's source folder), as the app's ``GobyMOOSApp``
#: subclass is built with ``GobyMOOSApp(&cfg_)`` of that message type.
APPS = {
    "pAcommsHandler": ("pAcommsHandlerConfig", "src/apps/moos/pAcommsHandler"),
    "iFrontSeat": ("iFrontSeatConfig", "src/apps/moos/iFrontSeat"),
    "pTranslator": ("pTranslatorConfig", "src/apps/moos/pTranslator"),
    "pGobyMOOSAppTemplate": ("GobyMOOSAppTemplateConfig", "src/apps/moos/pGobyMOOSAppTemplate"),
}

SCALARS = {
    "double",
    "float",
    "int32",
    "int64",
    "uint32",
    "uint64",
    "sint32",
    "sint64",
    "fixed32",
    "fixed64",
    "sfixed32",
    "sfixed64",
    "bool",
    "string",
    "bytes",
}

_TOKEN = re.compile(
    r'\s+|//[^\n]*|/\*.*?\*/|"(?:\\.|[^"\\])*"|\'(?:\\.|[^\'\\])*\'|[A-Za-z_.][\w.]*|-?\d[\w.+-]*|.',
    re.DOTALL,
)


_TEMPLATE = re.compile(r"@\w+@")  # CMake template lines (`@PROTOBUF_ALLOW_ALIAS@`)


def _tokens(text: str) -> list[str]:
    out = []
    for m in _TOKEN.finditer(_TEMPLATE.sub(" ", text)):
        t = m.group()
        if t.isspace() or t.startswith("//") or t.startswith("/*"):
            continue
        out.append(t)
    return out


class _ProtoFile:
    """The declarations of one ``.proto`` file."""

    def __init__(self, path: str, text: str) -> None:
        self.path = path
        self.package = ""
        self.messages: dict[str, dict] = {}  # full name -> {"fields": {...}}
        self.enums: dict[str, list[str]] = {}
        #: (scope, extended type name, field name, field type)
        self.extensions: list[tuple[str, str, str, str]] = []
        #: (scope, message full name, field name, type name)
        self.refs: list[tuple[str, str, str, str]] = []
        #: (field full name, the MOOS global key it is also read from)
        self.moos_globals: list[tuple[str, str]] = []
        self._toks = _tokens(text)
        self._i = 0
        self._parse()

    # ------------------------------------------------------------- tokens
    def _peek(self) -> str:
        return self._toks[self._i] if self._i < len(self._toks) else ""

    def _next(self) -> str:
        t = self._peek()
        self._i += 1
        return t

    def _skip_statement(self) -> None:
        depth = 0
        while self._i < len(self._toks):
            t = self._next()
            if t in "{[(":
                depth += 1
            elif t in "}])":
                depth -= 1
                if depth <= 0 and t == "}":
                    return
            elif t == ";" and depth == 0:
                return

    # ------------------------------------------------------------ grammar
    def _parse(self) -> None:
        while self._i < len(self._toks):
            t = self._next()
            if t == "package":
                self.package = self._next()
                self._skip_statement()
            elif t == "message":
                self._message(self.package)
            elif t == "enum":
                self._enum(self.package)
            elif t == "extend":
                self._extend(self.package)
            elif t in ("syntax", "import", "option"):
                self._skip_statement()

    def _full(self, scope: str, name: str) -> str:
        return f"{scope}.{name}" if scope else name

    def _message(self, scope: str) -> None:
        name = self._next()
        full = self._full(scope, name)
        fields: dict[str, str] = {}
        self.messages[full] = {"fields": fields}
        if self._next() != "{":
            return
        while self._i < len(self._toks):
            t = self._next()
            if t == "}":
                return
            if t == "message":
                self._message(full)
            elif t == "enum":
                self._enum(full)
            elif t == "extend":
                self._extend(full)
            elif t == "oneof":
                self._next()
                self._next()  # "{"
                while self._peek() not in ("}", ""):
                    self._field(full, self._next(), fields)
                self._next()
            elif t in ("optional", "required", "repeated"):
                self._field(full, self._next(), fields)
            elif t in ("option", "extensions", "reserved", ";"):
                if t != ";":
                    self._skip_statement()
            elif t == "map":
                self._skip_statement()
            else:  # proto3 style: a field without a label
                self._field(full, t, fields)

    def _field(self, scope: str, ftype: str, fields: dict[str, str]) -> None:
        fname = self._next()
        if fname == "group":
            self._skip_statement()
            return
        start = self._i
        self._skip_statement()
        # `[(goby.field).moos_global = "log_path"]`: the app also reads this top-of-file key
        opts = self._toks[start : self._i]
        for k, tok in enumerate(opts[:-2]):
            if tok.endswith("moos_global") and opts[k + 1] == "=" and opts[k + 2][:1] in "\"'":
                self.moos_globals.append((self._full(scope, fname), opts[k + 2][1:-1]))
        fields[fname] = ftype
        self.refs.append((scope, scope, fname, ftype))

    def _enum(self, scope: str) -> None:
        full = self._full(scope, self._next())
        values: list[str] = []
        self.enums[full] = values
        if self._next() != "{":
            return
        while self._i < len(self._toks):
            t = self._next()
            if t == "}":
                return
            if t in ("option", "reserved"):
                self._skip_statement()
            elif re.match(r"^[A-Za-z_]\w*$", t):
                values.append(t)
                self._skip_statement()

    def _extend(self, scope: str) -> None:
        extended = self._next()
        if self._next() != "{":
            return
        while self._i < len(self._toks):
            t = self._next()
            if t == "}":
                return
            if t in ("optional", "required", "repeated"):
                ftype = self._next()
                fname = self._next()
                self._skip_statement()
                self.extensions.append((scope, extended, self._full(scope, fname), ftype))


def _resolve(name: str, scope: str, known: set[str]) -> str | None:
    """Protobuf's scoping: look the name up from the innermost scope outwards."""
    if name.startswith("."):
        return name[1:] if name[1:] in known else None
    parts = scope.split(".") if scope else []
    while True:
        cand = ".".join([*parts, name])
        if cand in known:
            return cand
        if not parts:
            return None
        parts.pop()


def _git_commit(src: str) -> str:
    head = os.path.join(src, ".git", "HEAD")
    try:
        with open(head, encoding="utf-8") as fh:
            ref = fh.read().strip()
        if ref.startswith("ref: "):
            with open(os.path.join(src, ".git", ref[5:]), encoding="utf-8") as fh:
                return fh.read().strip()
        return ref
    except OSError:
        return ""


def generate(src: str, commit: str = "", repository: str = "") -> dict:
    files: list[_ProtoFile] = []
    for top, dirs, names in os.walk(src):
        dirs[:] = sorted(d for d in dirs if not d.startswith("."))
        for n in sorted(names):
            if n.endswith(".proto"):
                path = os.path.join(top, n)
                with open(path, encoding="utf-8", errors="replace") as fh:
                    files.append(_ProtoFile(os.path.relpath(path, src), fh.read()))
    messages: dict[str, dict] = {}
    enums: dict[str, dict] = {}
    where: dict[str, str] = {}
    for f in files:
        for full in f.messages:
            messages.setdefault(full, {"fields": {}, "extensions": {}, "source": f.path})
            where[full] = f.path
        for full, values in f.enums.items():
            enums.setdefault(full, {"values": values, "source": f.path})
    types = set(messages) | set(enums)
    for f in files:
        for scope, owner, fname, ftype in f.refs:
            if ftype in SCALARS:
                kind = ftype
            else:
                kind = _resolve(ftype, scope, types) or "?"
            messages[owner]["fields"][fname] = kind
        for scope, extended, fname, ftype in f.extensions:
            target = _resolve(extended, scope, set(messages))
            if target is None:
                continue
            kind = ftype if ftype in SCALARS else (_resolve(ftype, scope, types) or "?")
            messages[target]["extensions"][fname] = kind
    apps = {}
    keep: set[str] = set()
    for app, (root_name, folder) in APPS.items():
        root = _resolve(root_name, "", set(messages)) or next(
            (m for m in messages if m.endswith("." + root_name)), None
        )
        if root is None:
            continue
        apps[app] = {"message": root, "source": folder, "proto": where[root]}
        todo = [root]
        while todo:
            m = todo.pop()
            if m in keep:
                continue
            keep.add(m)
            d = messages.get(m)
            if d is None:
                continue
            for kind in (*d["fields"].values(), *d["extensions"].values()):
                if kind in messages and kind not in keep:
                    todo.append(kind)
                elif kind in enums:
                    keep.add(kind)
    moos_globals: dict[str, str] = {}
    for f in files:
        for field_name, key in f.moos_globals:
            owner = field_name.rsplit(".", 1)[0]
            if owner in keep:
                moos_globals.setdefault(key, f"{f.path} ({field_name})")
    return {
        #: top-of-file keys goby's apps read into their configuration (`moos_global`)
        "moos_globals": dict(sorted(moos_globals.items())),
        "source": {
            "repository": repository or "https://github.com/GobySoft/goby",
            "commit": commit or _git_commit(src),
            "generator": "python -m moos_lint.semantics.catalogue.goby",
        },
        "apps": apps,
        "messages": {k: messages[k] for k in sorted(keep) if k in messages},
        "enums": {k: enums[k] for k in sorted(keep) if k in enums},
    }


def merge(releases: list[dict]) -> dict:
    """One catalogue of several releases' :func:`generate` output, the first first.

    ``sources`` lists the releases; each app lists its message in each release that
    has it (``from``: the release's index). A message of one full name in several
    releases has the fields and extensions of all of them (the first release's type
    where they differ), and an enum every value of all of them."""
    apps: dict[str, list[dict]] = {}
    messages: dict[str, dict] = {}
    enums: dict[str, dict] = {}
    moos_globals: dict[str, str] = {}
    for i, data in enumerate(releases):
        for name, app in data["apps"].items():
            apps.setdefault(name, []).append({**app, "from": i})
        for name, msg in data["messages"].items():
            kept = messages.setdefault(name, {"fields": {}, "extensions": {}, **msg, "from": i})
            for part in ("fields", "extensions"):
                for field_name, kind in msg[part].items():
                    kept[part].setdefault(field_name, kind)
        for name, enum in data["enums"].items():
            kept_enum = enums.setdefault(name, {**enum, "values": list(enum["values"])})
            kept_enum["values"] += [v for v in enum["values"] if v not in kept_enum["values"]]
        for key, where in data["moos_globals"].items():
            moos_globals.setdefault(key, where)
    return {
        "moos_globals": dict(sorted(moos_globals.items())),
        "sources": [data["source"] for data in releases],
        "apps": apps,
        "messages": dict(sorted(messages.items())),
        "enums": dict(sorted(enums.items())),
    }


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(prog="python -m moos_lint.semantics.catalogue.goby")
    ap.add_argument("src", nargs="+", help="work trees of GobySoft/goby, then GobySoft/goby3")
    ap.add_argument("-o", "--output", default=GOBY)
    ap.add_argument("--commit", action="append", default=[])
    ap.add_argument("--repository", action="append", default=[])
    args = ap.parse_args(argv)
    releases = []
    for i, src in enumerate(args.src):
        commit = args.commit[i] if i < len(args.commit) else ""
        repository = args.repository[i] if i < len(args.repository) else ""
        releases.append(generate(src, commit, repository))
    data = merge(releases)
    with open(args.output, "w", encoding="utf-8") as fh:
        json.dump(data, fh, indent=1, sort_keys=True)
        fh.write("\n")
    print(f"{len(data['apps'])} apps, {len(data['messages'])} messages -> {args.output}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
