"""Simulations of the 3D answers, for `derive check`: each asked quantity of a body on a fixed
point, rolling on its edge, in free rotation or in bearings against the full nonlinear motion of
derive.mechanics.rigid_motion (Euler's equations and a quaternion, the rolling condition in vectors), started
from the derived state, at the middle of the parameter ranges (open sizes at sample values).

- a top's steady precession (slow or fast root): started on it, the tilt must stay constant to
  STEADY rad and the axis turn about the vertical at the answer;
- nutation: the steady slow precession given a small tilting rate (the conserved momenta kept),
  the frequency from the time between the tilt's crossings of its steady value;
- a sleeping top's least spin, a coin's least upright speed: a small tilting rate at the answer
  times 1 + MARGIN must turn back while the tilt is small, at 1 - MARGIN the tilt must grow four
  times as far, or fall past FALLEN (so an answer 1 % off fails);
- a coin's steady circle: the lean constant, the heading's rate, the center's speed, the spin
  and the floor's force (m a_G + m g z) equal to the answers;
- free rotation: omega's turning about the axis in the body and the axis's about L measured,
  the angles of L and omega from the axis; a steady rotation's wobble frequency (zero crossings)
  and growth rate (the time to grow a thousandfold as cosh);
- bearings: L = I omega from the integrated orientation, the torque dL/dt and the center's
  acceleration by finite differences of the simulated motion, the supports' force m a_cm - m g,
  split between the bearings by the statics of the shaft (derive.mechanics.bearings.by_moments).

A small-size limit (`small:`) is compared before the limit, and again, to LIMIT_TOLERANCE, with the
small sizes at SHRINK of their sample values; a fast-top limit or a value where a quantity vanishes
(`zero_for`) is not simulated, and the report says so.

>>> from derive.solution.answers import Solution
>>> from derive.language.problem import load
>>> report = check(Solution(load("top_precession_exact")))
>>> report.passed, report.compared
(True, ['Omega_slow', 'Omega_fast'])
"""
from __future__ import annotations

import math
from typing import Callable, NamedTuple

import numpy as np
import sympy as sp

from derive.mechanics import rigid_motion, bearings, free_rotation
from derive.solution.crosschecks import sample_points
from derive.model.scene import Quantity
from derive.model.solid_scene import own_axis
from derive.checks.simulate import SimulationReport

#: The 3D kinds of asks this module simulates.
KINDS = {"pivot_point", "rolls_on_edge", "free_rotation", "bearings"}
#: Relative agreement asked of a simulated rate, angle, force or frequency.
TOLERANCE = 1e-6
#: A small-size limit (`small:`) is compared with the sizes at SHRINK of their sample values, to
#: LIMIT_TOLERANCE (the exact answer differs from the limit by about SHRINK times a ratio of sizes).
SHRINK, LIMIT_TOLERANCE = 1e-4, 1e-3
#: How many turns of its fastest angle a steady motion is simulated for (a coin: once round its circle, at most).
TURNS = 10
#: How far a steady motion's tilt may wander (rad) over its run.
STEADY = 1e-7
#: Spins and speeds tried either side of a least spin or speed, relatively.
MARGIN = 0.005
#: The integrator's relative tolerance where a run shows only whether a tilt turns back.
THRESHOLD_RTOL = 1e-9
#: A tilt (rad) past which a top or a coin started upright with a tilting rate of 1e-7 of its spin
#: has fallen away (a stable one stays within about 1e-5 rad; a top spun too slowly wobbles out to
#: about 0.1 rad and back, a coin falls over).
FALLEN = 0.01
#: Not simulated: limits of the exact answer (a fast top's).
LIMITS = ("precession.fast_top", "nutation.fast_top")


def check(solution) -> SimulationReport:
    """Simulate every 3D ask of the solution's problem and compare."""
    report = SimulationReport()
    simulation, shrunk = _Simulation(solution, report), {}
    for name, ask in solution.problem.asks.items():
        if ask.quantity.kind not in KINDS:
            continue
        try:
            simulation.ask(name, ask)
            if ask.small and ask.quantity.detail not in LIMITS:
                shrunk.setdefault(ask.small, _Simulation(solution, report, ask.small)).ask(name, ask)
        except RuntimeError as error:  # the integrator gave up, or no real start: a failed check, never a crash
            report.fail(f"{name}: {error}")
    return report


class _Upright(NamedTuple):
    """Upright motion started with a small tilting rate: the rates of the motion, the state at a spin,
    a measure of the tilt and its rate along the motion, that measure at a tilt, the spin per unit of
    the answer, and the answer's word."""

    rates: Callable
    state: Callable
    deviation: Callable
    deviation_at: Callable
    per_spin: float
    what: str


class _Simulation:
    """The runs of one problem's bodies at one point of the parameters, each run once; with
    `small` sizes, those at SHRINK of their sample values, where a small-size limit is compared."""

    def __init__(self, solution, report: SimulationReport, small: tuple[sp.Symbol, ...] = ()):
        self.solution, self.report, self.runs, self.small = solution, report, {}, small
        problem = solution.problem
        symbols = [p.symbol for p in problem.parameters.values()]
        for body in solution.scene.bodies.values():
            symbols += [body.mass, *body.sizes.values()]
        for held in solution.scene.pivot_points.values():  # a custom body's transverse moment, open where no ask needs it
            symbols += [held.tilt, held.spin, *(held.inertia or ())]
        for held in solution.scene.bearings.values():
            symbols += [*(held.inertia or ())]  # a custom rotor's transverse moment, open where no ask needs it
        self.point = sample_points(problem, sp.Add(*symbols), count=1)[0]
        self.point.update({size: self.point[size] * SHRINK for size in small})
        self.tolerance, self.magnitude = (LIMIT_TOLERANCE if small else TOLERANCE), False

    def number(self, expr) -> float:
        value = sp.N(sp.sympify(expr).xreplace(self.point), 30)  # safe: derived expressions, never file text
        if not value.is_real:
            raise RuntimeError(f"{sp.sstr(expr)} is {value} at the point simulated, not a real number")
        return float(value)

    def matrix(self, matrix) -> np.ndarray:
        return np.array(sp.Matrix(matrix).applyfunc(self.number).tolist(), dtype=float)

    def once(self, key, run):
        if key not in self.runs:
            self.runs[key] = run()
        return self.runs[key]

    def ask(self, name: str, ask) -> None:
        q = ask.quantity
        if q.detail in LIMITS or ask.zero_for:
            self.report.figures.append(f"{name}: {q.target}.{q.detail} not simulated ("
                                       f"{'a fast-top limit' if q.detail in LIMITS else 'where it vanishes'})")
            return
        measure = {"pivot_point": self._pivot_point, "rolls_on_edge": self._rolls_on_edge,
                   "free_rotation": self._free_rotation, "bearings": self._bearings}[q.kind]
        self.magnitude = ask.magnitude
        if not ask.small or self.small:  # the ask's own answer (a small-size limit: at the sizes shrunk)
            note = (f" (the small-size limit; {', '.join(map(str, self.small))} at {SHRINK:g} of the sample)"
                    if self.small else "")
            measure(name, q, self.number(self.solution.signed(name)), note)
            return
        # before the limit, by the route the answers use
        exact = {"pivot_point": self.solution._pivot_point, "rolls_on_edge": self.solution._rolls_on_edge,
                 "free_rotation": self.solution._free_rotation, "bearings": self._bearing}[q.kind](q)
        measure(name, q, self.number(exact), " (before the small-size limit)")

    def _bearing(self, q: Quantity):
        return self.solution._bearings(q, "newton_euler")

    def compare(self, name: str, what: str, simulated: float, expected: float, scale: float = 0.0) -> None:
        """Record the relative difference of a simulated value (scaled by `scale` where the value
        may be zero: a component by its vector's length)."""
        if self.magnitude:
            simulated, expected = abs(simulated), abs(expected)
        difference = abs(simulated - expected) / max(abs(expected), scale, 1e-300)
        line = (f"{name}: {what}: simulated {simulated:.10g}, derived {expected:.10g}, "
                f"relative difference {difference:.1e}")
        self.report.figures.append(line)
        self.report.compared.append(name)
        if not difference <= self.tolerance:
            self.report.fail(line)

    # a body on a fixed point

    def _top(self, name: str):
        """The rates of the top's motion, in its top frame (z from the fixed point through the center
        of mass), its tensor moved to the fixed point by the parallel-axis theorem."""
        tensor, mass, g, distance = self.solution.standing_top(name)
        m, l = self.number(mass), self.number(distance)
        about_point = self.matrix(tensor) + m * l**2 * np.diag([1.0, 1.0, 0.0])
        return rigid_motion.about_point(about_point, m, self.number(g), (0.0, 0.0, l))

    def _precessing(self, name: str, detail: str):
        """The state of steady precession at the derived root (`detail`) and the numbers (tilt, rate, spin)."""
        point = self.solution.scene.pivot_points[name]
        tilt, spin = self.number(point.tilt), self.number(point.spin)
        rate = self.number(self.solution._pivot_point(Quantity("pivot_point", name, detail)))
        turn = np.array([[math.cos(tilt), 0.0, math.sin(tilt)], [0.0, 1.0, 0.0],
                         [-math.sin(tilt), 0.0, math.cos(tilt)]])  # the top frame tilted about y
        omega = rate * rigid_motion.UP + (spin - rate * math.cos(tilt)) * turn[:, 2]
        return rigid_motion.start(turn, omega), tilt, rate, spin

    def _pivot_point(self, name: str, q: Quantity, expected: float, note: str) -> None:
        rates = self._top(q.target)
        if q.detail.startswith("precession."):
            state, tilt, rate, spin = self._precessing(q.target, q.detail)
            duration = 2 * math.pi * TURNS / max(abs(spin), abs(rate), abs(spin - rate * math.cos(tilt)))
            run = self.once(("steady", q.target, q.detail), lambda: rigid_motion.integrate(rates, state, duration))
            times = np.linspace(0, duration, 2001)
            axis = np.array([rigid_motion.axes(run.sol(t))[:, 2] for t in times])
            wander = float(np.max(np.abs(np.arccos(np.clip(axis[:, 2], -1, 1)) - tilt)))
            turned = np.unwrap(np.arctan2(axis[:, 1], axis[:, 0]))
            self.compare(name, f"steady precession simulated for {duration:.3g} s, tilt held to {wander:.0e} rad;"
                         f" the axis's rate about the vertical{note}", (turned[-1] - turned[0]) / duration, expected)
            if wander > STEADY:
                self.report.fail(f"{name}: started on the steady precession, the tilt wanders by {wander:.1e} rad")
        elif q.detail == "nutation.frequency":
            state, tilt, _, _ = self._precessing(q.target, "precession.slow")
            kick = 1e-5 * expected  # a tilting rate about the line of nodes: an amplitude of 1e-5 rad
            state[4:7] += rigid_motion.axes(state).T @ (kick * np.array([0.0, 1.0, 0.0]))

            def crossing(t, y):
                return rigid_motion.axes(y)[2, 2] - math.cos(tilt)
            crossing.direction = 1
            periods = 6
            run = rigid_motion.integrate(rates, state, (periods + 0.5) * 2 * math.pi / expected, events=crossing)
            times = run.t_events[0]
            measured = 2 * math.pi * (len(times) - 1) / (times[-1] - times[0]) if len(times) > 1 else float("nan")
            self.compare(name, f"the slow precession nudged (1e-5 rad), {len(times) - 1} nutation periods between "
                         f"the tilt's upward crossings{note}", measured, expected)
        else:  # sleeping.min_spin
            self._threshold(name, q, expected, note)

    def _upright_top(self, q: Quantity) -> _Upright:
        def state(spin):  # upright, spinning, given a small rate about the ground's x
            return rigid_motion.start(np.eye(3), [1e-7 * spin, 0.0, spin])

        def deviation(y):  # 1 - cos(tilt), and its rate
            axis = rigid_motion.axes(y)[:, 2]
            return 1 - axis[2], -np.cross(rigid_motion.axes(y) @ y[4:7], axis)[2]
        return _Upright(self._top(q.target), state, deviation, lambda tilt: 1 - math.cos(tilt), 1.0, "spin")

    def _upright_coin(self, q: Quantity) -> _Upright:
        I1, I3, mass, g, radius = (self.number(v) for v in self.solution.rolling_coin(q.target))

        def state(spin):  # upright, rolling along x, its axis along y, given a small leaning rate about x
            turn = np.array([[1.0, 0.0, 0.0], [0.0, 0.0, 1.0], [0.0, -1.0, 0.0]])
            return rigid_motion.start(turn, [1e-7 * spin, spin, 0.0], 0.0, 0.0, radius)

        def deviation(y):  # sin(lean)^2 and its rate
            axis = rigid_motion.axes(y)[:, 2]
            return axis[2] ** 2, 2 * axis[2] * np.cross(rigid_motion.axes(y) @ y[4:7], axis)[2]
        speed = q.detail == "upright.min_speed"
        return _Upright(rigid_motion.rolling_on_rim(I1, I3, mass, g, radius), state, deviation,
                        lambda lean: math.sin(lean) ** 2, 1 / radius if speed else 1.0, "speed" if speed else "spin")

    def _threshold(self, name: str, q: Quantity, expected: float, note: str) -> None:
        """A least spin or speed: a small tilting rate above it turns back, below it keeps growing."""
        rates, state, deviation, deviation_at, per_spin, what = (
            self._upright_top(q) if q.kind == "pivot_point" else self._upright_coin(q))

        def turning_back(t, y):
            return deviation(y)[1]

        def fallen(t, y):
            return deviation(y)[0] - deviation_at(FALLEN)
        turning_back.direction, turning_back.terminal, fallen.terminal = -1, True, True
        spin = per_spin * expected
        horizon = 4000 * math.pi / spin  # 2000 turns of the spin

        def runs():  # only whether the tilt turns back: a looser tolerance
            above = rigid_motion.integrate(rates, state(spin * (1 + MARGIN)), horizon, events=(turning_back, fallen),
                                           rtol=THRESHOLD_RTOL)
            if not above.t_events[0].size:
                return None
            turned_at = above.t_events[0][0]
            below = rigid_motion.integrate(rates, state(spin * (1 - MARGIN)), 3 * turned_at,
                                           events=(turning_back, fallen), rtol=THRESHOLD_RTOL)
            return turned_at, deviation(above.y_events[0][0])[0], deviation(below.y[:, -1])[0], below.t[-1]
        found = self.once(("threshold", q.target, f"{spin:.9e}"), runs)
        if found is None:
            self.report.fail(f"{name}: at {1 + MARGIN} times the least {what}{note} the tilt does not turn back: it "
                             f"falls past {FALLEN} rad or still grows after {horizon:.3g} s")
            return
        turned_at, highest, grown, ended = found
        self.report.figures.append(f"{name}: the least {what}{note}, derived {expected:.10g}, bracketed within "
                                   f"±{MARGIN:.1%} by simulation: upright at {1 + MARGIN:g} times it, a small tilt turns "
                                   f"back after {turned_at:.3g} s; at {1 - MARGIN:g} times, it grows "
                                   f"{math.sqrt(grown / highest):.3g} times as far by {ended:.3g} s")
        self.report.compared.append(name)
        if grown < 16 * highest:  # a tilt 4 times the highest above
            self.report.fail(f"{name}: below the least {what}{note} the tilt does not keep growing")

    # a body rolling on its edge

    def _rolls_on_edge(self, name: str, q: Quantity, expected: float, note: str) -> None:
        if q.detail.startswith("upright."):
            self._threshold(name, q, expected, note)
            return
        I1, I3, mass, g, radius = (self.number(v) for v in self.solution.rolling_coin(q.target))
        coin = self.solution.scene.rolls_on_edge[q.target]
        tilt, circle = self.number(coin.tilt), self.number(coin.circle)
        rate = self.number(self.solution._rolls_on_edge(Quantity("rolls_on_edge", q.target, "steady.precession")))
        duration = 2 * math.pi / max(rate, rate * circle / radius / TURNS)  # once round the circle, at most TURNS spins
        rates = rigid_motion.rolling_on_rim(I1, I3, mass, g, radius)

        def run_steady():
            # rolling along x at the contact point (the origin), leaning toward the circle's axis at y = circle
            up = np.array([0.0, math.sin(tilt), math.cos(tilt)])  # from the contact to the center
            normal = np.array([0.0, math.cos(tilt), -math.sin(tilt)])
            turn = np.column_stack([[1.0, 0.0, 0.0], -up, normal])
            omega = rate * rigid_motion.UP + rate * circle / radius * normal
            return rigid_motion.integrate(rates, rigid_motion.start(turn, omega, *(radius * up)), duration)
        run = self.once(("circle", q.target), run_steady)
        times = np.linspace(0, duration, 2001)
        states = [run.sol(t) for t in times]
        normals = np.array([rigid_motion.axes(y)[:, 2] for y in states])
        wander = float(np.max(np.abs(np.arcsin(np.clip(-normals[:, 2], -1, 1)) - tilt)))
        end = states[-1]
        omega = rigid_motion.axes(end) @ end[4:7]
        axis = np.array([0.0, circle, 0.0])
        what = q.detail.partition(".")[2]
        if what == "precession":
            heading = np.unwrap(np.arctan2(normals[:, 1], normals[:, 0]))
            simulated = (heading[-1] - heading[0]) / duration
        elif what == "speed":
            simulated = float(np.linalg.norm(np.cross(omega, end[7:10] - rigid_motion.contact_point(end, radius))))
        elif what == "spin":
            simulated = float(omega @ rigid_motion.axes(end)[:, 2])
        else:
            force = rigid_motion.contact_force(end, I1, I3, mass, g, radius)
            inward = (axis - end[7:10]) * np.array([1.0, 1.0, 0.0])
            simulated = force[2] if what == "normal_force" else force @ inward / np.linalg.norm(inward)
        self.compare(name, f"the steady circle rolled for {duration:.3g} s, lean held to {wander:.0e} rad; "
                     f"{q.detail}{note} at the end", simulated, expected)
        if wander > STEADY:
            self.report.fail(f"{name}: started on the steady circle, the lean wanders by {wander:.1e} rad")

    # a body in free rotation

    def _free_rotation(self, name: str, q: Quantity, expected: float, note: str) -> None:
        moments = [self.number(m) for m in self.solution.free_moments(q.target)]
        rates = rigid_motion.about_point(np.diag(moments))
        free = self.solution.scene.free_rotations[q.target]
        spin = self.number(free.spin)
        if q.detail in free_rotation.SYMMETRIC:
            k = "xyz".index(free_rotation.symmetric(self.solution.free_moments(q.target))[2])
            i, j = (k + 1) % 3, (k + 2) % 3
            omega = np.zeros(3)
            open_across = free.across.free_symbols - {p.symbol for p in self.solution.problem.parameters.values()}
            omega[k], omega[i] = spin, spin / 10 if open_across else self.number(free.across)  # a small wobble
            duration = 2 * math.pi * TURNS / float(np.linalg.norm(omega))
            start = rigid_motion.start(np.eye(3), omega)
            run = self.once(("free", q.target), lambda: rigid_motion.integrate(rates, start, duration))
            times = np.linspace(0, duration, 2001)
            states = [run.sol(t) for t in times]
            axes = np.array([rigid_motion.axes(y)[:, k] for y in states])
            end = rigid_motion.axes(states[-1])
            momentum = end @ (np.diag(moments) @ states[-1][4:7])  # L in space, at the end
            if q.detail == "free_precession.body":
                body = np.array([y[4:7] for y in states])
                angle = np.unwrap(np.arctan2(body[:, j], body[:, i]))
                simulated, what = (angle[-1] - angle[0]) / duration, "omega's turning about the axis in the body"
            elif q.detail == "free_precession.space":
                simulated, what = turning_rate(axes, times, momentum), "the axis's turning about L in space"
            else:
                along = momentum if q.detail == "angle_L_axis" else end @ states[-1][4:7]
                simulated = math.acos(along @ axes[-1] / np.linalg.norm(along))
                what = f"the angle between {'L' if q.detail == 'angle_L_axis' else 'omega'} and the axis at the end"
            self.compare(name, f"the free body turned for {duration:.3g} s ({TURNS} turns); {what}{note}", simulated,
                         expected)
            return
        _, rank, kind = q.detail.split(".")
        k = self.solution.free_axis(q.target, rank)
        i = (k + 1) % 3
        omega = np.zeros(3)
        omega[k], omega[i] = spin, (1e-7 if kind == "wobble" else 1e-10) * spin

        def across(t, y):
            return y[4 + i] - (0.0 if kind == "wobble" else 1000 * omega[i])
        across.direction = 1
        across.terminal = kind == "growth_rate"
        if kind == "wobble":
            periods = 6
            run = rigid_motion.integrate(rates, rigid_motion.start(np.eye(3), omega),
                                         (periods + 0.5) * 2 * math.pi / expected, events=across)
            times = run.t_events[0]
            simulated = 2 * math.pi * (len(times) - 1) / (times[-1] - times[0]) if len(times) > 1 else float("nan")
            what = f"a steady rotation about the axis of {rank} moment nudged (1e-7), {len(times) - 1} periods of " \
                   f"omega's part across it"
        else:
            run = rigid_motion.integrate(rates, rigid_motion.start(np.eye(3), omega), 30 / expected, events=across)
            simulated = math.acosh(1000) / run.t_events[0][0] if run.t_events[0].size else float("nan")
            what = "a steady rotation about the intermediate axis nudged (1e-10): acosh(1000) over the time omega's " \
                   "part across it takes to grow a thousandfold"
        self.compare(name, what + note, simulated, expected)

    # a body in bearings

    def _bearings(self, name: str, q: Quantity, expected: float, note: str) -> None:
        found, scales = self.once(("bearings", q.target), lambda: self._turned(q.target))
        held = self.solution.scene.bearings[q.target]
        apart = None if held.apart is None else self.number(held.apart)
        simulated = float(bearings.quantity(found, q.detail, self.number(held.tilt), apart))
        head = q.detail.rpartition(".")[0]
        size = (scales[bearings.VECTORS[head]] if head in bearings.VECTORS else scales["torque"] / apart
                if q.detail == "bearings.force" else scales.get(q.detail.rpartition(".")[2], 0.0))
        # a component by its vector's length, a value by itself; where that is nothing, by its kind's size
        length = float(found[bearings.VECTORS[head]].norm()) if head in bearings.VECTORS else abs(simulated)
        scale = length if length > 1e-6 * size else size
        self.compare(name, f"turned once on its shaft, L = I omega, dL/dt and a_cm by finite differences of the "
                     f"motion; {q.detail}{note}", simulated, expected, scale)

    def _turned(self, name: str) -> tuple[dict, dict]:
        """What the supports supply to the simulated motion of a body in bearings, at the end of
        one turn (where it is mounted as at the start), as `bearings.motion` gives it; and the size
        of each kind of quantity, against which a zero vector is compared: the moments and forces
        the body's inertia, mass and weight could need at its rate."""
        body, held = self.solution.scene.bodies[name], self.solution.scene.bearings[name]
        tensor = self.matrix(self.solution.bearing_tensor(name))
        tilt, roll, rate, turn = (self.number(v) for v in (held.tilt, held.roll, held.rate, held.turned))
        axis = own_axis(body.shape)
        mounted = self.matrix(bearings.mounted_axes(tilt, roll, axis))
        center = -np.array([self.number(c) for c in held.through])  # from the shaft's point, body frame
        mass = self.number(body.mass)
        gravity = np.array([self.number(c) for c in self.solution.shaft_gravity(name)])
        period = 2 * math.pi / rate
        run = rigid_motion.integrate(rigid_motion.turned(rate, turn), rigid_motion.start(mounted, [0, 0, 0])[:4],
                                     1.1 * period)
        step = 0.01 / rate
        times = [period + k * step for k in (-2, -1, 0, 1, 2)]
        turns = [rigid_motion.axes(run.sol(t)) for t in times]
        omegas = [rate * rigid_motion.shaft(turn, t) + turn * np.array([0.0, 1.0, 0.0]) for t in times]
        momenta = [R @ tensor @ R.T @ omega for R, omega in zip(turns, omegas)]
        positions = [R @ center for R in turns]
        torque = (momenta[0] - 8 * momenta[1] + 8 * momenta[3] - momenta[4]) / (12 * step)
        velocity = (positions[0] - 8 * positions[1] + 8 * positions[3] - positions[4]) / (12 * step)
        acceleration = (-positions[0] + 16 * positions[1] - 30 * positions[2] + 16 * positions[3]
                        - positions[4]) / (12 * step**2)
        force = mass * (acceleration - gravity)
        # in the frame of the shaft, turned with it (by nothing where it is not turned): as mounted at the start
        back = rigid_motion.about_y(turn * period).T
        momenta[2], torque, force, positions[2], velocity = (back @ v for v in (momenta[2], torque, force,
                                                                                  positions[2], velocity))
        omega = back @ omegas[2]
        apart = None if held.apart is None else self.number(held.apart)
        column = sp.Matrix
        found = {"angular_momentum": column(momenta[2]), "torque": column(torque), "force": column(force),
                 "kinetic_energy": float(omega @ momenta[2] + mass * velocity @ velocity) / 2,
                 **bearings.by_moments(column(torque), column(force), column(positions[2]), apart, held.thrust)}
        reach = float(np.linalg.norm(center))
        moment = rate**2 * (np.linalg.norm(tensor, 2) + mass * reach**2) + mass * float(np.linalg.norm(gravity)) * reach
        pull = mass * (rate**2 * reach + float(np.linalg.norm(gravity))) + (moment / apart if apart else 0.0)
        scales = {"angular_momentum": moment / rate, "torque": moment, "drive_torque": moment, "force": pull,
                  "bearing.A": pull, "bearing.B": pull, "kinetic_energy": moment, "angle_L_omega": 1.0}
        return found, scales


def turning_rate(vectors, times, about) -> float:
    """The mean rate at which the vectors' parts across `about` turn about it (unwrapped angle)."""
    about = about / np.linalg.norm(about)
    first = np.cross(about, [1.0, 0, 0]) if abs(about[0]) < 0.9 else np.cross(about, [0, 1.0, 0])
    first /= np.linalg.norm(first)
    angle = np.unwrap(np.arctan2(vectors @ np.cross(about, first), vectors @ first))
    return float((angle[-1] - angle[0]) / (times[-1] - times[0]))

