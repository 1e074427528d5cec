"""What the general layout (derive.publishing.figure.parts) draws on: the scene's reference geometry on the
figure's scale, its layers and labels (_Scene), and each body's outline (_Body).
"""
from __future__ import annotations

import math

import sympy as sp

from derive.publishing.figure import label_places
from derive.publishing.figure.canvas import _add, _anchor, _f, _Figure, _pt, _unit
from derive.publishing.figure.vectors import _degrees, _dot, _norm, _perp, _sub
from derive.model.kinematics import Coordinates
from derive.model.scene import Body


BLOCK = 0.42  # cm: the side of a point mass drawn as a block
BALL = 0.1  # cm: the radius of a point mass drawn as a ball
ARROW = 0.85  # cm: a force's arrow
LAYERS = ("surfaces", "supports", "bodies", "elements", "cords", "blocks", "joints", "marks", "arrows", "labels")
DIRECTIONS = [_unit(a) for a in (90, 0, 180, 270, 45, 135, 315, 225)]  # candidate sides, in order of preference


class Undrawable(Exception):
    """A part or a geometry the figure cannot draw truthfully."""


class _Scene:
    """The reference geometry of one scene, on the figure's scale, and the drawing in layers."""

    def __init__(self, fig: _Figure):
        self.fig, self.scene = fig, fig.scene
        self.coords = Coordinates(self.scene)
        self.rest = {s: sp.Integer(v) for s, v in self.coords.at_rest_in_reference().items()}
        self.layers: dict[str, list[str]] = {name: [] for name in LAYERS}
        self.ink: list[tuple[float, float]] = []  # sample points of what is drawn, for the labels to avoid
        self.ground: set[tuple[float, float]] = set()  # those of them that are the ground's
        self.boxes: list[tuple[float, float, float, float]] = []  # the labels placed so far
        self.origin, self.scale = (0.0, 0.0), 1.0
        self.values = {symbol: sp.sympify(v, strict=True) for symbol, v in fig.values.items()}  # safe: numbers computed from the parameters; strict refuses text

    # numbers
    def value(self, expression) -> float:
        """A reference-configuration number: the parameters at the middle of their ranges, open sizes at 1."""
        expression = sp.sympify(expression, strict=True)  # safe: the scene's own expressions
        expression = expression.xreplace(self.rest).xreplace(self.values)
        expression = expression.xreplace({s: sp.Integer(1) for s in expression.free_symbols})
        try:
            number = complex(sp.N(expression))
        except (TypeError, ValueError, ZeroDivisionError) as error:
            raise Undrawable(f"{expression} has no value") from error
        if not (math.isfinite(number.real) and abs(number.imag) <= 1e-9 * (1 + abs(number.real))):
            raise Undrawable(f"{expression} is not a real number")
        return number.real

    def vector(self, matrix) -> tuple[float, float]:
        return (self.value(matrix[0]), self.value(matrix[1]))

    def world(self, body, offset=(0, 0)) -> tuple[float, float]:
        return self.vector(self.coords.position(body, offset))

    def at(self, world) -> tuple[float, float]:
        """A world point (m) on the figure (cm)."""
        return ((world[0] - self.origin[0]) * self.scale, (world[1] - self.origin[1]) * self.scale)

    # drawing
    def put(self, layer: str, line: str) -> None:
        self.layers[layer].append(line)

    def draw(self, layer: str, call, *args, **kwargs) -> None:
        """One of the canvas' drawing methods, its lines into a layer."""
        saved, self.fig.lines = self.fig.lines, self.layers[layer]
        try:
            call(*args, **kwargs)
        finally:
            self.fig.lines = saved

    def ink_line(self, a, b) -> None:
        steps = max(1, int(math.hypot(*_sub(b, a)) / 0.08))
        self.ink += [_add(a, _sub(b, a), k / steps) for k in range(steps + 1)]

    def ink_polyline(self, points) -> None:
        for a, b in zip(points, points[1:]):
            self.ink_line(a, b)

    def ink_circle(self, center, radius: float) -> None:
        steps = max(8, int(2 * math.pi * radius / 0.1))
        self.ink += [_add(center, _unit(360 * k / steps), radius) for k in range(steps)]

    def label(self, point, text: str | None, gap: float = 0.05, prefer=None) -> None:
        """A label beside `point` (at `gap` cm), on the side where it covers the least ink and no
        label; `prefer`: the sides to try, in order (a direction, or a direction and an extra gap)."""
        if not text:
            return
        width, height = label_places.text_width(text), label_places.HEIGHT
        best = None
        for rank, side in enumerate(prefer or DIRECTIONS):
            direction, extra = (side if isinstance(side[0], tuple) else (side, 0.0))
            direction = _norm(direction)
            where = _add(point, direction, gap + extra)
            box = label_places.box(where, _anchor(*direction), width, height)
            covered = label_places.covered(box, self.ink)
            overlap = sum(label_places.overlap(box, label_places.grown(other, 0.2)) for other in self.boxes)  # nor close enough to read as one
            cost = covered + 400 * overlap + 0.3 * rank
            if best is None or cost < best[0]:
                best = (cost, where, direction, box)
        _, where, direction, box = best
        self.boxes.append(box)
        self.draw("labels", self.fig.label, where, direction, text)

    def clearest(self, point, reach: float, own=(), candidates=None, beyond: float = 0.0) -> tuple[float, float]:
        """The side of `point` (a unit vector) with the least ink within `reach` cm (the nearer, the
        more it weighs), skipping the ink points `own` (the thing the side is chosen for) and those
        within `beyond` (a pulley's rim: its support is behind it); the ground's own ink (a
        surface, an anchor) draws it instead (a pulley's bracket goes to the table it is on)."""
        skip = set(own)
        near = [p for p in self.ink if p not in skip and max(1e-6, beyond) < math.hypot(*_sub(p, point)) <= reach]
        best = None
        for rank, direction in enumerate(candidates or DIRECTIONS):
            direction = _norm(direction)
            cost = 0.0
            for p in near:
                towards = _norm(_sub(p, point))
                angle = math.degrees(math.acos(max(-1.0, min(1.0, _dot(towards, direction)))))
                if angle < 50:
                    weight = (50 - angle) / 50 * reach / max(math.hypot(*_sub(p, point)), 0.35)
                    if p in self.ground:
                        cost -= 0.5 * weight
                    elif abs(_dot(_sub(p, point), _perp(direction))) < 0.22:  # in its way: it would cross it
                        cost += 10 * weight
                    else:
                        cost += weight
            cost += 0.01 * rank
            if best is None or cost < best[0]:
                best = (cost, direction)
        return best[1]

    def ground_ink(self, points) -> None:
        """Ink of the ground (a surface, an anchor): what a support may reach to."""
        start = len(self.ink)
        self.ink_polyline(points)
        self.ground.update(self.ink[start:])


class _Body:
    """How one body is drawn: its center and angle on the figure, its shape's sizes (cm)."""

    def __init__(self, view: _Scene, name: str, part=None):
        """The scene's body `name`, or `part` = (body, world position, angle) of a composite's part."""
        self.view, self.name = view, name
        self.body, self.world, self.angle = part or (view.scene.bodies[name], view.world(name),
                                                      view.value(view.scene.bodies[name].angle))
        body = self.body
        self.pieces = [_Body(view, f"{name}.{piece}", (Body(piece, shape, mass, sizes), view.world(name, offset),
                                                       self.angle + view.value(angle)))
                       for offset, (piece, (shape, mass, sizes, _, angle)) in
                       zip((body.composite.points()[n] for n in body.composite.parts), body.composite.parts.items())] \
            if body.composite is not None else []  # a composite is drawn part by part
        sizes = {k: view.value(v) for k, v in body.sizes.items()}
        self.radius_m = sizes.get("radius", sizes.get("outer_radius"))
        self.rod = sizes.get("length") if body.shape == "rod" else None
        self.sides = (sizes["side_a"], sizes["side_b"]) if "side_a" in sizes and "side_b" in sizes else None
        self.kind = "point" if body.shape == "point" else "rod" if self.rod else "rectangle" if self.sides else \
            "round" if self.radius_m else "oval"
        self.block = False  # a point mass: a block (set by the layout), else a ball
        self.ends = None  # a bar: the two points of its body (body frame) it runs between (set by the layout)
        self.tilt = 0.0  # degrees: a block on an incline is turned to lie on it
        self.seat = None  # a block on a plane that round bodies share: the plane's unit normal (it sits on it)
        self.polygon = None  # a solid (a point mass that carries a surface): its outline on the figure (cm)
        self.holds = None  # a solid: the surface it carries

    def corners_m(self) -> list[tuple[float, float]]:
        """World points of its outline that bound it (for the figure's extent)."""
        if self.pieces:
            return [p for piece in self.pieces for p in piece.corners_m()]
        c, a = self.world, self.angle
        along, across = (math.cos(a), math.sin(a)), (-math.sin(a), math.cos(a))
        if self.kind == "round":
            r = self.radius_m
            return [_add(c, d, r) for d in ((1, 0), (0, 1), (-1, 0), (0, -1))]
        if self.kind == "rod":
            return [_add(c, along, self.rod / 2), _add(c, along, -self.rod / 2)]
        if self.kind == "bar":
            return [self.view.world(self.name, end) for end in self.ends]
        if self.kind == "solid":
            return [_add(self.view.origin, p, 1 / self.view.scale) for p in self.polygon]
        if self.kind == "rectangle":
            a_, b_ = self.sides[0] / 2, self.sides[1] / 2
            return [_add(_add(c, along, sx * a_), across, sy * b_) for sx in (-1, 1) for sy in (-1, 1)]
        return [c]

    # on the figure
    @property
    def center(self):
        return self.view.at(self.world)

    def segment(self) -> tuple[tuple[float, float], tuple[float, float]]:
        """A rod's or a bar's two ends on the figure (cm)."""
        if self.kind == "bar":
            return tuple(self.view.at(p) for p in self.corners_m())
        along, half = (math.cos(self.angle), math.sin(self.angle)), self.rod / 2 * self.view.scale
        return _add(self.center, along, -half), _add(self.center, along, half)

    @property
    def axis(self) -> tuple[float, float]:
        """The unit vector along it: a bar's from its first end to its second, else its angle's."""
        if self.kind == "bar":
            p, q = self.segment()
            return _norm(_sub(q, p))
        return _unit(math.degrees(self.angle))

    @property
    def drawn_center(self):
        """Where the shape is drawn: a block resting on a plane sits on it, its point at its base."""
        if self.seat is not None:
            return _add(self.center, self.seat, BLOCK / 2)
        return self.center

    def outline(self) -> list[tuple[float, float]]:
        """Points of its drawn outline (cm)."""
        if self.pieces:
            return [p for piece in self.pieces for p in piece.outline()]
        c, s = self.drawn_center, self.view.scale
        along = (math.cos(self.angle), math.sin(self.angle))
        across = _perp(along)
        if self.kind == "point":
            if not self.block:
                return [_add(c, _unit(45 * k), BALL) for k in range(8)]
            tilt, h = self.tilt, BLOCK / 2
            return [_add(c, _unit(tilt + 45 + 90 * k), h * math.sqrt(2)) for k in range(4)] + \
                [_add(c, _unit(tilt + 90 * k), h) for k in range(4)]
        if self.kind == "round":
            return [_add(c, _unit(10 * k), self.radius_m * s) for k in range(36)]
        if self.kind in ("rod", "bar"):
            p, q = self.segment()
            steps = max(2, int(math.hypot(*_sub(q, p)) / 0.1))
            return [_add(p, _sub(q, p), k / steps) for k in range(steps + 1)]
        if self.kind in ("rectangle", "solid"):
            if self.kind == "solid":
                corners = list(self.polygon)
            else:
                a_, b_ = self.sides[0] / 2 * s, self.sides[1] / 2 * s
                corners = [_add(_add(c, along, sx * a_), across, sy * b_) for sx, sy in ((-1, -1), (1, -1), (1, 1), (-1, 1))]
            points = []
            for p, q in zip(corners, corners[1:] + corners[:1]):
                steps = max(1, int(math.hypot(*_sub(q, p)) / 0.1))
                points += [_add(p, _sub(q, p), k / steps) for k in range(steps)]
            return points
        a_, b_ = self.oval
        return [_add(_add(c, self.oval_axis, a_ * math.cos(math.radians(10 * k))), _perp(self.oval_axis),
                     b_ * math.sin(math.radians(10 * k))) for k in range(36)]

    @property
    def extent(self) -> float:
        """How far its drawn outline reaches from its center (cm)."""
        return max((math.hypot(*_sub(p, self.center)) for p in self.outline()), default=0.0)

    def reach(self, point, direction) -> float:
        """How far its outline reaches beyond `point` along `direction`, near that line (cm)."""
        far = 0.0
        for p in self.outline():
            offset = _sub(p, point)
            if abs(_dot(offset, _perp(direction))) < 0.3:
                far = max(far, _dot(offset, direction))
        return far

    def shape(self) -> None:
        """Draw it (onto the bodies layer, or the blocks layer for a point mass)."""
        view, fig, body = self.view, self.view.fig, self.body
        c, s = self.drawn_center, view.scale
        degrees = math.degrees(self.angle)
        if self.pieces:
            for piece in self.pieces:
                piece.shape()
        elif self.kind == "solid":  # drawn with the surface it carries (derive.publishing.figure.drawn_carriers)
            pass
        elif self.kind == "point":
            if self.block:
                tilt = self.tilt
                view.draw("blocks", fig.body, body, c, BLOCK / 2, tilt, block=True)
                if tilt:  # a block on an incline: turned to sit on it
                    view.layers["blocks"][-1] = (f"\\draw[body, rotate around={{{_f(tilt)}:{_pt(c)}}}] "
                                                 f"{_pt(_add(c, (-BLOCK / 2, -BLOCK / 2)))} rectangle "
                                                 f"{_pt(_add(c, (BLOCK / 2, BLOCK / 2)))};")
            else:
                view.put("blocks", f"\\shade[ball color=gray!60] {_pt(c)} circle ({_f(BALL)}); "
                                   f"\\draw {_pt(c)} circle ({_f(BALL)});")
        elif self.kind == "round":
            r = self.radius_m * s
            if body.shape == "cone":  # seen along its axis: a disk
                view.put("bodies", f"\\draw[body] {_pt(c)} circle ({_f(r)}); \\fill {_pt(c)} circle (0.04);")
            else:
                view.draw("bodies", fig.body, body, c, r, degrees)
        elif self.kind == "rod":
            view.draw("bodies", fig.body, body, c, self.rod / 2 * s, degrees)
        elif self.kind == "bar":  # its center of mass marked on it
            view.draw("bodies", fig.bar, *self.segment())
            view.put("bodies", f"\\draw[fill=white] {_pt(c)} circle (0.05); \\fill {_pt(c)} circle (0.025);")
        elif self.kind == "rectangle":
            view.draw("bodies", fig.body, body, c, self.sides[0] / 2 * s, degrees, aspect=self.sides[1] / self.sides[0])
        else:
            a_, b_ = self.oval
            view.put("bodies", f"\\draw[body, rotate around={{{_f(_degrees(self.oval_axis))}:{_pt(c)}}}] {_pt(c)} "
                               f"ellipse ({_f(a_)} and {_f(b_)}); \\fill {_pt(c)} circle (0.04);")
        view.ink += self.outline()

    def fit_oval(self, points) -> None:
        """A body of no particular shape: an oval about its center that holds the points it is
        attached at (cm), along the farthest of them."""
        c = self.center
        offsets = [_sub(p, c) for p in points if math.hypot(*_sub(p, c)) > 1e-6]
        if not offsets:
            self.oval_axis, self.oval = (1.0, 0.0), (0.45, 0.3)
            return
        axis = _norm(max(offsets, key=lambda o: math.hypot(*o)))
        along = max(abs(_dot(o, axis)) for o in offsets)
        across = max(abs(_dot(o, _perp(axis))) for o in offsets)
        self.oval_axis, self.oval = axis, (along + 0.22, max(0.28, across * 1.6 + 0.15))
