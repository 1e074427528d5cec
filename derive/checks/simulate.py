"""Numerical simulation of a scene's equations of motion, to check the closed forms.

The solved accelerations (Lagrange's route) are integrated with scipy (METHOD) from a random
state the constraints allow, at the middle of the parameter ranges. The trajectory must keep
every constraint gap at zero, obey the work-energy theorem (T + V changes by the work of the
applied pulls, the ideal constraints doing none), and agree with the asked answers: a
constant acceleration with the change of velocity over the run, a period with the time
between zero crossings.

>>> from derive.language.problem import load
>>> from derive.solution.answers import Solution
>>> report = check(Solution(load("string_wrapped_disk")))
>>> report.passed, report.compared
(True, ['a', 'alpha'])
"""
from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np
import sympy as sp
from scipy.integrate import solve_ivp
from scipy.linalg import eigh

from derive.solution.answers import Solution
from derive.solution.crosschecks import sample_points
from derive.model.kinematics import solve_gaps
from derive.mechanics.lagrange import energies, nonconservative_power

TOLERANCE = 1e-7
#: The integrator: the cheapest setting of `derive bench`'s work-precision table that keeps the
#: error below 1e-6 (LSODA at rtol 1e-10, against DOP853 at 1e-10 for twice the time).
METHOD, RTOL = "LSODA", 1e-10
#: Evaluations of a scene's rates after which a run is given up (`Stalled`): an integrator that
#: chatters where a force jumps takes ever shorter steps, and a check must never run away (a
#: slipping clutch's run, started with its plates' slip about to change sign, took 17 GB).
MAX_EVALUATIONS = 200_000


class Stalled(RuntimeError):
    """A run took more than MAX_EVALUATIONS evaluations of its rates."""


class LeftTheScene(Stalled):
    """A run's step reached states where the scene's equations no longer hold: their matrix singular
    or their numbers not finite (a block run into its pulley, where the cord's geometry takes the
    root of a negative number), before an event (`ends`) could stop it."""


@dataclass
class SimulationReport:
    passed: bool = True
    compared: list[str] = field(default_factory=list)
    notes: list[str] = field(default_factory=list)
    figures: list[str] = field(default_factory=list)  # what was simulated, each with its relative difference
    #: (what, why) the simulation does not reach: said by name, never silently skipped
    unchecked: list[tuple[str, str]] = field(default_factory=list)

    def fail(self, message: str) -> None:
        self.passed = False
        self.notes.append(message)


def _values(solution: Solution) -> dict[sp.Symbol, sp.Expr]:
    """Parameter values (SI) at the middle of their ranges, open sizes at sample values."""
    symbols = set()
    for d in solution.derivations.values():
        for e in [*d.balances, *d.rates]:
            symbols |= e.free_symbols
    for expr in (*solution.expressions.values(), *solution.regime_conditions()):  # mu_s: the regime simulated
        symbols |= expr.free_symbols
    symbols -= solution.coordinates.state | set(solution.derivations["lagrange"].unknowns)
    point = sample_points(solution.problem, sp.Add(*symbols), count=1)[0] if symbols else {}
    return point


def rates(scene, lagrange, coords, values):
    """d/dt of (q, u, W) in `scene`: velocities, the accelerations of its Lagrange derivation
    `lagrange` and the power of the non-conservative forces, at the parameter `values`."""
    state = [c.q for c in coords.all] + [c.u for c in coords.all]
    solve = lagrange.numeric(values)
    power = sp.lambdify(state + lagrange.unknowns,
                        nonconservative_power(scene, coords).xreplace(values), "numpy")
    n = len(coords.all)
    evaluations = [0]

    def rhs(t, y):
        evaluations[0] += 1
        if evaluations[0] > MAX_EVALUATIONS:
            raise Stalled(f"the integrator stalled (over {MAX_EVALUATIONS} steps' evaluations): a force jumps on "
                          "the way")
        try:
            with np.errstate(invalid="ignore", divide="ignore", over="ignore"):  # not finite: LeftTheScene, below
                unknowns = solve(y[:2 * n])
        except np.linalg.LinAlgError:
            unknowns = None
        if unknowns is None or not np.all(np.isfinite(unknowns)):
            raise LeftTheScene("the integrator stepped to where the scene's equations no longer hold (a body run "
                               "into a pulley or a cord's end)")
        return np.concatenate([y[n:2 * n], unknowns[:n], [power(*y[:2 * n], *unknowns)]])
    return rhs, state


def switches(scene, coords, values, start) -> list:
    """Terminal events of solve_ivp where a force of `scene` jumps: the slip of each kinetic
    friction (and of a slipping clutch) changing sign, sign(slip) in the power of the
    non-conservative forces. Past that point the force is another, so a run stops there. A slip
    that is zero at the start (released from rest) has no event: it leaves zero the way the
    other forces push it."""
    state = [c.q for c in coords.all] + [c.u for c in coords.all]
    velocities = {c.u for c in coords.all}
    power = nonconservative_power(scene, coords).xreplace(values)
    events = []
    for slip in {f.args[0] for f in power.atoms(sp.sign, sp.Abs) if f.args[0].free_symbols & velocities}:
        function = sp.lambdify(state, slip, "numpy")
        at_start = float(function(*start[:len(state)]))
        if at_start == 0:
            continue

        def event(t, y, function=function):
            return function(*y[:len(state)])
        event.terminal, event.direction = True, -np.sign(at_start)
        events.append(event)
    return events


def ends(scene, coords, values, start) -> list:
    """Terminal events of solve_ivp where an extent of a part shrinks to nearly nothing, a hundredth
    of what it was at the start (a cord's run whose ends meet, a block reaching its pulley): past
    it the scene is another, and where it ends its equations take roots of negative numbers (the
    steps would reach them before an event at zero could be found). Each event's `meaning` says
    which."""
    state = [c.q for c in coords.all]
    events = []
    for part in (*scene.constraints, *scene.loads):
        for extent, meaning in part.extents(coords):
            function = sp.lambdify(state, extent.xreplace(values), "numpy")
            initial = float(function(*start[:len(state)]))
            if not initial > 0:
                continue

            def event(t, y, function=function, least=initial / 100):
                with np.errstate(invalid="ignore"):  # past the end: nan, and the run stops at the step before
                    return function(*y[:len(state)]) - least
            event.terminal, event.direction, event.meaning = True, -1, meaning
            events.append(event)
    return events


def _stopped(run, events) -> str:
    """Why a run that an event stopped stopped: the event's meaning, or a slip's switch."""
    fired = next(event for event, times in zip(events, run.t_events) if len(times))
    return getattr(fired, "meaning", "a kinetic friction's slip changes sign there, where its force jumps")


def hold(report: SimulationReport, scene, lagrange, coords, values, start, duration: float, where: str = ""):
    """Integrate `scene` (its Lagrange derivation `lagrange`) for `duration` from `start` (every
    coordinate and velocity, then the work done so far): every constraint gap keeps its value at
    the start (zero where the scene is placed on them) and T + V changes by the work of the
    non-conservative forces, up to where a kinetic friction's slip changes sign (`switches`: the
    run stops there, and says so). Failures go to `report`, `where` ahead of them; the run is
    returned (None where the integration failed or stalled: `report.unchecked` says why)."""
    rhs, state = rates(scene, lagrange, coords, values)
    n = len(coords.all)
    gaps = [g.xreplace(values) for c in scene.constraints for g in c.gaps(coords)]
    gap_function = sp.lambdify(state[:n], gaps or [0], "numpy")
    kinetic, potential = energies(scene, coords)
    energy = sp.lambdify(state, (kinetic + potential).xreplace(values), "numpy")
    events = switches(scene, coords, values, start) + ends(scene, coords, values, start)
    try:
        run = solve_ivp(rhs, (0, duration), start, method=METHOD, rtol=RTOL, atol=RTOL * 1e-2, dense_output=True,
                        events=events or None)
    except Stalled as stalled:
        report.unchecked.append((f"{where}the motion from a random start", str(stalled)))
        return None
    if not run.success:
        report.fail(f"{where}integration failed: {run.message}")
        return None
    if run.status == 1:
        report.unchecked.append((f"{where}the motion from a random start after {run.t[-1]:.3g} s", _stopped(run, events)))
    at_start = np.asarray(gap_function(*run.y[:n, 0]), dtype=float)
    drift = max(float(np.max(np.abs(np.asarray(gap_function(*run.y[:n, i]), dtype=float) - at_start)))
                for i in range(run.y.shape[1]))
    scale = 1 + float(np.max(np.abs(run.y[:n])))
    if drift > TOLERANCE * scale:
        report.fail(f"{where}constraints drift by {drift:.2e}")
    # The work-energy theorem: T + V changes by the work of the non-conservative forces (the constraints do none).
    change = [energy(*run.y[:2 * n, i]) - energy(*run.y[:2 * n, 0]) - run.y[2 * n, i] + run.y[2 * n, 0]
              for i in range(run.y.shape[1])]
    size = 1 + max(abs(energy(*run.y[:2 * n, i])) for i in range(run.y.shape[1]))
    if max(abs(c) for c in change) > TOLERANCE * size:
        report.fail(f"{where}the work-energy theorem fails by {max(abs(c) for c in change):.2e}")
    return run


def check(solution: Solution, duration: float = 1.0) -> SimulationReport:
    """Integrate the scene and compare the trajectory with the answers it can test."""
    report = SimulationReport()
    coords = solution.coordinates
    values = _values(solution)
    regime = solution.regime_index(values)  # the friction regime at these values: the one simulated
    scene = solution.regimes[regime].scene
    lagrange = solution._regime_derivations(regime)["lagrange"]
    rhs, _ = rates(scene, lagrange, coords, values)
    n = len(coords.all)
    # The reference configuration (every gap vanishes there), moving with random velocities the
    # constraints allow; the last entry accumulates the work of the non-conservative forces.
    admissible = solution._states_on_constraints(count=1, scene=scene)[0]
    start = np.array([0.0] * n + [float(sp.N(admissible[c.u].xreplace(values))) / 4 for c in coords.all] + [0.0])
    if hold(report, scene, lagrange, coords, values, start, duration) is None:
        return report
    # Released from rest in the reference configuration, where the answers are read: the mean
    # acceleration over the run when it stays constant, else its value at release: Richardson's
    # extrapolation, twice, of the mean over the first millisecond, its half and its quarter. The mean
    # over [0, h] is a + c1 h + c2 h^2 + ...; from rest c1 is often zero and c2 not (the acceleration
    # changes with the angle, which grows as t^2), which one extrapolation left at 1e-6 of a trapdoor's.
    released = _released(rhs, duration, n, ends(scene, coords, values, np.zeros(2 * n + 1)))
    if isinstance(released, Stalled):
        report.unchecked.append(("the motion released from rest", str(released)))
        return report
    lasted = float(released.t[-1])  # to the end, or to where a cord's run shrank to nothing

    def mean_acceleration(body: str, kind: str) -> float:
        index = n + coords.all.index(coords.of(body, kind))
        mean = released.y[index, -1] / lasted
        at_release, at_end = (rhs(t, released.sol(t))[index] for t in (0.0, lasted))
        if abs(at_end - at_release) <= TOLERANCE * (abs(at_release) + 1):
            return mean
        def mean_over(h: float) -> float:
            return released.sol(h)[index] / h

        def once(h: float) -> float:  # c1 gone
            return 2 * mean_over(h / 2) - mean_over(h)

        short = 1e-3 * lasted
        return (4 * once(short / 2) - once(short)) / 3  # c2 gone

    for name, ask in solution.problem.asks.items():
        q = ask.quantity
        if ask.zero_for or ask.magnitude or ask.small:
            continue  # a transformed quantity (a critical value, a magnitude, a limit)
        if ask.state is not None:
            continue  # read in a state, not at release: derive.checks.chain_simulation's, from the simulated state
        if q.kind in ("acceleration", "angular_acceleration"):
            simulated = mean_acceleration(q.target, q.detail if q.kind == "acceleration" else "theta")
            compare(report, name, simulated, solution.signed(name), values)
        elif q.kind == "contact" and q.detail == "acceleration.down_incline":
            down = solution.scene.surfaces[solution.scene.contact_of(q.target).surface].down.xreplace(values)
            simulated = float(down[0]) * mean_acceleration(q.target, "x") + float(down[1]) * mean_acceleration(q.target, "y")
            compare(report, name, simulated, solution.signed(name), values)
        elif q.kind == "small_oscillation" and q.detail.endswith(("omega", "period")):
            period = _small_period(solution, rhs, values, q.detail)
            compare(report, name, period if q.detail.endswith("period") else 2 * np.pi / period,
                     solution.signed(name), values)
        elif q.kind == "oscillation":
            amplitude = float(sp.N(ask.amplitude.xreplace(values)))
            compare(report, name, _period(solution, rhs, values, amplitude), solution.signed(name), values)
    return report


def _released(rhs, duration: float, n: int, events: list, tries: int = 3):
    """The run released from rest over `duration`, or over an eighth of it, or a sixty-fourth, where a
    longer run steps out of the scene (a block let go near its pulley reaches it within the second);
    the last failure (`Stalled`) where none holds."""
    for attempt in range(tries):
        try:
            return solve_ivp(rhs, (0, duration / 8**attempt), np.zeros(2 * n + 1), method=METHOD, rtol=RTOL,
                             atol=RTOL * 1e-2, dense_output=True, events=events or None)
        except LeftTheScene as left:
            failure = left
        except Stalled as stalled:
            return stalled
    return failure


def compare(report: SimulationReport, name: str, simulated: float, exact: sp.Expr, values) -> None:
    expected = float(sp.N(exact.xreplace(values), 20))
    if abs(simulated - expected) > 1e-6 * (abs(expected) + 1e-12):
        report.fail(f"{name}: simulation {simulated:.10g}, closed form {expected:.10g}")
    report.compared.append(name)


def _small_period(solution: Solution, rhs, values, detail: str, amplitude: float = 1e-5) -> float:
    """Time between downward zero crossings of the free coordinate (of several, the one that moves
    most in the mode asked), started in the reference configuration with a small velocity along
    the free direction (on the constraints to first order, however curved they are), or along the
    mode's shape, found here numerically: scipy's eigh of K and M at these values."""
    coords = solution.coordinates
    n = len(coords.all)
    if solution.freedoms > 1:
        modes = solution.normal_modes["lagrange"]
        expected = float(sp.N(modes.quantity(detail.replace("omega", "period")).xreplace(values)))
        numbers = [np.array(sp.N(m.xreplace(values)).tolist(), dtype=float) for m in (modes.stiffness, modes.mass)]
        squares, shapes = eigh(*numbers)
        shape = shapes[:, int(np.argmin(np.abs(squares - (2 * np.pi / expected) ** 2)))]
        direction = np.array(sp.N(modes.directions.xreplace(values)).tolist(), dtype=float) @ shape
        index = int(np.argmax(np.abs(direction)))
        direction = direction * np.sign(direction[index])
    else:
        linear = solution.oscillations["lagrange"]
        expected = float(sp.N(linear.quantity("period").xreplace(values)))
        direction = [float(sp.N(v.xreplace(values))) for v in linear.direction]
        index = coords.all.index(linear.coordinate)
    speed = amplitude * 2 * np.pi / expected
    start = np.zeros(2 * n + 1)
    start[n:2 * n] = [speed * v for v in direction]

    def crossing(t, y):
        return y[index]
    crossing.direction = -1
    run = solve_ivp(rhs, (0, 2 * expected), start, method=METHOD, rtol=RTOL, atol=RTOL * 1e-6, events=crossing)
    times = run.t_events[0]
    return float(times[1] - times[0]) if len(times) >= 2 else float("nan")


def _period(solution: Solution, rhs, values, amplitude: float) -> float:
    """Time between upward zero crossings of the free coordinate, released at rest at `amplitude`."""
    linear = solution.oscillations["lagrange"]
    coords = solution.coordinates
    n = len(coords.all)
    dependent = solve_gaps(solution.scene, coords)
    position = {linear.coordinate.q: amplitude}
    start = np.zeros(2 * n + 1)
    for i, c in enumerate(coords.all):
        expr = dependent.get(c.q, c.q).xreplace(values)
        start[i] = float(sp.N(expr.xreplace({linear.coordinate.q: amplitude, **{k: 0 for k in coords.state}})
                              if c.q in dependent else position.get(c.q, 0)))
    index = coords.all.index(linear.coordinate)
    expected = float(sp.N(linear.quantity("period").xreplace(values))) * (1 + amplitude**2)  # generous bound

    def crossing(t, y):
        return y[index]
    crossing.direction = 1
    run = solve_ivp(rhs, (0, 2.5 * expected), start, method=METHOD, rtol=RTOL, atol=RTOL * 1e-6, events=crossing)
    times = run.t_events[0]
    return float(times[1] - times[0]) if len(times) >= 2 else float("nan")
