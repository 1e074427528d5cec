"""A rigid body made of parts (`shape: composite`): a wheel with a rim, a hub and spokes, a T of
two rods, a rod with a ball at its end.

Each part is a uniform shape of `derive inertia` placed in the composite's own frame (`at`, from
the frame's origin, and `angle`). The inertia module composes them
(`derive.model.inertia.composite_tensor`): the total mass, the center of mass, and the moment of inertia
about it (each part's tensor moved there by the parallel-axis theorem). The engine then moves the
composite as one body, its frame at that center of mass; the problem file keeps naming points in
the frame it placed the parts in:

- `BODY.origin` (the frame's origin; the body's `at:` places it), `BODY.center` (the center of
  mass, as for any body), `BODY.PART` (a part's center), `BODY.PART.POINT` (a point the part's
  shape names: `tee.stem.end`);
- `{BODY: [x, y]}`, from the frame's origin.

A composite rolls on its largest round part whose center is the composite's center of mass, or,
without one, on its largest round part off it (a hoop loaded at its rim rocks on the hoop).

>>> import sympy as sp
>>> m, L = sp.symbols("m L", positive=True)
>>> tee = build({"bar": ("rod", m, {"length": L}, (0, 0), 0),
...              "stem": ("rod", m, {"length": L}, (0, -L / 2), sp.pi / 2)})
>>> tee.center, sp.factor(tee.inertia)
((0, -L/4), 7*L**2*m/24)
"""
from __future__ import annotations

from dataclasses import dataclass

import sympy as sp

from derive.core.tidying import tidy
from derive.model import inertia
from derive.parts.places import body_points, extent, sample, turned
from derive.core.spelling import did_you_mean

ROUND = ("ring", "disk", "annulus", "cylinder", "cylindrical_shell", "sphere", "spherical_shell",
         "thick_spherical_shell", "cone")


@dataclass(frozen=True)
class CompositeParts:
    """The parts of a composite in its own frame, and what the inertia module makes of them.

    `parts`: name -> (shape, mass, sizes, center (x, y), angle); `center`: the center of mass in
    that frame; `inertia`: the moment about the center of mass, normal to the plane.
    """

    parts: dict
    mass: sp.Expr
    center: tuple[sp.Expr, sp.Expr]
    inertia: sp.Expr

    def points(self) -> dict[str, tuple[sp.Expr, sp.Expr]]:
        """The composite's named points, in its body frame from its center of mass."""
        cx, cy = self.center
        result = {"center": (sp.Integer(0), sp.Integer(0)), "origin": (-cx, -cy)}
        for name, (shape, _, sizes, (x, y), angle) in self.parts.items():
            for point, offset in body_points(shape, sizes).items():
                px, py = sp.Matrix([x - cx, y - cy]) + turned(angle, offset)
                result[name if point == "center" else f"{name}.{point}"] = (px, py)
        return result

    def moment_about(self, point: tuple[sp.Expr, sp.Expr]) -> sp.Expr:
        """The moment of inertia about an axis through `point` (body frame, from the center of mass) as a
        solution manual writes it, part by part, unevaluated: each part's own about its center plus its mass
        times the square of its center's distance from the axis (parallel-axis theorem).

        >>> m, M, L, r = sp.symbols("m M L r", positive=True)
        >>> clock = build({"rod": ("rod", m, {"length": L}, (0, -L / 2), -sp.pi / 2),
        ...                "bob": ("disk", M, {"radius": r}, (0, -L - r), 0)})
        >>> cx, cy = clock.center
        >>> about = clock.moment_about((-cx, -cy))  # the rod's upper end: the frame's origin
        >>> len(about.args), sp.expand(about.doit() - (m*L**2/3 + M*r**2/2 + M*(L + r)**2))
        (4, 0)
        """
        cx, cy = self.center
        terms = []
        for shape, mass, sizes, (x, y), _ in self.parts.values():
            own = tidy(inertia.central_moment(shape, mass, sizes))
            dx, dy = tidy(x - cx - point[0]), tidy(y - cy - point[1])
            apart = tidy(sp.sqrt(dx**2 + dy**2))
            terms += [own] if own != 0 else []
            terms += [sp.Mul(mass, sp.Pow(apart, 2, evaluate=False), evaluate=False)] if apart != 0 else []
        return sp.Add(*terms, evaluate=False)

    def extent(self) -> sp.Expr | None:
        """How far from the center of mass a point of the composite can lie (None: a part does not say)."""
        cx, cy = self.center
        reaches = []
        for shape, _, sizes, (x, y), _ in self.parts.values():
            own = sp.Integer(0) if shape == "point" else extent(shape, sizes)
            if own is None:
                return None
            reaches.append(sp.sqrt((x - cx) ** 2 + (y - cy) ** 2) + own)
        return sp.Max(*reaches)

    def radius(self, reader) -> tuple[sp.Expr | None, tuple[sp.Expr, sp.Expr] | None]:
        """(the radius it rolls on, that part's center from the center of mass): its largest round part
        centered at its center of mass (center None), else its largest round part ((None, None): none)."""
        cx, cy = self.center
        rounds = [(sizes.get("radius", sizes.get("outer_radius")), (sp.simplify(x - cx), sp.simplify(y - cy)))
                  for shape, _, sizes, (x, y), _ in self.parts.values() if shape in ROUND]
        centered = [radius for radius, off in rounds if off == (0, 0)]
        if centered:
            return max(centered, key=lambda r: sample(reader, r)), None
        return max(rounds, key=lambda pair: sample(reader, pair[0]), default=(None, None))


def build(parts: dict) -> CompositeParts:
    """Compose parts given as name -> (shape, mass, sizes, (x, y), angle) in the composite's frame."""
    turned = [inertia.Part(shape, mass, sizes, (x, y, 0), sp.Matrix([[sp.cos(a), -sp.sin(a), 0],
                                                                      [sp.sin(a), sp.cos(a), 0], [0, 0, 1]]))
              for shape, mass, sizes, (x, y), a in parts.values()]
    made = inertia.composite_tensor(turned)
    return CompositeParts(dict(parts), made.mass, (made.center[0], made.center[1]), made.tensor[2, 2])


def moment_by_sum(made: CompositeParts) -> sp.Expr:
    """The same moment by the scalar route: each part's planar moment about its own center plus
    m d^2 (the check of `build`'s tensor route)."""
    cx, cy = made.center
    return sum((inertia.central_moment(shape, mass, sizes) + mass * ((x - cx) ** 2 + (y - cy) ** 2)
                for shape, mass, sizes, (x, y), _ in made.parts.values()), sp.Integer(0))


def read(reader, raw, field: str) -> CompositeParts:
    """`parts: {NAME: {shape, mass, SIZES..., at: [x, y], angle}}`, at least two."""
    specs = reader.mapping(raw, field, free=True)
    if len(specs) < 2:
        raise reader.fail(field, "a composite has at least two parts (one part is a body of that shape)")
    parts = {}
    for name, spec in specs.items():
        where = f"{field}.{reader.name(name, field, 'a part')}"
        shape = reader.mapping(spec, where, required=("shape",), free=True)["shape"]
        if shape not in inertia.SHAPES:
            raise reader.fail(f"{where}.shape", f"unknown shape {shape!r} (a part is one of: {', '.join(inertia.SHAPES)})"
                                                + did_you_mean(shape, inertia.SHAPES))
        sizes_needed = tuple(inertia.SHAPES[shape].sizes)
        spec = reader.mapping(spec, where, required=("shape", "mass", *sizes_needed), optional=("at", "angle"))
        mass = reader.positive(spec["mass"], f"{where}.mass", "kg", "a mass")
        sizes = {s: reader.positive(spec[s], f"{where}.{s}", "m", f"a {s}") for s in sizes_needed}
        position = reader.vector(spec.get("at", [0, 0]), f"{where}.at", where=" in the composite's frame")
        angle = reader.dimensioned(spec.get("angle", 0), f"{where}.angle", "rad", "an angle")
        if angle != 0 and shape == "point":
            raise reader.fail(f"{where}.angle", "a point mass has no orientation")
        parts[name] = (shape, mass, sizes, position, angle)
    return build(parts)
