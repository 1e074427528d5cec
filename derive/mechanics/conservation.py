"""Energy conservation: the speed a body reaches after its center drops a height.

An independent route to the dynamics: only T and V are used. The constraints of the
body's connected component are solved for all but one coordinate (at position level for
V, at velocity level for T), so that T = k v^2 in the body's speed v and V changes
linearly with the body's height; then T_final = -Delta V gives v = sqrt(-Delta V / k).
Constraints that do no work (rolling without slipping, frictionless contacts, pivots,
cords) are what make this valid: the scenes here have no others.

>>> import sympy as sp
>>> from derive.parts.contact import Contact
>>> from derive.parts.gravity import Gravity
>>> from derive.parts.surfaces import Plane
>>> from derive.model.scene import Body, Scene
>>> M, R, g, H, a = sp.symbols("M R g H alpha", positive=True)
>>> scene = Scene({"hoop": Body("hoop", "ring", M, {"radius": R})},
...               (Contact("c", "hoop", "ramp", True),), Gravity(g), {"ramp": Plane("ramp", a, H)})
>>> speed_after_drop(scene, "hoop", H).speed
sqrt(H*g)
"""
from __future__ import annotations

from dataclasses import dataclass

import sympy as sp

from derive.mechanics.derivation import KINETIC, POTENTIAL
from derive.text.steps import Step
from derive.core.tidying import root, tidy
from derive.model.kinematics import Coordinates, solve_gaps
from derive.mechanics.lagrange import energies, nonconservative_power
from derive.model.scene import Scene


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
    idle = _idle(component, coords, kinetic, potential)
    k = _kinetic_per_speed_squared(component, coords, body, kinetic.xreplace(idle), idle)
    potential_change = _potential_change(component, coords, body, potential, drop)
    speed = root(-potential_change / k)
    v = sp.Symbol("v")
    steps = (
        Step("Kinetic and potential energy", (sp.Eq(KINETIC, kinetic), sp.Eq(POTENTIAL, potential))),
        Step("With the constraints, in the speed v of the center", (sp.Eq(KINETIC, k * v**2),)),
        Step(f"Energy conservation from rest as the center drops {sp.sstr(drop)}",
             (sp.Eq(k * v**2, -potential_change), sp.Eq(v, speed))),
    )
    return EnergyBalance(speed, k, -potential_change, steps)


def _rates(scene: Scene, coords: Coordinates) -> list[sp.Expr]:
    """The constraints at velocity level, dg/dt = 0."""
    return [coords.ddt(gap) for c in scene.constraints for gap in c.gaps(coords)]


def _idle(scene: Scene, coords: Coordinates, kinetic: sp.Expr, potential: sp.Expr) -> dict[sp.Symbol, sp.Expr]:
    """Velocities that no constraint ties, no potential or other force drives and T does not couple
    to another (the spin of a ball sliding without friction): each one's momentum dT/du is c u and
    conserved, so from rest it stays zero.

    >>> from derive.model.scene import Body, Scene
    >>> M, R = sp.symbols("M R", positive=True)
    >>> scene = Scene({"ball": Body("ball", "sphere", M, {"radius": R})}, ())
    >>> coords = Coordinates(scene)
    >>> sorted(map(str, _idle(scene, coords, *energies(scene, coords))))
    ['thetadot_ball', 'xdot_ball', 'ydot_ball']
    """
    tied = set().union(*(rate.free_symbols for rate in _rates(scene, coords)))
    power = nonconservative_power(scene, coords)
    return {c.u: sp.Integer(0) for c in coords.all
            if c.u not in tied and not potential.has(c.q) and not power.has(c.u)
            and all(sp.diff(kinetic, c.u, other.u) == 0 for other in coords.all if other is not c)}


def _kinetic_per_speed_squared(scene: Scene, coords: Coordinates, body: str, kinetic: sp.Expr,
                               idle: dict[sp.Symbol, sp.Expr]) -> sp.Expr:
    """T / v^2, with every velocity expressed through the body's by the constraints dg/dt = 0
    (the idle ones at zero)."""
    rates = [rate.xreplace(idle) for rate in _rates(scene, coords)]
    velocities = [c.u for c in coords.all if c.u not in idle]
    if len(velocities) - len(rates) != 1:
        raise ConservationError(f"energy alone fixes one unknown speed; {body}'s system has "
                                f"{len(velocities) - len(rates)} freedoms")
    vx, vy = coords.of(body, "x").u, coords.of(body, "y").u
    for free in (u for u in (vx, vy) if u not in idle):
        others = [u for u in velocities if u != free]
        matrix, rhs = sp.linear_eq_to_matrix(rates, others)
        if not matrix.det().equals(0):
            solved = dict(zip(others, matrix.LUsolve(rhs)))
            break
    else:
        raise ConservationError(f"the constraints do not fix the motion through {body}'s velocity")
    # On the constraints (every gap vanishes in the reference configuration, q = 0): off them a
    # curved track's expressions carry |p - c| terms that equal its radius only on the track.
    on_track = {c.q: 0 for c in coords.all}
    ratio = tidy((kinetic.xreplace(solved) / (vx**2 + vy**2).xreplace({**idle, **solved})).xreplace(on_track))
    if ratio.free_symbols & coords.state:
        raise ConservationError("the kinetic energy is not proportional to the square of the body's speed")
    return ratio


def _potential_change(scene: Scene, coords: Coordinates, body: str, potential: sp.Expr, drop: sp.Expr) -> sp.Expr:
    """V after minus V before when the body's center falls `drop`."""
    if len(scene.bodies) == 1:
        return -scene.bodies[body].mass * scene.gravity.g * drop
    # Several bodies: the constraints, solved at position level, fix how the others move.
    try:
        dependent = solve_gaps(scene, coords)
    except ValueError as error:
        raise ConservationError(str(error)) from None
    (coordinate,) = [c for c in coords.all if c.q not in dependent]
    rate = tidy(sp.diff(potential.xreplace(dependent), coordinate.q)
                / sp.diff(coords.of(body, "y").q.xreplace(dependent), coordinate.q))
    if rate.free_symbols & coords.state:
        raise ConservationError("the potential energy is not linear in the body's height")
    return -rate * drop
