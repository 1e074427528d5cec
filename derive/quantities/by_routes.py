"""The quantities read from the whole derivation's solve (`ByRoutes`): an acceleration, a force, a
contact's, a rate in a state, an impulse, an equilibrium, a small or a finite oscillation.

Their values come out of the scene's equations of motion, by Lagrange's method (route 0, the key's)
and by the Newton–Euler equations (route 1): the Solution solves each route once for every ask
(`Solution.in_state`, `linearized`, `equilibria`, ...), and a module's `on_route` reads its quantity
from that solve. The routes check (derive.solution.crosschecks) compares the two routes' answers
and every acceleration and force at random states, so the kinds add no check of their own. Their
paths are parsed with the paths every body has (derive.model.scene.parse_quantity, a layer below),
and which state they are read in is derive.language.ask_states' (`state = "motion"`).

>>> from derive.quantities import KINDS
>>> KINDS["force"].routes
("Lagrange's method", 'the Newton–Euler equations')
"""
from __future__ import annotations

from abc import abstractmethod

import sympy as sp

from derive.model import directions
from derive.model.directions import Sense
from derive.model.scene import Quantity
from derive.quantities.base import Check, QuantityKind

#: The derivations' routes, by index: the key's, then its check.
ROUTES = ("lagrange", "newton_euler")


class ByRoutes(QuantityKind):
    """A quantity of the derivation's solve by both routes (see the module)."""

    unit = None  # by what is asked (m/s^2, N, m, s, ...): the ask's unit checked against the answer
    state = "motion"
    routes = ("Lagrange's method", "the Newton–Euler equations")
    own_section = False  # its steps are the derivation's, by route (derive.solution.answer_steps)

    def claims(self, scene, head: str, rest: str) -> Quantity | None:
        return None  # derive.model.scene.parse_quantity parses its paths, with every body's

    def value(self, solution, ask, route: int) -> sp.Expr:
        solution.refuse_undetermined(ask)
        return self.on_route(solution, ask, ROUTES[route])

    @abstractmethod
    def on_route(self, solution, ask, route: str) -> sp.Expr:
        """The answer read from the route's solve ("lagrange" or "newton_euler")."""

    def reads_motion(self, ask) -> bool:
        return True

    def checks(self, solution, names: list[str]) -> list[Check]:
        return []  # the routes check compares both routes (derive.solution.crosschecks._routes_check)

    def directional(self, quantity: Quantity) -> bool:
        return directions.directional(quantity)

    def sense_in(self, scene, quantity: Quantity, coords, sample) -> Sense | None:
        return directions.sense(scene, quantity, coords, sample)

    def describe(self, ask) -> str:
        return ask.meaning


class OneUnknown(ByRoutes):
    """A quantity that is one unknown of the routes' solve (a coordinate's acceleration, a constraint's
    force), read where it is asked (`in_state`), an unknown the student's route finds too."""

    @abstractmethod
    def _unknown(self, solution, ask) -> sp.Symbol:
        """The unknown of the routes' solve it is."""

    def on_route(self, solution, ask, route: str) -> sp.Expr:
        return solution.in_state(route, ask.state)[self._unknown(solution, ask)]

    def unknowns(self, solution, ask) -> set[sp.Symbol]:
        return {self._unknown(solution, ask)}

    def student_route(self, quantity) -> bool:
        return True
