"""Joints of the general layout (derive.publishing.figure.parts): pins and their supports, pegs, sliders, welds,
torsional springs and rotational dampers at their joints.
"""
from __future__ import annotations

import math

import sympy as sp

from derive.publishing.figure.canvas import _add, _f, _pt, _unit
from derive.publishing.figure.vectors import _degrees, _norm, _perp, _scale_vec, _sub
from derive.parts.damper import Damper
from derive.parts.pin import Pin
from derive.parts.slider import Slider
from derive.parts.torsional_spring import TorsionalSpring
from derive.parts.weld import Weld


class JointDrawings:
    """How the general layout draws joints (a mixin of parts._Layout)."""

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
        if drawn.kind == "solid":  # it does not turn: its rail under its base (derive.publishing.figure.drawn_carriers)
            a, b = self._rail_under(drawn, point, along)
        below = _perp(along)
        below = (-below[0], -below[1])
        view.put("supports", f"\\fill[pattern=north east lines] {_pt(_add(a, below, 0.04))} -- {_pt(_add(b, below, 0.04))}"
                             f" -- {_pt(_add(b, below, 0.16))} -- {_pt(_add(a, below, 0.16))} -- cycle; "
                             f"\\draw[thick, gray!70!black] {_pt(a)} -- {_pt(b)};")
        view.ink_line(a, b)
        if drawn.kind in ("point", "solid"):
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


def _weld_mark(point, direction) -> str:
    """The filled triangle of a weld, on the body's side of the joint at `point`."""
    back = (-direction[0], -direction[1])
    across = _perp(direction)
    a, b, c = _add(point, across, 0.12), _add(point, across, -0.12), _add(point, back, 0.16)
    return f"\\fill {_pt(a)} -- {_pt(b)} -- {_pt(c)} -- cycle;"
