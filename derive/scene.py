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


@dataclass(frozen=True)
class Quantity:
    """A quantity a problem may ask of its scene, parsed from a dotted path.

    kinds: "inertia" (target a body, detail an axis), "acceleration" (a body; x or y),
    "angular_acceleration" (a body), "force" (a constraint; tension, reaction.x, reaction.y),
    "small_oscillation" (detail omega or period).
    """

    kind: str
    target: str | None
    detail: str | None


#: The forces each constraint kind exerts, as an answer path names them.
CONSTRAINT_FORCES = {Pin: ("reaction.x", "reaction.y"), WoundString: ("tension",)}

def parse_quantity(scene: Scene, path: str, axis: str | None = None) -> Quantity:
    """Parse an answer path such as ``block.acceleration.y`` against a scene.

    Raises ValueError with a one-line reason when the path names nothing in the scene.

    >>> import sympy as sp
    >>> scene = Scene({"ball": Body("ball", "point", sp.Symbol("m"), {})})
    >>> parse_quantity(scene, "ball.acceleration.y")
    Quantity(kind='acceleration', target='ball', detail='y')
    """
    head, _, rest = path.partition(".")
    if head == "small_oscillation":
        if rest not in ("omega", "period"):
            raise ValueError("small_oscillation has omega and period")
        return Quantity("small_oscillation", None, rest)
    if head in scene.bodies:
        body = scene.bodies[head]
        if rest == "inertia":
            shape = inertia.SHAPES.get(body.shape)
            axes = tuple(shape.axes) if shape else ()
            if axis is None and body.shape != "point":
                return Quantity("inertia", head, None)
            if axis not in axes:
                raise ValueError(f"axis of a {body.shape} is one of: {', '.join(axes) or 'none'}")
            return Quantity("inertia", head, axis)
        if rest in ("acceleration.x", "acceleration.y"):
            return Quantity("acceleration", head, rest[-1])
        if rest == "angular_acceleration" and body.rotates:
            return Quantity("angular_acceleration", head, None)
        raise ValueError(f"a body has inertia, acceleration.x, acceleration.y, angular_acceleration; not {rest!r}")
    names = {c.name: c for c in scene.constraints}
    if head in names:
        allowed = CONSTRAINT_FORCES[type(names[head])]
        if rest not in allowed:
            raise ValueError(f"{head} has {', '.join(allowed)}; not {rest!r}")
        return Quantity("force", head, rest)
    known = sorted(scene.bodies) + sorted(names) + ["small_oscillation"]
    raise ValueError(f"{head!r} is neither a body nor a constraint of the scene (known: {', '.join(known)})")
