"""`derive check`: every cross-check over the library, as a table.

For each problem: the independent routes (Lagrange and Newton–Euler, energy, conservation
and impulses, integration and the parallel-axis theorem, ...), the dimensions of every
answer, that no answer is negative where the question states no sign (derive.checks.signs),
and a numerical simulation where the scene moves (of a chain of states, each of its
motion segments from the state the link before produced: derive.checks.chain_simulation).

>>> rows = audit(["rod_endpoint"])
>>> rows[0].passed, rows[0].routes
(True, 'tensor_vs_integral, parallel_axis')
"""
from __future__ import annotations

import time
from dataclasses import dataclass

from derive.checks import chain_simulation, signs, simulate, simulate_solid
from derive.core import library
from derive.language import problem
from derive.solution.answers import Solution
from derive.solution.crosschecks import CheckFailure
from derive.model.scene import DYNAMIC_KINDS
from derive.core.errors import InputError
from derive.publishing.progress import Reporter


@dataclass
class Row:
    id: str
    routes: str
    simulation: str
    dimensions: str
    seconds: float
    passed: bool
    failure: str = ""
    figures: tuple[str, ...] = ()  # what was simulated, each with its relative difference


def audit(references: list[str] | None = None, progress: Reporter = Reporter()) -> list[Row]:
    """Check the given problems (ids or paths), or the whole library."""
    references = references or [str(p) for p in library.problem_files()]
    rows = []
    with progress.task("checking", len(references)) as begin:
        for reference in references:
            rows.append(_audit_one(reference, begin))
    return rows


def _audit_one(reference: str, begin) -> Row:
    """One problem's routes, dimensions and simulation, timed."""
    start = time.perf_counter()
    p = problem.load(reference)
    begin(p.id)
    return row_of(Solution(p), start)


def row_of(solution: Solution, start: float | None = None) -> Row:
    """The row of a problem's solution (derived here, or already: its checks are kept in it), timed
    from `start` (default now)."""
    start = time.perf_counter() if start is None else start
    p = solution.problem
    row = Row(p.id, "-", "-", "-", 0.0, True)
    try:
        solution.expressions
        checks = solution.checks()
        row.dimensions = "ok"
        row.routes = ", ".join(c.name for c in checks if c.name != "dimensions") or "-"
        kinds = {a.quantity.kind for a in p.asks.values()}
        moving = bool(kinds & DYNAMIC_KINDS)
        reports = ([simulate.check(solution)] if moving else []) + (
            [chain_simulation.simulate(solution)] if moving and solution.scene.states else []) + (
            [simulate_solid.check(solution)] if kinds & simulate_solid.KINDS else [])
        if reports:
            passed = all(r.passed for r in reports)
            compared = ", ".join(dict.fromkeys(n for r in reports for n in r.compared))
            row.simulation = ("ok: " + compared if compared else "-") if passed else "FAILED"
            unchecked: dict[str, list[str]] = {}
            for what, why in (u for r in reports for u in r.unchecked):
                unchecked.setdefault(why, []).append(what)
            if unchecked:
                row.simulation += "; not simulated: " + "; ".join(f"{', '.join(w)} ({why})" for why, w in unchecked.items())
            row.figures = tuple(f for r in reports for f in r.figures)
            if not passed:
                row.passed, row.failure = False, "; ".join(n for r in reports for n in r.notes)
        unstated = signs.unstated(solution) + signs.ungiven(solution.problem)
        if unstated:
            row.passed, row.failure = False, "; ".join(filter(None, [row.failure, *unstated]))
    except (CheckFailure, InputError) as error:
        row.passed, row.failure = False, str(error)
    row.seconds = time.perf_counter() - start
    return row


def table(rows: list[Row]) -> str:
    headers = ("problem", "independent routes", "simulation", "dimensions", "time")
    body = [(r.id, r.routes if r.passed or r.routes != "-" else "FAILED", r.simulation, r.dimensions,
             f"{r.seconds:.1f} s") for r in rows]
    widths = [max(len(h), *(len(b[i]) for b in body)) for i, h in enumerate(headers)]
    lines = ["  ".join(h.ljust(w) for h, w in zip(headers, widths)),
             "  ".join("-" * w for w in widths)]
    lines += ["  ".join(c.ljust(w) for c, w in zip(b, widths)) for b in body]
    failed = [r for r in rows if not r.passed]
    figures = [f"  {r.id}: {f}" for r in rows for f in r.figures]
    if figures:
        lines += ["", "simulated in 3D (derive.checks.simulate_solid):", *figures]
    lines.append("")
    lines.append(f"{len(rows) - len(failed)} passed, {len(failed)} failed")
    lines += [f"FAILED {r.id}: {r.failure}" for r in failed]
    return "\n".join(lines)


@dataclass
class Spread:
    """How one answer varies over the seeds: its range, and how often a draw sat on a bound."""

    problem: str
    answer: str
    low: float
    high: float
    on_bound: int
    seeds: int


def stress(references: list[str] | None, seeds: int, progress: Reporter = Reporter()) -> tuple[list[Spread], list[str]]:
    """Draw each problem's parameters with `seeds` seeds: every draw must meet the problem's
    conditions and give a key equal to `derive solve` at those parameters, and a chain of states
    must simulate to its closed forms at it (derive.checks.chain_simulation)."""
    import random

    from derive.publishing import report, variants

    references = references or [str(p) for p in library.problem_files()]
    spreads, failures = [], []
    for reference in references:
        p = problem.load(reference)
        progress(f"stress-testing {p.id} over {seeds} seeds")
        solution = Solution(p)
        values: dict[str, list[float]] = {name: [] for name in p.asks}
        on_bound = 0
        for seed in range(seeds):
            try:
                draw = variants.valid_draw(p, solution, random.Random(f"{seed}/{p.id}/1"))
            except InputError as error:
                failures.append(str(error))
                break
            on_bound += any(q.range is not None and draw[n] in q.range for n, q in p.parameters.items())
            if solution.scene.states:  # the chain simulated at the variant's values, as a sheet gives it
                chain = chain_simulation.simulate(solution, variants.si_values(p, draw))
                failures += [f"{p.id} seed {seed}: chain simulation: {note}" for note in chain.notes]
            item = variants.ProblemVariants(p, solution, [draw])
            key = item.answers(draw)
            given = p.values({n: str(draw[n]) for n, q in p.parameters.items() if q.range is not None})
            full = report.answer_values(solution, given, 15)
            for name, ask in p.asks.items():
                if key[name] is None:
                    continue
                again = report.answer_values(solution, given, ask.sig_figs or 3)[name]
                if again != key[name]:
                    failures.append(f"{p.id} seed {seed}: key {name} = {key[name]}, derive solve gives {again}")
                values[name].append(float(full[name]))
        spreads += [Spread(p.id, name, min(v), max(v), on_bound, seeds) for name, v in values.items() if v]
    return spreads, failures


def spread_table(spreads: list[Spread], failures: list[str]) -> str:
    lines = [f"{'problem':<28} {'answer':<14} {'lowest':>12} {'highest':>12}  draws on a range bound"]
    lines += [f"{s.problem:<28} {s.answer:<14} {s.low:>12.4g} {s.high:>12.4g}  {s.on_bound}/{s.seeds}" for s in spreads]
    lines.append("")
    lines.append(f"{len(failures)} failed" if failures else "every seed: conditions met, key equal to derive solve")
    lines += [f"FAILED {f}" for f in failures]
    return "\n".join(lines)
