"""A body resting on a surface, in one of three regimes: held without slip (a normal force and
static friction: a round body rolls, any other stays put), smooth sliding (a normal force only),
or sliding with kinetic friction mu_k N against the slip. A round body touches a radius below its
center; a point mass at it; a body touching at one of its material points (a ladder's foot on the
floor, its top on the wall: the scene's `joints:` as `{touches: BODY.POINT, on: SURFACE}`) at
that point, so a rod may rest on two surfaces at once.

Lagrange: the gap to the surface (multiplier: the normal force) and, rolling, the distance rolled
plus R theta (multiplier: the friction along the surface); kinetic friction is power,
P = mu_k N s (t . v_contact), with s the direction it acts. Newton–Euler: the forces at the point
of contact; it does not move into the surface and, rolling, not along it either.

Which regime a body is in, when the file gives mu_s (and mu_k), is decided by derive.solution.answers:
rolling while the friction it needs is at most mu_s N, kinetic sliding beyond.

>>> import sympy as sp
>>> c = Contact("ball_contact", "ball", "ramp", True)
>>> sorted(c.unknowns())
['friction', 'normal']
"""
from __future__ import annotations

from dataclasses import dataclass

import sympy as sp

from derive.core.keys import Key, Keys
from derive.parts import AppliedForce, Part, Sign, acting, at_placement
from derive.parts.surfaces import carried
from derive.text.prose import Sentence
from derive.core.spelling import no_such


@dataclass(frozen=True)
class Contact(Part):
    """`body` on the surface named `surface`: `rolling`, or sliding (smooth unless `kinetic`, the
    coefficient mu_k, with `direction` +1 or -1: the friction acts along +t or -t). `static` is
    mu_s when the file gives it. `point`: the material point that touches, in the body's frame
    (None: the round body's rim below its center, or the point mass itself). `carrier`: the body
    that carries the surface (None: the ground); it feels the opposite forces, and the contact
    holds the two bodies' velocities at the point of contact together. `slipped`: how far it
    slid before it gripped (rolling, the distance rolled plus R theta is that much off the
    placement's). `center`: the center of the round face it touches with, in the body's frame
    from its center of mass (None: the center of mass; a hemisphere's is 3R/8 from it)."""

    name: str
    body: str
    surface: str
    rolling: bool
    static: sp.Expr | None = None
    kinetic: sp.Expr | None = None
    direction: int = 0
    point: tuple[sp.Expr, sp.Expr] | None = None
    carrier: str | None = None
    slipped: sp.Expr = sp.Integer(0)
    center: tuple[sp.Expr, sp.Expr] | None = None

    def bodies(self) -> tuple[str, ...]:
        return (self.body,) if self.carrier is None else (self.body, self.carrier)

    @property
    def title(self) -> str:
        return f"the {self.body}'s contact with the {self.surface}"

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
        label = self.body if self.point is None else self.name  # a body may touch at two points
        result = {"normal": sp.Symbol(f"N^{label}", real=True)}
        if self.rolling:
            result["friction"] = sp.Symbol(f"f^{label}", real=True)
        return result

    def _geometry(self, coords):
        """(surface where its carrier has it, the center of the circle that touches it, that
        circle's radius): a touching material point is a circle of radius 0."""
        surface = carried(coords.scene.surfaces[self.surface], coords)
        if self.point is not None:
            return surface, coords.position(self.body, self.point), sp.Integer(0)
        radius = coords.scene.bodies[self.body].sizes.get("radius", sp.Integer(0))
        return surface, coords.position(self.body, self.center or (0, 0)), radius

    def offset(self, coords) -> sp.Matrix:
        """World offset from the body's center to the point touching the surface."""
        if self.point is not None:
            return coords.rotated(self.body, self.point)
        surface, center, radius = self._geometry(coords)
        off_center = sp.zeros(2, 1) if self.center is None else coords.rotated(self.body, self.center)
        return off_center - radius * surface.normal_at(center, radius)

    def _carrier_offset(self, coords) -> sp.Matrix:
        """World offset from the carrier's center to the point of contact."""
        return coords.position(self.body) + self.offset(coords) - coords.position(self.carrier)

    def _slip_velocity(self, coords) -> sp.Matrix:
        """The velocity of the body's touching point relative to the surface's material point
        there (rigid-body kinematics of each)."""
        touching = coords.velocity(self.body, self.offset(coords))
        if self.carrier is None:
            return touching
        return touching - coords.velocity(self.carrier, self._carrier_offset(coords))

    def gaps(self, coords) -> list[sp.Expr]:
        surface, center, radius = self._geometry(coords)
        result = [surface.gap(center, radius)]
        if self.rolling:  # the arc along the surface and the turn, both as seen from the carrier
            rolled = self.rolled(coords)
            result.append(rolled - rolled.xreplace(coords.at_rest_in_reference()) - self.slipped)
        return result

    def slip(self, coords) -> sp.Expr:
        """The rate the touching point slides along the surface (zero where it grips)."""
        surface, center, radius = self._geometry(coords)
        return self._slip_velocity(coords).dot(surface.tangent_at(center, radius))

    def rolled(self, coords) -> sp.Expr:
        """The arc along the surface (from its own origin) plus R theta, both as seen from the
        carrier: constant while it grips."""
        surface, center, radius = self._geometry(coords)
        turned = coords.angle(self.body) - (coords.angle(self.carrier) if self.carrier else 0)
        return surface.arc(center, radius) + radius * turned

    def friction_direction(self, coords) -> sp.Matrix:
        """The direction friction acts along where its unknown is positive: the surface's tangent where
        the body touches it (derive.model.directions words it)."""
        surface, center, radius = self._geometry(coords)
        return surface.tangent_at(center, radius)

    def _kinetic_force(self, coords) -> sp.Matrix:
        surface, center, radius = self._geometry(coords)
        return self.kinetic * self.direction * self.unknowns()["normal"] * surface.tangent_at(center, radius)

    def power(self, coords) -> sp.Expr:
        if self.regime != "kinetic":
            return sp.Integer(0)
        return self._kinetic_force(coords).dot(self._slip_velocity(coords))

    def loads(self, coords) -> list[AppliedForce]:
        surface, center, radius = self._geometry(coords)
        f = self.unknowns()
        forces = [(f["normal"] * surface.normal_at(center, radius), "normal force")]
        if self.rolling:
            forces.append((f["friction"] * surface.tangent_at(center, radius), "static friction"))
        elif self.regime == "kinetic":
            forces.append((self._kinetic_force(coords), "kinetic friction"))
        result = [AppliedForce(self.body, self.offset(coords), force, label) for force, label in forces]
        if self.carrier is not None:  # the body pushes back on the surface's carrier
            result += [AppliedForce(self.carrier, self._carrier_offset(coords), -force, f"{label} of the {self.body}")
                       for force, label in forces]
        return result

    def conditions(self, coords) -> list[sp.Expr]:
        surface, center, radius = self._geometry(coords)
        slip = self._slip_velocity(coords)
        result = [slip.dot(surface.normal_at(center, radius))]
        if self.rolling:
            result.append(slip.dot(surface.tangent_at(center, radius)))
        return result

    def sentences(self, route: str, coords) -> list[Sentence]:
        f = self.unknowns()
        who = f"the {self.body}" if self.point is None else f"the {self.body}'s {self.name}"
        on = f"the {self.surface}" + ("" if self.carrier is None else f", which the {self.carrier} carries")
        if route == "lagrange":
            radius = self._geometry(coords)[2]
            touching = ("it keeps touching it, a gap held by the normal force ", f["normal"])
            if self.rolling:
                along = "it does not slide along it" if radius == 0 else \
                    "the distance along it, with its radius times its turn, stays what it is"
                held = (" and does not slip: ", *touching, f", and {along}, held by the friction ", f["friction"])
            elif self.regime == "kinetic":
                held = (" and slides: ", *touching, "; kinetic friction, ", self.kinetic * f["normal"], ", acts against "
                        "the slip, its power ", at_placement(self.power(coords), coords))
            else:
                held = (" without friction: ", *touching)
            return [Sentence((f"{who.capitalize()} rests on {on}", *held, "."))]
        words = {"normal force": ("The {surface} pushes {who} with the normal force ", f["normal"], ""),
                 "static friction": ("Static friction ", f.get("friction"), " acts on {who} along the {surface}"),
                 "kinetic friction": ("Kinetic friction, ", None, ", acts on {who} along the {surface}, against the slip")}
        result = []
        for load in self.loads(coords):
            if load.body == self.body:
                first, math, rest = words[load.label]
                math = self.kinetic * f["normal"] if math is None else math
                result.append(Sentence((first.format(surface=self.surface, who=who), math,
                                        rest.format(surface=self.surface, who=who), *acting(load, coords, (f["normal"],)),
                                        "."), load.body))
            else:
                result.append(Sentence((f"{who.capitalize()} pushes back on the {self.carrier} with the opposite "
                                        f"{load.label.split(' of ')[0]}", *acting(load, coords), "."), load.body))
        along = ", nor along it: it grips" if self.rolling else ""
        touching = who if self.point is not None else f"the point of contact of {who}"
        return result + [Sentence((f"{touching.capitalize()} does not move into {on}{along}.",))]

    def signs(self) -> list[Sign]:
        normal = self.unknowns()["normal"]
        where = "" if self.point is None else f" at {self.name}"
        return [Sign(normal, f"the {self.body} leaves the surface {self.surface}{where} (its normal force would be "
                             "negative)", f"the {self.body} does not press on the surface {self.surface}{where}",
                     "its normal force")]


FRICTION = Keys(static=Key("expression", "the coefficient of static friction, mu_s"),
                kinetic=Key("expression", "the coefficient of kinetic friction, mu_k (mu_s defaults to it)"))
KEYS = Keys(touches=Key("point", "the material point of a body that touches the surface (BODY.POINT)", required=True),
            on=Key("name", "the surface it rests on", required=True),
            grips=Key("boolean", "held by static friction as needed (default false: smooth)"),
            friction=Key("mapping", "coefficients; the engine decides whether it holds", keys=FRICTION))


def read(reader, places, name: str, spec: dict, field: str) -> Contact:
    """`{touches: BODY.POINT, on: SURFACE}`: the body touches the surface at that material point,
    smoothly unless `grips: true` (static friction holds the point as needed) or `friction:
    {static: mu_s, kinetic: mu_k}` (the engine decides whether it holds).

    The point must lie on its body and on the surface in the reference configuration (checked
    with the scene's geometry)."""
    spec = reader.mapping(spec, field, keys=KEYS)
    body, point = places.point(spec["touches"], f"{field}.touches", ground=False)
    places.on_body(body, point, f"{field}.touches")
    if spec["on"] not in places.surfaces:
        raise reader.fail(f"{field}.on", no_such("surface", spec["on"], places.surfaces, "surfaces"))
    if places.surfaces[spec["on"]].carrier == body:
        raise reader.fail(f"{field}.on", f"the {body} carries {spec['on']}: it cannot rest on it")
    grips = spec.get("grips", False)
    if not isinstance(grips, bool):
        raise reader.fail(f"{field}.grips", "expected true or false")
    static, kinetic = coefficients(reader, spec, field)
    if grips and static is None and kinetic is not None:
        raise reader.fail(f"{field}.grips", "the point grips as long as static friction holds it: give "
                                            "friction.static: mu_s (and kinetic: mu_k for when it slips)")
    if grips and static is not None:
        raise reader.fail(f"{field}.grips", "with friction.static the engine decides whether the point grips: "
                                            "leave grips out")
    return Contact(name, body, spec["on"], grips, static, kinetic, point=point,
                   carrier=places.surfaces[spec["on"]].carrier)


def coefficients(reader, spec: dict, field: str) -> tuple[sp.Expr | None, sp.Expr | None]:
    """(mu_s, mu_k) from `friction: {static: mu_s, kinetic: mu_k}`, each None when not given."""
    if "friction" not in spec:
        return None, None
    friction = reader.mapping(spec["friction"], f"{field}.friction", keys=FRICTION)
    if not friction:
        raise reader.fail(f"{field}.friction", "give static: mu_s, kinetic: mu_k or both")
    return tuple(reader.positive(friction[k], f"{field}.friction.{k}", "1", "a coefficient of friction")
                 if k in friction else None for k in ("static", "kinetic"))
