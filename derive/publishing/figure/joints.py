"""Bodies on pivots and axles: a pendulum, bodies sharing an axle, wound strings to their loads."""
from __future__ import annotations

import math

from derive.publishing.figure.canvas import _add, _f, _Figure, _label_mass, _pt, _unit
from derive.parts.cord import Cord
from derive.parts.pin import Pin
from derive.model.scene import Body


def _pinned(fig: _Figure) -> None:
    """Bodies on fixed axles or pivots: a pendulum hangs from its pivot (displaced a little, its
    angle to the vertical marked), a body stands on a pivot, bodies share an axle; wound strings
    run from the rim to their hanging loads, with tension and gravity."""
    scene = fig.scene
    pins = [c for c in scene.constraints if isinstance(c, Pin)]
    axles = [p for p in pins if all(fig.num(o, 1) == 0 for o in p.offset)]
    pivots = [p for p in pins if p not in axles]
    x = 0.0
    for pin in pivots:
        _pendulum(fig, scene.bodies[pin.body], pin, (x, 0.0))
        x += 3.0
    if axles:
        _axles(fig, [scene.bodies[p.body] for p in axles], (x, 0.0))


def _pendulum(fig: _Figure, body: Body, pin: Pin, at) -> None:
    offset = fig.num(pin.offset[1], 1)
    hanging = offset > 0
    swing = math.radians(22 if hanging else 12)
    length = 2.0
    axis = (math.sin(swing), -math.cos(swing) if hanging else math.cos(swing))
    cm = _add(at, axis, length)
    angle = math.degrees(math.atan2(axis[1], axis[0]))
    if "radius" in body.sizes or body.shape != "custom":
        fig.body(body, cm, 0.7, angle)
    else:
        blob = _pt(_add(cm, axis, -0.45))  # a body of no particular shape, reaching to its pivot
        fig.add(f"\\draw[body, rotate around={{{_f(angle)}:{blob}}}] {blob} ellipse (1.6 and 0.55);")
    fig.support(at, hanging)
    fig.add(f"\\draw[axis] {_pt(at)} -- {_pt(_add(at, (0, -2.5 if hanging else 2.5)))};")
    fig.line(at, cm, "thin")
    fig.dot(cm, 0.06)
    away = (math.cos(swing), math.sin(swing) * (1 if hanging else -1))  # the side away from the vertical
    fig.label(_add(_add(at, axis, length * (0.5 if hanging else 0.3)), away, 0.05), away,
              fig.m(abs(pin.offset[1])))
    amplitude = next((a.amplitude for a in fig.problem.asks.values() if a.amplitude is not None), None)
    vertical = -90 if hanging else 90
    fig.arc(at, 1.1, min(vertical, angle), max(vertical, angle), fig.tex(amplitude) if amplitude else None,
            label_radius=1.15)
    if fig.scene.gravity is not None:
        fig.gravity_arrow(cm, body, toward=(1, 0))


def _axles(fig: _Figure, bodies: list[Body], at) -> None:
    """Bodies on one fixed axle (concentric, the larger moment outside), strings and internal turns."""
    scene = fig.scene
    ordered = sorted(bodies, key=lambda b: -fig.num(b.inertia, 1.0))
    radii = [1.1] if len(ordered) == 1 else [1.6 - 1.0 * k / (len(ordered) - 1) for k in range(len(ordered))]
    aspect = 1.0 if len(ordered) == 1 else 0.7  # bodies without a radius drawn as ovals
    for k, body in enumerate(ordered):
        if body.shape == "custom" and "radius" not in body.sizes:
            fig.body(body, at, radii[k], aspect=aspect)
        else:
            fig.body(body, at, radii[k])
    for k, body in enumerate(ordered):  # each moment of inertia inside its own ring
        if len(ordered) > 1 and fig.tex(body.inertia):
            where = (-(radii[k] + radii[k + 1]) / 2, 0) if k + 1 < len(radii) else (-radii[k] * 0.55, 0)
            fig.label(_add(at, where), (0, 0), fig.m(body.inertia))
    fig.axle(at)
    reel, r = ordered[0], radii[0]
    for turn in (s.event for s in scene.states.values() if s.event and s.event.kind == "turn"):
        k = next((i for i, b in enumerate(ordered) if b.name == turn.body), 0)
        fig.spin(at, radii[k] * aspect * 0.75, 1, fig.tex(turn.angle), at=-90)
    strings = [c for c in scene.constraints if isinstance(c, Cord) and c.path[0].kind == "wound"
               and c.path[-1].kind == "point" and len(c.path) == 2]
    for cord in strings:
        _string(fig, cord, at, r)
    if fig.tex(reel.sizes.get("radius")):
        angle = 135 if strings and -strings[0].path[0].turn > 0 else 45
        fig.line(at, _add(at, _unit(angle), r), "thin")
        fig.label(_add(at, _unit(angle), r * 0.55), _unit(angle + 90), fig.m(reel.sizes['radius']))
    if len(ordered) == 1:
        _label_mass(fig, reel, _add(at, (0.12, -0.12)), (1, -1))
    if scene.gravity is not None and not strings:
        fig.gravity_arrow(at, reel)


def _string(fig: _Figure, cord: Cord, center, radius: float) -> None:
    """The cord from the rim (tangent, vertical) down to its load, with tension and gravity."""
    scene = fig.scene
    side = -cord.path[0].turn  # wound clockwise: it leaves the rim on the right
    top = _add(center, (side * radius, 0))
    load = scene.bodies[cord.path[-1].body]
    half = 0.3
    block = _add(top, (0, -2.4))
    fig.line(top, _add(block, (0, half)), "thick")
    fig.body(load, block, half, block=load.shape == "point")
    _label_mass(fig, load, _add(block, (side * (half + 0.05), 0)), (side, 0))
    tension = fig.ask_symbol("force", cord.name, "tension") or "T"
    fig.arrow(_add(block, (0, half)), (0, 0.8), "force", f"${tension}$", toward=(side, 0))
    if scene.gravity is not None:
        fig.gravity_arrow(_add(block, (0, -half)), load, 0.8)
