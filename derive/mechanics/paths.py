"""Kinematics of a prescribed path: velocity, acceleration, angular momentum, areal velocity.

Everything is derived from the Cartesian position (x(t), y(t)) by differentiation and
projection onto r-hat and theta-hat — the polar acceleration a_r = r'' - r theta'^2,
a_theta = 2 r' theta' + r theta'' comes out, it is not typed in. `check_polar` derives
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

from derive.scene import TIME, Path

def _simplify(expr: sp.Expr) -> sp.Expr:
    return sp.simplify(sp.trigsimp(sp.expand(expr)))


def quantity(path: Path, mass: sp.Expr, name: str) -> sp.Expr:
    """A kinematic quantity of a point mass on the path (z components for vectors)."""
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
        "speed": lambda: sp.sqrt(velocity.dot(velocity)),
        "acceleration.x": lambda: acceleration[0],
        "acceleration.y": lambda: acceleration[1],
        "acceleration.radial": lambda: acceleration.dot(r_hat),
        "acceleration.tangential": lambda: acceleration.dot(theta_hat),
        "angular_momentum": lambda: mass * cross,
        "areal_velocity": lambda: cross / 2,
    }
    return _simplify(values[name]())


def check_polar(path: Path) -> tuple[sp.Expr, sp.Expr]:
    """Radial and tangential acceleration by sympy.physics.mechanics, for the cross-check."""
    from sympy.physics.mechanics import Point, ReferenceFrame

    r, theta = path.radius_and_angle
    inertial = ReferenceFrame("N")
    turning = inertial.orientnew("A", "Axis", [theta, inertial.z])
    origin = Point("O")
    origin.set_vel(inertial, 0)
    point = origin.locatenew("P", r * turning.x)
    components = point.acc(inertial).express(turning).to_matrix(turning)
    return _simplify(components[0]), _simplify(components[1])
