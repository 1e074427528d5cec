"""A body resting on a surface, in one of three regimes: rolling without slipping (a normal force
and static friction), smooth sliding (a normal force only), or sliding with kinetic friction
mu_k N against the slip. A round body touches a radius below its center; a point mass at it.

Lagrange: the gap to the surface (multiplier: the normal force) and, rolling, the distance rolled
plus R theta (multiplier: the friction along the surface); kinetic friction is power,
P = mu_k N s (t . v_contact), with s the direction it acts. Newton–Euler: the forces at the point
of contact; it does not move into the surface and, rolling, not along it either.

Which regime a body is in, when the file gives mu_s (and mu_k), is decided by derive.answers:
rolling while the friction it needs is at most mu_s N, kinetic sliding beyond.

>>> import sympy as sp
>>> c = Contact("ball_contact", "ball", "ramp", True)
>>> sorted(c.unknowns())
['friction', 'normal']
"""
from __future__ import annotations

from dataclasses import dataclass

import sympy as sp

from derive.parts import AppliedForce, Part, Sign


@dataclass(frozen=True)
class Contact(Part):
    """`body` on the surface named `surface`: `rolling`, or sliding (smooth unless `kinetic`, the
    coefficient mu_k, with `direction` +1 or -1: the friction acts along +t or -t). `static` is
    mu_s when the file gives it."""

    name: str
    body: str
    surface: str
    rolling: bool
    static: sp.Expr | None = None
    kinetic: sp.Expr | None = None
    direction: int = 0

    def bodies(self) -> tuple[str, ...]:
        return (self.body,)

    @property
    def has_friction(self) -> bool:
        """The file gives a coefficient: derive.mechanics.friction decides the regime."""
        return self.static is not None or self.kinetic is not None

    @property
    def regime(self) -> str:
        if self.rolling:
            return "rolling"
        return "kinetic" if self.direction else "sliding"

    def unknowns(self) -> dict[str, sp.Symbol]:
        result = {"normal": sp.Symbol(f"N^{self.body}", real=True)}
        if self.rolling:
            result["friction"] = sp.Symbol(f"f^{self.body}", real=True)
        return result

    def _geometry(self, coords):
        surface = coords.scene.surfaces[self.surface]
        radius = coords.scene.bodies[self.body].sizes.get("radius", sp.Integer(0))
        return surface, coords.position(self.body), radius

    def offset(self, coords) -> sp.Matrix:
        """World offset from the body's center to the point touching the surface."""
        surface, center, radius = self._geometry(coords)
        return -radius * surface.normal_at(center, radius)

    def gaps(self, coords) -> list[sp.Expr]:
        surface, center, radius = self._geometry(coords)
        result = [surface.gap(center, radius)]
        if self.rolling:
            result.append(surface.arc(center, radius) + radius * coords.angle(self.body))
        return result

    def _kinetic_force(self, coords) -> sp.Matrix:
        surface, center, radius = self._geometry(coords)
        return self.kinetic * self.direction * self.unknowns()["normal"] * surface.tangent_at(center, radius)

    def power(self, coords) -> sp.Expr:
        if self.regime != "kinetic":
            return sp.Integer(0)
        return self._kinetic_force(coords).dot(coords.velocity(self.body, self.offset(coords)))

    def loads(self, coords) -> list[AppliedForce]:
        surface, center, radius = self._geometry(coords)
        f = self.unknowns()
        offset = self.offset(coords)
        result = [AppliedForce(self.body, offset, f["normal"] * surface.normal_at(center, radius), "normal force")]
        if self.rolling:
            result.append(AppliedForce(self.body, offset, f["friction"] * surface.tangent_at(center, radius),
                                       "static friction"))
        elif self.regime == "kinetic":
            result.append(AppliedForce(self.body, offset, self._kinetic_force(coords), "kinetic friction"))
        return result

    def conditions(self, coords) -> list[sp.Expr]:
        surface, center, radius = self._geometry(coords)
        touching = coords.velocity(self.body, self.offset(coords))
        result = [touching.dot(surface.normal_at(center, radius))]
        if self.rolling:
            result.append(touching.dot(surface.tangent_at(center, radius)))
        return result

    def signs(self) -> list[Sign]:
        normal = self.unknowns()["normal"]
        return [Sign(normal, f"the {self.body} leaves the surface {self.surface} (its normal force would be "
                             "negative)")]
