"""The publish/subscribe picture of one mission: ``moos-lint graph MISSION.moos``.

Processes (the Run lines) and the variables they exchange, built from the
mission model (:mod:`moos_lint.mission_model`), with the mission's findings
marked on the processes and variables they concern. Three formats:

- ``json``: the graph as data (processes, variables, edges, findings);
- ``dot``: Graphviz;
- ``html``: one self-contained page (no network): an inline SVG laid out in
  columns, processes on the left and variables on the right, with a little
  JavaScript that highlights the neighbours of what you point at.

By default a variable is drawn when two processes of the mission exchange it
(a publisher and a reader), when a finding concerns it, or when a
configuration value names it; ``all_variables`` draws every variable the
catalogue says an app publishes too.
"""

from __future__ import annotations

import html
import json
import os
from dataclasses import dataclass, field
from typing import Any

from moos_lint.config import Settings
from moos_lint.diagnostics import Diagnostic
from moos_lint.variables import PUBLISH, SUBSCRIBE, bare_name


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
    from moos_lint.engine import LintRun, lint_files
    from moos_lint.mission_model import model_of
    from moos_lint.registry import select_rules

    rules = select_rules(settings.select, settings.extend_select, settings.ignore)
    run = LintRun(settings, rules)
    unit = run.build_unit(path)
    if unit.expansion.read_problem is not None:
        raise GraphError(f"{path}: {unit.expansion.read_problem.message}")
    if unit.moos is None or not unit.moos.is_mission:
        raise GraphError(f"{path}: not a mission (no ANTLER block)")
    run.units.append(unit)
    model = model_of(run, unit.path, unit.moos)
    files = [unit.path, *(p for p, _ in model.behavior_files)]
    result = lint_files(files, settings)
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


_ROW = 24
_PROC_H = 34
_PROC_W = 210
_VAR_W = 230
_COL_GAP = 120
_MAX_ROWS = 36


def to_html(g: Graph) -> str:
    """One self-contained page: inline SVG, inline CSS and JS, no network."""
    esc = html.escape
    n_proc = max(len(g.processes), 1)
    cols = max(1, -(-len(g.variables) // _MAX_ROWS))
    rows = -(-len(g.variables) // cols) if g.variables else 0
    height = max(n_proc * (_PROC_H + 10), rows * _ROW) + 60
    width = 40 + _PROC_W + _COL_GAP + cols * (_VAR_W + 40) + 20
    pos: dict[str, tuple[float, float, float, float]] = {}
    parts: list[str] = []
    # processes
    step = (height - 60) / n_proc
    for i, p in enumerate(g.processes):
        x, y = 20, 40 + i * step + (step - _PROC_H) / 2
        pos[p["id"]] = (x, y, _PROC_W, _PROC_H)
        cls = "proc" + (" bad" if p["findings"] else "") + ("" if p["known"] else " unknown")
        tip = f"{p['name']} ({p['binary']})"
        if p["source"]:
            tip += f"\n{p['source']}"
        for f in p["findings"]:
            tip += f"\n{f['code']} {f['message']}"
        label = p["name"] if p["name"] == p["binary"] else f"{p['name']} ({p['binary']})"
        mark = " \u26a0" if p["findings"] else ""
        parts.append(
            f'<g class="{cls}" id="{esc(p["id"])}" data-id="{esc(p["id"])}">'
            f"<title>{esc(tip)}</title>"
            f'<rect x="{x}" y="{y:.1f}" width="{_PROC_W}" height="{_PROC_H}" rx="6"/>'
            f'<text x="{x + 10}" y="{y + 22:.1f}">{esc(_clip(label, 30))}{mark}</text></g>'
        )
    # variables
    x0 = 20 + _PROC_W + _COL_GAP
    for i, v in enumerate(g.variables):
        c, r = divmod(i, rows) if rows else (0, 0)
        x, y = x0 + c * (_VAR_W + 40), 40 + r * _ROW
        pos[v["id"]] = (x, y, _VAR_W, _ROW - 6)
        cls = "var" + (" bad" if v["findings"] else "")
        tip = v["name"] + "".join(f"\n{f['code']} {f['message']}" for f in v["findings"])
        mark = " \u26a0" if v["findings"] else ""
        parts.append(
            f'<g class="{cls}" id="{esc(v["id"])}" data-id="{esc(v["id"])}">'
            f"<title>{esc(tip)}</title>"
            f'<rect x="{x}" y="{y}" width="{_VAR_W}" height="{_ROW - 6}" rx="9"/>'
            f'<text x="{x + 8}" y="{y + 13}">{esc(_clip(v["name"], 32))}{mark}</text></g>'
        )
    edges: list[str] = []
    for e in g.edges:
        if e["from"] not in pos or e["to"] not in pos:
            continue
        proc = e["from"] if e["kind"] == "publish" else e["to"]
        var = e["to"] if e["kind"] == "publish" else e["from"]
        px, py, pw, ph = pos[proc]
        vx, vy, _vw, vh = pos[var]
        off = 8 if e["kind"] == "publish" else -8
        x1, y1 = px + pw, py + ph / 2 + off / 2
        x2, y2 = vx, vy + vh / 2
        mid = (x1 + x2) / 2
        d = f"M{x1:.1f},{y1:.1f} C{mid:.1f},{y1:.1f} {mid:.1f},{y2:.1f} {x2:.1f},{y2:.1f}"
        edges.append(
            f'<path class="edge {e["kind"]}" d="{d}" data-a="{esc(proc)}" data-b="{esc(var)}">'
            f"<title>{esc(e['kind'])} ({esc(str(e['how']))})</title></path>"
        )
    findings = "".join(
        f'<li class="{esc(f["severity"])}"><b>{esc(f["code"])}</b> '
        f"{esc(os.path.basename(f['path']))}:{f['line']}: {esc(f['message'])}</li>"
        for f in g.findings
    )
    notes = "".join(f"<li>{esc(n)}</li>" for n in g.notes)
    title = esc(os.path.basename(g.mission))
    return _PAGE.format(
        title=title,
        width=int(width),
        height=int(height),
        edges="".join(edges),
        nodes="".join(parts),
        findings=findings or "<li>none</li>",
        notes=notes,
        n_proc=len(g.processes),
        n_var=len(g.variables),
        n_find=len(g.findings),
        x_var=x0,
    )


def _clip(s: str, n: int) -> str:
    return s if len(s) <= n else s[: n - 1] + "\u2026"


_PAGE = """<!DOCTYPE html>
<html lang="en"><head><meta charset="utf-8">
<title>{title}: processes and variables</title>
<style>
body {{ font-family: Helvetica, Arial, sans-serif; margin: 16px; color: #222; }}
h1 {{ font-size: 18px; margin: 0 0 4px 0; }}
p.sum {{ margin: 0 0 8px 0; color: #555; font-size: 13px; }}
.legend span {{ display: inline-block; margin-right: 14px; font-size: 12px; }}
svg {{ border: 1px solid #ddd; background: #fcfcfc; }}
svg text {{ font-size: 12px; pointer-events: none; }}
.proc rect {{ fill: #e8f0fb; stroke: #3b6fb6; stroke-width: 1.2; }}
.proc.unknown rect {{ fill: #f0f0f0; stroke: #999; stroke-dasharray: 4 2; }}
.var rect {{ fill: #fff; stroke: #8aa; }}
.bad rect {{ stroke: #d22; stroke-width: 2.2; }}
.bad text {{ fill: #b00; font-weight: bold; }}
.edge {{ fill: none; stroke-width: 1; opacity: .35; }}
.edge.publish {{ stroke: #2a62c9; }}
.edge.subscribe {{ stroke: #1a9a4a; stroke-dasharray: 5 3; }}
svg.focus .edge {{ opacity: .05; }}
svg.focus g {{ opacity: .25; }}
svg.focus .edge.on {{ opacity: 1; stroke-width: 2; }}
svg.focus g.on {{ opacity: 1; }}
g {{ cursor: pointer; }}
ul.findings li.error {{ color: #b00; }}
ul.findings li.warning {{ color: #a60; }}
ul {{ font-size: 13px; }}
</style></head>
<body>
<h1>{title}</h1>
<p class="sum" id="summary">{n_proc} processes, {n_var} variables, {n_find} findings.
Point at a process or a variable to see its neighbours; click to keep the highlight.</p>
<div class="legend"><span style="color:#2a62c9">&#9473; publishes</span>
<span style="color:#1a9a4a">&#9476; subscribes</span>
<span style="color:#d22">&#9633; has findings</span>
<span style="color:#999">&#9633; not in the catalogue</span></div>
<svg id="graph" xmlns="http://www.w3.org/2000/svg" width="{width}" height="{height}"
 viewBox="0 0 {width} {height}">
<text x="20" y="24" style="font-weight:bold">Processes</text>
<text x="{x_var}" y="24" style="font-weight:bold">Variables</text>
<g class="edges">{edges}</g>{nodes}
</svg>
<h2 style="font-size:15px">Findings</h2><ul class="findings">{findings}</ul>
<ul class="notes">{notes}</ul>
<script>
(function () {{
  var svg = document.getElementById('graph');
  var pinned = null;
  function show(id) {{
    var on = {{}}; on[id] = true;
    svg.querySelectorAll('.edge').forEach(function (e) {{
      var hit = e.dataset.a === id || e.dataset.b === id;
      e.classList.toggle('on', hit);
      if (hit) {{ on[e.dataset.a] = true; on[e.dataset.b] = true; }}
    }});
    svg.querySelectorAll('g[data-id]').forEach(function (g) {{
      g.classList.toggle('on', !!on[g.dataset.id]);
    }});
    svg.classList.add('focus');
  }}
  function clear() {{ if (!pinned) svg.classList.remove('focus'); }}
  svg.querySelectorAll('g[data-id]').forEach(function (g) {{
    g.addEventListener('mouseenter', function () {{ if (!pinned) show(g.dataset.id); }});
    g.addEventListener('mouseleave', clear);
    g.addEventListener('click', function (ev) {{
      ev.stopPropagation();
      pinned = pinned === g.dataset.id ? null : g.dataset.id;
      if (pinned) show(pinned); else svg.classList.remove('focus');
    }});
  }});
  svg.addEventListener('click', function () {{ pinned = null; svg.classList.remove('focus'); }});
  document.body.setAttribute('data-rendered', String(svg.querySelectorAll('g[data-id]').length));
}})();
</script>
</body></html>
"""


def render(g: Graph, fmt: str) -> str:
    if fmt == "json":
        return to_json(g)
    if fmt == "dot":
        return to_dot(g)
    return to_html(g)


__all__ = ["Graph", "GraphError", "build_graph", "render", "to_dot", "to_html", "to_json"]
