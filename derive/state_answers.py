"""Answers in the named states of a scene (`scene.states`, `in: STATE`): where each state is
(derive.mechanics.states), each route's accelerations and forces there, the rates, positions and
times asked in it, the conditions a variant must meet for the motion to get there, and the steps
a worked solution shows. A mixin of derive.answers.Solution, which gives it the scene, the
coordinates, the routes' derivations and the parameter ranges.

>>> from derive.problem import load
>>> from derive.answers import Solution
>>> solution = Solution(load("tests/textbook/states/rod_swings_down.yaml"))
>>> solution.expression("omega")
sqrt(3)*sqrt(g)/sqrt(L)
"""
from __future__ import annotations

import dataclasses
import functools
from functools import cached_property

import sympy as sp

from derive import limits
from derive.mechanics import states as state_motion
from derive.mechanics.derivation import Solved, Step, root, tidy
from derive.parts.contact import Contact
from derive.parts.surfaces import Plane
from derive.scene import Quantity


class StateAnswers:
    """What Solution answers in a named state."""

    @cached_property
    def states(self) -> dict[str, state_motion.Reached]:
        """Every coordinate and velocity in each named state of the scene (derive.mechanics.states):
        the placement moving at given rates, or where a coordinate gets to from another state."""
        if self.scene.states and len(self.regimes) > 1:
            raise self.problem.limit("read a state of a scene whose friction regime it decides (mu_s given): "
                                     "give contact: rolling or sliding")
        result = {}
        resolve = functools.partial(self._within_ranges, absolute=True)
        for name, state in self.scene.states.items():
            try:
                with limits.time_limit(f"finding the state {name}"):
                    reached = self._state(state, result)
                # |L0 - d|, |sin(theta0)|: in the form the parameter ranges give
                result[name] = dataclasses.replace(
                    reached, values={k: resolve(v) for k, v in reached.values.items()},
                    positive=tuple((resolve(e), m) for e, m in reached.positive))
            except state_motion.StateLimit as error:
                raise self.problem.limit(f"{error} (scene.states.{name})") from None
            except state_motion.StateError as error:
                raise self.problem.error(f"scene.states.{name}", str(error)) from None
        return result

    def _state(self, state, found: dict) -> state_motion.Reached:
        coords = self.coordinates
        if state.rates:
            return state_motion.moving(self.dynamics_scene, coords, {coords.of(body, kind): value
                                                                     for body, kind, value in state.rates})
        start = found[state.start].values if state.start else state_motion.rest(coords)
        return state_motion.reach(self.dynamics_scene, coords, start, self._condition(state),
                                  self.derivations["lagrange"], self._sample)

    def _condition(self, state) -> state_motion.Gets | state_motion.Stops | state_motion.Vanishes:
        """Where a state reached by the motion is: a coordinate's value, a stop, a force at zero."""
        if state.until is None:
            body, kind, value = state.when
            return state_motion.Gets(self.coordinates.of(body, kind), value - self.scene.bodies[body].placed(kind))
        kind, name = state.until
        if kind == "stops":
            return state_motion.Stops()
        part = self.dynamics_scene.constraint(name)
        force = part.unknowns()["normal"] if kind == "leaves" else next(iter(part.unknowns().values()))
        what = f"the normal force on the {part.body} at {name}" if kind == "leaves" else f"the tension of {name}"
        return state_motion.Vanishes(force, what)

    @functools.lru_cache(maxsize=None)  # noqa: B019 - one Solution per problem, two routes, a few states
    def in_state(self, route: str, name: str | None) -> Solved:
        """One route's accelerations and forces in a named state (None: the placement at rest)."""
        if name is None:
            return self.at_reference(route)
        reached, derivation = self.states[name], self.derivations[route]
        if reached.path is None:
            return self._solved(derivation, reached.values)
        # Along the path first (functions of its one coordinate s), then at the state: its values
        # hold roots of the whole scene's sizes (a ball leaving a dome), in which the linear solve
        # took 26 s against 1 s along the path.
        path = reached.path
        general, where, rate = path.general
        at = {where: reached.values[path.s], rate: reached.values[path.coordinate.u]}
        return Solved({u: v.xreplace(at) for u, v in self._solved(derivation, general, path.frozen).raw.items()})

    def _rate(self, q: Quantity, name: str) -> sp.Expr:
        """A body's velocity, speed, angular velocity, position or angle in a named state, or the
        time the motion takes to get there."""
        values, coords = self.states[name].values, self.coordinates
        if q.kind == "time":
            return self._duration(name)[0]
        if q.kind in ("angle", "position"):
            kind = "theta" if q.kind == "angle" else q.detail
            return tidy(self.scene.bodies[q.target].placed(kind) + values[coords.of(q.target, kind).q])
        if q.kind == "angular_velocity":
            return values[coords.of(q.target, "theta").u]
        if q.kind == "velocity":
            return values[coords.of(q.target, q.detail).u]
        return root(values[coords.of(q.target, "x").u] ** 2 + values[coords.of(q.target, "y").u] ** 2)

    @functools.lru_cache(maxsize=None)  # noqa: B019 - one Solution per problem, a few states
    def _duration(self, name: str) -> tuple[sp.Expr, Step]:
        reached = self.states[name]
        time, step = state_motion.duration(reached.path, reached.end)
        # |s1 - s0| by the ranges; an integral's integrand as it is (simplifying it cancels digits)
        return time.xreplace({a: self._within_ranges(a, absolute=True) for a in time.atoms(sp.Abs)}), step

    def _state_conditions(self) -> list[tuple[sp.Expr, bool, str]]:
        """In each state asked: the motion gets there, the state is on the scene's geometry, and
        the parts keep their signs there."""
        scene, result = self.dynamics_scene, []
        for name in dict.fromkeys(a.state for a in self.problem.asks.values() if a.state is not None):
            reached, forces = self.states[name], self.in_state("lagrange", name).raw
            result += [(expr, True, f"{meaning} ({name})") for expr, meaning in reached.positive]
            # the state is real: where a formula puts it off the scene's geometry (a ball higher
            # than its cord reaches), the motion never gets there at these values
            result += [(radicand, False, f"the motion never gets to the state {name} at these values (it lies off "
                                         "the scene's geometry there)")
                       for radicand in dict.fromkeys(p.base for v in reached.values.values() for p in v.atoms(sp.Pow)
                                                     if p.exp.is_Rational and p.exp.q == 2)]
            # (a force the state is defined by, zero there, has no sign to keep: it was positive on the way)
            result += [(sign.expression.xreplace(forces).xreplace(reached.values), False, f"{sign.meaning} ({name})")
                       for part in (*scene.constraints, *scene.loads) for sign in part.signs()
                       if not sign.expression.has(*reached.vanished)]
        return result + self._ramp_conditions()

    def _ramp_conditions(self) -> list[tuple[sp.Expr, bool, str]]:
        """An incline's height is how far it drops below where a body starts
        (derive.parts.surfaces.Plane): in every state the motion gets to, the body has not dropped
        past its bottom (where a formula for an endless plane would put it beyond, the variant is
        refused). Up the slope the plane goes on: a block pulled up it is not limited."""
        result = []
        for contact in self.dynamics_scene.constraints:
            surface = self.scene.surfaces.get(getattr(contact, "surface", None))
            if not isinstance(contact, Contact) or not isinstance(surface, Plane) or surface.height is None:
                continue
            for name, reached in self.states.items():
                if reached.path is None:
                    continue
                drop = -reached.values[self.coordinates.of(contact.body, "y").q]
                result.append((surface.height - drop, False, f"the {contact.body} would be past the bottom of "
                                                             f"{contact.surface} in the state {name} (it drops "
                                                             f"{sp.sstr(surface.height)} below where the "
                                                             f"{contact.body} starts)"))
        return result

    def _state_steps(self, result: dict[str, list[Step]]) -> None:
        """Add to a worked solution's steps, by route, how each state asked is found and the
        routes' solution there."""
        for name in dict.fromkeys(a.state for a in self.problem.asks.values() if a.state is not None):
            result[f"the state {name}"] = list(self.states[name].steps)
            if any(a.state == name and a.quantity.kind == "time" for a in self.problem.asks.values()):
                result[f"the state {name}"].append(self._duration(name)[1])
            in_state = self._needed_unknowns(name)
            for route, d in self.derivations.items() if in_state else ():
                solved = self.in_state(route, name)  # the answers' own solution there (along a path: by it)
                result[route] = [*(result[route] or d.steps),
                                 Step(f"Solving in the state {name}", tuple(sp.Eq(u, solved[u]) for u in d.unknowns
                                                                            if u in in_state))]
