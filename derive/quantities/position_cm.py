"""A body's position from the center of mass of every body: `BODY.position_cm.x` (or `.y`), where
the bodies are placed (a molecule's atoms, masses on a light rod).

    x_1 - x_cm

Route 0 (the key's): the body's position less the center of mass's. Route 1, its check: the
mass-weighted mean of its position from each body, sum_j m_j (x_1 - x_j) / M.

>>> from derive.language.problem import load
>>> POSITION_CM.claims(load("diatomic_molecule").scene, "atom1", "position_cm.x")
Quantity(kind='position_cm', target='atom1', detail='x')
"""
from __future__ import annotations

import sympy as sp

from derive.core.tidying import tidy
from derive.model.scene import Quantity
from derive.quantities.base import QuantityKind
from derive.model import placement


class PositionFromCenterOfMass(QuantityKind):
    """A body's position from the center of mass (see the module)."""

    kind = "position_cm"
    symbol = "x"
    unit = "m"
    routes = ("the position less the center of mass's", "the mean of its position from each body")

    def claims(self, scene, head: str, rest: str) -> Quantity | None:
        if head not in scene.bodies or not rest.startswith("position_cm"):
            return None
        if rest not in ("position_cm.x", "position_cm.y"):
            raise ValueError("a body's position from the center of mass has position_cm.x and position_cm.y")
        return Quantity(self.kind, head, rest[-1])

    def value(self, solution, ask, route: int) -> sp.Expr:
        scene, body = solution.scene, ask.quantity.target
        index = 0 if ask.quantity.detail == "x" else 1
        if route == 0:
            return tidy((placement.position(scene, body) - placement.center_of_mass(scene))[index])
        total = sum((b.mass for b in scene.bodies.values()), sp.Integer(0))
        return tidy(sum(((placement.position(scene, body) - placement.position(scene, n))[index] * b.mass
                         for n, b in scene.bodies.items()), sp.Integer(0)) / total)

    def symbol_for(self, ask) -> str:
        return "{}".format(ask.quantity.detail)

    def describe(self, ask) -> str:
        return f"the {ask.quantity.detail} of the {ask.quantity.target} from the center of mass"


POSITION_CM = PositionFromCenterOfMass()
