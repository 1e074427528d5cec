"""A body's entry under `scene.bodies`: its shape, mass (or density), sizes or given inertia, its
place and angle, its joint to the ground, a prescribed path, its parts (a composite), and where
it starts moving; what touches it and what acts on it are read with the scene (derive.language.scene_file).

Every field goes through the `derive.language.reader.Reader`, so errors name the file and the field.

>>> from derive.language.problem import load
>>> load("string_wrapped_disk").scene.bodies["disk"].shape
'disk'
"""
from __future__ import annotations

import itertools

import sympy as sp

from derive.model import composite, inertia
from derive.language import solid_file
from derive.core import units
from derive.core.keys import Key, Keys
from derive.parts import contact
from derive.core.errors import InputError
from derive.parts.pin import Pin
from derive.parts.places import sample as reader_sample
from derive.parts.places import turned
from derive.language.reader import Reader, describe
from derive.core.expr import TIME
from derive.numbers import intervals
from derive.model.scene import Path as MotionPath  # a prescribed motion, not a file path
from derive.model.scene import SHAPE_SIZES, Body, Motion
from derive.core.spelling import did_you_mean


#: A body's keys that start it moving: its place (`at`) and its velocity (a rolling body's).
MOTION_KEYS = ("at", "velocity")
#: The units of a shape's coordinates in a density.
COORDINATE_UNITS = {"x": "m", "y": "m", "z": "m", "r": "m", "phi": "rad", "theta": "rad"}
#: A prescribed path's coordinates and their units, by kind.
PATH_COORDINATES = {"polar": (("r", "m"), ("theta", "rad")), "cartesian": (("x", "m"), ("y", "m"))}


#: The sizes any shape takes (each shape its own: SHAPE_SIZES).
ALL_SIZES = sorted({s for sizes in SHAPE_SIZES.values() for s in sizes})
#: `joint: {pivot: ...}`: the body turns about a fixed point off its center.
PIVOT = Keys(distance=Key("expression", "how far the pin is from the center of mass, in m", required=True),
             side=Key("name", "above (the body hangs) or below (it stands on it), in its own frame (default above)",
                      choices=("above", "below")))
#: `path: {polar: ...}` or `{cartesian: ...}`: a prescribed motion.
PATH = Keys(**{kind: Key("mapping", f"the {kind} coordinates as functions of t (or any)",
                         keys=Keys(**{c: Key("expression", f"{c}, in {unit}", required=True) for c, unit in names},
                                   **({"z": Key("expression", "z, in m, off the plane (a path in space; default 0)")}
                                      if kind == "cartesian" else {})))
               for kind, names in PATH_COORDINATES.items()})
#: A body's entry under `scene.bodies`.
BODY = Keys(shape=Key("name", "its shape: one of derive inertia's, composite or custom", required=True,
                      choices=(*SHAPE_SIZES,)),
            mass=Key("expression", "its mass, in kg"),
            density=Key("expression", "its density instead of a mass (a function of the shape's coordinates)"),
            inertia=Key("any", "a custom body's moment about its center (an expression), or in 3D {axial, transverse} "
                               "or {principal: [Ix, Iy, Iz]}"),
            inertia_about=Key("name", "where a custom inertia is taken: center (default) or pivot",
                              choices=("center", "pivot")),
            joint=Key("any", "fixed_axle (a pin at its center) or {pivot: {distance, side}}"),
            on=Key("name", "the surface it rests on"),
            contact=Key("name", "how it moves on the surface (rolling: a round body's default)",
                        choices=("rolling", "sliding")),
            friction=Key("mapping", "coefficients of its contact; derive decides the regime", keys=contact.FRICTION),
            path=Key("mapping", "a prescribed motion", keys=PATH),
            bearings=Key("mapping", "in 3D: it turns at a constant rate about a fixed shaft", keys=solid_file.BEARINGS),
            pivot_point=Key("mapping", "in 3D: it turns about a fixed point (a top)", keys=solid_file.PIVOT_POINT),
            rolls_on_edge=Key("mapping", "in 3D: it rolls on its rim on the horizontal plane",
                              keys=solid_file.ROLLS_ON_EDGE),
            free_rotation=Key("mapping", "in 3D: it turns with no torque", keys=solid_file.FREE_ROTATION),
            angle=Key("quantity", "its angle in the reference configuration, from +x counter-clockwise (default 0)"),
            parts=Key("mapping", "a composite's parts, each {shape, mass, sizes, at, angle} in the body's frame"),
            at=Key("vector", "where its center of mass is placed, [x, y] in m (a composite's: its origin)"),
            velocity=Key("vector", "its velocity [vx, vy] in m/s where it starts (a rolling body's)"),
            round_center=Key("vector", "a custom body's: the center of its round face of `radius`, [x, y] in m in its "
                                       "own frame from its center of mass (a hemisphere's, [0, 3*R/8]); it rests on "
                                       "that face, the half of the circle on the center of mass's side"),
            **{size: Key("expression", "a size of its shape, in m (see derive inertia --help)") for size in ALL_SIZES})


def read(reader: Reader, name: str, spec) -> tuple[Body, Pin | None]:
    """The body `name` and its joint to the ground (None without one)."""
    field = f"scene.bodies.{name}"
    spec = reader.mapping(spec, field, keys=BODY)
    shape = spec["shape"]
    if shape not in SHAPE_SIZES:
        raise reader.fail(f"{field}.shape", f"unknown shape {shape!r} (shapes: {', '.join(SHAPE_SIZES)})"
                                            + did_you_mean(shape, SHAPE_SIZES))
    if (shape == "composite") != ("parts" in spec):
        raise reader.fail(f"{field}.parts", "a composite body has parts: {NAME: {shape, mass, sizes, at}}; other "
                                            "shapes have none")
    if shape == "composite":
        return _composite(reader, name, spec, field)
    if "mass" in spec:
        mass = reader.positive(spec["mass"], f"{field}.mass", "kg", "a mass")
    elif "density" in spec:
        mass = None  # from the density, once the sizes are known
    else:
        mass = reader.unspecified(f"m_{name}", "kg")
    sizes = {}
    for size in ALL_SIZES:
        if shape == "custom" and size == "radius" and size in spec:  # a custom body may roll
            sizes[size] = reader.positive(spec[size], f"{field}.{size}", "m", "a radius")
        elif size in SHAPE_SIZES[shape]:
            if size in spec:
                sizes[size] = reader.positive(spec[size], f"{field}.{size}", "m", f"a {size}")
            else:
                sizes[size] = reader.unspecified(f"{size}_{name}", "m")
        elif size in spec:
            raise reader.fail(f"{field}.{size}", f"a {shape} has no {size}" + did_you_mean(size, SHAPE_SIZES[shape]))
    given = None
    if shape == "custom" and "free_rotation" in spec:
        given = solid_file.free_inertia(reader, spec, field)[2]  # the moment about z; the rest is read with the rotation
    elif shape == "custom" and ("pivot_point" in spec or "rolls_on_edge" in spec or "bearings" in spec):
        given = solid_file.axial_inertia(reader, spec, field)[1]  # the axial moment; the rest is read with the key
    elif shape == "custom":
        if "inertia" not in spec:
            raise reader.fail(f"{field}.inertia", "a custom body needs its moment of inertia about its center of mass")
        if isinstance(spec["inertia"], dict):
            raise reader.fail(f"{field}.inertia", "{axial, transverse} are a body's moments in 3D, read with what holds "
                                                  "it there (bearings:, pivot_point:, rolls_on_edge:, free_rotation:); "
                                                  "in a planar scene a body turns about the normal to the plane: give "
                                                  "that one moment")
        given = reader.dimensioned(spec["inertia"], f"{field}.inertia", "kg*m^2", "a moment of inertia")
        if given.is_nonnegative is not True:
            raise reader.fail(f"{field}.inertia", "a moment of inertia cannot be negative")
    elif "inertia" in spec:
        raise reader.fail(f"{field}.inertia", f"the inertia of a {shape} is derived, not given (use shape: custom)")
    density = None
    if "density" in spec:
        density, mass = _density(reader, spec["density"], f"{field}.density", shape, sizes, mass)
    path = None
    if "path" in spec:
        if shape != "point" or "joint" in spec or "on" in spec:
            raise reader.fail(f"{field}.path", "a prescribed path is for a free point mass")
        path = _path(reader, spec["path"], f"{field}.path", name)
    at = (reader.vector(spec["at"], f"{field}.at", "m", "a position") if "at" in spec
          else (sp.Integer(0), sp.Integer(0)))
    angle = reader.dimensioned(spec.get("angle", 0), f"{field}.angle", "rad", "an angle")
    if angle != 0 and shape == "point":
        raise reader.fail(f"{field}.angle", "a point mass has no orientation")
    body = Body(name, shape, mass, sizes, given, path, density, at, angle,
                round_center=_round_center(reader, spec, field, sizes))
    joint = _joint(reader, body, spec.get("joint"), f"{field}.joint")
    about = "center" if "pivot_point" in spec or "free_rotation" in spec else spec.get("inertia_about", "center")
    if about not in ("center", "pivot") or about == "pivot" and (given is None or joint is None or joint.name != "pivot"):
        raise reader.fail(f"{field}.inertia_about", "center, or pivot for a custom body on a pivot joint")
    if about == "pivot":
        # Given about the pivot: the center-of-mass moment follows from the parallel-axis theorem.
        distance = joint.offset[0] ** 2 + joint.offset[1] ** 2
        body = Body(name, shape, mass, sizes, given - mass * distance, at=at, angle=angle)
    return body, joint


def _round_center(reader: Reader, spec: dict, field: str, sizes: dict) -> tuple[sp.Expr, sp.Expr] | None:
    """`round_center: [x, y]`: a custom body with a `radius` whose round face is centered off its
    center of mass (a hemisphere, a half-cylinder), inside the circle and off the center of mass."""
    if "round_center" not in spec:
        return None
    where = f"{field}.round_center"
    if spec["shape"] != "custom" or "radius" not in sizes:
        raise reader.fail(where, "only a custom body with a radius has a round face off its center of mass (a "
                                 "uniform shape's is at its center)")
    center = reader.vector(spec["round_center"], where, "m", "a position")
    inside = reader_sample(reader, sizes["radius"] ** 2 - center[0] ** 2 - center[1] ** 2)
    if not 0 < inside < reader_sample(reader, sizes["radius"] ** 2):
        raise reader.fail(where, "the round face's center is off the center of mass by less than the radius (not so "
                                 "at the middle of the ranges; leave it out for a face centered there)")
    return center


def _composite(reader: Reader, name: str, spec: dict, field: str) -> tuple[Body, Pin | None]:
    """A body made of parts (derive.model.composite): `at` places the origin of the parts' frame."""
    for key in ("mass", "density", "inertia", "inertia_about", "path"):
        if key in spec:
            raise reader.fail(f"{field}.{key}", f"a composite's {key.replace('_', ' ')} comes from its parts"
                              if key in ("mass", "density", "inertia", "inertia_about") else
                              f"a composite body has no {key}")
    for size in sorted({s for sizes in SHAPE_SIZES.values() for s in sizes} & set(spec)):
        raise reader.fail(f"{field}.{size}", f"a composite has no {size} of its own: its parts have sizes")
    made = composite.read(reader, spec["parts"], f"{field}.parts")
    origin = (reader.vector(spec["at"], f"{field}.at", "m", "a position") if "at" in spec
              else (sp.Integer(0), sp.Integer(0)))
    angle = reader.dimensioned(spec.get("angle", 0), f"{field}.angle", "rad", "an angle")
    at = tuple(sp.Matrix(origin) + turned(angle, made.center))
    radius, center = made.radius(reader)
    if center is not None and "on" not in spec:  # a round part off the center of mass matters only to roll on
        radius = None
    body = Body(name, "composite", made.mass, {} if radius is None else {"radius": radius}, made.inertia,
                at=at, angle=angle, composite=made, round_center=center)
    return body, _joint(reader, body, spec.get("joint"), f"{field}.joint")


def _density(reader: Reader, raw, field: str, shape: str, sizes: dict, mass: sp.Expr | None):
    """A body's density in its shape's coordinates: with a mass, a profile scaled to that mass
    (dimensionless); without, an absolute density whose integral gives the mass."""
    if shape not in inertia.SHAPES or shape == "point":
        raise reader.fail(field, f"a {shape} has no density to give")
    coordinates = inertia.SHAPES[shape].density_symbols
    clash = sorted(set(coordinates) & set(reader.symbols))
    if clash:
        raise reader.fail(field, f"the parameter {clash[0]} has the name of a {shape} coordinate: rename it")
    density = reader.expression(raw, field, {**reader.symbols, **coordinates})
    units_here = {**reader.symbol_units, **{s: COORDINATE_UNITS[n] for n, s in coordinates.items()}}
    try:
        found = units.expression_dimension(density, units_here)
    except units.UnitError as error:
        raise reader.fail(field, str(error)) from None
    _not_negative(reader, field, shape, sizes, density)
    if mass is not None:
        if found:
            raise reader.fail(field, f"with a mass given, the density is a profile without dimension; it has "
                                     f"{describe(found)}")
        return density, mass
    try:
        derived, _ = inertia.body_moment(shape, inertia.PLANAR_AXIS[shape], None, sizes, density)
        found = units.expression_dimension(derived, units_here)
    except (units.UnitError, InputError) as error:
        raise reader.fail(field, str(error)) from None
    if not units.same_dimension(found, units.dimension(units.parse_unit("kg"))):
        raise reader.fail(field, f"the density integrates to {describe(found)}, not to a mass")
    return density, derived


def _not_negative(reader: Reader, field: str, shape: str, sizes: dict, density: sp.Expr) -> None:
    """Refuse a density negative somewhere on the body for a parameter value the file allows: it is
    proven not negative by sympy (every value), or in balls over the declared ranges with the body's
    coordinates over the body (derive.numbers.intervals; those parameters then held to their ranges);
    else a point of the body and of the ranges where it is negative is named, or it is refused as
    unproven. The body's sizes are its own (the file's L in (x + L/2)/L is the rod's length).

    Each coordinate is written lo + t (hi - lo), t in (0, 1): the interior, where a density counts
    ((r/R)**k with k < 0 is infinite at r = 0 only)."""
    table = inertia.SHAPES[shape]
    generic = {table.sizes[name]: value for name, value in sizes.items()}
    where, fractions = {}, []
    for coordinate, low, high in table.coordinates:  # outermost first: inner ends may use outer coordinates
        low, high = (sp.sympify(e, strict=True).xreplace(generic).xreplace(where)  # safe: inertia.SHAPES' own, never text
                     for e in (low, high))
        fraction = sp.Dummy(f"t_{coordinate}", positive=True)
        where[coordinate], fractions = low + fraction * (high - low), fractions + [fraction]
    position = [sp.sympify(c, strict=True).xreplace(generic).xreplace(where)  # safe: the shape table's, never text
                for c in table.position]
    rho = density.xreplace({**where, **dict(zip((inertia.x, inertia.y, inertia.z), position))})
    rho = sp.cancel(rho) if rho.is_rational_function() else sp.powsimp(rho)
    if rho.is_nonnegative:
        return
    ends = {p.symbol: p.si_ends for p in reader.parameters.values()}
    box = {**{s: ends[s] for s in rho.free_symbols if s in ends}, **{t: (0, 1) for t in fractions}}
    if any(all(f.is_nonnegative or f.free_symbols <= set(box) and intervals.positive_over(f, box, strict=False)
               for f in factors) for factors in ([rho], sp.Mul.make_args(rho))):  # whole, or factor by factor
        reader.held_to_range |= rho.free_symbols - set(fractions)
        return
    grid = itertools.product(*([(s, low + (high - low) * sp.Rational(k, 4)) for k in range(5)]
                               for s, (low, high) in box.items()))
    for point in itertools.islice(grid, 20000):
        if rho.xreplace(dict(point)).evalf().is_extended_negative:
            at = dict(point)
            shown = {**{c: v.xreplace(at) for c, v in where.items()}, **{s: at[s] for s in box if s in ends}}
            text = ", ".join(f"{s}={sp.nsimplify(v) if v.is_number else v}" for s, v in shown.items())
            raise reader.fail(field, f"the density {density} is negative on the {shape} where {text} (SI units), "
                                     "inside the declared ranges")
    raise reader.fail(field, f"the density {density} could not be proven not negative on the {shape} over the "
                             "declared ranges (no point where it is negative was found either): narrow the ranges, "
                             "or write it so that its sign is plain")


def motion(reader: Reader, name: str, spec: dict, bodies: dict[str, Body]) -> Motion | None:
    """A body placed at a given point (`at`), or rolling at a given `velocity`."""
    field = f"scene.bodies.{name}"
    if not any(k in spec for k in MOTION_KEYS):
        return None
    velocity = reader.vector(spec["velocity"], f"{field}.velocity", "m/s", "a velocity") if "velocity" in spec \
        else (sp.Integer(0), sp.Integer(0))
    return Motion(bodies[name].at, velocity)  # the center of mass (a composite's `at` is its parts' origin)


def _path(reader: Reader, raw, field: str, body: str) -> MotionPath:
    """`{polar: {r: EXPR, theta: EXPR}}` or `{cartesian: {x: ..., y: ...}}` in the parameters and
    the time t; `any` leaves a coordinate an arbitrary function of time."""
    raw = reader.mapping(raw, field, keys=PATH)
    if len(raw) != 1:
        raise reader.fail(field, "expected polar or cartesian")
    (kind, spec), = raw.items()
    names = PATH_COORDINATES[kind]
    spec = reader.mapping(spec, f"{field}.{kind}", keys=PATH[kind].keys)
    if "t" in reader.symbols:
        raise reader.fail(f"{field}.{kind}", "t is the time in a path: rename the parameter t")
    reader.symbol_units.setdefault(TIME, "s")
    allowed = {**reader.symbols, "t": TIME}
    functions = []
    for name, unit in names:
        if spec[name] == "any":
            function = sp.Function(name)(TIME)
            reader.symbol_units[function] = unit
            functions.append(function)
        else:
            functions.append(reader.dimensioned(spec[name], f"{field}.{kind}.{name}", unit, f"a path's {name}", allowed))
    z = reader.dimensioned(spec["z"], f"{field}.{kind}.z", "m", "a path's z", allowed) if "z" in spec else sp.Integer(0)
    return MotionPath(kind, tuple(functions), z)


def _joint(reader: Reader, body: Body, spec, field: str) -> Pin | None:
    """`joint: fixed_axle` or `joint: {pivot: {distance, side}}`: the body turns about a fixed point."""
    if spec is None:
        return None
    if not body.rotates:
        raise reader.fail(field, "a point mass has no joint")
    if spec == "fixed_axle":
        return Pin("axle", body.name, (0, 0))
    spec = reader.mapping(spec, field, optional=("pivot",))
    pivot = reader.mapping(spec.get("pivot"), f"{field}.pivot", keys=PIVOT)
    distance = reader.positive(pivot["distance"], f"{field}.pivot.distance", "m", "a pivot distance")
    side = pivot.get("side", "above")
    if side not in ("above", "below"):
        raise reader.fail(f"{field}.pivot.side", "above (the body hangs) or below (the body stands on it)")
    return Pin("pivot", body.name, (0, distance if side == "above" else -distance))
