"""A given torque on a body (a motor, a brake's couple): constant, or a function of the time t.

Lagrange: its power tau omega. Newton–Euler: the couple in the body's torque balance. On a body
turning in 3D about a fixed point at its center of mass (`pivot_point: {at: center}`), a couple
about a direction fixed in the ground (`axis: [x, y, z]`) that acts for a time (`duration`):
derive.mechanics.angular_impulse takes it, not the planar routes.

>>> import sympy as sp
>>> Torque("motor", "wheel", sp.Symbol("tau")).bodies()
('wheel',)
"""
from __future__ import annotations

from dataclasses import dataclass

import sympy as sp

from derive.core.keys import Key, Keys
from derive.parts import AppliedTorque, Part, acting
from derive.text.prose import Sentence


@dataclass(frozen=True)
class Torque(Part):
    """A couple `torque` (counter-clockwise positive) on `body`; in 3D, about the unit direction
    `axis` fixed in the ground, from t = 0 for the time `duration` (None in the plane)."""

    name: str
    body: str
    torque: sp.Expr
    axis: tuple[sp.Expr, sp.Expr, sp.Expr] | None = None
    duration: sp.Expr | None = None

    def bodies(self) -> tuple[str, ...]:
        return (self.body,)

    def power(self, coords) -> sp.Expr:
        return self.torque * coords.angular_velocity(self.body)

    def loads(self, coords) -> list[AppliedTorque]:
        return [AppliedTorque(self.body, self.torque, f"torque {self.name}")]

    def sentences(self, route: str, coords) -> list[Sentence]:
        if self.axis is not None:
            return [Sentence((f"The torque {self.name}, ", self.torque, " about the fixed direction ",
                              sp.Matrix(self.axis).T, f", acts on the {self.body} for the time ", self.duration,
                              ": its angular impulse about the fixed point is ", self.torque * self.duration, "."),
                             self.body)]
        if route == "lagrange":
            return [Sentence((f"The torque {self.name} does work at the rate of the torque times the {self.body}'s angular "
                              "velocity: its power is ", self.power(coords), "."))]
        (load,) = self.loads(coords)
        return [Sentence((f"The torque {self.name}, ", self.torque, f" counter-clockwise, acts on the {self.body}",
                          *acting(load, coords), "."), self.body)]


KEYS = Keys(on=Key("name", "the turning body the couple acts on", required=True),
            magnitude=Key("expression", "the couple in N m, counter-clockwise positive; may be a function of t",
                          required=True),
            axis=Key("vector", "in 3D: the direction [x, y, z] fixed in the ground the couple is about"),
            duration=Key("expression", "in 3D: how long the couple acts, in s"),
            name=Key("name", "its name in the equations (default torqueN)"))


def read(reader, places, name: str, spec: dict, field: str) -> Torque:
    """`{on: BODY, magnitude: EXPR}`: a couple (counter-clockwise positive), constant or a
    function of the time t; in 3D `{on: BODY, magnitude: tau, axis: [0, 0, 1], duration: dt}`, a
    constant couple about a direction fixed in the ground for a time (scene_file checks that the
    body turns about a fixed point at its center of mass)."""
    spec = reader.mapping(spec, field, keys=KEYS)
    body, offset = places.point(spec["on"], f"{field}.on", ground=False)
    if any(offset) or not places.bodies[body].rotates:
        raise reader.fail(f"{field}.on", "a torque acts on a turning body as a whole: name the body")
    if ("axis" in spec) != ("duration" in spec):
        raise reader.fail(f"{field}.{'duration' if 'axis' in spec else 'axis'}", "a couple in 3D is about a direction "
                          "fixed in the ground for a time: give both axis: [x, y, z] and duration: dt")
    if "axis" not in spec:
        return Torque(name, body, reader.dimensioned(spec["magnitude"], f"{field}.magnitude", "N*m", "a torque",
                                                     places.with_time()))
    raw = spec["axis"]
    if not isinstance(raw, list) or len(raw) != 3:
        raise reader.fail(f"{field}.axis", "a direction in the ground, [x, y, z] (z up)")
    axis = sp.Matrix([reader.dimensioned(c, f"{field}.axis[{i}]", "1", "a direction's component")
                      for i, c in enumerate(raw)])
    length = sp.sqrt(axis.dot(axis))
    if length.is_positive is not True:
        raise reader.fail(f"{field}.axis", "a direction: not zero for any allowed parameter value")
    return Torque(name, body, reader.dimensioned(spec["magnitude"], f"{field}.magnitude", "N*m", "a constant torque"),
                  tuple(sp.simplify(c / length) for c in axis),
                  reader.positive(spec["duration"], f"{field}.duration", "s", "a duration"))
