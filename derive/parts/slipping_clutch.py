"""A slipping clutch: two turning bodies (or a body and the ground, a brake) whose plates rub
with a kinetic friction couple of a given size against their relative turning, until they turn
together (a disk dropped onto a turning one, a brake that stops a wheel). The state where they
grip is `when: {grips: NAME}` (derive.mechanics.states.grip); from then on the scene has a
clutch (derive.parts.clutch) of the same name in its place.

Lagrange: the couple's power, -C |omega_body - omega_to| (its generalized forces are
-C sign(omega_body - omega_to) times the rates' derivatives). Newton–Euler: the couple
-C sign(omega_body - omega_to) on the body, its opposite on the other.

>>> import sympy as sp
>>> from derive.model.scene import Body, Scene
>>> from derive.model.kinematics import Coordinates
>>> C, I = sp.symbols("C I", positive=True)
>>> scene = Scene({n: Body(n, "custom", sp.Symbol("M"), {}, I) for n in ("top", "bottom")})
>>> coords = Coordinates(scene)
>>> top, bottom = coords.angular_velocity("top"), coords.angular_velocity("bottom")
>>> SlippingClutch("plates", "top", "bottom", C).loads(coords)[0].torque == -C * sp.sign(top - bottom)
True
"""
from __future__ import annotations

from dataclasses import dataclass

import sympy as sp

from derive.parts import AppliedTorque, Part, at_placement
from derive.text.prose import Sentence


@dataclass(frozen=True)
class SlippingClutch(Part):
    """`body` rubbing on `to` (None: the ground) with a kinetic couple of size `couple`."""

    name: str
    body: str
    to: str | None
    couple: sp.Expr

    def bodies(self) -> tuple[str, ...]:
        return (self.body,) if self.to is None else (self.body, self.to)

    def slip(self, coords) -> sp.Expr:
        """The plates' relative rate, omega_body - omega_to: zero where they grip."""
        return coords.angular_velocity(self.body) - (coords.angular_velocity(self.to) if self.to else 0)

    def power(self, coords) -> sp.Expr:
        return -self.couple * sp.Abs(self.slip(coords))

    def loads(self, coords) -> list[AppliedTorque]:
        couple = -self.couple * sp.sign(self.slip(coords))
        label = f"kinetic couple {self.name}"
        return [AppliedTorque(self.body, couple, label)] + (
            [AppliedTorque(self.to, -couple, label)] if self.to else [])

    def sentences(self, route: str, coords) -> list[Sentence]:
        other = "the ground" if self.to is None else f"the {self.to}"
        if route == "lagrange":
            return [Sentence((f"The plates of {self.name} rub with a kinetic couple of size ", self.couple, " against the "
                              f"turning of the {self.body} relative to {other}; its power is always negative: ",
                              at_placement(self.power(coords), coords), "."))]
        loads = self.loads(coords)
        result = [Sentence((f"The plates of {self.name} turn the {self.body} against its slip with the couple ",
                            loads[0].torque, "."), self.body)]
        if self.to is not None:
            result.append(Sentence((f"They turn the {self.to} with the opposite couple.",), self.to))
        return result
