"""Uniform gravity of strength g along -y, on every body.

Lagrange: V = sum m g y (heights from the reference configuration). Newton–Euler: the weight m g at each center of mass.

>>> import sympy as sp
>>> from derive.model.scene import Body, Scene
>>> from derive.model.kinematics import Coordinates
>>> m, g = sp.symbols("m g", positive=True)
>>> Gravity(g).potential(Coordinates(Scene({"ball": Body("ball", "point", m, {})})))
g*m*y_ball
>>> Gravity(g).sentences("newton_euler", Coordinates(Scene({"ball": Body("ball", "point", m, {})})))[0].text()
'The weight of the ball, g⋅m, pulls it straight down.'
"""
from __future__ import annotations

from dataclasses import dataclass

import sympy as sp

from derive.parts import AppliedForce, Part, acting
from derive.text.prose import Sentence


@dataclass(frozen=True)
class Gravity(Part):
    """A uniform gravitational field of strength `g` along -y."""

    g: sp.Expr
    name: str = "gravity"

    @property
    def title(self) -> str:
        return "gravity"

    def potential(self, coords) -> sp.Expr:
        return sum((b.mass * self.g * (coords.position(n)[1] - b.at[1]) for n, b in coords.scene.bodies.items()),
                   sp.Integer(0))

    def loads(self, coords) -> list[AppliedForce]:
        return [AppliedForce(n, sp.zeros(2, 1), sp.Matrix([0, -b.mass * self.g]), "weight")
                for n, b in coords.scene.bodies.items()]

    def sentences(self, route: str, coords) -> list[Sentence]:
        if route == "lagrange":
            return [Sentence(("Gravity gives each body the potential energy of its weight times its height above where "
                              "it is placed: ", self.potential(coords), "."))]
        return [Sentence((f"The weight of the {load.body}, ", -load.force[1], ", pulls it straight down",
                          *acting(load, coords), "."), load.body) for load in self.loads(coords)]


def read(reader, places, name: str, spec, field: str) -> Gravity:
    """`gravity: g` (a field strength in m/s^2, along -y)."""
    return Gravity(reader.positive(spec, field, "m/s^2", "a gravitational field"))
