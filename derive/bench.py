"""`derive bench`: the speed-for-accuracy trade, measured and printed (never asserted).

Figures: CLI start-up; derivation per problem, cold and cached; time per answer and the
largest relative error of each evaluation backend against a 50-digit reference, at typical
and extreme parameters; an answer key of 30 problems x 300 variants; the same derivations
with sympy.physics.mechanics alone; a work-precision table of scipy's integrators and a
symplectic one on a large-amplitude pendulum; derive's cold time for both routes with the
cross-check next to sympy.physics.mechanics' KanesMethod on the same scenes (derive.bench_anchors),
and how both grow along chains of n bodies.

>>> lines = []
>>> startup(lines.append, runs=1)
>>> lines[0].startswith("derive --help")
True
"""
from __future__ import annotations

import random
import shutil
import statistics
import subprocess
import sys
import time
from pathlib import Path

import mpmath
import numpy as np
import sympy as sp

from derive import library, numeric, problem, sheet
from derive.answers import Solution


_CRITICAL = mpmath.nstr(mpmath.acos(mpmath.mpf(1) / 3) + mpmath.mpf("1e-10"), 45)

#: Parameters at the edges: mass ratios of 1e-12 and 1e12, angles of 1e-8 rad and pi/2 - 1e-9,
#: eccentricities near 0 and 1, near-cancellations (a beetle whose momentum nearly cancels the
#: lazy Susan's, a spool 1e-10 rad from its critical angle, a ball nearly filling the loop), a
#: collision with mass ratio 1e-14, huge and tiny magnitudes.
EXTREME_CASES = [
    ("string_wrapped_disk", {"m": "1e-12", "M": "1", "R": "0.2"}),
    ("string_wrapped_disk", {"m": "1e12", "M": "1", "R": "0.2"}),
    ("rolling_incline", {"M": "1", "R": "0.1", "H": "1", "theta": "1e-8"}),
    ("rolling_incline", {"M": "1", "R": "0.1", "H": "1", "theta": mpmath.nstr(mpmath.pi / 2 - mpmath.mpf("1e-9"), 45)}),
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


def startup(say, runs: int = 10) -> None:
    script = Path(sys.executable).parent / "derive"
    command = [str(script)] if script.exists() else [sys.executable, "-m", "derive.cli"]
    times = [_timed(lambda: subprocess.run([*command, "--help"], capture_output=True, check=True))[1]
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
    """Parameter values (SI) drawn inside the ranges."""
    p = solution.problem
    return p.values({n: repr(float(q.range[0] + (q.range[1] - q.range[0]) * sp.Rational(rng.random())))
                     for n, q in p.parameters.items() if q.range is not None})


def _cases(pairs) -> list:
    """(expression, values, 50-digit reference) for every numeric answer of (solution, values) pairs."""
    cases = []
    for solution, values in pairs:
        for expression in solution.expressions.values():
            if expression.free_symbols and expression.free_symbols <= set(values):
                exact = expression.xreplace(values)
                reference = mpmath.mpf(str(sp.N(exact, 50))) if exact != 0 else mpmath.mpf(0)
                cases.append((expression, values, reference))
                numeric.evaluator(expression).compile()  # before anything is timed
    return cases


def backends(say, solutions: dict[str, Solution], samples: int) -> None:
    say("\nEvaluation backends, over every numeric answer (15 digits asked):")
    say(f"  {'backend':<8} {'parameters':<10} {'answers':>8} {'us/answer':>10} {'worst relative error':>22}")
    rng = random.Random(6)
    typical = _cases((s, _typical(s, rng)) for s in solutions.values() for _ in range(samples))
    extreme = _cases((Solution(problem.load(p)), problem.load(p).values(o)) for p, o in EXTREME_CASES)
    for kind, cases in (("typical", typical), ("extreme", extreme)):
        for backend in ("float", "mpmath", "auto", "exact"):
            worst, start = mpmath.mpf(0), time.perf_counter()
            for expression, values, reference in cases:
                try:
                    value = mpmath.mpf(numeric.evaluate(expression, values, 15, backend))
                except (ValueError, ZeroDivisionError):
                    value = mpmath.mpf("inf")
                if reference != 0:
                    worst = max(worst, abs(value - reference) / abs(reference))
            elapsed = (time.perf_counter() - start) / max(len(cases), 1)
            say(f"  {backend:<8} {kind:<10} {len(cases):>8} {elapsed * 1e6:>10.1f} {mpmath.nstr(worst, 3):>22}")
    say("  (15 digits are correct when the relative error is below 5e-15)")


def answer_key(say, solutions: dict[str, Solution], variants: int) -> None:
    chosen = [s for s in solutions.values() if all(not e.has(sp.Derivative) for e in s.expressions.values())][:30]
    start = time.perf_counter()
    count = 0
    for solution in chosen:
        draws = [sheet.valid_draw(solution.problem, solution, random.Random(f"bench/{n}")) for n in range(variants)]
        item = sheet._ProblemVariants(solution.problem, solution, draws)
        for draw in item.draws:
            count += sum(v is not None for v in item.answers(draw).values())
    elapsed = time.perf_counter() - start
    say(f"\nAnswer key: {len(chosen)} problems x {variants} variants = {count} values in {elapsed:.2f} s "
        f"({count / elapsed:.0f} values/s, each correct to its digits; target under 10 s for 30 x 300)")


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
    """A 10-problem set with 30 variants: LaTeX only, and with PDFs (pages per second)."""
    import os
    import tempfile

    ids = [p.stem for p in library.problem_files()][:10]
    with tempfile.TemporaryDirectory() as folder:
        sets = Path(folder) / "library"
        shutil.copytree(library.problems_dir(), sets)
        (sets / "sets" / "bench.yaml").write_text(f"title: Bench\nproblems: [{', '.join(ids)}]\nvariants: 30\n")
        previous = os.environ.get("DERIVE_LIBRARY")
        os.environ["DERIVE_LIBRARY"] = str(sets)
        try:
            say("\nA 10-problem set with 30 variants:")
            latex_only = None
            for formats, label in ((set(), "LaTeX, keys"), ({"pdf"}, "with the 3 PDFs")):
                if formats and not with_pdfs:
                    continue
                built, elapsed = _timed(lambda: sheet.build("bench", out_dir=str(Path(folder) / "out"), formats=formats))
                line = f"  {label:<16} {elapsed:6.1f} s"
                if formats:
                    pages = sum(int(subprocess.run(["pdfinfo", str(p)], capture_output=True, text=True).stdout
                                    .split("Pages:")[1].split()[0]) for p in built if p.suffix == ".pdf")
                    step = max(elapsed - latex_only, 1e-3)
                    line += f"  ({pages} pages; the PDF step {step:.1f} s, {pages / step:.0f} pages/s, in parallel)"
                latex_only = elapsed
                say(line)
        finally:
            if previous is None:
                os.environ.pop("DERIVE_LIBRARY")
            else:
                os.environ["DERIVE_LIBRARY"] = previous


# --- derive against sympy.physics.mechanics' KanesMethod, cold (derive.bench_anchors) -----------

#: The worker imports these before it forks: neither engine pays for an import in its figure.
_PRELOAD = ("sympy", "sympy.physics.mechanics", "scipy.integrate", "derive.answers", "derive.problem",
            "derive.simulate", "derive.bench_anchors")
#: CPU seconds one job may take before the worker's child is stopped; and its simulation, after.
JOB_CPU_LIMIT = 900
SIMULATION_CPU_LIMIT = 30
#: A job is run again (a fresh cold child each time) while its runs took under this many seconds
#: in all, at most REPEATS times; its figure is the median.
REPEAT_BELOW = 3.0
REPEATS = 3


def _serve() -> None:
    """The cold-start worker (`python -c "from derive.bench import _serve; _serve()"`): import
    both engines once, then for each job (a JSON line on stdin) fork a child that clears sympy's
    cache, runs the job and sends JSON lines back (a derive job: its figures, then the simulation's
    time in a second line). A child starts with every cache empty (the worker itself derives
    nothing), without paying the 1 to 2 s of a fresh interpreter."""
    import importlib
    import json
    import os

    for name in _PRELOAD:
        importlib.import_module(name)
    for line in sys.stdin:
        read, write = os.pipe()
        pid = os.fork()
        if pid == 0:  # the child: never returns
            os.close(read)
            try:
                _child(json.loads(line), lambda result: os.write(write, (json.dumps(result) + "\n").encode()))
            finally:
                os._exit(0)
        os.close(write)
        with os.fdopen(read) as pipe:
            answers = [json.loads(a) for a in pipe.read().splitlines() if a.strip()]
        _, status = os.waitpid(pid, 0)
        result = answers[0] if answers else {"error": f"stopped (status {status}; over {JOB_CPU_LIMIT} CPU s?)"}
        if result.get("simulate") == "pending":
            result["simulate"] = answers[1]["simulate"] if len(answers) > 1 else \
                f"stopped after {SIMULATION_CPU_LIMIT} CPU s"
        print(json.dumps(result), flush=True)


def _child(job: dict, send) -> None:
    """Run one job in a forked child, with stdout and stderr silenced and a CPU limit."""
    import os
    import resource

    def limit(seconds: float) -> None:
        used = resource.getrusage(resource.RUSAGE_SELF)
        soft = int(used.ru_utime + used.ru_stime + seconds)
        resource.setrlimit(resource.RLIMIT_CPU, (soft, soft + 5))

    devnull = os.open(os.devnull, os.O_WRONLY)
    os.dup2(devnull, 1)
    os.dup2(devnull, 2)
    limit(JOB_CPU_LIMIT)
    from sympy.core.cache import clear_cache

    clear_cache()
    try:
        result, solution = _job(job)
    except BaseException as error:  # noqa: B036 - reported as the job's figure
        send({"error": f"{type(error).__name__}: {str(error).splitlines()[0] if str(error) else ''}"})
        return
    if solution is None or not job.get("simulate", True):
        send(result)
        return
    send({**result, "simulate": "pending"})
    limit(SIMULATION_CPU_LIMIT)
    from derive import simulate

    try:
        report, seconds = _timed(simulate.check, solution)
        send({"simulate": seconds if report.passed else f"check failed ({'; '.join(report.notes)[:60]})"})
    except BaseException as error:  # noqa: B036
        send({"simulate": f"{type(error).__name__}"})


def _job(job: dict) -> tuple[dict, object]:
    """(figures, the derive Solution to simulate or None)."""
    if job["engine"] == "derive":
        return _derive_cold(job["reference"])
    from derive import bench_anchors

    if "chain" in job:
        _, build = bench_anchors.CHAINS[job["chain"]]
        _, seconds = _timed(lambda: build(job["n"]).solve())
    else:
        _, seconds = _timed(bench_anchors.SCENES[job["scene"]].run)
    return {"total": seconds}, None


def _derive_cold(reference: str) -> tuple[dict, object]:
    """What `derive check` runs, timed: the problem read, both routes, every answer and every
    cross-check (the simulation is timed apart, after). The routes' own time (forming each route's
    equations and solving them, at the reference and at the states the checks draw) and the
    inertia integrals are measured by wrapping those functions in this child process."""
    from derive import inertia, problem
    from derive.answers import Solution
    from derive.mechanics import derivation, lagrange, newton_euler
    from derive.scene import DYNAMIC_KINDS

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

    start = time.perf_counter()
    p = problem.load(reference)
    solution = Solution(p)
    solution.expressions
    solution.checks()
    total = time.perf_counter() - start
    result = {**spent, "total": total, "answers_and_checks": total - sum(spent.values())}
    return result, solution if {a.quantity.kind for a in p.asks.values()} & DYNAMIC_KINDS else None


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

    def __call__(self, **job) -> dict:
        """The job's figures: its first run, with each time the median over the runs (see REPEATS)."""
        runs = [self.once(job)]
        while ("error" not in runs[0] and len(runs) < REPEATS
               and sum(r["total"] for r in runs) < REPEAT_BELOW):
            runs.append(self.once({**job, "simulate": False}))
        if len(runs) > 1 and all("error" not in r for r in runs):
            for key, value in runs[0].items():
                if isinstance(value, float) and key != "simulate":
                    runs[0][key] = statistics.median(r[key] for r in runs)
        return runs[0]

    def __exit__(self, *exc):
        self.process.stdin.close()
        self.process.wait(timeout=60)


def _seconds(result: dict, key: str = "total") -> str:
    return "failed" if "error" in result else f"{result[key]:.2f}"


def _growth(sizes: list[int], times: list[float]) -> float:
    """The exponent k of t ~ n^k, by least squares on log t against log n."""
    xs, ys = np.log(sizes), np.log(times)
    return float(np.polyfit(xs, ys, 1)[0])


def engines(say, quick: bool = False, scenes: list[str] | None = None, sizes: list[int] | None = None,
            chains: list[str] | None = None) -> dict:
    """derive's cold time for both routes with the cross-check, scene by scene, next to
    sympy.physics.mechanics' KanesMethod on the same scene (derive.bench_anchors says what the
    anchor computes), and how each grows along chains of n bodies. Each figure is one cold run
    in a fresh child of a worker process. Returns the figures."""
    import tempfile

    from derive import bench_anchors

    scenes = scenes or list(bench_anchors.QUICK if quick else bench_anchors.SCENES)
    sizes = sizes or list(range(1, 5 if quick else 7))
    chains = chains or list(bench_anchors.CHAINS)[:1 if quick else None]
    figures: dict = {"scenes": {}, "chains": {}}
    say("\nderive against sympy.physics.mechanics (KanesMethod), cold, seconds (targets: derive's both routes "
        "with the cross-check within 1.5x the anchor's one route; growth along a chain no steeper; 6 bodies "
        "in seconds):")
    say("  derive: the problem read, Lagrange and Newton-Euler (each: equations formed and solved), the inertia "
        "integrals, the answers and every cross-check (as `derive check`, whose simulation is timed apart).")
    say("  anchor: KanesMethod in minimal coordinates, an auxiliary speed per constraint force derive computes, "
        "accelerations and those forces solved at the reference configuration at rest (plus small oscillations "
        "and loop heights where asked).")
    with tempfile.TemporaryDirectory() as folder, _Worker() as worker:
        say(f"  {'scene':<20} {'Lagrange':>8} {'N-E':>6} {'inertia':>7} {'answers':>7} {'derive':>7} "
            f"{'anchor':>7} {'ratio':>6} {'simulate':>8}")
        met = 0
        for ident in scenes:
            anchor = bench_anchors.SCENES[ident]
            ours = worker(engine="derive", reference=anchor.reference(folder))
            theirs = worker(engine="anchor", scene=ident)
            figures["scenes"][ident] = (ours, theirs)
            if "error" in ours or "error" in theirs:
                say(f"  {ident:<20} derive: {ours.get('error', 'ok')}; anchor: {theirs.get('error', 'ok')}")
                continue
            ratio = ours["total"] / theirs["total"]
            met += ratio <= 1.5
            simulated = ours.get("simulate", "-")
            simulated = f"{simulated:.2f}" if isinstance(simulated, float) else simulated
            say(f"  {ident:<20} {ours['lagrange']:>8.2f} {ours['newton_euler']:>6.2f} {ours['inertia']:>7.2f} "
                f"{ours['answers_and_checks']:>7.2f} {ours['total']:>7.2f} {theirs['total']:>7.2f} {ratio:>6.1f} "
                f"{simulated:>8}")
        timed = [(o["total"], t["total"]) for o, t in figures["scenes"].values() if "error" not in o and "error" not in t]
        if timed:
            ours_total, theirs_total = (sum(x) for x in zip(*timed))
            say(f"  {'all ' + str(len(timed)) + ' scenes':<20} {'':>8} {'':>6} {'':>7} {'':>7} {ours_total:>7.2f} "
                f"{theirs_total:>7.2f} {ours_total / theirs_total:>6.1f}   ({met} of {len(timed)} within 1.5x)")
        for kind in chains:
            write, _ = bench_anchors.CHAINS[kind]
            say(f"\n  A chain of n {kind}, cold seconds:")
            say(f"  {'n':>3} {'derive':>8} {'anchor':>8} {'ratio':>6}")
            rows = []
            for n in sizes:
                path = Path(folder) / f"{kind.replace(' ', '_')}_{n}.yaml"
                path.write_text(write(n))
                ours = worker(engine="derive", reference=str(path))
                theirs = worker(engine="anchor", chain=kind, n=n)
                rows.append((n, ours, theirs))
                ratio = f"{ours['total'] / theirs['total']:>6.1f}" if "error" not in ours and "error" not in theirs \
                    else "     -"
                say(f"  {n:>3} {_seconds(ours):>8} {_seconds(theirs):>8} {ratio}"
                    + "".join(f"   ({who}: {r['error']})" for who, r in (("derive", ours), ("anchor", theirs))
                              if "error" in r))
            figures["chains"][kind] = rows
            good = [(n, o["total"], t["total"]) for n, o, t in rows if "error" not in o and "error" not in t]
            if len(good) >= 3:
                ns, ours_t, theirs_t = zip(*good)
                say(f"  growth t ~ n^k: derive k = {_growth(ns, ours_t):.2f}, anchor k = {_growth(ns, theirs_t):.2f}; "
                    f"t({ns[-1]}) / t({ns[0]}): derive {ours_t[-1] / ours_t[0]:.1f}, anchor "
                    f"{theirs_t[-1] / theirs_t[0]:.1f}")
    return figures


#: The sections of `derive bench`, in order (`--only` runs one).
SECTIONS = ("startup", "derivations", "backends", "answer_key", "sheet", "mechanics_alone", "work_precision", "engines")


def run(say, quick: bool = False, only: str | None = None) -> None:
    def wanted(section: str) -> bool:
        return only is None or only == section

    ids = [p.stem for p in library.problem_files()]
    if wanted("startup"):
        startup(say, runs=3 if quick else 10)
    if only is None or only in ("derivations", "backends", "answer_key"):
        solutions = derivations(say, ids[:8] if quick else ids)
        if wanted("backends"):
            backends(say, solutions, samples=1 if quick else 3)
        if wanted("answer_key"):
            answer_key(say, solutions, variants=30 if quick else 300)
    if wanted("sheet"):
        sheet_build(say, with_pdfs=not quick)
    if only == "mechanics_alone" or only is None and not quick:
        mechanics_alone(say)
    if wanted("work_precision"):
        work_precision(say)
    if wanted("engines"):
        engines(say, quick=quick)
