"""Which layout a scene gets: the first in the table that applies draws the figure.

The schematic layouts (an incline, a level floor, a loop, a pendulum, bodies on one axle, a
collision, a bounce off a fixed surface) apply only to the scenes whose every part they draw; any other scene of parts gets the
general layout (`derive.publishing.figure.parts`), which draws each part where the scene puts it.
"""
from __future__ import annotations

import sympy as sp

from derive.publishing.figure.bodies import _placed
from derive.publishing.figure.bounces import _bounce, bounces
from derive.publishing.figure.collisions import _impact, struck
from derive.publishing.figure.inertia import _specimens
from derive.publishing.figure.joints import _pinned
from derive.publishing.figure.orbits import _orbit
from derive.publishing.figure.parts import _parts
from derive.publishing.figure.paths import _paths
from derive.publishing.figure.surfaces import _on_surface
from derive.publishing.figure.solids import _bearings, _free_rotation, _pivot_point, _rolls_on_edge
from derive.publishing.figure.systems import _internal, _wave, _wheel
from derive.parts.contact import Contact
from derive.parts.cord import Cord
from derive.parts.pin import Pin
from derive.parts.surfaces import Circle, Plane


def _on_one_surface(problem) -> bool:
    """Bodies on one incline, level floor or loop (released on a ramp into it), nothing else but
    gravity and, on a level floor, cords wound on them and pulled: what `_on_surface` draws."""
    scene = problem.scene
    contacts = [c for c in scene.constraints if isinstance(c, Contact)]
    if not contacts or len(contacts) != len(scene.constraints) or len({c.surface for c in contacts}) != 1:
        return False
    if {c.body for c in contacts} != set(scene.bodies):
        return False
    surface = scene.surfaces[contacts[0].surface]
    if isinstance(surface, Circle):  # the loop-the-loop schematic: a body released on a ramp into a loop
        return surface.side == "inside" and not scene.loads and all(
            a.quantity.kind == "contact" and a.quantity.detail == "min_release_height" for a in problem.asks.values())
    if isinstance(surface, Plane) and surface.descends == "left":  # the schematic's incline goes down to the right
        return False
    level = isinstance(surface, Plane) and surface.angle == 0
    for load in scene.loads:
        pulled = isinstance(load, Cord) and len(load.path) == 2 and load.path[0].kind == "wound" \
            and load.path[-1].kind == "pulled" and load.path[0].body in scene.bodies
        if not (pulled and level):
            return False
    return True


def _collision(problem) -> bool:
    """A body struck by another on its line of motion, the struck one free or on an axle at its center."""
    scene = problem.scene
    event = struck(scene)
    if event is None or scene.loads:
        return False
    return all(isinstance(c, Pin) and c.body == event.to and c.to is None and all(o == 0 for o in c.offset)
               for c in scene.constraints)


def _on_pivots(problem) -> bool:
    """One body hanging from or standing on a pivot straight above or below its center, or bodies
    on one fixed axle with cords wound on them straight down to point masses: what `_pinned` draws."""
    scene = problem.scene
    pins = [c for c in scene.constraints if isinstance(c, Pin)]
    cords = [c for c in scene.constraints if isinstance(c, Cord)]
    if not pins or len(pins) + len(cords) != len(scene.constraints) or scene.loads:
        return False
    if any(p.to is not None for p in pins):
        return False
    axles = [p for p in pins if all(o == 0 for o in p.offset)]
    pivots = [p for p in pins if p not in axles]
    if pivots:
        pin = pivots[0]
        return len(pins) == 1 and not cords and pin.offset[0] == 0 and scene.bodies[pin.body].angle == 0 \
            and len(scene.bodies) == 1
    if len({scene.bodies[p.body].at for p in axles}) != 1:
        return False
    on_axle = {p.body for p in axles}
    hanging = set()
    for cord in cords:
        reel, load = cord.path[0], cord.path[-1]
        if len(cord.path) != 2 or reel.kind != "wound" or reel.body not in on_axle or load.kind != "point" \
                or load.body is None or scene.bodies[load.body].shape != "point" or any(load.offset):
            return False
        if reel.radius != scene.bodies[reel.body].sizes.get("radius") or not _straight_down(scene, reel, load):
            return False
        hanging.add(load.body)
    return on_axle | hanging == set(scene.bodies)


def _straight_down(scene, reel, load) -> bool:
    """The run from the reel's rim to the load is vertical, downward, in the reference configuration."""
    below = sp.Matrix(scene.bodies[load.body].at) - sp.Matrix(scene.bodies[reel.body].at)
    return sp.simplify(below[0] - reel.radius * -reel.turn) == 0 and bool(sp.simplify(below[1]).is_negative)


def _has_parts(problem) -> bool:
    return bool(problem.scene.constraints or problem.scene.loads)


#: (applies to the problem, draws the figure), the first that applies wins.
_LAYOUTS = (
    (lambda p: any(point.centered for point in p.scene.pivot_points.values()), _wheel),
    (lambda p: bool(p.scene.pivot_points), _pivot_point),
    (lambda p: bool(p.scene.rolls_on_edge), _rolls_on_edge),
    (lambda p: p.scene.wave is not None, _wave),
    (lambda p: p.scene.orbit is not None, _orbit),
    (lambda p: p.scene.internal_forces is not None, _internal),
    (lambda p: bool(p.scene.bearings), _bearings),
    (lambda p: bool(p.scene.free_rotations), _free_rotation),
    (lambda p: any(b.path is not None for b in p.scene.bodies.values()), _paths),
    (lambda p: any(b.composite is not None for b in p.scene.bodies.values()), _parts),  # drawn part by part
    (_on_one_surface, _on_surface),
    (_collision, _impact),
    (_on_pivots, _pinned),
    (_has_parts, _parts),
    (bounces, _bounce),
    (lambda p: bool(p.scene.motions) and all(n in p.scene.motions for n in p.scene.bodies), _placed),
    (lambda p: bool(p.scene.bodies), _specimens),
)
