"""The page of ``moos-lint graph``, laid out in headless Chromium: no two boxes overlap,
every label is inside its box and the page, the highlight and the zoom work.

The page is made by the real program; a checking script is added to a copy of it,
and its verdict is read from the DOM Chromium dumps.
"""

from __future__ import annotations

import json
import re
import shutil
import subprocess
import sys
import tempfile
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parent.parent
FIXTURE = ROOT / "fixtures" / "graph" / "harbour.moos"
CORPUS = Path(__file__).resolve().parents[2] / "shared" / "corpus" / "moos-ivp"

_CHECK = r"""
<script>
(function () {
  var svg = document.getElementById('graph');
  var page = document.documentElement;
  var W = Math.max(page.scrollWidth, window.innerWidth);
  var H = Math.max(page.scrollHeight, window.innerHeight);
  var frame = svg.getBoundingClientRect();
  var nodes = Array.prototype.slice.call(svg.querySelectorAll('g.node'));
  var boxes = nodes.map(function (g) { return g.querySelector('rect').getBoundingClientRect(); });
  var out = {nodes: nodes.length, overlaps: [], outside: [], edges: 0, broken: 0};
  var eps = 0.5;
  for (var i = 0; i < boxes.length; i++) {
    for (var j = i + 1; j < boxes.length; j++) {
      var a = boxes[i], b = boxes[j];
      if (a.left < b.right - eps && b.left < a.right - eps &&
          a.top < b.bottom - eps && b.top < a.bottom - eps) {
        out.overlaps.push([nodes[i].id, nodes[j].id]);
      }
    }
    var t = nodes[i].querySelector('text').getBoundingClientRect(), r = boxes[i];
    var inBox = t.left >= r.left - eps && t.right <= r.right + eps &&
                t.top >= r.top - eps && t.bottom <= r.bottom + eps;
    var inFrame = t.left >= frame.left - eps && t.right <= frame.right + eps &&
                  t.top >= frame.top - eps && t.bottom <= frame.bottom + eps;
    var inPage = t.left >= 0 && t.top >= 0 && t.right <= W && t.bottom <= H;
    if (!(inBox && inFrame && inPage && t.width > 0)) out.outside.push(nodes[i].id);
  }
  svg.querySelectorAll('path.edge').forEach(function (p) {
    out.edges++;
    if (!/^M[-0-9.]+,[-0-9.]+/.test(p.getAttribute('d') || '') || /NaN/.test(p.getAttribute('d'))) {
      out.broken++;
    }
  });
  // the highlight: pointing at a publisher lights it and its neighbours
  var first = document.getElementById(svg.querySelector('path.edge').dataset.a);
  first.dispatchEvent(new MouseEvent('mouseenter'));
  out.focus = svg.classList.contains('focus');
  out.lit = svg.querySelectorAll('.edge.on').length;
  out.litNodes = svg.querySelectorAll('g.node.on').length;
  first.dispatchEvent(new MouseEvent('mouseleave'));
  // the zoom: the wheel narrows the view, Fit gives the whole drawing back
  var before = svg.getAttribute('viewBox');
  svg.dispatchEvent(new WheelEvent('wheel', {deltaY: -120, clientX: frame.left + 50,
                                             clientY: frame.top + 50, cancelable: true}));
  out.zoomed = svg.getAttribute('viewBox') !== before &&
      parseFloat(svg.getAttribute('viewBox').split(' ')[2]) < parseFloat(before.split(' ')[2]);
  document.getElementById('fit').click();
  out.refit = svg.getAttribute('viewBox') === before;
  var pre = document.createElement('pre');
  pre.id = 'layout-check';
  pre.textContent = JSON.stringify(out);
  document.body.appendChild(pre);
})();
</script>
"""


def _chromium() -> str | None:
    for name in ("chromium", "chromium-browser", "google-chrome"):
        found = shutil.which(name)
        if found:
            return found
    return None


def _layout(mission: Path, tmp_path: Path) -> tuple[dict, dict]:
    """(the verdict of the checking script, the graph as JSON) for ``mission``."""
    browser = _chromium()
    if browser is None:
        pytest.skip("chromium is not installed")
    page = tmp_path / "graph.html"
    run = [sys.executable, "-m", "moos_lint", "graph", str(mission)]
    subprocess.run([*run, "-o", str(page)], check=True, capture_output=True)
    graph = json.loads(
        subprocess.run([*run, "--format", "json"], check=True, capture_output=True).stdout
    )
    text = page.read_text(encoding="utf-8")
    assert "<script src" not in text and "https://" not in text  # nothing fetched
    checked = tmp_path / "checked.html"
    checked.write_text(text.replace("</body>", _CHECK + "</body>"), encoding="utf-8")
    with tempfile.TemporaryDirectory() as profile:
        proc = subprocess.run(
            [
                browser,
                "--headless",
                "--no-sandbox",
                "--disable-gpu",
                "--disable-quic",
                "--no-first-run",
                "--disable-background-networking",
                "--disable-component-update",
                "--disable-sync",
                f"--user-data-dir={profile}",
                "--window-size=1400,1000",
                "--dump-dom",
                checked.as_uri(),
            ],
            capture_output=True,
            text=True,
            timeout=120,
            check=False,
        )
    found = re.search(r'<pre id="layout-check">(.*?)</pre>', proc.stdout, re.S)
    if not proc.stdout.strip():
        pytest.skip(f"chromium rendered nothing: {proc.stderr[-300:]}")
    assert found, proc.stdout[-2000:]
    return json.loads(found.group(1).replace("&quot;", '"').replace("&amp;", "&")), graph


def _check(verdict: dict, graph: dict) -> None:
    assert verdict["nodes"] == len(graph["processes"]) + len(graph["variables"])
    assert verdict["overlaps"] == []
    assert verdict["outside"] == []
    assert verdict["edges"] == len(graph["edges"]) and verdict["broken"] == 0
    assert verdict["focus"] and verdict["lit"] > 0 and verdict["litNodes"] > 1
    assert verdict["zoomed"] and verdict["refit"]


def test_a_mission_of_thirteen_processes(tmp_path: Path):
    verdict, graph = _layout(FIXTURE, tmp_path)
    assert len(graph["processes"]) >= 12
    _check(verdict, graph)


def test_the_largest_moos_ivp_mission(tmp_path: Path):
    if not CORPUS.is_dir():
        pytest.skip("the MOOS-IvP corpus is not here")
    launches = {}  # the mission launching the most processes (then the largest file)
    for p in CORPUS.rglob("*.moos"):
        text = p.read_text(errors="replace")
        if "ANTLER" in text:
            launches[p] = (len(re.findall(r"(?im)^\s*Run\s*=", text)), len(text))
    if not launches:
        pytest.skip("no mission in the corpus")
    largest = max(launches, key=launches.__getitem__)
    verdict, graph = _layout(largest, tmp_path)
    _check(verdict, graph)
