"""`derive bench`: the speed-for-accuracy trade, measured and printed (never asserted).

Figures: CLI start-up; derivation per problem, cold and cached; answers per second, the
largest relative error and the wrong values of each evaluation method (naive evalf, the
previous policy, balls) against a 50-digit reference, at typical and extreme parameters; an
answer key of 30 problems x 300 variants; the marginal answers per second of a whole set
build (300 variants against 1, per CPU second); a 10-problem set of 30 variants with its PDFs,
step by step (derivations, answers and keys, LaTeX, PDF compiles, pandoc); the same derivations
with sympy.physics.mechanics alone; a work-precision table of scipy's integrators and a
symplectic one on a large-amplitude pendulum; derive against sympy.physics.mechanics'
KanesMethod in the same run, cold, on 14 scenes checked to agree at a sample point
(derive.bench.anchors), and the n-link pendulum by each route, time and peak memory.

>>> lines = []
>>> startup(lines.append, runs=1)
>>> lines[0].startswith("derive --help")
True
"""
from __future__ import annotations

import random
import re
import shutil
import statistics
import subprocess
import sys
import time
from decimal import Decimal, localcontext
from pathlib import Path

import mpmath
import numpy as np
import sympy as sp

from derive.language import defaults, problem
from derive.publishing import export, variants, worksheets
from derive.core import library
from derive.numbers import numeric
from derive.solution.answers import Solution
from derive.bench.course import course
from derive.bench.engines import engines
from derive.bench.solution_length import solution_length
from derive.publishing.progress import Reporter


_CRITICAL = mpmath.nstr(mpmath.acos(mpmath.mpf(1) / 3) + mpmath.mpf("1e-10"), 45)

#: Parameters at the edges: mass ratios of 1e-12 and 1e12, angles of 1e-8 rad and pi/2 - 1e-9,
#: eccentricities near 0 and 1, near-cancellations (a beetle whose momentum nearly cancels the
#: lazy Susan's, a spool 1e-10 rad from its critical angle, a ball nearly filling the loop), a
#: collision with mass ratio 1e-14, huge and tiny magnitudes.
EXTREME_CASES = [
    ("string_wrapped_disk", {"m": "1e-12", "M": "1", "R": "0.2"}),
    ("string_wrapped_disk", {"m": "1e12", "M": "1", "R": "0.2"}),
    ("rolling_incline", {"M": "1", "R": "0.1", "H": "1", "theta": "1e-8"}),
    ("rolling_incline", {"M": "1", "R": "0.1", "H": "1", "mu_s": "1e9",
                         "theta": mpmath.nstr(mpmath.pi / 2 - mpmath.mpf("1e-9"), 45)}),
    ("kepler_orbit", {"a": "1.496e11", "e": "0.999999999999"}),
    ("kepler_orbit", {"a": "1.496e11", "e": "1e-12"}),
    ("beetle_lazy_susan", {"m": "0.004", "R": "0.25", "I": "0.001", "omega0": "0.6", "v": "0.6000000000006"}),
    ("tugged_spool", {"F": "5", "M": "1", "R": "0.06", "r": "0.02", "I_cm": "0.001", "theta": _CRITICAL}),
    ("loop_the_loop_ball", {"R": "1", "r": "0.999999999999"}),
    ("sticky_impact_free", {"m": "1e-14", "M": "1", "R": "0.3", "v": "5"}),
    ("rod_endpoint", {"m": "1e30", "L": "1e-15"}),
    ("diatomic_molecule", {"m1": "1.674e-27", "m2": "1e-30", "d": "1e-10"}),
    ("top_precession_exact", {"m": "0.2", "Rcm": "0.05", "I3": "5e-5", "I1": "5e-4", "theta": "1e-8", "omega": "1e6"}),
    ("compound_pendulum_large", {"M": "2", "Rcm": "0.3", "I_cm": "0.05", "theta0": "3.14159"}),
]


def _timed(function, *args):
    start = time.perf_counter()
    result = function(*args)
    return result, time.perf_counter() - start


def _command() -> list[str]:
    """How to run derive's CLI from this interpreter."""
    script = Path(sys.executable).parent / "derive"
    return [str(script)] if script.exists() else [sys.executable, "-m", "derive.cli"]


def startup(say, runs: int = 10) -> None:
    times = [_timed(lambda: subprocess.run([*_command(), "--help"], capture_output=True, check=True))[1]
             for _ in range(runs)]
    say(f"derive --help: median {statistics.median(times):.3f} s over {runs} runs (target 0.3 s)")


def derivations(say, ids: list[str]) -> dict[str, Solution]:
    say("\nDerivation per problem (answers and every cross-check), cold and cached:")
    solutions = {}
    for problem_id in ids:
        p = problem.load(problem_id)
        solution = Solution(p)
        _, cold = _timed(lambda: (solution.expressions, solution.checks()))
        _, warm = _timed(lambda: solution.expressions)
        solutions[problem_id] = solution
        say(f"  {problem_id:<30} cold {cold:6.2f} s   cached {warm * 1e6:6.1f} us")
    return solutions


def _typical(solution: Solution, rng: random.Random) -> dict:
    """A variant's parameter values (SI), drawn as a set's are (variants.valid_draw)."""
    draw = variants.valid_draw(solution.problem, solution, rng)
    return variants.ProblemVariants(solution.problem, solution, [draw]).si_values(draw)


def _groups(pairs) -> list[tuple[tuple, list, list]]:
    """For each (solution, values) pair: its numeric answers, the values, and each answer's
    50-digit reference; pairs of the same solution (its variants) make one group, (answers,
    rows, references per row). Keyed by the solution itself, not its id(): a solution made in
    the pairs' generator and freed can leave its id to the next one, which would merge two
    problems' groups (a clean-clone CI run met it as a row without a symbol's value)."""
    groups: dict[Solution, tuple[tuple, list, list]] = {}
    for solution, values in pairs:
        expressions = tuple(e for e in solution.expressions.values() if e.free_symbols and e.free_symbols <= set(values))
        if not expressions:
            continue
        group = groups.setdefault(solution, (expressions, [], []))
        references = []
        for expression in expressions:
            exact = expression.xreplace(values)
            references.append(Decimal(str(sp.N(exact, 50))) if exact != 0 else Decimal(0))
        group[1].append(values)
        group[2].append(references)
    for expressions, _, _ in groups.values():  # compiled before anything is timed
        numeric.evaluator(expressions).compile()
        for expression in expressions:
            numeric.evaluator((expression,)).compile()
    return list(groups.values())


def _naive(expression, values, digits):
    return str(expression.evalf(digits, subs=values))


def _one_at_a_time(backend: str):
    return lambda expression, values, digits: numeric.evaluate(expression, values, digits, backend)


#: The rows of the evaluation table: naive evalf, the float64 and mpmath backends, the policy
#: before balls (agreement), and balls one answer at a time and over a problem's variants together.
METHODS = {"naive evalf": _naive, **{b: _one_at_a_time(b) for b in ("float", "mpmath", "agreement", "auto")},
           "auto, variants together": None}


def _values(method: str, groups) -> list[list[list[str | None]]]:
    """Each group's texts, [row][answer], by one method (None where it raised)."""
    if METHODS[method] is None:
        return [[[c.text for c in row] for row in numeric.evaluator(expressions).certified(rows, [15] * len(expressions))]
                for expressions, rows, _ in groups]
    texts = []
    for expressions, rows, _ in groups:
        texts.append([])
        for values in rows:
            row = []
            for expression in expressions:
                try:
                    row.append(METHODS[method](expression, values, 15))
                except (ValueError, ZeroDivisionError, TypeError):
                    row.append(None)
            texts[-1].append(row)
    return texts


def _number(text: str | None) -> Decimal | None:
    """A backend's value as a number; None where it gave none ("nan", or text that is no number,
    which a bench counts as a wrong value rather than stopping on).

    >>> _number("1.5e-3"), _number("nan"), _number("zoo")
    (Decimal('0.0015'), None, None)
    """
    try:
        value = Decimal(text) if text is not None else None
    except ArithmeticError:  # decimal.InvalidOperation
        return None
    return value if value is not None and value.is_finite() else None


def _errors(groups, texts) -> tuple[Decimal, int]:
    """The worst relative error against the references, and how many values print a digit
    other than the reference's rounded to 15 digits (a value not given counts as both)."""
    worst, wrong = Decimal(0), 0
    with localcontext() as context:
        context.prec = 60
        for (_, _, references), group in zip(groups, texts):
            for reference_row, row in zip(references, group):
                for reference, text in zip(reference_row, row):
                    value = _number(text)
                    given = value is not None
                    value = Decimal("Infinity") if value is None else value
                    if reference != 0:
                        worst = max(worst, abs(value - reference) / abs(reference))
                    wrong += not given or numeric.round_decimal(value, 15) != numeric.round_decimal(reference, 15)
    return worst, wrong


def backends(say, solutions: dict[str, Solution], samples: int, repeats: int = 3) -> dict:
    """Answers per second (the best of `repeats` runs, and their range) and accuracy of each
    method over every numeric answer of the problems at `samples` typical draws each, and at
    the extreme cases; returns {(method, kind): answers per second}."""
    say("\nEvaluation, over every numeric answer (15 digits asked; answers/s: the best of "
        f"{repeats} runs, and their range; wrong: values with a digit other than the 50-digit reference's):")
    say(f"  {'method':<24} {'parameters':<10} {'answers':>8} {'answers/s':>10} {'range':>15} {'x naive':>8} "
        f"{'worst relative error':>21} {'wrong':>6}")
    typical = _groups((s, _typical(s, random.Random(f"bench/{n}"))) for s in solutions.values()
                      for n in range(samples))
    extreme = _groups((Solution(problem.load(p)), problem.load(p).values(o)) for p, o in EXTREME_CASES)
    rates = {}
    numeric.FALLBACKS.clear()
    for kind, groups in (("typical", typical), ("extreme", extreme)):
        count = sum(len(rows) * len(expressions) for expressions, rows, _ in groups)
        for method in METHODS:
            runs = []
            for _ in range(repeats):
                texts, elapsed = _timed(_values, method, groups)
                runs.append(count / elapsed)
            rates[method, kind] = max(runs)
            worst, wrong = _errors(groups, texts)
            say(f"  {method:<24} {kind:<10} {count:>8} {max(runs):>10.0f} {f'{min(runs):.0f}-{max(runs):.0f}':>15} "
                f"{max(runs) / rates['naive evalf', kind]:>8.1f} {worst:>21.2e} {wrong:>6}")
    say("  (15 digits are correct when the relative error is below 5e-15; auto's fallbacks over every run: "
        f"{dict(numeric.FALLBACKS) or 'none'})")
    return rates


def answer_key(say, solutions: dict[str, Solution], count: int) -> None:
    chosen = [s for s in solutions.values() if all(not e.has(sp.Derivative) for e in s.expressions.values())][:30]
    start = time.perf_counter()
    values = 0
    for solution in chosen:
        draws = [variants.valid_draw(solution.problem, solution, random.Random(f"bench/{n}")) for n in range(count)]
        item = variants.ProblemVariants(solution.problem, solution, draws)
        for draw in item.draws:
            values += sum(v is not None for v in item.answers(draw).values())
    elapsed = time.perf_counter() - start
    say(f"\nAnswer key: {len(chosen)} problems x {count} variants = {values} values in {elapsed:.2f} s "
        f"({values / elapsed:.0f} values/s, each correct to its digits; target under 10 s for 30 x 300)")


#: The set whose build gives the marginal rate (issue 17's): a pulley, a pendulum, rolling, a
#: collision and an orbit.
SET_PROBLEMS = ("string_wrapped_disk", "compound_pendulum", "rolling_incline", "beetle_lazy_susan", "kepler_orbit")
#: The 10-problem set of the sheet section: those and a top, a spool, a loop, a large swing and a
#: collision with a rod, every one with its figure.
SHEET_PROBLEMS = SET_PROBLEMS + ("top_precession_exact", "tugged_spool", "loop_the_loop_ball",
                                 "compound_pendulum_large", "restitution_rod")


class _Clock(Reporter):
    """A silent Reporter that notes when each step of a build begins: (step, wall clock, CPU
    seconds of this process)."""

    def __init__(self):
        super().__init__("none")
        self.steps: list[tuple[str, float, float]] = []

    def __call__(self, message: str) -> None:
        self.steps.append((message, time.time(), time.process_time()))


def _timed_build(job: str) -> None:
    """Run in a fresh process by _build_steps: build the set of `job` (JSON: references,
    variants, formats, out) and print its steps as one JSON line."""
    import json

    options = json.loads(job)
    clock = _Clock()
    worksheets.build(options["references"], variants=options["variants"], out_dir=options["out"],
                     formats=frozenset(options["formats"]), progress=clock)
    clock("end")
    print(json.dumps(clock.steps))


def _build_steps(references, variants: int, formats, out: Path) -> list[tuple[str, float, float]]:
    """A set build in a fresh process (`derive sheet` as a function, its hash seed fixed): each step
    as (name, wall seconds, CPU seconds of the Python process; TeX's and pandoc's own CPU is not
    counted), "start-up" first (the interpreter and the imports), the derivations as one step."""
    import json
    import os

    job = json.dumps({"references": list(references), "variants": variants, "formats": sorted(formats),
                      "out": str(out)})
    began = time.time()
    done = subprocess.run([sys.executable, "-c", f"from derive.bench.runs import _timed_build; _timed_build({job!r})"],
                          capture_output=True, text=True, check=True, env={**os.environ, "PYTHONHASHSEED": "0"})
    events = json.loads(done.stdout.splitlines()[-1])
    steps = [("start-up", events[0][1] - began, events[0][2])]
    for (name, wall, cpu), (_, next_wall, next_cpu) in zip(events, events[1:]):
        name = "derivations" if name.startswith("deriving ") else re.sub(r" \(\d+/\d+\)$", "", name)
        if steps[-1][0] == name:
            steps[-1] = (name, steps[-1][1] + next_wall - wall, steps[-1][2] + next_cpu - cpu)
        else:
            steps.append((name, next_wall - wall, next_cpu - cpu))
    return steps


def _per_variant(steps) -> list[tuple[str, float, float]]:
    """The steps of a build from drawing its variants on (what grows with them), "drawing N
    variants" named "drawing"."""
    first = next(i for i, (name, _, _) in enumerate(steps) if name.startswith("drawing "))
    return [("drawing" if name.startswith("drawing ") else name, wall, cpu) for name, wall, cpu in steps[first:]]


def set_rate(say, variants: int = 300, repeats: int = 3) -> float:
    """The marginal answers per second of a whole set build (`derive sheet SET_PROBLEMS --to ''`):
    its cost per variant (drawing, conditions, answers, keys, the .tex files: every step from the
    draws on; the derivations and the start-up are the same for 1 variant and for 300) with
    `variants` variants against one, each build a fresh process (the two alternated, `repeats`
    times; medians). CPU seconds are the headline (two shared cores make wall time noisy), against
    naive evalf's answers per CPU second on the same answers; returns that marginal rate."""
    import csv
    import tempfile

    say(f"\nA whole set build (derive sheet {' '.join(SET_PROBLEMS)} --to ''), {variants} variants against 1, "
        "from the draws on:")
    costs: dict[int, list[list[tuple[str, float, float]]]] = {1: [], variants: []}
    answers = {}
    with tempfile.TemporaryDirectory() as folder:
        for _ in range(repeats):
            for count in (1, variants):
                out = Path(folder) / f"set-{count}"
                shutil.rmtree(out, ignore_errors=True)
                costs[count].append(_per_variant(_build_steps(SET_PROBLEMS, count, (), out)))
                with open(out / "key.csv", encoding="utf-8") as key:
                    answers[count] = sum(1 for _ in csv.DictReader(key))
    extra = answers[variants] - answers[1]
    wall, cpu = ([statistics.median(sum(step[k] for step in steps) for steps in costs[count]) for count in (1, variants)]
                 for k in (1, 2))
    marginal, marginal_wall = extra / (cpu[1] - cpu[0]), extra / (wall[1] - wall[0])
    solutions = [Solution(problem.load(p)) for p in SET_PROBLEMS]
    naive = _groups((s, _typical(s, random.Random(f"bench/set/{n}"))) for s in solutions for n in range(20))
    count = sum(len(rows) * len(expressions) for expressions, rows, _ in naive)
    naive_rate = 0.0
    for _ in range(repeats):
        started = time.process_time()
        _values("naive evalf", naive)
        naive_rate = max(naive_rate, count / (time.process_time() - started))
    say(f"  1 variant: {answers[1]} answers, median {cpu[0]:.3f} s CPU ({wall[0]:.3f} s wall); {variants} variants: "
        f"{answers[variants]} answers, median {cpu[1]:.3f} s CPU ({wall[1]:.3f} s wall)")
    say(f"  marginal: {marginal:.0f} answers per CPU second ({marginal_wall:.0f} per wall second); naive evalf on "
        f"these answers {naive_rate:.0f} per CPU second: {marginal / naive_rate:.1f}x (target 10x)")
    say(f"  where the marginal CPU time goes, per added answer (target {1e6 / (10 * naive_rate):.1f} us in all):")
    for name in dict.fromkeys(name for name, _, _ in costs[variants][0]):
        spent = [statistics.median(sum(cpu for step, _, cpu in steps if step == name) for steps in costs[count])
                 for count in (1, variants)]
        say(f"    {name:<58} {1e6 * (spent[1] - spent[0]) / extra:6.1f} us")
    floor = _floor(solutions, variants)
    say(f"  the steps every variant takes whatever writes its documents, each timed alone (per answer; "
        f"{1e6 * sum(floor.values()):.1f} us in all):")
    for name, seconds in floor.items():
        say(f"    {name:<58} {1e6 * seconds:6.1f} us")
    return marginal


def _floor(solutions: list[Solution], count: int) -> dict[str, float]:
    """CPU seconds per answer of what each of `count` variants of each problem must do before a
    document is written, timed step by step: its generator seeded from its string (which fixes
    the draws, and so the keys), its values drawn, its conditions tested, its answers evaluated
    in balls and their digits proven (the marginal cost of a set can go no lower)."""
    spent = dict.fromkeys(("seeding each variant's generator", "drawing its values", "testing its conditions",
                           "its answers in balls, digits proven"), 0.0)
    answers = 0
    for solution in solutions:
        found, clock = solution.problem, time.process_time
        started = clock()
        rngs = [random.Random(f"bench/floor/{found.id}/{n}") for n in range(count)]
        seeded = clock()
        draws = [variants.draw(found, rng) for rng in rngs]
        drawn = clock()
        solution.violations([variants.si_values(found, values) for values in draws])
        tested = clock()
        item = variants.ProblemVariants(found, solution, draws)
        numeric.evaluator(tuple(item.in_declared_units.values())).compile()
        compiled = clock()
        item.certified(draws[0])  # every draw's, together
        for name, seconds in zip(spent, (seeded - started, drawn - seeded, tested - drawn, clock() - compiled)):
            spent[name] += seconds
        answers += count * len(found.asks)
    return {name: seconds / answers for name, seconds in spent.items()}


def mechanics_alone(say) -> None:
    """The disk and block, the pendulum and the top by sympy.physics.mechanics' LagrangesMethod."""
    from sympy.physics.mechanics import LagrangesMethod, Lagrangian, Point, ReferenceFrame, RigidBody
    from sympy.physics.mechanics import dynamicsymbols, inertia

    say("\nThe same derivations with sympy.physics.mechanics alone (LagrangesMethod, minimal coordinates):")
    m, M, R, g, d, I1, I3 = sp.symbols("m M R g d I_1 I_3", positive=True)

    def disk():
        th = dynamicsymbols("theta")
        N = ReferenceFrame("N")
        lag = M * R**2 / 4 * th.diff() ** 2 + m * (R * th.diff()) ** 2 / 2 - m * g * R * th
        method = LagrangesMethod(lag, [th])
        method.form_lagranges_equations()
        return sp.simplify(method.rhs()[1]), N

    def pendulum():
        th = dynamicsymbols("theta")
        N = ReferenceFrame("N")
        A = N.orientnew("A", "Axis", [th, N.z])
        O = Point("O")
        O.set_vel(N, 0)
        C = O.locatenew("C", -d * A.y)
        C.v2pt_theory(O, N, A)
        body = RigidBody("b", C, A, M, (inertia(A, 0, 0, I3), C))
        body.potential_energy = M * g * C.pos_from(O).dot(N.y)
        method = LagrangesMethod(Lagrangian(N, body), [th])
        method.form_lagranges_equations()
        return sp.simplify(method.rhs()[1]), N

    def top():
        q = dynamicsymbols("phi theta psi")
        N = ReferenceFrame("N")
        B = N.orientnew("B", "Body", q, "313")
        O = Point("O")
        O.set_vel(N, 0)
        C = O.locatenew("C", d * B.z)
        C.v2pt_theory(O, N, B)
        body = RigidBody("top", C, B, M, (inertia(B, I1, I1, I3), O))
        body.potential_energy = M * g * d * sp.cos(q[1])
        method = LagrangesMethod(Lagrangian(N, body), q)
        method.form_lagranges_equations()
        return method.mass_matrix.shape, N

    for name, build in (("disk and block", disk), ("compound pendulum", pendulum), ("top (Euler angles)", top)):
        _, elapsed = _timed(build)
        say(f"  {name:<22} {elapsed:6.2f} s")


def work_precision(say) -> None:
    """A pendulum at amplitude 2.5 rad over 20 periods: error of the final angle against the
    elliptic-integral period (it returns to the amplitude), and the energy drift."""
    from scipy.integrate import solve_ivp

    w0, amplitude, periods = 1.0, 2.5, 20
    period = float(4 * mpmath.ellipk(mpmath.sin(amplitude / 2) ** 2) / w0)
    end = periods * period

    def energy(y):
        return 0.5 * y[1] ** 2 - w0**2 * np.cos(y[0])

    say(f"\nWork-precision, pendulum at amplitude {amplitude} rad over {periods} periods:")
    say(f"  {'method':<10} {'tolerance':>10} {'angle error':>12} {'energy drift':>13} {'time (ms)':>10}")
    meeting = []  # (time, method, tolerance) of the settings whose angle error is below 1e-6
    for method in ("RK45", "DOP853", "Radau", "LSODA"):
        for tolerance in (1e-4, 1e-7, 1e-10):
            run, elapsed = _timed(lambda: solve_ivp(lambda t, y: [y[1], -w0**2 * np.sin(y[0])], (0, end),
                                                    [amplitude, 0.0], method=method, rtol=tolerance, atol=tolerance * 1e-2))
            error = abs(run.y[0, -1] - amplitude)
            drift = abs(energy(run.y[:, -1]) - energy([amplitude, 0.0]))
            say(f"  {method:<10} {tolerance:>10.0e} {error:>12.2e} {drift:>13.2e} {elapsed * 1e3:>10.1f}")
            if error < 1e-6:
                meeting.append((elapsed, method, tolerance))
    for steps_per_period in (100, 1000):
        h = period / steps_per_period
        start = time.perf_counter()
        theta, omega = amplitude, 0.0
        for _ in range(periods * steps_per_period):  # Stormer-Verlet (leapfrog): symplectic
            omega -= 0.5 * h * w0**2 * np.sin(theta)
            theta += h * omega
            omega -= 0.5 * h * w0**2 * np.sin(theta)
        elapsed = time.perf_counter() - start
        drift = abs(energy([theta, omega]) - energy([amplitude, 0.0]))
        say(f"  {'Verlet':<10} {'h=T/' + str(steps_per_period):>10} {abs(theta - amplitude):>12.2e} {drift:>13.2e}"
            f" {elapsed * 1e3:>10.1f}")
    from derive.checks import simulate

    fastest = min(meeting)
    say(f"  cheapest scipy setting with the angle right to 1e-6: {fastest[1]} at rtol {fastest[2]:.0e} "
        f"({fastest[0] * 1e3:.1f} ms); the simulation check uses {simulate.METHOD} at rtol {simulate.RTOL:.0e}")


def sheet_build(say, with_pdfs: bool) -> None:
    """SHEET_PROBLEMS with 30 variants, as `derive sheet` builds them by default (the PDFs and the
    HTML; LaTeX and the keys only without `with_pdfs`), in a fresh process: where the time goes,
    step by step (the start-up, the derivations, drawing the variants with their answers and
    keys, the .tex files, the PDF compiles, the figures' images, pandoc, writing the files)."""
    import tempfile

    formats = defaults.DEFAULT_OUTPUTS if with_pdfs else frozenset()
    with tempfile.TemporaryDirectory() as folder:
        out = Path(folder) / "out"
        steps = _build_steps(SHEET_PROBLEMS, 30, formats, out)
        total = sum(wall for _, wall, _ in steps)
        outputs = ", ".join(sorted(formats)) or "LaTeX and keys only"
        say(f"\nA 10-problem set with 30 variants ({outputs}): {total:.1f} s wall on {export.workers()} cores "
            "(target 15 s with the PDFs); where the time goes (wall, and CPU of the Python process):")
        for name, wall, cpu in steps:
            say(f"  {name:<58} {wall:6.2f} s  {cpu:6.2f} s CPU")
        if with_pdfs:
            pages = sum(int(subprocess.run(["pdfinfo", str(p)], capture_output=True, text=True).stdout
                            .split("Pages:")[1].split()[0]) for p in out.glob("*.pdf") if p.stem in ("worksheet", "solutions", "key"))
            say(f"  ({pages} pages in the worksheet, the solutions and the key)")


#: The sections of `derive bench`, in order (`--only` runs one).
SECTIONS = ("startup", "derivations", "backends", "answer_key", "set_rate", "sheet", "mechanics_alone", "work_precision",
            "engines", "solution_length", "course")


def run(say, quick: bool = False, only: str | None = None, note=None, variants: int = 30, outputs: str = "",
        **engine_options) -> dict:
    """Every section (or `only` one) in order, printing through `say`; `note` gets progress
    lines (default: `say`). Returns the engines section's figures ({} when it did not run), or
    the course's when only it ran (`variants` and `outputs` are the course's; it runs only when
    asked: a library of 160 problems takes minutes)."""
    if only == "course":
        return course(say, variants=3 if quick else variants, outputs=outputs, limit=8 if quick else None)
    def wanted(section: str) -> bool:
        return only is None or only == section

    ids = [p.stem for p in library.problem_files()]
    if wanted("startup"):
        startup(say, runs=3 if quick else 10)
    if only is None or only in ("derivations", "backends", "answer_key"):
        solutions = derivations(say, ids[:8] if quick else ids)
        if wanted("backends"):
            backends(say, solutions, samples=3 if quick else 20, repeats=1 if quick else 3)
        if wanted("answer_key"):
            answer_key(say, solutions, count=30 if quick else 300)
    if wanted("set_rate"):
        set_rate(say, variants=30 if quick else 300, repeats=1 if quick else 3)
    if wanted("sheet"):
        sheet_build(say, with_pdfs=not quick)
    if only == "mechanics_alone" or only is None and not quick:
        mechanics_alone(say)
    if wanted("work_precision"):
        work_precision(say)
    if only == "solution_length" or only is None and not quick:
        solution_length(say)
    if wanted("engines"):
        return engines(say, note or say, quick=quick, **engine_options)
    return {}
