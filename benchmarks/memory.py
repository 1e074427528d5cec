"""Memory of a set build (LaTeX and keys, no PDF): peak RSS and tracemalloc's peak, by variants.

    .venv/bin/python benchmarks/memory.py                  # demo set, 30 and 300 variants
    .venv/bin/python benchmarks/memory.py --set demo --variants 300 --no-tracemalloc

Each count builds in a fresh process (peak RSS is a process's high-water mark) into a
temporary folder. Figures, not a test.
"""
from __future__ import annotations

import argparse
import json
import subprocess
import sys
import tempfile
import time


def child(problem_set: str, variants: int, trace: bool) -> dict:
    import resource
    import tracemalloc

    from derive.publishing import worksheets

    if trace:
        tracemalloc.start()
    start = time.perf_counter()
    with tempfile.TemporaryDirectory() as folder:
        written = worksheets.build(problem_set, variants=variants, seed=1, out_dir=f"{folder}/out", formats=frozenset())
        sizes = sum(p.stat().st_size for p in written)
    seconds = time.perf_counter() - start
    peak_traced = tracemalloc.get_traced_memory()[1] if trace else None
    rss_kib = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss  # KiB on Linux
    return {"variants": variants, "seconds": round(seconds, 1), "peak_rss_mib": round(rss_kib / 1024, 1),
            "tracemalloc_peak_mib": None if peak_traced is None else round(peak_traced / 2**20, 1),
            "output_mib": round(sizes / 2**20, 2)}


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--set", default="demo")
    parser.add_argument("--variants", type=int, nargs="*", default=[30, 300])
    parser.add_argument("--no-tracemalloc", action="store_true")
    parser.add_argument("--child", type=int, help=argparse.SUPPRESS)
    args = parser.parse_args()
    if args.child is not None:
        print(json.dumps(child(args.set, args.child, not args.no_tracemalloc)))
        return
    print(f"set {args.set}: LaTeX and keys, no PDF")
    print(f"{'variants':>8} {'seconds':>8} {'peak RSS MiB':>13} {'tracemalloc MiB':>16} {'output MiB':>11}")
    for count in args.variants:
        command = [sys.executable, __file__, "--set", args.set, "--child", str(count)]
        if args.no_tracemalloc:
            command.append("--no-tracemalloc")
        done = subprocess.run(command, capture_output=True, text=True, check=True)
        row = json.loads(done.stdout.strip().splitlines()[-1])
        traced = "-" if row["tracemalloc_peak_mib"] is None else row["tracemalloc_peak_mib"]
        print(f"{row['variants']:>8} {row['seconds']:>8} {row['peak_rss_mib']:>13} {traced:>16} {row['output_mib']:>11}")


if __name__ == "__main__":
    main()
