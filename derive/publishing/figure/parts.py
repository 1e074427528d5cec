r"""Any scene of parts, drawn in its reference configuration to scale, from the parts' own geometry.

Every position comes from the scene: a body's center and angle (`at`, `angle`), a point of a body
from `Coordinates.position`, a cord's straight runs from `derive.parts.cord.run` (the exact tangent
points on pulleys, reels and pegs), a contact point from its surface's normal. Evaluated at the
middle of the parameter ranges, open sizes at 1 (as the parts decide a cord's turning sense), and
scaled uniformly so that the scene is about 4 cm wide.

What each part looks like:

- surfaces carried by a body (`drawn_carriers`): a point mass that carries a plane is the wedge or
  the slab under it, one that carries a circular track the block (a cart) it is cut into, its rail
  drawn under its base; a rod that carries a plane along its own line is that plane (a tilted plank);
- clutches (`drawn_clutches`): a brake a pad on the rim from a hatched anchor, a clutch between two
  disks on one axis a dotted felt inside the smaller one's rim, each with its name and couple;
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

from derive.publishing.figure.canvas import _add, _Figure, _pt
from derive.publishing.figure.drawn_view import BALL, BLOCK, DIRECTIONS, LAYERS, Undrawable, _Body, _Scene
from derive.publishing.figure.vectors import _norm, _on_segment, _perp, _scale_vec, _sub
from derive.publishing.figure.drawn_carriers import CarrierDrawings
from derive.publishing.figure.drawn_clutches import ClutchDrawings
from derive.publishing.figure.drawn_cords import CordDrawings
from derive.publishing.figure.drawn_joints import JointDrawings
from derive.publishing.figure.drawn_surfaces import SurfaceDrawings
from derive.publishing.figure.drawn_loads import LoadDrawings
from derive.parts.clutch import Clutch
from derive.parts.contact import Contact
from derive.parts.cord import Cord, run
from derive.parts.damper import Damper
from derive.parts.force import Force
from derive.parts.pin import Pin
from derive.parts.slider import Slider
from derive.parts.slipping_clutch import SlippingClutch
from derive.parts.spring import Spring
from derive.parts.surfaces import Circle, Plane
from derive.parts.torque import Torque
from derive.parts.torsional_spring import TorsionalSpring
from derive.parts.weld import Weld
from derive.text.latex import tex_escape

CORE_WIDTH, CORE_HEIGHT = 4.2, 3.6  # cm: the scene's geometry, before anchors, arrows and labels

#: The parts this layout draws (gravity is the scene's own field).
KNOWN = (Clutch, Contact, Cord, Damper, Force, Pin, Slider, SlippingClutch, Spring, Torque, TorsionalSpring, Weld)


class _Layout(CordDrawings, JointDrawings, SurfaceDrawings, LoadDrawings, CarrierDrawings, ClutchDrawings):
    """The general layout: gathers the geometry, scales it, draws each part."""

    def __init__(self, fig: _Figure):
        self.fig, self.scene = fig, fig.scene
        self.view = view = _Scene(fig)
        scene = self.scene
        parts = list(scene.constraints) + list(scene.loads)
        for part in parts:
            if not isinstance(part, KNOWN):
                raise Undrawable(f"the figure does not draw a {type(part).__name__}")
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
        self._mark_bars()
        self._mark_faces()
        self._mark_blocks()
        self._scale()
        self._mark_solids()

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
            if resting and all(d.kind == "point" for d in resting) and name not in self.faces:  # a rod's face: on it
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

    def draw(self) -> None:
        view = self.view
        for drawn in self.bodies.values():
            if drawn.kind == "oval" and not drawn.pieces:
                drawn.fit_oval([view.at(p) for p in self._attached(drawn.name)])
            drawn.shape()
        self._carriers()
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
        for clutch in self.of(Clutch) + self.of(SlippingClutch):
            self._clutch(clutch)
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

    def _ground_anchor(self, point, toward, layer: str = "supports", width: float = 0.5) -> None:
        """A hatched ceiling or wall at `point` (cm), facing `toward` (where the attached part is)."""
        toward = _norm(toward)
        across = _perp(toward)
        a, b = _add(point, across, width / 2), _add(point, across, -width / 2)
        back_a, back_b = _add(a, toward, -0.14), _add(b, toward, -0.14)
        self.view.put(layer, f"\\fill[pattern=north east lines] {_pt(a)} -- {_pt(b)} -- {_pt(back_b)} -- "
                             f"{_pt(back_a)} -- cycle; \\draw[thick] {_pt(a)} -- {_pt(b)};")
        self.view.ground_ink([a, b, back_b, back_a, a])

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
        elif drawn.kind == "solid":  # inside a wedge or a slab, beside a cart's block
            corners = drawn.polygon
            if isinstance(self.scene.surfaces[drawn.holds], Plane):
                middle = tuple(sum(p[k] for p in corners) / len(corners) for k in (0, 1))
                self.later(label, middle, 0.0, [(0.0, 0.0)] + DIRECTIONS)
            else:
                self.later(label, _add(corners[1], _sub(corners[2], corners[1]), 0.5), 0.06, [(1, 0), (1, 1), (1, -1)])
        elif drawn.kind in ("round", "oval"):  # inside when it is large enough to hold it (clear of a hub), else beside
            reach = drawn.extent
            if reach > 0.6:
                sides = [(d, extra) for extra in (0.0, 0.35 * reach) for d in DIRECTIONS]
                self.later(label, drawn.center, 0.1, sides)
            else:
                self.later(label, drawn.center, reach + 0.05)
        else:
            self.later(label, drawn.drawn_center, drawn.extent + 0.04)


def _parts(fig: _Figure) -> None:
    """Any scene of parts, in its reference configuration (see the module)."""
    _Layout(fig).draw()
