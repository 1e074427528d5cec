"""A pin: a point of a body turns about a point of the ground or of another body.

Lagrange: the two points coincide, g = P_body(q) - P_other(q) (x and y), each multiplier the
reaction's component on the body. Newton–Euler: the reaction R at the body's point, -R at the
other body's point; their material points have the same velocity.

>>> import sympy as sp
>>> from derive.model.scene import Body, Scene
>>> from derive.model.kinematics import Coordinates
>>> d = sp.Symbol("d", positive=True)
>>> scene = Scene({"rod": Body("rod", "custom", sp.Symbol("M"), {}, sp.Symbol("I"))})
>>> Pin("hinge", "rod", (0, d)).gaps(Coordinates(scene))
[-d*sin(theta_rod) + x_rod, d*cos(theta_rod) - d + y_rod]
>>> Pin("axle", "rod", (0, 0)).sentences("newton_euler", Coordinates(scene))[0].latex()
'The axle pushes on the rod with its reaction at its center of mass, so it exerts no torque about it.'
"""
from __future__ import annotations

from dataclasses import dataclass

import sympy as sp

from derive.core.keys import Key, Keys
from derive.parts import AppliedForce, Part, acting
from derive.text.prose import Sentence


@dataclass(frozen=True)
class Pin(Part):
    """`body`'s point at `offset` (body frame, from its center of mass) pinned to the ground (`to`
    None: where the point is in the reference configuration) or to body `to`'s point at `to_offset`."""

    name: str
    body: str
    offset: tuple[sp.Expr, sp.Expr]
    to: str | None = None
    to_offset: tuple[sp.Expr, sp.Expr] = (sp.Integer(0), sp.Integer(0))

    def bodies(self) -> tuple[str, ...]:
        return (self.body,) if self.to is None else (self.body, self.to)

    def unknowns(self) -> dict[str, sp.Symbol]:
        return {"reaction.x": sp.Symbol(f"R_x^{self.name}", real=True),
                "reaction.y": sp.Symbol(f"R_y^{self.name}", real=True)}

    def _other(self, coords) -> sp.Matrix:
        if self.to is None:
            return coords.position(self.body, self.offset).xreplace(coords.at_rest_in_reference())
        return coords.position(self.to, self.to_offset)

    def gaps(self, coords) -> list[sp.Expr]:
        return list(coords.position(self.body, self.offset) - self._other(coords))

    def loads(self, coords) -> list[AppliedForce]:
        f = self.unknowns()
        reaction = sp.Matrix([f["reaction.x"], f["reaction.y"]])
        label = f"reaction of {self.name}"
        result = [AppliedForce(self.body, coords.rotated(self.body, self.offset), reaction, label)]
        if self.to is not None:
            result.append(AppliedForce(self.to, coords.rotated(self.to, self.to_offset), -reaction, label))
        return result

    @property
    def title(self) -> str:
        """How a sentence names it: the axle, the pivot (a body's joint), or the pin NAME."""
        return f"the {self.name}" if self.name in ("axle", "pivot") else f"the pin {self.name}"

    def sentences(self, route: str, coords) -> list[Sentence]:
        point = "center" if not any(self.offset) else "pinned point"
        there = "in place" if self.to is None else f"to the {self.to}'s point there"
        if route == "lagrange":
            f = self.unknowns()
            return [Sentence((f"{self.title.capitalize()} holds the {self.body}'s {point} {there}: the gap between the "
                              "two points is held by the multipliers ", f["reaction.x"], " and ", f["reaction.y"],
                              ", the components of its reaction."))]
        loads = self.loads(coords)
        result = [Sentence((f"{self.title.capitalize()} pushes on the {self.body} with its reaction", *acting(loads[0], coords),
                            "."), self.body)]
        if self.to is not None:
            result.append(Sentence((f"{self.title.capitalize()} pushes back on the {self.to} with the opposite reaction",
                                    *acting(loads[1], coords), "."), self.to))
        moves = "does not move" if self.to is None else f"moves with the {self.to}'s point there"
        return result + [Sentence((f"The {self.body}'s {point} on {self.title} {moves}.",))]

    def conditions(self, coords) -> list[sp.Expr]:
        here = coords.velocity(self.body, coords.rotated(self.body, self.offset))
        there = coords.velocity(self.to, coords.rotated(self.to, self.to_offset)) if self.to else sp.zeros(2, 1)
        return list(here - there)


KEYS = Keys(pin=Key("point", "the point of a body that is pinned (BODY.POINT)", required=True),
            to=Key("point", "the other body's point it is pinned to (default: the ground where the point is)"))


def read(reader, places, name: str, spec: dict, field: str) -> Pin:
    """`{pin: BODY.POINT}` (to the ground where the point is) or `{pin: POINT, to: POINT}` (to
    another body's point, or a point of the ground, where the first point is)."""
    spec = reader.mapping(spec, field, keys=KEYS)
    body, offset = places.point(spec["pin"], f"{field}.pin", ground=False)
    places.on_body(body, offset, f"{field}.pin")
    if "to" not in spec or spec["to"] == "ground":
        return Pin(name, body, offset)
    to, to_offset = places.point(spec["to"], f"{field}.to")
    if to == body:
        raise reader.fail(f"{field}.to", f"a pin joins two bodies, or a body and the ground: not the {body} to itself")
    if to is not None:
        places.on_body(to, to_offset, f"{field}.to")
    if not places.coincide(places.world(body, offset), places.world(to, to_offset)):
        raise reader.fail(f"{field}.to", f"the two points of the pin are apart in the reference configuration "
                          f"({sp.sstr(list(places.world(body, offset)))} and "
                          f"{sp.sstr(list(places.world(to, to_offset)))}): place the bodies with at (a massless "
                          "arm or string between two points is a cord: a cords: entry, `NAME: [POINT, POINT]`)")
    return Pin(name, body, offset) if to is None else Pin(name, body, offset, to, to_offset)
