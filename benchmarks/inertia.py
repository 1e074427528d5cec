"""Print figures for derive.model.inertia: cold and warm (cached) time per (shape, axis) and per
tensor, and a 300-variant loop of one custom-density shape. Figures, not assertions.

Run: .venv/bin/python benchmarks/inertia.py
"""
import random
import time

import sympy as sp

from derive.model import inertia
from derive.numbers import numeric
from derive.model.inertia import R, r


def timed(call) -> float:
    start = time.perf_counter()
    call()
    return time.perf_counter() - start


def row(shape: str, what: str, call) -> float:
    """Print the first (integrating) and the second (cached) time of a call; return the first."""
    cold, warm = timed(call), timed(call)
    print(f"{shape:<22} {what:<10} {cold:7.3f}s {warm * 1e6:7.1f}us")
    return cold


def main() -> None:
    print(f"{'shape':<22} {'axis':<10} {'cold':>8} {'warm':>9}")
    total = 0.0
    for name, shape in inertia.SHAPES.items():
        for axis in shape.axes:
            total += row(name, axis, lambda: inertia.moment_of_inertia(name, axis))
        total += row(name, "tensor", lambda: inertia.tensor(name))
    print(f"{'all shapes, cold':<33} {total:7.2f}s")

    k, rho0 = sp.symbols("k rho0", positive=True)
    density = rho0 * (r / R)**k
    cold = timed(lambda: inertia.moment_of_inertia("disk", "symmetry", density=density))
    rng = random.Random(7)
    start = time.perf_counter()
    for _ in range(300):
        result = inertia.moment_of_inertia("disk", "symmetry", density=density)
        values = {rho0: sp.Rational(rng.randint(100, 900), 100), k: sp.Rational(rng.randint(0, 40), 10),
                  R: sp.Rational(rng.randint(5, 50), 100)}
        numeric.evaluate(result.I, values, 15)
    loop = time.perf_counter() - start
    print(f"disk, density rho0*(r/R)**k: first integration {cold:.3f}s; 300 variants (cached I, "
          f"15-digit value each) {loop:.3f}s = {loop / 300 * 1e3:.2f} ms/variant")


if __name__ == "__main__":
    main()
