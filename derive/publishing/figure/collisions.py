"""A collision: the struck body, the incoming one on its line with its velocity, the impact parameter."""
from __future__ import annotations

import math

import sympy as sp

from derive.publishing.figure.canvas import _add, _f, _Figure, _label_mass, _pt, _unit, given_motion
from derive.parts.pin import Pin
from derive.model.scene import Event


def struck(scene) -> Event | None:
    """The scene's first impact (a stick or a bounce, a state's `event:`) in a state given by
    rates, where the striking body moves, on another body (not a surface): what a collision figure
    draws; None for none."""
    return next((s.event for s in scene.states.values() if s.event and s.event.kind in ("stick", "bounce")
                 and s.event.to in scene.bodies
                 and scene.states[s.start].rates and given_motion(scene, s.event.body) is not None), None)


def _impact(fig: _Figure) -> None:
    """A collision: the struck body at the origin, the incoming body on its line of motion with its
    velocity, and the impact parameter (the line's distance from the struck body's center)."""
    scene = fig.scene
    event = struck(scene)
    target_name = event.to
    target, mover = scene.bodies[target_name], scene.bodies[event.body]
    motion = given_motion(scene, event.body)
    x, y = (p - o for p, o in zip(motion.position, target.at))  # from the struck body's center
    # the drawing scale: the struck body (or the farthest contact point) is about 1.3 cm
    position = [fig.num(x, 0), fig.num(y, 0)]
    reach = max(math.hypot(*position), fig.size(target, "radius", 0), fig.size(target, "length", 0) / 2, 1e-9)
    scale = (2.4 if target.shape == "rod" else 1.3) / reach
    size = target.sizes.get("radius") or (target.sizes.get("length", 0) / 2)
    drawn = fig.num(size, 0) * scale or 1.3
    pin = next((c for c in scene.constraints if isinstance(c, Pin) and c.body == target_name), None)
    tilt = math.degrees(fig.num(target.angle, 0))  # a rod lies at its angle
    end = _add((0, 0), _unit(tilt), drawn)
    if target.shape == "custom" and "radius" not in target.sizes:
        fig.add(f"\\draw[body] (0,0) circle ({_f(drawn)}); \\fill (0,0) circle (0.04);")
    else:
        fig.body(target, (0, 0), drawn, angle=tilt)
    if target.shape == "rod" and fig.tex(target.sizes.get("length")):
        fig.dimension((-end[0], -end[1]), end, fig.tex(target.sizes["length"]), side=-1, gap=0.3)
    if pin is not None:
        fig.axle((0, 0))
    spin = given_motion(scene, target_name)
    if spin is not None and spin.spin != 0:
        sign = 1 if fig.num(spin.spin, 1) > 0 else -1
        fig.spin((0, 0), drawn + 0.25, sign, fig.tex(sp.Abs(spin.spin)), at=135)
    if target.shape == "rod":
        _label_mass(fig, target, _add((-end[0], -end[1]), _unit(tilt + 90), 0.12), (1, 1))
    else:
        _label_mass(fig, target, (-0.15, -0.15), (-1, -1))
    v = (fig.num(motion.velocity[0], 1), fig.num(motion.velocity[1], 0))
    speed = math.hypot(*v) or 1.0
    along = (v[0] / speed, v[1] / speed)
    hit = (position[0] * scale, position[1] * scale)
    back = 1.4 if target.shape == "rod" else 1.9
    incoming = _add(hit, along, -back)
    fig.line(incoming, hit, "dashed, gray")
    rim = max(fig.num(mover.sizes.get("radius", 0), 0) * scale, 0.09)  # a round body to scale, a point a dot
    if mover.rotates:
        fig.body(mover, incoming, rim)
    else:
        fig.dot(incoming, rim)
    left = (-along[1], along[0])
    _label_mass(fig, mover, _add(incoming, left, -rim - 0.03), (along[1], -along[0]))
    fig.arrow(_add(incoming, along, rim + 0.06), (0.85 * along[0], 0.85 * along[1]), "velocity",
              fig.m(sp.sqrt(motion.velocity[0] ** 2 + motion.velocity[1] ** 2)), toward=left)
    fig.add(f"\\fill[red!70!black] {_pt(hit)} circle (0.04);")
    distance = sp.simplify(abs(x * motion.velocity[1] - y * motion.velocity[0])
                           / sp.sqrt(motion.velocity[0] ** 2 + motion.velocity[1] ** 2))
    foot_length = hit[0] * (-along[1]) + hit[1] * along[0]
    foot = (-along[1] * foot_length, along[0] * foot_length)
    if abs(foot_length) > 0.05:
        side = 1 if (foot[0] * along[1] - foot[1] * along[0]) < 0 else -1
        fig.dimension((0, 0), foot, fig.tex(distance), side=side * (1 if target.shape == "rod" else -1),
                      gap=0.2 if target.shape == "rod" else drawn + 0.35)
