"""CPU seconds of `derive solve` per problem, for this tree and optionally an older one, side by side,
with whether the two print the same (every answer, step and check). Figures, not assertions.

    .venv/bin/python benchmarks/solve_cpu.py --every 8 tests/textbook/ball_chute_into_loop_released.yaml
    git worktree add /tmp/old eef5dcc
    .venv/bin/python benchmarks/solve_cpu.py --old /tmp/old --every 8 --limit 20 FILE...

Each run is a fresh child process (imports included, about 2 s), with no time limit and an empty
derivation cache; with --old the two trees run one after the other for each problem, so that both
see the same load on the machine. CPU time (user + system of the child), not wall time: the machine
is shared.
"""
from __future__ import annotations

import argparse
import os
import resource
import subprocess
import sys
import tempfile
from pathlib import Path

HERE = Path(__file__).resolve().parent.parent


def run(tree: Path, problem: str) -> tuple[float, str, int]:
    """CPU seconds, stdout and exit status of `derive solve problem` with `tree` first on the path."""
    env = {**os.environ, "PYTHONPATH": str(tree), "DERIVE_TIME_LIMIT": "0",
           "DERIVE_CACHE_DIR": tempfile.mkdtemp(prefix="solve-cpu-"), "PYTHONHASHSEED": "0"}
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    done = subprocess.run([sys.executable, "-m", "derive", "solve", problem], capture_output=True, text=True,
                          env=env, cwd=tree)
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
    return cpu, done.stdout, done.returncode


def library(every: int, limit: int | None) -> list[str]:
    """Every `every`-th problem id of `derive list`, at most `limit`."""
    listed = subprocess.run([sys.executable, "-m", "derive", "list"], capture_output=True, text=True, check=True,
                            env={**os.environ, "PYTHONPATH": str(HERE)}, cwd=HERE).stdout
    ids = [line.split()[0] for line in listed.splitlines() if line.strip()]
    return ids[::every][:limit]


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("files", nargs="*", help="problem ids or files (relative to this tree)")
    parser.add_argument("--old", type=Path, help="an older source tree to compare with (a git worktree)")
    parser.add_argument("--every", type=int, help="also every N-th problem of `derive list`")
    parser.add_argument("--limit", type=int, help="at most this many of those")
    args = parser.parse_args()
    problems = [str((HERE / f).resolve()) if (HERE / f).exists() else f for f in args.files]
    problems += library(args.every, args.limit) if args.every else []
    print(f"{'problem':<42} {'old s':>7} {'new s':>7} {'new/old':>7}  same output")
    totals = [0.0, 0.0]
    for problem in problems:
        new, new_out, new_status = run(HERE, problem)
        name = Path(problem).stem
        if args.old is None:
            print(f"{name:<42} {'':>7} {new:7.2f}" + ("" if new_status == 0 else f"  (exit {new_status})"), flush=True)
            totals[1] += new
            continue
        old, old_out, old_status = run(args.old, problem)
        totals[0] += old
        totals[1] += new
        same = "yes" if (old_out, old_status) == (new_out, new_status) else "NO"
        print(f"{name:<42} {old:7.2f} {new:7.2f} {new / old:7.2f}  {same}", flush=True)
    print(f"{'total':<42} {totals[0]:7.2f} {totals[1]:7.2f}" +
          (f" {totals[1] / totals[0]:7.2f}" if totals[0] else ""))


if __name__ == "__main__":
    main()
