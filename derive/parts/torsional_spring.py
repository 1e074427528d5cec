"""A torsional spring on a body, against the ground or another body, with a rest angle.

Lagrange: V = kappa (phi - phi0)^2 / 2 with phi the body's turn (relative to the other body's).
Newton–Euler: the couple -kappa (phi - phi0) on the body and its opposite on the other.

>>> import sympy as sp
>>> TorsionalSpring("coil", "door", None, sp.Symbol("kappa"), sp.Integer(0)).bodies()
('door',)
"""
from __future__ import annotations

from dataclasses import dataclass

import sympy as sp

from derive.core.keys import Key, Keys
from derive.parts import AppliedTorque, Part, at_placement
from derive.text.prose import Sentence


@dataclass(frozen=True)
class TorsionalSpring(Part):
    """A spring of `stiffness` (torque per radian) turning `body` back toward `rest_angle`
    (its turn from the reference configuration, relative to `to`'s)."""

    name: str
    body: str
    to: str | None
    stiffness: sp.Expr
    rest_angle: sp.Expr

    def bodies(self) -> tuple[str, ...]:
        return (self.body,) if self.to is None else (self.body, self.to)

    def _twist(self, coords) -> sp.Expr:
        other = coords.angle(self.to) if self.to is not None else sp.Integer(0)
        return coords.angle(self.body) - other - self.rest_angle

    def potential(self, coords) -> sp.Expr:
        return self.stiffness * self._twist(coords) ** 2 / 2

    def loads(self, coords) -> list[AppliedTorque]:
        couple = -self.stiffness * self._twist(coords)
        result = [AppliedTorque(self.body, couple, f"torsional spring {self.name}")]
        if self.to is not None:
            result.append(AppliedTorque(self.to, -couple, f"torsional spring {self.name}"))
        return result

    def sentences(self, route: str, coords) -> list[Sentence]:
        if route == "lagrange":
            return [Sentence((f"The torsional spring {self.name} stores half its stiffness times the square of the "
                              f"{self.body}'s twist from its rest angle: ", self.potential(coords), "."))]
        result = []
        for load in self.loads(coords):
            couple = at_placement(load.torque, coords)
            result.append(Sentence((f"The torsional spring {self.name} is at its rest angle where the {load.body} is "
                                    "placed, so it exerts no couple on it there.",) if couple == 0 else
                                   (f"The torsional spring {self.name} turns the {load.body} back toward its rest angle "
                                    "with the couple ", couple, "."), load.body))
        return result


KEYS = Keys(on=Key("name", "the turning body it acts on", required=True),
            stiffness=Key("expression", "its stiffness, in N m/rad", required=True),
            to=Key("name", "the other turning body (default ground)"),
            rest_angle=Key("quantity", "the turn from the reference configuration at which it exerts no torque "
                                       "(default 0)"),
            name=Key("name", "its name in the equations (default torsional_springN)"))


def read(reader, places, name: str, spec: dict, field: str) -> TorsionalSpring:
    """`{on: BODY, to: OTHER, stiffness: kappa, rest_angle: EXPR}` (to the ground by default;
    rest angle: the turn from the reference configuration at which it exerts no torque, 0)."""
    spec = reader.mapping(spec, field, keys=KEYS)
    body, _ = places.point(spec["on"], f"{field}.on", ground=False)
    to = None if spec.get("to", "ground") == "ground" else places.point(spec["to"], f"{field}.to", ground=False)[0]
    for b in (body, to):
        if b is not None and not places.bodies[b].rotates:
            raise reader.fail(f"{field}.on", f"a torsional spring turns a body; the {b} is a point mass")
    stiffness = reader.positive(spec["stiffness"], f"{field}.stiffness", "N*m/rad", "a torsional stiffness")
    rest = reader.dimensioned(spec.get("rest_angle", 0), f"{field}.rest_angle", "rad", "an angle")
    return TorsionalSpring(name, body, to, stiffness, rest)
