r"""Any scene of parts, drawn in its reference configuration to scale, from the parts' own geometry.

Every position comes from the scene: a body's center and angle (`at`, `angle`), a point of a body
from `Coordinates.position`, a cord's straight runs from `derive.parts.cord.run` (the exact tangent
points on pulleys, reels and pegs), a contact point from its surface's normal. Evaluated at the
middle of the parameter ranges, open sizes at 1 (as the parts decide a cord's turning sense), and
scaled uniformly so that the scene is about 4 cm wide.

What each part looks like:

- surfaces: a plane a hatched floor or wall (an incline a shaded wedge with its angle), stopping
  short of things below its level (a pulley at a table's edge) and meeting another such plane at
  their corner (a floor and a wall); a circle a thick track hatched on the solid side (outside a
  bowl or a loop, inside a dome), with its radius;
- bodies by shape (a point mass a block when it rests on a plane or ends a cord, a spring or a
  dashpot, else a small ball; a custom body an oval about the points where parts attach, or a bar
  between the two points it touches surfaces at when its center of mass and those points lie on
  that segment: a ladder), labelled with their mass (or name). A point mass touches its surface
  at its point, where its cords and springs attach: a surface only point masses rest on is drawn
  half a block (a ball's radius) below their points, so that each block, centered on its point,
  sits on it and its cord leaves its side, as in a textbook. A body touching a surface at one of
  its points is drawn on its side of it (an outline that would cross it is Undrawable); a rod or
  a bar there has its angle to a plane marked when the scene gives that angle as a parameter (a
  ladder's theta above the floor);
- pin to the ground: a hatched support on the clearest side, toward the ground's own lines when
  near (a pulley's bracket to its table; a bracket past the rim for an axle), with the pin a small
  circle (an axle a circled dot); a pin between bodies a small circle; a slider a hatched rail
  through its point, with a collar (a block for a guide that keeps the body from turning); a weld
  to the ground a hatched wall against the body (a side first: a shelf) with the filled triangle
  of a weld, between bodies that triangle between their centers (on a thick bar when apart);
- a cord: its runs, the arcs where it wraps a pulley or leaves a reel, a hub drawn where its
  radius is not the body's, a smooth peg a small circle on a support, an end tied to the ground a
  hatched ceiling or wall across the run, a pulled end an arrow labelled with the force;
- spring a zigzag, dashpot a cylinder and piston, from one point exactly to the other (a hatched
  anchor at a ground end), labelled k, b; a torsional spring a coil at the body's pin (or
  center), a rotational damper a hatched sector there;
- force an arrow at its point in its direction (ending at the point when it pushes on the body's
  edge), torque a curved arrow (counter-clockwise, or clockwise for a negative one) around a small
  body or about the center of a large one, gravity the weight m g of a single body or a g arrow
  beside the scene; labels are placed where they cover the least of the drawing;
- contact regime, written at the point of contact as textbooks do: "no slip" (rolling without
  slipping, or a point held by static friction; with mu_s when given), "smooth" (sliding without
  friction), "rough, mu_s, mu_k" (the coefficients the file gives: the engine decides the regime).

A part this module does not know, or geometry that does not evaluate to real numbers, raises
`Undrawable`: `tikz` then omits the figure rather than draw something wrong.
"""
from __future__ import annotations

import math
import re

import sympy as sp

from derive.figure.canvas import _add, _anchor, _f, _Figure, _pt, _unit, regime_text
from derive.mechanics.kinematics import Coordinates
from derive.parts.contact import Contact
from derive.parts.cord import Cord, run
from derive.parts.damper import Damper
from derive.parts.force import Force
from derive.parts.pin import Pin
from derive.parts.slider import Slider
from derive.parts.spring import Spring
from derive.parts.surfaces import Circle, Plane
from derive.parts.torque import Torque
from derive.parts.torsional_spring import TorsionalSpring
from derive.parts.weld import Weld
from derive.render import tex_escape
from derive.scene import Body

#: The parts this layout draws (gravity is the scene's own field).
KNOWN = (Contact, Cord, Damper, Force, Pin, Slider, Spring, Torque, TorsionalSpring, Weld)
CORE_WIDTH, CORE_HEIGHT = 4.2, 3.6  # cm: the scene's geometry, before anchors, arrows and labels
BLOCK = 0.42  # cm: the side of a point mass drawn as a block
BALL = 0.1  # cm: the radius of a point mass drawn as a ball
ARROW = 0.85  # cm: a force's arrow
LAYERS = ("surfaces", "supports", "bodies", "elements", "cords", "blocks", "joints", "marks", "arrows", "labels")
DIRECTIONS = [_unit(a) for a in (90, 0, 180, 270, 45, 135, 315, 225)]  # candidate sides, in order of preference


class Undrawable(Exception):
    """A part or a geometry the figure cannot draw truthfully."""


def _sub(p, q):
    return (p[0] - q[0], p[1] - q[1])


def _dot(p, q):
    return p[0] * q[0] + p[1] * q[1]


def _norm(p):
    length = math.hypot(*p)
    return (p[0] / length, p[1] / length) if length > 1e-12 else (0.0, 0.0)


def _perp(p):
    return (-p[1], p[0])


def _degrees(p) -> float:
    return math.degrees(math.atan2(p[1], p[0]))


def _text_width(text: str) -> float:
    """A rough width (cm) of a label at \\small: letters and symbols, subscripts narrower."""
    small = "\\scriptsize" in text
    text = re.sub(r"\\(scriptsize|vec|mathrm|,|!|;)", "", text)
    text = re.sub(r"\\[A-Za-z]+", "x", text)  # a Greek letter or a symbol: one character
    sub = sum(len(m) for m in re.findall(r"_\{([^}]*)\}|_(.)", text) for m in m)
    body = len(re.sub(r"[${}_^\\ ]", "", text)) - sub
    return (0.19 * body + 0.13 * sub) * (0.75 if small else 1.0) + 0.12


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
        width, height = _text_width(text), 0.34
        best = None
        for rank, side in enumerate(prefer or DIRECTIONS):
            direction, extra = (side if isinstance(side[0], tuple) else (side, 0.0))
            direction = _norm(direction)
            where = _add(point, direction, gap + extra)
            box = _box(where, _anchor(*direction), width, height)
            covered = sum(1 for p in self.ink if box[0] <= p[0] <= box[2] and box[1] <= p[1] <= box[3])
            overlap = sum(_overlap(box, _grown(other, 0.2)) for other in self.boxes)  # nor close enough to read as one
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


def _box(point, anchor: str, width: float, height: float):
    """The box (x0, y0, x1, y1) of a node of that size anchored at `point`."""
    x, y = point
    dx = {"west": 0, "east": -width, "north": -width / 2, "south": -width / 2, "center": -width / 2}
    dy = {"south": 0, "north": -height, "west": -height / 2, "east": -height / 2, "center": -height / 2}
    horizontal = next((k for k in ("west", "east") if k in anchor), anchor if anchor in ("north", "south") else "center")
    vertical = next((k for k in ("south", "north") if k in anchor), anchor if anchor in ("west", "east") else "center")
    x0, y0 = x + dx[horizontal], y + dy[vertical]
    return (x0, y0, x0 + width, y0 + height)


def _grown(box, margin: float):
    return (box[0] - margin, box[1] - margin, box[2] + margin, box[3] + margin)


def _overlap(a, b) -> float:
    return max(0.0, min(a[2], b[2]) - max(a[0], b[0])) * max(0.0, min(a[3], b[3]) - max(a[1], b[1]))


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
        if self.kind == "rectangle":
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


class _Layout:
    """The general layout: gathers the geometry, scales it, draws each part."""

    def __init__(self, fig: _Figure):
        self.fig, self.scene = fig, fig.scene
        self.view = view = _Scene(fig)
        scene = self.scene
        parts = list(scene.constraints) + list(scene.loads)
        for part in parts:
            if not isinstance(part, KNOWN):
                raise Undrawable(f"the figure does not draw a {type(part).__name__}")
            if isinstance(part, Contact) and part.carrier is not None:  # it would look fixed to the ground
                raise Undrawable(f"the figure does not draw a surface carried by a body ({part.surface})")
        self.parts = parts
        self.bodies = {name: _Body(view, name) for name in scene.bodies}
        self.cords = [p for p in parts if isinstance(p, Cord)]
        self.runs = {cord.name: [run(a, b, view.coords) for a, b in zip(cord.path, cord.path[1:])]
                     for cord in self.cords}
        self.contacts = [p for p in parts if isinstance(p, Contact)]
        self.pegs: list = []  # ground points and drums the cord passes around: (center, radius, incoming, outgoing)
        self.pulls: dict = {}  # cord name: (the pull arrow's tip, its label)
        self.pending: list = []  # labels, placed once everything is drawn
        self.lift: dict[str, float] = {}  # surface: how far below the points resting on it it is drawn (cm)
        self._mark_blocks()
        self._mark_bars()
        self._scale()

    def of(self, kind):
        return [p for p in self.parts if isinstance(p, kind)]

    def _mark_blocks(self) -> None:
        """A point mass is a block when it rests on a plane or ends a cord, a spring or a dashpot.

        A point mass touches its surface at its point, where its cords and springs attach: a
        surface that only point masses rest on is drawn half a block (a ball's radius) lower, so that
        each block, centered on its point, rests on it as in a textbook; on a surface a round body
        shares, a block sits on the surface with its point at its base."""
        for name, surface in self.scene.surfaces.items():
            resting = [self.bodies[c.body] for c in self.contacts if c.surface == name]
            if resting and all(d.kind == "point" for d in resting):
                self.lift[name] = BLOCK / 2 if isinstance(surface, Plane) else BALL
        ends = set()
        for cord in self.cords:
            ends |= {a.body for a in (cord.path[0], cord.path[-1]) if a.kind == "point"}
        for part in self.of(Spring) + self.of(Damper):
            ends |= set(part.ends)
        for name, drawn in self.bodies.items():
            if drawn.kind != "point":
                continue
            contact = self.scene.contact_of(name)
            if contact is not None and isinstance(self.scene.surfaces[contact.surface], Plane):
                normal = _norm(self.view.vector(self.scene.surfaces[contact.surface].normal))
                drawn.block, drawn.tilt = True, math.degrees(math.atan2(-normal[0], normal[1]))
                if not self.lift.get(contact.surface):
                    drawn.seat = normal
            elif name in ends:
                drawn.block = True

    def _mark_bars(self) -> None:
        """A custom body of no given size that touches surfaces at two of its points (or more, in a
        line) is a bar between the two farthest apart, when its center of mass and every point
        where a part attaches lie on that segment (a ladder given by its foot and its top)."""
        view = self.view
        for name, drawn in self.bodies.items():
            if drawn.kind != "oval" or drawn.pieces:
                continue
            touching = [c.point for c in self.contacts if c.body == name and c.point is not None]
            if len(touching) < 2:
                continue
            ends = max(((p, q) for p in touching for q in touching),
                       key=lambda pq: math.hypot(*_sub(view.world(name, pq[0]), view.world(name, pq[1]))))
            p, q = (view.world(name, end) for end in ends)
            if all(_on_segment(point, p, q) for point in [drawn.world] + self._attached(name)):
                drawn.kind, drawn.ends = "bar", ends

    # the extent and the scale
    def _world_points(self) -> list[tuple[float, float]]:
        view, points = self.view, []
        for drawn in self.bodies.values():
            points += drawn.corners_m()
        for cord in self.cords:
            for a in cord.path:
                if a.kind != "pulled":
                    center, r = view.vector(a.center(view.coords)), view.value(a.radius)
                    points += [_add(center, d, r) for d in ((1, 0), (0, 1), (-1, 0), (0, -1))]
            for r in self.runs[cord.name]:
                points += [view.vector(r.start_point), view.vector(r.end_point)]
        for part in self.of(Spring) + self.of(Damper):
            if not getattr(part, "rotational", False):
                points += [view.world(b, o) for b, o in zip(part.ends, part.offsets)]
        for part in self.of(Pin) + self.of(Slider) + self.of(Force):
            points.append(view.world(part.body, part.offset))
        for contact in self.contacts:
            surface = self.scene.surfaces[contact.surface]
            if contact.point is not None:
                points.append(view.world(contact.body, contact.point))
            if isinstance(surface, Circle):
                middle, r = view.vector(surface.middle), view.value(surface.radius)
                points += [_add(middle, d, r) for d in ((1, 0), (0, 1), (-1, 0), (0, -1))]
        return points

    def _scale(self) -> None:
        view = self.view
        points = self._world_points()
        xs, ys = [p[0] for p in points], [p[1] for p in points]
        width, height = max(xs) - min(xs), max(ys) - min(ys)
        scales = [CORE_WIDTH / width if width > 1e-9 else math.inf, CORE_HEIGHT / height if height > 1e-9 else math.inf]
        radii = [d.radius_m for d in self.bodies.values() if d.kind == "round"]
        if radii:
            scales.append(1.4 / max(radii))
        scale = min(scales)
        view.scale = scale if math.isfinite(scale) else 1.0
        view.origin = (min(xs), min(ys))
        self.size = (width * view.scale, height * view.scale)  # the scene's extent on the figure, from (0, 0)

    # drawing
    def draw(self) -> None:
        view = self.view
        for drawn in self.bodies.values():
            if drawn.kind == "oval" and not drawn.pieces:
                drawn.fit_oval([view.at(p) for p in self._attached(drawn.name)])
            drawn.shape()
        self._off_the_surfaces()
        for cord in self.cords:
            self._cord(cord)
        for spring in self.of(Spring):
            self._spring(spring)
        for damper in self.of(Damper):
            self._damper(damper)
        self._surfaces()
        # what takes the clearest side of its point, once the ink it avoids is known
        for peg in self.pegs:
            self._peg(*peg)
        for pin in self.of(Pin):
            self._pin(pin)
        for slider in self.of(Slider):
            self._slider(slider)
        for weld in self.of(Weld):
            self._weld(weld)
        for coil in self.of(TorsionalSpring):
            self._coil(coil)
        for damper in (d for d in self.of(Damper) if d.rotational):
            self._rotational_damper(damper)
        for force in self.of(Force):
            self._force(force)
        for torque in self.of(Torque):
            self._torque(torque)
        self._gravity()
        self._velocities()
        for contact in self.contacts:  # the angles' labels after the loads' (beside the arcs, they have more room)
            self._contact_angle(contact)
        for contact in self.contacts:
            self._regime(contact)
        for drawn in self.bodies.values():
            self._name(drawn)
        for tip, text in self.pulls.values():
            self.later(text, tip, 0.04)
        for spring in self.of(Spring):
            self._element_label(spring, spring.stiffness)
        for damper in (d for d in self.of(Damper) if not d.rotational):
            self._element_label(damper, damper.coefficient)
        for text, point, gap, prefer in self.pending:
            view.label(point, text, gap, prefer)
        self.fig.lines += [line for name in LAYERS for line in view.layers[name]]

    def later(self, text, point, gap: float = 0.05, prefer=None) -> None:
        """A label placed once everything is drawn (so that it can avoid it)."""
        self.pending.append((text, point, gap, prefer))

    def _attached(self, name: str) -> list[tuple[float, float]]:
        """The points of a body where parts attach to it or it touches a surface (world, m)."""
        view, points = self.view, []
        for part in self.of(Pin) + self.of(Slider) + self.of(Force):
            if part.body == name:
                points.append(view.world(name, part.offset))
            if isinstance(part, Pin) and part.to == name:
                points.append(view.world(name, part.to_offset))
        for part in self.of(Spring) + self.of(Damper):
            points += [view.world(b, o) for b, o in zip(part.ends, part.offsets) if b == name]
        for cord in self.cords:
            points += [view.vector(a.center(view.coords)) for a in cord.path if a.body == name]
        points += [view.world(name, c.point) for c in self.contacts if c.body == name and c.point is not None]
        return points

    def _off_the_surfaces(self) -> None:
        """A body touching a surface at one of its points stays on the side it touches it from: a
        drawn outline that would cross the surface as drawn (an oval about a ladder's foot) is
        Undrawable."""
        view = self.view
        for contact in self.contacts:
            if contact.point is None:
                continue
            surface, lift = self.scene.surfaces[contact.surface], self.lift.get(contact.surface, 0.0)
            for point in self.bodies[contact.body].outline():
                world = _add(view.origin, point, 1 / view.scale)
                if view.value(surface.gap(sp.Matrix(world), sp.Integer(0))) * view.scale + lift < -0.02:
                    raise Undrawable(f"the {contact.body} drawn would cross the surface {contact.surface}")

    def _ground_anchor(self, point, toward, layer: str = "supports", width: float = 0.5) -> None:
        """A hatched ceiling or wall at `point` (cm), facing `toward` (where the attached part is)."""
        toward = _norm(toward)
        across = _perp(toward)
        a, b = _add(point, across, width / 2), _add(point, across, -width / 2)
        back_a, back_b = _add(a, toward, -0.14), _add(b, toward, -0.14)
        self.view.put(layer, f"\\fill[pattern=north east lines] {_pt(a)} -- {_pt(b)} -- {_pt(back_b)} -- "
                             f"{_pt(back_a)} -- cycle; \\draw[thick] {_pt(a)} -- {_pt(b)};")
        self.view.ground_ink([a, b, back_b, back_a, a])

    def _support(self, point, direction, length: float) -> None:
        """A pin's support: a triangle from the pin at `point` to a hatched base `length` cm along `direction`."""
        direction = _norm(direction)
        across = _perp(direction)
        base = _add(point, direction, length)
        half = min(0.3, max(0.2, 0.35 * length))
        left, right = _add(base, across, half), _add(base, across, -half)
        self.view.put("supports", f"\\draw[fill=gray!30] {_pt(point)} -- {_pt(left)} -- {_pt(right)} -- cycle;")
        self.view.ink_polyline([point, left, right, point])
        self._ground_anchor(base, (-direction[0], -direction[1]), width=0.62)

    # cords
    def _cord(self, cord: Cord) -> None:
        view, fig = self.view, self.fig
        runs = self.runs[cord.name]
        path = cord.path
        for r in runs:
            start, end = view.at(view.vector(r.start_point)), view.at(view.vector(r.end_point))
            if r.length is not None:
                view.put("cords", f"\\draw[thick] {_pt(start)} -- {_pt(end)};")
                view.ink_line(start, end)
        for i, a in enumerate(path):
            if a.kind == "pulled":
                continue
            center = view.at(view.vector(a.center(view.coords)))
            radius = view.value(a.radius) * view.scale
            incoming = view.at(view.vector(runs[i - 1].end_point)) if i > 0 else None
            outgoing = view.at(view.vector(runs[i].start_point)) if i < len(runs) else None
            body = self.bodies.get(a.body) if a.body is not None else None
            if radius > 1e-9:
                if body is None:  # a fixed drum of the ground
                    view.put("bodies", f"\\draw[fill=gray!30] {_pt(center)} circle ({_f(radius)});")
                    view.ink_circle(center, radius)
                    self.pegs.append((center, radius))
                elif body.kind != "round" or abs(body.radius_m * view.scale - radius) > 1e-6 or \
                        math.hypot(*_sub(center, body.center)) > 1e-6:  # a hub, a step of a pulley
                    view.put("elements", f"\\draw[fill=gray!35] {_pt(center)} circle ({_f(radius)});")
                    view.ink_circle(center, radius)
                self._wrap(a, center, radius, incoming, outgoing)
            elif a.kind == "around":  # a peg of no size
                if body is None:
                    view.put("joints", f"\\draw[fill=white] {_pt(center)} circle (0.07);")
                    self.pegs.append((center, 0.07))
                else:
                    view.put("joints", f"\\fill {_pt(center)} circle (0.05);")
            elif a.kind == "point":
                toward = view.vector(runs[0].direction) if i == 0 else _scale_vec(view.vector(runs[-1].direction), -1)
                if body is None:
                    self._ground_anchor(center, toward)
                elif body.kind != "point":
                    view.put("joints", f"\\fill {_pt(center)} circle (0.04);")
        for r in runs:
            if r.length is None:  # the pulled end: an arrow from the tangent point toward the pull
                pulled = r.end if r.end.kind == "pulled" else r.start
                start = view.at(view.vector(r.start_point))
                toward = _norm((view.value(sp.cos(pulled.angle)), view.value(sp.sin(pulled.angle))))
                view.put("cords", f"\\draw[thick] {_pt(start)} -- {_pt(_add(start, toward, 0.9))};")
                view.put("arrows", f"\\draw[force] {_pt(_add(start, toward, 0.9))} -- "
                                   f"{_pt(_add(start, toward, 0.9 + ARROW))};")
                view.ink_line(start, _add(start, toward, 0.9 + ARROW))
                self.pulls[cord.name] = (_add(start, toward, 0.9 + ARROW), fig.m(pulled.force))

    def _wrap(self, a, center, radius: float, incoming, outgoing) -> None:
        """The cord in contact with a circle: from the incoming tangent point to the outgoing one in
        its sense; a wound end shows a quarter turn still on the reel."""
        view = self.view
        if incoming is not None and outgoing is not None:
            start = _degrees(_sub(incoming, center))
            sweep = (_degrees(_sub(outgoing, center)) - start) * a.turn % 360 * a.turn
        elif outgoing is not None:  # wound at the start: the cord reaches the tangent point turning with `turn`
            end = _degrees(_sub(outgoing, center))
            start, sweep = end - 90 * a.turn, 90 * a.turn
        elif incoming is not None:
            start, sweep = _degrees(_sub(incoming, center)), 90 * a.turn
        else:
            return
        if abs(sweep) < 0.5:
            return
        first_point = _add(center, _unit(start), radius)
        view.put("cords", f"\\draw[thick] {_pt(first_point)} arc[start angle={_f(start)}, "
                          f"end angle={_f(start + sweep)}, radius={_f(radius)}];")
        steps = max(2, int(abs(sweep) / 10))
        view.ink += [_add(center, _unit(start + sweep * k / steps), radius) for k in range(steps + 1)]

    # springs and dashpots
    def _ends(self, part):
        view = self.view
        return [view.at(view.world(b, o)) for b, o in zip(part.ends, part.offsets)]

    def _spring(self, spring: Spring) -> None:
        view = self.view
        p, q = self._ends(spring)
        points = zigzag(p, q)
        view.put("elements", f"\\draw[line join=round] {' -- '.join(_pt(x) for x in points)};")
        view.ink_polyline(points)
        self._element_anchors(spring, p, q)

    def _damper(self, damper: Damper) -> None:
        if damper.rotational:
            return
        view = self.view
        p, q = self._ends(damper)
        lines = dashpot(p, q)
        view.put("elements", " ".join(f"\\draw{style} {' -- '.join(_pt(x) for x in points)};"
                                      for style, points in lines))
        for _, points in lines:
            view.ink_polyline(points)
        self._element_anchors(damper, p, q)

    def _element_anchors(self, part, p, q) -> None:
        for body, here, there in ((part.ends[0], p, q), (part.ends[1], q, p)):
            if body is None:
                self._ground_anchor(here, _sub(there, here))

    def _element_label(self, part, expression) -> None:
        p, q = self._ends(part)
        self.later(self.fig.m(expression), _add(p, _sub(q, p), 0.5), 0.16)

    # joints
    def _pin(self, pin: Pin) -> None:
        view = self.view
        drawn = self.bodies[pin.body]
        point = view.at(view.world(pin.body, pin.offset))
        if pin.to is not None:  # between bodies: a small circle (a point mass is its own mark)
            if drawn.kind != "point" and self.bodies[pin.to].kind != "point":
                view.put("joints", f"\\draw[fill=white] {_pt(point)} circle (0.07);")
            return
        at_center = math.hypot(*_sub(point, drawn.center)) < 1e-6
        beyond = drawn.extent + 0.03 if at_center and drawn.kind == "round" else 0.0
        direction = view.clearest(point, max(drawn.extent, 0.4) + 0.9, beyond=beyond)
        coiled = self._has_coil(point)
        extra = 0.42 if coiled else 0.0  # past a coil or a rotational damper at the pin
        if at_center and drawn.kind == "round":
            self._support(point, direction, max(drawn.extent, extra) + 0.38)
            view.draw("joints", self.fig.axle, point)
        else:
            self._support(point, direction, max(drawn.reach(point, direction), extra) + 0.38)
            view.put("joints", f"\\draw[fill=white] {_pt(point)} circle (0.06);")

    def _peg(self, center, radius: float) -> None:
        """A fixed peg or drum of the ground: a support on its clearest side."""
        direction = self.view.clearest(center, radius + 0.8, beyond=radius + 0.03)
        self._support(center, direction, radius + 0.38)
        if radius > 0.07:
            self.view.put("joints", f"\\draw[fill=white] {_pt(center)} circle (0.05);")

    def _slider(self, slider: Slider) -> None:
        view = self.view
        drawn = self.bodies[slider.body]
        point = view.at(view.world(slider.body, slider.offset))
        along = _norm((view.value(sp.cos(slider.angle)), view.value(sp.sin(slider.angle))))
        back, ahead = drawn.reach(point, (-along[0], -along[1])), drawn.reach(point, along)
        a, b = _add(point, along, -back - 0.7), _add(point, along, ahead + 0.7)
        below = _perp(along)
        below = (-below[0], -below[1])
        view.put("supports", f"\\fill[pattern=north east lines] {_pt(_add(a, below, 0.04))} -- {_pt(_add(b, below, 0.04))}"
                             f" -- {_pt(_add(b, below, 0.16))} -- {_pt(_add(a, below, 0.16))} -- cycle; "
                             f"\\draw[thick, gray!70!black] {_pt(a)} -- {_pt(b)};")
        view.ink_line(a, b)
        if drawn.kind == "point":
            return
        degrees = _degrees(along)
        if slider.turns:  # a pin in a slot
            view.put("blocks", f"\\draw[fill=white] {_pt(point)} circle (0.07);")
        else:  # a guide holds the body's angle: a sliding block
            view.put("blocks", f"\\draw[fill=white, rotate around={{{_f(degrees)}:{_pt(point)}}}] "
                               f"{_pt(_add(point, (-0.16, -0.09)))} rectangle {_pt(_add(point, (0.16, 0.09)))};")

    def _weld(self, weld: Weld) -> None:
        """To the ground: a hatched wall against the body (a side first: a shelf, a cantilever) with
        the filled triangle of a weld; between bodies the triangle between their centers, on a thick
        bar when they are apart."""
        view = self.view
        drawn = self.bodies[weld.body]
        c = drawn.center
        if weld.to is None:
            direction = view.clearest(c, drawn.extent + 0.8, own=drawn.outline(),
                                      candidates=[(-1, 0), (1, 0), (0, 1), (0, -1)])
            edge = _add(c, direction, drawn.reach(c, direction))
            self._ground_anchor(edge, (-direction[0], -direction[1]), width=0.6)
            view.put("joints", _weld_mark(edge, direction))
            return
        other = self.bodies[weld.to]
        between = _sub(other.center, c)
        apart = math.hypot(*between)
        if apart > 1e-6 and apart > drawn.reach(c, _norm(between)) + other.reach(other.center, _norm(_scale_vec(
                between, -1))):  # apart: a rigid bar between them
            view.put("elements", f"\\draw[line width=2pt] {_pt(c)} -- {_pt(other.center)};")
            view.ink_line(c, other.center)
        middle = _add(c, between, 0.5)
        view.put("joints", _weld_mark(_add(middle, (0, -0.06)), (0, -1)))

    def _joint_point(self, body: str, other: str | None):
        """Where a coil or a rotational damper goes: the pin that holds the body (to `other`), else its center."""
        view = self.view
        for pin in self.of(Pin):
            if pin.body == body and pin.to == other:
                return view.at(view.world(body, pin.offset))
            if other is not None and pin.body == other and pin.to == body:
                return view.at(view.world(other, pin.offset))
        return self.bodies[body].center

    def _has_coil(self, point) -> bool:
        """Whether a torsional spring or a rotational damper is drawn at this point (cm)."""
        held = [(c.body, c.to) for c in self.of(TorsionalSpring)] + [(d.ends[0], None) for d in self.of(Damper)
                                                                      if d.rotational]
        return any(math.hypot(*_sub(self._joint_point(body, to), point)) < 1e-6 for body, to in held)

    def _coil(self, coil: TorsionalSpring) -> None:
        view = self.view
        point = self._joint_point(coil.body, coil.to)
        outward = view.clearest(point, 0.8)
        start = _degrees(outward)
        points = [_add(point, _unit(start - 720 + 720 * k / 48), 0.05 + 0.25 * k / 48) for k in range(49)]
        tail = _add(points[-1], outward, 0.22)
        view.put("elements", f"\\draw[line join=round] plot[smooth] coordinates {{{' '.join(_pt(p) for p in points)}}} "
                             f"-- {_pt(tail)};")
        view.ink_polyline(points + [tail])
        if coil.to is None:
            self._ground_anchor(tail, (-outward[0], -outward[1]), width=0.4)
        else:
            view.put("joints", f"\\fill {_pt(tail)} circle (0.04);")
        self.later(self.fig.m(coil.stiffness), _add(point, outward, 0.32), 0.08)

    def _rotational_damper(self, damper: Damper) -> None:
        view = self.view
        point = self._joint_point(damper.ends[0], None)
        side = _degrees(view.clearest(point, 0.7))
        a, b = side - 40, side + 40
        inner, outer = 0.22, 0.36
        view.put("elements", f"\\fill[pattern=north east lines] {_pt(_add(point, _unit(a), inner))} "
                             f"arc[start angle={_f(a)}, end angle={_f(b)}, radius={_f(inner)}] -- "
                             f"{_pt(_add(point, _unit(b), outer))} arc[start angle={_f(b)}, end angle={_f(a)}, "
                             f"radius={_f(outer)}] -- cycle; \\draw {_pt(_add(point, _unit(a), outer))} "
                             f"arc[start angle={_f(a)}, end angle={_f(b)}, radius={_f(outer)}];")
        view.ink += [_add(point, _unit(a + 8 * k), r) for k in range(11) for r in (inner, outer)]
        self.later(self.fig.m(damper.coefficient), _add(point, _unit(side), outer), 0.06)

    # surfaces and contacts
    def _contact_point(self, contact: Contact):
        view = self.view
        drawn = self.bodies[contact.body]
        surface = self.scene.surfaces[contact.surface]
        if contact.point is not None:  # a material point touches (a ladder's foot)
            world = view.world(contact.body, contact.point)
            return world, _norm(view.vector(surface.normal_at(sp.Matrix(world), sp.Integer(0))))
        radius = drawn.radius_m if drawn.kind == "round" and "radius" in drawn.body.sizes else 0.0
        normal = _norm(view.vector(surface.normal_at(sp.Matrix(drawn.world), sp.Float(radius))))
        return _add(drawn.world, normal, -radius), normal

    def _surfaces(self) -> None:
        view = self.view
        done = set()
        for contact in self.contacts:
            if contact.surface in done:
                continue
            done.add(contact.surface)
            surface = self.scene.surfaces[contact.surface]
            if isinstance(surface, Plane):
                self._plane(surface)
            else:
                middle, radius = view.at(view.vector(surface.middle)), view.value(surface.radius) * view.scale
                radius += self.lift.get(surface.name, 0.0) * (1 if surface.side == "inside" else -1)
                solid = radius + 0.16 if surface.side == "inside" else max(radius - 0.16, 0.0)  # the solid side
                hatch = f"{_pt(middle)} circle ({_f(solid)}) {_pt(middle)} circle ({_f(radius)})"
                view.put("surfaces", f"\\fill[pattern=north east lines, even odd rule] {hatch}; "
                                     f"\\draw[thick] {_pt(middle)} circle ({_f(radius)}); \\fill {_pt(middle)} "
                                     "circle (0.03);")
                side = view.clearest(middle, radius, candidates=[_unit(a) for a in (150, 30, 210, 330, 120, 60)])
                view.put("surfaces", f"\\draw[thin] {_pt(middle)} -- {_pt(_add(middle, side, radius))};")
                start = len(view.ink)
                view.ink_circle(middle, radius)
                view.ink_circle(middle, solid)
                view.ground.update(view.ink[start:])
                view.ink_line(middle, _add(middle, side, radius))
                if radius > 0.8:  # on the radius
                    self.later(self.fig.m(surface.radius), _add(middle, side, radius / 2), 0.04)
                else:  # a small circle: beyond its rim, on the radius' line
                    self.later(self.fig.m(surface.radius), _add(middle, side, max(radius, solid)), 0.1, [side])

    def _plane(self, plane: Plane) -> None:
        """The plane from before its first body to past its last (a little past a touching point),
        stopping short of what lies below its level (a pulley at the table's edge) and at the
        corner where it meets another plane (a floor and a wall); an incline a wedge with its angle."""
        view = self.view
        through = view.vector(plane.through)
        down, normal = _norm(view.vector(plane.down)), _norm(view.vector(plane.normal))
        on = [c for c in self.contacts if c.surface == plane.name]
        along = [_dot(_sub(self._contact_point(c)[0], through), down) for c in on]
        around = max([1.1] + [1.3 * self.bodies[c.body].extent for c in on if c.point is None])  # a body on it
        margins = [(0.6 if c.point is not None else around) / view.scale for c in on]
        low, high = min(s - m for s, m in zip(along, margins)), max(s + m for s, m in zip(along, margins))
        lowest, highest = min(along), max(along)
        def level(point) -> tuple[float, float]:
            return _dot(_sub(point, through), down), _dot(_sub(point, through), normal)

        # a cord that runs along the plane, a ground point on it (a wall, a peg): the plane reaches them
        for cord in self.cords:
            for r in self.runs[cord.name]:
                for point in (view.vector(r.start_point), view.vector(r.end_point)):
                    s, h = level(point)
                    if abs(h) < 1e-9 * (1 + abs(s)):
                        low, high = min(low, s), max(high, s)
        for part in self.of(Spring) + self.of(Damper):
            for b, o in zip(part.ends, part.offsets):
                if b is None and not getattr(part, "rotational", False):
                    s, h = level(view.world(b, o))
                    if -1e-9 < h < 0.5 / view.scale:
                        low, high = min(low, s), max(high, s)
        # what lies below the plane's level beyond its bodies (a pulley at a table's edge): it stops short
        resting = {c.body for c in on}
        gap = 0.08 / view.scale
        for name, drawn in self.bodies.items():
            if name in resting:
                continue
            radius = drawn.radius_m if drawn.kind == "round" else 0.0
            for corner in drawn.corners_m() + [drawn.world]:
                s, h = level(corner)
                if h < -1e-9 * (1 + abs(h)):
                    if s > highest:
                        high = min(high, s - radius - gap if corner == drawn.world else s - gap)
                    elif s < lowest:
                        low = max(low, s + radius + gap if corner == drawn.world else s + gap)
        corners = {} if _wedge(down) else self._corners(plane, lowest, highest)
        low, high = corners.get(-1, low), corners.get(1, high)
        lift = self.lift.get(plane.name, 0.0)
        a, b = (_add(view.at(_add(through, down, s)), normal, -lift) for s in (low, high))
        angle = math.degrees(math.atan2(-down[1], down[0]))
        if _wedge(down):  # an incline; a level floor, a wall or any other plane is a hatched line
            corner = (a[0], b[1])
            view.put("surfaces", f"\\draw[fill=gray!10] {_pt(a)} -- {_pt(b)} -- {_pt(corner)} -- cycle; "
                                 f"\\fill[pattern=north east lines] {_pt(_add(corner, (0, -0.15)))} rectangle {_pt(b)};")
            view.ground_ink([a, b, corner, a])
            radius = min(0.8, 0.45 * math.hypot(*_sub(b, corner)))
            # at the foot b, between the ground and the slope: toward the upper end a, left or right
            start, end = (180 - angle, 180) if down[0] > 0 else (0, 180 - angle)
            view.draw("surfaces", self.fig.arc, b, radius, start, end)
            view.ink += [_add(b, _unit(start + (end - start) * k / 6), radius) for k in range(7)]
            self.later(self.fig.m(plane.angle), _add(b, _unit((start + end) / 2), radius + 0.02), 0.03)
        else:  # at a corner the hatching runs on past it, under the other plane's
            under = (-normal[0], -normal[1])
            ha, hb = (_add(a, down, -0.16) if -1 in corners else a), (_add(b, down, 0.16) if 1 in corners else b)
            view.put("surfaces", f"\\fill[pattern=north east lines] {_pt(ha)} -- {_pt(hb)} -- "
                                 f"{_pt(_add(hb, under, 0.16))} -- {_pt(_add(ha, under, 0.16))} -- cycle; "
                                 f"\\draw[thick] {_pt(a)} -- {_pt(b)};")
            view.ground_ink([ha, hb, _add(hb, under, 0.16), _add(ha, under, 0.16), ha])

    def _drawn_line(self, plane: Plane):
        """Where a plane is drawn (cm): a point of its line (lowered by its lift), its down-slope
        and its normal unit vectors."""
        view = self.view
        normal = _norm(view.vector(plane.normal))
        return _add(view.at(view.vector(plane.through)), normal, -self.lift.get(plane.name, 0.0)), \
            _norm(view.vector(plane.down)), normal

    def _corners(self, plane: Plane, lowest: float, highest: float) -> dict[int, float]:
        """Where another plane drawn as a line meets this one within the scene (a floor and a
        wall), with this one's contacts (from `lowest` to `highest`, m along it) on the open side
        of the other: {-1 or +1, the end it makes (up- or down-slope): m along it from `through`}."""
        view = self.view
        base, down, _ = self._drawn_line(plane)
        result = {}
        for name in dict.fromkeys(c.surface for c in self.contacts):
            other = self.scene.surfaces[name]
            if name == plane.name or not isinstance(other, Plane):
                continue
            other_base, other_down, other_normal = self._drawn_line(other)
            corner = _crossing(base, down, other_base, other_down)
            if _wedge(other_down) or corner is None or not all(-0.5 <= corner[k] <= self.size[k] + 0.5 for k in (0, 1)):
                continue
            at = _dot(_sub(corner, base), down) / view.scale
            side = -1 if _dot(down, other_normal) > 0 else 1  # the end of this plane that the corner is
            if (lowest >= at if side < 0 else highest <= at):
                result[side] = at
        return result

    def _drawn_contact(self, contact: Contact):
        """The point of contact on the figure (on its surface as drawn, cm) and the surface's normal there."""
        world, normal = self._contact_point(contact)
        return _add(self.view.at(world), normal, -self.lift.get(contact.surface, 0.0)), normal

    def _contact_angle(self, contact: Contact) -> None:
        """A straight body (a rod, a bar) touching a plane at one of its points: the angle between
        them marked there, on the side of the point where the scene gives it as a parameter (a
        ladder's theta above the floor); no mark when neither angle is one."""
        view, drawn, plane = self.view, self.bodies[contact.body], self.scene.surfaces[contact.surface]
        if contact.point is None or drawn.kind not in ("rod", "bar") or not isinstance(plane, Plane):
            return
        toward = drawn.body.angle + self._direction(drawn, contact.point)  # along the body, from the point
        parameters = {p.symbol for p in self.fig.problem.parameters.values()}
        for line in (plane.line_angle, sp.pi + plane.line_angle):  # along the plane, down- and up-slope
            turn = toward - line
            turn -= 2 * sp.pi * round(view.value(turn) / (2 * math.pi))  # within half a turn
            swept = turn if view.value(turn) >= 0 else -turn
            if swept in parameters:
                break
        else:
            return
        point, _ = self._drawn_contact(contact)
        start, sweep = math.degrees(view.value(line)), math.degrees(view.value(turn))
        radius = min(0.5, 0.4 * math.hypot(*_sub(*drawn.segment())))
        view.draw("marks", self.fig.arc, point, radius, start, start + sweep)
        view.ink += [_add(point, _unit(start + sweep * k / 6), radius) for k in range(7)]
        sides = [(_unit(start + sweep * k), extra) for extra in (0.0, 0.3) for k in (0.5, 0.3, 0.7, 0.15)]
        self.later(self.fig.m(swept), point, radius + 0.04, sides)  # beyond the arc, the nearer the better

    def _direction(self, drawn: _Body, point) -> sp.Expr:
        """The angle, in the body's frame, of a rod's or a bar's line from its `point` to its far end."""
        view = self.view
        if drawn.kind == "bar":
            ends = drawn.ends
        else:
            half = drawn.body.sizes["length"] / 2
            ends = ((-half, sp.Integer(0)), (half, sp.Integer(0)))
        far = max(ends, key=lambda end: math.hypot(view.value(end[0] - point[0]), view.value(end[1] - point[1])))
        dx, dy = (sp.sympify(far[k] - point[k], strict=True) for k in (0, 1))  # safe: the scene's own expressions
        if dy == 0:
            return sp.Integer(0) if view.value(dx) > 0 else sp.pi
        return sp.atan2(dy, dx)

    def _regime(self, contact: Contact) -> None:
        """The contact's regime beside its point of contact: no slip, smooth, rough."""
        view, fig = self.view, self.fig
        point, normal = self._drawn_contact(contact)
        tangent = (normal[1], -normal[0])
        gap = BLOCK / 2 + 0.06 if self.bodies[contact.body].kind == "point" else 0.12
        sides = [_add(tangent, normal, k) for k in (0.25, 1.0)] + [_add(_scale_vec(tangent, -1), normal, k)
                                                                  for k in (0.25, 1.0)]
        below = 0.2 - gap + 0.04  # under the surface's hatching
        sides += [(_scale_vec(normal, -1), below), (_add(tangent, normal, -1.6), below + 0.1),
                  (_add(_scale_vec(tangent, -1), normal, -1.6), below + 0.1)]
        self.later(regime_text(fig, contact), point, gap, sides)
        if contact.rolling:
            view.put("marks", f"\\fill {_pt(point)} circle (0.035);")

    # loads
    def _force(self, force: Force) -> None:
        view, fig = self.view, self.fig
        drawn = self.bodies[force.body]
        point = view.at(view.world(force.body, force.offset))
        magnitude, angle = force.magnitude, force.angle
        if magnitude.could_extract_minus_sign():
            magnitude, angle = -magnitude, angle + sp.pi
        direction = _norm((view.value(sp.cos(angle)), view.value(sp.sin(angle))))
        offset = _sub(point, drawn.center)
        pushes = math.hypot(*offset) > 0.5 * drawn.extent > 0 and _dot(offset, direction) < 0
        start = _add(point, direction, -ARROW) if pushes else point
        end = _add(start, direction, ARROW)
        view.put("arrows", f"\\draw[force] {_pt(start)} -- {_pt(end)};")
        view.ink_line(start, end)
        view.put("joints", f"\\fill[red!70!black] {_pt(point)} circle (0.035);")
        self.later(fig.m(magnitude), start if pushes else end, 0.06)

    def _torque(self, torque: Torque) -> None:
        view, fig = self.view, self.fig
        drawn = self.bodies[torque.body]
        magnitude, sign = torque.torque, 1
        if magnitude.could_extract_minus_sign():
            magnitude, sign = -magnitude, -1
        radius = drawn.extent + 0.2 if drawn.extent <= 1.0 else 0.5  # around it, or about its center within it
        side = _degrees(view.clearest(drawn.center, radius + 0.3, own=drawn.outline()))
        start, end = (side - 55, side + 55) if sign > 0 else (side + 55, side - 55)
        first = _add(drawn.center, _unit(start), radius)
        view.put("arrows", f"\\draw[force] {_pt(first)} arc[start angle={_f(start)}, end angle={_f(end)}, "
                           f"radius={_f(radius)}];")
        view.ink += [_add(drawn.center, _unit(start + (end - start) * k / 10), radius * f)  # the arc and its hollow
                     for k in range(11) for f in (0.4, 0.7, 1.0)]
        self.later(fig.m(magnitude), _add(drawn.center, _unit(side), radius), 0.06)

    def _gravity(self) -> None:
        gravity = self.scene.gravity
        if gravity is None:
            return
        view, fig = self.view, self.fig
        if len(self.bodies) == 1:
            drawn = next(iter(self.bodies.values()))
            weight = fig.product(drawn.body.mass, gravity.g)
            start = drawn.drawn_center
            view.put("arrows", f"\\draw[force] {_pt(start)} -- {_pt(_add(start, (0, -ARROW)))};")
            view.ink_line(start, _add(start, (0, -ARROW)))
            self.later(f"${weight}$" if weight else "$\\vec g$", _add(start, (0, -ARROW)), 0.04)
            return
        xs = [p[0] for p in view.ink] or [0.0]
        ys = [p[1] for p in view.ink] or [0.0]
        top = (max(xs) + 0.5, max(ys))
        view.put("arrows", f"\\draw[force] {_pt(top)} -- {_pt(_add(top, (0, -0.7)))};")
        view.ink_line(top, _add(top, (0, -0.7)))
        self.later("$\\vec g$", _add(top, (0, -0.35)), 0.06)

    def _velocities(self) -> None:
        view, fig = self.view, self.fig
        for name, motion in self.scene.motions.items():
            if name not in self.bodies or all(v == 0 for v in motion.velocity):
                continue
            drawn = self.bodies[name]
            direction = _norm((view.value(motion.velocity[0]), view.value(motion.velocity[1])))
            start = _add(drawn.drawn_center, direction, max(drawn.extent, BALL) + 0.08)
            view.put("arrows", f"\\draw[velocity] {_pt(start)} -- {_pt(_add(start, direction, 0.8))};")
            view.ink_line(start, _add(start, direction, 0.8))
            self.later(fig.m(sp.sqrt(motion.velocity[0] ** 2 + motion.velocity[1] ** 2)), _add(start, direction, 0.8))

    # labels
    def _name(self, drawn: _Body) -> None:
        body = drawn.body
        text = self.fig.tex(body.mass) or self.fig.tex(body.given_inertia)
        label = f"${text}$" if text else f"\\scriptsize {tex_escape(body.name)}"
        if drawn.kind in ("rod", "bar", "rectangle"):  # across it, beside its middle (a bar's center of mass)
            along = drawn.axis
            across = _perp(along)
            self.later(label, drawn.center, 0.12 if drawn.kind != "rectangle" else drawn.reach(drawn.center, across) + 0.04,
                       [across, _scale_vec(across, -1)]
                       + [(_add(side, along, k), extra) for extra, k in ((0.2, 1.0), (0.5, 1.5))
                          for side in (across, _scale_vec(across, -1)) for k in (k, -k)])
        elif drawn.kind in ("round", "oval"):  # inside when it is large enough to hold it (clear of a hub), else beside
            reach = drawn.extent
            if reach > 0.6:
                sides = [(d, extra) for extra in (0.0, 0.35 * reach) for d in DIRECTIONS]
                self.later(label, drawn.center, 0.1, sides)
            else:
                self.later(label, drawn.center, reach + 0.05)
        else:
            self.later(label, drawn.drawn_center, drawn.extent + 0.04)



def _on_segment(point, p, q) -> bool:
    """Whether `point` lies on the segment from p to q (to a millionth of its length)."""
    length = math.hypot(*_sub(q, p))
    direction, offset, tolerance = _norm(_sub(q, p)), _sub(point, p), 1e-6 * length
    return abs(_dot(offset, _perp(direction))) <= tolerance and -tolerance <= _dot(offset, direction) <= length + tolerance


def _crossing(p, u, q, v):
    """Where the line through p along u crosses the line through q along v; None if they are parallel."""
    cross = u[0] * v[1] - u[1] * v[0]
    if abs(cross) < 1e-9:
        return None
    t = ((q[0] - p[0]) * v[1] - (q[1] - p[1]) * v[0]) / cross
    return _add(p, u, t)


def _wedge(down) -> bool:
    """Whether a plane descending along `down` is drawn as an incline's wedge (else a hatched line):
    to the right or to the left."""
    return 0.5 < abs(90 - math.degrees(math.atan2(-down[1], down[0]))) < 89.5


def _scale_vec(p, k: float):
    return (p[0] * k, p[1] * k)


def _weld_mark(point, direction) -> str:
    """The filled triangle of a weld, on the body's side of the joint at `point`."""
    back = (-direction[0], -direction[1])
    across = _perp(direction)
    a, b, c = _add(point, across, 0.12), _add(point, across, -0.12), _add(point, back, 0.16)
    return f"\\fill {_pt(a)} -- {_pt(b)} -- {_pt(c)} -- cycle;"


def zigzag(p, q, amplitude: float = 0.11) -> list[tuple[float, float]]:
    """A spring's polyline from exactly p to exactly q: straight leads, a zigzag between."""
    length = math.hypot(*_sub(q, p))
    along = _norm(_sub(q, p))
    across = _perp(along)
    lead = min(0.2, 0.15 * length)
    teeth = max(4, min(12, int((length - 2 * lead) / 0.12)))
    step = (length - 2 * lead) / teeth
    points = [p, _add(p, along, lead)]
    for k in range(teeth):
        points.append(_add(_add(p, along, lead + step * (k + 0.5)), across, amplitude * (1 if k % 2 == 0 else -1)))
    points += [_add(q, along, -lead), q]
    return points


def dashpot(p, q, width: float = 0.14) -> list[tuple[str, list]]:
    """A dashpot from p to q: a rod to a cylinder open toward q, a piston inside, its rod to q."""
    length = math.hypot(*_sub(q, p))
    along = _norm(_sub(q, p))
    across = _perp(along)
    bottom, mouth, piston = (_add(p, along, length * k) for k in (0.3, 0.62, 0.5))
    return [("", [p, bottom]),
            ("", [_add(mouth, across, width), _add(bottom, across, width), _add(bottom, across, -width),
                  _add(mouth, across, -width)]),
            ("[thick]", [_add(piston, across, width * 0.75), _add(piston, across, -width * 0.75)]),
            ("", [piston, q])]


def _parts(fig: _Figure) -> None:
    """Any scene of parts, in its reference configuration (see the module)."""
    _Layout(fig).draw()
