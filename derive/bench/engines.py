"""`derive bench`'s engines section: derive against sympy.physics.mechanics, cold, in the same run.

Each scene of derive.bench.anchors is derived by both engines in a fresh child of one worker
process (imports paid once before it forks, every cache empty), checked to give the same
accelerations, constraint forces and answers at a sample point, and timed; the n-link pendulum
is derived by each of derive's routes and by KanesMethod for growing n. Figures, never asserted.

>>> _growth([1, 2, 4], [1.0, 2.0, 4.0])
1.0
"""
from __future__ import annotations

import statistics
import subprocess
import sys
import time
from pathlib import Path

import numpy as np

#: The worker imports these before it forks: neither engine pays for an import in its figure.
_PRELOAD = ("sympy", "sympy.physics.mechanics", "derive.solution.answers", "derive.language.problem", "derive.bench.anchors",
            "derive.mechanics.lagrange", "derive.mechanics.newton_euler")
#: The routes of the chain study, in the table's order, with their headings.
ROUTES = {"lagrange": "derive Lagrange", "newton_euler": "derive Newton-Euler", "solve": "derive solve",
          "anchor": "anchor (Kane)"}
#: A job is run again (a fresh cold child each time), up to `repeats` times, while its first run
#: took less than this many seconds; its figures are the medians.
REPEAT_BELOW = 20.0


def _serve() -> None:
    """The cold-start worker (`python -c "from derive.bench.engines import _serve; _serve()"`): import
    both engines once, then for each job (a JSON line on stdin) fork a child that runs it with
    every cache empty and sends one JSON line back, without paying the 1 to 2 s of a fresh
    interpreter. A child killed at its CPU limit answers {"over_limit": true}."""
    import importlib
    import json
    import os
    import signal

    for name in _PRELOAD:
        importlib.import_module(name)
    for line in sys.stdin:
        read, write = os.pipe()
        pid = os.fork()
        if pid == 0:  # the child: never returns
            os.close(read)
            try:
                result = _child(json.loads(line))
            except BaseException as error:  # noqa: B036 - reported as the job's figure
                result = {"error": f"{type(error).__name__}: {str(error).splitlines()[0] if str(error) else ''}"}
            os.write(write, (json.dumps(result) + "\n").encode())
            os._exit(0)
        os.close(write)
        with os.fdopen(read) as pipe:
            answer = pipe.read().strip()
        _, status = os.waitpid(pid, 0)
        if not answer:
            killed = os.WIFSIGNALED(status) and os.WTERMSIG(status) in (signal.SIGXCPU, signal.SIGKILL)
            answer = json.dumps({"over_limit": True} if killed else {"error": f"the child stopped ({status})"})
        print(answer, flush=True)


def _status_kib(field: str) -> int:
    """A field of /proc/self/status in KiB (VmRSS, VmHWM); 0 where there is none."""
    try:
        for line in Path("/proc/self/status").read_text().splitlines():
            if line.startswith(field + ":"):
                return int(line.split()[1])
    except OSError:
        pass
    return 0


def _child(job: dict) -> dict:
    """Run one job in a forked child: output silenced, derive's own time limit off and a CPU
    limit of job["limit"] seconds instead, sympy's cache cleared; add its wall time and the rise
    of its peak resident memory (the peak is reset first, /proc/self/clear_refs)."""
    import os
    import resource

    from sympy.core.cache import clear_cache

    from derive.core import limits

    devnull = os.open(os.devnull, os.O_WRONLY)
    os.dup2(devnull, 1)
    os.dup2(devnull, 2)
    used = resource.getrusage(resource.RUSAGE_SELF)
    soft = int(used.ru_utime + used.ru_stime + job["limit"]) + 1
    resource.setrlimit(resource.RLIMIT_CPU, (soft, soft + 5))
    limits.configure(0)
    clear_cache()
    try:
        Path("/proc/self/clear_refs").write_text("5")
    except OSError:
        pass
    before = _status_kib("VmRSS")
    start = time.perf_counter()
    result, compare = _JOBS[job["kind"]](job)
    result["seconds"] = time.perf_counter() - start
    result["peak_mib"] = max(_status_kib("VmHWM") - before, 0) / 1024
    if compare is not None:  # untimed: the numbers the parent compares
        result["numbers"] = compare()
    return result


def _derive_scene(job: dict):
    """What `derive check` runs but the simulation: the problem read, both routes, every answer
    and every cross-check. The routes' own time (each route's equations formed and solved) and the
    inertia integrals are measured by wrapping those functions in this child."""
    from derive.bench import anchors as bench_anchors
    from derive.model import inertia
    from derive.language import problem
    from derive.solution.answers import Solution
    from derive.mechanics import derivation, lagrange, newton_euler

    spent = {"lagrange": 0.0, "newton_euler": 0.0, "inertia": 0.0}
    inner: list[float] = []  # time of the wrapped calls inside the one running, by depth

    def timed(label, function):
        def wrapper(*args, **kwargs):
            start = time.perf_counter()
            inner.append(0.0)
            try:
                return function(*args, **kwargs)
            finally:
                elapsed = time.perf_counter() - start
                spent[label(args)] += elapsed - inner.pop()
                if inner:
                    inner[-1] += elapsed
        return wrapper

    lagrange.derive = timed(lambda a: "lagrange", lagrange.derive)
    newton_euler.derive = timed(lambda a: "newton_euler", newton_euler.derive)
    derivation.Derivation.at = timed(lambda a: a[0].route, derivation.Derivation.at)
    inertia.central_moment = timed(lambda a: "inertia", inertia.central_moment)
    p = problem.load(job["reference"])
    solution = Solution(p)
    solution.expressions
    solution.checks()
    return spent, lambda: bench_anchors.derive_numbers(solution, bench_anchors.sample_point(p))


def _anchor_scene(job: dict):
    """The anchor of a scene: its model, Kane's equations, their solution and its answers."""
    from derive.bench import anchors as bench_anchors
    from derive.language import problem

    anchor = bench_anchors.SCENES[job["scene"]]
    model, answers = anchor.run()
    point = bench_anchors.sample_point(problem.load(anchor.reference()))
    return {}, lambda: bench_anchors.anchor_numbers(model, answers, point)


def _chain_route(job: dict):
    """One route along the n-link pendulum: derive's Lagrange or Newton-Euler route (equations
    formed and solved at the reference configuration at rest), derive's whole solve (both routes,
    every answer, the cross-checks), or the KanesMethod anchor."""
    from derive.bench import anchors as bench_anchors
    from derive.language import problem
    from derive.solution.answers import Solution
    from derive.mechanics import lagrange, newton_euler
    from derive.model.kinematics import Coordinates

    p = problem.load(job["reference"])
    point = bench_anchors.sample_point(p)
    if job["route"] == "anchor":
        model = bench_anchors.pendulum_chain(job["n"])
        model.solve()
        return {}, lambda: bench_anchors.anchor_numbers(model, {}, point)
    if job["route"] == "solve":
        solution = Solution(p)
        solution.expressions
        solution.checks()
        return {}, lambda: bench_anchors.derive_numbers(solution, point)
    route = {"lagrange": lagrange, "newton_euler": newton_euler}[job["route"]]
    coords = Coordinates(p.scene)
    route.derive(p.scene, coords).at(coords.at_rest_in_reference())
    return {}, None


_JOBS = {"derive": _derive_scene, "anchor": _anchor_scene, "chain": _chain_route}


class _Worker:
    """The cold-start worker process (see `_serve`)."""

    def __enter__(self):
        self.process = subprocess.Popen([sys.executable, "-c", "from derive.bench.engines import _serve; _serve()"],
                                        stdin=subprocess.PIPE, stdout=subprocess.PIPE, text=True, bufsize=1)
        return self

    def once(self, job: dict) -> dict:
        import json

        self.process.stdin.write(json.dumps(job) + "\n")
        line = self.process.stdout.readline()
        return json.loads(line) if line else {"error": "the worker stopped"}

    def measure(self, repeats: int, **job) -> dict:
        """The job's figures: its first run, with seconds and peak memory the medians over up to
        `repeats` runs (repeated only while the first run took under REPEAT_BELOW s)."""
        runs = [self.once(job)]
        while len(runs) < repeats and "seconds" in runs[0] and runs[0]["seconds"] < REPEAT_BELOW:
            runs.append(self.once(job))
        timed = [r for r in runs if "seconds" in r]
        result = dict(runs[0], runs=len(timed))
        for key in ("seconds", "peak_mib", "lagrange", "newton_euler", "inertia"):
            if key in result and len(timed) == len(runs):
                result[key] = statistics.median(r[key] for r in timed)
        return result

    def __exit__(self, *exc):
        self.process.stdin.close()
        self.process.wait(timeout=60)


def _failure(result: dict) -> str | None:
    """Why a job has no figure ("over limit", the error), or None."""
    return "over limit" if result.get("over_limit") else result.get("error")


def _compare(ours: dict, theirs: dict) -> list[str]:
    """Where the anchor answers differently from derive (none when either has no numbers)."""
    from derive.bench import anchors as bench_anchors

    if "numbers" not in ours or "numbers" not in theirs:
        return []
    return bench_anchors.disagreements(ours["numbers"], theirs["numbers"])


def _growth(sizes, times) -> float:
    """The exponent k of t ~ n^k, by least squares on log t against log n."""
    return float(np.polyfit(np.log(sizes), np.log(times), 1)[0])


def compare_scenes(worker: _Worker, note, scenes: list[str], repeats: int, limit: float) -> list[dict]:
    """Each scene by derive and by its anchor, one after the other in the same run."""
    from derive.bench import anchors as bench_anchors

    rows = []
    for k, scene in enumerate(scenes, start=1):
        anchor = bench_anchors.SCENES[scene]
        ours = worker.measure(repeats, kind="derive", reference=anchor.reference(), limit=limit)
        theirs = worker.measure(repeats, kind="anchor", scene=scene, limit=limit)
        row = {"scene": scene, "derive": ours, "anchor": theirs, "disagreements": _compare(ours, theirs)}
        row["agrees"] = not row["disagreements"] and not (_failure(ours) or _failure(theirs))
        rows.append(row)
        note(f"  [{k}/{len(scenes)}] {scene}: derive {_cell(ours)} s, anchor {_cell(theirs)} s"
             + ("" if row["agrees"] else "; NOT COMPARED: " + "; ".join(row["disagreements"] or
                                                                        [_failure(ours) or _failure(theirs)])))
    return rows


def chain_growth(worker: _Worker, note, folder: Path, sizes: list[int], repeats: int, limit: float) -> list[dict]:
    """The n-link pendulum by each route; a route over the limit at n is not run at larger n."""
    from derive.bench import anchors as bench_anchors

    rows, over = [], set()
    for n in sizes:
        path = folder / f"pendulum_chain_{n}.yaml"
        path.write_text(bench_anchors.pendulum_chain_file(n))
        row = {"n": n}
        for route in ROUTES:
            row[route] = {"over_limit": True, "skipped": True} if route in over else \
                worker.measure(repeats, kind="chain", route=route, n=n, reference=str(path), limit=limit)
            if row[route].get("over_limit"):
                over.add(route)
        row["disagreements"] = _compare(row["solve"], row["anchor"])
        rows.append(row)
        note(f"  chain n={n}: " + ", ".join(f"{route} {_cell(row[route])} s" for route in ROUTES)
             + ("; DISAGREES: " + "; ".join(row["disagreements"]) if row["disagreements"] else ""))
    return rows


def _cell(result: dict, key: str = "seconds", digits: int = 2) -> str:
    failure = _failure(result)
    return failure if failure else f"{result[key]:.{digits}f}"


def _rich_text(table) -> str:
    """A rich table as plain text (no colour codes), for `say`."""
    import io

    from rich.console import Console

    console = Console(file=io.StringIO(), width=200, color_system=None)
    console.print(table)
    return console.file.getvalue().rstrip()


def scenes_table(rows: list[dict]) -> str:
    """derive against the anchor, scene by scene; a scene whose anchor disagrees has no figures."""
    from rich.table import Table

    table = Table(title="derive against sympy.physics.mechanics, cold, median seconds (peak MiB)")
    for heading in ("scene", "Lagrange", "N-E", "inertia", "derive", "anchor", "derive/anchor", "runs", "agrees"):
        table.add_column(heading, justify="left" if heading == "scene" else "right")
    for row in rows:
        ours, theirs = row["derive"], row["anchor"]
        if not row["agrees"]:
            why = "; ".join(row["disagreements"]) or f"derive: {_failure(ours) or 'ok'}, anchor: {_failure(theirs) or 'ok'}"
            table.add_row(row["scene"], "-", "-", "-", "-", "-", "-", "-", f"NO: {why}")
            continue
        table.add_row(row["scene"], _cell(ours, "lagrange"), _cell(ours, "newton_euler"), _cell(ours, "inertia"),
                      f"{_cell(ours)} ({_cell(ours, 'peak_mib', 1)})", f"{_cell(theirs)} ({_cell(theirs, 'peak_mib', 1)})",
                      f"{ours['seconds'] / theirs['seconds']:.1f}x", f"{ours['runs']}/{theirs['runs']}",
                      f"yes ({len(theirs['numbers'])})")
    return _rich_text(table)


def chain_table(rows: list[dict]) -> str:
    """The n-link pendulum: seconds and peak MiB of each route, and whether derive and the anchor agree."""
    from rich.table import Table

    table = Table(title="The n-link pendulum, rods pinned end to end: median s (peak MiB)")
    table.add_column("n", justify="right")
    for heading in ROUTES.values():
        table.add_column(heading, justify="right")
    table.add_column("agrees", justify="right")
    for row in rows:
        cells = [_cell(row[r]) if _failure(row[r]) else f"{_cell(row[r])} ({_cell(row[r], 'peak_mib', 1)})"
                 for r in ROUTES]
        compared = "numbers" in row["solve"] and "numbers" in row["anchor"]
        agrees = ("NO: " + "; ".join(row["disagreements"])) if row["disagreements"] else "yes" if compared else "-"
        table.add_row(str(row["n"]), *cells, agrees)
    return _rich_text(table)


def _growth_line(rows: list[dict]) -> str | None:
    """t ~ n^k for each route, over the sizes every route finished."""
    done = [r for r in rows if not any(_failure(r[route]) for route in ROUTES)]
    if len(done) < 3:
        return None
    sizes = [r["n"] for r in done]
    return "  growth t ~ n^k: " + ", ".join(f"{heading} k = {_growth(sizes, [r[route]['seconds'] for r in done]):.1f}"
                                            for route, heading in ROUTES.items())


def engines(say, note=None, quick: bool = False, scenes: list[str] | None = None, max_n: int | None = None,
            repeats: int = 3, limit: float | None = None) -> dict:
    """derive against sympy.physics.mechanics (derive.bench.anchors), cold, in the same run:
    each scene by both engines, checked to give the same accelerations, constraint forces and
    answers at a sample point, then the n-link pendulum by each route for n = 1 .. max_n. Prints
    two tables; `note` gets a progress line per job. Returns the figures."""
    import tempfile

    from derive.bench import anchors as bench_anchors

    note = note or say
    scenes = scenes or list(bench_anchors.QUICK if quick else bench_anchors.SCENES)
    max_n = max_n or (3 if quick else 6)
    limit = limit or (60 if quick else 300)
    say(f"\nderive against sympy.physics.mechanics: {len(scenes)} scenes, then the n-link pendulum, n = 1..{max_n}; "
        f"each job a cold child of one worker, the median of up to {repeats} runs, at most {limit:g} CPU s a run.")
    with tempfile.TemporaryDirectory() as folder, _Worker() as worker:
        rows = compare_scenes(worker, note, scenes, repeats, limit)
        chain = chain_growth(worker, note, Path(folder), list(range(1, max_n + 1)), repeats, limit)
    say(scenes_table(rows))
    for row in rows:
        if row["disagreements"]:
            say(f"  {row['scene']}: the anchor answers differently, no timing shown: " + "; ".join(row["disagreements"]))
    agreeing = [r for r in rows if r["agrees"]]
    if agreeing:
        ours, theirs = (sum(r[who]["seconds"] for r in agreeing) for who in ("derive", "anchor"))
        routes = sum(r["derive"][route] for r in agreeing for route in ("lagrange", "newton_euler"))
        say(f"  {len(agreeing)} agreeing scenes: derive {ours:.1f} s, anchor {theirs:.1f} s, {ours / theirs:.1f}x; "
            f"derive's two routes alone (Lagrange + N-E, the issue's target of 1.5x the anchor's one route) "
            f"{routes:.1f} s, {routes / theirs:.1f}x")
    say(chain_table(chain))
    growth = _growth_line(chain)
    if growth:
        say(growth)
    return {"scenes": rows, "chain": chain,
            "settings": {"repeats": repeats, "limit_cpu_seconds": limit, "max_n": max_n, "quick": quick}}


