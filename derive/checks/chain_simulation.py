"""Simulation of a chain of states (`scene.states`): each motion segment integrated from the
state the link before it produced, each event carried across by its derived jump.

The states are walked in the file's order at one point of the parameter ranges where the motion
gets to every one of them (the middle, else the first of 20 draws that meets every condition):

- a state given by its rates is where the simulation starts (its closed form, in numbers);
- a state the motion gets to (a coordinate's value, a turning point, a normal force or a tension
  falling to zero, a grip that fails or takes hold) is found by integrating Newton–Euler's
  equations of the scene in the state before (scipy DOP853 with event detection,
  derive.mechanics.integrated_motion) from the simulated state before it, not from its closed
  form, until the condition holds;
- an event (an impact, a clutch, a move, a turn) is instantaneous: the simulated velocities
  before it go through the jump derived for it (Lagrange's impact or move, evaluated at those
  velocities); its two routes are compared by derive.solution.crosschecks;
- after a chain's last event or grip, the motion that follows is integrated for AFTER seconds in
  the scene the event leaves (derive.checks.simulate.hold): its joints hold and the work-energy theorem
  balances, so the jump's velocities are ones the new joints allow.

At each state every coordinate and velocity and the time the motion took are compared with the
closed forms (to TOLERANCE of 1 + |value|), and each answer asked in a state with its value from
the simulated state (to 1e-6 of its size, a force or an acceleration to 1e-6 of the largest one
there).

>>> from derive.language.problem import load
>>> from derive.solution.answers import Solution
>>> report = simulate(Solution(load("skid_to_roll")))
>>> report.passed, report.compared
(True, ['state rolling', 't', 'd', 'V', 'dE', 'after rolling'])
"""
from __future__ import annotations

import numpy as np
import sympy as sp

from derive.numbers import numeric
from derive.solution.crosschecks import sample_points
from derive.core.errors import EngineLimit
from derive.mechanics import integrated_motion, moves, states as state_motion
from derive import quantities
from derive.model.scene import RATE_KINDS
from derive.checks.simulate import SimulationReport, hold

#: Agreement of a simulated coordinate, velocity or time with its closed form, relative to 1 + |value|.
TOLERANCE = 1e-7
#: Agreement of an answer asked in a state with its value from the simulated state.
ANSWER_TOLERANCE = 1e-6
#: Seconds the motion after a chain's last event is followed.
AFTER = 1.0


def simulate(solution, variant: dict[sp.Symbol, sp.Expr] | None = None) -> SimulationReport:
    """Simulate the chain of states of a Solution's scene (see the module), at a variant's SI
    parameter values (`variant`: a sheet's draw, which meets every condition) or by default at a
    point of the ranges where the motion gets to every state."""
    report = SimulationReport()
    scene = solution.scene
    if not scene.states:
        return report
    values = _point(solution, variant)
    carried: dict[str, dict] = {}  # each state as simulated: every coordinate and velocity, sympy Floats
    took: dict[str, float] = {}
    for name, state in scene.states.items():
        closed = solution.states[name].values
        if state.rates:  # where the simulation starts
            carried[name] = {k: _number(v, values) for k, v in closed.items()}
            continue
        if state.start is not None and state.start not in carried:
            report.unchecked.append((f"the state {name}", f"the state {state.start} it starts from was not simulated"))
            continue
        try:
            if state.event:
                carried[name] = _jump(solution, name, carried[state.start], values, report)
            else:
                found = _segment(solution, name, carried.get(state.start), values)
                if found is None:
                    report.fail(f"{name}: Newton–Euler's motion from the state before does not get there")
                    return report
                took[name], carried[name] = found
        except (EngineLimit, state_motion.StateLimit, moves.MoveLimit, np.linalg.LinAlgError) as error:
            # an engine limit (an impact or a move derive cannot solve at these velocities, a
            # singular system on the way): said by name, with every state and answer after it
            report.unchecked.append((f"the state {name}", str(error)))
            continue
        if name in took and state.nudge:
            report.unchecked.append((f"the time to {name}", "from a vanishing push it is unbounded (the limit the "
                                                            "places and speeds are)"))
        elif name in took:
            expected = _float(solution.duration(name)[0], values)
            if abs(took[name] - expected) > TOLERANCE * (1 + expected):
                report.fail(f"{name}: the motion takes {took[name]:.10g} s simulated, {expected:.10g} s by the closed form")
        expected = {k: _float(v, values) for k, v in closed.items()}
        worst = max(abs(float(carried[name][k]) - v) / (1 + abs(v)) for k, v in expected.items())
        if worst > TOLERANCE:
            report.fail(f"{name}: the simulated state and the closed form differ by {worst:.2e}")
        report.compared.append(f"state {name}")
    for ask_name, ask in solution.problem.asks.items():
        if ask.state is not None and ask.state not in carried:
            report.unchecked.append((ask_name, f"its state {ask.state} was not simulated"))
        elif ask.state is not None:
            _answer(solution, report, ask_name, carried, took, values)
    for name in (n for n in _last_links(solution) if n in carried):
        _after(solution, report, name, carried[name], values)
    return report


def _point(solution, variant: dict | None) -> dict[sp.Symbol, sp.Expr]:
    """Parameter values where the motion gets to every state of the chain: the variant's, with
    sizes the problem leaves open at sample values."""
    exprs, unknowns = [], set()
    for name, state in solution.scene.states.items():
        exprs += solution.states[name].values.values()
        derivation = solution.derivations_to(name)["newton_euler"]
        unknowns |= set(derivation.unknowns)
        exprs += [e.lhs - e.rhs for e in derivation.equations]
        if not state.rates and not state.event and not state.nudge:
            exprs.append(solution.duration(name)[0])
    exprs += [solution.expressions[n] for n, a in solution.problem.asks.items() if a.state is not None]
    if variant is None:
        return solution.reaching_point(exprs, unknowns, next(reversed(solution.scene.states)))
    symbols = set().union(*(e.free_symbols for e in exprs)) - solution.coordinates.state - unknowns
    return {**sample_points(solution.problem, sp.Add(*symbols), count=1)[0], **variant}


def _number(expr: sp.Expr, values: dict) -> sp.Float:
    return sp.Float(sp.N(sp.sympify(expr).xreplace(values), 20), 20)  # safe: derived expressions, not file text


def _float(expr: sp.Expr, values: dict) -> float:
    """A closed form's value (an integral by derive.numbers.numeric's quadrature, not sympy's evalf)."""
    return float(numeric.evaluate(sp.sympify(expr), values, 12))  # safe: derived expressions, not file text


def _segment(solution, name: str, start: dict | None, values: dict) -> tuple[float, dict] | None:
    """The state `name` reached by Newton–Euler's motion of the scene before it, integrated from
    the simulated state `start` (None: the placement at rest): (the time, the state)."""
    state, coords = solution.scene.states[name], solution.coordinates
    newton_euler = solution.derivations_to(name)["newton_euler"]
    if start is None:
        start = {k: sp.Float(0) for k in state_motion.rest(coords)}
    if state.nudge:
        start, horizon = integrated_motion.nudged_start(solution.states[name], start, values)
    else:
        horizon = 2 * _float(solution.duration(name)[0], values) + 1
    found = integrated_motion.integrate_to(newton_euler, coords, values, solution.states[name],
                                           solution._condition(state), horizon, start)
    if found is None:
        return None
    time, reached = found
    return float(time), {k: sp.Float(float(v), 20) for k, v in reached.items()}


def _jump(solution, name: str, before: dict, values: dict, report: SimulationReport) -> dict:
    """The state just after the event of `name`: the jump derived for it (Lagrange's impact or
    move), from the closed form's positions (where the event's joint was made) at the simulated
    velocities `before`."""
    state, coords, chain = solution.scene.states[name], solution.coordinates, solution._chain
    closed = solution.states[state.start].values
    at = {**{c.q: closed[c.q] for c in coords.all}, **{c.u: sp.Rational(repr(float(before[c.u]))) for c in coords.all}}
    if state.event.kind in ("move", "turn", "pull"):
        moved = solution._move(name, at, chain.joints[state.start], "lagrange")
        if moved.loose:
            report.unchecked.append((f"where the bodies are after the turn {name} ({', '.join(map(str, moved.loose))})",
                                     "it depends on how long the turn takes"))
        after = moved.values
    else:
        impact = solution._impact(name, at, solution._struck_with(name), chain.made[name], "lagrange")
        after = {**{c.q: before[c.q] for c in coords.all}, **impact.velocities}
    return {k: _number(v, values) for k, v in after.items()}


def _answer(solution, report: SimulationReport, name: str, carried: dict, took: dict, values: dict) -> None:
    """An answer asked in a state, from the simulated state, against its closed form."""
    ask, coords = solution.problem.asks[name], solution.coordinates
    q, state = ask.quantity, ask.state
    if ask.zero_for or ask.small:
        report.unchecked.append((name, "a critical value or a limit, not a state's value"))
        return
    if q.kind == "impulse":
        report.unchecked.append((name, f"the event {state}'s impulses: by its two routes"))
        return
    scale = 0.0
    if q.kind == "time":
        simulated = took[state]
    elif q.kind in RATE_KINDS or isinstance(quantities.KINDS[q.kind], quantities.StateChange):  # `at` a state
        start = solution.scene.states[state].start
        before = carried[start] if start else state_motion.rest(coords)
        simulated = _float(quantities.KINDS[q.kind].at(solution, ask, carried[state], before), values)
    else:
        read = _unknown(solution, q, state)
        if read is None:
            report.unchecked.append((name, f"{q.kind} {q.detail} is not read from a simulated state"))
            return
        unknown, factor = read
        derivation = solution.derivations_in(state)["newton_euler"]
        y = np.array([float(carried[state][s]) for s in [c.q for c in coords.all] + [c.u for c in coords.all]])
        solved = derivation.numeric(values)(y)
        simulated = float(solved[derivation.unknowns.index(unknown)]) * _float(factor, values)
        scale = float(np.max(np.abs(solved)))
    if ask.magnitude:
        simulated = abs(simulated)
    exact = solution.signed(name)  # in the file's axes, as simulated
    expected = _float(exact, values)
    # an answer exactly zero (the kinetic energy where a motion from rest stops) against the float
    # noise of the simulated state: 1e-20 in SI, far below any mechanics a scene holds
    floor = 1e-20 if exact == 0 else 1e-300
    if abs(simulated - expected) > ANSWER_TOLERANCE * (abs(expected) + scale) + floor:
        report.fail(f"{name}: simulation {simulated:.10g}, closed form {expected:.10g} (in the state {state})")
    report.compared.append(name)


def _unknown(solution, q, state: str) -> tuple[sp.Symbol, sp.Expr] | None:
    """The routes' unknown an ask in a state reads (an acceleration, a joint's force, a contact's
    normal force or friction) and the factor it is taken times (kinetic friction is mu_k N along
    the tangent, the way it acts in the state), or None."""
    coords, scene = solution.coordinates, solution.dynamics_scene
    if q.kind == "acceleration":
        return coords.of(q.target, q.detail).a, sp.Integer(1)
    if q.kind == "angular_acceleration":
        return coords.of(q.target, "theta").a, sp.Integer(1)
    if q.kind == "force":
        return scene.constraint(q.target).unknowns()[q.detail], sp.Integer(1)
    if q.kind == "contact" and q.detail in ("normal_force", "friction"):
        contact = scene.contact_of(q.target)
        there = solution.scene_in(state).constraint(contact.name)
        if q.detail == "friction" and there.regime == "kinetic":
            return contact.unknowns()["normal"], there.direction * there.kinetic
        return contact.unknowns()["normal" if q.detail == "normal_force" else "friction"], sp.Integer(1)
    return None


def _last_links(solution) -> list[str]:
    """The states no other state starts from that an event or a grip made: the motion after each
    goes on in a scene of its own (after a force falls to zero it would be another regime, not
    modelled; after a coordinate's value or a turning point, the same motion)."""
    starts = {s.start for s in solution.scene.states.values()}
    return [name for name, s in solution.scene.states.items() if name not in starts and (s.event or solution.grips_in(name))]


def _after(solution, report: SimulationReport, name: str, state: dict, values: dict) -> None:
    """The motion after the state `name`, in the scene the event leaves, for AFTER seconds."""
    coords = solution.coordinates
    start = np.array([float(state[c.q]) for c in coords.all] + [float(state[c.u]) for c in coords.all] + [0.0])
    hold(report, solution.scene_in(name), solution.derivations_in(name)["lagrange"], coords, values, start, AFTER,
         f"after {name}: ")
    report.compared.append(f"after {name}")
