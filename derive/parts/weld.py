"""A weld: a body held rigidly to another body or to the ground (a shelf on a wall, a part glued
to a wheel).

Lagrange: the body's center keeps its place in the other's frame and its angle the other's
(multipliers: the force on the body at its center, and the couple). Newton–Euler: that force
and couple on the body, their opposites on the other; the body's center moves with the other's
material point there, and both turn together.

>>> import sympy as sp
>>> sorted(Weld("glue", "shelf", None).unknowns())
['reaction.x', 'reaction.y', 'torque']
"""
from __future__ import annotations

from dataclasses import dataclass

import sympy as sp

from derive.core.keys import Key, Keys
from derive.parts import AppliedForce, AppliedTorque, Part, acting
from derive.text.prose import Sentence


@dataclass(frozen=True)
class Weld(Part):
    """`body` held rigidly to `to` (None: the ground) as they are in the reference configuration,
    or (`offset`, `turn`) with its center at `offset` in the other's frame and its turn `turn`
    more than the other's (a body that sticks to another in a state away from the placement)."""

    name: str
    body: str
    to: str | None
    offset: tuple[sp.Expr, sp.Expr] | None = None
    turn: sp.Expr = sp.Integer(0)

    def bodies(self) -> tuple[str, ...]:
        return (self.body,) if self.to is None else (self.body, self.to)

    def unknowns(self) -> dict[str, sp.Symbol]:
        return {"reaction.x": sp.Symbol(f"R_x^{self.name}", real=True),
                "reaction.y": sp.Symbol(f"R_y^{self.name}", real=True),
                "torque": sp.Symbol(f"M^{self.name}", real=True)}

    def _offset(self, coords) -> sp.Matrix:
        """Where the body's center sits in the other's frame (from its center of mass)."""
        if self.offset is not None:
            return sp.Matrix(self.offset)
        this, other = coords.scene.bodies[self.body], coords.scene.bodies[self.to]
        between = sp.Matrix(this.at) - sp.Matrix(other.at)
        turn = -other.angle
        return sp.Matrix([[sp.cos(turn), -sp.sin(turn)], [sp.sin(turn), sp.cos(turn)]]) * between

    def gaps(self, coords) -> list[sp.Expr]:
        center = coords.position(self.body)
        if self.to is None:
            held, angle = center.xreplace(coords.at_rest_in_reference()), sp.Integer(0)
        else:
            held, angle = coords.position(self.to, tuple(self._offset(coords))), coords.angle(self.to)
        return [*(center - held), coords.angle(self.body) - angle - self.turn]

    def loads(self, coords) -> list[AppliedForce | AppliedTorque]:
        f = self.unknowns()
        force = sp.Matrix([f["reaction.x"], f["reaction.y"]])
        label = f"weld {self.name}"
        result = [AppliedForce(self.body, sp.zeros(2, 1), force, label), AppliedTorque(self.body, f["torque"], label)]
        if self.to is not None:
            arm = coords.position(self.body) - coords.position(self.to)
            result += [AppliedForce(self.to, arm, -force, label), AppliedTorque(self.to, -f["torque"], label)]
        return result

    def sentences(self, route: str, coords) -> list[Sentence]:
        f = self.unknowns()
        other = "the ground" if self.to is None else f"the {self.to}"
        forces = (f["reaction.x"], " and ", f["reaction.y"])
        if route == "lagrange":
            return [Sentence((f"The weld {self.name} holds the {self.body} rigidly to {other}: its center's place is "
                              "held by the multipliers ", *forces, ", its angle by the couple ", f["torque"], "."))]
        result = [Sentence((f"The weld {self.name} acts on the {self.body} with the force components ", *forces,
                            " at its center of mass, so they exert no torque about it, and with the couple ",
                            f["torque"], "."), self.body)]
        if self.to is not None:
            result.append(Sentence((f"The weld {self.name} acts on the {self.to} with the opposite force and couple, the "
                                    "force", *acting(self.loads(coords)[2], coords), "."), self.to))
        held = "neither moves nor turns" if self.to is None else f"moves and turns with the {self.to}"
        return result + [Sentence((f"The {self.body} {held}: the weld {self.name} holds it.",))]

    def conditions(self, coords) -> list[sp.Expr]:
        velocity = coords.velocity(self.body, sp.zeros(2, 1))
        if self.to is None:
            return [*velocity, coords.angular_velocity(self.body)]
        carried = coords.velocity(self.to, coords.position(self.body) - coords.position(self.to))
        return [*(velocity - carried), coords.angular_velocity(self.body) - coords.angular_velocity(self.to)]


KEYS = Keys(weld=Key("name", "the turning body that is welded", required=True),
            to=Key("name", "the other turning body (default ground)"))


def read(reader, places, name: str, spec: dict, field: str) -> Weld:
    """`{weld: BODY}` (to the ground) or `{weld: BODY, to: OTHER}`."""
    spec = reader.mapping(spec, field, keys=KEYS)
    body, _ = places.point(spec["weld"], f"{field}.weld", ground=False)
    to = spec.get("to", "ground")
    if to != "ground":
        to, _ = places.point(to, f"{field}.to", ground=False)
        if to == body:
            raise reader.fail(f"{field}.to", f"a weld joins two bodies: not the {body} to itself")
    if not places.bodies[body].rotates or (to != "ground" and not places.bodies[to].rotates):
        raise reader.fail(field, "a weld holds turning bodies; a point mass fixed on a body is a part of it (shape: composite)")
    return Weld(name, body, None if to == "ground" else to)
