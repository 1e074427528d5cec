"""Energy conservation: the speed a body reaches after its center drops a height.

An independent route to the dynamics: only T and V are used. The constraints of the
body's connected component are solved for all but one coordinate (at position level for
V, at velocity level for T), so that T = k v^2 in the body's speed v and V changes
linearly with the body's height; then T_final = -Delta V gives v = sqrt(-Delta V / k).
Constraints that do no work (rolling without slipping, frictionless contacts, pivots,
cords) are what make this valid: the scenes here have no others.

>>> import sympy as sp
>>> from derive.scene import Body, Contact, Gravity, Incline, Scene
>>> M, R, g, H, a = sp.symbols("M R g H alpha", positive=True)
>>> scene = Scene({"hoop": Body("hoop", "ring", M, {"radius": R})},
...               (Contact("c", "hoop", "ramp", True),), Gravity(g), {"ramp": Incline("ramp", a, H)})
>>> speed_after_drop(scene, "hoop", H).speed
sqrt(H*g)
"""
from __future__ import annotations

from dataclasses import dataclass

import sympy as sp

from derive.mechanics import joints
from derive.mechanics.derivation import Step, root, tidy
from derive.mechanics.kinematics import Coordinates
from derive.mechanics.lagrange import energies
from derive.scene import Scene


class ConservationError(ValueError):
    """Energy conservation does not fix the asked speed in this scene."""


@dataclass(frozen=True)
class EnergyBalance:
    speed: sp.Expr
    kinetic_per_speed_squared: sp.Expr
    potential_drop: sp.Expr
    steps: tuple[Step, ...]


def speed_after_drop(scene: Scene, body: str, drop: sp.Expr) -> EnergyBalance:
    """Speed of `body`'s center, starting from rest, after its center falls `drop`."""
    component = scene.component(body)
    coords = Coordinates(component)
    kinetic, potential = energies(component, coords)
    try:
        dependent = joints.solve_gaps(component, coords)
    except ValueError as error:
        raise ConservationError(str(error)) from None
    free = [c for c in coords.all if c.q not in dependent]
    if len(free) != 1:
        raise ConservationError(f"energy alone fixes one unknown speed; {body}'s system has {len(free)} freedoms")
    (coordinate,) = free
    # Velocities of the dependent coordinates follow by differentiating their solutions.
    velocity = {c.u: coords.ddt(dependent[c.q]) for c in coords.all if c.q in dependent}
    kinetic_free = sp.expand(kinetic.xreplace(velocity).xreplace(dependent))
    vx, vy = coords.of(body, "x").u, coords.of(body, "y").u
    speed_squared = sp.expand((vx**2 + vy**2).xreplace(velocity).xreplace(dependent))
    k = tidy(kinetic_free / speed_squared)
    height = coords.of(body, "y").q
    potential_free = potential.xreplace(dependent)
    height_free = height.xreplace(dependent)
    rate = tidy(sp.diff(potential_free, coordinate.q) / sp.diff(height_free, coordinate.q))
    if k.free_symbols & coords.state or rate.free_symbols & coords.state:
        raise ConservationError("the kinetic or potential energy is not linear in the body's motion")
    potential_change = -rate * drop
    speed = root(-potential_change / k)
    v = sp.Symbol("v")
    steps = (
        Step("Kinetic and potential energy", (sp.Eq(sp.Symbol("T"), kinetic), sp.Eq(sp.Symbol("V"), potential))),
        Step("With the constraints, in the speed v of the center", (sp.Eq(sp.Symbol("T"), k * v**2),)),
        Step(f"Energy conservation from rest as the center drops {sp.sstr(drop)}",
             (sp.Eq(k * v**2, -potential_change), sp.Eq(v, speed))),
    )
    return EnergyBalance(speed, k, -potential_change, steps)
