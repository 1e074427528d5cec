"""What each constraint means to each route of derivation.

For Lagrange's method a constraint is a holonomic gap g(q) = 0, normalized so that its
multiplier *is* the physical force it names (the tension, a reaction component): the
generalized constraint force is lambda * dg/dq. For Newton–Euler the same constraint is
a set of forces applied at material points, and a velocity condition built from
rigid-body kinematics (v = v_cm + omega x r), differentiated once for the accelerations.
The two descriptions are written independently, so agreement of the routes checks both.

>>> import sympy as sp
>>> from derive.scene import Body, Pin, Scene
>>> from derive.mechanics.kinematics import Coordinates
>>> scene = Scene({"disk": Body("disk", "custom", sp.Symbol("M"), {}, sp.Symbol("I"))},
...               (Pin("axle", "disk", (0, 0)),))
>>> gaps(scene.constraints[0], Coordinates(scene))
[x_disk, y_disk]
"""
from __future__ import annotations

from dataclasses import dataclass
from functools import singledispatch

import sympy as sp

from derive.mechanics.kinematics import Coordinates
from derive.scene import Constraint, Contact, Pin, WoundString


@dataclass(frozen=True)
class AppliedForce:
    """A force on a body, applied at a world-frame offset from its center of mass."""

    body: str
    offset: sp.Matrix
    force: sp.Matrix
    label: str


@singledispatch
def forces(constraint: Constraint) -> dict[str, sp.Symbol]:
    """The unknown force components a constraint exerts, by the names an answer asks for."""
    raise TypeError(constraint)


@forces.register
def _(pin: Pin) -> dict[str, sp.Symbol]:
    return {
        "reaction.x": sp.Symbol(f"R_x^{pin.name}", real=True),
        "reaction.y": sp.Symbol(f"R_y^{pin.name}", real=True),
    }


@forces.register
def _(cord: WoundString) -> dict[str, sp.Symbol]:
    return {"tension": sp.Symbol(f"T_{cord.name}", real=True)}


@forces.register
def _(contact: Contact) -> dict[str, sp.Symbol]:
    result = {"normal": sp.Symbol(f"N^{contact.body}", real=True)}
    if contact.rolling:
        result["friction"] = sp.Symbol(f"f^{contact.body}", real=True)
    return result


def _contact_geometry(contact: Contact, coords: Coordinates):
    surface = coords.scene.surfaces[contact.surface]
    radius = coords.scene.bodies[contact.body].sizes.get("radius", sp.Integer(0))
    return surface, coords.position(contact.body), radius


def contact_offset(contact: Contact, coords: Coordinates) -> sp.Matrix:
    """World offset from the body's center to the point touching the surface."""
    surface, center, radius = _contact_geometry(contact, coords)
    return -radius * surface.normal_at(center, radius)


@singledispatch
def gaps(constraint: Constraint, coords: Coordinates) -> list[sp.Expr]:
    """Holonomic constraint functions g(q), each paired in order with `forces(constraint)`."""
    raise TypeError(constraint)


@gaps.register
def _(pin: Pin, coords: Coordinates) -> list[sp.Expr]:
    point = coords.position(pin.body, pin.offset)
    anchor = point.xreplace(coords.at_rest_in_reference())
    return list(point - anchor)


@gaps.register
def _(cord: WoundString, coords: Coordinates) -> list[sp.Expr]:
    # The cord pays out from the rim: the load's height follows the rim's arc length
    # s * R * theta, so g = y_load - y_reel - s R theta; its multiplier pulls the load up.
    radius = coords.scene.bodies[cord.reel].sizes["radius"]
    return [
        coords.of(cord.load, "y").q
        - coords.of(cord.reel, "y").q
        - cord.side * radius * coords.angle(cord.reel)
    ]


@gaps.register
def _(contact: Contact, coords: Coordinates) -> list[sp.Expr]:
    # Height above the surface (multiplier: the normal force) and, when rolling, the
    # distance rolled along it plus R theta (multiplier: friction along the surface).
    surface, center, radius = _contact_geometry(contact, coords)
    result = [surface.gap(center, radius)]
    if contact.rolling:
        result.append(surface.arc(center, radius) + radius * coords.angle(contact.body))
    return result


@singledispatch
def applied_forces(constraint: Constraint, coords: Coordinates) -> list[AppliedForce]:
    """The forces a constraint applies to the bodies, for the Newton–Euler balances."""
    raise TypeError(constraint)


@applied_forces.register
def _(pin: Pin, coords: Coordinates) -> list[AppliedForce]:
    f = forces(pin)
    reaction = sp.Matrix([f["reaction.x"], f["reaction.y"]])
    return [AppliedForce(pin.body, coords.rotated(pin.body, pin.offset), reaction, f"reaction of {pin.name}")]


@applied_forces.register
def _(cord: WoundString, coords: Coordinates) -> list[AppliedForce]:
    tension = forces(cord)["tension"]
    radius = coords.scene.bodies[cord.reel].sizes["radius"]
    # The tangent point is fixed in space beside the reel's center, not in the reel.
    tangent = sp.Matrix([cord.side * radius, 0])
    return [
        AppliedForce(cord.load, sp.zeros(2, 1), sp.Matrix([0, tension]), f"tension of {cord.name}"),
        AppliedForce(cord.reel, tangent, sp.Matrix([0, -tension]), f"tension of {cord.name}"),
    ]


@applied_forces.register
def _(contact: Contact, coords: Coordinates) -> list[AppliedForce]:
    surface, center, radius = _contact_geometry(contact, coords)
    f = forces(contact)
    offset = contact_offset(contact, coords)
    result = [AppliedForce(contact.body, offset, f["normal"] * surface.normal_at(center, radius), "normal force")]
    if contact.rolling:
        tangent = surface.tangent_at(center, radius)
        result.append(AppliedForce(contact.body, offset, f["friction"] * tangent, "static friction"))
    return result


@singledispatch
def velocity_conditions(constraint: Constraint, coords: Coordinates) -> list[sp.Expr]:
    """Velocity expressions the constraint holds at zero (rigid-body kinematics)."""
    raise TypeError(constraint)


@velocity_conditions.register
def _(pin: Pin, coords: Coordinates) -> list[sp.Expr]:
    # The material point at the pivot does not move.
    return list(coords.material_velocity(pin.body, coords.rotated(pin.body, pin.offset)))


@velocity_conditions.register
def _(cord: WoundString, coords: Coordinates) -> list[sp.Expr]:
    # An inextensible cord that does not slip on the rim: the load moves vertically with
    # the rim's material point at the tangent.
    radius = coords.scene.bodies[cord.reel].sizes["radius"]
    rim = coords.material_velocity(cord.reel, sp.Matrix([cord.side * radius, 0]))
    return [coords.of(cord.load, "y").u - rim[1]]


@velocity_conditions.register
def _(contact: Contact, coords: Coordinates) -> list[sp.Expr]:
    # The material point touching the surface does not move into it, and when rolling
    # without slipping it does not move along it either.
    surface, center, radius = _contact_geometry(contact, coords)
    touching = coords.material_velocity(contact.body, contact_offset(contact, coords))
    result = [touching.dot(surface.normal_at(center, radius))]
    if contact.rolling:
        result.append(touching.dot(surface.tangent_at(center, radius)))
    return result


def solve_gaps(scene, coords: Coordinates) -> dict[sp.Symbol, sp.Expr]:
    """Solve every constraint gap for one coordinate, preferring translations to angles;
    the coordinates left over are the free ones.

    Raises ValueError when a gap cannot be solved for any remaining coordinate.
    """
    order = sorted(coords.all, key=lambda c: c.kind == "theta")
    solved: dict[sp.Symbol, sp.Expr] = {}
    for c in scene.constraints:
        for gap in gaps(c, coords):
            gap = gap.xreplace(solved)
            for candidate in order:
                if candidate.q in solved or not gap.has(candidate.q):
                    continue
                roots = sp.solve(gap, candidate.q)
                if len(roots) == 1:
                    solved = {q: v.xreplace({candidate.q: roots[0]}) for q, v in solved.items()}
                    solved[candidate.q] = roots[0]
                    break
            else:
                raise ValueError(f"the constraint {c.name} could not be solved for any coordinate")
    return solved
