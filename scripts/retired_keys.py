"""Write the configuration keys older MOOS-IvP releases read that today's no longer does.

Usage::

    python scripts/retired_keys.py STOCK OLD_TREE:LABEL:COMMIT [OLD_TREE:LABEL:COMMIT ...]
        [-o moos_lint/semantics/catalogue/retired.json] [--repository URL]

``STOCK`` is the stock catalogue (``stock.json``, generated from today's tree);
each ``OLD_TREE`` is a work tree of https://github.com/moos-ivp/moos-ivp at an
older ``COMMIT``, read with the same generator (:mod:`generate_catalogue`), and
``LABEL`` names it in messages (``2019-08``). A key an app or behavior of the
old tree compares its configuration against, which the same app or behavior of
the stock catalogue no longer reads, is written with the label of the newest
tree that still read it, when a mission or behavior file of an old tree gives
it in that app's block or that behavior (the generator also finds keys a value
is split into, `ip=...,name=...`: a key no old mission sets is left out).
Missions written for an older release keep such keys: unknown-parameter and
unknown-behavior-parameter say so instead of offering a respelling.
"""

from __future__ import annotations

import argparse
import json
import os
import re
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

from generate_catalogue import generate, write_json


def _keys(entry: dict) -> set[str]:
    keys = {p.lower() for p in entry.get("params", [])}
    for lib in entry.get("params_from_libraries", {}).values():
        keys.update(p.lower() for p in lib)
    return keys


_HEADER = re.compile(r"^\s*(ProcessConfig|Behavior)\s*=\s*([\w.-]+)", re.I)
_KEY = re.compile(r"^\s*([A-Za-z_]\w*)\s*=")
_MISSION_SUFFIXES = (".moos", ".bhv", ".plug", ".def")


def used_keys(tree: str) -> dict[str, dict[str, set[str]]]:
    """The keys the mission and behavior files of ``tree`` give each app's block and each
    behavior kind (lower case), read line by line (no macro expansion: evidence only)."""
    out: dict[str, dict[str, set[str]]] = {"apps": {}, "behaviors": {}}
    for folder, _dirs, names in os.walk(tree):
        for name in names:
            if not name.endswith(_MISSION_SUFFIXES):
                continue
            try:
                with open(os.path.join(folder, name), encoding="utf-8", errors="replace") as fh:
                    lines = fh.read().splitlines()
            except OSError:
                continue
            pending = current = None
            for line in lines:
                text = line.split("//", 1)[0].strip()
                header = _HEADER.match(text)
                if header:
                    kind = "apps" if header.group(1).lower() == "processconfig" else "behaviors"
                    pending, current = (kind, header.group(2).lower()), None
                elif text.startswith("{"):
                    current, pending = pending, None
                elif text.startswith("}"):
                    current = None
                elif current is not None:
                    key = _KEY.match(text)
                    if key:
                        out[current[0]].setdefault(current[1], set()).add(key.group(1).lower())
    return out


def retired(
    stock: dict,
    olds: list[tuple[dict, str]],
    used: dict[str, dict[str, set[str]]] | None = None,
) -> dict[str, dict[str, dict[str, str]]]:
    """For apps and behaviors in the stock catalogue: the keys the ``olds`` (catalogues with
    their labels, oldest first) read that the stock one does not, with the newest label;
    with ``used`` (:func:`used_keys` of the old trees), only those their files set."""
    generic = {k.lower() for k in stock.get("behavior_extra_params", {})}
    base_keys = {k for b in stock.get("base_classes", {}).values() for k in _keys(b)}
    out: dict[str, dict[str, dict[str, str]]] = {"apps": {}, "behaviors": {}}
    for old, label in olds:
        for kind in ("apps", "behaviors"):
            now_by_name = {n.lower(): (n, e) for n, e in stock.get(kind, {}).items()}
            for name, entry in old.get(kind, {}).items():
                found = now_by_name.get(name.lower())
                if found is None:
                    continue  # gone altogether: unknown-behavior's business
                now_name, now = found
                known = _keys(now) | base_keys | (generic if kind == "behaviors" else set())
                for key in sorted(_keys(entry) - known):
                    if used is not None and key not in used[kind].get(name.lower(), ()):
                        continue
                    out[kind].setdefault(now_name, {})[key] = label
    return {k: dict(sorted(v.items())) for k, v in out.items()}


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(prog="python scripts/retired_keys.py")
    ap.add_argument("stock", help="stock.json, the catalogue of today's tree")
    ap.add_argument("olds", nargs="+", metavar="OLD_TREE:LABEL:COMMIT", help="oldest first")
    ap.add_argument("-o", "--output", default="-")
    ap.add_argument("--repository", default="https://github.com/moos-ivp/moos-ivp")
    args = ap.parse_args(argv)
    with open(args.stock, encoding="utf-8") as fh:
        stock = json.load(fh)
    olds, releases = [], []
    used: dict[str, dict[str, set[str]]] = {"apps": {}, "behaviors": {}}
    for spec in args.olds:
        tree, label, commit = spec.rsplit(":", 2)
        olds.append((generate(tree, commit, args.repository, strict=False), label))
        releases.append({"label": label, "commit": commit})
        for kind, by_name in used_keys(tree).items():
            for name, keys in by_name.items():
                used[kind].setdefault(name, set()).update(keys)
    data = {"source": {"repository": args.repository, "releases": releases}}
    data.update(retired(stock, olds, used))
    write_json(data, args.output)
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
