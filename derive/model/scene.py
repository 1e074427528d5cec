"""The scene model: bodies, joints and constraints, loads — data only, no physics.

A scene is planar: the xy plane with y up, angles counter-clockwise (+z) positive,
as in the lecture notes. `derive.language.problem` builds a Scene from a problem file; the
modules in `derive.mechanics` derive its motion.

>>> import sympy as sp
>>> m = sp.Symbol("m", positive=True)
>>> Scene(bodies={"ball": Body("ball", "point", m, {})}).degrees_of_freedom()
2
"""
from __future__ import annotations

import itertools
import re
from dataclasses import dataclass, field

import sympy as sp

from derive.model import inertia
from derive.model.composite import CompositeParts
from derive.parts import Part
from derive.parts.contact import Contact
from derive.parts.gravity import Gravity
from derive.parts.surfaces import Circle, Plane, Surface
from derive.model.solid_scene import Bearings, FreeRotation, PivotPoint, RollsOnEdge
from derive.core.spelling import did_you_mean

#: Body shapes a scene may use, with the size names each needs (from the inertia module's shapes).
SHAPE_SIZES: dict[str, tuple[str, ...]] = {
    "point": (),
    "custom": (),
    "composite": (),
    **{name: tuple(shape.sizes) for name, shape in inertia.SHAPES.items()},
}


#: What a point mass on a prescribed path can be asked.
#: What a path in space (with z) has no meaning for: the plane's polar components and sweep.
PLANAR_PATH_QUANTITIES = ("acceleration.radial", "acceleration.tangential", "areal_velocity")
PATH_QUANTITIES = ("velocity.x", "velocity.y", "speed", "acceleration.x", "acceleration.y", "acceleration.radial",
                   "acceleration.tangential", "angular_momentum", "areal_velocity")


@dataclass(frozen=True)
class Path:
    """A body's prescribed motion: ("polar", (r(t), theta(t))) or ("cartesian", (x(t), y(t))),
    with `z` (t) off the plane for a cartesian path in space (0: in the plane)."""

    kind: str
    functions: tuple[sp.Expr, sp.Expr]
    z: sp.Expr = sp.Integer(0)

    @property
    def position3(self) -> sp.Matrix:
        """The position in space, (x, y, z)."""
        return sp.Matrix([*self.position, self.z])

    @property
    def position(self) -> sp.Matrix:
        if self.kind == "polar":
            r, theta = self.functions
            return sp.Matrix([r * sp.cos(theta), r * sp.sin(theta)])
        return sp.Matrix(self.functions)

    @property
    def radius_and_angle(self) -> tuple[sp.Expr, sp.Expr]:
        if self.kind == "polar":
            return self.functions
        x, y = self.functions
        return sp.sqrt(x**2 + y**2), sp.atan2(y, x)


@dataclass(frozen=True)
class Body:
    """A rigid body (or a point mass) in the plane.

    `inertia` is the moment of inertia about the axis through the center of mass normal to
    the plane: given for a custom body, composed from the parts of a composite, otherwise
    integrated by `derive.model.inertia`.
    """

    name: str
    shape: str
    mass: sp.Expr
    sizes: dict[str, sp.Expr]
    given_inertia: sp.Expr | None = None
    path: Path | None = None
    density: sp.Expr | None = None
    at: tuple[sp.Expr, sp.Expr] = (sp.Integer(0), sp.Integer(0))  # the center of mass, reference configuration
    angle: sp.Expr = sp.Integer(0)  # the body frame's angle from the world's axes there
    composite: CompositeParts | None = None  # a body made of parts: derive.model.composite
    round_center: tuple[sp.Expr, sp.Expr] | None = None  # its round face's center off its center of mass

    @property
    def rotates(self) -> bool:
        """A point mass has no orientation; every other body has an angle."""
        return self.shape != "point"

    def placed(self, kind: str) -> sp.Expr:
        """Where the file places the coordinate `kind` (x, y or theta): every coordinate of the
        engine is a displacement from it."""
        return self.angle if kind == "theta" else self.at[0 if kind == "x" else 1]

    @property
    def shape_center(self) -> tuple[sp.Expr, sp.Expr]:
        """Where the shape's middle lies from the center of mass, in the body's frame: (0, 0) but for
        a density that moves the center of mass (a rod denser at one end: its named points, `start`
        and `end`, are then measured from the center of mass like every point of the body)."""
        if self.density is None or self.shape not in inertia.SHAPES:
            return (sp.Integer(0), sp.Integer(0))
        center = inertia.body_center(self.shape, self.sizes, self.density)
        return (-center[0], -center[1])

    @property
    def face_center(self) -> tuple[sp.Expr, sp.Expr] | None:
        """Where the center of its round face lies from the center of mass, in its frame, where that
        is not the center of mass: a custom body's `round_center`, a composite's round part off it,
        or the middle of a round shape whose density moves the center of mass; else None."""
        if self.round_center is not None:
            return self.round_center
        middle = self.shape_center
        return None if middle == (0, 0) or "radius" not in self.sizes else middle

    @property
    def inertia(self) -> sp.Expr:
        if self.given_inertia is not None:
            return self.given_inertia
        if self.density is not None:  # about its center of mass, which a density may move off the middle
            return inertia.central_body_moment(self.shape, inertia.PLANAR_AXIS[self.shape], self.mass, self.sizes,
                                               self.density)[1]
        return inertia.central_moment(self.shape, self.mass, self.sizes)


@dataclass(frozen=True)
class Orbit:
    """A small mass in the inverse-square field of a mass M at the origin (per unit mass):
    given its angular momentum l, or the ellipse's semi-major axis a and eccentricity e (derived
    from its distance and speed at periapsis where the file gives those: `periapsis_speed`)."""

    GM: sp.Expr
    angular_momentum: sp.Expr | None = None
    semi_major_axis: sp.Expr | None = None
    eccentricity: sp.Expr | None = None
    periapsis_speed: tuple[sp.Expr, sp.Expr] | None = None  # (r_p, v_p) where the file gives the ellipse so


#: What an orbit can be asked, and what each needs of the orbit's description.
ORBIT_QUANTITIES = {
    "circular_radius": "angular_momentum", "effective_potential_minimum": "angular_momentum",
    "energy": "semi_major_axis", "angular_momentum": "semi_major_axis", "period": "semi_major_axis",
    "periapsis": "semi_major_axis", "apoapsis": "semi_major_axis",
    "speed_at_periapsis": "semi_major_axis", "speed_at_apoapsis": "semi_major_axis",
}


@dataclass(frozen=True)
class Motion:
    """A body's given placement and motion: center position, velocity (a body rolling at a given
    speed) and spin (rad/s, +z; the figures take a state's rates so)."""

    position: tuple[sp.Expr, sp.Expr] = (sp.Integer(0), sp.Integer(0))
    velocity: tuple[sp.Expr, sp.Expr] = (sp.Integer(0), sp.Integer(0))
    spin: sp.Expr = sp.Integer(0)


@dataclass(frozen=True)
class StandingWave:
    """A particle whose de Broglie wavelength fits `wavelengths` times around a circle (§8)."""

    radius: sp.Expr
    planck: sp.Expr
    wavelengths: sp.Expr


#: Scene-level systems and what each can be asked: (scene attribute, quantities).
SYSTEMS = {
    "standing_wave": ("wave", ("momentum", "angular_momentum")),
    "internal_forces": ("internal_forces", ("torque",)),
}
def constraint_bodies(part: Part) -> tuple[str, ...]:
    """The bodies a part couples."""
    return part.bodies()


@dataclass(frozen=True)
class Event:
    """What happens to the scene in an instant, or by its own forces, between two states: an
    impact (`kind` stick, lock or bounce of `body` on `to`, a lock `rims` of two round bodies on
    fixed axles that roll on each other from then on, a bounce with its coefficient of
    `restitution` and, rough, its `friction` (mu for the grip, mu for the slide) or `grips`
    always; a bounce's `to` may be a fixed surface), a move (`kind` move: the point mass `body` carried to `place` on the body
    `to`, in its frame, where the pin `joint` holds it), a turn (`kind` turn: the body `body`
    turned through `angle` relative to the body `to` by a couple between them, Elroy's beanie),
    a transfer (`kind` transfer: the contact `joint` of the body `body` passes onto the surface
    `to`, a ball rolling from a ramp into a loop), or a pull (`kind` pull: the cord `joint`, from a
    ground point to the point mass `body`, drawn slowly to the `length`).

    >>> Event("stick", "bullet", "rod").restitution is None
    True
    """

    kind: str
    body: str
    to: str
    restitution: sp.Expr | None = None
    friction: tuple[sp.Expr, sp.Expr] | None = None
    grips: bool = False
    place: tuple[sp.Expr, sp.Expr] | None = None
    joint: str | None = None
    angle: sp.Expr | None = None
    rims: bool = False
    length: sp.Expr | None = None


@dataclass(frozen=True)
class State:
    """A named state of a scene (`states:`), where asks may be read (`in: STATE`).

    Either the placement moving at given `rates` ((body, coordinate kind, value) with kind x, y
    or theta), or a state the motion from the state `start` (None: the placement at rest) gets
    to first: where one body coordinate reaches a value (`when`: an absolute x, y of the center
    or angle, as `at` and `angle` are given; with `rate`, where its rate does), or (`until`) where the motion stops, ("stops",
    None), or a part's force falls to zero: ("leaves", CONTACT) or ("slack", CORD); or the state
    just after an `event` in the state `start`: an impact (a stick, the body held where it is; a
    lock, the two turning together from then on, the scene keeping the joint the impact made; a
    bounce off a body), a move of a point mass on the body that holds it, a turn of one body
    relative to another, or a body's contact passing onto another surface.

    >>> State("vertical", when=("rod", "theta", -sp.pi / 2)).start is None
    True
    """

    name: str
    rates: tuple[tuple[str, str, sp.Expr], ...] = ()
    when: tuple[str, str, sp.Expr] | None = None
    start: str | None = None
    until: tuple[str, str | None] | None = None
    event: Event | None = None
    rate: bool = False  # `when` gives a rate (velocity.x|y, angular_velocity), not a position
    # From a balance it would never leave (a rod on its end, a ball on a dome's top), the motion begins with a
    # push too small to count (`nudged:`): True, toward where the state is; or (body, kind, +1 or -1), the way
    # that coordinate first moves. The state's speeds and places are the limit of a vanishing push; its time is not.
    nudge: bool | tuple[str, str, int] = False
    # `when`'s position measured in another body's frame from its point (body, offset in its frame): a block's
    # x from a plank's end, a bead's along a turning rod from its end (`when: {..., relative_to: rod.end}`).
    relative_to: tuple[str, tuple[sp.Expr, sp.Expr]] | None = None


@dataclass(frozen=True)
class Scene:
    """Bodies and parts: the constraints (parts with unknown forces: pins, sliders, welds, cords,
    contacts), gravity and the other loads (forces, torques, springs, dampers, pulled cords);
    what `derive.mechanics` derives the motion of."""

    bodies: dict[str, Body]
    constraints: tuple[Part, ...] = ()
    gravity: Gravity | None = None
    surfaces: dict[str, Surface] = field(default_factory=dict)
    loads: tuple[Part, ...] = ()
    orbit: Orbit | None = None
    motions: dict[str, Motion] = field(default_factory=dict)
    wave: StandingWave | None = None
    internal_forces: int | None = None
    bearings: dict[str, Bearings] = field(default_factory=dict)
    pivot_points: dict[str, PivotPoint] = field(default_factory=dict)
    rolls_on_edge: dict[str, RollsOnEdge] = field(default_factory=dict)
    free_rotations: dict[str, FreeRotation] = field(default_factory=dict)
    states: dict[str, State] = field(default_factory=dict)
    placed: tuple[sp.Expr, ...] = ()  # positive where the file places the bodies (scene_file._placed)

    @property
    def parts(self) -> tuple[Part, ...]:
        """Every part that acts in the dynamics: the constraints, gravity, the other loads."""
        return self.constraints + ((self.gravity,) if self.gravity is not None else ()) + self.loads

    def constraint(self, name: str) -> Part:
        for c in self.constraints:
            if c.name == name:
                return c
        raise KeyError(name)

    def numbers(self) -> dict[str, int]:
        """Each body's number, for a symbol of its own where no plain name is free (a_1, alpha_2; never
        the body's key, which is the file's): its mass's index where the file numbers the masses (m1:
        1), the other bodies the numbers left, in the scene's order.

        >>> Scene({n: Body(n, "point", sp.Symbol(m), {}) for n, m in (("pulley", "M"), ("left", "m1"),
        ...                                                          ("right", "m_2"))}).numbers()
        {'pulley': 3, 'left': 1, 'right': 2}
        """
        indexed: dict[str, int] = {}
        for name, body in self.bodies.items():
            index = re.fullmatch(r"[A-Za-z]+_?(\d+)", body.mass.name) if isinstance(body.mass, sp.Symbol) else None
            if index and int(index[1]) not in indexed.values():
                indexed[name] = int(index[1])
        left = (n for n in itertools.count(1) if n not in indexed.values())
        return {name: indexed[name] if name in indexed else next(left) for name in self.bodies}

    def degrees_of_freedom(self) -> int:
        """Coordinates (x, y and, for rotating bodies, an angle) less the scalar constraints."""
        coordinates = sum(3 if b.rotates else 2 for b in self.bodies.values())
        return coordinates - sum(len(c.unknowns()) for c in self.constraints)

    def component(self, body: str) -> "Scene":
        """The sub-scene of the bodies coupled to `body` through constraints."""
        members, grew = {body}, True
        while grew:
            grew = False
            for c in self.constraints:
                coupled = set(c.bodies())
                if coupled & members and not coupled <= members:
                    members |= coupled
                    grew = True
        constraints = tuple(c for c in self.constraints if set(c.bodies()) <= members)
        bodies = {name: b for name, b in self.bodies.items() if name in members}
        loads = tuple(p for p in self.loads if set(p.bodies()) <= members)
        return Scene(bodies, constraints, self.gravity, self.surfaces, loads)

    def contact_of(self, body: str) -> Contact | None:
        """The contact of a body resting on a surface by its rim or as a point mass (`body` names the
        body), or the named contact of a body touching at a material point (`body` names the contact)."""
        return next((c for c in self.constraints if isinstance(c, Contact)
                     and (c.body == body and c.point is None or c.point is not None and c.name == body)), None)


#: Quantities that come out of the equations of motion (both routes).
DYNAMIC_KINDS = {"acceleration", "angular_acceleration", "force", "contact", "small_oscillation", "oscillation",
                 "equilibrium", "velocity", "angular_velocity", "speed", "position", "angle", "time", "kinetic_energy",
                 "kinetic_energy_change", "center_of_mass_velocity", "impulse"}
#: Read in a state (`in: STATE`): the rates only there, the others at the placement at rest without it.
STATE_KINDS = {"acceleration", "angular_acceleration", "force", "contact", "velocity", "angular_velocity", "speed",
               "position", "angle", "time", "kinetic_energy", "kinetic_energy_change", "center_of_mass_velocity",
               "impulse"}
#: What a state gives: read only with `in: STATE` (positions and times only in a state reached).
RATE_KINDS = {"velocity", "angular_velocity", "speed", "position", "angle", "time", "kinetic_energy",
              "kinetic_energy_change", "center_of_mass_velocity", "impulse"}
#: Quantities of the bodies and their arrangement, with no motion.
STATIC_KINDS = {"inertia", "mass", "position_cm", "system"}


@dataclass(frozen=True)
class Quantity:
    """A quantity a problem may ask of its scene, parsed from a dotted path.

    kinds: "inertia" (target a body, detail an axis), "acceleration" (a body; x or y),
    "angular_acceleration" (a body), "force" (a constraint; tension, reaction.x, reaction.y),
    "contact" (a body on a surface; one of CONTACT_QUANTITIES), "path" (a point mass on a
    prescribed path; one of PATH_QUANTITIES), "orbit" (one of ORBIT_QUANTITIES), "mass" (a body), "position_cm" (a body's position from the system's center of mass; x or y),
    "system" (inertia about the center of mass, reduced_mass of two bodies), "pivot_point" (a body on a
    fixed point; PIVOT_POINT_QUANTITIES), "rolls_on_edge" (a coin rolling on its rim; ROLLING_COIN_QUANTITIES),
    "free_rotation" (a body turning with no torque; FREE_ROTATION_QUANTITIES), "angular_impulse" (a body on a
    fixed point at its center of mass under a couple for a time; IMPULSE_TURN_QUANTITIES),
    "oscillation" (period at the ask's amplitude), the SYSTEMS
    ("standing_wave", "internal_forces"), "bearings" (a body turning in bearings; BEARING_QUANTITIES),
    "small_oscillation" (omega, period, growth_rate; modes.N.omega|period), "equilibrium" (a body's angle, x or y where
    the scene rests: derive.mechanics.equilibrium); read in a state (RATE_KINDS) also
    "kinetic_energy_change" (every body's, in the state minus in the state it comes from),
    "center_of_mass_velocity" (of every body; x or y) and, just after an impact, "impulse" (a
    body's, or a joint's on the body it holds; x or y: derive.mechanics.impulses).
    """

    kind: str
    target: str | None
    detail: str | None



#: The heads of ask paths that name no body or part: a body, joint, cord or load may not be named so.
RESERVED_NAMES = ("system", "orbit", "oscillation", "small_oscillation", "ground",
                  "time", "kinetic_energy", "kinetic_energy_change", "center_of_mass")

#: What a body on a surface can be asked, besides what every body can.
CONTACT_QUANTITIES = ("acceleration.down_incline", "normal_force", "friction", "min_friction_coefficient",
                      "speed_at_bottom", "time_to_bottom", "min_release_height")
#: Of a body rolling without slipping at its given velocity (derive.mechanics.rolling).
ROLLING_QUANTITIES = ("angular_velocity", "distance_per_turn", "kinetic_energy", "translational_energy",
                      "rotational_energy", "rotational_fraction")
#: A body's impulse, or a joint's on the body it holds, just after an impact.
IMPULSES = ("impulse.x", "impulse.y")
INCLINE_ONLY = ("acceleration.down_incline", "speed_at_bottom", "time_to_bottom")

def parse_quantity(scene: Scene, path: str, axis: str | None = None) -> Quantity:
    """Parse an answer path such as ``block.acceleration.y`` against a scene.

    Raises ValueError with a one-line reason when the path names nothing in the scene.

    >>> import sympy as sp
    >>> scene = Scene({"ball": Body("ball", "point", sp.Symbol("m"), {})})
    >>> parse_quantity(scene, "ball.acceleration.y")
    Quantity(kind='acceleration', target='ball', detail='y')
    """
    head, _, rest = path.partition(".")
    if head == "time":
        if rest or not scene.states:
            raise ValueError("time is asked as of: time, in: STATE (the time the motion takes from the state's "
                             "from: to it)" if scene.states else "time needs a state: add scene.states")
        return Quantity("time", None, None)
    if head == "kinetic_energy":
        if rest or not scene.states:
            raise ValueError("kinetic_energy is asked as of: kinetic_energy, in: STATE (of every body, in that state)"
                             if scene.states else "kinetic_energy needs a state: add scene.states")
        return Quantity("kinetic_energy", None, None)
    if head == "kinetic_energy_change":
        if rest or not scene.states:
            raise ValueError("kinetic_energy_change is asked as of: kinetic_energy_change, in: STATE (of every body, "
                             "in that state minus in the state it comes from)" if scene.states else
                             "kinetic_energy_change needs a state: add scene.states")
        return Quantity("kinetic_energy_change", None, None)
    if head == "center_of_mass":
        if rest not in ("velocity.x", "velocity.y") or not scene.states:
            raise ValueError("the center of mass of every body has position.x and position.y, and velocity.x and "
                             "velocity.y, asked in: STATE"
                             if scene.states else "center_of_mass.velocity needs a state: add scene.states")
        return Quantity("center_of_mass_velocity", None, rest[-1])
    if head == "oscillation":
        if rest != "period":
            raise ValueError("an oscillation at a given amplitude has period (give amplitude:)")
        return Quantity("oscillation", None, "period")
    if head == "small_oscillation":
        ratio = re.fullmatch(r"modes\.[1-9][0-9]?\.ratio\.(\w+)\.(x|y|angle)\.to\.(\w+)\.(x|y|angle)", rest, re.ASCII)
        if rest not in ("omega", "period", "growth_rate") and not ratio \
                and not re.fullmatch(r"modes\.[1-9][0-9]?\.(omega|period)", rest):
            raise ValueError("small_oscillation has omega, period, growth_rate (about an unstable equilibrium) and, "
                             "with several degrees of freedom, modes.N.omega and modes.N.period (N = 1, 2, ...: the "
                             "normal modes, lowest frequency first) and modes.N.ratio.BODY.x.to.BODY.x (the ratio of "
                             "two amplitudes in the mode; x, y or angle)")
        for body, kind in (ratio.group(1, 2), ratio.group(3, 4)) if ratio else ():
            if body not in scene.bodies or kind == "angle" and not scene.bodies[body].rotates:
                raise ValueError(f"{body}.{kind} is not a coordinate of the scene in a mode's ratio"
                                 + did_you_mean(body, list(scene.bodies)))
        return Quantity("small_oscillation", None, rest)
    if head in scene.bodies:
        body = scene.bodies[head]
        if rest == "inertia":
            shape = inertia.SHAPES.get(body.shape)
            axes = tuple(shape.axes) if shape else ()
            if isinstance(axis, tuple):  # a direction through the center of mass
                if shape is None:
                    raise ValueError(f"a {body.shape}'s moment about a direction needs a shape derive integrates "
                                     f"({', '.join(inertia.SHAPES)})")
                return Quantity("inertia", head, axis)
            if axis is None and body.shape != "point":
                return Quantity("inertia", head, None)
            if axis not in axes:
                raise ValueError(f"axis of a {body.shape} is one of: {', '.join(axes) or 'none'}" + did_you_mean(axis, axes))
            return Quantity("inertia", head, axis)
        if rest in ("acceleration.x", "acceleration.y"):
            return Quantity("acceleration", head, rest[-1])
        if rest in ("velocity.x", "velocity.y"):
            return Quantity("velocity", head, rest[-1])
        if rest in IMPULSES:
            return Quantity("impulse", head, rest[-1])
        if rest == "speed" or rest in ("angular_velocity", "angle") and body.rotates:
            return Quantity(rest, head, None)
        if rest in ("position.x", "position.y"):
            return Quantity("position", head, rest[-1])
        if rest in ("equilibrium.x", "equilibrium.y") or rest == "equilibrium.angle" and body.rotates:
            return Quantity("equilibrium", head, rest.partition(".")[2])
        if rest == "angular_acceleration" and body.rotates:
            return Quantity("angular_acceleration", head, None)
        contact = scene.contact_of(head)
        if contact and rest in CONTACT_QUANTITIES:
            if rest in ("friction", "min_friction_coefficient") and not contact.rolling and not contact.has_friction:
                raise ValueError(f"{head} slides without friction: it has no {rest}")
            surface = scene.surfaces[contact.surface]
            if rest in INCLINE_ONLY and not isinstance(surface, Plane):
                raise ValueError(f"{rest} is for a body on an incline")
            if rest in (*INCLINE_ONLY, "min_release_height") and surface.carrier is not None:
                raise ValueError(f"{rest} is measured on a fixed surface; {contact.surface} moves with the "
                                 f"{surface.carrier}: ask {head}.acceleration.x|y")
            if rest == "min_release_height" and not (isinstance(surface, Circle) and surface.side == "inside"):
                raise ValueError("min_release_height is for a body riding a loop")
            if rest in ("speed_at_bottom", "time_to_bottom", "min_release_height") and contact.center is not None:
                raise ValueError(f"{rest} takes the acceleration along the surface constant; the {head} rests on a "
                                 "round face off its center of mass, so it changes as the body turns")
            if rest in ("speed_at_bottom", "time_to_bottom") and surface.height is None:
                raise ValueError(f"{rest} needs the height of {contact.surface}")
            return Quantity("contact", head, rest)
        known = ("inertia, acceleration.x, acceleration.y, velocity.x, velocity.y, speed, position.x, position.y, "
                 "equilibrium.x, equilibrium.y, impulse.x, impulse.y"
                 + (", angular_acceleration, angular_velocity, angle, equilibrium.angle" if body.rotates else ""))
        if contact:
            known += ", " + ", ".join(CONTACT_QUANTITIES)
        raise ValueError(f"a body has {known}; not {rest!r}" + did_you_mean(rest, known.split(", ")))
    names = {c.name: c for c in scene.constraints}
    if head in names:
        part = names[head]
        pushes = any(k.startswith("reaction") or k == "normal" for k in part.unknowns())  # a force at a point
        if rest in IMPULSES:
            if not pushes:
                raise ValueError(f"{head} gives no force at a point, so no impulse of one: a body's impulse is asked "
                                 "as BODY.impulse.x|y")
            return Quantity("impulse", head, rest[-1])
        allowed = tuple(part.unknowns())
        if isinstance(part, Contact) and part.has_friction and "friction" not in allowed:
            allowed += ("friction",)
        if isinstance(part, Contact) and part.point is not None and "friction" in allowed:
            allowed += ("min_friction_coefficient",)
        if rest not in allowed:
            offered = allowed + (IMPULSES if pushes else ())
            raise ValueError(f"{head} has {', '.join(offered)}; not {rest!r}" + did_you_mean(rest, offered))
        return Quantity("contact" if rest == "min_friction_coefficient" else "force", head, rest)
    known = sorted(scene.bodies) + sorted(names) + ["small_oscillation"]
    raise ValueError(f"{head!r} is neither a body nor a constraint of the scene (known: {', '.join(known)})"
                     + did_you_mean(head, [*known, *SYSTEMS]))
