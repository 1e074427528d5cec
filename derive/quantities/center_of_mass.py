"""Where the center of mass of every body is: `center_of_mass.position.x` (or `.y`), in the file's
axes, at the placement at rest or `in: STATE`.

    x_cm = (m_1 x_1 + m_2 x_2 + ...) / (m_1 + m_2 + ...)

Route 0 (the key's): the mass-weighted mean of the bodies' centers. Route 1, its check: the
bodies added one at a time, as a textbook finds a composite's center: the center of the first
two, then of that and the third, and so on, each the balance point of two masses.

>>> from derive.language.problem import load
>>> from derive.solution.answers import Solution
>>> problem = load("diatomic_molecule")
>>> CENTER_OF_MASS.claims(problem.scene, "center_of_mass", "position.x")
Quantity(kind='center_of_mass', target=None, detail='x')
"""
from __future__ import annotations

import sympy as sp

from derive.core.tidying import tidy
from derive.model.scene import Quantity
from derive.quantities.base import QuantityKind


class CenterOfMass(QuantityKind):
    """The position of the center of mass of every body (see the module)."""

    kind = "center_of_mass"
    symbol = "x_cm"
    unit = "m"
    state = "optional"
    routes = ("the mass-weighted mean of the bodies' centers", "the bodies added one at a time")

    def claims(self, scene, head: str, rest: str) -> Quantity | None:
        if head != "center_of_mass" or not rest.startswith("position"):
            return None
        if rest not in ("position.x", "position.y"):
            raise ValueError("the center of mass has position.x and position.y")
        return Quantity(self.kind, None, rest[-1])

    def value(self, solution, ask, route: int) -> sp.Expr:
        coords = solution.coordinates
        where = solution.states[ask.state].values if ask.state else coords.at_rest_in_reference()
        index = 0 if ask.quantity.detail == "x" else 1
        bodies = [(b.mass, coords.position(n)[index].xreplace(where)) for n, b in solution.scene.bodies.items()]
        if route == 0:
            return tidy(sum(m * x for m, x in bodies) / sum(m for m, _ in bodies))
        mass, center = bodies[0]
        for m, x in bodies[1:]:
            mass, center = mass + m, (mass * center + m * x) / (mass + m)
        return tidy(center)

    def symbol_for(self, ask) -> str:
        return "{}_cm".format(ask.quantity.detail)

    def describe(self, ask) -> str:
        return f"the {ask.quantity.detail} of the center of mass"


CENTER_OF_MASS = CenterOfMass()
