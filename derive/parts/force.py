"""A given force at a point of a body, in a fixed direction (a push, a pull at the axle).

Lagrange: its power F . v_P (Q_j = dP/du_j). Newton–Euler: the force at the point.

>>> import sympy as sp
>>> F = sp.Symbol("F", positive=True)
>>> Force("push", "rod", (sp.Integer(1), sp.Integer(0)), F, sp.pi / 2).vector.T
Matrix([[0, F]])
"""
from __future__ import annotations

from dataclasses import dataclass

import sympy as sp

from derive.core.keys import Key, Keys
from derive.parts import AppliedForce, Part, acting, at_placement
from derive.text.prose import Sentence


@dataclass(frozen=True)
class Force(Part):
    """`magnitude` on `body` at `offset` (body frame, from its center of mass), toward `angle`
    (from +x, counter-clockwise), fixed in space."""

    name: str
    body: str
    offset: tuple[sp.Expr, sp.Expr]
    magnitude: sp.Expr
    angle: sp.Expr

    @property
    def vector(self) -> sp.Matrix:
        return self.magnitude * sp.Matrix([sp.cos(self.angle), sp.sin(self.angle)])

    def bodies(self) -> tuple[str, ...]:
        return (self.body,)

    def power(self, coords) -> sp.Expr:
        return self.vector.dot(coords.velocity(self.body, coords.rotated(self.body, self.offset)))

    def loads(self, coords) -> list[AppliedForce]:
        return [AppliedForce(self.body, coords.rotated(self.body, self.offset), self.vector, f"force {self.name}")]

    def sentences(self, route: str, coords) -> list[Sentence]:
        if route == "lagrange":
            return [Sentence((f"The force {self.name} does work at the rate of the force times the velocity of its point, "
                              "along the force: its power is ", at_placement(self.power(coords), coords), "."))]
        (load,) = self.loads(coords)
        return [Sentence((f"The force {self.name}, ", self.magnitude, " at the angle ", self.angle, " from the horizontal, "
                          f"pushes the {self.body}", *acting(load, coords), "."), self.body)]


KEYS = Keys(on=Key("point", "the point of a body it acts at (BODY or BODY.POINT)", required=True),
            magnitude=Key("expression", "its magnitude in N; may be a function of t", required=True),
            angle=Key("quantity", "its direction from +x, counter-clockwise (default 0)"),
            name=Key("name", "its name in the equations (default forceN)"))


def read(reader, places, name: str, spec: dict, field: str) -> Force:
    """`{on: BODY.POINT, magnitude: F, angle: EXPR}` (angle from +x, counter-clockwise; default 0)."""
    spec = reader.mapping(spec, field, keys=KEYS)
    body, offset = places.point(spec["on"], f"{field}.on", ground=False)
    places.on_body(body, offset, f"{field}.on")
    magnitude = reader.dimensioned(spec["magnitude"], f"{field}.magnitude", "N", "a force", places.with_time())
    angle = reader.dimensioned(spec.get("angle", 0), f"{field}.angle", "rad", "an angle")
    return Force(name, body, offset, magnitude, angle)
