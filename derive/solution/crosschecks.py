"""The independent checks of a Solution: every answer again by a second route.

Lagrange against Newton–Euler (answers symbolically, every acceleration and force at random
states the constraints allow), the work-energy theorem, energy against dynamics, conservation
laws against impulses, both routes of orbits, the top, a couple's angular impulse and the small systems,
integration against the tensor and the parallel-axis theorem, projections against
sympy.physics.mechanics, and the dimensions of every answer. `CrossChecks` is a mixin of
`derive.solution.answers.Solution`, whose derivations it reads; the 3D slices' checks are
`derive.solution.solid_checks`'.

>>> import sympy as sp
>>> agree(sp.sin(sp.Symbol("x"))**2 + sp.cos(sp.Symbol("x"))**2, sp.Integer(1))
'symbolic'
"""
from __future__ import annotations

import random

import sympy as sp

from derive.core.memo import kept
from derive.core import limits, units
from derive.numbers import numeric
from derive.core.errors import EngineLimit
from derive.numbers.agreement import BITS, METHODS, MIN_POINTS, agree, by_balls, same_ball
from derive.mechanics import impacts, integrated_motion, lagrange, orbits, reaching
from derive.mechanics.oscillation import NotAPendulum, exact_period
from derive.mechanics.small_swings import SmallSwing
from derive.mechanics.derivation import row_reduced
from derive.language.problem import Problem
from derive.model.scene import DYNAMIC_KINDS
from derive import quantities
from derive.quantities.base import Check, CheckFailure
from derive.quantities.by_routes import ROUTES, ByRoutes
from derive.solution.textbook_routes import TextbookRoute

#: An event's kind (`derive.model.scene.Event`), as the work-energy check names it.
_EVENT_WORDS = {"stick": "the impact", "lock": "the impact", "bounce": "the impact", "move": "the move",
                "turn": "the turn", "transfer": "the transfer", "pull": "the pull on the cord"}


class CrossChecks:
    """Checks of a Solution's answers by independent routes (mixed into Solution)."""

    @kept
    def checks(self) -> list[Check]:
        """Every independent check that applies: routes, parallel axes, dimensions (within the
        time limit of derive.core.limits)."""
        with limits.time_limit(f"{self.problem.path}: checks"):
            return self._checks()

    def _checks(self) -> list[Check]:
        result = [self._dimension_check()]
        kinds = {a.quantity.kind for a in self.problem.asks.values()}
        if kinds & DYNAMIC_KINDS:
            result.append(self._routes_check())
            result.append(self._work_energy_check())
        if any(not state.rates for state in self.scene.states.values()):
            result.append(self._states_check())
        if self.energy_balances:
            result.append(self._energy_check())
        if self.textbook_route is not None:
            result.append(self._textbook_check())
        result += self._quantity_checks()
        return result

    def _quantity_checks(self) -> list[Check]:
        """Each quantity of derive.quantities by its own checks (`QuantityKind.checks`), in the order the
        problem first asks it, else by its two routes (a route 1 that is the motion simulated is the
        states check's)."""
        agreed: dict[str, tuple[list[str], set[str]]] = {}
        result = []
        asked: dict[str, list[str]] = {}
        for name, ask in self.problem.asks.items():
            asked.setdefault(ask.quantity.kind, []).append(name)
        compared = []  # the asks of the kinds with no checks of their own: route 1 against route 0
        for kind, names in asked.items():
            own = quantities.KINDS[kind].checks(self, names)
            result += own if own is not None else []
            compared += names if own is None else []
        for name, ask in self.problem.asks.items():
            kind = quantities.KINDS[ask.quantity.kind]
            second = kind.value(self, ask, 1) if name in compared else None
            if second is None:
                continue
            first = kind.value(self, ask, 0)
            method = agree(first, second, points=sample_points(self.problem, sp.Tuple(first, second), count=MIN_POINTS))
            if method is None:
                raise CheckFailure(f"{self.problem.id}: {name} is {first} by {kind.routes[0]}, {second} by "
                                   f"{kind.routes[1]}")
            asks, methods = agreed.setdefault(kind.kind, ([], set()))
            asks.append(name)
            methods.add(method)
        return result + [Check(kind, True, ", ".join(sorted(methods)), f"{', '.join(asks)} agree by two routes",
                               f"Two routes give the same {', '.join(asks)}: {quantities.KINDS[kind].routes[0]}, and "
                               f"{quantities.KINDS[kind].routes[1]}.") for kind, (asks, methods) in agreed.items()]

    def _dimension_check(self) -> Check:
        found = {}
        for name, ask in self.problem.asks.items():
            if self.expressions[name] == 0:  # zero has every dimension
                found[name] = ask.unit
                continue
            try:
                dimension = units.expression_dimension(self.expressions[name], self.problem.symbol_units)
            except units.UnitError as error:  # of derive's own expression, not of the file's
                raise EngineLimit(f"{self.problem.path}: ask.{name}", f"find the dimension of its derived "
                                  f"answer ({error})") from None
            wanted = units.dimension(units.parse_unit(ask.unit))
            kind = quantities.KINDS[ask.quantity.kind] if not ask.zero_for else None  # a parameter found: its unit
            if kind is not None and kind.unit and not units.same_dimension(units.dimension(units.parse_unit(kind.unit)), wanted):
                raise self.problem.error(f"ask.{name}.unit", f"declared {ask.unit}, but a {kind.kind} is in {kind.unit}")
            if not units.same_dimension(dimension, wanted):
                raise self.problem.error(
                    f"ask.{name}.unit", f"declared {ask.unit}, but the derived answer has dimension {dimension or 'none'}"
                )
            found[name] = ask.unit
        return Check("dimensions", True, "dimensional analysis", ", ".join(f"{k} [{v}]" for k, v in found.items()),
                     "Every answer has the units it should: " + ", ".join(
                         f"{k} in {units.unicode_unit(v)}" if units.unicode_unit(v) else f"{k} a pure number"
                         for k, v in found.items()) + ".")

    def _routes_check(self) -> Check:
        """Lagrange's method and Newton–Euler give the same answers (symbolically where that is
        cheap, else certified by balls at points of the ranges: derive.numbers.agreement) and the same
        value of every acceleration and constraint force at random states (each route's linear
        system solved in balls: simplifying them all would cost far more than the question)."""
        methods, by_balls = set(), True
        for name, ask in self.problem.asks.items():
            kind = quantities.KINDS[ask.quantity.kind]
            if not isinstance(kind, ByRoutes):
                continue
            a, b = (kind.value(self, ask, r) for r in range(len(ROUTES)))
            method = agree(a, b, points=sample_points(self.problem, sp.Tuple(a, b), count=MIN_POINTS))
            if method is None:
                raise CheckFailure(f"{self.problem.id}: Lagrange and Newton–Euler disagree on {name}: {a} vs {b}")
            methods.add(method)
        for index, regime in enumerate(self.regimes):  # every friction regime, each on its own motions
            where = f" where the {regime.name}" if regime.name else ""
            for state in self._check_states(index):
                by_balls &= self._unknowns_agree(index, state, where)
        asked = " or ".join(m if m != "balls" else "by balls at 30 digits" for m in METHODS if m in methods)
        unknowns = "by balls" if by_balls else "numeric"
        return Check("lagrange_vs_newton_euler", True, f"answers {asked}, all unknowns {unknowns}",
                     f"answers and {len(self._regime_derivations(0)['lagrange'].unknowns)} accelerations and forces "
                     "agree" + ("" if methods <= {"symbolic"} else " (answers at 30 digits at points of the ranges)"),
                     "Lagrange's method and the Newton–Euler equations (the forces and torques on each body) give "
                     "the same accelerations and forces.")

    def _textbook_check(self) -> Check:
        """The student's route (derive.solution.textbook: Newton's law along the motion, torques about
        the center or a pivot) gives every acceleration and force it finds as Lagrange's method does;
        it is built from Newton–Euler's balances, projected, so an error of the projection shows here."""
        route = self.textbook_route
        if isinstance(route, SmallSwing):  # omega^2 is the stiffness the routes give
            engine = self.oscillations["lagrange"].stiffness
            method = agree(route.omega**2, engine, points=sample_points(self.problem, sp.Tuple(route.omega, engine), count=5))
            if method is None:
                raise CheckFailure(f"{self.problem.id}: the torque about the pivot gives omega^2 = {route.omega**2}, "
                                   f"Lagrange's method {engine}")
            return Check("textbook_route", True, f"small oscillations about {route.about} vs Lagrange, {method}",
                         "omega agrees", f"The student's route (small oscillations about {route.about}) gives the same "
                                         "frequency as Lagrange's method and the Newton–Euler equations.")
        if isinstance(route, TextbookRoute):  # a top, a skid, an impact: each finding beside the engine's
            methods = route.agreement(lambda a, b: agree(a, b, points=sample_points(self.problem, sp.Tuple(a, b), count=5)),
                                      lambda what, a, b: CheckFailure(f"{self.problem.id}: the student's route gives "
                                                                      f"{what} = {a}, the engine {b}"))
            return Check("textbook_route", True, " or ".join(sorted(methods)), f"{len(route.compared)} findings agree",
                         f"The student's route ({route.principle}) gives the same results as the engine's routes.")
        reference = self.derivations["lagrange"].at(self.coordinates.at_rest_in_reference())
        methods = set()
        for unknown, value in self.textbook_route.values.items():
            expected = reference[unknown]
            method = agree(value, expected, points=sample_points(self.problem, sp.Tuple(value, expected), count=5))
            if method is None:
                raise CheckFailure(f"{self.problem.id}: the student's route gives {unknown} = {value}, "
                                   f"Lagrange's method {expected}")
            methods.add(method)
        return Check("textbook_route", True, "route along the motion vs Lagrange, " + " or ".join(sorted(methods)),
                     f"{len(self.textbook_route.values)} accelerations and forces agree",
                     "Newton's second law along the motion, with the torques, gives the same accelerations and "
                     "forces as Lagrange's method and the Newton–Euler equations.")

    def _unknowns_agree(self, index: int, state: dict, where: str) -> bool:
        """Every unknown of both routes at a state of the index-th regime, in balls (True), or
        where balls cannot tell, from the exact solutions at 30 digits (False); a difference
        raises CheckFailure."""
        routes = self._regime_derivations(index)
        try:
            solved = [routes[r].balls_at(state) for r in ROUTES]
        except ValueError:
            solved = None
        by_balls = True
        for unknown in routes["lagrange"].unknowns:
            verdict = None if solved is None else same_ball(solved[0][unknown], solved[1][unknown], BITS[-1])
            if verdict is None:
                by_balls = False
                exact = [routes[r].at(state).raw[unknown].xreplace(state) for r in ROUTES]
                verdict = agree(*exact, symbolic=False) is not None
            if not verdict:
                raise CheckFailure(f"{self.problem.id}: Lagrange and Newton–Euler disagree on {unknown}{where}")
        return by_balls

    def energy_ledger(self, scene=None) -> dict[str, sp.Expr]:
        """Kinetic energy (translational, rotational), potential energy and the power of the
        non-conservative applied forces, in the coordinates of the scene (by default the one
        the derivations describe)."""
        scene = scene or self.dynamics_scene
        coords = self.coordinates
        translational = sum((b.mass * (coords.of(n, "x").u ** 2 + coords.of(n, "y").u ** 2) / 2
                             for n, b in self.scene.bodies.items()), sp.Integer(0))
        rotational = sum((b.inertia * coords.angular_velocity(n) ** 2 / 2
                          for n, b in self.scene.bodies.items() if b.rotates), sp.Integer(0))
        _, potential = lagrange.energies(scene, coords)
        power = sp.trigsimp(sp.expand(lagrange.nonconservative_power(scene, coords)))
        return {"kinetic_translational": translational, "kinetic_rotational": rotational,
                "potential": potential, "power_nonconservative": power}

    def _states_check(self) -> Check:
        """Each state reached by the motion (energy, derive.mechanics.states) against Newton–Euler's
        equations integrated numerically from its start until its condition holds (a coordinate
        gets there, the motion turns, a force falls to zero), at a point of the parameter ranges
        where the motion gets there (the middle, else the first of 20 draws that meets every
        condition): every coordinate and velocity, and the time it takes, within 1e-7."""
        coords = self.coordinates
        impacts = 0
        for name, state in self.scene.states.items():
            if state.rates:
                continue
            if state.event:
                (self._move_check if state.event.kind in ("move", "turn", "pull") else self._impact_check)(name)
                impacts += 1
                continue
            newton_euler = self.derivations_to(name)["newton_euler"]  # to a grip: with the part slipping
            reached = self.states[name]
            start = reached.path.start if reached.path else self.states[state.start].values
            time = self.duration(name)[0] if not state.nudge else sp.Integer(0)  # from a vanishing push: unbounded
            exprs = [*reached.values.values(), *start.values(), time,
                     *(e.lhs - e.rhs for e in newton_euler.balances)]
            values = self.reaching_point(exprs, set(newton_euler.unknowns), name)
            expected = {k: float(sp.N(v.xreplace(values), 20)) for k, v in reached.values.items()}
            try:
                expected_time = float(numeric.evaluate(time, values, 12))  # an integral: by mpmath's quadrature
            except ValueError as error:
                raise CheckFailure(f"{self.problem.id}: the time to the state {name}: {error}") from None
            horizon = 2 * expected_time + 1
            if state.nudge:
                start, horizon = integrated_motion.nudged_start(reached, start, values)
            simulated = integrated_motion.integrate_to(newton_euler, coords, values, reached, self._condition(state), horizon,
                                            start)
            if simulated is None:
                raise CheckFailure(f"{self.problem.id}: Newton–Euler's motion from the start does not reach the "
                                   f"state {name} in {horizon:.3g} s")
            took, simulated = simulated
            worst = max(abs(simulated[k] - expected[k]) / (1 + abs(expected[k])) for k in expected)
            if not state.nudge:
                worst = max(worst, abs(took - expected_time) / (1 + expected_time))
            if worst > 1e-7:
                raise CheckFailure(f"{self.problem.id}: the state {name} by energy and by Newton–Euler's motion "
                                   f"differ by {worst:.2e}")
        detail = "every state reached, and the time it takes: energy against Newton–Euler's motion, integrated"
        if impacts:
            detail += (f"; {impacts} impact{'s' if impacts > 1 else ''} or move{'s' if impacts > 1 else ''}: generalized "
                       "momenta against each body's impulses or moments")
        reading = ("Newton–Euler's equations, integrated numerically from the start, reach each state at the same "
                   "place, speed and time as the derivation.")
        if impacts:
            reading += " In each impact or move, the velocities agree with each body's impulse and momentum."
        nudged = [n for n, state in self.scene.states.items() if state.nudge]
        if nudged:  # from a balance the motion starts at 1e-9 of its final rate: the time is the log of that
            detail += f"; from a vanishing push ({', '.join(nudged)}): places and speeds only"
            reading += (" From a vanishing push, the motion is followed from a push a billionth of the speed it "
                        "reaches; the time, which grows without bound as the push vanishes, is not compared.")
        return Check("states", True, "numeric", detail, reading)

    def reaching_point(self, exprs: list, unknowns: set, name: str) -> dict[sp.Symbol, sp.Expr]:
        """A point of the parameter ranges where the motion gets to the state `name` (the middle,
        else the first of 20 draws that meets every condition), with values for every symbol of
        `exprs` but the coordinates, the velocities and the `unknowns`."""
        symbols = set().union(*(e.free_symbols for e in exprs), *(c.free_symbols for c, _, _ in self.conditions))
        symbols -= self.coordinates.state | unknowns
        values = next((point for point in sample_points(self.problem, sp.Add(*symbols), count=20)
                       if self.violated(point) is None), None)
        if values is None:
            raise self.problem.error(f"scene.states.{name}", "the motion gets to this state at none of 20 points "
                                                             "of the parameter ranges: narrow them")
        return values

    def period_check(self, names: list[str]) -> Check:
        """The period at its amplitude of each ask `names` (derive.quantities.oscillation) found by
        energy between the turning points (not a pendulum's elliptic integral) against Newton–Euler's
        motion integrated from rest at the amplitude to the turning point on the other side, at the
        middle of the ranges: twice its time, within 1e-7."""
        coords, newton_euler = self.coordinates, self.derivations["newton_euler"]
        compared = 0
        for ask in (self.problem.asks[name] for name in names):
            try:
                exact_period(self.scene, self.derivations["lagrange"], ask.amplitude)
                continue  # a pendulum: the elliptic integral, compared by the routes check
            except NotAPendulum:
                period, _, turned = self._period_by_energy(ask.amplitude)
            compared += 1
            symbols = (period.free_symbols | set().union(*(e.free_symbols for e in newton_euler.equations))
                       | set().union(*(v.free_symbols for v in turned.path.start.values())))
            symbols -= coords.state | set(newton_euler.unknowns)
            values = sample_points(self.problem, sp.Add(*symbols), count=1)[0]
            expected = float(numeric.evaluate(period, values, 12))
            simulated = integrated_motion.integrate_to(newton_euler, coords, values, turned, reaching.Stops(), expected + 1)
            if simulated is None or abs(2 * simulated[0] - expected) > 1e-7 * expected:
                raise CheckFailure(f"{self.problem.id}: the period at amplitude {ask.amplitude} is {expected} by energy, "
                                   f"{None if simulated is None else 2 * simulated[0]} by Newton–Euler's motion")
        if not compared:
            return Check("period", True, "symbolic", "a pendulum's period: the elliptic integral by both routes",
                         "Both methods give the same period, an elliptic integral.")
        return Check("period", True, "numeric", "the period at its amplitude by energy between the turning points "
                                                "against Newton–Euler's motion, integrated",
                     "The period found from energy agrees with Newton–Euler's motion integrated over a swing.")

    def _impact_check(self, name: str) -> None:
        """The velocities and impulses just after an impact by Lagrange (generalized momenta and
        impulses) and by Newton–Euler (each body's impulse and momentum) agree, symbolically."""
        by_lagrange = self._chain.impacts[name]
        state = self.scene.states[name]
        by_impulses = self._impact_by(name, "newton_euler")
        # a rough bounce's regimes each on its own (where it holds is found from the grip's impulses)
        pairs = (zip((r.impact for r in by_lagrange.regimes), (r.impact for r in by_impulses.regimes))
                 if by_lagrange.regimes else [(by_lagrange, by_impulses)])
        before = self.states[state.start].values
        for first, second in pairs:
            for key in (*first.velocities, *first.impulses):
                # |R - r| of a circle's normal where a body is on it: as the parameter ranges have it
                a, b = (self._within_ranges(e, absolute=True) if e.has(sp.Abs) and not by_lagrange.regimes else e
                        for e in ({**first.velocities, **first.impulses}[key],
                                  {**second.velocities, **second.impulses}[key]))
                if agree(a, b) is None:
                    raise CheckFailure(f"{self.problem.id}: in the impact {name}, {key} is {a} by generalized momenta "
                                       f"and {b} by impulses")
            # where no impulse from outside has a moment about a point, Newton–Euler's velocities
            # keep the angular momentum about it (and with none at all, the momentum)
            with_touch = self._scene_with((*self._struck_with(name), self._chain.made[name]))
            kept = impacts.conserved(with_touch, self.coordinates, before,
                                     {**before, **second.velocities})
            for was, now in zip(*(iter(kept.equations if kept else ()),) * 2):
                if agree(was.rhs, now.rhs) is None:
                    raise CheckFailure(f"{self.problem.id}: in the impact {name}, {was.lhs} is {was.rhs} before and "
                                       f"{now.rhs} after")

    def _move_check(self, name: str) -> None:
        """The state after a move or a turn by Lagrange (momenta of the rigid motions that leave the
        Lagrangian and the gaps unchanged) and by Newton–Euler (angular momenta about points where
        the forces from outside have no moment) agree, symbolically."""
        by_lagrange = self._chain.impacts[name]
        start = self.scene.states[name].start
        by_moments = self._move(name, self.states[start].values, self._chain.joints[start], "newton_euler")
        kind = self.scene.states[name].event.kind
        if by_lagrange.loose != by_moments.loose:
            raise CheckFailure(f"{self.problem.id}: after the {kind} {name}, the Lagrangian's symmetries leave "
                               f"{by_lagrange.loose} loose and moments about points {by_moments.loose}")
        for key, a in by_lagrange.values.items():
            if agree(a, by_moments.values[key]) is None:
                raise CheckFailure(f"{self.problem.id}: after the {kind} {name}, {key} is {a} by the Lagrangian's "
                                   f"symmetries and {by_moments.values[key]} by moments about points")

    def _work_energy_check(self) -> Check:
        """d(T + V)/dt = power of the applied non-conservative forces, with the solved accelerations,
        on motions the constraints allow: the constraint forces do no work. Each side in balls,
        with Lagrange's accelerations and forces solved in balls (else exactly, at 30 digits)."""
        coords = self.coordinates
        kinds = set()
        for index, regime in enumerate(self.regimes):
            ledger = self.energy_ledger(regime.scene)
            rate = coords.ddt(ledger["kinetic_translational"] + ledger["kinetic_rotational"] + ledger["potential"])
            lagrange_route = self._regime_derivations(index)["lagrange"]
            for state in self._check_states(index):
                left, right = rate.xreplace(state), ledger["power_nonconservative"].xreplace(state)
                try:
                    verdict = by_balls(left, right, [lagrange_route.balls_at(state)])
                except ValueError:
                    verdict = None
                if verdict is None:
                    solved = lagrange_route.at(state).raw
                    verdict = agree(left.xreplace(solved), right.xreplace(solved), symbolic=False) is not None
                if not verdict:
                    raise CheckFailure(f"{self.problem.id}: the work-energy theorem fails"
                                       + (f" where the {regime.name}" if regime.name else ""))
            kinds.add(ledger["power_nonconservative"] == 0)
        kind = "conserved" if kinds == {True} else "changes by the work of the applied forces"
        return Check("work_energy", True, "numeric", f"T + V {kind}; constraints do no work",
                     self._work_energy_reading(kinds == {True}))

    def _work_energy_reading(self, conserved: bool) -> str:
        """What the work-energy check says, true of this scene: a sliding contact's kinetic friction
        does work (the other constraint forces none); an event (an impact, a move) changes the energy
        in an instant the check's motions leave out, so the energy is conserved only between events.

        "Energy is conserved: the constraint forces do no work." had stood beside a sticky impact's loss."""
        sliding = any("slip" in r.name for r in self.regimes)
        events = sorted({_EVENT_WORDS[s.event.kind] for s in self.scene.states.values() if s.event is not None})
        between = " while the bodies move between the events" if events else ""
        if conserved:
            reading = f"Energy is conserved{between}: the constraint forces do no work"
        elif sliding:
            reading = (f"The energy changes{between} only by the work of the applied forces and of kinetic friction "
                       "where it slides: the other constraint forces do no work")
        else:
            reading = f"The energy changes{between} only by the work of the applied forces: the constraint forces do no work"
        if events:
            reading += f"; {' and '.join(events)}, in an instant, is not part of this check"
        return reading + "."

    @kept
    def _check_states(self, index: int) -> list[dict[sp.Symbol, sp.Expr]]:
        """The states the routes and the work-energy checks compare in the index-th friction
        regime: motions on its constraints, at sample parameters (the checks are numeric, and each
        derivative along a motion is then taken of a number-valued geometry, not of the general
        one). The same states for both checks: each route solves them once."""
        routes = self._regime_derivations(index).values()
        symbols = set().union(*(e.free_symbols for d in routes for e in [*d.balances, *d.rates]))
        symbols -= self.coordinates.state | {u for d in routes for u in d.unknowns}
        parameters = sample_points(self.problem, sp.Add(*symbols), count=1)[0] if symbols else {}
        return self._states_on_constraints(scene=self.regimes[index].scene, parameters=parameters)

    def _states_on_constraints(self, count: int = 2, scene=None, parameters=None) -> list[dict[sp.Symbol, sp.Expr]]:
        """Motions the constraints of the scene (by default the one the derivations describe)
        allow: the reference configuration (where every gap vanishes) with random velocities
        solving dg/dt = 0 (with `parameters`, at those values, which the states then include).
        Off the constraints the two routes' descriptions of a curved contact differ, so only
        states on them are compared."""
        coords = self.coordinates
        parameters = parameters or {}
        rates = [coords.ddt(g).xreplace(parameters) for c in (scene or self.dynamics_scene).constraints
                 for g in c.gaps(coords)]
        at_reference = {c.q: 0 for c in coords.all}
        velocities = [c.u for c in coords.all]
        matrix, rhs = sp.linear_eq_to_matrix([r.xreplace(at_reference) for r in rates], velocities)
        # at sample parameters a coefficient zero only by nested roots' identities (a cord's run to a
        # weight hanging straight down, for its x) is a number: zero where it vanishes to 60 digits,
        # else rref took it for a pivot and the velocities came out near 1e77, then NaN
        matrix = matrix.applyfunc(lambda e: sp.Integer(0) if e.is_number and e != 0 and abs(sp.N(e, 60)) < 1e-45 else e)
        reduced, pivots = row_reduced(matrix.row_join(rhs))  # once: the free velocities, the rest in them
        free = [u for i, u in enumerate(velocities) if i not in pivots]
        solvable = len(velocities) not in pivots
        rng = random.Random(2)
        states = []
        for _ in range(count):
            chosen = {u: sp.Rational(rng.randint(-90, 90), 37) for u in free}
            solved = {velocities[p]: reduced(row, len(velocities)) - sum(
                (reduced(row, velocities.index(u)) * value for u, value in chosen.items()), sp.Integer(0))
                for row, p in enumerate(pivots)} if solvable else {}
            states.append({**parameters, **at_reference, **chosen, **solved})
        return states

    def _orbit_check(self) -> Check:
        """Lagrange's and Newton's radial equations agree; for an ellipse, the energy is the same
        at both turning points (where the velocity is l / r)."""
        orbit = self.scene.orbit
        l = sp.Symbol("l", positive=True)
        routes = [orbits.radial_acceleration(orbit.GM, l, route) for route in ROUTES]
        if agree(*routes) is None:
            raise CheckFailure(f"{self.problem.id}: the radial equations differ: {routes}")
        detail = "radial equations agree"
        if orbit.semi_major_axis is not None:
            k = orbits.kepler(orbit.GM, orbit.semi_major_axis, orbit.eccentricity)
            at = [(k["angular_momentum"] / d) ** 2 / 2 - orbit.GM / d for d in (k["periapsis"], k["apoapsis"])]
            if agree(*at) is None or agree(at[0], k["energy"]) is None:
                raise CheckFailure(f"{self.problem.id}: the energy differs at periapsis and apoapsis")
            detail += "; energy equal at periapsis and apoapsis"
            if orbit.periapsis_speed is not None:  # the ellipse gives back the file's periapsis and speed there
                given = orbit.periapsis_speed
                if agree(k["periapsis"], given[0]) is None or agree(k["speed_at_periapsis"], given[1]) is None:
                    raise CheckFailure(f"{self.problem.id}: the ellipse does not give back its periapsis and speed")
                detail += "; the ellipse gives back the periapsis and its speed"
        return Check("lagrange_vs_newton_euler", True, "symbolic", detail,
                     "Lagrange's method and Newton's second law give the same orbit.")

    def _energy_check(self) -> Check:
        """Energy conservation gives the same speeds as the accelerations integrated."""
        methods = set()
        for body, balance in self.energy_balances.items():
            dynamics = self.contact_expression(body, "speed_at_bottom", self.derivations["lagrange"])
            method = agree(balance.speed, dynamics)
            if method is None:
                raise CheckFailure(f"{self.problem.id}: energy gives {balance.speed}, dynamics {dynamics} for {body}")
            methods.add(method)
        return Check("energy_vs_dynamics", True, "symbolic" if methods == {"symbolic"} else "numeric",
                     f"speeds of {', '.join(self.energy_balances)} agree",
                     "Energy conservation and the equations of motion give the same speeds.")


def same_at_samples(problem: Problem, a: sp.Expr, b: sp.Expr, count: int = 3) -> bool:
    """Whether `a` and `b` are the same expression at `count` points of the ranges (`sample_points`), by
    derive.numbers.agreement: how a student's route tells that a finding is the key's."""
    return agree(a, b, points=sample_points(problem, sp.Tuple(a, b), count=count)) is not None


def sample_points(problem: Problem, expr: sp.Expr, count: int = 5) -> list[dict[sp.Symbol, sp.Expr]]:
    """Points where `expr` can be evaluated, in SI units like the answers: parameters inside
    their ranges (the middle, then random draws), sizes the problem leaves open at positive
    values, open angles in (0, pi/2)."""
    rng = random.Random(1)
    by_symbol = {p.symbol: p for p in problem.parameters.values()}
    points = []
    for i in range(count):
        point = {}
        for s in sorted(expr.free_symbols, key=str):  # in one order whatever the hash seed: the same points
            p = by_symbol.get(s)
            si = units.si_factor(units.parse_unit(p.unit)) if p is not None else 1
            if p is not None and p.range is not None:
                fraction = sp.Rational(1, 2) if i == 0 else sp.Rational(rng.randint(1, 99), 100)
                point[s] = (p.range[0] + fraction * (p.range[1] - p.range[0])) * si
            elif p is not None and p.value is not None:
                point[s] = p.value * si
            else:
                point[s] = sp.Rational(rng.randint(5, 145), 100)  # open sizes; below pi/2 for angles
        points.append(point)
    return points
