"""A slider: a point of a body keeps to a fixed straight line (a bead on a wire, a cart on a
track); unless the body may turn (`turns`), the slider also keeps it from turning (a carriage in
its guide).

Lagrange: the point's distance from the line, n . (P - P0) (multiplier: the normal force along
n) and, locked, the body's turn (multiplier: the guide's couple). Newton–Euler: the normal force
at the point and the couple; the point does not move across the line, the body does not turn.

>>> import sympy as sp
>>> sorted(Slider("track", "cart", (0, 0), sp.Integer(0)).unknowns())
['normal', 'torque']
"""
from __future__ import annotations

from dataclasses import dataclass

import sympy as sp

from derive.core.keys import Key, Keys
from derive.parts import AppliedForce, AppliedTorque, Part, acting
from derive.text.prose import Sentence


@dataclass(frozen=True)
class Slider(Part):
    """`body`'s point at `offset` keeps to the line through its reference position at `angle`
    (from +x); `turns`: the body may turn."""

    name: str
    body: str
    offset: tuple[sp.Expr, sp.Expr]
    angle: sp.Expr
    turns: bool = False

    @property
    def across(self) -> sp.Matrix:
        """The unit normal of the line (its direction turned a quarter counter-clockwise)."""
        return sp.Matrix([-sp.sin(self.angle), sp.cos(self.angle)])

    def bodies(self) -> tuple[str, ...]:
        return (self.body,)

    def unknowns(self) -> dict[str, sp.Symbol]:
        result = {"normal": sp.Symbol(f"N^{self.name}", real=True)}
        if not self.turns:
            result["torque"] = sp.Symbol(f"M^{self.name}", real=True)
        return result

    def gaps(self, coords) -> list[sp.Expr]:
        point = coords.position(self.body, self.offset)
        result = [self.across.dot(point - point.xreplace(coords.at_rest_in_reference()))]
        if not self.turns:
            result.append(coords.angle(self.body))
        return result

    def loads(self, coords) -> list[AppliedForce | AppliedTorque]:
        f = self.unknowns()
        result = [AppliedForce(self.body, coords.rotated(self.body, self.offset), f["normal"] * self.across,
                               f"normal force of {self.name}")]
        if not self.turns:
            result.append(AppliedTorque(self.body, f["torque"], f"couple of {self.name}"))
        return result

    def sentences(self, route: str, coords) -> list[Sentence]:
        f = self.unknowns()
        held = () if self.turns else (f", and the {self.body}'s angle by its couple ", f["torque"])
        if route == "lagrange":
            return [Sentence((f"The slider {self.name} keeps the {self.body}'s point on a line at the angle ", self.angle,
                              " from the horizontal: the gap across the line is held by its normal force ", f["normal"],
                              *held, "."))]
        loads = self.loads(coords)
        result = [Sentence((f"The slider {self.name} pushes the {self.body} across its line with the normal force ",
                            f["normal"], *acting(loads[0], coords), "."), self.body)]
        if not self.turns:
            result.append(Sentence((f"It holds the {self.body} from turning with the couple ", f["torque"], "."),
                                   self.body))
        still = "" if self.turns else f", and the {self.body} does not turn"
        return result + [Sentence((f"The {self.body}'s point on the slider {self.name} does not move across its line"
                                   f"{still}.",))]

    def conditions(self, coords) -> list[sp.Expr]:
        result = [self.across.dot(coords.velocity(self.body, coords.rotated(self.body, self.offset)))]
        if not self.turns:
            result.append(coords.angular_velocity(self.body))
        return result


KEYS = Keys(slider=Key("point", "the point of a body that keeps to a line (BODY or BODY.POINT)", required=True),
            angle=Key("quantity", "the line's angle from +x, counter-clockwise (default 0, level)"),
            turns=Key("boolean", "whether the body may turn as it slides (default false)"))


def read(reader, places, name: str, spec: dict, field: str) -> Slider:
    """`{slider: BODY.POINT, angle: EXPR, turns: false}`: the point keeps to the line through it
    at `angle` (default 0, level); the body does not turn unless `turns: true`."""
    spec = reader.mapping(spec, field, keys=KEYS)
    body, offset = places.point(spec["slider"], f"{field}.slider", ground=False)
    places.on_body(body, offset, f"{field}.slider")
    angle = reader.dimensioned(spec.get("angle", 0), f"{field}.angle", "rad", "an angle")
    turns = spec.get("turns", False)
    if not isinstance(turns, bool):
        raise reader.fail(f"{field}.turns", "expected true or false")
    if not places.bodies[body].rotates:
        turns = True  # a point mass has no angle to lock
    return Slider(name, body, offset, angle, turns)
