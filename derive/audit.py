"""`derive check`: every cross-check over the library, as a table.

For each problem: the independent routes (Lagrange and Newton–Euler, energy, conservation
and impulses, integration and the parallel-axis theorem, ...), the dimensions of every
answer, and a numerical simulation where the scene moves.

>>> rows = audit(["rod_endpoint"])
>>> rows[0].passed, rows[0].routes
(True, 'parallel_axis')
"""
from __future__ import annotations

import time
from dataclasses import dataclass

from derive import library, problem, simulate
from derive.answers import Solution
from derive.crosschecks import CheckFailure
from derive.scene import DYNAMIC_KINDS
from derive.errors import InputError


@dataclass
class Row:
    id: str
    routes: str
    simulation: str
    dimensions: str
    seconds: float
    passed: bool
    failure: str = ""


def audit(references: list[str] | None = None, progress=lambda message: None) -> list[Row]:
    """Check the given problems (ids or paths), or the whole library."""
    references = references or [str(p) for p in library.problem_files()]
    rows = []
    for reference in references:
        start = time.perf_counter()
        p = problem.load(reference)
        progress(f"checking {p.id}")
        row = Row(p.id, "-", "-", "-", 0.0, True)
        try:
            solution = Solution(p)
            solution.expressions
            checks = solution.checks()
            row.dimensions = "ok"
            row.routes = ", ".join(c.name for c in checks if c.name != "dimensions") or "-"
            if {a.quantity.kind for a in p.asks.values()} & DYNAMIC_KINDS:
                report = simulate.check(solution)
                row.simulation = ("ok: " + ", ".join(report.compared)) if report.passed else "FAILED"
                if not report.passed:
                    row.passed, row.failure = False, "; ".join(report.notes)
        except (CheckFailure, InputError) as error:
            row.passed, row.failure = False, str(error)
        row.seconds = time.perf_counter() - start
        rows.append(row)
    return rows


def table(rows: list[Row]) -> str:
    headers = ("problem", "independent routes", "simulation", "dimensions", "time")
    body = [(r.id, r.routes if r.passed or r.routes != "-" else "FAILED", r.simulation, r.dimensions,
             f"{r.seconds:.1f} s") for r in rows]
    widths = [max(len(h), *(len(b[i]) for b in body)) for i, h in enumerate(headers)]
    lines = ["  ".join(h.ljust(w) for h, w in zip(headers, widths)),
             "  ".join("-" * w for w in widths)]
    lines += ["  ".join(c.ljust(w) for c, w in zip(b, widths)) for b in body]
    failed = [r for r in rows if not r.passed]
    lines.append("")
    lines.append(f"{len(rows) - len(failed)} passed, {len(failed)} failed")
    lines += [f"FAILED {r.id}: {r.failure}" for r in failed]
    return "\n".join(lines)
