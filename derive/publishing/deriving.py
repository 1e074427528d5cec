"""A set's problems derived: from the derivation cache where it holds them, the others one process
per core, the same results whatever the number of processes.

The derivations of a set are independent, so each runs in a worker process of its own
(multiprocessing's pool, forked: the imports are paid once) and comes back as the bytes the
cache writes (derive.publishing.derivation_cache.dumps), loaded by the parent exactly as an
entry of the cache is: one way from a derivation to a Solution in another process, whose
byte-identity tests/test_derivation_cache.py proves. With one job everything runs in this
process, as before. A problem whose derivation fails in a worker (or cannot be written) is
derived again here, so that its error is the one a single job raises.

>>> from derive.language.problem import load
>>> [(s.problem.id, cached) for s, cached in derive([load("rod_endpoint")], jobs=1, cache=False)]
[('rod_endpoint', False)]
"""
from __future__ import annotations

import contextlib
import logging
import multiprocessing
import os
import signal
from collections.abc import Callable, Iterable, Iterator, Sequence

from derive.language.problem import Problem, load
from derive.publishing import cluster, derivation_cache
from derive.publishing.progress import Reporter
from derive.solution.answers import Solution


def cores() -> int:
    """The cores this process may run on (the default of --jobs)."""
    try:
        return len(os.sched_getaffinity(0))
    except AttributeError:  # not on Linux
        return os.cpu_count() or 1


def derive(problems: Sequence[Problem], jobs: int = 1, cache: bool = True, progress: Reporter = Reporter(),
           where: Callable[[int], object] | None = None, scheduler: str | None = None) -> list[tuple[Solution, bool]]:
    """Each problem's Solution (derivation_cache.derived) and whether it came from the cache, in
    order. `where(i)` is a context manager that names problem i in its errors (a set's entry).
    `scheduler`: a Dask scheduler's address, whose workers derive them in place of `jobs` processes
    (derive.publishing.cluster)."""
    results: list[tuple[Solution, bool] | None] = [None] * len(problems)
    cap = derivation_cache.size_cap() if cache else 0  # a bad DERIVE_CACHE_MB refused before any derivation
    keys = [derivation_cache.key(p) if cache else None for p in problems]
    with progress.task("deriving", len(problems)) as begin:
        for i, problem in enumerate(problems):  # the cached ones first: a moment each
            solution = derivation_cache.fetch(problem, keys[i]) if cache else None
            if solution is not None:
                results[i] = solution, True
                begin(f"{problem.id} (from the cache)")
        missing = [i for i, r in enumerate(results) if r is None]
        workers = min(jobs, len(missing))
        waiting = [problems[i] for i in missing]
        if scheduler is not None and missing:
            payloads = _collected(waiting, cluster.derived(waiting, scheduler), begin, " on the cluster")
        elif workers > 1:
            payloads = _collected(waiting, _in_workers(waiting, workers), begin)
        else:
            payloads = {}
        for n, i in enumerate(missing):
            problem = problems[i]
            payload = payloads.get(n)
            solution = derivation_cache.loads(payload, problem) if payload is not None else None
            if solution is None:  # one job, or a failure in a worker: here, with its error named
                if workers <= 1 and scheduler is None:
                    begin(problem.id)
                with where(i) if where else contextlib.nullcontext():
                    solution = derivation_cache.derived(problem)
            if cache:
                derivation_cache.store(problem, solution, keys[i], payload, trimmed=False)
            results[i] = solution, False
    if cache:
        derivation_cache.trim(cap)
    return results


def _in_workers(problems: Sequence[Problem], workers: int) -> Iterator[tuple[int, bytes | None, list[str]]]:
    """The problems' solutions as bytes (None where a worker failed), derived by `workers`
    processes, by index as each ends, with the ids of those still running."""
    context = multiprocessing.get_context("fork")  # the parent's modules and settings (the time limit), no re-import
    pool = context.Pool(workers, initializer=_worker_signals)
    try:
        waiting = [pool.apply_async(_derived_bytes, (str(p.path),)) for p in problems]
        pending = list(range(len(problems)))
        while pending:
            finished = next((n for n in pending if waiting[n].ready()), None)
            if finished is None:
                waiting[pending[0]].wait(0.05)
                continue
            pending.remove(finished)
            yield finished, waiting[finished].get(), [problems[n].id for n in pending[:workers]]  # taken in order
        pool.close()
    finally:
        pool.terminate()  # at once, on Ctrl-C or SIGTERM too: no derivation outlives the command
        pool.join()


def _collected(problems: Sequence[Problem], results: Iterable[tuple[int, bytes | None, list[str] | None]],
               begin: Callable[[str], None], where: str = "") -> dict[int, bytes]:
    """The payloads of `results` ((index, bytes or None, the ids still running where known) as each
    ends), each reported as it ends."""
    done = {}
    with contextlib.closing(iter(results)) as ending:  # an error here stops the workers at once
        for count, (n, payload, running) in enumerate(ending, start=1):
            done[n] = payload
            left = len(problems) - count
            after = (f"; running {', '.join(running)}" if running else "") if running is not None else \
                (f"; {left} left" if left else "")
            begin(f"{problems[n].id} done{where}{after}")
    return {n: payload for n, payload in done.items() if payload is not None}


def _worker_signals() -> None:
    """A worker leaves Ctrl-C to the parent (which stops the pool) and ends at once on SIGTERM; it
    shows no progress of its own (the parent's lines say what is running)."""
    logging.getLogger("derive").disabled = True
    signal.signal(signal.SIGINT, signal.SIG_IGN)
    signal.signal(signal.SIGTERM, signal.SIG_DFL)


def _derived_bytes(path: str) -> bytes | None:
    """In a worker: the problem at `path` derived, as bytes; None if it fails (the parent derives
    it again, to report the error as one job would)."""
    try:
        return derivation_cache.dumps(derivation_cache.derived(load(path)))
    except Exception:  # noqa: BLE001 - reported by the parent's own attempt
        return None

