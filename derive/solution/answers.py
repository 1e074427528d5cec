"""Answers to a problem's asked quantities, from the scene's derivations, with their checks.

A `Solution` derives lazily: an inertia question never runs the dynamics, a question
about a force runs both routes once. Each answer is an exact expression (in the
parameter symbols, SI units), checked by an independent route and for dimensions.

>>> from derive.language.problem import load
>>> solution = Solution(load("rod_endpoint"))
>>> solution.expression("I")
L**2*m/3
"""
from __future__ import annotations

import functools
from functools import cached_property

import sympy as sp
from flint import ctx

from derive.core.memo import kept
from derive.numbers import balls
from derive.model.directions import Sense
from derive.core import limits
from derive.core.errors import EngineLimit
from derive.mechanics import (lagrange, many_bodies, newton_euler, orbits, paths, quantum, rolling, durations, friction, states as state_motion)
from derive.mechanics.conservation import ConservationError, EnergyBalance, speed_after_drop
from derive.mechanics.derivation import Derivation, Indeterminate, Solved
from derive.text.steps import Step
from derive.core.tidying import root, tidy
from derive.mechanics.equilibrium import Equilibrium, EquilibriumError, EquilibriumLimit, equilibrium
from derive.model.kinematics import Coordinates
from derive.mechanics.normal_modes import NormalModes, normal_modes
from derive.mechanics.oscillation import (NotAPendulum, Oscillation, OscillationError, OscillationLimit,
                                         exact_period, free_directions, small_oscillation)
from derive import quantities
from derive.solution import answer_signs, inverse, textbook
from derive.solution.answer_conditions import AnswerConditions
from derive.solution.answer_steps import AnswerSteps
from derive.solution.crosschecks import CrossChecks, sample_points
from derive.solution.solid_answers import SolidAnswers
from derive.solution.solid_checks import SolidChecks
from derive.solution.state_answers import StateAnswers
from derive.language.problem import Ask, Problem
from derive.core.expr import TIME

class Solution(AnswerConditions, AnswerSteps, StateAnswers, CrossChecks, SolidAnswers, SolidChecks):
    """Everything derived for one problem, computed on first use."""

    def __init__(self, problem: Problem):
        self.problem = problem
        self.scene = problem.scene

    @cached_property
    def coordinates(self) -> Coordinates:
        return Coordinates(self.scene)

    @cached_property
    def regimes(self) -> list[friction.Regime]:
        """The scene in each friction regime (derive.mechanics.friction), the stuck one first;
        one regime, the scene itself, where no contact gives friction coefficients."""
        try:
            contact = friction.frictional(self.scene)
        except ValueError as error:
            raise self.problem.limit(str(error)) from None
        return [friction.Regime("", self.scene)] if contact is None else friction.regimes(self.scene, contact)

    @property
    def dynamics_scene(self):
        """The scene the derivations describe: stuck at a contact with friction coefficients."""
        return self.regimes[0].scene

    @cached_property
    def derivations(self) -> dict[str, Derivation]:
        return self._regime_derivations(0)

    @kept
    def _regime_derivations(self, index: int) -> dict[str, Derivation]:
        scene = self.regimes[index].scene
        try:
            with limits.time_limit("the derivation by Lagrange"):
                by_lagrange = lagrange.derive(scene, self.coordinates)
            with limits.time_limit("the derivation by Newton-Euler"):
                by_newton_euler = newton_euler.derive(scene, self.coordinates)
        except limits.TimeLimitError:
            raise
        except ValueError as error:
            raise self.problem.error("scene", str(error)) from None
        return {"lagrange": by_lagrange, "newton_euler": by_newton_euler}

    def _grip(self, route: str) -> tuple[sp.Expr, sp.Expr]:
        """(normal force, friction) the stuck contact needs, in the reference configuration at rest.

        A contact that presses with no force cannot grip: refused (mu_s N >= |f| has no mu_s)."""
        stuck = self._solved(self.derivations[route], self.coordinates.at_rest_in_reference())
        contact = friction.frictional(self.scene)
        forces = self.dynamics_scene.constraint(contact.name).unknowns()
        normal, grip = stuck.raw[forces["normal"]], stuck.raw[forces["friction"]]
        self._presses(contact, normal, grip)
        return normal, grip

    def _presses(self, contact, normal: sp.Expr, grip: sp.Expr) -> None:
        """Refuse a contact held by friction that it does not press on (friction needs N > 0)."""
        if tidy(normal) != 0 or tidy(grip) == 0:
            return
        if contact.kinetic is not None:
            raise self.problem.limit(f"decide whether the {contact.body} slips at {contact.name}, which presses "
                                     "with no force while held")
        raise self.problem.error("scene", f"the {contact.body} presses on {contact.surface} with no force at "
                                          f"{contact.name}, so friction there cannot hold it (it needs "
                                          f"{sp.sstr(tidy(grip))}): the scene cannot stay at rest")

    def _solved(self, derivation: Derivation, state: dict, frozen=None) -> Solved:
        """The derivation solved in a state (`frozen`: see Derivation.at); equations that do not fix
        every force are the scene's fault."""
        try:
            return derivation.at(state, frozen)
        except Indeterminate as error:
            raise self.problem.error("scene", str(error)) from None

    @kept
    def period_at_amplitude(self, amplitude: sp.Expr, route: str):
        """(period, steps) at an amplitude: the elliptic integral of a pendulum, else twice the time
        between the turning points (derive.mechanics.durations.period; Newton–Euler's motion
        integrated checks it: crosschecks)."""
        try:
            return exact_period(self.scene, self.derivations[route], amplitude)
        except NotAPendulum:
            period, steps, _ = self._period_by_energy(amplitude)
            return period, steps

    @kept
    def _period_by_energy(self, amplitude: sp.Expr):
        coordinate = self.oscillations["lagrange"].coordinate
        if coordinate.kind != "theta":
            raise self.problem.limit(f"find the period at an amplitude in rad of a scene that swings in "
                                     f"{coordinate.q}, not an angle")
        try:
            with limits.time_limit("the period at its amplitude"):
                return durations.period(self.dynamics_scene, self.coordinates, coordinate, amplitude,
                                           self.derivations["lagrange"], self._sample)
        except state_motion.StateLimit as error:
            raise self.problem.limit(str(error)) from None
        except state_motion.StateError as error:
            raise self.problem.error("ask", f"the swing at that amplitude: {error}") from None

    @cached_property
    def oscillations(self) -> dict[str, Oscillation]:
        return self._small_motions(small_oscillation)

    def _small_motions(self, linearized) -> dict:
        """`linearized(scene, derivation, sample)` by each route; an engine limit reported as one,
        and what the file states wrongly as the ask's fault."""
        try:
            return {route: linearized(self.dynamics_scene, d, self._sample) for route, d in self.derivations.items()}
        except OscillationLimit as error:
            raise self.problem.limit(str(error)) from None
        except OscillationError as error:
            raise self.problem.error("ask", str(error)) from None

    @cached_property
    def freedoms(self) -> int:
        """How many directions the scene may move in from its reference configuration (to first order)."""
        return len(free_directions(self.dynamics_scene, self.coordinates))

    @cached_property
    def normal_modes(self) -> dict[str, NormalModes]:
        """The normal modes of a scene of several degrees of freedom, by each route's equations."""
        return self._small_motions(normal_modes)

    @property
    def linearized(self) -> dict[str, Oscillation | NormalModes]:
        """The small oscillations by each route: of one degree of freedom, or the normal modes of several."""
        return self.normal_modes if self.freedoms > 1 else self.oscillations

    @cached_property
    def equilibria(self) -> dict[str, Equilibrium]:
        """Where the scene rests, found by each route's equations."""
        try:
            return {route: equilibrium(self.dynamics_scene, d, self._sample,
                                       functools.partial(self._within_ranges, absolute=True))
                    for route, d in self.derivations.items()}
        except EquilibriumLimit as error:
            raise self.problem.limit(str(error)) from None
        except EquilibriumError as error:
            raise self.problem.error("ask", str(error)) from None

    def linearized_quantity(self, ask: Ask, route: str) -> sp.Expr:
        """A small oscillation's quantity by one route (derive.quantities.small_oscillation)."""
        try:
            return self.linearized[route].quantity(ask.quantity.detail)
        except OscillationLimit as error:
            raise self.problem.limit(str(error)) from None
        except OscillationError as error:
            raise self.problem.error(f"ask.{ask.name}.of", str(error)) from None

    def period(self, ask: Ask, route: str) -> sp.Expr:
        """The period at the ask's amplitude by one route (derive.quantities.oscillation)."""
        try:
            return self.period_at_amplitude(ask.amplitude, route)[0]
        except OscillationLimit as error:
            raise EngineLimit(f"{self.problem.path}: ask.{ask.name}", str(error)) from None
        except OscillationError as error:
            raise self.problem.error(f"ask.{ask.name}", str(error)) from None

    @kept
    def at_reference(self, route: str):
        """One route's accelerations and forces in the reference configuration, at rest: where the
        bodies are placed and released (every coordinate and velocity zero). With a contact that
        may slip, each is a Piecewise over the regimes: stuck where mu_s N >= |f|, else slipping
        with kinetic friction the way f points."""
        rest = self.coordinates.at_rest_in_reference()
        stuck = self._solved(self.derivations[route], rest)
        if len(self.regimes) == 1:
            return stuck
        contact = self.dynamics_scene.constraint(friction.frictional(self.scene).name)
        forces = contact.unknowns()
        pieces = [stuck.raw]
        for index, regime in enumerate(self.regimes[1:], start=1):
            solved = dict(self._solved(self._regime_derivations(index)[route], rest).raw)
            solved[forces["friction"]] = regime.direction * contact.kinetic * solved[forces["normal"]]
            pieces.append(solved)
        where = self.regime_conditions(route)
        return Solved({u: sp.Piecewise(*((values[u], w) for values, w in zip(pieces, where))) for u in stuck.raw})

    @kept
    def regime_conditions(self, route: str = "lagrange") -> list:
        """Where each regime holds, in the order of `regimes` (each where those before do not):
        stuck while mu_s >= |f/N| (N > 0 is a sign condition of every problem), then slipping
        the way f points."""
        if len(self.regimes) == 1:
            return [sp.true]
        normal, grip = self._grip(route)
        ratio = tidy(grip / normal)
        return list(friction.where_each(friction.frictional(self.scene), self.regimes, ratio))

    def regime_index(self, values: dict[sp.Symbol, sp.Expr]) -> int | None:
        """The index in `regimes` of the regime these parameter values give (None when a
        parameter it depends on has no value)."""
        for index, where in enumerate(self.regime_conditions()):
            decided = where.xreplace(values)
            if decided not in (sp.true, sp.false):
                return None
            if decided == sp.true:
                return index
        raise AssertionError("the last regime holds wherever the others do not")

    def regime_at(self, values: dict[sp.Symbol, sp.Expr]) -> str | None:
        """What the body does at these parameter values (rolls, stays, slips); None without a
        contact with friction coefficients, or when a parameter has no value."""
        index = self.regime_index(values)
        return None if index is None else self.regimes[index].name or None

    def contact_expression(self, body: str, detail: str, derivation: Derivation, state: str | None = None) -> sp.Expr:
        """Quantities of a body on a surface, from one route's accelerations and forces (its
        normal force and friction also in a named state)."""
        solved = self.in_state(derivation.route, state)
        contact = self.dynamics_scene.contact_of(body)
        surface = self.scene.surfaces[contact.surface]
        forces = contact.unknowns()
        if detail == "normal_force":
            return solved[forces["normal"]]
        if detail == "friction":
            there = self.scene_in(state).constraint(contact.name) if state else contact
            if there.regime == "kinetic":  # mu_k N along the tangent, the way it acts there
                return tidy(there.direction * there.kinetic * solved[forces["normal"]])
            return solved[forces["friction"]] if there.rolling else sp.Integer(0)
        if detail == "min_friction_coefficient":  # of the grip, whatever the regime
            stuck = derivation.at(self.coordinates.at_rest_in_reference())
            ratio = tidy(stuck[forces["friction"]] / stuck[forces["normal"]])
            return answer_signs.magnitude(self.problem, ratio)
        if detail == "min_release_height":
            return self.release_height(body, derivation.route)[0]
        acceleration = sp.Matrix([solved[self.coordinates.of(body, k).a] for k in ("x", "y")])
        along = tidy(surface.down.dot(acceleration))
        if detail == "acceleration.down_incline":
            return along
        # From rest down the whole incline, at constant acceleration: s = H / sin(angle).
        distance = surface.height / sp.sin(surface.angle)
        if along.free_symbols & self.coordinates.state:
            raise self.problem.error("ask", f"{body}'s acceleration along the incline is not constant")
        if detail == "speed_at_bottom":
            return root(2 * along * distance)
        return root(2 * distance / along)

    @kept
    def release_height(self, body: str, route: str) -> tuple[sp.Expr, tuple[Step, ...]]:
        """Lowest release height (of the center, above its lowest point) that keeps the body on a
        loop: the normal force at the top (this route's dynamics) vanishes at the speed energy
        conservation gives after the drop."""
        derivation = self.derivations[route]
        contact = self.scene.contact_of(body)
        loop = self.scene.surfaces[contact.surface]
        radius = self.scene.bodies[body].sizes.get("radius", sp.Integer(0))
        top = loop.top(radius)
        placed = sp.Matrix(self.scene.bodies[body].at)  # the coordinates are displacements from here
        speed, drop = sp.symbols("s D", positive=True)
        coords = self.coordinates
        state = {coords.of(body, "x").q: top[0] - placed[0], coords.of(body, "y").q: top[1] - placed[1]}
        state.update({c.q: 0 for c in coords.all if c.q not in state})
        velocity = speed * loop.tangent_at(top, radius)
        state.update({coords.of(body, "x").u: velocity[0], coords.of(body, "y").u: velocity[1]})
        if contact.rolling:  # the contact point is at rest
            rate = contact.conditions(coords)[-1].xreplace(state)
            state[coords.of(body, "theta").u] = sp.solve(rate, coords.of(body, "theta").u)[0]
        elif self.scene.bodies[body].rotates:  # sliding without friction from rest: nothing turns it
            if contact.has_friction:
                raise self.problem.error("ask", f"the {body} slides with friction: energy is not conserved on the way "
                                                "to the loop")
            state[coords.of(body, "theta").u] = sp.Integer(0)
        normal = sp.simplify(derivation.at(state).raw[contact.unknowns()["normal"]])
        critical = [s for s in sp.solve(normal, speed) if s.is_positive is not False]
        if len(critical) != 1:
            raise self.problem.error("ask", f"the normal force at the top of the loop vanishes at {critical}")
        try:
            balance = speed_after_drop(self.scene, body, drop)
        except ConservationError as error:
            raise self.problem.error("ask", str(error)) from None
        (needed,) = sp.solve(sp.Eq(balance.speed**2, critical[0] ** 2), drop)
        height = tidy(needed + top[1] - (loop.middle[1] - loop.path_radius(radius)))  # above the lowest point
        steps = (
            Step(f"Normal force on the {body} at the top of the loop, at speed s", (sp.Eq(sp.Symbol("N"), normal),)),
            Step("It stays on the track while the normal force is not negative: the least speed at the top",
                 (sp.Eq(speed, critical[0]),)),
            *balance.steps,
            Step("The least drop to the top, and the release height above the lowest point",
                 (sp.Eq(drop, tidy(needed)), sp.Eq(sp.Symbol("h"), height))),
        )
        return height, steps

    @cached_property
    def energy_balances(self) -> dict[str, EnergyBalance]:
        """The energy route to each speed asked, by body."""
        result = {}
        for ask in self.problem.asks.values():
            q = ask.quantity
            if q.kind == "contact" and q.detail == "speed_at_bottom":
                surface = self.scene.surfaces[self.scene.contact_of(q.target).surface]
                try:
                    result[q.target] = speed_after_drop(self.scene, q.target, surface.height)
                except ConservationError as error:
                    raise self.problem.error(f"ask.{ask.name}", str(error)) from None
        return result

    def _orbit(self, detail: str) -> sp.Expr:
        """An orbit's quantity (derive.quantities.orbit), by Binet's equation and Kepler's laws."""
        orbit = self.scene.orbit
        if detail in ("circular_radius", "effective_potential_minimum"):
            radius, minimum = orbits.circular_orbit(orbit.GM, orbit.angular_momentum)
            return radius if detail == "circular_radius" else minimum
        return orbits.kepler(orbit.GM, orbit.semi_major_axis, orbit.eccentricity)[detail]

    def _path(self, ask: Ask, route: int = 0) -> sp.Expr:
        """A path's quantity (derive.quantities.path) by projection (route 0) or by
        sympy.physics.mechanics' rotating frames (route 1)."""
        body = self.scene.bodies[ask.quantity.target]
        return (paths.quantity if route == 0 else paths.by_mechanics)(body.path, body.mass, ask.quantity.detail)

    def _within_ranges(self, expr: sp.Expr, absolute: bool = False) -> sp.Expr:
        """Resolve what an integral left open, using the parameter ranges: the branch of a Piecewise
        that holds over them, and 0**e where e > 0 over them (a density (r/R)**k with k > -2);
        with `absolute`, also |e| where e keeps its sign over them (an equilibrium's root)."""
        if not expr.has(sp.Piecewise) and not expr.has(sp.Pow) and not (absolute and expr.has(sp.Abs)):
            return expr
        points = sample_points(self.problem, expr)

        def holds(condition) -> bool:
            try:
                return all(bool(condition.xreplace(p)) for p in points)
            except TypeError:  # not real at a point (a state the motion does not reach there)
                return False

        if absolute:
            expr = expr.replace(lambda e: isinstance(e, sp.Abs) and (holds(e.args[0] > 0) or holds(e.args[0] < 0)),
                                lambda e: e.args[0] if holds(e.args[0] > 0) else -e.args[0])

        def branch(piecewise):
            for value, condition in piecewise.args:
                if condition is sp.true or holds(condition):
                    return value
            raise self.problem.error("ask", f"no branch of {piecewise} holds over the parameter ranges")

        expr = sp.piecewise_fold(expr).replace(lambda e: isinstance(e, sp.Piecewise), branch)
        expr = expr.replace(lambda e: e.is_Pow and e.base == 0 and holds(e.exp > 0), lambda e: sp.Integer(0))
        return tidy(expr)

    def _standing_wave(self, detail: str, route: int) -> sp.Expr:
        """A standing wave's momentum or angular momentum (derive.quantities.standing_wave) from the
        wavelength (route 0) or the operator (route 1: derive.mechanics.quantum)."""
        w = self.scene.wave
        if detail == "momentum" and route == 0:
            return quantum.momentum(w.planck, w.radius, w.wavelengths)
        found = quantum.angular_momentum(w.planck, w.radius, w.wavelengths, ("wave", "operator")[route])
        return found / w.radius if detail == "momentum" else found

    def _internal_torque(self, route: int) -> sp.Expr:
        """The torque of internal central forces (derive.quantities.internal_forces), summed over the
        bodies (route 0) or over the pairs (route 1: derive.mechanics.many_bodies)."""
        return many_bodies.internal_torque(self.scene.internal_forces, ("direct", "pairs")[route])

    def _rolling(self, body: str, detail: str, route: int) -> sp.Expr:
        """A rolling body's quantity (derive.quantities.rolling) about its center of mass (route 0) or
        its contact point (route 1: derive.mechanics.rolling)."""
        return rolling.rolling(self.scene, body, rolling.ROUTES[route])[0][detail]

    def _sample(self, expr: sp.Expr) -> float:
        """The value of an expression at the middle of the parameter ranges (SI), to 30 digits:
        its ball (derive.numbers.balls) where it has one narrow enough, else sympy's evalf (slower: most
        of the time a motion along a line in several coordinates took, derive.mechanics.states)."""
        value = expr.xreplace(sample_points(self.problem, expr, count=1)[0])
        try:
            with ctx.workprec(128):
                ball = balls.constant(value)
        except ValueError:  # no ball for it (a Piecewise, an integral)
            return float(sp.N(value, 30))
        if ball.is_finite() and float(ball.rad()) <= 1e-30 * (1 + abs(float(ball.mid()))):
            return float(ball.mid())
        return float(sp.N(value, 30))

    @kept
    def expression(self, name: str) -> sp.Expr:
        """The exact answer, in the parameter symbols, for SI values of the parameters
        (within the time limit of derive.core.limits: a runaway integral is an input error)."""
        with limits.time_limit(f"{self.problem.path}: ask.{name}"):
            result = self._expression(name)
            ask = self.problem.asks[name]
            if ask.sign is not None and not ask.zero_for:  # a parameter found has no direction
                return result if answer_signs.stated(self, name) == 1 else answer_signs.negated(result)
            if ask.magnitude or self.senses[name] is None:
                return answer_signs.magnitude(self.problem, result) if ask.magnitude else result
            return answer_signs.magnitude(self.problem, result, proven=True)

    @kept
    def signed_expression(self, name: str) -> sp.Expr:
        """The answer as the routes give it: a component along its axis, a rotation counter-clockwise
        positive, before `expression` takes the magnitude of a quantity with a direction."""
        with limits.time_limit(f"{self.problem.path}: ask.{name}"):
            return self._expression(name)

    @cached_property
    def textbook_route(self):
        """The route along the motion a solution manual takes (derive.solution.textbook), or None."""
        return textbook.route(self)

    @cached_property
    def student_steps(self) -> dict[str, list[Step]] | None:
        """The student's worked solution by section (derive.solution.textbook), or None: the routes'."""
        return textbook.student_steps(self)

    def signed(self, name: str) -> sp.Expr:
        """The answer in the file's own axes, before a direction in words: a component, a rotation
        counter-clockwise positive (`signed_expression`), the magnitude where the file asks
        `magnitude: true`; what a simulation measures."""
        ask = self.problem.asks[name]
        if ask.magnitude:
            return self.expressions[name]
        if ask.sign is not None:  # the key's answer, in the file's axes again
            return answer_signs.stated(self, name) * self.expressions[name]
        return self.signed_expressions.get(name, self.expressions[name])

    @cached_property
    def signed_expressions(self) -> dict[str, sp.Expr]:
        """The signed answer of each quantity with a direction (`senses`), for its direction per variant."""
        return {name: self.signed_expression(name) for name, sense in self.senses.items() if sense is not None}

    @cached_property
    def senses(self) -> dict[str, Sense | None]:
        """The words for the two ways each asked quantity can point (derive.model.directions), None where
        it has none, the question states its sign convention (`sign:`) or the answer is the parameter
        where it vanishes (`zero_for:`); the others are answered as magnitudes."""
        return {name: None if ask.sign or ask.zero_for else quantities.sense(self.scene, ask.quantity, self.coordinates, self._sample)
                for name, ask in self.problem.asks.items()}

    def _expression(self, name: str) -> sp.Expr:
        ask = self.problem.asks[name]
        result = quantities.KINDS[ask.quantity.kind].value(self, ask, 0)
        if result.has(sp.Piecewise):  # regimes: one case per regime, each in its simplest form
            folded = sp.piecewise_fold(result)
            result = tidy(folded) if isinstance(folded, sp.Piecewise) else folded
        placed = {a: sign * a.args[0] for a in result.atoms(sp.Abs) for sign in (1, -1)
                  if tidy(sign * a.args[0]) in self.scene.placed}
        if placed:  # |R - r| at a loop's top as the scene is placed, a sign kept in every variant (conditions)
            result = tidy(result.xreplace(placed))
        for size in ask.small:
            result = tidy(sp.limit(result, size, 0, "+"))
        if ask.zero_for:  # the quantity counted as the question says (`sign:`) takes the value `equals`
            result = inverse.solved(self.problem, self.counted(name, result), ask)
        leftover = result.free_symbols - {p.symbol for p in self.problem.parameters.values()} - {TIME}
        if leftover:
            names = ", ".join(sorted(map(str, leftover)))
            if leftover & self.coordinates.state:
                raise self.problem.error(f"ask.{name}.of", f"the answer depends on the state of motion ({names})")
            raise self.problem.error(f"ask.{name}.of", f"the answer depends on {names}, which the problem leaves "
                                     "unspecified: declare them as parameters")
        return result

    def counted(self, name: str, value: sp.Expr) -> sp.Expr:
        """An inverse ask's quantity `value` counted as its question says: its magnitude (`magnitude:`),
        along the way `sign:` names positive, or as the routes give it (a value of zero any way)."""
        ask = self.problem.asks[name]
        if ask.equals == 0 or not (ask.magnitude or ask.sign):
            return value
        if ask.magnitude:
            return answer_signs.magnitude(self.problem, value, proven=True)
        return answer_signs.stated(self, name) * value

    @cached_property
    def expressions(self) -> dict[str, sp.Expr]:
        return {name: self.expression(name) for name in self.problem.asks}
