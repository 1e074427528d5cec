"""Kinematics of a prescribed path: velocity, acceleration, angular momentum, areal velocity.

Everything is derived from the Cartesian position (x(t), y(t)) by differentiation and
projection onto r-hat and theta-hat — the polar acceleration a_r = r'' - r theta'^2,
a_theta = 2 r' theta' + r theta'' comes out, it is not typed in. `by_mechanics` derives
the same components independently with sympy.physics.mechanics (a rotating frame).

>>> import sympy as sp
>>> r, w, t = sp.Symbol("r", positive=True), sp.Symbol("omega", positive=True), TIME
>>> path = Path("polar", (r, w * t))
>>> quantity(path, sp.Integer(1), "acceleration.radial")
-omega**2*r
>>> quantity(path, sp.Symbol("m"), "angular_momentum")
m*omega*r**2
"""
from __future__ import annotations

import sympy as sp

from derive.core.expr import TIME
from derive.model.scene import Path

def _simplify(expr: sp.Expr) -> sp.Expr:
    return sp.simplify(sp.trigsimp(sp.expand(expr)))


def quantity(path: Path, mass: sp.Expr, name: str) -> sp.Expr:
    """A kinematic quantity of a point mass on the path (z components for vectors; the speed in
    space where the path leaves the plane)."""
    position = path.position
    velocity = position.diff(TIME)
    acceleration = velocity.diff(TIME)
    _, theta = path.radius_and_angle
    r_hat = sp.Matrix([sp.cos(theta), sp.sin(theta)])
    theta_hat = sp.Matrix([-sp.sin(theta), sp.cos(theta)])
    cross = position[0] * velocity[1] - position[1] * velocity[0]
    values = {
        "velocity.x": lambda: velocity[0],
        "velocity.y": lambda: velocity[1],
        "speed": lambda: sp.sqrt(path.position3.diff(TIME).dot(path.position3.diff(TIME))),  # off the plane too
        "acceleration.x": lambda: acceleration[0],
        "acceleration.y": lambda: acceleration[1],
        "acceleration.radial": lambda: acceleration.dot(r_hat),
        "acceleration.tangential": lambda: acceleration.dot(theta_hat),
        "angular_momentum": lambda: mass * cross,
        "areal_velocity": lambda: cross / 2,
    }
    return _simplify(values[name]())


def by_mechanics(path: Path, mass: sp.Expr, name: str) -> sp.Expr:
    """The same quantity by sympy.physics.mechanics: a Point located in a frame turning with
    the polar angle, a Particle for the angular momentum (the cross-check route)."""
    from sympy.physics.mechanics import Particle, Point, ReferenceFrame

    r, theta = path.radius_and_angle
    inertial = ReferenceFrame("N")
    turning = inertial.orientnew("A", "Axis", [theta, inertial.z])
    origin = Point("O")
    origin.set_vel(inertial, 0)
    point = origin.locatenew("P", r * turning.x + path.z * inertial.z)
    velocity, acceleration = point.vel(inertial), point.acc(inertial)
    values = {
        "velocity.x": lambda: velocity.dot(inertial.x),
        "velocity.y": lambda: velocity.dot(inertial.y),
        "speed": lambda: velocity.magnitude(),
        "acceleration.x": lambda: acceleration.dot(inertial.x),
        "acceleration.y": lambda: acceleration.dot(inertial.y),
        "acceleration.radial": lambda: acceleration.dot(turning.x),
        "acceleration.tangential": lambda: acceleration.dot(turning.y),
        "angular_momentum": lambda: Particle("p", point, mass).angular_momentum(origin, inertial).dot(inertial.z),
        "areal_velocity": lambda: point.pos_from(origin).cross(velocity).dot(inertial.z) / 2,
    }
    return _simplify(values[name]())
