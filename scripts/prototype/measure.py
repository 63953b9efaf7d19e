"""What a compiled front end would give the mission path: a measured prototype.

    python scripts/prototype/measure.py TREE [--runs N]

Builds ``frontend.c`` (beside this script) with the system C compiler into a
temporary folder, then times, over the ``.moos`` and ``.bhv`` files of TREE
(medians of N runs, one process):

- each stage of moos-lint's mission path, as ``moos-lint check FILES -j 1``
  runs them: imports, settings and rules, the front end (nsplug expansion and
  parsing: ``LintRun.build_unit``), the rules;
- the compiled prototype doing the front end's work on the same files, with
  the Python objects the rules would need.

The prototype is a measurement, not moos-lint's front end (see ``frontend.c``):
it is never installed and no test or CI step depends on it.
"""

from __future__ import annotations

import argparse
import importlib.util
import json
import os
import statistics
import subprocess
import sys
import sysconfig
import tempfile
import time
from pathlib import Path

HERE = Path(__file__).resolve().parent


def build(out_dir: str):
    """The compiled prototype, imported (None when no compiler is found)."""
    suffix = sysconfig.get_config_var("EXT_SUFFIX") or ".so"
    target = os.path.join(out_dir, "frontend_prototype" + suffix)
    cc = os.environ.get("CC", "cc")
    cmd = [cc, "-O2", "-shared", "-fPIC", "-I", sysconfig.get_paths()["include"]]
    try:
        subprocess.run([*cmd, str(HERE / "frontend.c"), "-o", target], check=True)
    except (OSError, subprocess.CalledProcessError) as exc:
        print(f"cannot build the prototype: {exc}", file=sys.stderr)
        return None
    spec = importlib.util.spec_from_file_location("frontend_prototype", target)
    if spec is None or spec.loader is None:
        return None
    mod = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(mod)
    return mod


def mission_files(tree: str) -> list[str]:
    out = []
    for folder, dirs, names in os.walk(tree):
        dirs[:] = sorted(d for d in dirs if not d.startswith("."))
        out += [os.path.join(folder, n) for n in sorted(names) if n.endswith((".moos", ".bhv"))]
    return out


def stages(files: list[str]) -> dict[str, float]:
    """The mission path's stages in this process, as one ``-j 1`` run takes them."""
    t0 = time.perf_counter()
    from moos_lint.core import engine
    from moos_lint.core.config import resolve_settings
    from moos_lint.core.registry import select_rules

    t1 = time.perf_counter()
    settings = resolve_settings([Path(f) for f in files], None)
    rules = select_rules(settings.select, settings.extend_select, settings.ignore)
    t2 = time.perf_counter()
    run = engine.LintRun(settings, rules, None)
    for path in files:
        run.units.append(run.build_unit(path))
    t3 = time.perf_counter()
    for unit in run.units:
        run.included_elsewhere.update(p for p in unit.expansion.sources if p != unit.path)
    for unit in run.units:
        run.run_rules(unit)
    t4 = time.perf_counter()
    return {
        "imports": t1 - t0,
        "settings and rules": t2 - t1,
        "front end": t3 - t2,
        "rules": t4 - t3,
    }


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("tree")
    ap.add_argument("--runs", type=int, default=5)
    args = ap.parse_args()
    files = mission_files(args.tree)
    print(f"{len(files)} mission and behavior files; medians of {args.runs} runs")
    # each Python run in a fresh process: imports and memos start cold, as a command does
    code = (
        f"import json, sys; sys.path.insert(0, {str(HERE)!r}); import measure; "
        "print(json.dumps(measure.stages(sys.argv[1:])))"
    )

    runs = [
        json.loads(
            subprocess.run(
                [sys.executable, "-c", code, *files], capture_output=True, text=True, check=True
            ).stdout
        )
        for _ in range(args.runs)
    ]
    py = {k: statistics.median(r[k] for r in runs) for k in runs[0]}
    for k, v in py.items():
        print(f"  python {k:<20} {v * 1e3:8.1f} ms")
    print(f"  python total {'':<14} {sum(py.values()) * 1e3:8.1f} ms")
    with tempfile.TemporaryDirectory() as tmp:
        mod = build(tmp)
        if mod is None:
            return 1
        times = []
        for _ in range(args.runs):
            t = time.perf_counter()
            n_lines = n_params = 0
            for f in files:
                lines, params = mod.expand_moos(f)
                n_lines += len(lines)
                n_params += len(params)
            times.append(time.perf_counter() - t)
    c = statistics.median(times)
    print(f"  compiled front end       {c * 1e3:8.1f} ms ({n_lines} lines, {n_params} parameters)")
    print(f"  front end, python / compiled: {py['front end'] / c:.0f}x")
    rest = sum(py.values()) - py["front end"] + c
    print(
        f"  mission path with the compiled front end: {rest * 1e3:.1f} ms "
        f"({rest / sum(py.values()):.0%} of today's)"
    )
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
