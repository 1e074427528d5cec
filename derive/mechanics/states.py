"""States of a scene: where it is and how fast it moves, at the placement or where it gets to.

A state is the placement (the reference configuration, every coordinate zero) moving at given
rates, or the configuration where one body coordinate reaches a value, reached by the motion from
another state (the placement at rest by default). The constraints fix the other velocities of
the first; for the second the motion must have one degree of freedom (the scene's one, a
straight line in its coordinates that it keeps: blocks on cords, a free flight's coordinate at a
constant rate, or the one kept momenta leave: a rod on a smooth floor), and its rates come from the
work-energy theorem along its coordinate s (every constraint of derive's parts is ideal: pins,
cords, smooth or rolling contacts do no work):

    K(s1) = K(s0) + V(s0) - V(s1) + W,   K = k(s) s'^2,   W = integral of Q(s) ds

with V the potential energy of gravity and springs and Q the generalized force of the other loads
(forces and torques that depend on the configuration alone). The other route is Newton–Euler's
equations integrated numerically from the start to the state (derive.mechanics.integrated_motion,
checked at every solve by derive.solution.crosschecks); the time it takes is derive.mechanics.durations.

>>> import sympy as sp
>>> from derive.mechanics import lagrange
>>> from derive.parts.gravity import Gravity
>>> from derive.parts.pin import Pin
>>> from derive.model.scene import Body, Scene
>>> m, g, L = sp.symbols("m g L", positive=True)
>>> rod = Body("rod", "rod", m, {"length": L}, m * L**2 / 12, at=(L / 2, 0), angle=0)
>>> scene = Scene({"rod": rod}, (Pin("hinge", "rod", (-L / 2, 0)),), Gravity(g))
>>> coords = Coordinates(scene)
>>> down = reach(scene, coords, rest(coords), Gets(coords.of("rod", "theta"), -sp.pi / 2), lagrange.derive(scene, coords))
>>> down.values[coords.of("rod", "theta").u]
-sqrt(3)*sqrt(g)/sqrt(L)
"""
from __future__ import annotations

import dataclasses

import numpy as np
import sympy as sp

from derive.mechanics import first_integrals, first_root, free_flight, work
from derive.mechanics.derivation import KINETIC, Derivation
from derive.text.steps import Step
from derive.mechanics.reaching import Gets, GetsRate, Path, Reached, Stops, Vanishes, settled
from derive.core.tidying import radicals, tidy
from derive.model.kinematics import Coordinate, Coordinates, solve_gaps
from derive.mechanics.lagrange import energies
from derive.mechanics.state_errors import Curved, StateError, StateLimit
from derive.parts import listed, titled
from derive.text.prose import Sentence, capital
from derive.model.scene import Scene

#: Points between the start and a state where the motion must still move (the kinetic energy
#: stays positive): a turning point on the way would mean the state is never reached.
ON_THE_WAY = 8


#: Where no one coordinate carries the motion from its start to the state, and what to do.
NO_COORDINATE = ("find a coordinate that describes the whole motion from the start to the state (each one the "
                 "constraints leave free turns back on the way or has no rate there): give a state on the way "
                 "(when:), such as a bead at the side of its hoop, and reach this one from it (from:)")


def rest(coords: Coordinates) -> dict[sp.Symbol, sp.Expr]:
    """The placement at rest: every coordinate and velocity zero."""
    return {s: sp.Integer(0) for s in coords.at_rest_in_reference()}


def moving(scene: Scene, coords: Coordinates, rates: dict[Coordinate, sp.Expr]) -> Reached:
    """The placement moving at the given rates, the other velocities fixed by the constraints
    (dg/dt = 0 at the placement); refused where the rates leave a velocity open or break a
    constraint."""
    placement = {c.q: sp.Integer(0) for c in coords.all}
    given = {c.u: sp.sympify(value) for c, value in rates.items()}  # safe: expressions derive.core.expr parsed, or ints
    rows = [tidy(radicals(coords.ddt(g).xreplace(placement).xreplace(given), scene.placed))  # a run |L - 2 r| as
            for c in scene.constraints for g in c.gaps(coords)]  # placed: else a weight's swing reads as fixed
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
                             f"({', '.join(open_)}): give more of them (0 for one that does not move)")
        solved = {others[i]: tidy(reduced[row, -1]) for row, i in enumerate(pivots)}
    elif any(tidy(r) != 0 for r in rows):
        raise StateError("the rates break a constraint: no motion of the scene has them")
    values = {**placement, **given, **solved}
    said = [Sentence(("The motion starts where the bodies are placed, at the rates given: ",
                      *listed([sp.Eq(u, v) for u, v in given.items()]), "."))]
    if solved:
        one = len(scene.constraints) == 1
        said.append(Sentence((f"{capital(titled(scene.constraints))} hold{'s' * one} at every instant, so the rates of "
                              f"{'its' if one else 'their'} gaps are zero too: that fixes the other rates.",)))
    steps = (Step("The placement, moving at the given rates (the constraints give the others)",
                  tuple(sp.Eq(c.u, values[c.u]) for c in coords.all if values[c.u] != 0), sentences=tuple(said)),)
    return Reached(values, (), steps)


def reach(scene: Scene, coords: Coordinates, start: dict[sp.Symbol, sp.Expr],
          condition: Gets | GetsRate | Stops | Vanishes,
          derivation: Derivation, sample=None, nudge: bool | tuple = False) -> Reached:
    """The state the motion from the state `start` (every coordinate and velocity) gets to first
    where `condition` holds, by the work-energy theorem along the one free coordinate (with
    several, along the line the motion keeps, `_line`; where it curves, a free flight's coordinate
    at a constant rate, derive.mechanics.free_flight, or the one coordinate the constraints and
    the kept momenta leave, derive.mechanics.first_integrals).
    `derivation` gives the direction a start at rest moves in and the forces along the way;
    `sample` (an expression's float value at sample parameters) decides signs the symbols'
    assumptions leave open. `nudge` (derive.model.scene.State.nudge): from a balance, the motion
    starts with a vanishing push that way."""
    free = len(coords.all) - sum(len(c.gaps(coords)) for c in scene.constraints)
    decide = (lambda expr: sample(sp.sympify(expr))) if sample else _assumed  # safe: engine expressions
    integrals = ()
    if free > 1:  # before solving any gap: energy fixes one rate of several, unless the motion is a line
        try:
            return _line(scene, coords, start, condition, derivation, decide, free, nudge)
        except Curved:
            if sample is None:
                raise
            flying = free_flight.flight(scene, coords, start, derivation)
            if flying is not None:  # a projectile: along its coordinate that moves at a constant rate
                coordinate, positions, step = flying
                path = _path(scene, coords, start, coordinate, positions, derivation, decide, condition, nudge)
                reached = _arrive(path, condition, derivation, decide, "The flight is followed along one coordinate")
                clear = _clear_of_surfaces(free_flight.clearances(scene, coords), path, reached.end, decide)
                return dataclasses.replace(reached, steps=(step, *reached.steps), positive=reached.positive + clear)
            # kept momenta, zero at the start, fix sums of the coordinates: a rod on a smooth floor
            integrals = first_integrals.zero_momenta(scene, coords, start, sample)
            if free - len(integrals) != 1:
                raise
    if free < 1:
        raise StateError("the constraints leave the scene no motion: it never gets to the state")
    heading = _heading(start, coords, derivation, decide)
    target = condition.coordinate if isinstance(condition, Gets) else None
    if target is not None and not heading[target.q] and condition.measured is None:  # at rest and not pushed
        heading[target.q] = 1 if decide(condition.value - start[target.q]) > 0 else -1
    # The state's coordinate left free first; where it is extremal at the state (a disk's center
    # at its lowest, whose angle has no derivative in its height there), another, those that
    # move from the start first (one that does not is no measure of the motion near it).
    tried, problem = [], None
    # An angle before a translation: a swinging rod's angle gives its height as a cosine, its x a root.
    # Not an angle the gaps hold only linearly (a ball's rolled arc, r theta): keeping it would solve
    # the rolling gap for a position inside the arc's atan2, which sympy's solve ran past the limit on.
    gaps = [gap for part in scene.constraints for gap in part.gaps(coords)]
    others = sorted((c for c in coords.all if c != target),
                    key=lambda c: (heading[c.q] == 0, c.kind != "theta" or _rolled(c, gaps)))
    carried = "The constraints and the kept momentum leave one coordinate" if integrals else \
        "The constraints leave one coordinate"
    for keep in [target, *others] if target else others:
        try:
            dependent = solve_gaps(scene, coords, sample, keep=keep, heading=heading,
                                   at={c.q: start[c.q] for c in coords.all}, integrals=tuple(i.gap for i in integrals))
        except (ValueError, NotImplementedError) as error:
            problem = problem or StateLimit(f"find where the scene gets to: {error}")
            continue
        if set(dependent) in tried:
            continue
        tried.append(set(dependent))
        left = [c for c in coords.all if c.q not in dependent]
        if len(left) != 1:
            problem = problem or StateLimit(f"find a state reached by a scene of {len(left)} degrees of freedom "
                                            "(energy fixes one rate)")
            continue
        try:
            positions = {c.q: dependent.get(c.q, c.q) for c in coords.all}
            path = _path(scene, coords, start, left[0], positions, derivation, decide, condition, nudge)
            reached = _arrive(path, condition, derivation, decide, carried)
        except StateError as error:
            problem = problem or error
            continue
        if not any(v.has(sp.nan, sp.zoo, sp.oo, -sp.oo) for v in reached.values.values()):
            return dataclasses.replace(reached, steps=(*(i.step for i in integrals), *reached.steps))
        problem = problem or StateLimit(NO_COORDINATE)
    raise problem


def _rolled(coordinate: Coordinate, gaps: list[sp.Expr]) -> bool:
    """Whether the gaps hold a coordinate, and each only linearly: a rolling body's angle, in its
    gap as r theta beside the arc along the surface (not a swinging rod's, inside a cosine).

    >>> from derive.model.kinematics import Coordinate
    >>> r, x, th = sp.symbols("r x theta")
    >>> angle = Coordinate("ball", "theta", th, sp.Symbol("w"), sp.Symbol("a"))
    >>> _rolled(angle, [r * th + sp.atan2(x, r)]), _rolled(angle, [x - r * sp.cos(th)])
    (True, False)
    """
    holding = [gap for gap in gaps if gap.has(coordinate.q)]
    return bool(holding) and not any(sp.diff(gap, coordinate.q).has(coordinate.q) for gap in holding)


def _path(scene: Scene, coords: Coordinates, start: dict, coordinate: Coordinate, positions: dict,
          derivation: Derivation, decide, condition, nudge: bool | tuple = False) -> Path:
    """The motion from the start along one coordinate, every coordinate's position (`positions`)
    a function of it: the one the solved constraints leave free, or a line's."""
    s, speed = coordinate.q, coordinate.u
    # From rest a coordinate with no acceleration at the start (a bead's x at a bowl's rim, where
    # it first falls straight down) moves the way the other coordinates take it: toward the state
    # (Newton–Euler's motion, integrated at every solve, checks that it gets there).
    direction, leaves = _direction(start[speed], start, coordinate, derivation, decide)
    if not direction and isinstance(condition, Gets) and not _balanced(coords, start, derivation):
        direction = first_root.toward(positions, condition, s, start[s], decide)
    if not direction and nudge:
        direction = _nudged(nudge, coords, positions, condition, s, start[s], decide)
    if not direction:
        raise StateError("the scene stays at rest at the start (nothing pushes it): it never gets to the state; "
                         "a body at rest in balance (a stick on its end, a particle on a dome's top, a pendulum "
                         "hanging still) moves from a push: give a state with a rate to start from")
    velocities = {c.u: tidy(sp.diff(positions[c.q], s)) * speed for c in coords.all}
    kinetic, potential = energies(scene, coords)
    per_speed_squared = tidy(kinetic.xreplace(velocities).xreplace(positions) / speed**2)
    force, kept = work.force_along(scene, coords, coordinate, start, positions, velocities, derivation)
    antiderivative = sp.integrate(force, s) if force != 0 else sp.Integer(0)
    if antiderivative.has(sp.Integral):
        raise StateLimit(f"integrate the work of the loads, {sp.sstr(force)} d{s}")
    s0 = start[s]
    energy = kinetic.xreplace(start) + potential.xreplace(start) - antiderivative.xreplace({s: s0})
    along = tidy(energy - potential.xreplace(positions) + antiderivative)
    return Path(coordinate, start, direction, positions, velocities, per_speed_squared, along, leaves=leaves,
                work=work.work_said(scene, coords, s, kept), kept=kept)


def _line(scene: Scene, coords: Coordinates, start: dict, condition, derivation: Derivation, decide,
          free: int, nudge: bool | tuple = False) -> Reached:
    """The state a scene of several degrees of freedom gets to where its motion is a straight line
    in its coordinates: q = q0 + (s - s0) d / d_s, d the start's velocities (from rest its
    accelerations), s a coordinate that moves (the state's own where it does). Blocks on cords
    over pulleys move so, and a yo-yo falling from its string: a block's sideways coordinate,
    free to swing, never does. The line is checked, at the middle of the parameter ranges, at five
    points from the start to the state: every constraint holds on it, and the accelerations there
    (with the velocities along it from energy) stay in proportion to d. Per variant, each part's
    extents (a cord's runs) keep their signs."""
    if any(start[c.u] != 0 for c in coords.all):
        d = {c: start[c.u] for c in coords.all}
    else:
        solved = derivation.at(start).raw
        d = {c: tidy(solved[c.a]) for c in coords.all}
    moves = [c for c in coords.all if d[c] != 0]
    if not moves and nudge:  # from a balance: the way a vanishing push takes it is not along a line of rest
        raise Curved("follow a vanishing push from a balance along a straight line")
    if not moves:
        raise StateError("the scene stays at rest at the start (nothing pushes it): it never gets to the state")
    target = condition.coordinate if isinstance(condition, Gets) else None
    along = target if target in moves else min(moves, key=lambda c: c.kind == "theta")
    ratios = {c: tidy(d[c] / d[along]) for c in coords.all}
    s, s0 = along.q, start[along.q]
    positions = {c.q: s if c == along else start[c.q] + ratios[c] * (s - s0) for c in coords.all}
    path = _path(scene, coords, start, along, positions, derivation, decide, condition, nudge)
    curved = Curved(f"find a state reached by a scene of {free} degrees of freedom whose motion is not a "
                    "straight line in its coordinates (energy fixes one rate of several)")
    if not _on_line(scene, coords, path, s0, ratios, derivation, decide):  # at the start already (a ball flying off)
        raise curved
    reached = _arrive(path, condition, derivation, decide)
    if not _on_line(scene, coords, path, reached.end, ratios, derivation, decide):
        raise curved
    extents = [(e.xreplace(reached.values), meaning)  # per variant in numbers: tidying took minutes (a slanted cord)
               for part in scene.constraints for e, meaning in part.extents(coords)]
    _positive_at_the_middle(extents, decide, ": narrow the ranges to where the state is on the scene's geometry")
    path = dataclasses.replace(path, line=(reached.end, decide))
    moved = tuple(sp.Eq(c.q - start[c.q], ratios[c] * (s - s0)) for c in coords.all if c != along and ratios[c] != 0)
    kinetic = reached.steps[0].equations
    steps = (Step("From the start the scene moves along a straight line of its coordinates: each in proportion to "
                  "one of them, as the accelerations there are, and they stay so along it (the constraints hold and "
                  "the forces keep the proportions); the kinetic energy in its rate", (*moved, *kinetic), sentences=(Sentence((
                      f"The constraints leave the scene {free} degrees of freedom, but from the start it moves along a "
                      "straight line of its coordinates: every coordinate follows from ", s, " on it, and the kinetic "
                      "energy is a function of it times the square of its rate.")),)),
             *reached.steps[1:])
    return Reached(reached.values, reached.positive + tuple(extents), steps, path, reached.end, reached.vanished)


def _clear_of_surfaces(gaps: list[tuple[sp.Expr, str]], path: Path, end: sp.Expr, decide) -> tuple:
    """What must stay positive for a flight to keep off the scene's surfaces on its way: each gap
    (on the side the body starts, at the middle of the ranges: a surface behind it is none of its
    business) at the ON_THE_WAY - 1 points between the start and the state, and at the state
    unless it lands there (zero); refused at once where the middle of the ranges breaks one."""
    s, s0 = path.s, path.start[path.s]
    result = []
    for gap, meaning in gaps:
        along = gap.xreplace(path.positions)
        if decide(along.xreplace({s: s0})) < -1e-12:
            continue
        result += [(tidy(along.xreplace({s: s0 + sp.Rational(k, ON_THE_WAY) * (end - s0)})), meaning)
                   for k in range(1, ON_THE_WAY)]
        landed = tidy(along.xreplace({s: end}))
        result += [(landed, meaning)] if landed != 0 else []
    _positive_at_the_middle(result, decide, ": narrow the ranges to where the flight clears them")
    return tuple(result)


def _on_line(scene: Scene, coords: Coordinates, path: Path, end: sp.Expr, ratios: dict, derivation: Derivation,
             decide) -> bool:
    """Whether, at the middle of the parameter ranges, the line from the path's start to `end`
    keeps every constraint (each gap, its terms evaluated at 30 digits, zero to 1e-15 of their sizes, at
    five points) and the motion on it
    (velocities along it, at the rate energy gives) accelerates along it (each acceleration in
    its ratio to the path's, to 1e-8 and 1e-9 of the largest, the equations solved in floats)."""
    s0 = path.start[path.s]
    gaps = [g for part in scene.constraints for g in part.gaps(coords)]
    parameters = set().union(*(e.free_symbols for e in derivation.equations))
    parameters -= coords.state | set(derivation.unknowns)
    accelerations = derivation.numeric({p: decide(p) for p in parameters})
    n, index = len(coords.all), coords.all.index(path.coordinate)
    numbers = [decide(ratios[c]) for c in coords.all]
    for k in range(5):
        where = s0 + sp.Rational(k, 4) * (end - s0)
        at = path.values(where, path.rate(where), settle=False)
        for gap in gaps:
            terms = [decide(t.xreplace(at)) for t in sp.Add.make_args(gap)]
            if abs(sum(terms)) > 1e-15 * (1 + sum(abs(t) for t in terms)):
                return False
        a = accelerations(np.array([decide(at[c.q]) for c in coords.all] + [decide(at[c.u]) for c in coords.all]))[:n]
        floor = 1e-9 * max(abs(a))  # the rounding of a zero acceleration in floats
        if any(abs(a[i] - r * a[index]) > 1e-8 * (abs(a[i]) + abs(r * a[index])) + floor for i, r in enumerate(numbers)):
            return False
    return True


def _arrive(path: Path, condition, derivation: Derivation, decide,
            carried: str = "The constraints leave one coordinate") -> Reached:
    """The state on the path where the condition first holds, what must stay positive on the way,
    and the steps that found it (the first saying what leaves the path's one coordinate, `carried`)."""
    s, speed, s0 = path.s, path.coordinate.u, path.start[path.s]
    symbol = KINETIC
    steps = [Step(f"{carried}; the kinetic energy in its rate",
                  (sp.Eq(symbol, path.inertia * speed**2),), sentences=(Sentence((
                      f"{carried} of the scene: every coordinate follows from ", s,
                      ", and the kinetic energy is a function of it times the square of its rate.")),)),
             Step("Work and energy from the start", (sp.Eq(symbol, path.kinetic),), sentences=path.work)]
    vanished = ()
    if isinstance(condition, Gets):
        position = condition.at(path.positions) if condition.measured is None else tidy(condition.at(path.positions))
        function = position - condition.value
        s1 = first_root.first(sp.Eq(position, condition.value), function, path, decide,
                    "the motion from the start does not get there")
        if condition.coordinate == path.coordinate and condition.measured is None:  # every variant's state lies ahead
            steps_ahead = [(path.direction * (condition.value - s0), f"the state lies behind the start in {s} (the "
                                                                     "motion moves away from it)")]
        elif condition.measured is not None:  # a place relative to another body: its root ahead in every variant
            steps_ahead = [(path.direction * (s1 - s0), f"the state lies behind the start in {s} (the motion moves "
                                                        "away from it)")]
        else:
            steps_ahead = []
    elif isinstance(condition, GetsRate):
        speed_there = path.velocities[condition.coordinate.u].xreplace({speed: path.rate(s)})
        function = tidy(speed_there - condition.value)
        s1 = first_root.first(sp.Eq(function, 0), function, path, decide, f"the motion from the start does not get to "
                                                                  f"{condition.coordinate.u} = {sp.sstr(condition.value)}")
        steps.append(Step(f"The rate {condition.coordinate.u} along the way, and where it gets to "
                          f"{sp.sstr(condition.value)}", (sp.Eq(condition.coordinate.u, speed_there), sp.Eq(s, s1))))
    elif isinstance(condition, Stops):
        function = path.kinetic
        s1 = first_root.first(sp.Eq(path.kinetic, 0), function, path, decide,
                    "the motion does not stop: it goes on (over the top, or forever)")
        way = "increasing" if path.direction > 0 else "decreasing"
        steps.append(Step("It stops where its kinetic energy is zero", (sp.Eq(s, s1),), sentences=(Sentence((
            "A turning point: the motion, with ", s, f" {way}, stops at its first value ahead of the start where the "
            "kinetic energy has fallen to zero, and every rate with it.")),)))
    else:
        force = along(path, condition.force, derivation)
        steps.append(Step(f"Along the way, {condition.meaning}", (sp.Eq(condition.force, force),),
                          sentences=condition.said))
        function = force
        s1 = first_root.first(sp.Eq(force, 0), force, path, decide, f"{condition.meaning} stays positive: it never falls to zero")
        steps.append(Step("It falls to zero at", (sp.Eq(s, s1),)))
        vanished = (condition.force,) if condition.force.is_Symbol else ()
    work.check_kept(path, s1, derivation, decide)
    inertia = path.inertia.xreplace({s: s1})
    if inertia.has(sp.zoo, sp.oo, sp.nan) or not first_root.real(inertia, decide) or settled(1 / inertia) == 0:
        # the coordinate is extremal there (a bead's height at the bottom of a bowl): it has no
        # rate to carry the motion's, which another coordinate must
        raise StateLimit(NO_COORDINATE)
    rate = sp.Integer(0) if isinstance(condition, Stops) else path.rate(s1)
    values = path.values(s1, rate)
    arrived = path.kinetic.xreplace({s: s1})
    positive = [] if isinstance(condition, Stops) else [(arrived, "the motion does not reach the state: it stops before it")]
    positive[:0] = steps_ahead if isinstance(condition, Gets) else []
    if path.leaves is not None:  # every variant leaves the start the way the middle of the ranges does
        way = "decreasing" if path.direction > 0 else "increasing"
        positive[:0] = [(path.leaves**2, "at these values the scene stays at rest at the start (nothing pushes it: a "
                                         "ball at rest on a dome's top), so it never gets to the state"),
                        (path.direction * path.leaves, f"at these values the motion leaves the start with {s} {way}, "
                                                       "the other way than at the middle of the parameter ranges, "
                                                       "where derive found the state: it does not get there as "
                                                       "derived")]
    positive += [(path.kinetic.xreplace({s: s0 + sp.Rational(k, ON_THE_WAY) * (s1 - s0)}),
                  f"the motion stops on its way to the state (its kinetic energy, sampled at {ON_THE_WAY - 1} "
                  "points between, falls to zero)") for k in range(1, ON_THE_WAY)]
    _positive_at_the_middle(positive, decide, " (where derive decides which way the motion goes): narrow the ranges "
                                             "to where it gets there")
    guard = first_root.a_root(function, s, s0, s1)
    if guard and decide(guard[0][0]) <= 0:  # first checked the root there: an engine fault, not the file's
        raise StateLimit(f"find the state: its formula {s} = {sp.sstr(s1)} does not hold at the middle of the ranges")
    positive[:0] = guard
    if not isinstance(condition, Stops):
        steps.append(Step("So, at the state", (sp.Eq(symbol, tidy(arrived)), sp.Eq(speed, rate)), sentences=(Sentence((
            "The motion goes the way it leaves the start, with ", s,
            f" {'increasing' if path.direction > 0 else 'decreasing'}, so its rate at the state is the root of the "
            "kinetic energy there of that sign.")),)))
    return Reached(values, tuple(positive), tuple(steps), path, s1, vanished)


def _positive_at_the_middle(positive, decide, advice: str) -> None:
    """Refuse (StateError, with `advice`) where one of the (expression, meaning) pairs is not
    positive at the middle of the parameter ranges, where derive makes its choices; a sign that
    no sample parameters decide is left to the per-variant conditions."""
    for expr, meaning in positive:
        try:
            holds = decide(expr) > 0
        except StateError:  # no sample parameters, and a sign the assumptions leave open
            continue
        if not holds:
            raise StateError(f"{meaning}, at the middle of the parameter ranges{advice}")


def along(path: Path, force: sp.Expr, derivation: Derivation) -> sp.Expr:
    """A constraint force along the path, as a function of s (s'^2 from the energy); an
    expression of the route's unknowns with each of them so (each tidied, the whole not)."""
    if not force.is_Symbol:
        return force.xreplace({u: along(path, u, derivation) for u in force.free_symbols if u in derivation.unknowns})
    general, where, rate = path.general
    solved = derivation.at(general, path.frozen).raw[force].xreplace({where: path.s})
    return tidy(solved.xreplace({rate: sp.sqrt(path.kinetic / path.inertia)}))


def _assumed(expr: sp.Expr) -> float:
    """A number's value, or a symbolic expression's sign by the symbols' assumptions."""
    expr = sp.sympify(expr)  # safe: an engine expression or a Python number
    if expr.is_number:
        return float(expr)
    if expr.is_positive or expr.is_negative:
        return 1.0 if expr.is_positive else -1.0
    raise StateError(f"cannot decide the sign of {sp.sstr(expr)}: give the parameters ranges")


def _heading(start: dict, coords: Coordinates, derivation: Derivation, decide) -> dict[sp.Symbol, int]:
    """The way each coordinate leaves the start (+1, -1, 0): along its velocity, or where that is
    zero (from rest, or a bob's height at the bottom of its swing) along its acceleration."""
    motion = {c.q: start[c.u] for c in coords.all}
    if any(value == 0 for value in motion.values()):
        solved = derivation.at(start).raw
        motion = {c.q: value if value != 0 else tidy(solved[c.a]) for (c, value) in zip(coords.all, motion.values())}
    signs = {}
    for q, value in motion.items():
        number = 0.0 if value == 0 else decide(value)
        signs[q] = 1 if number > 1e-12 else -1 if number < -1e-12 else 0
    return signs


def _nudged(nudge: bool | tuple, coords: Coordinates, positions: dict, condition, s: sp.Symbol, s0: sp.Expr,
            decide) -> int:
    """The way s moves from a balance under a vanishing push: toward the state's position (`nudge`
    True), or the way the named coordinate first moves ((body, kind, +1 or -1)); 0 where it cannot say."""
    if nudge is True:
        return first_root.toward(positions, condition, s, s0, decide) if isinstance(condition, Gets) else 0
    body, kind, way = nudge
    rate = decide(sp.diff(positions[coords.of(body, kind).q], s).xreplace({s: s0}))
    return 0 if abs(rate) < 1e-12 else way * (1 if rate > 0 else -1)


def _balanced(coords: Coordinates, start: dict, derivation: Derivation) -> bool:
    """Whether the start is at rest with no acceleration at all: a balance the scene never leaves
    (a stick on its end; not a bead at a bowl's rim, which falls though its x is not pushed)."""
    if any(start[c.u] != 0 for c in coords.all):
        return False
    solved = derivation.at(start).raw
    return all(tidy(solved[c.a]) == 0 for c in coords.all)


def _direction(u0: sp.Expr, start: dict, coordinate: Coordinate, derivation: Derivation, decide) -> tuple:
    """(+1 or -1, the expression whose sign says so): the way the free coordinate moves from the
    start (its rate, or from rest the way it is pushed); (0, None) where it is not pushed."""
    if u0 != 0:
        return (1 if decide(u0) > 0 else -1), u0
    pushed = tidy(derivation.at(start).raw[coordinate.a])
    return (0, None) if pushed == 0 else ((1 if decide(pushed) > 0 else -1), pushed)


