"""A given torque on a body (a motor, a brake's couple): constant, or a function of the time t.

Lagrange: its power tau omega. Newton–Euler: the couple in the body's torque balance.

>>> import sympy as sp
>>> Torque("motor", "wheel", sp.Symbol("tau")).bodies()
('wheel',)
"""
from __future__ import annotations

from dataclasses import dataclass

import sympy as sp

from derive.parts import AppliedTorque, Part, acting
from derive.prose import Sentence


@dataclass(frozen=True)
class Torque(Part):
    """A couple `torque` (counter-clockwise positive) on `body`."""

    name: str
    body: str
    torque: sp.Expr

    def bodies(self) -> tuple[str, ...]:
        return (self.body,)

    def power(self, coords) -> sp.Expr:
        return self.torque * coords.angular_velocity(self.body)

    def loads(self, coords) -> list[AppliedTorque]:
        return [AppliedTorque(self.body, self.torque, f"torque {self.name}")]

    def sentences(self, route: str, coords) -> list[Sentence]:
        if route == "lagrange":
            return [Sentence((f"The torque {self.name} does work at the rate of the torque times the {self.body}'s angular "
                              "velocity: its power is ", self.power(coords), "."))]
        (load,) = self.loads(coords)
        return [Sentence((f"The torque {self.name}, ", self.torque, f" counter-clockwise, acts on the {self.body}",
                          *acting(load, coords), "."), self.body)]


def read(reader, places, name: str, spec: dict, field: str) -> Torque:
    """`{on: BODY, magnitude: EXPR}`: a couple (counter-clockwise positive), constant or a
    function of the time t."""
    spec = reader.mapping(spec, field, required=("on", "magnitude"), optional=("name",))
    body, offset = places.point(spec["on"], f"{field}.on", ground=False)
    if any(offset) or not places.bodies[body].rotates:
        raise reader.fail(f"{field}.on", "a torque acts on a turning body as a whole: name the body")
    return Torque(name, body, reader.dimensioned(spec["magnitude"], f"{field}.magnitude", "N*m", "a torque",
                                                 places.with_time()))
