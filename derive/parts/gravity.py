"""Uniform gravity of strength g along -y, on every body.

Lagrange: V = sum m g y (heights from the reference configuration). Newton–Euler: the weight m g at each center of mass.

>>> import sympy as sp
>>> from derive.scene import Body, Scene
>>> from derive.mechanics.kinematics import Coordinates
>>> m, g = sp.symbols("m g", positive=True)
>>> Gravity(g).potential(Coordinates(Scene({"ball": Body("ball", "point", m, {})})))
g*m*y_ball
"""
from __future__ import annotations

from dataclasses import dataclass

import sympy as sp

from derive.parts import AppliedForce, Part


@dataclass(frozen=True)
class Gravity(Part):
    """A uniform gravitational field of strength `g` along -y."""

    g: sp.Expr
    name: str = "gravity"

    def potential(self, coords) -> sp.Expr:
        return sum((b.mass * self.g * (coords.position(n)[1] - b.at[1]) for n, b in coords.scene.bodies.items()),
                   sp.Integer(0))

    def loads(self, coords) -> list[AppliedForce]:
        return [AppliedForce(n, sp.zeros(2, 1), sp.Matrix([0, -b.mass * self.g]), "weight")
                for n, b in coords.scene.bodies.items()]


def read(reader, places, name: str, spec, field: str) -> Gravity:
    """`gravity: g` (a field strength in m/s^2, along -y)."""
    return Gravity(reader.positive(spec, field, "m/s^2", "a gravitational field"))
