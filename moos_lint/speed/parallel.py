"""Worker processes for ``--jobs N``: the same result as one process, sooner.

A lint run has two expensive phases, and each is spread over worker
processes:

1. **Reading C++.** Each folder of C++ files is read, prefiltered (only files
   that mention the MOOS API are parsed) and parsed with tree-sitter in a
   worker; the largest folders go first, so that no big folder starts last.
   Meanwhile the main process expands and parses the mission and behavior
   files, then takes the folders no worker has started yet, smallest first.
   The workers send back plain facts (the relevant sources and the extracted
   :class:`~moos_lint.frontends.cpp.model.CppFile` records); the main process links them
   into apps exactly as a single process does.
2. **Running the rules.** Once every unit is built, one worker fewer than the
   jobs is forked: each worker inherits the whole run (every unit, the
   cross-unit sets) and runs the rules a folder at a time (missions there
   share models), taking the next folder, heaviest first, from a pipe that
   holds their numbers; the main process takes folders from the same pipe
   meanwhile. These workers are plain forks (no pool, no ``multiprocessing``
   import: a mission run's workers cost about a millisecond each): a worker
   writes each folder's findings to a memory file of its own and exits; the
   main process reads them, merges them in unit order, then applies
   suppressions and runs the run-wide rules (``unused-suppression``) itself.
   Caches that rules build lazily on the run (mission models, the app
   catalogue) are rebuilt in each worker from the same units, so every worker
   sees what a single process would.

Each C++ folder is read by whichever process claims it first (:class:`Claims`, a
flag per task in memory the workers share): a worker that finds its task
claimed by the main process returns at once. (Cancelling the pool's futures
instead races with a worker's death: Python's pool then fails to mark the
futures left, and the run would wait for them forever.)

Workers are forked, which shares the run with them for free; where ``fork``
is not available (Windows, macOS, where it is unsafe) a run stays in one
process, and so does a process that runs other threads (forking it could
deadlock). A small input (fewer than :data:`MIN_FILES` files) also stays in one
process: starting a pool costs more than it saves, and editors re-lint one
file at a time. Without ``--jobs``, a run takes the CPUs that other work leaves
idle at its start (a CPU shared with a busy process gains nothing from a second
worker but the cost of starting it), so it is never slower than ``-j 1``. A
worker that dies (breaking the C++ pool, or leaving its rule folders unwritten)
leaves the rest of the work to the main process, so a run never waits forever.
"""

from __future__ import annotations

import contextlib
import os
import sys
import threading
from collections.abc import Iterator
from typing import TYPE_CHECKING, Any

# ``multiprocessing`` and ``concurrent.futures`` (with the sockets, pickling, logging and
# temporary files they load: a tenth of a mission run's start) are imported only
# when workers start.

if TYPE_CHECKING:  # the engine starts the workers: this module does not import it
    from moos_lint.commands.progress import Progress
    from moos_lint.core.engine import LintRun
    from moos_lint.files.diagnostics import Diagnostic
    from moos_lint.frontends.unit import Unit

#: below this many files a run stays in one process
MIN_FILES = 50

# The run a forked rule worker inherits (set just before the pool is forked).
_RUN: LintRun | None = None


def default_jobs() -> int:
    """The number of CPUs this process may use."""
    try:
        return max(1, len(os.sched_getaffinity(0)))
    except (AttributeError, OSError):
        return max(1, os.cpu_count() or 1)


def busy_cpus() -> int:
    """How many tasks other than this one are running now (Linux's ``/proc/loadavg``
    counts the runnable tasks, this one included); 0 where that is not known."""
    try:
        with open("/proc/loadavg", encoding="ascii") as fh:
            running = int(fh.read().split()[3].split("/")[0])
    except (OSError, ValueError, IndexError):
        return 0
    return max(0, running - 1)


def can_fork() -> bool:
    return sys.platform.startswith("linux") and hasattr(os, "fork")


def effective_jobs(jobs: int | None, n_files: int) -> int:
    """How many processes to use for ``n_files`` files when ``jobs`` are asked for."""
    if jobs is None:  # as many as there are CPUs that other work leaves idle now
        jobs = max(1, default_jobs() - busy_cpus())
    if jobs <= 1 or n_files < MIN_FILES or not can_fork():
        return 1
    if threading.active_count() > 1:  # forking a threaded process (an embedding host) can deadlock
        return 1
    return jobs


def pool(jobs: int) -> Any:
    """Forked workers, or None where the system cannot give a pool its locks (no
    ``/dev/shm`` in some containers): the run then stays in this process. A worker that
    dies (a crash in a parser) breaks the pool, which the callers notice: the work is
    then done in this process, never waited for forever."""
    import multiprocessing
    from concurrent.futures import ProcessPoolExecutor

    try:
        return ProcessPoolExecutor(jobs, mp_context=multiprocessing.get_context("fork"))
    except (OSError, ImportError, NotImplementedError):
        return None


def stop(workers: Any) -> None:
    workers.shutdown(wait=True, cancel_futures=True)


class Claims:
    """Which of ``n`` tasks some process has taken, in memory shared with the workers
    forked after it is made: each task is done by the first process to claim it."""

    def __init__(self, n: int) -> None:
        import multiprocessing

        self._taken = multiprocessing.get_context("fork").Array("b", max(1, n))

    def claim(self, i: int) -> bool:
        """Take task ``i``; False when another process has it."""
        with self._taken.get_lock():
            if self._taken[i]:
                return False
            self._taken[i] = 1
            return True


class _Unshared:
    """Claims of tasks no worker takes: this process may take every one."""

    def claim(self, i: int) -> bool:
        return True


# The claims of the tasks a pool's workers run (set before the pool forks them).
_CLAIMS: Claims | None = None


def _claimed(i: int) -> bool:
    """In a worker: whether this worker takes task ``i`` (the main process may have it)."""
    return _CLAIMS is None or _CLAIMS.claim(i)


# ------------------------------------------------------------------ phase 1: C++
def _cpp_folder(i: int, paths: list[str]) -> tuple[tuple, list] | None:
    """In a worker: read, prefilter and parse one folder of C++ files (task ``i``); with
    the reads noted meanwhile (see :func:`moos_lint.files.source.keep_journal`). None
    when the main process took the task."""
    from moos_lint.files import source

    if not _claimed(i):
        return None
    size = source.journal_size()
    facts = cpp_folder_facts(paths)
    return facts, source.journal_since(size)


def cpp_folder_facts(
    paths: list[str],
) -> tuple[list[str], dict[str, Any], list[Any] | None, str, dict[str, Any]]:
    """Read, prefilter and parse one folder of C++ files: (paths, sources, facts, error,
    the value analysis's index of each file read)."""
    from moos_lint.frontends.cpp.app import parse_folder, read_relevant

    names: dict[str, Any] = {}
    try:
        sources = read_relevant(paths, names=names)
        files = parse_folder(sources) if sources else []
        return paths, sources, files, "", names
    except Exception as exc:  # the main process redoes this folder to report it
        return paths, {}, None, f"{type(exc).__name__}: {exc}", {}


def _load_cpp() -> None:
    """Load the C++ reader and compile its query (about 30 ms) in this process, which
    needs them too, before the workers are forked: each would otherwise do it again."""
    from moos_lint.frontends.cpp import app, values  # noqa: F401
    from moos_lint.frontends.cpp.parse import backend

    backend()


def _folder_weight(paths: list[str]) -> int:
    total = 0
    for p in paths:
        with contextlib.suppress(OSError):
            total += os.stat(p).st_size
    return total


def start_cpp(workers: Any, paths: list[str]) -> Iterator[Any]:
    """Submit the C++ folders of ``paths`` to ``workers``, largest first; results in any order."""
    global _CLAIMS
    folders: dict[str, list[str]] = {}
    for p in paths:
        folders.setdefault(os.path.dirname(p), []).append(p)
    tasks = sorted(folders.values(), key=lambda ps: (-_folder_weight(ps), ps[0]))
    _load_cpp()  # before the first submit forks the workers: they share it
    futures: list[Any] = []
    claims: Claims | _Unshared = _Unshared()
    try:
        claims = _CLAIMS = Claims(len(tasks))  # before the first submit, which forks them
        for i, t in enumerate(tasks):
            futures.append(workers.submit(_cpp_folder, i, t))
    except Exception:  # a worker died already (or no claims): the tasks left are done here
        pass
    finally:
        _CLAIMS = None
    return _completed(futures, tasks, claims)


def _completed(
    futures: list[Any], tasks: list[list[str]], claims: Claims | _Unshared
) -> Iterator[Any]:
    """The results; the folders no worker has started yet are taken here, smallest first,
    so that this process (done with the missions) shares the tail of the work."""
    from concurrent.futures import as_completed

    try:
        for i in range(len(tasks) - 1, -1, -1):
            if not claims.claim(i):  # a worker has it (or had it)
                break
            yield cpp_folder_facts(tasks[i])
        from moos_lint.files.source import merge_journal

        for fut in as_completed(futures):
            got = fut.result()
            if got is None:  # taken here
                continue
            facts, reads = got
            merge_journal(reads)
            yield facts
    except Exception as exc:  # a worker died: the main process redoes the C++
        yield tasks[0] if tasks else [], {}, None, f"{type(exc).__name__}: {exc}", {}


# ------------------------------------------------------------------ phase 2: rules
_REPORTED: set[str] = set()


def _unit_rules(
    b: int, indices: list[int]
) -> tuple[list[tuple[int, list[Diagnostic], int]], set[str], set[str], list[Any]]:
    """In a worker: the findings of some units (the folder it took from the queue, task
    ``b``), the files and folders newly read, and the reads noted meanwhile (see
    :func:`moos_lint.files.source.keep_journal`)."""
    from moos_lint.files import source

    run = _RUN
    if run is None:
        raise RuntimeError("a rule worker started without a run")
    size = source.journal_size()
    out = []
    for i in indices:
        diags, errors = run.run_rules(run.units[i])
        out.append((i, diags, errors))
    read = run.cache.paths() - _REPORTED
    _REPORTED.update(read)
    return out, read, set(run.cache.probed), source.journal_since(size)


def _unit_weight(unit: Unit) -> int:
    if unit.cpp is not None:
        return sum(len(f.publications) + len(f.subscriptions) for f in unit.cpp.files) * 400
    n = len(unit.expansion.lines)
    if unit.moos is not None and unit.moos.is_mission:
        n *= 8  # a mission builds its model: the costliest unit by far
    return n


def rule_batches(units: list[Unit]) -> list[list[int]]:
    """The units (by index) a rule worker takes at a time: one folder's.

    Missions of a folder share their sibling missions, fragments and behavior
    files, whose models a worker then builds once. Heaviest folders first, so
    that no big folder starts last.
    """
    folders: dict[str, list[int]] = {}
    for i, unit in enumerate(units):
        folders.setdefault(os.path.dirname(unit.path), []).append(i)
    return sorted(folders.values(), key=lambda b: (-sum(_unit_weight(units[i]) for i in b), b[0]))


def run_rules_parallel(
    run: LintRun, jobs: int, progress: Progress | None = None
) -> list[tuple[list[Diagnostic], int]]:
    """``run.run_rules(unit)`` for every unit, in ``jobs`` processes: this one and
    ``jobs - 1`` forked workers; results in unit order. ``progress``: told of each unit
    done (:mod:`moos_lint.commands.progress`).

    The folders (:func:`rule_batches`, heaviest first) wait in a pipe, one number each,
    written before the workers are forked; each process takes the next by reading one
    number, so no folder is checked twice and none waits for a busy process. A worker
    writes its findings to a memory file of its own and exits; this process reads them
    once the queue is empty and its own folders are done. These workers cost a fork
    each: no pool, no ``multiprocessing`` import (about 25 ms at the start of a mission
    run). A worker that dies leaves what it did not write to this process, so a run
    never waits forever; a system that cannot give the pipe or the memory files runs
    every unit here."""
    batches = rule_batches(run.units)
    results: list[tuple[list[Diagnostic], int] | None] = [None] * len(run.units)
    try:
        queue = _task_queue(len(batches))
    except OSError:
        return [run.run_rules(unit) for unit in run.units]
    workers: list[tuple[int, int]] = []  # (pid, memory file)
    try:
        for _ in range(max(0, min(jobs - 1, len(batches) - 1))):
            worker = _fork_rule_worker(run, batches, queue)
            if worker is None:
                break
            workers.append(worker)
        for b in _take(queue):  # this process takes its share meanwhile
            for i in batches[b]:
                results[i] = run.run_rules(run.units[i])
            if progress is not None:
                progress.advance(len(batches[b]))
    finally:
        os.close(queue)
        for pid, out in workers:
            _collect(run, pid, out, results, progress)
    return [r if r is not None else run.run_rules(run.units[i]) for i, r in enumerate(results)]


_TASK = 4  # bytes per task number in the queue (atomic in a pipe: PIPE_BUF is at least 512)


def _task_queue(n: int) -> int:
    """The read end of a pipe holding the numbers ``0 .. n-1``, its write end closed: a
    read of one number takes a task, and the end of the pipe says that none is left."""
    r, w = os.pipe()
    try:
        data = b"".join(i.to_bytes(_TASK, "little") for i in range(n))
        with contextlib.suppress(OSError):  # room for every task, where the system allows
            import fcntl

            fcntl.fcntl(w, getattr(fcntl, "F_SETPIPE_SZ", 1031), max(len(data), 4096))
        os.set_blocking(w, False)  # a full pipe fails (BlockingIOError) rather than blocks
        written = 0
        while written < len(data):
            written += os.write(w, data[written:])
    except OSError:
        os.close(r)
        raise
    finally:
        os.close(w)
    return r


def _take(queue: int) -> Iterator[int]:
    """The tasks this process takes from the queue, until it is empty."""
    while True:
        got = os.read(queue, _TASK)
        if len(got) < _TASK:
            return
        yield int.from_bytes(got, "little")


def _fork_rule_worker(run: LintRun, batches: list[list[int]], queue: int) -> tuple[int, int] | None:
    """Fork a worker that runs the rules on the folders it takes from ``queue`` and
    writes each folder's result to a memory file: (its pid, the file). None when the
    system gives no memory file or no fork."""
    global _RUN
    try:
        out = os.memfd_create("moos-lint-rules", getattr(os, "MFD_CLOEXEC", 0))
    except (AttributeError, OSError):
        return None
    try:
        pid = os.fork()
    except OSError:
        os.close(out)
        return None
    if pid == 0:  # the worker: never returns
        status = 1
        try:
            import pickle

            _RUN = run
            _REPORTED.clear()  # what it reads beyond what the run had read counts
            _REPORTED.update(run.cache.paths())
            for b in _take(queue):
                record = pickle.dumps(_unit_rules(b, batches[b]), pickle.HIGHEST_PROTOCOL)
                os.write(out, len(record).to_bytes(8, "little"))
                view = memoryview(record)
                while view:
                    view = view[os.write(out, view) :]
            status = 0
        finally:
            os._exit(status)
    return pid, out


def _collect(
    run: LintRun,
    pid: int,
    out: int,
    results: list[tuple[list[Diagnostic], int] | None],
    progress: Progress | None,
) -> None:
    """Wait for worker ``pid`` and take the results it wrote (those of a worker that died
    part way are kept up to its last whole record; its other folders are redone here)."""
    import pickle

    from moos_lint.files.source import merge_journal

    try:
        os.waitpid(pid, 0)
        os.lseek(out, 0, os.SEEK_SET)
        with open(out, "rb", closefd=False) as fh:
            data = fh.read()
    except OSError:
        data = b""
    finally:
        os.close(out)
    at = 0
    while at + 8 <= len(data):
        size = int.from_bytes(data[at : at + 8], "little")
        if at + 8 + size > len(data):
            break
        try:
            got = pickle.loads(data[at + 8 : at + 8 + size])
        except Exception:
            break
        at += 8 + size
        batch, read, probed, reads = got
        merge_journal(reads)
        for i, diags, errors in batch:
            results[i] = (diags, errors)
        if progress is not None:
            progress.advance(len(batch))
        # what the workers read counts for the result cache (moos_lint.speed.cache)
        run.cache.read_elsewhere.update(read)
        run.cache.probed.update(probed)


__all__ = [
    "MIN_FILES",
    "Claims",
    "default_jobs",
    "effective_jobs",
    "pool",
    "run_rules_parallel",
    "start_cpp",
    "stop",
]
