"""The angular momentum of a point mass on a path in space about a fixed point, as a vector:
`BODY.angular_momentum.x|y|z|magnitude` for a body with `path: {cartesian: {x, y, z}}` (a particle
at a given position and velocity: x0 + vx*t, ...), as a textbook asks it in components; about the
origin, or `about: [x, y, z]`.

    L = (r - r_P) x p = m (r - r_P) x v

Route 0 (the key's): the cross product of the position from the point and the momentum, by
components. Route 1, its check: sympy.physics.mechanics, a Particle at a Point located from the fixed
point in an inertial frame, its angular_momentum about that point.

>>> ANGULAR_MOMENTUM.kind, ANGULAR_MOMENTUM.unit, ANGULAR_MOMENTUM.about_default
('particle_angular_momentum', 'kg*m^2/s', (0, 0, 0))
"""
from __future__ import annotations

import sympy as sp

from derive.core.expr import TIME
from derive.model.scene import Quantity
from derive.quantities.base import QuantityKind

COMPONENTS = ("x", "y", "z", "magnitude")


class ParticleAngularMomentum(QuantityKind):
    """A point mass's angular momentum about a fixed point, in space (see the module)."""

    kind = "particle_angular_momentum"
    symbol = "L"
    unit = "kg*m^2/s"
    routes = ("the cross product m r x v by components", "sympy.physics.mechanics' Particle.angular_momentum")
    options = ("about",)
    about_in_space = True
    about_default = (0, 0, 0)

    def claims(self, scene, head: str, rest: str) -> Quantity | None:
        body = scene.bodies.get(head)
        if body is None or body.path is None or body.path.kind != "cartesian" or not rest.startswith("angular_momentum."):
            return None
        detail = rest.partition(".")[2]
        if detail not in COMPONENTS:
            raise ValueError(f"a point mass's angular momentum in space has angular_momentum.{'|'.join(COMPONENTS)}")
        return Quantity(self.kind, head, detail)

    def value(self, solution, ask, route: int) -> sp.Expr:
        body = solution.scene.bodies[ask.quantity.target]
        about = ask.about.offset
        vector = _by_components(body, about) if route == 0 else by_mechanics(body, about)
        if ask.quantity.detail == "magnitude":
            return sp.simplify(sp.sqrt(vector.dot(vector)))
        return sp.simplify(vector["xyz".index(ask.quantity.detail)])

    def axis_of(self, quantity: Quantity) -> str | None:
        return None if quantity.detail == "magnitude" else quantity.detail

    def symbol_for(self, ask) -> str:
        return "L" if ask.quantity.detail == "magnitude" else f"L_{ask.quantity.detail}"

    def describe(self, ask) -> str:
        part = "the size" if ask.quantity.detail == "magnitude" else f"the {ask.quantity.detail} component"
        return f"{part} of the {ask.quantity.target}'s angular momentum about {ask.about.words}"


def _by_components(body, about) -> sp.Matrix:
    position = body.path.position3 - sp.Matrix(about)
    return body.mass * position.cross(position.diff(TIME))


def by_mechanics(body, about=(0, 0, 0)) -> sp.Matrix:
    """The body's angular momentum about the fixed point `about` (x, y, z), by sympy.physics.mechanics
    (also the route of derive.quantities.particle_torque's tau = dL/dt)."""
    from sympy.physics.mechanics import Particle, Point, ReferenceFrame

    frame = ReferenceFrame("N")
    fixed = Point("O")
    fixed.set_vel(frame, 0)
    x, y, z = body.path.position3 - sp.Matrix(about)
    point = fixed.locatenew("P", x * frame.x + y * frame.y + z * frame.z)
    point.set_vel(frame, point.pos_from(fixed).dt(frame))
    momentum = Particle("p", point, body.mass).angular_momentum(fixed, frame)
    return sp.Matrix([momentum.dot(frame.x), momentum.dot(frame.y), momentum.dot(frame.z)])


ANGULAR_MOMENTUM = ParticleAngularMomentum()
