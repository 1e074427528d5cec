"""Where things are in a problem file: points of bodies and of the ground, by name.

A point is written as
- `BODY` (its center of mass) or `BODY.POINT`, a point the body's shape names (`BODY_POINTS`:
  a rod's `end` and `start`, a round body's `top`, `bottom`, `left`, `right` on its rim, a plate's
  or a box's sides), in the body's own frame (before the body is turned by its `angle`);
- `{BODY: [x, y]}`: any point in the body's frame, from its center of mass (a composite's from
  the origin its parts are placed from: `derive.model.composite`);
- `[x, y]`, or the name of a point declared under `scene.points`: a fixed point of the ground.

`Places` resolves these for the scene reader, and evaluates reference geometry at the middle of the
parameter ranges (to decide a cord's turning sense, to check that things touch).

>>> import sympy as sp
>>> L = sp.Symbol("L", positive=True)
>>> body_points("rod", {"length": L})["end"]
(L/2, 0)
"""
from __future__ import annotations

import sympy as sp

from derive.core import units
from derive.core.expr import TIME
from derive.core.spelling import did_you_mean

ZERO = sp.Integer(0)


def body_points(shape: str, sizes: dict[str, sp.Expr]) -> dict[str, tuple[sp.Expr, sp.Expr]]:
    """The named points of a shape, in its frame from its center of mass."""
    result = {"center": (ZERO, ZERO)}
    if shape == "rod":
        half = sizes["length"] / 2
        result.update(end=(half, ZERO), start=(-half, ZERO))
    radius = sizes.get("radius", sizes.get("outer_radius"))
    if radius is not None:
        result.update(top=(ZERO, radius), bottom=(ZERO, -radius), left=(-radius, ZERO), right=(radius, ZERO))
    if "side_a" in sizes and "side_b" in sizes:
        a, b = sizes["side_a"] / 2, sizes["side_b"] / 2
        result.update(top=(ZERO, b), bottom=(ZERO, -b), left=(-a, ZERO), right=(a, ZERO))
    return result


def extent(shape: str, sizes: dict[str, sp.Expr]) -> sp.Expr | None:
    """How far from its center of mass a point of the body can lie (None: the file does not say)."""
    if shape == "rod":
        return sizes["length"] / 2
    if "radius" in sizes or "outer_radius" in sizes:
        radius = sizes.get("radius", sizes.get("outer_radius"))
        return sp.sqrt(radius**2 + sizes["height"] ** 2 / 4) if "height" in sizes else radius
    if "side_a" in sizes and "side_b" in sizes:
        return sp.sqrt(sizes["side_a"] ** 2 + sizes["side_b"] ** 2) / 2
    return None


def sample(reader, expr: sp.Expr) -> float:
    """The value at the middle of the parameter ranges (SI), open sizes at 1: for decisions of sign
    and geometry that the problem's parameters do not change."""
    values = {}
    for p in reader.parameters.values():
        middle = p.value if p.value is not None else (p.range[0] + p.range[1]) / 2
        values[p.symbol] = middle * units.si_factor(units.parse_unit(p.unit))
    expr = expr.xreplace(values) if isinstance(expr, sp.Basic) else sp.Integer(expr)
    return float(expr.xreplace({s: 1 for s in expr.free_symbols}))


def turned(angle: sp.Expr, offset) -> sp.Matrix:
    """An offset (x, y) turned counter-clockwise by an angle."""
    return sp.Matrix([[sp.cos(angle), -sp.sin(angle)], [sp.sin(angle), sp.cos(angle)]]) * sp.Matrix(offset)


def points_of(body) -> dict[str, tuple[sp.Expr, sp.Expr]]:
    """A body's named points from its center of mass (a composite's include its parts' points)."""
    if body.composite is not None:
        return body.composite.points()
    middle = getattr(body, "shape_center", (ZERO, ZERO))  # a density may move the center of mass off the middle
    middle = getattr(body, "round_center", None) or middle  # a hemisphere's rim points are its round face's
    return {name: (px, py) if name == "center" else (px + middle[0], py + middle[1])  # center: the center of mass
            for name, (px, py) in body_points(body.shape, body.sizes).items()}


class Places:
    """Resolves point references of one problem file (see the module)."""

    def __init__(self, reader, bodies: dict, ground: dict[str, tuple[sp.Expr, sp.Expr]], surfaces: dict | None = None):
        self.reader, self.bodies, self.ground = reader, bodies, ground
        self.surfaces = surfaces or {}

    def sample(self, expr: sp.Expr) -> float:
        """`sample` for this problem file."""
        return sample(self.reader, expr)

    def coincide(self, first: sp.Matrix, second: sp.Matrix) -> bool:
        """Whether two reference positions are the same point (at the middle of the ranges)."""
        scale = 1 + max(abs(self.sample(v)) for v in (*first, *second))
        return all(abs(self.sample(a - b)) <= 1e-9 * scale for a, b in zip(first, second))

    def with_time(self) -> dict[str, sp.Symbol]:
        """The symbols an expression may use, with the time t (a force that varies in time)."""
        if "t" in self.reader.symbols:
            return dict(self.reader.symbols)
        self.reader.symbol_units.setdefault(TIME, "s")
        return {**self.reader.symbols, "t": TIME}

    def point(self, value, field: str, ground: bool = True) -> tuple[str | None, tuple[sp.Expr, sp.Expr]]:
        """(body or None for the ground, the point in the body's frame or on the ground)."""
        if isinstance(value, list):
            if not ground:
                raise self.reader.fail(field, "expected a point of a body (BODY or BODY.POINT)")
            return None, self.reader.vector(value, field)
        if isinstance(value, dict):
            spec = self.reader.mapping(value, field, free=True)
            if len(spec) != 1:
                raise self.reader.fail(field, "expected {BODY: [x, y]}")
            (body, offset), = spec.items()
            self._body(body, field)
            return body, self.reader.vector(offset, f"{field}.{body}")
        if not isinstance(value, str):
            raise self.reader.fail(field, "expected a point: BODY, BODY.POINT, {BODY: [x, y]} or [x, y]")
        if value in self.ground and ground:
            return None, self.ground[value]
        body, _, name = value.partition(".")
        self._body(body, field)
        rigid = self.bodies[body]
        named = points_of(rigid)
        if (name or "center") not in named:
            raise self.reader.fail(field, f"a {rigid.shape} has no point {name!r} (points: {', '.join(named)}; or "
                                          f"{{{body}: [x, y]}} in its frame)" + did_you_mean(name, named))
        return body, named[name or "center"]

    def two_points(self, value, field: str) -> list[tuple[str | None, tuple[sp.Expr, sp.Expr]]]:
        """`[POINT, POINT]`, at least one on a body, apart in the reference configuration (the
        ends of a spring or a dashpot)."""
        if not isinstance(value, list) or len(value) != 2:
            raise self.reader.fail(field, "expected [POINT, POINT]")
        ends = [self.point(v, f"{field}[{i}]") for i, v in enumerate(value)]
        for i, (body, offset) in enumerate(ends):
            if body is not None:
                self.on_body(body, offset, f"{field}[{i}]")
        if ends[0][0] is None and ends[1][0] is None:
            raise self.reader.fail(field, "at least one end is on a body")
        if self.coincide(self.world(*ends[0]), self.world(*ends[1])):
            raise self.reader.fail(field, "the two ends are at one point in the reference configuration: the line "
                                          "between them has no direction")
        return ends

    def _body(self, name, field: str) -> None:
        if name not in self.bodies:
            known = ", ".join([*self.bodies, *self.ground]) or "none"
            raise self.reader.fail(field, f"no body or point {name!r} (known: {known})"
                                   + did_you_mean(name, [*self.bodies, *self.ground]))

    def world(self, body: str | None, offset) -> sp.Matrix:
        """The point's position in the reference configuration."""
        if body is None:
            return sp.Matrix(offset)
        rigid = self.bodies[body]
        return sp.Matrix(rigid.at) + turned(rigid.angle, offset)

    def on_body(self, body: str, offset, field: str) -> None:
        """Refuse a point that lies outside its body (a pin's point, a winding's radius)."""
        rigid = self.bodies[body]
        reach = rigid.composite.extent() if rigid.composite is not None else extent(rigid.shape, rigid.sizes)
        middle = getattr(rigid, "shape_center", (ZERO, ZERO))
        if reach is not None and middle != (ZERO, ZERO):  # from the center of mass, off the middle
            reach = reach + sp.sqrt(middle[0] ** 2 + middle[1] ** 2)
        if rigid.shape == "point":
            reach = ZERO
        if reach is None:
            return
        distance = sp.sqrt(sp.Matrix(offset).dot(sp.Matrix(offset)))
        if self.sample(distance) > self.sample(reach) * (1 + 1e-12):
            raise self.reader.fail(field, f"the point lies {sp.sstr(distance)} from the {body}'s center, outside "
                                          f"the {rigid.shape} (at most {sp.sstr(reach)})")
