"""How fast moos-lint is on a tree: ``python3 -m moos_lint.benchmark TREE [--runs N]``.

Prints each figure as the median (or the 95th percentile, for the editor
re-lint) of ``N`` runs (default 5, at least 5):

- ``cold``: ``moos-lint check TREE --no-cache`` (default rules, default jobs), and with ``-j 1``;
- ``warm``: the same with the result cache filled and nothing changed;
- ``--version``: ``moos-lint --version``, beside ``python3 -c pass`` (the interpreter alone);
- ``re-lint``: one file linted as the language server does it after an edit
  (a comment line added before each run; with its neighbours, from the editor's
  text), on the largest mission files of the tree and on the C++ file of the
  tree closest to 2,000 lines: p95 over the runs;
- ``floor``: what any cold run costs before moos-lint's own Python runs: start
  the interpreter, read every lintable file, prefilter the C++ and parse and
  query the relevant files with tree-sitter, shared between as many processes
  as the cold run uses (``--floor-of TREE``, which prints nothing). The rest
  of a cold run (expanding and parsing the missions, extracting the C++ facts,
  the rules, the report) is what the Python code of moos-lint costs;
- ``peak memory``: the largest resident set of the whole-tree run (any of its processes);
- ``ruff``: ``ruff check`` (no cache) over as many bytes of Python, copied from the
  installed packages into a temporary folder, and the ratio moos-lint / ruff.

The cache of the warm runs lives in a temporary folder (``--cache-dir``): the
benchmark writes nothing into the tree.

**The installation measured.** The command-line figures run ``moos-lint`` as
``pip install`` leaves it in a fresh virtual environment: the console script
of the package, compiled bytecode (kept in a temporary folder), and no import
hooks from ``.pth`` files. The environment is made in a temporary folder
(``python3 -m venv --without-pip``) and reaches moos-lint and its dependencies
where this interpreter has them; start-up hooks that a development machine may
carry in its own site-packages (an editable-install finder, certificate
injectors, ...) run before any program and are not moos-lint's. The
interpreter's own start in that environment is shown beside ``--version``.
"""

from __future__ import annotations

import argparse
import os
import shutil
import statistics
import subprocess
import sys
import sysconfig
import tempfile
import time
from pathlib import Path

MIN_RUNS = 5
#: the console script's entry point, as ``[project.scripts]`` in pyproject.toml names it
ENTRY_POINT = "moos_lint.cli:run"


#: the console script and the interpreter of the measured installation (see above)
_SCRIPT: list[str] = [sys.executable, "-m", "moos_lint"]
_PYTHON: str = sys.executable
_ENV: dict[str, str] | None = None


def _cli(*args: str) -> list[str]:
    return [*_SCRIPT, *args]


def clean_install(folder: str) -> tuple[str, str, dict[str, str]]:
    """A fresh virtual environment in ``folder`` that runs this moos-lint.

    Returns the ``moos-lint`` console script, the environment's interpreter and
    the process environment to run them with (bytecode written to a temporary
    cache, as an installed package has it compiled).
    """
    import moos_lint

    venv = os.path.join(folder, "venv")
    subprocess.run(
        [sys.executable, "-m", "venv", "--without-pip", venv], check=True, capture_output=True
    )
    bindir = os.path.join(venv, "Scripts" if os.name == "nt" else "bin")
    python = os.path.join(bindir, "python.exe" if os.name == "nt" else "python")
    site = subprocess.run(
        [python, "-c", "import sysconfig; print(sysconfig.get_paths()['purelib'])"],
        capture_output=True,
        text=True,
        check=True,
    ).stdout.strip()
    here = sysconfig.get_paths()
    package_root = os.path.dirname(os.path.dirname(os.path.abspath(moos_lint.__file__)))
    roots = list(dict.fromkeys([package_root, here["purelib"], here["platlib"]]))
    with open(os.path.join(site, "moos_lint_benchmark.pth"), "w", encoding="utf-8") as fh:
        fh.write("".join(f"{r}\n" for r in roots))  # paths only: no import lines run
    script = os.path.join(bindir, "moos-lint")
    with open(script, "w", encoding="utf-8") as fh:  # what pip writes for [project.scripts]
        module, function = ENTRY_POINT.split(":")
        fh.write(
            f"#!{python}\nimport sys\nfrom {module} import {function}\n"
            f'if __name__ == "__main__":\n    sys.exit({function}())\n'
        )
    os.chmod(script, 0o755)
    env = dict(os.environ)
    env.pop("PYTHONDONTWRITEBYTECODE", None)
    env["PYTHONPYCACHEPREFIX"] = os.path.join(folder, "bytecode")
    subprocess.run([script, "--version"], env=env, capture_output=True, check=True)
    # compile every module once, as pip does at install time
    subprocess.run(
        [python, "-m", "compileall", "-q", os.path.dirname(os.path.abspath(moos_lint.__file__))],
        env=env,
        capture_output=True,
        check=False,
    )
    return script, python, env


def _timed(cmd: list[str], env: dict[str, str] | None = None) -> float:
    start = time.perf_counter()
    subprocess.run(cmd, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, env=env, check=False)
    return time.perf_counter() - start


def _median(cmd: list[str], runs: int, env: dict[str, str] | None = None) -> float:
    return statistics.median(_timed(cmd, env or _ENV) for _ in range(runs))


def _p95(values: list[float]) -> float:
    values = sorted(values)
    return values[min(len(values) - 1, round(0.95 * (len(values) - 1)))]


def _peak_rss_mb(cmd: list[str]) -> float:
    """The largest resident set of ``cmd`` or any of its worker processes, in MB."""
    probe = (
        "import resource, subprocess, sys;"
        "subprocess.run(sys.argv[1:], stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL);"
        "print(resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss)"
    )
    out = subprocess.run(
        [sys.executable, "-c", probe, *cmd],
        capture_output=True,
        text=True,
        check=False,
        env=_ENV,
    )
    kb = int(out.stdout.strip() or 0)
    scale = 1024 * 1024 if sys.platform == "darwin" else 1024  # bytes on macOS, KB on Linux
    return kb / scale


def _lintable(tree: str) -> list[str]:
    from moos_lint.config import resolve_settings
    from moos_lint.discovery import discover

    settings = resolve_settings([Path(tree)], None)
    return discover([Path(tree)], settings.exclude, settings.root).files


def _python_sample(n_bytes: int, dest: str) -> int:
    """Copy installed ``.py`` files into ``dest`` until ``n_bytes``; return the bytes copied."""
    total = 0
    site = sysconfig.get_paths()["purelib"]
    for dirpath, dirnames, filenames in os.walk(site):
        dirnames.sort()
        for name in sorted(filenames):
            if not name.endswith(".py") or total >= n_bytes:
                continue
            src = os.path.join(dirpath, name)
            try:
                size = os.path.getsize(src)
                shutil.copyfile(src, os.path.join(dest, f"f{total:010d}_{name}"))
            except OSError:
                continue
            total += size
        if total >= n_bytes:
            break
    return total


def _relint_times(path: str, runs: int) -> list[float]:
    from moos_lint.lsp.analysis import analyse, settle

    settle()  # as the server does before it takes requests
    text = Path(path).read_text(encoding="utf-8", errors="replace")
    analyse(path, {path: text})  # warm: imports, the parser, the catalogue
    times = []
    for i in range(runs):
        edited = f"{text}\n// edit {i}\n"  # each re-lint follows an edit, as in the editor
        start = time.perf_counter()
        analyse(path, {path: edited})
        times.append(time.perf_counter() - start)
    return times


def _floor(tree: str) -> None:
    """Read every lintable file of ``tree``, and parse and query the C++ files that
    mention the MOOS API, shared between the processes a cold run uses."""
    from moos_lint import parallel
    from moos_lint.cpp.parse import backend
    from moos_lint.cpp.prefilter import mentions_moos
    from moos_lint.source import read_bytes
    from moos_lint.suffixes import is_cpp

    files = _lintable(tree)
    jobs = parallel.effective_jobs(None, len(files))
    be = backend()

    def work(part: list[str]) -> None:
        for p in part:
            data = read_bytes(p)
            if is_cpp(p) and isinstance(data, bytes) and mentions_moos(data):
                be.matches(be.parse(data))

    children = []
    for i in range(1, jobs):
        pid = os.fork()
        if pid == 0:
            work(files[i::jobs])
            os._exit(0)
        children.append(pid)
    work(files[0::jobs])
    for pid in children:
        os.waitpid(pid, 0)


def _cpp_near(files: list[str], lines: int) -> str | None:
    from moos_lint.cpp.prefilter import mentions_moos
    from moos_lint.suffixes import is_cpp_source

    best, best_gap = None, None
    for p in files:
        if not is_cpp_source(p):
            continue
        try:
            data = Path(p).read_bytes()
        except OSError:
            continue
        if not mentions_moos(data):
            continue
        gap = abs(data.count(b"\n") - lines)
        if best_gap is None or gap < best_gap:
            best, best_gap = p, gap
    return best


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(prog="python3 -m moos_lint.benchmark", description=__doc__)
    ap.add_argument("tree", help="the folder to lint (a MOOS-IvP checkout, say)")
    ap.add_argument("--runs", type=int, default=MIN_RUNS, help="runs per figure (at least 5)")
    ap.add_argument("--floor-of", action="store_true", help=argparse.SUPPRESS)
    args = ap.parse_args(argv)
    if args.floor_of:  # one run of the floor figure, timed by the benchmark
        _floor(os.path.abspath(args.tree))
        return 0
    runs = max(MIN_RUNS, args.runs)
    tree = os.path.abspath(args.tree)
    if not os.path.isdir(tree):
        print(f"benchmark: {args.tree}: not a folder", file=sys.stderr)
        return 2
    files = _lintable(tree)
    n_bytes = sum(os.path.getsize(p) for p in files if os.path.isfile(p))
    print(f"tree: {tree}: {len(files)} files, {n_bytes / 1e6:.1f} MB; median of {runs} runs")
    print(f"cpus: {os.cpu_count()}, python {sys.version.split()[0]}")
    out = []

    def show(name: str, value: str) -> None:
        out.append((name, value))
        print(f"  {name:40s} {value}", flush=True)

    global _SCRIPT, _PYTHON, _ENV
    with tempfile.TemporaryDirectory(prefix="moos-lint-bench-") as tmp:
        try:
            script, _PYTHON, _ENV = clean_install(os.path.join(tmp, "install"))
            _SCRIPT = [script]
            print("installation: a fresh virtual environment (see --help)")
        except (OSError, subprocess.CalledProcessError) as exc:
            print(f"installation: this interpreter (no virtual environment: {exc})")
        report = os.path.join(tmp, "report.json")
        cache = os.path.join(tmp, "cache")
        check = ["check", tree, "--output-format", "json", "-o", report, "--exit-zero"]
        cold = _median(_cli(*check, "--no-cache"), runs)
        show("cold (default jobs)", f"{cold:.3f} s")
        show("cold (-j 1)", f"{_median(_cli(*check, '--no-cache', '-j', '1'), runs):.3f} s")
        _timed(_cli(*check, "--cache-dir", cache))  # fill the cache
        show(
            "warm (cache, nothing changed)",
            f"{_median(_cli(*check, '--cache-dir', cache), runs):.3f} s",
        )
        show("moos-lint --version", f"{_median(_cli('--version'), runs) * 1000:.0f} ms")
        show(
            "python -c pass (same environment)",
            f"{_median([_PYTHON, '-c', 'pass'], runs) * 1000:.0f} ms",
        )
        floor = [_PYTHON, "-m", "moos_lint.benchmark", "--floor-of", tree]
        show(
            "floor (read + tree-sitter only)",
            f"{_median(floor, runs):.3f} s (the rest of a cold run is moos-lint's Python)",
        )
        rss = max(_peak_rss_mb(_cli(*check, "--no-cache")) for _ in range(2))
        show("peak memory (whole tree)", f"{rss:.0f} MB")

        missions = sorted(
            (p for p in files if p.endswith(".moos")), key=lambda p: -os.path.getsize(p)
        )[:3]
        for p in missions:
            t = _relint_times(p, max(runs, 20))
            name = f"re-lint {os.path.basename(p)}"
            show(name, f"p95 {_p95(t) * 1000:.1f} ms (median {statistics.median(t) * 1000:.1f})")
        cpp = _cpp_near(files, 2000)
        if cpp is not None:
            n = Path(cpp).read_bytes().count(b"\n")
            t = _relint_times(cpp, max(runs, 20))
            name = f"re-lint {os.path.basename(cpp)} ({n} lines)"
            show(name, f"p95 {_p95(t) * 1000:.1f} ms (median {statistics.median(t) * 1000:.1f})")

        sample = os.path.join(tmp, "python-sample")
        os.mkdir(sample)
        got = _python_sample(n_bytes, sample)
        ruff = shutil.which("ruff")
        if ruff is None:
            show("ruff", "not installed (pip install ruff)")
        else:
            cmd = [ruff, "check", "--no-cache", "--isolated", "--exit-zero", "-q", sample]
            r = _median(cmd, runs)
            show(f"ruff over {got / 1e6:.1f} MB of Python", f"{r:.3f} s")
            show("ratio moos-lint cold / ruff", f"{cold / r:.1f}x")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
