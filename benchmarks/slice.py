"""Print figures for the foundation slice: CLI start-up, derivation per problem (cold and
cached), and answers per second over sampled variants. Figures, not assertions.

Run: .venv/bin/python benchmarks/slice.py
"""
import random
import statistics
import subprocess
import sys
import time
from pathlib import Path

DERIVE = Path(sys.executable).parent / "derive"


def startup(runs: int = 10) -> float:
    times = []
    for _ in range(runs):
        start = time.perf_counter()
        subprocess.run([str(DERIVE), "--help"], capture_output=True, check=True)
        times.append(time.perf_counter() - start)
    return statistics.median(times)


def main() -> None:
    print(f"derive --help: median {startup():.3f} s over 10 runs")
    from derive.language import problem
    from derive.publishing import variants
    from derive.solution.answers import Solution

    for problem_id in ("rod_endpoint", "string_wrapped_disk", "compound_pendulum"):
        p = problem.load(problem_id)
        start = time.perf_counter()
        solution = Solution(p)
        solution.expressions
        solution.checks()
        cold = time.perf_counter() - start
        start = time.perf_counter()
        solution.expressions
        warm = time.perf_counter() - start
        item = variants.ProblemVariants(p, solution, [variants.draw(p, random.Random(n)) for n in range(300)])
        start = time.perf_counter()
        for values in item.draws:
            item.answers(values)
        per_second = 300 * len(p.asks) / (time.perf_counter() - start)
        print(f"{problem_id:<22} derive+check cold {cold:6.2f} s, cached {warm * 1e6:6.1f} us; "
              f"{per_second:8.0f} answers/s (exact evaluation, sig figs)")


if __name__ == "__main__":
    main()
