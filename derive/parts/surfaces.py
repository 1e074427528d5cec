"""Surfaces a body can rest on: a plane at any angle, and a circle seen from inside (a bowl, a
loop, a cylinder) or from outside (a dome). A surface is fixed to the ground, or carried by a body
(`carrier`: a wedge's face, a plank's top, a cart's curved track), given where it is in the
reference configuration; `carried` moves it with its carrier.

Each gives, for a round body of radius r whose center is at C: `gap` (how far the body stands off
the surface; zero when it touches), `normal_at` (the unit vector from the surface toward the
center: the normal force's direction), `tangent_at` (t = (n_y, -n_x): down a plane that descends
to the right, up one that descends to the left, counter-clockwise inside a circle) and `arc` (the distance the center has travelled
along t: its rate is t . v). A point mass is a body of radius 0.

>>> import sympy as sp
>>> Plane("ramp", sp.pi / 6).normal_at(sp.Matrix([0, 1]), 1).T
Matrix([[1/2, sqrt(3)/2]])
>>> Circle("bowl", sp.Integer(2)).gap(sp.Matrix([0, 1]), 1)
0
"""
from __future__ import annotations

import dataclasses
from dataclasses import dataclass

import sympy as sp

from derive.parts.places import turned


@dataclass(frozen=True)
class Plane:
    """A fixed plane through `through`, descending at `angle` (0 is a level floor) to the right
    or, `descends="left"`, to the left (s = -1): down-slope unit vector (s cos angle, -sin angle),
    normal (s sin angle, cos angle). `height` is the drop from where bodies start to the bottom,
    when given. A wall is a plane at pi/2: its normal points the way it descends.

    >>> Plane("left_face", sp.pi / 3, descends="left").down.T
    Matrix([[-1/2, -sqrt(3)/2]])
    """

    name: str
    angle: sp.Expr
    height: sp.Expr | None = None
    through: tuple[sp.Expr, sp.Expr] = (sp.Integer(0), sp.Integer(0))
    carrier: str | None = None
    descends: str = "right"

    @property
    def _sign(self) -> int:
        return 1 if self.descends == "right" else -1

    @property
    def line_angle(self) -> sp.Expr:
        """The angle of its down-slope direction from +x, counter-clockwise, less pi where it
        descends to the left (the plane's line either way)."""
        return -self._sign * self.angle

    @property
    def down(self) -> sp.Matrix:
        return sp.Matrix([self._sign * sp.cos(self.angle), -sp.sin(self.angle)])

    @property
    def normal(self) -> sp.Matrix:
        return sp.Matrix([self._sign * sp.sin(self.angle), sp.cos(self.angle)])

    def touching(self, radius: sp.Expr) -> sp.Matrix:
        """Where a body of this radius has its center when it touches the plane at `through`."""
        return sp.Matrix(self.through) + radius * self.normal

    def gap(self, center: sp.Matrix, radius: sp.Expr) -> sp.Expr:
        return self.normal.dot(center - sp.Matrix(self.through)) - radius

    def normal_at(self, center: sp.Matrix, radius: sp.Expr) -> sp.Matrix:
        return self.normal

    def tangent_at(self, center: sp.Matrix, radius: sp.Expr) -> sp.Matrix:
        return self._sign * self.down

    def arc(self, center: sp.Matrix, radius: sp.Expr) -> sp.Expr:
        return self.tangent_at(center, radius).dot(center - sp.Matrix(self.through))


@dataclass(frozen=True)
class Circle:
    """A circle of `radius` about `center`, ridden on its `side`: "inside" (a bowl, a loop; by
    default its lowest point is at the origin) or "outside" (a dome; by default its highest point
    is at the origin). `turn`: how far its carrier has turned it (arcs are measured on it)."""

    name: str
    radius: sp.Expr
    center: tuple[sp.Expr, sp.Expr] | None = None
    side: str = "inside"
    carrier: str | None = None
    turn: sp.Expr = sp.Integer(0)

    @property
    def middle(self) -> sp.Matrix:
        if self.center is not None:
            return sp.Matrix(self.center)
        return sp.Matrix([0, self.radius if self.side == "inside" else -self.radius])

    @property
    def _sign(self) -> int:
        return 1 if self.side == "inside" else -1

    def path_radius(self, radius: sp.Expr) -> sp.Expr:
        """The radius of the circle a body's center moves on."""
        return self.radius - self._sign * radius

    def touching(self, radius: sp.Expr) -> sp.Matrix:
        """The center of a body touching the lowest point (inside) or the highest (outside)."""
        return self.middle - self._sign * sp.Matrix([0, self.path_radius(radius)])

    def gap(self, center: sp.Matrix, radius: sp.Expr) -> sp.Expr:
        offset = center - self.middle
        return self._sign * (self.path_radius(radius) - sp.sqrt(offset.dot(offset)))

    def normal_at(self, center: sp.Matrix, radius: sp.Expr) -> sp.Matrix:
        offset = self.middle - center
        return self._sign * offset / sp.sqrt(offset.dot(offset))

    def tangent_at(self, center: sp.Matrix, radius: sp.Expr) -> sp.Matrix:
        normal = self.normal_at(center, radius)
        return sp.Matrix([normal[1], -normal[0]])

    def arc(self, center: sp.Matrix, radius: sp.Expr) -> sp.Expr:
        """The path radius times the center's polar angle about the circle's center, measured from
        the touching point, counter-clockwise inside and clockwise outside, on the circle as its
        carrier has turned it."""
        offset = center - self.middle
        return self.path_radius(radius) * (sp.atan2(offset[0], -self._sign * offset[1]) - self._sign * self.turn)

    def top(self, radius: sp.Expr) -> sp.Matrix:
        """The highest point of the circle a body inside rides on."""
        return self.middle + sp.Matrix([0, self.path_radius(radius)])


Surface = Plane | Circle


def carried(surface: Surface, coords) -> Surface:
    """The surface where its carrier has moved it (turned with it about the carrier's center of
    mass, and shifted with it); a fixed surface as it is.

    >>> from derive.model.kinematics import Coordinates
    >>> from derive.model.scene import Body, Scene
    >>> scene = Scene({"wedge": Body("wedge", "point", sp.Symbol("M"), {})})
    >>> carried(Plane("face", sp.pi / 6, carrier="wedge"), Coordinates(scene)).through
    (x_wedge, y_wedge)
    """
    if surface.carrier is None:
        return surface
    body = coords.scene.bodies[surface.carrier]

    def moved(point) -> tuple[sp.Expr, sp.Expr]:
        local = turned(-body.angle, sp.Matrix(point) - sp.Matrix(body.at))  # in the carrier's own frame
        return tuple(coords.position(surface.carrier, local))

    turn = coords.angle(surface.carrier)  # counter-clockwise, since the reference configuration
    if isinstance(surface, Plane):  # its normal turns with the carrier: it descends less to the right
        return dataclasses.replace(surface, through=moved(surface.through), angle=surface.angle - surface._sign * turn)
    return dataclasses.replace(surface, center=moved(surface.middle), turn=turn)
