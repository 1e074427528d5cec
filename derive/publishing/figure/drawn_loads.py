"""Loads of the general layout (derive.publishing.figure.parts): forces, torques, gravity and given velocities,
as arrows.
"""
from __future__ import annotations

import math

import sympy as sp

from derive.publishing.figure.canvas import _add, _f, _pt, _unit
from derive.publishing.figure.drawn_view import ARROW, BALL
from derive.publishing.figure.vectors import _degrees, _dot, _norm, _sub
from derive.parts.force import Force
from derive.parts.torque import Torque


class LoadDrawings:
    """How the general layout draws loads (a mixin of parts._Layout)."""

    def _force(self, force: Force) -> None:
        view, fig = self.view, self.fig
        drawn = self.bodies[force.body]
        point = view.at(view.world(force.body, force.offset))
        magnitude, angle = force.magnitude, force.angle
        if magnitude.could_extract_minus_sign():
            magnitude, angle = -magnitude, angle + sp.pi
        direction = _norm((view.value(sp.cos(angle)), view.value(sp.sin(angle))))
        if drawn.kind == "solid":  # from its outline, on its line of action (derive.publishing.figure.drawn_carriers)
            point = _add(point, direction, drawn.reach(point, direction))
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
