"""A clutch: two turning bodies locked to turn together (an engaged clutch, a disk dropped onto
another and carried by it), their centers left to the other parts (a shared axle); or a body held
from turning (a brake that grips). With `slipping: C` it is a slipping clutch until it grips
(derive.parts.slipping_clutch).

Lagrange: the angle between them stays what it was when they locked, g = theta_body -
theta_to - turn (the multiplier is the couple on the body). Newton–Euler: that couple on the
body, its opposite on the other; their angular velocities are equal.

>>> import sympy as sp
>>> from derive.model.scene import Body, Scene
>>> from derive.model.kinematics import Coordinates
>>> I = sp.Symbol("I")
>>> scene = Scene({n: Body(n, "custom", sp.Symbol("M"), {}, I) for n in ("top", "bottom")})
>>> Clutch("plates", "top", "bottom").gaps(Coordinates(scene))
[-theta_bottom + theta_top]
"""
from __future__ import annotations

from dataclasses import dataclass

import sympy as sp

from derive.core.keys import Key, Keys
from derive.parts import AppliedTorque, Part
from derive.parts.slipping_clutch import SlippingClutch
from derive.text.prose import Sentence


@dataclass(frozen=True)
class Clutch(Part):
    """`body` locked to turn with `to` (None: held by the ground), `turn` (their turns'
    difference from the placement) apart."""

    name: str
    body: str
    to: str | None
    turn: sp.Expr = sp.Integer(0)

    def bodies(self) -> tuple[str, ...]:
        return (self.body,) if self.to is None else (self.body, self.to)

    def unknowns(self) -> dict[str, sp.Symbol]:
        return {"torque": sp.Symbol(f"M^{self.name}", real=True)}

    def gaps(self, coords) -> list[sp.Expr]:
        return [coords.angle(self.body) - (coords.angle(self.to) if self.to else 0) - self.turn]

    def loads(self, coords) -> list[AppliedTorque]:
        couple = self.unknowns()["torque"]
        label = f"clutch {self.name}"
        return [AppliedTorque(self.body, couple, label)] + ([AppliedTorque(self.to, -couple, label)] if self.to else [])

    def sentences(self, route: str, coords) -> list[Sentence]:
        couple = self.unknowns()["torque"]
        other = "the ground" if self.to is None else f"the {self.to}"
        if route == "lagrange":
            return [Sentence((f"The clutch {self.name} locks the {self.body}'s angle to {other}'s: the couple ", couple,
                              " between them is the multiplier of that constraint."))]
        result = [Sentence((f"The clutch {self.name} turns the {self.body} with the couple ", couple,
                            ", which pushes its center nowhere."), self.body)]
        if self.to is not None:
            result.append(Sentence((f"The clutch {self.name} turns the {self.to} with the opposite couple.",), self.to))
        rate = "does not turn" if self.to is None else f"turns at the same rate as the {self.to}"
        return result + [Sentence((f"The {self.body} {rate}: the clutch {self.name} holds it.",))]

    def conditions(self, coords) -> list[sp.Expr]:
        return [coords.angular_velocity(self.body) - (coords.angular_velocity(self.to) if self.to else 0)]


KEYS = Keys(clutch=Key("name", "one of the two turning bodies", required=True),
            to=Key("name", "the other turning body, or ground (a brake)", required=True),
            slipping=Key("expression", "the kinetic friction couple in N m while the plates slip (until a state "
                                       "when: {grips: NAME})"))


def read(reader, places, name: str, spec: dict, field: str) -> Clutch | SlippingClutch:
    """`{clutch: BODY, to: OTHER}`: two turning bodies that turn together (`to: ground`: a
    brake that holds the body); with `slipping: C`, their plates slip with the kinetic couple C
    until they grip (a state `when: {grips: NAME}`)."""
    spec = reader.mapping(spec, field, keys=KEYS)
    body, _ = places.point(spec["clutch"], f"{field}.clutch", ground=False)
    to = None if spec["to"] == "ground" else places.point(spec["to"], f"{field}.to", ground=False)[0]
    if to == body:
        raise reader.fail(f"{field}.to", f"a clutch joins two bodies: not the {body} to itself")
    if not places.bodies[body].rotates or to is not None and not places.bodies[to].rotates:
        raise reader.fail(field, "a clutch locks two turning bodies together (a point mass does not turn)")
    if "slipping" in spec:
        return SlippingClutch(name, body, to, reader.positive(spec["slipping"], f"{field}.slipping", "N*m",
                                                              "a kinetic friction couple"))
    return Clutch(name, body, to)
