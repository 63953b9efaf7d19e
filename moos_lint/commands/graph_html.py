"""The HTML page of ``moos-lint graph``: one self-contained file that works offline.

The page carries the graph as JSON and lays it out in the browser with dagre
(a layered-graph layout, the Sugiyama method Graphviz's ``dot`` uses: ranks,
crossing reduction, coordinates, routed edges), inlined from the vendored
``moos_lint/commands/vendor/dagre.min.js`` (MIT). Boxes are sized to their labels as the
browser measures them, so no label is cut off.

Processes are boxes and variables are rounded tags, in layers from left to
right, each edge going from a publisher to the variable and from the variable
to its readers. Pointing at a box highlights its neighbours (a click keeps the
highlight); the wheel zooms, a drag pans, and ``Fit`` shows the whole mission
again.
"""

from __future__ import annotations

import functools
import html
import json
import os
from importlib import resources
from typing import Any

_DAGRE = "dagre.min.js"


@functools.lru_cache(maxsize=1)
def dagre_source() -> str:
    """The vendored dagre, as the page inlines it."""
    text = resources.files("moos_lint.commands.vendor").joinpath(_DAGRE).read_text(encoding="utf-8")
    return text.replace("</script", "<\\/script")


def _nodes(g: Any) -> list[dict[str, Any]]:
    out = []
    for p in g.processes:
        cls = "proc" + (" bad" if p["findings"] else "") + ("" if p["known"] else " unknown")
        tip = f"{p['name']} ({p['binary']})"
        if p["source"]:
            tip += f"\n{p['source']}"
        tip += "".join(f"\n{f['code']} {f['message']}" for f in p["findings"])
        label = p["name"] if p["name"] == p["binary"] else f"{p['name']} ({p['binary']})"
        mark = " \u26a0" if p["findings"] else ""
        out.append({"id": p["id"], "cls": cls, "label": label + mark, "tip": tip})
    for v in g.variables:
        cls = "var" + (" bad" if v["findings"] else "")
        tip = v["name"] + "".join(f"\n{f['code']} {f['message']}" for f in v["findings"])
        mark = " \u26a0" if v["findings"] else ""
        out.append({"id": v["id"], "cls": cls, "label": v["name"] + mark, "tip": tip})
    return out


def _edges(g: Any, ids: set[str]) -> list[dict[str, Any]]:
    out = []
    for e in g.edges:
        if e["from"] not in ids or e["to"] not in ids:
            continue
        proc = e["from"] if e["kind"] == "publish" else e["to"]
        var = e["to"] if e["kind"] == "publish" else e["from"]
        out.append(
            {
                "from": e["from"],
                "to": e["to"],
                "kind": e["kind"],
                "proc": proc,
                "var": var,
                "tip": f"{e['kind']} ({e['how']})",
            }
        )
    return out


def _json_for_script(data: Any) -> str:
    """JSON that cannot end the ``<script>`` element it sits in."""
    text = json.dumps(data, ensure_ascii=False, separators=(",", ":"))
    return text.replace("</", "<\\/").replace("<!--", "<\\!--")


def to_html(g: Any) -> str:
    esc = html.escape
    nodes = _nodes(g)
    data = {"nodes": nodes, "edges": _edges(g, {n["id"] for n in nodes})}
    findings = "".join(
        f'<li class="{esc(f["severity"])}"><b>{esc(f["code"])}</b> '
        f"{esc(os.path.basename(f['path']))}:{f['line']}: {esc(f['message'])}</li>"
        for f in g.findings
    )
    notes = "".join(f"<li>{esc(n)}</li>" for n in g.notes)
    page = _PAGE.format(
        title=esc(os.path.basename(g.mission)),
        findings=findings or "<li>none</li>",
        notes=notes,
        n_proc=len(g.processes),
        n_var=len(g.variables),
        n_find=len(g.findings),
    )
    return (
        page.replace("@DATA@", _json_for_script(data))
        .replace("@DAGRE@", dagre_source())
        .replace("@SCRIPT@", _SCRIPT)
    )


_PAGE = """<!DOCTYPE html>
<html lang="en"><head><meta charset="utf-8">
<meta name="viewport" content="width=device-width, initial-scale=1">
<title>{title}: processes and variables</title>
<style>
body {{ font-family: Helvetica, Arial, sans-serif; margin: 16px; color: #222; }}
h1 {{ font-size: 18px; margin: 0 0 4px 0; }}
p.sum {{ margin: 0 0 8px 0; color: #555; font-size: 13px; }}
.bar {{ display: flex; gap: 14px; align-items: center; flex-wrap: wrap; margin-bottom: 6px; }}
.legend span {{ display: inline-block; margin-right: 14px; font-size: 12px; }}
.bar button {{ font-size: 12px; padding: 2px 10px; }}
#graph {{ display: block; border: 1px solid #ddd; box-sizing: border-box;
  background: #fcfcfc; touch-action: none; user-select: none; }}
#graph.panning {{ cursor: grabbing; }}
svg text {{ font-size: 12px; pointer-events: none; dominant-baseline: central; }}
.proc rect {{ fill: #e8f0fb; stroke: #3b6fb6; stroke-width: 1.2; }}
.proc text {{ font-weight: bold; }}
.proc.unknown rect {{ fill: #f0f0f0; stroke: #999; stroke-dasharray: 4 2; }}
.var rect {{ fill: #fff; stroke: #8aa; }}
.bad rect {{ stroke: #d22; stroke-width: 2.2; }}
.bad text {{ fill: #b00; font-weight: bold; }}
.edge {{ fill: none; stroke-width: 1.1; opacity: .55; }}
.edge.publish {{ stroke: #2a62c9; }}
.edge.subscribe {{ stroke: #1a9a4a; stroke-dasharray: 5 3; }}
svg.focus .edge {{ opacity: .06; }}
svg.focus g.node {{ opacity: .25; }}
svg.focus .edge.on {{ opacity: 1; stroke-width: 2; }}
svg.focus g.node.on {{ opacity: 1; }}
g.node {{ cursor: pointer; }}
ul.findings li.error {{ color: #b00; }}
ul.findings li.warning {{ color: #a60; }}
ul {{ font-size: 13px; }}
</style></head>
<body>
<h1>{title}</h1>
<p class="sum" id="summary">{n_proc} processes, {n_var} variables, {n_find} findings.
Point at a process or a variable to see its neighbours; click to keep the highlight.
Wheel to zoom, drag to pan.</p>
<div class="bar"><div class="legend"><span style="color:#2a62c9">&#9473; publishes</span>
<span style="color:#1a9a4a">&#9476; subscribes</span>
<span style="color:#3b6fb6">&#9632; process</span>
<span style="color:#8aa">&#9634; variable</span>
<span style="color:#d22">&#9633; has findings</span>
<span style="color:#999">&#9633; not in the catalogue</span></div>
<div><button id="fit" type="button">Fit</button>
<button id="zoom-in" type="button">+</button>
<button id="zoom-out" type="button">&minus;</button></div></div>
<svg id="graph" xmlns="http://www.w3.org/2000/svg">
<defs>
<marker id="arrow-publish" viewBox="0 0 10 10" refX="9" refY="5" markerWidth="7"
 markerHeight="7" orient="auto"><path d="M0,0L10,5L0,10z" fill="#2a62c9"/></marker>
<marker id="arrow-subscribe" viewBox="0 0 10 10" refX="9" refY="5" markerWidth="7"
 markerHeight="7" orient="auto"><path d="M0,0L10,5L0,10z" fill="#1a9a4a"/></marker>
</defs>
<g class="view"><g class="edges"></g><g class="nodes"></g></g>
</svg>
<h2 style="font-size:15px">Findings</h2><ul class="findings">{findings}</ul>
<ul class="notes">{notes}</ul>
<script id="graph-data" type="application/json">@DATA@</script>
<script>@DAGRE@</script>
<script>@SCRIPT@</script>
</body></html>
"""

_SCRIPT = r"""
(function () {
  'use strict';
  var NS = 'http://www.w3.org/2000/svg';
  var data = JSON.parse(document.getElementById('graph-data').textContent);
  var svg = document.getElementById('graph');
  var nodeLayer = svg.querySelector('g.nodes');
  var edgeLayer = svg.querySelector('g.edges');
  var PAD_X = 10, PROC_H = 32, VAR_H = 22;

  function el(name, attrs, parent) {
    var e = document.createElementNS(NS, name);
    Object.keys(attrs).forEach(function (k) { e.setAttribute(k, attrs[k]); });
    if (parent) parent.appendChild(e);
    return e;
  }

  // the boxes first, to measure their labels
  var boxes = {};
  data.nodes.forEach(function (n) {
    var g = el('g', {'class': 'node ' + n.cls, id: n.id, 'data-id': n.id}, nodeLayer);
    el('title', {}, g).textContent = n.tip;
    var rect = el('rect', {rx: n.cls.indexOf('proc') === 0 ? 5 : 10}, g);
    var text = el('text', {}, g);
    text.textContent = n.label;
    var w = Math.ceil(text.getComputedTextLength()) + 2 * PAD_X;
    var h = n.cls.indexOf('proc') === 0 ? PROC_H : VAR_H;
    boxes[n.id] = {g: g, rect: rect, text: text, width: w, height: h};
  });

  var layout = new dagre.graphlib.Graph({multigraph: true});
  layout.setGraph({rankdir: 'LR', nodesep: 8, ranksep: 48, edgesep: 4,
                   marginx: 16, marginy: 16, ranker: 'network-simplex'});
  layout.setDefaultEdgeLabel(function () { return {}; });
  data.nodes.forEach(function (n) {
    layout.setNode(n.id, {width: boxes[n.id].width, height: boxes[n.id].height});
  });
  data.edges.forEach(function (e, i) { layout.setEdge(e.from, e.to, {}, 'e' + i); });
  dagre.layout(layout);

  data.nodes.forEach(function (n) {
    var b = boxes[n.id], at = layout.node(n.id);
    var x = at.x - b.width / 2, y = at.y - b.height / 2;
    b.rect.setAttribute('x', x.toFixed(1));
    b.rect.setAttribute('y', y.toFixed(1));
    b.rect.setAttribute('width', b.width);
    b.rect.setAttribute('height', b.height);
    b.text.setAttribute('x', (x + PAD_X).toFixed(1));
    b.text.setAttribute('y', at.y.toFixed(1));
  });

  // a B-spline through dagre's route, as d3's curveBasis draws it
  function basis(points) {
    var d = 'M' + points[0].x + ',' + points[0].y;
    if (points.length < 3) {
      return d + points.slice(1).map(function (p) { return 'L' + p.x + ',' + p.y; }).join('');
    }
    var x0 = points[0].x, y0 = points[0].y, x1 = points[1].x, y1 = points[1].y;
    d += 'L' + ((5 * x0 + x1) / 6) + ',' + ((5 * y0 + y1) / 6);
    for (var i = 2; i <= points.length; i++) {
      var p = points[Math.min(i, points.length - 1)];
      d += 'C' + ((2 * x0 + x1) / 3) + ',' + ((2 * y0 + y1) / 3) + ' ' +
           ((x0 + 2 * x1) / 3) + ',' + ((y0 + 2 * y1) / 3) + ' ' +
           ((x0 + 4 * x1 + p.x) / 6) + ',' + ((y0 + 4 * y1 + p.y) / 6);
      x0 = x1; y0 = y1; x1 = p.x; y1 = p.y;
    }
    return d + 'L' + x1 + ',' + y1;
  }

  data.edges.forEach(function (e, i) {
    var route = layout.edge({v: e.from, w: e.to, name: 'e' + i});
    var path = el('path', {'class': 'edge ' + e.kind, d: basis(route.points),
                           'marker-end': 'url(#arrow-' + e.kind + ')',
                           'data-a': e.proc, 'data-b': e.var}, edgeLayer);
    el('title', {}, path).textContent = e.tip;
  });

  // the view: fit, zoom about a point, pan
  var drawn = svg.querySelector('g.view').getBBox();  // the boxes and the routed edges
  var full = {x: drawn.x - 12, y: drawn.y - 12,
              w: Math.max(drawn.width, 1) + 24, h: Math.max(drawn.height, 1) + 24};
  var view = {x: full.x, y: full.y, w: full.w, h: full.h};
  function apply() {
    svg.setAttribute('viewBox', [view.x, view.y, view.w, view.h].join(' '));
  }
  function fit() {
    // the whole drawing at the page's width, but never so small that labels are
    // unreadable: a larger mission makes the page scroll (and the wheel zooms out)
    var avail = Math.max(svg.parentNode.clientWidth, 320);
    var scale = Math.min(1.25, Math.max(0.75, avail / full.w));
    svg.style.width = Math.round(full.w * scale) + 'px';
    svg.style.height = Math.round(full.h * scale) + 'px';
    view = {x: full.x, y: full.y, w: full.w, h: full.h};
    apply();
  }
  function toView(cx, cy) {
    var r = svg.getBoundingClientRect();
    var s = Math.max(view.w / r.width, view.h / r.height);
    var ox = view.x + (view.w - r.width * s) / 2, oy = view.y + (view.h - r.height * s) / 2;
    return {x: ox + (cx - r.left) * s, y: oy + (cy - r.top) * s, s: s};
  }
  function zoom(factor, cx, cy) {
    var r = svg.getBoundingClientRect();
    if (cx === undefined) { cx = r.left + r.width / 2; cy = r.top + r.height / 2; }
    var p = toView(cx, cy);
    view = {x: p.x - (p.x - view.x) * factor, y: p.y - (p.y - view.y) * factor,
            w: view.w * factor, h: view.h * factor};
    apply();
  }
  svg.addEventListener('wheel', function (ev) {
    ev.preventDefault();
    zoom(ev.deltaY > 0 ? 1.15 : 1 / 1.15, ev.clientX, ev.clientY);
  }, {passive: false});
  var drag = null, moved = false;
  svg.addEventListener('pointerdown', function (ev) {
    drag = {x: ev.clientX, y: ev.clientY, view: view, s: toView(0, 0).s};
    moved = false;
  });
  window.addEventListener('pointermove', function (ev) {
    if (!drag) return;
    var dx = ev.clientX - drag.x, dy = ev.clientY - drag.y;
    if (!moved && Math.abs(dx) + Math.abs(dy) < 4) return;
    moved = true;
    svg.classList.add('panning');
    view = {x: drag.view.x - dx * drag.s, y: drag.view.y - dy * drag.s,
            w: drag.view.w, h: drag.view.h};
    apply();
  });
  window.addEventListener('pointerup', function () {
    drag = null;
    svg.classList.remove('panning');
  });
  document.getElementById('fit').addEventListener('click', fit);
  document.getElementById('zoom-in').addEventListener('click', function () { zoom(1 / 1.3); });
  document.getElementById('zoom-out').addEventListener('click', function () { zoom(1.3); });
  window.addEventListener('resize', fit);
  fit();

  // the neighbours of what is pointed at
  var pinned = null;
  function show(id) {
    var on = {}; on[id] = true;
    svg.querySelectorAll('.edge').forEach(function (e) {
      var hit = e.dataset.a === id || e.dataset.b === id;
      e.classList.toggle('on', hit);
      if (hit) { on[e.dataset.a] = true; on[e.dataset.b] = true; }
    });
    svg.querySelectorAll('g[data-id]').forEach(function (g) {
      g.classList.toggle('on', !!on[g.dataset.id]);
    });
    svg.classList.add('focus');
  }
  function clear() { if (!pinned) svg.classList.remove('focus'); }
  svg.querySelectorAll('g[data-id]').forEach(function (g) {
    g.addEventListener('mouseenter', function () { if (!pinned) show(g.dataset.id); });
    g.addEventListener('mouseleave', clear);
    g.addEventListener('click', function (ev) {
      ev.stopPropagation();
      if (moved) return;
      pinned = pinned === g.dataset.id ? null : g.dataset.id;
      if (pinned) show(pinned); else svg.classList.remove('focus');
    });
  });
  svg.addEventListener('click', function () {
    if (moved) return;
    pinned = null;
    svg.classList.remove('focus');
  });
  document.body.setAttribute('data-rendered', String(data.nodes.length));
})();
"""
