"""The 3D keys of a problem file's bodies, read and checked (derive.language.scene_file reads the rest):
`bearings:` (a spin about a fixed shaft), `pivot_point:` (a top on a fixed point), `rolls_on_edge:`
(a coin rolling on its rim) and `free_rotation:` (a body turning with no torque), each into its
dataclass of derive.model.scene; errors name the file's field.

>>> from derive.language.problem import load
>>> load("top_precession").scene.pivot_points["top"].spin
omega
"""
from __future__ import annotations

import sympy as sp

from derive.core.keys import Key, Keys
from derive.language.reader import Reader
from derive.model.scene import Body
from derive.model.solid_scene import Bearings, FreeRotation, PivotPoint, RollsOnEdge, own_axis

#: `bearings:` a body turning at a constant rate about a fixed shaft.
BEARINGS = Keys(rate=Key("expression", "the constant rate about the shaft (the z axis), in rad/s", required=True),
                tilt=Key("quantity", "the body's own axis from the shaft toward +x, 0 to pi", required=True),
                roll=Key("quantity", "the body's turn about its own axis first (default 0)"),
                apart=Key("expression", "the distance between the two bearings, in m"),
                through=Key("any", "the body's point the shaft passes through: a named point or [x, y, z] in the "
                                   "body's frame (default: its center of mass)"),
                incline=Key("quantity", "the shaft's angle above the horizontal under gravity, -pi/2 to pi/2"),
                thrust=Key("name", "the bearing that takes the weight along an inclined shaft", choices=("A", "B")),
                turned=Key("expression", "the rate at which the shaft itself is turned about the y axis, across it, "
                                         "in rad/s (a ship's turbine as the ship turns; default 0)"))
#: `rolls_on_edge:` a thin round body rolling on its rim on the horizontal plane.
ROLLS_ON_EDGE = Keys(tilt=Key("quantity", "its plane's lean from the vertical in the steady motion, 0 to pi/2"),
                     circle=Key("expression", "the radius of the circle its contact point traces, in m"))
#: `inertia:` of an axially symmetric custom body in 3D.
AXIAL_INERTIA = Keys(axial=Key("expression", "the moment about its symmetry axis, I3, in kg m^2", required=True),
                     transverse=Key("expression", "the moment across it, I1, in kg m^2"))
#: `inertia:` of a custom body in free rotation, by its principal moments.
PRINCIPAL_INERTIA = Keys(principal=Key("vector", "the principal moments [Ix, Iy, Iz] about the center of mass",
                                       required=True))
#: `pivot_point:` a body turning about a fixed point (a top, a gyroscope).
PIVOT_POINT = Keys(at=Key("any", "where the point is: a distance below the center of mass along the body's axis, "
                                 "tip, end, center or a composite's named point", required=True),
                   tilt=Key("quantity", "the axis's tilt from the upward vertical, 0 to pi (beyond pi/2 the body hangs "
                                        "below its point)"),
                   spin=Key("expression", "omega's component along the axis, in rad/s"))
#: `free_rotation:` a body turning with no torque.
FREE_ROTATION = Keys(spin=Key("expression", "omega's component along the body's own axis, in rad/s", required=True),
                     across=Key("expression", "omega's component across it, in rad/s"))

def _at_range_ends(reader: Reader, value: sp.Expr) -> list[sp.Expr]:
    """The value at every corner of its parameters' ranges in SI (a fixed parameter at its value)."""
    corners = [{}]
    for p in (p for p in reader.parameters.values() if p.symbol in value.free_symbols):
        corners = [{**c, p.symbol: end} for c in corners for end in p.si_ends]
    return [value.xreplace(c) for c in corners]


def bearings(reader: Reader, spec: dict, field: str, body: Body, weighed: bool) -> Bearings:
    """`bearings: {rate: omega, tilt: alpha, roll: psi, apart: d, through: [e, 0, 0]}`: the body
    turns at a constant rate about a fixed shaft (derive.mechanics.bearings) through its point
    `through` (a named point, or [x, y, z] from the center of mass in the body's own frame; the
    center of mass unless given), a uniform shape of the inertia module or a composite of them,
    held by nothing else, or a custom body with `inertia: {axial: I3, transverse: I1}` (its own axis
    z). Under gravity (`weighed`) the shaft is horizontal, or inclined by `incline` with a `thrust`
    bearing (A, up the shaft, or B) taking the weight along it. `turned: Omega` turns the shaft
    itself about the y axis at a constant rate (a ship's turbine spinning at `rate` in its bearings
    as the ship turns: the bearings' gyroscopic torque I3 omega Omega)."""
    field_here = f"{field}.bearings"
    if body.shape == "point" or body.density is not None:
        raise reader.fail(field_here, "a body in bearings is a uniform shape of derive inertia (not a point, no "
                                      "density), a composite of them, or a custom body with inertia: {axial: I3, "
                                      "transverse: I1}")
    other = next((k for k in ("joint", "on", "path", "velocity") if k in spec), None)
    if other:
        raise reader.fail(f"{field}.{other}", "a body in bearings is held by its shaft alone")
    raw = reader.mapping(spec["bearings"], field_here, keys=BEARINGS)
    tilt = reader.dimensioned(raw["tilt"], f"{field_here}.tilt", "rad", "a tilt")
    if not all(v.is_number and 0 <= v <= sp.pi for v in _at_range_ends(reader, tilt)):
        raise reader.fail(f"{field_here}.tilt", "the tilt from the shaft is between 0 and pi (turn the body by "
                                                "roll: for the rest)")
    through = _through(reader, raw.get("through"), f"{field_here}.through", body)
    incline, thrust = _incline(reader, raw, field_here, weighed)
    turned = sp.Integer(0)
    if "turned" in raw:
        turned = reader.positive(raw["turned"], f"{field_here}.turned", "rad/s", "a rate the shaft is turned at")
        if any(through) or incline != 0:
            raise reader.fail(f"{field_here}.turned", "a turned shaft passes through the center of mass and lies "
                                                      "level (through: and incline: are not modelled with it)")
    moments = axial_inertia(reader, spec, field) if body.shape == "custom" else None
    return Bearings(reader.positive(raw["rate"], f"{field_here}.rate", "rad/s", "a rotation rate"), tilt,
                    reader.dimensioned(raw.get("roll", 0), f"{field_here}.roll", "rad", "an angle"),
                    reader.positive(raw["apart"], f"{field_here}.apart", "m", "a distance")
                    if "apart" in raw else None, through, incline, thrust, turned, moments)


def _through(reader: Reader, raw, field: str, body: Body) -> tuple[sp.Expr, sp.Expr, sp.Expr]:
    """The point of a body in bearings its shaft passes through, from its center of mass in its own
    frame: a named point (`_named_points`) or [x, y, z] in metres; the center of mass if None."""
    named = _named_points(body)
    if raw is None:
        return (sp.Integer(0),) * 3
    if isinstance(raw, str) and raw in named:
        return named[raw]
    if not isinstance(raw, list) or len(raw) != 3:
        raise reader.fail(field, "a point of the body: [x, y, z] from its center of mass in its own frame"
                                 + (f", or {', '.join(named)}" if named else ""))
    return tuple(reader.dimensioned(c, f"{field}[{i}]", "m", "a distance") for i, c in enumerate(raw))


def _incline(reader: Reader, raw: dict, field: str, weighed: bool) -> tuple[sp.Expr, str | None]:
    """(the shaft's angle above the horizontal, the thrust bearing) of a body in bearings: both only
    under gravity, a thrust bearing exactly where the weight has a part along an inclined shaft
    (else the bearings' shares of it along the shaft are not determined)."""
    if not weighed:
        unused = next((k for k in ("incline", "thrust") if k in raw), None)
        if unused:
            raise reader.fail(f"{field}.{unused}", "only a shaft under gravity (- gravity: g) has an incline or a "
                                                   "thrust bearing")
        return sp.Integer(0), None
    incline = reader.dimensioned(raw.get("incline", 0), f"{field}.incline", "rad", "an angle")
    ends = _at_range_ends(reader, incline)
    if not all(v.is_number and -sp.pi / 2 <= v <= sp.pi / 2 for v in ends):
        raise reader.fail(f"{field}.incline", "the shaft's angle above the horizontal is between -pi/2 and pi/2")
    level = all(v == 0 for v in ends)
    if "thrust" in raw and (level or raw["thrust"] not in ("A", "B")):
        raise reader.fail(f"{field}.thrust", "A or B, the bearing that takes the weight along an inclined shaft"
                          if not level else "a level shaft carries no weight along it: leave thrust out")
    if not level and "thrust" not in raw:
        raise reader.fail(f"{field}.thrust", "the weight's part along an inclined shaft is shared between the "
                                             "bearings in no way statics decides: name the thrust bearing, A "
                                             "(at the shaft's +z end, uphill for a positive incline) or B")
    return incline, raw.get("thrust")


#: The thin axially symmetric shapes that roll on their rim, and the size that is the rim's radius.
RIMS = {"disk": "radius", "ring": "radius", "annulus": "outer_radius", "custom": "radius"}


def rolls_on_edge(reader: Reader, spec: dict, field: str, body: Body) -> RollsOnEdge:
    """`rolls_on_edge: {tilt: theta, circle: R}`: the body rolls without slipping on its rim on a
    horizontal plane (derive.mechanics.rolling_coin); a thin axially symmetric body (a disk, a ring,
    an annulus, or a custom body with a radius and inertia: {axial, transverse}). In the steady
    motion its plane leans by `tilt` from the vertical toward the axis of the circle of radius
    `circle` its contact point traces; both are left out where only upright rolling is asked."""
    here = f"{field}.rolls_on_edge"
    if body.shape not in RIMS or body.density is not None:
        raise reader.fail(here, "a body rolling on its edge is a thin axially symmetric body with its rim in the "
                                "plane of its center: a disk, ring or annulus of derive inertia (no density), or a "
                                "custom body with radius: a and inertia: {axial: I3, transverse: I1}")
    other = next((k for k in ("joint", "on", "contact", "friction", "path", "velocity", "bearings", "pivot_point",
                              "inertia_about") if k in spec), None)
    if other:
        raise reader.fail(f"{field}.{other}", "a body rolling on its edge rolls without slipping on the horizontal "
                                              "plane its key stands for, held by nothing else (a surface, slipping "
                                              "and friction coefficients are not modelled)")
    if RIMS[body.shape] not in body.sizes:
        raise reader.fail(f"{field}.radius", "a custom body rolling on its edge needs the radius of its rim")
    moments = axial_inertia(reader, spec, field) if body.shape == "custom" else None
    raw = reader.mapping(spec["rolls_on_edge"] or {}, here, keys=ROLLS_ON_EDGE)
    if ("tilt" in raw) != ("circle" in raw):
        raise reader.fail(here, "the steady motion needs both the lean and the circle: {tilt: theta, circle: R}")
    tilt = circle = None
    if "tilt" in raw:
        tilt = reader.dimensioned(raw["tilt"], f"{here}.tilt", "rad", "a tilt")
        if not all(v.is_number and 0 < v < sp.pi / 2 for v in _at_range_ends(reader, tilt)):
            raise reader.fail(f"{here}.tilt", "the lean from the vertical lies between 0 and pi/2 (upright rolling "
                                              "in a circle, and a body lying flat, are not modelled)")
        circle = reader.positive(raw["circle"], f"{here}.circle", "m", "the radius of the contact point's circle")
    return RollsOnEdge(body.sizes[RIMS[body.shape]], tilt, circle, moments)


def axial_inertia(reader: Reader, spec: dict, field: str) -> tuple[sp.Expr, sp.Expr]:
    """An axially symmetric custom body's `inertia: {axial: I3, transverse: I1}` (on a fixed point,
    rolling on its edge, or in free rotation), (transverse, axial) as given (`inertia_about: pivot`:
    the transverse one about the point; the axial one is the same there). Without `transverse` it is
    left open (a fast top's rate does not need it)."""
    if "inertia" not in spec:
        raise reader.fail(f"{field}.inertia", "an axially symmetric custom body (on a fixed point, rolling on its "
                                              "edge, in free rotation) needs inertia: {axial: I3, transverse: I1} "
                                              "(in free rotation, or {principal: [Ix, Iy, Iz]})")
    if not isinstance(spec["inertia"], dict):
        raise reader.fail(f"{field}.inertia", "a custom body in 3D gives its moments about its center of mass as "
                                              "inertia: {axial: I3, transverse: I1}, about its symmetry axis and "
                                              "across it (transverse may be left out where no answer needs it)")
    raw = reader.mapping(spec["inertia"], f"{field}.inertia", keys=AXIAL_INERTIA)
    axial = reader.positive(raw["axial"], f"{field}.inertia.axial", "kg*m^2", "a moment of inertia")
    if "transverse" not in raw:
        return reader.unspecified(f"I_transverse_{field.rpartition('.')[2]}", "kg*m^2"), axial
    transverse = reader.positive(raw["transverse"], f"{field}.inertia.transverse", "kg*m^2", "a moment of inertia")
    return transverse, axial


def _named_points(body: Body) -> dict[str, tuple[sp.Expr, sp.Expr, sp.Expr]]:
    """A 3D body's named points from its center of mass in its own frame: a cone's `tip`, a rod's
    `end` (on its negative side), a composite's points (derive.model.composite); the offsets are the
    engine's own expressions (a file only picks one)."""
    zero = sp.Integer(0)
    if body.composite is not None:
        return {n: (*p, zero) for n, p in body.composite.points().items() if n != "center"}
    return {"cone": {"tip": (zero, zero, 3 * body.sizes.get("height", zero) / 4)},
            "rod": {"end": (-body.sizes.get("length", zero) / 2, zero, zero)}}.get(body.shape, {})


def pivot_point(reader: Reader, spec: dict, field: str, body: Body) -> PivotPoint:
    """`pivot_point: {at: tip, tilt: theta, spin: omega}`: the body turns about a fixed point under
    gravity (derive.mechanics.fixed_point); a tilt or spin left out is open (the asks that need it
    are refused). `at`: a distance along the body's own axis (a rod's
    length, a composite's x, the symmetry axis z of other shapes) from the center of mass, on its
    negative side; or `tip` (a cone's apex), `end` (a rod's), a composite's named point; or
    `center`, the center of mass itself (no weight's torque: derive.mechanics.angular_impulse)."""
    here = f"{field}.pivot_point"
    if body.shape == "point" or body.density is not None:
        raise reader.fail(here, "a body on a fixed point is a uniform shape of derive inertia, a composite of them "
                                "or a custom body with inertia: {axial, transverse} (not a point, no density)")
    other = next((k for k in ("joint", "on", "path", "velocity", "bearings") if k in spec), None)
    if other:
        raise reader.fail(f"{field}.{other}", "a body on a fixed point is held by that point alone")
    raw = reader.mapping(spec["pivot_point"], here, keys=PIVOT_POINT)
    at = raw["at"]
    axis = own_axis(body.shape)
    named = _named_points(body)
    if at == "center":
        offset = (sp.Integer(0),) * 3
    elif isinstance(at, str) and at in named:
        offset = named[at]
    else:
        distance = reader.positive(at, f"{here}.at", "m", f"a distance from the center of mass along the {axis} "
                                   f"axis, or a point: {', '.join([*named, 'center'])}")
        offset = tuple(-distance if a == axis else sp.Integer(0) for a in "xyz")
    tilt = (reader.dimensioned(raw["tilt"], f"{here}.tilt", "rad", "a tilt") if "tilt" in raw
            else reader.unspecified(f"tilt_{body.name}", "rad"))
    ends = _at_range_ends(reader, tilt) if "tilt" in raw else []
    if not all(v.is_number and 0 < v < sp.pi for v in ends) or \
            len({bool(v > sp.pi / 2) for v in ends}) > 1 or offset == (0, 0, 0) and any(v > sp.pi / 2 for v in ends):
        raise reader.fail(f"{here}.tilt", "the axis from the point through the center of mass leans from the upward "
                                          "vertical by more than 0 and less than pi, on one side of pi/2 over the "
                                          "ranges (at most pi/2: it stands; more: it hangs below its point, a rod "
                                          "swinging in a cone at theta from the downward vertical has tilt: pi - "
                                          "theta; an upright one has no tilt)")
    about = spec.get("inertia_about", "center")
    if about not in ("center", "pivot") or about == "pivot" and body.shape != "custom":
        raise reader.fail(f"{field}.inertia_about", "center, or pivot for a custom body's transverse moment")
    moments = None
    if body.shape == "custom":
        transverse, axial = axial_inertia(reader, spec, field)
        distance_squared = sum(c**2 for c in offset)
        moments = (transverse - body.mass * distance_squared if about == "pivot" else transverse, axial)
    if raw.get("spin") == 0:
        raise reader.fail(f"{here}.spin", "a spin is positive: leave it out where no ask needs it (a body that swings "
                                          "round in a cone, rod.conical.rate, has no spin of its own to give)")
    spin = (reader.positive(raw["spin"], f"{here}.spin", "rad/s", "a spin") if "spin" in raw
            else reader.unspecified(f"spin_{body.name}", "rad/s"))  # a sleeping top's least spin needs none
    return PivotPoint(offset, tilt, spin, moments, hangs=any(v > sp.pi / 2 for v in ends))


def free_rotation(reader: Reader, spec: dict, field: str, body: Body) -> FreeRotation:
    """`free_rotation: {spin: omega3, across: omega_t}`: the body turns with no torque about its
    center of mass (derive.mechanics.free_rotation); `spin` is omega's component along the
    symmetry axis (or the rate of the steady rotation asked), `across` its component across the
    axis, left open where no ask needs it. A uniform shape of derive inertia, a composite of them
    whose own axes are principal, or a custom body with inertia: {axial, transverse} or
    {principal: [Ix, Iy, Iz]}."""
    here = f"{field}.free_rotation"
    if body.shape == "point" or body.density is not None:
        raise reader.fail(here, "a body in free rotation is a uniform shape of derive inertia, a composite of them or "
                                "a custom body with inertia: {axial, transverse} (not a point, no density)")
    other = next((k for k in ("joint", "on", "path", "velocity", "bearings", "pivot_point", "inertia_about")
                  if k in spec), None)
    if other:
        raise reader.fail(f"{field}.{other}", "a body in free rotation is held by nothing (its moments are about "
                                              "its center of mass)")
    raw = reader.mapping(spec["free_rotation"], here, keys=FREE_ROTATION)
    spin = reader.positive(raw["spin"], f"{here}.spin", "rad/s", "a spin")
    across = (reader.positive(raw["across"], f"{here}.across", "rad/s", "omega's component across the axis")
              if "across" in raw else reader.unspecified(f"across_{body.name}", "rad/s"))
    moments = free_inertia(reader, spec, field) if body.shape == "custom" else None
    return FreeRotation(spin, across, moments)


def free_inertia(reader: Reader, spec: dict, field: str) -> tuple[sp.Expr, sp.Expr, sp.Expr]:
    """A custom body's principal moments about its center of mass along its own x, y, z in free
    rotation: `inertia: {principal: [Ix, Iy, Iz]}`, or `{axial: I3, transverse: I1}` (I1, I1, I3)."""
    raw = spec.get("inertia")
    if isinstance(raw, dict) and "principal" in raw:
        raw = reader.mapping(raw, f"{field}.inertia", keys=PRINCIPAL_INERTIA)
        here = f"{field}.inertia.principal"
        if not isinstance(raw["principal"], list) or len(raw["principal"]) != 3:
            raise reader.fail(here, "three principal moments about the center of mass, [Ix, Iy, Iz]")
        return tuple(reader.positive(v, f"{here}[{i}]", "kg*m^2", "a moment of inertia")
                     for i, v in enumerate(raw["principal"]))
    transverse, axial = axial_inertia(reader, spec, field)
    return transverse, transverse, axial
