"""Free flight: bodies that nothing holds (no joint, cord or contact; gravity and forces fixed in
size and direction) move at constant accelerations, q = q0 + u0 t + a t^2/2, a ball after it
bounces off a floor or a wedge. The motion is not a straight line in the coordinates (the
projectile's parabola), but a coordinate with no acceleration that moves (its x) is a clock:
t = (s - s0)/s'0, and every other coordinate is a polynomial in s. derive.mechanics.states
follows the motion along that coordinate (the work-energy theorem gives its rates, and
Newton–Euler's motion integrated checks the state at every solve).

>>> import sympy as sp
>>> from derive.mechanics import lagrange
>>> from derive.model.kinematics import Coordinates
>>> from derive.parts.gravity import Gravity
>>> from derive.model.scene import Body, Scene
>>> m, g, v = sp.symbols("m g v", positive=True)
>>> scene = Scene({"ball": Body("ball", "point", m, {})}, gravity=Gravity(g))
>>> coords = Coordinates(scene)
>>> x, y = coords.of("ball", "x"), coords.of("ball", "y")
>>> thrown = {x.q: 0, y.q: 0, x.u: v, y.u: v}
>>> coordinate, positions, step = flight(scene, coords, thrown, lagrange.derive(scene, coords))
>>> coordinate.q, positions[y.q]
(x_ball, x_ball*(-g*x_ball + 2*v**2)/(2*v**2))
"""
from __future__ import annotations

import sympy as sp

from derive.mechanics.derivation import Derivation
from derive.text.steps import Step
from derive.core.tidying import tidy
from derive.model.kinematics import Coordinate, Coordinates
from derive.core.expr import TIME
from derive.model.scene import Scene


def flight(scene: Scene, coords: Coordinates, start: dict, derivation: Derivation
           ) -> tuple[Coordinate, dict[sp.Symbol, sp.Expr], Step] | None:
    """The motion from `start` (every coordinate and rate) of a scene in free flight: the
    coordinate that carries it (no acceleration, a rate at the start: an x before an angle), every
    coordinate as a function of it, and the step that says so. None where a part holds a body,
    an acceleration is not constant (a spring, a force given in t), or no coordinate moves at a
    constant rate (a body thrown straight up moves on a line, derive.mechanics.states)."""
    if scene.constraints or not all(body.rotates is False or "radius" in body.sizes for body in scene.bodies.values()) \
            and scene.surfaces:  # a flying rod's clearance of a surface is not modelled
        return None
    solved = derivation.solution.raw
    accelerations = {c: tidy(solved[c.a]) for c in coords.all}
    if any(a.has(TIME, *coords.state) for a in accelerations.values()):
        return None
    clocks = [c for c in coords.all if accelerations[c] == 0 and tidy(start[c.u]) != 0]
    if not clocks:
        return None
    clock = min(clocks, key=lambda c: c.kind == "theta")
    time = (clock.q - start[clock.q]) / start[clock.u]
    positions = {c.q: clock.q if c == clock else
                 tidy(start[c.q] + start[c.u] * time + accelerations[c] * time**2 / 2) for c in coords.all}
    t = sp.Symbol("t")
    step = Step(f"Nothing holds the bodies: each coordinate moves at a constant acceleration, and {clock.q}, "
                f"with none, at a constant rate, so the time since the start is t = ({clock.q} - {clock.q}_0)/"
                f"{clock.u}_0; every coordinate in it",
                tuple(sp.Eq(c.q, tidy(start[c.q] + start[c.u] * t + accelerations[c] * t**2 / 2)) for c in coords.all)
                + tuple(sp.Eq(q, p) for q, p in positions.items() if q != clock.q))
    return clock, positions, step


def clearances(scene: Scene, coords: Coordinates) -> list[tuple[sp.Expr, str]]:
    """How far each flying body (a point mass, or a round body by its rim) stands off each surface
    of the scene, in the coordinates, and what it means where that is negative: nothing holds it
    there, so a flight that would pass through a floor or a wedge's face is not the motion."""
    return [(surface.gap(coords.position(body.name), body.sizes.get("radius", sp.Integer(0))),
             f"the {body.name} would pass through {surface.name} on its flight to the state (nothing holds it off it "
             "in free flight)")
            for body in scene.bodies.values() for surface in scene.surfaces.values()]
