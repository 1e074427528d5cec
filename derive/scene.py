"""The scene model: bodies, joints and constraints, loads — data only, no physics.

A scene is planar: the xy plane with y up, angles counter-clockwise (+z) positive,
as in the lecture notes. `derive.problem` builds a Scene from a problem file; the
modules in `derive.mechanics` derive its motion.

>>> import sympy as sp
>>> m = sp.Symbol("m", positive=True)
>>> Scene(bodies={"ball": Body("ball", "point", m, {})}).degrees_of_freedom()
2
"""
from __future__ import annotations

from dataclasses import dataclass

import sympy as sp

from derive import inertia

#: Body shapes a scene may use, with the size names each needs.
SHAPE_SIZES: dict[str, tuple[str, ...]] = {
    "point": (),
    "rod": ("length",),
    "ring": ("radius",),
    "disk": ("radius",),
    "custom": (),
}


@dataclass(frozen=True)
class Body:
    """A rigid body (or a point mass) in the plane.

    `inertia` is the moment of inertia about the axis through the center of mass normal to
    the plane: given for a custom body, otherwise integrated by `derive.inertia`.
    """

    name: str
    shape: str
    mass: sp.Expr
    sizes: dict[str, sp.Expr]
    given_inertia: sp.Expr | None = None

    @property
    def rotates(self) -> bool:
        """A point mass has no orientation; every other body has an angle."""
        return self.shape != "point"

    @property
    def inertia(self) -> sp.Expr:
        if self.given_inertia is not None:
            return self.given_inertia
        return inertia.central_moment(self.shape, self.mass, self.sizes)


@dataclass(frozen=True)
class Pin:
    """A body turns about a point fixed in space (a fixed axle or a pivot).

    `offset` is the pivot's position in the body's frame, from its center of mass, in the
    reference configuration (all angles zero): (0, 0) is an axle through the center;
    (0, d) a pivot a distance d above the center of mass, so the body hangs at angle 0.
    """

    name: str
    body: str
    offset: tuple[sp.Expr, sp.Expr]


@dataclass(frozen=True)
class WoundString:
    """A light inextensible cord wound on the rim of `reel`, hanging vertically to `load`.

    `side` is +1 when the cord leaves the rim on the right (x = +radius), -1 on the left.
    """

    name: str
    reel: str
    load: str
    side: int = 1


@dataclass(frozen=True)
class Gravity:
    """A uniform gravitational field of strength `g` along -y."""

    g: sp.Expr


Constraint = Pin | WoundString


@dataclass(frozen=True)
class Scene:
    """Bodies, constraints and loads; what `derive.mechanics` derives the motion of."""

    bodies: dict[str, Body]
    constraints: tuple[Constraint, ...] = ()
    gravity: Gravity | None = None

    def constraint(self, name: str) -> Constraint:
        for c in self.constraints:
            if c.name == name:
                return c
        raise KeyError(name)

    def degrees_of_freedom(self) -> int:
        """Coordinates (x, y and, for rotating bodies, an angle) less the scalar constraints."""
        coordinates = sum(3 if b.rotates else 2 for b in self.bodies.values())
        equations = sum(2 if isinstance(c, Pin) else 1 for c in self.constraints)
        return coordinates - equations

    def needs_dynamics(self) -> bool:
        return bool(self.constraints) or self.gravity is not None
