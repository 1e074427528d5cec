"""Cords, springs and dashpots of the general layout (derive.publishing.figure.parts): a cord's runs and the
arcs where it wraps, its ends; a spring's zigzag and a dashpot from one point exactly to the other.
"""
from __future__ import annotations

import math

import sympy as sp

from derive.publishing.figure.canvas import _add, _f, _pt, _unit
from derive.publishing.figure.drawn_view import ARROW
from derive.publishing.figure.vectors import _degrees, _norm, _perp, _scale_vec, _sub
from derive.parts.cord import Cord
from derive.parts.damper import Damper
from derive.parts.spring import Spring


class CordDrawings:
    """How the general layout draws cords, springs and dashpots (a mixin of parts._Layout)."""

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
