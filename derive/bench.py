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
(derive.bench_anchors), and the n-link pendulum by each route, time and peak memory.

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

from derive import export, library, numeric, problem, problem_sets, variants, worksheets
from derive.answers import Solution
from derive.progress import Reporter


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
    rows, references per row)."""
    groups: dict[int, tuple[tuple, list, list]] = {}
    for solution, values in pairs:
        expressions = tuple(e for e in solution.expressions.values() if e.free_symbols and e.free_symbols <= set(values))
        if not expressions:
            continue
        group = groups.setdefault(id(solution), (expressions, [], []))
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


def _errors(groups, texts) -> tuple[Decimal, int]:
    """The worst relative error against the references, and how many values print a digit
    other than the reference's rounded to 15 digits (a value not given counts as both)."""
    worst, wrong = Decimal(0), 0
    with localcontext() as context:
        context.prec = 60
        for (_, _, references), group in zip(groups, texts):
            for reference_row, row in zip(references, group):
                for reference, text in zip(reference_row, row):
                    given = text not in (None, "nan")
                    value = Decimal(text) if given else Decimal("Infinity")
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
    done = subprocess.run([sys.executable, "-c", f"from derive.bench import _timed_build; _timed_build({job!r})"],
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


def _per_variant(steps) -> tuple[float, float]:
    """Wall and CPU seconds of a build from drawing its variants on (what grows with them)."""
    first = next(i for i, (name, _, _) in enumerate(steps) if name.startswith("drawing "))
    return sum(wall for _, wall, _ in steps[first:]), sum(cpu for _, _, cpu in steps[first:])


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
    costs: dict[int, list[tuple[float, float]]] = {1: [], variants: []}
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
    wall, cpu = ([statistics.median(c[k] for c in costs[count]) for count in (1, variants)] for k in (0, 1))
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
    return marginal


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
    from derive import simulate

    fastest = min(meeting)
    say(f"  cheapest scipy setting with the angle right to 1e-6: {fastest[1]} at rtol {fastest[2]:.0e} "
        f"({fastest[0] * 1e3:.1f} ms); the simulation check uses {simulate.METHOD} at rtol {simulate.RTOL:.0e}")


def sheet_build(say, with_pdfs: bool) -> None:
    """SHEET_PROBLEMS with 30 variants, as `derive sheet` builds them by default (the PDFs and the
    HTML; LaTeX and the keys only without `with_pdfs`), in a fresh process: where the time goes,
    step by step (the start-up, the derivations, drawing the variants with their answers and
    keys, the .tex files, the PDF compiles, the figures' images, pandoc, writing the files)."""
    import tempfile

    formats = problem_sets.DEFAULT_OUTPUTS if with_pdfs else frozenset()
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


# --- derive against sympy.physics.mechanics, cold, in the same run (derive.bench_anchors) -------

#: The worker imports these before it forks: neither engine pays for an import in its figure.
_PRELOAD = ("sympy", "sympy.physics.mechanics", "derive.answers", "derive.problem", "derive.bench_anchors",
            "derive.mechanics.lagrange", "derive.mechanics.newton_euler")
#: The routes of the chain study, in the table's order, with their headings.
ROUTES = {"lagrange": "derive Lagrange", "newton_euler": "derive Newton-Euler", "solve": "derive solve",
          "anchor": "anchor (Kane)"}
#: A job is run again (a fresh cold child each time), up to `repeats` times, while its first run
#: took less than this many seconds; its figures are the medians.
REPEAT_BELOW = 20.0


def _serve() -> None:
    """The cold-start worker (`python -c "from derive.bench import _serve; _serve()"`): import
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

    from derive import limits

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
    from derive import bench_anchors, inertia, problem
    from derive.answers import Solution
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
    from derive import bench_anchors, problem

    anchor = bench_anchors.SCENES[job["scene"]]
    model, answers = anchor.run()
    point = bench_anchors.sample_point(problem.load(anchor.reference()))
    return {}, lambda: bench_anchors.anchor_numbers(model, answers, point)


def _chain_route(job: dict):
    """One route along the n-link pendulum: derive's Lagrange or Newton-Euler route (equations
    formed and solved at the reference configuration at rest), derive's whole solve (both routes,
    every answer, the cross-checks), or the KanesMethod anchor."""
    from derive import bench_anchors, problem
    from derive.answers import Solution
    from derive.mechanics import lagrange, newton_euler
    from derive.mechanics.kinematics import Coordinates

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
        self.process = subprocess.Popen([sys.executable, "-c", "from derive.bench import _serve; _serve()"],
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
    from derive import bench_anchors

    if "numbers" not in ours or "numbers" not in theirs:
        return []
    return bench_anchors.disagreements(ours["numbers"], theirs["numbers"])


def _growth(sizes, times) -> float:
    """The exponent k of t ~ n^k, by least squares on log t against log n."""
    return float(np.polyfit(np.log(sizes), np.log(times), 1)[0])


def compare_scenes(worker: _Worker, note, scenes: list[str], repeats: int, limit: float) -> list[dict]:
    """Each scene by derive and by its anchor, one after the other in the same run."""
    from derive import bench_anchors

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
    from derive import bench_anchors

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
    """derive against sympy.physics.mechanics (derive.bench_anchors), cold, in the same run:
    each scene by both engines, checked to give the same accelerations, constraint forces and
    answers at a sample point, then the n-link pendulum by each route for n = 1 .. max_n. Prints
    two tables; `note` gets a progress line per job. Returns the figures."""
    import tempfile

    from derive import bench_anchors

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


#: The sections of `derive bench`, in order (`--only` runs one).
SECTIONS = ("startup", "derivations", "backends", "answer_key", "set_rate", "sheet", "mechanics_alone", "work_precision",
            "engines")


def run(say, quick: bool = False, only: str | None = None, note=None, **engine_options) -> dict:
    """Every section (or `only` one) in order, printing through `say`; `note` gets progress
    lines (default: `say`). Returns the engines section's figures ({} when it did not run)."""
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
    if wanted("engines"):
        return engines(say, note or say, quick=quick, **engine_options)
    return {}
