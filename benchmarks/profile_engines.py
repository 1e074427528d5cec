"""Where derive spends a benchmark scene's cold time: the stack of the main thread sampled every
few milliseconds over what `derive bench` times (the problem read, both routes, the answers and
every cross-check); each sample is charged to the innermost of derive's own functions (a
comprehension to the function it is in) at the line running, with the sympy call below it.

    .venv/bin/python benchmarks/profile_engines.py                      # the slowest scenes
    .venv/bin/python benchmarks/profile_engines.py yo_yo chain:6 --top 8

A scene is an id of derive.bench.anchors.SCENES or "chain:n" for the n-link pendulum. Each runs in
a fresh process (cold). Sampling costs little (unlike cProfile, which slows sympy about 2.5x).
Figures, not a test.
"""
from __future__ import annotations

import argparse
import collections
import json
import os
import subprocess
import sys
import tempfile
import threading
import time
from pathlib import Path

SLOWEST = ["incline_race", "loop_the_loop", "rolling_incline", "chain:6"]
INTERVAL = 0.002  # seconds between samples


def reference(scene: str, folder: str) -> str:
    """The problem file of a scene of derive.bench.anchors.SCENES, or of "chain:n", the n-link pendulum."""
    from derive.bench import anchors as bench_anchors

    if scene.startswith("chain:"):
        n = int(scene.split(":")[1])
        path = Path(folder) / f"pendulum_chain_{n}.yaml"
        path.write_text(bench_anchors.pendulum_chain_file(n))
        return str(path)
    return bench_anchors.SCENES[scene].reference()


def _charge(frame, root: str):
    """(derive function, file:line running, the first call below it outside derive) of a stack."""
    below = None
    while frame is not None:
        code = frame.f_code
        if code.co_filename.startswith(root) and not code.co_name.startswith("<"):
            where = f"{Path(code.co_filename).relative_to(Path(root).parent)}:{frame.f_lineno}"
            return code.co_name, where, below
        if not code.co_filename.startswith(root):
            below = code.co_name
        frame = frame.f_back
    return None


def child(path: str, top: int, seconds: float | None = None) -> dict:
    from derive.language import problem
    from derive.solution.answers import Solution

    root = str(Path(__file__).resolve().parent.parent / "derive")
    main = threading.main_thread().ident
    counts: collections.Counter = collections.Counter()
    functions: collections.Counter = collections.Counter()
    running = True

    def report(total: float) -> dict:
        samples = sum(counts.values()) or 1
        return {"total": total, "samples": samples, "stopped": seconds is not None and total >= seconds,
                "functions": [(f, n / samples) for f, n in functions.most_common(top)],
                "lines": [(*k, n / samples) for k, n in counts.most_common(top)]}

    def sample():
        while running:
            if seconds is not None and time.perf_counter() - start > seconds:  # give up: report so far
                print(json.dumps(report(time.perf_counter() - start)), flush=True)
                os._exit(0)
            frame = sys._current_frames().get(main)
            charged = _charge(frame, root) if frame is not None else None
            if charged:
                counts[charged] += 1
                functions[charged[0]] += 1
            time.sleep(INTERVAL)

    sampler = threading.Thread(target=sample, daemon=True)
    start = time.perf_counter()
    sampler.start()
    solution = Solution(problem.load(path))
    solution.expressions
    solution.checks()
    running = False
    total = time.perf_counter() - start
    sampler.join()
    return report(total)


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("scenes", nargs="*", default=SLOWEST)
    parser.add_argument("--top", type=int, default=5)
    parser.add_argument("--seconds", type=float, default=None, help="stop a scene after this long and show "
                                                                        "where the time went so far")
    parser.add_argument("--child", help=argparse.SUPPRESS)
    args = parser.parse_args()
    if args.child:
        print(json.dumps(child(args.child, args.top, args.seconds)))
        return
    with tempfile.TemporaryDirectory() as folder:
        for scene in args.scenes:
            limit = ["--seconds", str(args.seconds)] if args.seconds else []
            done = subprocess.run([sys.executable, __file__, "--child", reference(scene, folder), "--top",
                                   str(args.top), *limit], capture_output=True, text=True, check=True)
            result = json.loads(done.stdout.splitlines()[-1])
            stopped = " (stopped: still running)" if result["stopped"] else ""
            print(f"{scene}: {result['total']:.1f} s{stopped}, {result['samples']} samples; by derive function:")
            for function, share in result["functions"]:
                print(f"  {share:6.1%}  {function}")
            print("  by line, with the call below it:")
            for function, where, below, share in result["lines"]:
                print(f"  {share:6.1%}  {function:<24} {where:<40} -> {below}")


if __name__ == "__main__":
    main()
