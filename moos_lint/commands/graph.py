"""The publish/subscribe picture of one mission: ``moos-lint graph MISSION.moos``.

Processes (the Run lines) and the variables they exchange, built from the
mission model (:mod:`moos_lint.semantics.mission_model`), with the mission's findings
marked on the processes and variables they concern. Three formats:

- ``json``: the graph as data (processes, variables, edges, findings);
- ``dot``: Graphviz;
- ``html``: one self-contained page (no network), laid out as a layered graph
  by the inlined dagre, with pan, zoom and the neighbours of what you point at
  highlighted (:mod:`moos_lint.commands.graph_html`).

By default a variable is drawn when two processes of the mission exchange it
(a publisher and a reader), when a finding concerns it, or when a
configuration value names it; ``all_variables`` draws every variable the
catalogue says an app publishes too.
"""

from __future__ import annotations

import json
import os
from dataclasses import dataclass, field
from typing import Any

from moos_lint.core.config import Settings
from moos_lint.files.diagnostics import Diagnostic
from moos_lint.semantics.variables import PUBLISH, SUBSCRIBE, bare_name


@dataclass
class Graph:
    mission: str
    processes: list[dict[str, Any]] = field(default_factory=list)
    variables: list[dict[str, Any]] = field(default_factory=list)
    edges: list[dict[str, Any]] = field(default_factory=list)
    findings: list[dict[str, Any]] = field(default_factory=list)
    notes: list[str] = field(default_factory=list)

    def as_dict(self) -> dict[str, Any]:
        return {
            "mission": self.mission,
            "processes": self.processes,
            "variables": self.variables,
            "edges": self.edges,
            "findings": self.findings,
            "notes": self.notes,
        }


class GraphError(Exception):
    """The file cannot be drawn (unreadable, or not a mission)."""


def build_graph(path: str, settings: Settings, *, all_variables: bool = False) -> Graph:
    from moos_lint.core.engine import LintRun, _build_cpp_units, lint_files
    from moos_lint.core.registry import select_rules
    from moos_lint.semantics.mission_model import model_of

    rules = select_rules(settings.select, settings.extend_select, settings.ignore)
    run = LintRun(settings, rules)
    unit = run.build_unit(path)
    if unit.expansion.read_problem is not None:
        raise GraphError(f"{path}: {unit.expansion.read_problem.message}")
    if unit.moos is None or not unit.moos.is_mission:
        raise GraphError(f"{path}: not a mission (no ANTLER block)")
    run.units.append(unit)
    # the repository's own C++ apps, as `moos-lint check` over the project reads them:
    # one catalogue, so one model and the same findings
    cpp = _project_cpp(unit.path, settings)
    if cpp:
        units, _errors = _build_cpp_units(run, cpp)
        run.units.extend(units)
    model = model_of(run, unit.path, unit.moos)
    files = [unit.path, *(p for p, _ in model.behavior_files)]
    result = lint_files([*files, *cpp], settings)
    diags = [d for d in result.diagnostics if _concerns(d, files, model)]

    g = Graph(mission=unit.path)
    names = [p.name for p in model.processes]
    # ---- edges
    pub: dict[str, dict[str, str]] = {}  # var -> process -> how
    sub: dict[str, dict[str, str]] = {}
    for var, pubs in model.publishers.items():
        if "*" in var:
            continue
        for p in pubs:
            if p.process:
                pub.setdefault(var, {}).setdefault(p.process, p.how)
            else:
                pub.setdefault(var, {}).setdefault("(outside)", p.how)
    named: set[str] = set()
    for ref in model.refs:
        proc = model.ref_process.get(id(ref))
        if proc is None:
            continue
        for read in ref.read_names if ref.role == SUBSCRIBE else (ref.name,):
            name = bare_name(read)
            if not name or "*" in name:
                continue
            named.add(name)
            if ref.role == SUBSCRIBE:
                sub.setdefault(name, {}).setdefault(proc, ref.param)
            elif ref.role == PUBLISH:
                pub.setdefault(name, {}).setdefault(proc, "config")
    for proc_ in model.processes:
        if proc_.app is None:
            continue
        for var in proc_.app.subscribes:
            sub.setdefault(var, {}).setdefault(proc_.name, "app")
    for ref in model.waits:  # waits satisfied by a dynamic name (prefix/suffix)
        name = bare_name(ref.name)
        if name and name not in pub:
            for pb in model.published_by(name):
                if pb.process:
                    pub.setdefault(name, {}).setdefault(pb.process, pb.how)
    flagged = _flagged_vars(diags)
    keep = set()
    for var in set(pub) | set(sub):
        readers = set(sub.get(var, {}))
        writers = set(pub.get(var, {}))
        exchanged = bool(readers and writers and (readers | writers) - {"(outside)"})
        if all_variables or exchanged or var in flagged or var in named:
            keep.add(var)
    # ---- nodes
    proc_findings = _process_findings(diags, model)
    for proc_ in model.processes:
        g.processes.append(
            {
                "id": "p:" + proc_.name,
                "name": proc_.name,
                "binary": proc_.binary,
                "known": proc_.app is not None or proc_.binary.lower() in ("moosdb", "pantler"),
                "source": proc_.app.provenance if proc_.app else "",
                "findings": proc_findings.get(proc_.name, []),
            }
        )
    if any(("(outside)" in pub.get(v, {})) for v in keep):
        g.processes.append(
            {
                "id": "p:(outside)",
                "name": "(outside)",
                "binary": "other communities, uPokeDB",
                "known": True,
                "source": "",
                "findings": [],
            }
        )
        names.append("(outside)")
    for var in sorted(keep, key=lambda v: (_first_index(v, pub, sub, names), v)):
        g.variables.append(
            {
                "id": "v:" + var,
                "name": var,
                "findings": [_finding(d) for d in diags if _variable(d) == var],
            }
        )
        for proc, how in sorted(pub.get(var, {}).items()):
            g.edges.append({"from": "p:" + proc, "to": "v:" + var, "kind": "publish", "how": how})
        for proc, how in sorted(sub.get(var, {}).items()):
            g.edges.append({"from": "v:" + var, "to": "p:" + proc, "kind": "subscribe", "how": how})
    g.findings = [_finding(d) for d in diags]
    if model.unknown_apps:
        g.notes.append(
            "not in the catalogue (their variables are not drawn): "
            + ", ".join(p.name for p in model.unknown_apps)
        )
    for b in model.unresolved_behaviors:
        g.notes.append(f"behavior file not found: {b}")
    for path_, _bf in model.behavior_files:
        g.notes.append(f"behaviors from {os.path.relpath(path_, os.path.dirname(unit.path))}")
    return g


def _project_cpp(path: str, settings: Settings) -> list[str]:
    """The C++ files of the project holding the mission (see :mod:`moos_lint.files.launch`)."""
    from pathlib import Path

    from moos_lint.files.discovery import discover, kind_of
    from moos_lint.files.launch import project_folder

    root = project_folder(settings, path)
    found = discover([Path(root)], settings.exclude, settings.root or root).files
    return sorted(f for f in found if kind_of(f) == "cpp")


def _concerns(d: Diagnostic, files: list[str], model) -> bool:
    norm = {os.path.normpath(f) for f in files}
    return os.path.normpath(d.span.path) in norm or any(
        os.path.normpath(s.path) in norm for s in d.chain
    )


def _variable(d: Diagnostic) -> str | None:
    """The variable a finding is about, as the rule that made it says."""
    return d.subject.variable if d.subject is not None else None


def _flagged_vars(diags: list[Diagnostic]) -> set[str]:
    """Variables that the publish/subscribe rules report."""
    out: set[str] = set()
    for d in diags:
        var = _variable(d)
        if d.code in ("M005", "M006") and var:
            out.add(var)
    return out


def _finding(d: Diagnostic) -> dict[str, Any]:
    return {
        "code": d.code,
        "name": d.name,
        "severity": d.severity.value if hasattr(d.severity, "value") else str(d.severity),
        "path": d.span.path,
        "line": d.span.line,
        "message": d.message,
    }


def _process_findings(diags: list[Diagnostic], model) -> dict[str, list[dict[str, Any]]]:
    """Findings located in a process's block or on its Run line."""
    spans: list[tuple[str, str, int, int]] = []
    for p in model.processes:
        line = p.run.param.line
        spans.append((p.name, os.path.normpath(line.path), line.lineno, line.lineno))
        b = p.block
        if b is not None and b.header is not None and b.params:
            lines = [b.header, *(q.line for q in b.params)]
            paths = {os.path.normpath(x.path) for x in lines}
            if len(paths) == 1:
                lo = min(x.lineno for x in lines)
                hi = max(x.lineno for x in lines)
                spans.append((p.name, paths.pop(), lo, hi))
    out: dict[str, list[dict[str, Any]]] = {}
    for d in diags:
        path = os.path.normpath(d.span.path)
        for name, sp, lo, hi in spans:
            if sp == path and lo <= d.span.line <= hi:
                out.setdefault(name, []).append(_finding(d))
                break
    return out


def _first_index(var: str, pub, sub, names: list[str]) -> int:
    procs = list(pub.get(var, {})) or list(sub.get(var, {}))
    idx = [names.index(p) for p in procs if p in names]
    return min(idx) if idx else len(names)


# ------------------------------------------------------------------ formats
def to_json(g: Graph) -> str:
    return json.dumps(g.as_dict(), indent=2) + "\n"


def _dot_id(s: str) -> str:
    return '"' + s.replace("\\", "\\\\").replace('"', '\\"') + '"'


def to_dot(g: Graph) -> str:
    out = [
        "digraph mission {",
        "  rankdir=LR;",
        f"  label={_dot_id(os.path.basename(g.mission))};",
        '  node [fontname="Helvetica", fontsize=10];',
    ]
    for p in g.processes:
        color = "red" if p["findings"] else ("black" if p["known"] else "gray50")
        label = p["name"] if p["name"] == p["binary"] else f"{p['name']}\\n({p['binary']})"
        out.append(f"  {_dot_id(p['id'])} [shape=box, color={color}, label={_dot_id(label)}];")
    for v in g.variables:
        color = "red" if v["findings"] else "steelblue"
        out.append(
            f"  {_dot_id(v['id'])} [shape=ellipse, color={color}, label={_dot_id(v['name'])}];"
        )
    for e in g.edges:
        style = "solid" if e["kind"] == "publish" else "dashed"
        out.append(f"  {_dot_id(e['from'])} -> {_dot_id(e['to'])} [style={style}];")
    out.append("}")
    return "\n".join(out) + "\n"


def to_html(g: Graph) -> str:
    """One self-contained page, laid out in the browser (:mod:`moos_lint.commands.graph_html`)."""
    from moos_lint.commands.graph_html import to_html as page

    return page(g)


def render(g: Graph, fmt: str) -> str:
    if fmt == "json":
        return to_json(g)
    if fmt == "dot":
        return to_dot(g)
    return to_html(g)


__all__ = ["Graph", "GraphError", "build_graph", "render", "to_dot", "to_html", "to_json"]
