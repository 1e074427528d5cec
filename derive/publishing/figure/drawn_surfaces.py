"""Surfaces and contacts of the general layout (derive.publishing.figure.parts): planes and inclines, circular
tracks, where a body touches them, the angle to them and the contact regime in words.
"""
from __future__ import annotations

import math

import sympy as sp

from derive.publishing.figure.canvas import _add, _f, _pt, _unit, regime_text
from derive.publishing.figure.drawn_view import BLOCK, Undrawable, _Body
from derive.publishing.figure.vectors import _crossing, _dot, _norm, _scale_vec, _sub
from derive.parts.contact import Contact
from derive.parts.damper import Damper
from derive.parts.spring import Spring
from derive.parts.surfaces import Plane


class SurfaceDrawings:
    """How the general layout draws surfaces and contacts (a mixin of parts._Layout)."""

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
            if surface.carrier is not None:  # its carrier draws it (derive.publishing.figure.drawn_carriers)
                continue
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
        # a body on it; alone on a slope the file gives no length of, room to roll a few times its size
        # (at most 2.4 cm, so that the figure stays within its width)
        alone = plane.height is None and plane.angle != 0 and len(self.bodies) == 1
        around = max([1.1] + [max(1.3 * e, min(3 * e, 2.4)) if alone else 1.3 * e
                              for e in (self.bodies[c.body].extent for c in on if c.point is None)])
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
            if name == plane.name or not isinstance(other, Plane) or other.carrier is not None:
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


def _wedge(down) -> bool:
    """Whether a plane descending along `down` is drawn as an incline's wedge (else a hatched line):
    to the right or to the left."""
    return 0.5 < abs(90 - math.degrees(math.atan2(-down[1], down[0]))) < 89.5
