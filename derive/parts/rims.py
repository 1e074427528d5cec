"""Two round bodies on fixed axles that roll on each other at their rims (a friction drive, two
disks pressed together until they stop slipping). Made by the event `{lock: A, to: B, at: rims}`
(derive.mechanics.impacts): from that instant their rims' points at the contact move together.

The contact point P is fixed in space (both centers are), `s_A` and `s_B` the distances from each
center to P along the unit vector n from A's center toward B's (s_B < 0 where B lies outside A,
> 0 inside it). A friction force F along t = z x n acts on A at P, -F on B there.

Lagrange: the rims' points at P do not slip along t, g = t . (c_A - c_B) + s_A theta_A - s_B theta_B
- k (k: its value when they lock; exact while the axles hold the centers): the multiplier is F,
since dg/dc_A = t and dg/dtheta_A = s_A, the moment of F about A's axle. Newton–Euler: F t on A at
s_A n from its center, -F t on B at s_B n from its own; the rims' points at P have the same
velocity along t (with the centers at rest, s_A omega_A - s_B omega_B = 0).

>>> import sympy as sp
>>> from derive.model.scene import Body, Scene
>>> from derive.model.kinematics import Coordinates
>>> R1, R2 = sp.symbols("R1 R2", positive=True)
>>> scene = Scene({n: Body(n, "custom", sp.Symbol("M"), {}, sp.Symbol("I")) for n in ("one", "two")})
>>> Rims("grip", "one", "two", (1, 0), R1, -R2).conditions(Coordinates(scene))
[R1*thetadot_one + R2*thetadot_two + ydot_one - ydot_two]
"""
from __future__ import annotations

from dataclasses import dataclass

import sympy as sp

from derive.core.tidying import tidy
from derive.parts import AppliedForce, Part
from derive.text.prose import Sentence


@dataclass(frozen=True)
class Rims(Part):
    """`body` and `to` rolling on each other at their rims, the contact along the world direction
    `normal` (a unit vector from `body`'s center toward `to`'s) at `reach` from `body`'s center and
    `to_reach` from `to`'s (signed along `normal`); `arc`: the gap's terms when they lock."""

    name: str
    body: str
    to: str
    normal: tuple[sp.Expr, sp.Expr]
    reach: sp.Expr
    to_reach: sp.Expr
    arc: sp.Expr = sp.Integer(0)

    def bodies(self) -> tuple[str, ...]:
        return (self.body, self.to)

    @property
    def title(self) -> str:
        return f"the rims' grip {self.name}"

    def unknowns(self) -> dict[str, sp.Symbol]:
        return {"friction": sp.Symbol(f"F^{self.name}", real=True)}

    def _tangent(self) -> sp.Matrix:
        return sp.Matrix([-self.normal[1], self.normal[0]])

    def gaps(self, coords) -> list[sp.Expr]:
        shift = self._tangent().dot(coords.position(self.body) - coords.position(self.to))
        return [shift + self.reach * coords.angle(self.body) - self.to_reach * coords.angle(self.to) - self.arc]

    def loads(self, coords) -> list[AppliedForce]:
        n = sp.Matrix(self.normal)
        push = self.unknowns()["friction"] * self._tangent()
        label = f"friction of {self.name}"
        return [AppliedForce(self.body, self.reach * n, push, label),
                AppliedForce(self.to, self.to_reach * n, -push, label)]

    def conditions(self, coords) -> list[sp.Expr]:
        n = sp.Matrix(self.normal)
        slip = coords.velocity(self.body, self.reach * n) - coords.velocity(self.to, self.to_reach * n)
        return [tidy(self._tangent().dot(slip))]

    def sentences(self, route: str, coords) -> list[Sentence]:
        friction = self.unknowns()["friction"]
        if route == "lagrange":
            return [Sentence((f"The rims of the {self.body} and the {self.to} roll on each other: the arcs they turn "
                              "through at the contact are equal, and the friction ", friction, " between them is the "
                              "multiplier of that constraint."))]
        return [Sentence((f"The {self.to}'s rim pushes on the {self.body}'s with the friction ", friction, " along the "
                          "tangent at the contact, a moment ", self.reach * friction, " about its center."), self.body),
                Sentence((f"The {self.body}'s rim pushes back on the {self.to}'s with the opposite friction, a moment ",
                          -self.to_reach * friction, " about its center."), self.to),
                Sentence((f"The rims of the {self.body} and the {self.to} move together at the contact: ",
                          sp.Eq(self.conditions(coords)[0], 0), "."))]
