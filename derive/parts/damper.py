"""Viscous damping: a dashpot between two points (force -b times the rate of stretch, along the
line between them), or a rotational damper on a body (couple -c omega).

Lagrange: Rayleigh's dissipation function D = b (dl/dt)^2 / 2 or c omega^2 / 2 (Q_j = -dD/du_j).
Newton–Euler: the forces at the points, the couple on the body.

>>> import sympy as sp
>>> Damper("dashpot", ("block", None), ((0, 0), (0, 0)), sp.Symbol("b")).bodies()
('block',)
"""
from __future__ import annotations

from dataclasses import dataclass

import sympy as sp

from derive.core.keys import Key, Keys
from derive.parts import AppliedForce, AppliedTorque, Part, acting, at_placement
from derive.text.prose import Sentence


@dataclass(frozen=True)
class Damper(Part):
    """A dashpot of `coefficient` b between `ends` at `offsets` (as a Spring's); with one end
    and no offsets (`rotational`), a couple -b omega on that body."""

    name: str
    ends: tuple[str | None, str | None]
    offsets: tuple[tuple, tuple]
    coefficient: sp.Expr
    rotational: bool = False

    def bodies(self) -> tuple[str, ...]:
        return tuple(b for b in self.ends if b is not None)

    def _line(self, coords) -> tuple[sp.Matrix, sp.Expr]:
        """The unit vector from the first end to the second, and the rate of stretch along it."""
        points = [coords.position(b, o) for b, o in zip(self.ends, self.offsets)]
        between = points[1] - points[0]
        along = between / sp.sqrt(between.dot(between))
        velocities = [coords.velocity(b, coords.rotated(b, o)) if b is not None else sp.zeros(2, 1)
                      for b, o in zip(self.ends, self.offsets)]
        return along, along.dot(velocities[1] - velocities[0])

    def dissipation(self, coords) -> sp.Expr:
        if self.rotational:
            return self.coefficient * coords.angular_velocity(self.ends[0]) ** 2 / 2
        return self.coefficient * self._line(coords)[1] ** 2 / 2

    def loads(self, coords) -> list[AppliedForce | AppliedTorque]:
        if self.rotational:
            body = self.ends[0]
            return [AppliedTorque(body, -self.coefficient * coords.angular_velocity(body), f"damper {self.name}")]
        along, stretching = self._line(coords)
        pull = self.coefficient * stretching * along  # resists the stretch: pulls the ends together
        result = []
        for body, offset, force in ((self.ends[0], self.offsets[0], pull), (self.ends[1], self.offsets[1], -pull)):
            if body is not None:
                result.append(AppliedForce(body, coords.rotated(body, offset), force, f"damper {self.name}"))
        return result

    def sentences(self, route: str, coords) -> list[Sentence]:
        rate = "angular velocity" if self.rotational else "rate of stretch"
        if route == "lagrange":
            return [Sentence((f"The damper {self.name} dissipates energy: Rayleigh's function, half its coefficient times "
                              f"the square of its {rate}, is ", at_placement(self.dissipation(coords), coords), "."))]
        if self.rotational:
            (load,) = self.loads(coords)
            return [Sentence((f"The damper {self.name} turns the {load.body} against its angular velocity with the "
                              "couple ", at_placement(load.torque, coords), "."), load.body)]
        resisting = at_placement(self.coefficient * self._line(coords)[1], coords)
        return [Sentence((f"The damper {self.name} pulls the {load.body} toward its other end with its coefficient times "
                          "its rate of stretch, ", resisting, *acting(load, coords), "."), load.body)
                for load in self.loads(coords)]


KEYS = Keys(coefficient=Key("expression", "the damping coefficient: N s/m for a dashpot, N m s on a turning body",
                             required=True),
            between=Key("points", "the two points a dashpot joins (or on:)"),
            on=Key("name", "the turning body a rotational damper acts on (or between:)"),
            name=Key("name", "its name in the equations (default damperN)"))


def read(reader, places, name: str, spec: dict, field: str) -> Damper:
    """`{between: [POINT, POINT], coefficient: b}` (a dashpot, N s/m) or `{on: BODY, coefficient: c}`
    (a rotational damper on a turning body, N m s)."""
    spec = reader.mapping(spec, field, keys=KEYS)
    if ("between" in spec) == ("on" in spec):
        raise reader.fail(field, "give between: [POINT, POINT] (a dashpot) or on: BODY (a rotational damper)")
    if "on" in spec:
        body, _ = places.point(spec["on"], f"{field}.on", ground=False)
        if not places.bodies[body].rotates:
            raise reader.fail(f"{field}.on", f"a rotational damper turns a body; the {body} is a point mass")
        c = reader.positive(spec["coefficient"], f"{field}.coefficient", "N*m*s", "a damping coefficient")
        return Damper(name, (body, None), ((0, 0), (0, 0)), c, rotational=True)
    ends = places.two_points(spec["between"], f"{field}.between")
    b = reader.positive(spec["coefficient"], f"{field}.coefficient", "N*s/m", "a damping coefficient")
    return Damper(name, (ends[0][0], ends[1][0]), (ends[0][1], ends[1][1]), b)
