r"""Surfaces carried by a body, in the general layout (derive.publishing.figure.parts): the carrier drawn
as what holds its surface, never as ground (no hatching: it moves).

- a plane carried by a rod (or a bar) that lies along it is the rod's own face: the rod is drawn,
  a block on it sits on it, and the plane's angle to the level is marked at the rod's center
  against a dashed level line when a parameter names it (a tilted plank);
- a plane carried by a point mass is the top of a solid under it: an inclined one a wedge (the
  plane its face, its back upright, its base level, its angle marked at its foot), a level one a
  slab (a plank) whose top is the plane, as thick as twice the carrier's point's depth under it;
- a circle carried by a point mass is a track in a block (a cart): the block under the track's
  lower half, from the level of its middle down past its bottom, the track a thick circle.

A slider on such a solid (a point mass: it does not turn, so each of its points keeps to a line
parallel to the rail) has its rail drawn under the solid's base, as the floor it slides on; a
force on it starts at its outline (on its line of action). Any other carrier is `Undrawable`.

>>> from derive.language.problem import load
>>> from derive.publishing.figure import tikz
>>> drawn = tikz(load("wedge_block"))
>>> r"{$\theta$}" in drawn and "{$M$}" in drawn and "pattern=north east lines" in drawn
True
"""
from __future__ import annotations

import math

from derive.publishing.figure.canvas import _add, _f, _pt, _unit
from derive.publishing.figure.drawn_view import Undrawable
from derive.publishing.figure.vectors import _dot, _norm, _perp, _scale_vec, _sub
from derive.parts.pin import Pin
from derive.parts.surfaces import Circle, Plane

SLAB = 0.3  # cm: a slab's thickness when the carrier's point lies on its top
MARGIN = 1.1  # cm: how far a solid reaches past the bodies on it, along its surface
WALL = 0.25  # cm: a cart's wall beside its track, and its floor under it


class CarrierDrawings:
    """How the general layout draws carried surfaces and their carriers (a mixin of parts._Layout)."""

    def _carried(self) -> dict[str, str]:
        """{surface: its carrier} for the carried surfaces a body touches."""
        touched = {c.surface for c in self.contacts}
        return {name: s.carrier for name, s in self.scene.surfaces.items() if s.carrier is not None and name in touched}

    def _mark_faces(self) -> None:
        """A plane carried by a rod or a bar whose line it is: the rod's own face (`self.faces`)."""
        view = self.view
        self.faces = set()
        for name, carrier in self._carried().items():
            surface, drawn = self.scene.surfaces[name], self.bodies[carrier]
            if not isinstance(surface, Plane) or drawn.kind not in ("rod", "bar"):
                continue
            through, down = view.vector(surface.through), _norm(view.vector(surface.down))
            ends = drawn.corners_m()
            if all(abs(_dot(_sub(end, through), _perp(down))) <= 1e-9 * (1 + math.hypot(*end)) for end in ends):
                self.faces.add(name)

    def _mark_solids(self) -> None:
        """Each point mass that carries a surface becomes the solid under it (see the module); any
        other carrier, but a rod whose face the plane is, is Undrawable."""
        for name, carrier in self._carried().items():
            if name in self.faces:
                continue
            drawn = self.bodies[carrier]
            if drawn.kind != "point" or drawn.polygon is not None:
                raise Undrawable(f"the figure does not draw the {name} carried by the {carrier}")
            surface = self.scene.surfaces[name]
            drawn.polygon, drawn.holds = (self._under_plane(surface, drawn) if isinstance(surface, Plane)
                                          else self._around_track(surface)), name
            drawn.kind = "solid"

    def _span(self, name: str, through, down) -> tuple[float, float]:
        """How far the bodies on a surface reach along its line `through` + s `down` (cm), with a margin."""
        along = [_dot(_sub(self._drawn_contact(c)[0], through), down) for c in self.contacts if c.surface == name]
        around = max([MARGIN] + [1.3 * self.bodies[c.body].extent for c in self.contacts
                                 if c.surface == name and self.bodies[c.body].kind == "round"])
        return min(along) - around, max(along) + around

    def _under_plane(self, plane: Plane, drawn) -> list[tuple[float, float]]:
        """A wedge (inclined) or a slab (level) whose top is the plane as drawn (cm).

        >>> from derive.language.problem import load
        >>> from derive.publishing.figure.canvas import _Figure
        >>> from derive.publishing.figure.parts import _Layout
        >>> layout = _Layout(_Figure(load("plank_cylinder")))
        >>> top, bottom = layout.bodies["plank"].polygon[0][1], layout.bodies["plank"].polygon[2][1]
        >>> round(top - bottom, 2) == round(2 * (top - layout.bodies["plank"].center[1]), 2)
        True
        """
        base, down, normal = self._drawn_line(plane)
        low, high = self._span(plane.name, base, down)
        a, b = _add(base, down, low), _add(base, down, high)
        if abs(down[1]) > 1e-6:  # a wedge: upright back under its upper end, level base through its foot
            upper, foot = (a, b) if a[1] > b[1] else (b, a)
            return [upper, foot, (upper[0], foot[1])]
        depth = _dot(_sub(base, drawn.center), normal)
        thick = 2 * depth if depth > 0.1 else SLAB
        under = _scale_vec(normal, -thick)
        return [a, b, _add(b, under), _add(a, under)]

    def _around_track(self, track: Circle) -> list[tuple[float, float]]:
        """A block holding a circular track ridden inside: from the level of its middle down past its
        bottom, a wall's width beyond it on either side (cm). (The track is cut out of it when drawn.)"""
        if track.side != "inside":
            raise Undrawable(f"the figure does not draw a carried dome ({track.name})")
        middle, radius = self._track(track)
        reach = radius + WALL
        return [(middle[0] - reach, middle[1]), (middle[0] + reach, middle[1]),
                (middle[0] + reach, middle[1] - reach), (middle[0] - reach, middle[1] - reach)]

    def _track(self, track: Circle):
        """A circular track's middle and radius as drawn (cm; grown by its lift: the beads on it)."""
        view = self.view
        radius = view.value(track.radius) * view.scale + self.lift.get(track.name, 0.0)
        return view.at(view.vector(track.middle)), radius

    def _carried_surface(self, drawn) -> None:
        """The solid a point mass is drawn as, and its surface: a wedge's angle at its foot, a track
        cut out of its block and drawn whole, with its radius."""
        view, fig = self.view, self.fig
        surface = self.scene.surfaces[drawn.holds]
        outline = " -- ".join(_pt(p) for p in drawn.polygon)
        if isinstance(surface, Circle):
            middle, radius = self._track(surface)
            view.put("bodies", f"\\draw[body] {outline} -- cycle; \\fill[white] {_pt(_add(middle, (-radius, 0)))} "
                               f"arc[start angle=180, end angle=360, radius={_f(radius)}]; \\draw[thick] {_pt(middle)} "
                               f"circle ({_f(radius)}); \\fill {_pt(middle)} circle (0.03);")
            view.ink_circle(middle, radius)
            side = _unit(135)
            view.put("marks", f"\\draw[thin] {_pt(middle)} -- {_pt(_add(middle, side, radius))};")
            view.ink_line(middle, _add(middle, side, radius))
            self.later(fig.m(surface.radius), _add(middle, side, radius / 2), 0.04)
            return
        view.put("bodies", f"\\draw[body] {outline} -- cycle;")
        if len(drawn.polygon) == 3:  # a wedge: its angle at its foot, between the base and the face
            upper, foot, back = drawn.polygon
            radius = min(0.7, 0.45 * math.hypot(*_sub(foot, back)))
            angle = math.degrees(math.atan2(upper[1] - foot[1], abs(upper[0] - foot[0])))
            start, end = (180 - angle, 180) if upper[0] < foot[0] else (0, angle)
            view.draw("marks", fig.arc, foot, radius, start, end)
            view.ink += [_add(foot, _unit(start + (end - start) * k / 6), radius) for k in range(7)]
            self.later(fig.m(surface.angle), _add(foot, _unit((start + end) / 2), radius + 0.02), 0.03)

    def _face_angle(self, name: str) -> None:
        """A rod's face at an angle a parameter names: that angle from a dashed level line, at the
        rod's pin (else its center), on the side of it away from the bodies on the face."""
        view, fig = self.view, self.fig
        plane = self.scene.surfaces[name]
        if fig.tex(plane.angle) is None or plane.angle == 0:
            return
        carrier = plane.carrier
        pins = [view.at(view.world(p.body, p.offset)) for p in self.of(Pin) if p.body == carrier and p.to is None]
        point = pins[0] if pins else self.bodies[carrier].center
        down = _norm(view.vector(plane.down))
        if sum(_dot(_sub(self._drawn_contact(c)[0], point), down) for c in self.contacts if c.surface == name) > 0:
            down = _scale_vec(down, -1)  # the bodies are down the slope: up it
        level = (1.0 if down[0] > 0 else -1.0, 0.0)
        radius = 0.8
        view.put("marks", f"\\draw[dashed, gray] {_pt(point)} -- {_pt(_add(point, level, radius + 0.3))};")
        view.ink_line(point, _add(point, level, radius + 0.3))
        start, end = sorted((math.degrees(math.atan2(level[1], level[0])), math.degrees(math.atan2(down[1], down[0]))))
        if end - start > 180:
            start, end = end, start + 360
        view.draw("marks", fig.arc, point, radius, start, end)
        view.ink += [_add(point, _unit(start + (end - start) * k / 6), radius) for k in range(7)]
        middle = _unit((start + end) / 2)
        self.later(fig.m(plane.angle), _add(point, middle, radius), 0.04, [middle, (middle, 0.15)])

    def _carriers(self) -> None:
        for drawn in self.bodies.values():
            if drawn.kind == "solid":
                self._carried_surface(drawn)
        for name in sorted(self.faces):
            self._face_angle(name)

    def _rail_under(self, drawn, point, along) -> tuple[tuple[float, float], tuple[float, float]]:
        """A solid's rail: a line along `along` under its base, past its ends (cm)."""
        below = _scale_vec(_perp(along), -1)
        depth = max(_dot(_sub(p, point), below) for p in drawn.polygon)
        spans = [_dot(_sub(p, point), along) for p in drawn.polygon]
        base = _add(point, below, depth)
        return _add(base, along, min(spans) - 0.5), _add(base, along, max(spans) + 0.5)

