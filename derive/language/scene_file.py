"""The scene section of a problem file: bodies (each read by derive.language.body_file), joints, contacts,
surfaces, loads and the scene-level systems (orbit, standing wave, internal forces); its states
are read by derive.language.state_file.

Every field goes through the `derive.language.reader.Reader`, so errors name the file and the field.

>>> from derive.language.problem import load
>>> sorted(load("string_wrapped_disk").scene.bodies)
['block', 'disk']
"""
from __future__ import annotations

import dataclasses

import sympy as sp

from derive.language import body_file, solid_file, state_file
from derive.core.errors import EngineLimit
from derive.core.keys import Key, Keys
from derive.parts import (clutch, contact, cord, damper, force, gravity, pin, slider, spring, torque, torsional_spring, weld)
from derive.parts.contact import Contact
from derive.parts.cord import Attachment, Cord
from derive.parts.pin import Pin
from derive.parts.torque import Torque
from derive.parts.places import Places, turned
from derive.parts.surfaces import Circle, Plane
from derive.language.reader import Reader
from derive.core.spelling import did_you_mean, no_such
from derive.model.scene import RESERVED_NAMES, SYSTEMS, Body, Orbit, Scene, StandingWave

#: The modules of the parts under `scene.joints` (a mapping of names) and `scene.loads` (a list), by
#: their key; each reads its entry (`read`) and declares its keys (`KEYS`, but gravity's value is one
#: expression).
JOINTS = {"pin": pin, "slider": slider, "weld": weld, "clutch": clutch, "touches": contact}
LOADS = {"gravity": gravity, "force": force, "torque": torque, "spring": spring, "torsional_spring": torsional_spring,
         "damper": damper}
#: The shorthand `pull:` of a cord wound on a hub and pulled by a force.
PULL = Keys(on=Key("name", "the turning body (a spool)", required=True),
            force=Key("expression", "the pulling force, in N", required=True),
            angle=Key("quantity", "its direction above the horizontal", required=True),
            hub_radius=Key("expression", "the radius of the hub the cord leaves from below, in m", required=True))
#: The shorthand `string:` under `constraints:`: a cord wound on a reel, its load hanging straight down.
STRING = Keys(wound_on=Key("name", "the disk or ring the cord is wound on", required=True),
              hangs=Key("name", "the body hanging from it", required=True),
              side=Key("name", "the side of the reel the cord leaves from (default right)", choices=("right", "left")),
              name=Key("name", "the cord's name (default string)"))
#: Surfaces under `scene.surfaces`, by their kind.
PLANE = Keys(angle=Key("quantity", "its angle below the horizontal, in [0, pi/2)"),
             descends=Key("name", "the way it goes down (default right)", choices=("left", "right")),
             height=Key("expression", "how far it drops below where the bodies on it start, in m"),
             through=Key("vector", "a point it passes through, [x, y] (default [0, 0])"))
CIRCLE = Keys(radius=Key("expression", "its radius, in m", required=True),
              center=Key("vector", "its center, [x, y]"),
              side=Key("name", "the side bodies ride on (default inside: a bowl)", choices=("inside", "outside")))
LOOP = Keys(radius=Key("expression", "its radius, in m (a circle ridden inside)", required=True))
WALL = Keys(facing=Key("name", "the side bodies touch it from", required=True, choices=("left", "right")),
            through=Key("vector", "a point it passes through, [x, y] (default [0, 0])"))
SURFACE = Keys(plane=Key("mapping", "a straight incline or floor", keys=PLANE),
               incline=Key("mapping", "the same as plane", keys=PLANE),
               circle=Key("mapping", "a circle: a bowl or a dome", keys=CIRCLE),
               loop=Key("mapping", "a loop ridden inside", keys=LOOP),
               wall=Key("mapping", "a vertical plane", keys=WALL),
               carried_by=Key("name", "the body that carries it (a wedge's face, a cart's track)"))
STANDING_WAVE = Keys(radius=Key("expression", "the radius of the orbit, in m", required=True),
                     planck=Key("expression", "Planck's constant, in J s", required=True),
                     wavelengths=Key("integer", "how many wavelengths fit around it (default 1)"))
INTERNAL_FORCES = Keys(bodies=Key("integer", "how many bodies, 2 to 5", required=True))
ORBIT = Keys(GM=Key("expression", "the central body's G M, in m^3/s^2", required=True),
             angular_momentum=Key("expression", "the angular momentum per unit mass, in m^2/s"),
             semi_major_axis=Key("expression", "the ellipse's semi-major axis, in m"),
             eccentricity=Key("expression", "the ellipse's eccentricity, 0 to 1"),
             periapsis=Key("expression", "the closest distance to the central body, in m (with speed_at_periapsis, "
                                         "in place of semi_major_axis and eccentricity)"),
             speed_at_periapsis=Key("expression", "the speed there, in m/s"))


def _contact(reader: Reader, body: Body, spec: dict, surfaces: dict, field: str) -> Contact | None:
    """`on: SURFACE` with `contact: rolling` (a round body's default) or `sliding`, and
    `friction: {static: mu_s, kinetic: mu_k}` when the file gives the coefficients."""
    if "on" not in spec:
        for key in ("contact", "friction"):
            if key in spec:
                raise reader.fail(f"{field}.{key}", "a contact needs a surface: on: SURFACE")
        return None
    if spec["on"] not in surfaces:
        raise reader.fail(f"{field}.on", no_such("surface", spec["on"], surfaces, "surfaces"))
    if spec.get("joint") is not None:
        raise reader.fail(f"{field}.on", "a body on a surface cannot also turn on a joint")
    if surfaces[spec["on"]].carrier == body.name:
        raise reader.fail(f"{field}.on", f"the {body.name} carries {spec['on']}: it cannot rest on it")
    if body.composite is not None and "radius" not in body.sizes:
        raise EngineLimit(f"{reader.path}: {field}.on", "model a composite's contact with a surface other than by a "
                                                        "round part centered at its center of mass")
    kind = spec.get("contact", "rolling" if "radius" in body.sizes else "sliding")
    if kind not in ("rolling", "sliding"):
        raise reader.fail(f"{field}.contact", "expected rolling or sliding")
    if kind == "rolling" and "outer_radius" in body.sizes:  # its contact's geometry reads a radius, which it has not
        raise EngineLimit(f"{reader.path}: {field}.contact",
                          f"roll {'an' if body.shape[0] in 'aeiou' else 'a'} {body.shape.replace('_', ' ')} on its "
                          "outer radius; state it as shape: custom with radius: "
                          "(its outer radius) and inertia: (its moment about its center, `derive inertia "
                          f"{body.shape}` gives it)")
    if kind == "rolling" and "radius" not in body.sizes:
        raise reader.fail(f"{field}.contact", f"a {body.shape} has no radius to roll on")
    static, kinetic = contact.coefficients(reader, spec, field)
    if "friction" in spec:
        if kind == "rolling" and static is None:
            raise reader.fail(f"{field}.friction", "a body rolls as long as static friction holds it: give static: "
                                                   "mu_s (and kinetic: mu_k for when it slips)")
    if body.face_center is not None and (surfaces[spec["on"]].carrier is not None or "velocity" in spec):
        raise EngineLimit(f"{reader.path}: {field}.on", "follow a body whose round face is off its center of mass on a "
                                                        "moving surface or at a given velocity")
    return Contact(f"{body.name}_contact", body.name, spec["on"], kind == "rolling", static, kinetic,
                   carrier=surfaces[spec["on"]].carrier, center=body.face_center)


def _surfaces(reader: Reader, raw) -> dict:
    """`plane: {angle, descends, through, height}` (`incline` is the same; `descends: left` or
    `right`, the default), `circle: {radius, center, side}`
    (`loop: {radius}` is a circle ridden inside), `wall: {facing: left|right, through}` (a vertical
    plane; bodies touch it from the side it faces)."""
    raw = reader.mapping(raw or {}, "scene.surfaces", free=True)
    result = {}
    for name, spec in raw.items():
        field = f"scene.surfaces.{name}"
        reader.name(name, field, "a surface name")
        spec = dict(reader.mapping(spec, field, keys=SURFACE))
        carrier = spec.pop("carried_by", None)
        if carrier is not None:
            reader.name(carrier, f"{field}.carried_by", "a body's name")
        if len(spec) != 1:
            raise reader.fail(field, "expected one surface kind (plane or incline, circle or loop, wall)")
        (kind, details), = spec.items()
        where = f"{field}.{kind}"
        if kind == "wall":
            details = reader.mapping(details, where, keys=WALL)
            if details["facing"] not in ("left", "right"):
                raise reader.fail(f"{where}.facing", "left or right (the side bodies touch it from)")
            through = reader.vector(details["through"], f"{where}.through", "m", "a position") \
                if "through" in details else (sp.Integer(0), sp.Integer(0))
            # A vertical plane: its normal points the way it "descends", to the side it faces.
            result[name] = Plane(name, sp.pi / 2, None, through, carrier, descends=details["facing"])
            continue
        if kind in ("circle", "loop"):
            details = reader.mapping(details, where, keys=SURFACE[kind].keys)
            side = details.get("side", "inside")
            if side not in ("inside", "outside"):
                raise reader.fail(f"{where}.side", "inside (a bowl, a loop) or outside (a dome)")
            center = reader.vector(details["center"], f"{where}.center", "m", "a position") \
                if "center" in details else None
            result[name] = Circle(name, reader.positive(details["radius"], f"{where}.radius", "m", "a radius"),
                                  center, side, carrier)
            continue
        details = reader.mapping(details or {}, where, keys=PLANE)
        descends = details.get("descends", "right")
        if descends not in ("left", "right"):
            raise reader.fail(f"{where}.descends", "left or right (the way the plane goes down)")
        if "angle" in details:
            angle = reader.dimensioned(details["angle"], f"{where}.angle", "rad", "an angle")
            if not (angle.is_nonnegative and (sp.pi / 2 - angle).is_positive) and not angle.free_symbols:
                raise reader.fail(f"{where}.angle", "a plane's angle lies in [0, pi/2) "
                                                    "(`descends: left` for one that goes down to the left)")
        else:
            angle = reader.unspecified(f"angle_{name}", "rad")
        height = reader.positive(details["height"], f"{where}.height", "m", "a height") if "height" in details else None
        through = reader.vector(details["through"], f"{where}.through", "m", "a position") \
            if "through" in details else (sp.Integer(0), sp.Integer(0))
        result[name] = Plane(name, angle, height, through, carrier, descends)
    return result


def _string(reader: Reader, index: int, spec, bodies: dict[str, Body]) -> tuple[str, dict]:
    """The shorthand `constraints: [{string: {wound_on: REEL, hangs: LOAD, side: right}}]`: a cord
    wound on the reel's rim, its run straight down to the load's center. Returns the cord's name
    and the cord in the general form (`cords:`), with where the load hangs when it has no `at`."""
    field = f"scene.constraints[{index}]"
    spec = reader.mapping(spec, field, optional=("string",))
    if len(spec) != 1:
        raise reader.fail(field, "expected one constraint kind (string); joints and cords have their own sections")
    cord_spec = reader.mapping(spec["string"], f"{field}.string", keys=STRING)
    for key in ("wound_on", "hangs"):
        if cord_spec[key] not in bodies:
            raise reader.fail(f"{field}.string.{key}", no_such("body", cord_spec[key], bodies, "bodies"))
    reel = bodies[cord_spec["wound_on"]]
    if "radius" not in reel.sizes:
        raise reader.fail(f"{field}.string.wound_on", f"a cord winds on a disk or a ring, not a {reel.shape}")
    if cord_spec["hangs"] == cord_spec["wound_on"]:
        raise reader.fail(f"{field}.string.hangs", "a cord cannot hang from the body it is wound on")
    side = cord_spec.get("side", "right")
    if side not in ("right", "left"):
        raise reader.fail(f"{field}.string.side", "expected right or left")
    name = cord_spec.get("name", "string")
    reader.name(name, f"{field}.string.name", "a cord's name")
    radius = reel.sizes["radius"]
    below = sp.Matrix(reel.at) + sp.Matrix([radius if side == "right" else -radius, -3 * radius])
    return name, {"path": [{"wound": reel.name, "side": side}, cord_spec["hangs"]], "field": f"{field}.string",
                  "hangs": (cord_spec["hangs"], tuple(below))}


def _placed(reader: Reader, bodies: dict[str, Body], specs: dict, surfaces: dict, hanging: dict) -> dict[str, Body]:
    """Bodies without `at`, placed: on a surface, touching it where it passes its reference point;
    hanging from a cord given in shorthand, below where the cord leaves the reel."""
    result = dict(bodies)
    for name, body in bodies.items():
        if "at" in specs[name]:
            continue
        if "on" in specs[name] and specs[name]["on"] in surfaces:
            radius = body.sizes.get("radius", sp.Integer(0))
            off = turned(body.angle, body.face_center or (0, 0))  # from the center of mass to the face's center
            result[name] = dataclasses.replace(body, at=tuple(surfaces[specs[name]["on"]].touching(radius) - off))
        elif name in hanging:
            result[name] = dataclasses.replace(body, at=hanging[name])
    return result


def _loads(reader: Reader, raw, places: Places) -> tuple[list, list]:
    """`loads:` a list of `{KIND: SPEC}` (LOADS; `pull` is the shorthand of a cord wound on a hub
    and pulled by a force). Returns (gravity, if any, in a list; the other loads)."""
    if not isinstance(raw, list):
        raise reader.fail("scene.loads", "expected a list")
    found, others = [], []
    counts: dict[str, int] = {}
    for i, load in enumerate(raw):
        field = f"scene.loads[{i}]"
        load = reader.mapping(load, field, optional=(*LOADS, "pull"))
        if len(load) != 1:
            raise reader.fail(field, f"expected one load kind ({', '.join([*LOADS, 'pull'])})")
        (kind, spec), = load.items()
        counts[kind] = counts.get(kind, 0) + 1
        name = spec.get("name") if isinstance(spec, dict) and "name" in spec else f"{kind}{counts[kind]}"
        if kind == "pull":
            others.append(_pull(reader, i, spec, places))
        elif kind == "gravity":
            if found:
                raise reader.fail(field, "gravity is given twice")
            found.append(LOADS[kind].read(reader, places, "gravity", spec, f"{field}.gravity"))
        else:
            reader.name(name, f"{field}.{kind}.name", "a load's name")
            others.append(LOADS[kind].read(reader, places, name, spec, f"{field}.{kind}"))
    return found, others


def _pull(reader: Reader, index: int, spec, places: Places) -> Cord:
    """The shorthand `pull: {on: SPOOL, force: F, angle: theta, hub_radius: r}`: a cord wound on a
    hub of radius r, leaving it from below (the tugged spool of the notes), pulled with force F
    toward theta above the horizontal."""
    field = f"scene.loads[{index}].pull"
    pull = reader.mapping(spec, field, keys=PULL)
    bodies = places.bodies
    if pull["on"] not in bodies or not bodies[pull["on"]].rotates:
        raise reader.fail(f"{field}.on", f"no turning body {pull['on']!r} (bodies: {', '.join(bodies)})")
    force = reader.positive(pull["force"], f"{field}.force", "N", "a pulling force")
    angle = reader.dimensioned(pull["angle"], f"{field}.angle", "rad", "an angle")
    hub = reader.positive(pull["hub_radius"], f"{field}.hub_radius", "m", "a hub radius")
    # Leaving the hub's underside toward the pull, the cord goes around it counter-clockwise.
    return Cord(f"pull{index}", (Attachment("wound", pull["on"], radius=hub, turn=1, grips=True),
                                 Attachment("pulled", force=force, angle=angle)))


def _placements(places: Places, scene: Scene) -> tuple[sp.Expr, ...]:
    """The factors whose sign the file's placement decides: each absolute value in a part's extents
    in the reference configuration (a block hanging at depth h below a pulley of radius R has a run
    |h - R| long), or in the radius a round body's center rides on a circular surface (R - r in a
    loop), with the sign it has at the middle of the ranges. The derivation takes them so
    (the answers read h - R, not |h - R|: sympy cannot cancel an absolute value, and an equilibrium
    was refused as none), and `Solution.conditions` keeps that sign in every variant."""
    from derive.core.tidying import radicals
    from derive.model.kinematics import Coordinates

    coords = Coordinates(scene)
    rest = coords.at_rest_in_reference()
    sizes = [e.xreplace(rest) for part in scene.constraints + scene.loads for e, _ in part.extents(coords)]
    # the radius of the circle a round body's center rides on a circular surface, |R - r| inside
    # (a ball in a loop), the one it rests on or the one a transfer carries it onto
    riding = [(c.surface, c.body) for c in scene.constraints if isinstance(c, Contact) and c.point is None]
    riding += [(s.event.to, s.event.body) for s in scene.states.values() if s.event and s.event.kind == "transfer"]
    sizes += [sp.Abs(scene.surfaces[surface].path_radius(scene.bodies[body].sizes.get("radius", sp.Integer(0))))
              for surface, body in riding if isinstance(scene.surfaces.get(surface), Circle)]
    placed = {}
    for size in sizes:
        for absolute in radicals(size).atoms(sp.Abs):
            value = places.sample(absolute.args[0])
            if value:
                placed[absolute.args[0] if value > 0 else -absolute.args[0]] = None
    return tuple(placed)


def _cord(reader: Reader, places: Places, name: str, path, field: str) -> Cord:
    """A cord read from its path (derive.parts.cord), its runs checked in the reference configuration."""
    made = cord.read(reader, places, name, path, field)
    _check_runs(reader, places, made, field)
    return made


def _check_runs(reader: Reader, places: Places, made: Cord, field: str) -> None:
    """Every run has a length in the reference configuration, and no circle overlaps the next."""
    from derive.model.kinematics import Coordinates

    coords = Coordinates(Scene(places.bodies))
    rest = coords.at_rest_in_reference()
    for i, (a, b) in enumerate(zip(made.path, made.path[1:])):
        if a.kind == "pulled" or b.kind == "pulled":
            continue
        between = (b.center(coords) - a.center(coords)).xreplace(rest)
        reach = places.sample(between.dot(between)) - places.sample((b.rho - a.rho) ** 2)
        if reach <= 1e-12 * (1 + places.sample(between.dot(between))):
            raise reader.fail(f"{field}[{i + 1}]", f"the cord's run from {cord.describe(a)} to {cord.describe(b)} has no "
                                                   "length (the two are at one place, or their circles overlap): "
                                                   "place the bodies with at")


def _check_geometry(reader: Reader, places: Places, scene: Scene) -> None:
    """Before anything is derived: each body on a surface touches it, and no cord whose tension is
    unknown pulls it straight off or into its surface (a body resting on a surface does not hang
    from a cord: the normal force and the tension would share one balance). A cord pulled with a
    given force may: the sign of the normal force is then checked for every variant."""
    from derive.model.kinematics import Coordinates

    coords = Coordinates(scene)
    rest = coords.at_rest_in_reference()
    for c in scene.constraints:
        if not isinstance(c, Contact):
            continue
        surface, body = scene.surfaces[c.surface], scene.bodies[c.body]
        if c.point is None:
            radius, center = body.sizes.get("radius", sp.Integer(0)), places.world(c.body, c.center or (0, 0))
            field = f"scene.bodies.{c.body}.at"
        else:
            radius, center, field = sp.Integer(0), places.world(c.body, c.point), f"scene.joints.{c.name}.touches"
        off = places.sample(surface.gap(center, radius))
        scale = 1 + max(abs(places.sample(v)) for v in center)
        if abs(off) > 1e-9 * scale:
            raise reader.fail(field, f"the {c.body} does not touch {c.surface} there (it is "
                                     f"{off:.4g} m {'off' if off > 0 else 'inside'} it, at the middle of the "
                                     "parameter ranges)")
        if c.point is not None:
            continue  # a body touching at a point has its own torque balance: a cord along the normal is no clash
        normal = surface.normal_at(coords.position(c.body), radius).xreplace(rest)
        for part in scene.constraints + scene.loads:
            if not isinstance(part, Cord):
                continue
            for segment in part.segments():
                if segment.symbol is None:  # pulled with a given force: the normal force is N = weight - pull
                    continue
                for r in segment.runs(coords):
                    if c.body in (r.start.body, r.end.body):
                        direction = r.direction.xreplace(rest)
                        across = places.sample(direction[0] * normal[1] - direction[1] * normal[0])
                        if abs(across) < 1e-9:
                            raise reader.fail(f"scene.cords.{part.name}", f"the cord pulls the {c.body} straight "
                                              f"along the normal of {c.surface}: a body resting on a surface does not "
                                              "hang from a cord (place the pulley so that the run is along the "
                                              "surface)")


#: The sections of `scene:`. Joints, loads, cords and constraints hold the parts of JOINTS and
#: LOADS, the cords' paths (derive.parts.cord) and STRING; derive.language.schema spells them out.
SCENE = Keys(bodies=Key("mapping", "the bodies, by name", values=body_file.BODY),
             points=Key("mapping", "points of the ground, by name: [x, y]", values=Key("vector", "a point of the ground")),
             surfaces=Key("mapping", "the surfaces, by name", values=SURFACE),
             joints=Key("mapping", "joints, by name: one of " + ", ".join(JOINTS)),
             cords=Key("mapping", "cords, by name: each a path from end to end"),
             constraints=Key("list", "the shorthand string: entries", items=Keys(string=Key("mapping", "a string wound "
                                                                                 "on a reel", keys=STRING))),
             loads=Key("list", "the loads, each one of " + ", ".join(LOADS) + " or pull"),
             states=Key("mapping", "states of the motion, by name, in order", values=state_file.STATE),
             orbit=Key("mapping", "a body in a Kepler orbit", keys=ORBIT),
             standing_wave=Key("mapping", "a standing wave on a circle (Bohr's model)", keys=STANDING_WAVE),
             internal_forces=Key("mapping", "internal forces between bodies", keys=INTERNAL_FORCES))
#: Keys of earlier versions, refused with what to write instead.
RETIRED = ("events", "top", "spinning_wheel")


def read_scene(reader: Reader, raw) -> Scene:
    """The scene section, validated, as a Scene."""
    raw = reader.mapping(raw, "scene", keys=SCENE, optional=RETIRED)
    if "events" in raw:
        raise reader.fail("scene.events", "write events as states: `struck: {from: flying, event: {stick: bullet, "
                                          "to: rod}}` (stick, lock, bounce, move, turn or transfer; see the "
                                          "documentation's States and events)")
    orbit = _orbit(reader, raw["orbit"]) if "orbit" in raw else None
    if "top" in raw:
        raise reader.fail("scene.top", "a top is a body on a fixed point: bodies: {top: {shape: custom, mass: m, "
                                       "inertia: {axial: I3, transverse: I1}, pivot_point: {at: l, tilt: theta, "
                                       "spin: omega}}} (or any shape of derive inertia), with - gravity: g")
    if "spinning_wheel" in raw:
        raise reader.fail("scene.spinning_wheel", "a spinning wheel is a body on a fixed point at its center of mass "
                                                  "under a couple for a time: bodies: {wheel: {shape: custom, "
                                                  "inertia: {axial: I}, pivot_point: {at: center, tilt: pi/2, spin: "
                                                  "omega}}}, loads: [{torque: {on: wheel, magnitude: tau, axis: "
                                                  "[0, 0, 1], duration: dt}}]")
    wave = _wave(reader, raw["standing_wave"]) if "standing_wave" in raw else None
    internal = _internal_forces(reader, raw["internal_forces"]) if "internal_forces" in raw else None
    surfaces = _surfaces(reader, raw.get("surfaces"))
    ground = {name: reader.vector(v, f"scene.points.{name}", "m", "a position")
              for name, v in reader.named(raw.get("points"), "points").items()}
    bodies_raw = reader.mapping(raw.get("bodies") or {}, "scene.bodies", free=True)
    if not bodies_raw and all(s is None for s in (orbit, wave, internal)):
        raise reader.fail("scene.bodies", "a scene needs at least one body (or an orbit, a standing_wave)")
    bodies, pins = {}, []
    for name, spec in bodies_raw.items():
        reader.name(name, f"scene.bodies.{name}", "a body name")
        if name in ground or name == "ground":
            raise reader.fail(f"scene.bodies.{name}", "the name is also a point of the ground")
        body, joint = body_file.read(reader, name, spec)
        bodies[name] = body
        pins += [joint] if joint else []
    rolling = {n: solid_file.rolls_on_edge(reader, spec, f"scene.bodies.{n}", bodies[n]) for n, spec in bodies_raw.items()
               if "rolls_on_edge" in spec}
    for name, surface in surfaces.items():
        if surface.carrier is not None and surface.carrier not in bodies:
            raise reader.fail(f"scene.surfaces.{name}.carried_by", no_such("body", surface.carrier, bodies, "bodies"))
    constraints_raw = raw.get("constraints") or []
    if not isinstance(constraints_raw, list):
        raise reader.fail("scene.constraints", "expected a list")
    strings = [_string(reader, i, c, bodies) for i, c in enumerate(constraints_raw)]
    hanging = {cord["hangs"][0]: cord["hangs"][1] for _, cord in strings}
    bodies = _placed(reader, bodies, bodies_raw, surfaces, hanging)
    places = Places(reader, bodies, ground, surfaces)
    contacts = [c for n, spec in bodies_raw.items()
                if (c := _contact(reader, bodies[n], spec, surfaces, f"scene.bodies.{n}")) is not None]
    # A joint given with its body is named "axle" or "pivot"; with several of a kind, "<body>_axle".
    kinds = [p.name for p in pins]
    pins = [p if kinds.count(p.name) == 1 else Pin(f"{p.body}_{p.name}", p.body, p.offset) for p in pins]
    joints = []
    for name, spec in reader.named(raw.get("joints"), "joints").items():
        field = f"scene.joints.{name}"
        kind = [k for k in JOINTS if isinstance(spec, dict) and k in spec]
        if len(kind) != 1:
            hint = next((h for k in spec if (h := did_you_mean(k, JOINTS))), "") if not kind and isinstance(spec, dict) \
                else ""
            raise reader.fail(field, f"expected one joint kind ({', '.join(JOINTS)}){hint}")
        joints.append(JOINTS[kind[0]].read(reader, places, name, spec, field))
    cords = [_cord(reader, places, name, spec["path"], spec["field"]) for name, spec in strings]
    cords += [_cord(reader, places, name, path, f"scene.cords.{name}")
              for name, path in reader.named(raw.get("cords"), "cords").items()]
    found, loads = _loads(reader, raw.get("loads") or [], places)
    # a part with no force of its own to find (a cord pulled with a given force, a slipping
    # clutch's kinetic couple) is a load
    constraints = [*pins, *contacts, *(j for j in joints if j.unknowns()), *(c for c in cords if c.unknowns())]
    loads = [*(j for j in joints if not j.unknowns()), *(c for c in cords if not c.unknowns()), *loads]
    names = [p.name for p in constraints + loads]
    duplicate = next((n for n in names if names.count(n) > 1 or n in bodies), None)
    if duplicate:
        raise reader.fail("scene", f"the name {duplicate!r} is used twice (bodies, joints, cords and loads)")
    reserved = next((n for n in [*bodies, *names] if n in (*RESERVED_NAMES, *SYSTEMS)), None)
    if reserved:
        raise reader.fail("scene", f"the name {reserved!r} is reserved for asks ({reserved}.…): name the part "
                                   "otherwise")
    motions = {n: m for n, spec in bodies_raw.items() if (m := body_file.motion(reader, n, spec, bodies)) is not None}
    # A velocity is the speed of a body rolling without slipping; other rates are a state's.
    rolling_at = {c.body for c in constraints if isinstance(c, Contact) and c.rolling}
    moving = next((n for n, spec in bodies_raw.items() if "velocity" in spec and n not in rolling_at), None)
    if moving:
        raise reader.fail(f"scene.bodies.{moving}.velocity", "a velocity is the speed of a body rolling without "
                          f"slipping; give other rates in a state: states: {{moving: {{rates: "
                          f"{{{moving}.velocity.x: v}}}}}}")
    gravity_part = found[0] if found else None
    pivoted = {n: solid_file.pivot_point(reader, spec, f"scene.bodies.{n}", bodies[n]) for n, spec in bodies_raw.items()
               if "pivot_point" in spec}
    _couples_in_3d(reader, raw.get("loads") or [], loads, pivoted)
    if any(p.centered for p in pivoted.values()):
        if gravity_part is not None or len(bodies) > 1 or constraints or len(loads) != 1 or raw.get("states"):
            raise reader.fail("scene.loads" if gravity_part is not None or len(loads) != 1 else "scene",
                              "a body on a fixed point at its center of mass turns under one couple for a time: one "
                              "body, one - torque: {on: BODY, magnitude: tau, axis: [x, y, z], duration: dt}, no "
                              "gravity (its weight exerts no torque about the point: leave it out), joints, cords or "
                              "states")
    elif pivoted and (gravity_part is None or len(bodies) > 1 or constraints or loads):
        raise reader.fail("scene.loads" if gravity_part is None else "scene", "a body on a fixed point turns under "
                          "gravity alone: one body, - gravity: g, no other loads, joints or cords")
    held = {n: solid_file.bearings(reader, spec, f"scene.bodies.{n}", bodies[n], gravity_part is not None)
            for n, spec in bodies_raw.items() if "bearings" in spec}
    if rolling and (gravity_part is None or len(bodies) > 1 or constraints or loads or surfaces):
        raise reader.fail("scene.loads" if gravity_part is None else "scene.surfaces" if surfaces else "scene",
                          "a body rolling on its edge rolls on the horizontal plane its key stands for, under gravity "
                          "alone: one body, - gravity: g, no surfaces (an inclined plane is not modelled), other "
                          "loads, joints or cords")
    free = {n: solid_file.free_rotation(reader, spec, f"scene.bodies.{n}", bodies[n]) for n, spec in bodies_raw.items()
            if "free_rotation" in spec}
    if free and (len(bodies) > 1 or constraints or loads or gravity_part is not None or raw.get("states")):
        raise reader.fail("scene", "a body in free rotation turns with no torque about its center: one body, no "
                                   "loads, joints, cords or states (its weight exerts no torque about its center: "
                                   "leave gravity out)")
    states = state_file.read(reader, raw.get("states"), places, [*constraints, *loads])
    rocking = next((c.body for c in contacts if c.center is not None), None)
    if rocking and states:
        raise EngineLimit(f"{reader.path}: scene.states", f"follow the {rocking}, whose round face is off its center "
                                                          "of mass, to a state: ask its small oscillations or where "
                                                          "it rests")
    scene = Scene(bodies, tuple(constraints), gravity_part, surfaces, tuple(loads), orbit, motions, wave,
                  internal, held, pivoted, rolling, free, states)
    _check_geometry(reader, places, scene)
    scene = dataclasses.replace(scene, placed=_placements(places, scene))
    return scene


def _wave(reader: Reader, raw) -> StandingWave:
    field = "scene.standing_wave"
    raw = reader.mapping(raw, field, keys=STANDING_WAVE)
    n = reader.expression(raw.get("wavelengths", 1), f"{field}.wavelengths", {})
    if not (n.is_integer and n.is_positive):
        raise reader.fail(f"{field}.wavelengths", "a whole number of wavelengths, 1 or more")
    return StandingWave(reader.positive(raw["radius"], f"{field}.radius", "m", "a radius"),
                        reader.positive(raw["planck"], f"{field}.planck", "J*s", "Planck's constant"), n)


def _internal_forces(reader: Reader, raw) -> int:
    raw = reader.mapping(raw, "scene.internal_forces", keys=INTERNAL_FORCES)
    if not isinstance(raw["bodies"], int) or not 2 <= raw["bodies"] <= 5:
        raise reader.fail("scene.internal_forces.bodies", "a whole number of bodies from 2 to 5")
    return raw["bodies"]


def _couples_in_3d(reader: Reader, raw: list, loads: list, pivoted: dict) -> None:
    """A torque about a direction in 3D (`axis:`, `duration:`) acts on a body on a fixed point at its
    center of mass, and such a body's torque is one: each refused by its field otherwise."""
    torques = iter(p for p in loads if isinstance(p, Torque))
    for i, spec in enumerate(raw):
        if "torque" not in spec:
            continue
        couple, field = next(torques), f"scene.loads[{i}].torque"
        centered = couple.body in pivoted and pivoted[couple.body].centered
        if couple.axis is not None and not centered:
            raise reader.fail(f"{field}.axis", "a couple about a direction in 3D for a time acts on a body on a fixed "
                                               "point at its center of mass (pivot_point: {at: center}); in the "
                                               "plane a torque is counter-clockwise, with no axis or duration")
        if couple.axis is None and centered:
            raise reader.fail(f"{field}.axis", "a body turning in 3D about its center of mass takes a couple about a "
                                               "direction fixed in the ground for a time: axis: [x, y, z] (z up) "
                                               "and duration: dt")


def _orbit_from_periapsis(reader: Reader, raw: dict, field: str, GM: sp.Expr, l) -> Orbit:
    """An ellipse given by its periapsis r_p and the speed v_p there: the energy v_p^2/2 - GM/r_p is
    -GM/(2a), so a = GM r_p/(2 GM - r_p v_p^2); and r_p = a(1 - e), so e = r_p v_p^2/GM - 1. Bound
    (2 GM > r_p v_p^2) and a periapsis (v_p^2 >= GM/r_p, at least the circular speed) over the
    declared ranges, or refused."""
    missing = [k for k in ("periapsis", "speed_at_periapsis") if k not in raw]
    if missing or "semi_major_axis" in raw or "eccentricity" in raw or l is not None:
        raise reader.fail(field, "an ellipse from its periapsis needs periapsis and speed_at_periapsis, and "
                                 "nothing else of its shape (semi_major_axis, eccentricity, angular_momentum)")
    rp = reader.positive(raw["periapsis"], f"{field}.periapsis", "m", "a periapsis")
    vp = reader.positive(raw["speed_at_periapsis"], f"{field}.speed_at_periapsis", "m/s", "a speed")
    if not reader.proven_over_ranges(2 * GM - rp * vp**2):
        raise reader.fail(f"{field}.speed_at_periapsis", "the orbit must be bound for every allowed parameter "
                                                         "value: v_p^2 < 2 GM/r_p (at the escape speed or above it "
                                                         "is a parabola or hyperbola)")
    if not reader.proven_over_ranges(rp * vp**2 - GM, strict=False):
        raise reader.fail(f"{field}.speed_at_periapsis", "at the closest point the speed is at least the circular "
                                                         "speed, v_p^2 >= GM/r_p, for every allowed parameter value "
                                                         "(slower, the point is the farthest: the apoapsis)")
    return Orbit(GM, None, sp.simplify(GM * rp / (2 * GM - rp * vp**2)), sp.simplify(rp * vp**2 / GM - 1), (rp, vp))


def _orbit(reader: Reader, raw) -> Orbit:
    field = "scene.orbit"
    raw = reader.mapping(raw, field, keys=ORBIT)
    GM = reader.positive(raw["GM"], f"{field}.GM", "m^3/s^2", "GM")
    l = None
    if "angular_momentum" in raw:
        l = reader.positive(raw["angular_momentum"], f"{field}.angular_momentum", "m^2/s", "an angular momentum per unit mass")
    a = e = None
    if "periapsis" in raw or "speed_at_periapsis" in raw:
        return _orbit_from_periapsis(reader, raw, field, GM, l)
    if ("semi_major_axis" in raw) != ("eccentricity" in raw):
        raise reader.fail(field, "an ellipse needs both semi_major_axis and eccentricity")
    if "semi_major_axis" in raw:
        a = reader.positive(raw["semi_major_axis"], f"{field}.semi_major_axis", "m", "a semi-major axis")
        e = reader.dimensioned(raw["eccentricity"], f"{field}.eccentricity", "1", "an eccentricity")
        ends = {p.symbol: p.si_ends for p in reader.parameters.values()}
        if e in ends:  # a parameter: its range's ends, exactly
            ellipse = 0 <= ends[e][0] and ends[e][1] < 1
        else:  # an expression (rp*vp**2/GM - 1): proven over the ranges
            ellipse = (e.is_nonnegative or reader.proven_over_ranges(e, strict=False)) and \
                ((1 - e).is_positive or reader.proven_over_ranges(1 - e))
        if not ellipse:
            raise reader.fail(f"{field}.eccentricity", "an ellipse has 0 <= e < 1 (e >= 1 is a parabola or hyperbola)")
    return Orbit(GM, l, a, e)

