"""States of a scene: where it is and how fast it moves, at the placement or where it gets to.

A state is the placement (the reference configuration, every coordinate zero) moving at given
rates, or the configuration where one body coordinate reaches a value, reached by the motion from
another state (the placement at rest by default). The constraints fix the other velocities of
the first; for the second the scene must have one degree of freedom, and its rates come from the
work-energy theorem along its free coordinate s (every constraint of derive's parts is ideal:
pins, cords, smooth or rolling contacts do no work):

    K(s1) = K(s0) + V(s0) - V(s1) + W,   K = k(s) s'^2,   W = integral of Q(s) ds

with V the potential energy of gravity and springs and Q the generalized force of the other loads
(forces and torques that depend on the configuration alone). The other route is Newton–Euler's
equations integrated numerically from the start to the state (`integrate_to`, checked at every
solve by derive.crosschecks).

>>> import sympy as sp
>>> from derive.mechanics import lagrange
>>> from derive.parts.gravity import Gravity
>>> from derive.parts.pin import Pin
>>> from derive.scene import Body, Scene
>>> m, g, L = sp.symbols("m g L", positive=True)
>>> rod = Body("rod", "rod", m, {"length": L}, m * L**2 / 12, at=(L / 2, 0), angle=0)
>>> scene = Scene({"rod": rod}, (Pin("hinge", "rod", (-L / 2, 0)),), Gravity(g))
>>> coords = Coordinates(scene)
>>> down = reach(scene, coords, rest(coords), coords.of("rod", "theta"), -sp.pi / 2, lagrange.derive(scene, coords))
>>> down.values[coords.of("rod", "theta").u]
-sqrt(3)*sqrt(g)/sqrt(L)
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import sympy as sp
from scipy.integrate import solve_ivp

from derive.mechanics.derivation import Derivation, Step, root, tidy
from derive.mechanics.kinematics import Coordinate, Coordinates, solve_gaps
from derive.mechanics.lagrange import energies, nonconservative_power
from derive.scene import TIME, Scene

#: Points between the start and a state where the motion must still move (the kinetic energy
#: stays positive): a turning point on the way would mean the state is never reached.
ON_THE_WAY = 8


class StateError(ValueError):
    """The state cannot be reached or does not fit the constraints (the file's fault)."""


class StateLimit(StateError):
    """A state derive cannot yet find (an engine limit, not the file's fault)."""


@dataclass(frozen=True)
class Reached:
    """Every coordinate and velocity in a state (`values`), what must stay positive for the
    motion to get there ((expression, meaning) pairs), the steps that found it, and the
    coordinate the motion was followed along (None at the placement)."""

    values: dict[sp.Symbol, sp.Expr]
    positive: tuple[tuple[sp.Expr, str], ...] = ()
    steps: tuple[Step, ...] = ()
    along: Coordinate | None = None


def rest(coords: Coordinates) -> dict[sp.Symbol, sp.Expr]:
    """The placement at rest: every coordinate and velocity zero."""
    return {s: sp.Integer(0) for s in coords.at_rest_in_reference()}


def moving(scene: Scene, coords: Coordinates, rates: dict[Coordinate, sp.Expr]) -> Reached:
    """The placement moving at the given rates, the other velocities fixed by the constraints
    (dg/dt = 0 at the placement); refused where the rates leave a velocity open or break a
    constraint."""
    placement = {c.q: sp.Integer(0) for c in coords.all}
    given = {c.u: sp.sympify(value) for c, value in rates.items()}  # safe: expressions derive.expr parsed, or ints
    rows = [coords.ddt(g).xreplace(placement).xreplace(given) for c in scene.constraints for g in c.gaps(coords)]
    others = [c.u for c in coords.all if c.u not in given]
    solved = {}
    if others:
        matrix, rhs = sp.linear_eq_to_matrix(rows, others) if rows else (sp.zeros(0, len(others)), sp.zeros(0, 1))
        reduced, pivots = matrix.row_join(rhs).rref(simplify=True)
        if len(others) in pivots:
            raise StateError("the rates break a constraint: no motion of the scene has them")
        if len(pivots) < len(others):
            open_ = [str(others[i]) for i in range(len(others)) if i not in pivots]
            raise StateError(f"the rates leave {len(open_)} velocit{'y' if len(open_) == 1 else 'ies'} open "
                             f"({', '.join(open_)}): give more of them")
        solved = {others[i]: tidy(reduced[row, -1]) for row, i in enumerate(pivots)}
    elif any(tidy(r) != 0 for r in rows):
        raise StateError("the rates break a constraint: no motion of the scene has them")
    values = {**placement, **given, **solved}
    steps = (Step("The placement, moving at the given rates (the constraints give the others)",
                  tuple(sp.Eq(c.u, values[c.u]) for c in coords.all if values[c.u] != 0)),)
    return Reached(values, (), steps)


def reach(scene: Scene, coords: Coordinates, start: dict[sp.Symbol, sp.Expr], target: Coordinate,
          value: sp.Expr, derivation: Derivation, sample=None) -> Reached:
    """The state where coordinate `target` reaches `value` (a displacement from the placement),
    moving from the state `start` (every coordinate and velocity), by the work-energy theorem
    along the one free coordinate. `derivation` gives the direction a start at rest moves in;
    `sample` (an expression's float value at sample parameters) decides signs the symbols'
    assumptions leave open."""
    decide = (lambda expr: sample(sp.sympify(expr))) if sample else _assumed  # safe: engine expressions
    heading = _heading(start, coords, derivation, decide)
    heading[target.q] = 1 if decide(value - start[target.q]) > 0 else -1
    # The state's coordinate left free first; where it is extremal at the state (a disk's center
    # at its lowest, whose angle has no derivative in its height there), another, those that
    # move from the start first (one that does not is no measure of the motion near it).
    tried, problem = [], None
    others = sorted((c for c in coords.all if c != target), key=lambda c: heading[c.q] == 0)
    for keep in [target, *others]:
        try:
            dependent = solve_gaps(scene, coords, sample, keep=keep, heading=heading)
        except (ValueError, NotImplementedError) as error:
            problem = problem or StateLimit(f"find where the scene gets to: {error}")
            continue
        if set(dependent) in tried:
            continue
        tried.append(set(dependent))
        try:
            reached = _along(scene, coords, start, target, value, dependent, heading, derivation, decide)
        except StateError as error:
            problem = problem or error
            continue
        if not any(v.has(sp.nan, sp.zoo, sp.oo, -sp.oo) for v in reached.values.values()):
            return reached
        problem = problem or StateLimit("find a coordinate that describes the motion through the state (each one the "
                             "constraints leave free has no rate there)")
    raise problem


def _along(scene: Scene, coords: Coordinates, start: dict, target: Coordinate, value: sp.Expr, dependent: dict,
           heading: dict, derivation: Derivation, decide) -> Reached:
    """The state reached along the one coordinate the solved constraints leave free."""
    free = [c for c in coords.all if c.q not in dependent]
    if len(free) != 1:
        raise StateLimit(f"find a state reached by a scene of {len(free)} degrees of freedom (energy fixes one rate)")
    (coordinate,) = free
    s, speed = coordinate.q, coordinate.u
    s0, u0 = start[s], start[speed]
    # From rest a coordinate with no acceleration at the start (a bead's x at a bowl's rim, where
    # it first falls straight down) moves the way the other coordinates take it: toward the state
    # (Newton–Euler's motion, integrated at every solve, checks that it gets there).
    direction = _direction(u0, start, coordinate, derivation, decide) or (heading[s] if s == target.q else 0)
    if not direction:
        raise StateError("the scene stays at rest at the start (nothing pushes it): it never gets to the state")
    s1 = _where(dependent.get(target.q, target.q), value, s, s0, direction, decide)

    positions = {c.q: dependent.get(c.q, c.q) for c in coords.all}
    velocities = {c.u: tidy(sp.diff(positions[c.q], s)) * speed for c in coords.all}
    kinetic, potential = energies(scene, coords)
    per_speed_squared = tidy(kinetic.xreplace(velocities).xreplace(positions) / speed**2)
    potential_along = potential.xreplace(positions)
    power = nonconservative_power(scene, coords).xreplace(velocities).xreplace(positions)
    force = tidy(power / speed)
    if force.has(speed, TIME) or force.free_symbols & {c.a for c in coords.all} or _holds_unknowns(force, scene):
        raise StateLimit("find a state reached under loads whose work depends on the speed, the time or a "
                         "contact force (a damper, a force given in t, kinetic friction)")
    start_energy = kinetic.xreplace(start) + potential.xreplace(start)
    antiderivative = sp.integrate(force, s) if force != 0 else sp.Integer(0)
    if antiderivative.has(sp.Integral):
        raise StateLimit(f"integrate the work of the loads, {sp.sstr(force)} d{s}")

    def kinetic_at(where: sp.Expr) -> sp.Expr:
        work = antiderivative.xreplace({s: where}) - antiderivative.xreplace({s: s0})
        return tidy(start_energy - potential_along.xreplace({s: where}) + work)

    arrived = kinetic_at(s1)
    rate = direction * root(arrived / per_speed_squared.xreplace({s: s1}))
    values = {c.q: tidy(positions[c.q].xreplace({s: s1})) for c in coords.all}
    values.update({c.u: tidy(velocities[c.u].xreplace({s: s1, speed: rate})) for c in coords.all})
    positive = [(arrived, "the motion does not reach the state: it stops before it")]
    positive += [(kinetic_at(s0 + sp.Rational(k, ON_THE_WAY) * (s1 - s0)),
                  f"the motion stops on its way to the state (its kinetic energy, sampled at {ON_THE_WAY - 1} "
                  "points between, falls to zero)") for k in range(1, ON_THE_WAY)]
    symbol = sp.Symbol("K")
    steps = (
        Step(f"The constraints leave one coordinate, {s}; the kinetic energy in its rate",
             (sp.Eq(symbol, per_speed_squared * speed**2),)),
        Step("Work and energy from the start: the constraints do no work, gravity and springs through V, "
             "the other loads through their work",
             (sp.Eq(symbol, arrived), sp.Eq(s, s1))),
        Step(f"So, moving {'forward' if direction > 0 else 'backward'} in {s}", (sp.Eq(speed, rate),)),
    )
    return Reached(values, tuple(positive), steps, coordinate)


def _assumed(expr: sp.Expr) -> float:
    """A number's value, or a symbolic expression's sign by the symbols' assumptions."""
    expr = sp.sympify(expr)  # safe: an engine expression or a Python number
    if expr.is_number:
        return float(expr)
    if expr.is_positive or expr.is_negative:
        return 1.0 if expr.is_positive else -1.0
    raise StateError(f"cannot decide the sign of {sp.sstr(expr)}: give the parameters ranges")


def _holds_unknowns(expr: sp.Expr, scene: Scene) -> bool:
    forces = {f for c in scene.constraints for f in c.unknowns().values()}
    return bool(expr.free_symbols & forces)


def _heading(start: dict, coords: Coordinates, derivation: Derivation, decide) -> dict[sp.Symbol, int]:
    """The way each coordinate leaves the start (+1, -1, 0): along its velocities, or from rest
    along its accelerations."""
    if any(start[c.u] != 0 for c in coords.all):
        motion = {c.q: start[c.u] for c in coords.all}
    else:
        solved = derivation.at(start).raw
        motion = {c.q: tidy(solved[c.a]) for c in coords.all}
    signs = {}
    for q, value in motion.items():
        number = 0.0 if value == 0 else decide(value)
        signs[q] = 1 if number > 1e-12 else -1 if number < -1e-12 else 0
    return signs


def _direction(u0: sp.Expr, start: dict, coordinate: Coordinate, derivation: Derivation, decide) -> int:
    """+1 or -1: the way the free coordinate moves from the start (its rate, or from rest the way
    it is pushed); 0 where it is not pushed."""
    if u0 != 0:
        return 1 if decide(u0) > 0 else -1
    pushed = tidy(derivation.at(start).raw[coordinate.a])
    return 0 if pushed == 0 else 1 if decide(pushed) > 0 else -1


def _where(position: sp.Expr, value: sp.Expr, s: sp.Symbol, s0: sp.Expr, direction: int, decide) -> sp.Expr:
    """The free coordinate where `position` (a function of it) equals `value`: the first such
    point the motion meets from s0 in `direction`."""
    if position == s:
        found = [value]
    else:
        found = [r for r in sp.solve(sp.Eq(position, value), s) if not r.has(sp.I)]
    ahead = [r for r in found if _real(r, decide) and direction * (decide(r) - decide(s0)) > 0]
    if not ahead:
        raise StateError(f"the motion from the start does not get there (it moves {'up' if direction > 0 else 'down'}"
                         f" in {s} from {sp.sstr(s0)}; the state is at {', '.join(map(sp.sstr, found)) or 'no point'})")
    return min(ahead, key=lambda r: abs(decide(r) - decide(s0)))


def _real(expr: sp.Expr, decide) -> bool:
    try:
        return bool(np.isfinite(decide(expr)))
    except (TypeError, ValueError):
        return False


def integrate_to(derivation: Derivation, coords: Coordinates, values: dict, start: dict, target: Coordinate,
                 value: float, horizon: float) -> dict[sp.Symbol, float]:
    """The state where `target`'s coordinate first reaches `value`, by integrating this route's
    equations of motion numerically (scipy, rtol 1e-11) from `start` at the parameter `values`;
    empty when it does not get there within `horizon` seconds."""
    accelerations = derivation.numeric(values)
    n = len(coords.all)

    def rates(t, y):
        return np.concatenate([y[n:], accelerations(y)[:n]])

    index = coords.all.index(target)

    def arrives(t, y):
        return y[index] - value
    arrives.terminal = True
    y0 = np.array([float(sp.N(start[s].xreplace(values), 20)) for s in [c.q for c in coords.all] + [c.u for c in coords.all]])
    run = solve_ivp(rates, (0, horizon), y0, method="DOP853", rtol=1e-11, atol=1e-13, events=arrives)
    if not len(run.t_events[0]):
        return {}
    end = run.y_events[0][0]
    return {**{c.q: end[i] for i, c in enumerate(coords.all)}, **{c.u: end[n + i] for i, c in enumerate(coords.all)}}
