"""A linear spring between two points (of bodies or of the ground), with a rest length.

Lagrange: V = k (l - l0)^2 / 2 with l the distance between the points. Newton–Euler: the force
k (l - l0) at each end, pulling it toward the other (pushing when compressed).

>>> import sympy as sp
>>> from derive.model.scene import Body, Scene
>>> from derive.model.kinematics import Coordinates
>>> k, m = sp.symbols("k m", positive=True)
>>> scene = Scene({"block": Body("block", "point", m, {}, at=(sp.Integer(1), sp.Integer(0)))})
>>> Spring("s", ("block", None), ((0, 0), (0, 0)), k, sp.Integer(1)).potential(Coordinates(scene))
k*(sqrt(y_block**2 + (-x_block - 1)**2) - 1)**2/2
"""
from __future__ import annotations

from dataclasses import dataclass

import sympy as sp

from derive.core.keys import Key, Keys
from derive.parts import AppliedForce, Part, acting, at_placement
from derive.text.prose import Sentence


@dataclass(frozen=True)
class Spring(Part):
    """A spring of `stiffness` and `rest_length` between `ends` (two bodies, None for the ground)
    at `offsets` (body frame from the center of mass, or points of the ground)."""

    name: str
    ends: tuple[str | None, str | None]
    offsets: tuple[tuple, tuple]
    stiffness: sp.Expr
    rest_length: sp.Expr

    def bodies(self) -> tuple[str, ...]:
        return tuple(b for b in self.ends if b is not None)

    def _points(self, coords) -> list[sp.Matrix]:
        return [coords.position(b, o) for b, o in zip(self.ends, self.offsets)]

    def length(self, coords) -> sp.Expr:
        first, second = self._points(coords)
        return sp.sqrt((second - first).dot(second - first))

    def tension(self, coords) -> sp.Expr:
        """The force the spring pulls its ends together with (negative: it pushes them apart)."""
        return self.stiffness * (self.length(coords) - self.rest_length)

    def potential(self, coords) -> sp.Expr:
        return self.stiffness * (self.length(coords) - self.rest_length) ** 2 / 2

    def loads(self, coords) -> list[AppliedForce]:
        first, second = self._points(coords)
        along = (second - first) / self.length(coords)
        pull = self.tension(coords) * along
        result = []
        for body, offset, force in ((self.ends[0], self.offsets[0], pull), (self.ends[1], self.offsets[1], -pull)):
            if body is not None:
                result.append(AppliedForce(body, coords.rotated(body, offset), force, f"spring {self.name}"))
        return result

    def sentences(self, route: str, coords) -> list[Sentence]:
        if route == "lagrange":
            return [Sentence((f"The spring {self.name} stores half its stiffness times the square of its stretch: ",
                              self.potential(coords), "."))]
        pull = at_placement(self.tension(coords), coords)
        if pull == 0:
            return [Sentence((f"The spring {self.name} has its rest length where the {body} is placed, so it pulls it with "
                              "no force there (its stiffness times its stretch).",), body) for body in self.bodies()]
        return [Sentence((f"The spring {self.name} pulls the {load.body} toward its other end with its stiffness times "
                          "its stretch, ", pull, *acting(load, coords), "."), load.body) for load in self.loads(coords)]


KEYS = Keys(between=Key("points", "the two points it joins", required=True),
            stiffness=Key("expression", "its stiffness, in N/m", required=True),
            rest_length=Key("expression", "its length unstretched, in m (default: the distance between the points as "
                                          "placed)"),
            name=Key("name", "its name in the equations (default springN)"))


def read(reader, places, name: str, spec: dict, field: str) -> Spring:
    """`{between: [POINT, POINT], stiffness: k, rest_length: L0}` (rest length by default the
    distance between the points in the reference configuration: unstretched there)."""
    spec = reader.mapping(spec, field, keys=KEYS)
    ends = places.two_points(spec["between"], f"{field}.between")
    stiffness = reader.positive(spec["stiffness"], f"{field}.stiffness", "N/m", "a stiffness")
    first, second = (places.world(b, o) for b, o in ends)
    if "rest_length" in spec:
        rest = reader.dimensioned(spec["rest_length"], f"{field}.rest_length", "m", "a length")
    else:
        rest = sp.sqrt((second - first).dot(second - first))
    return Spring(name, (ends[0][0], ends[1][0]), (ends[0][1], ends[1][1]), stiffness, rest)

