"""Lagrange's method with multipliers, in the planar coordinates of every body.

L = T - V with T = sum(1/2 m v_cm^2 + 1/2 I_cm omega^2) and V = sum(m g y); each
constraint g(q) = 0 enters with a multiplier that is the force it names (see
`derive.mechanics.joints`), and is also imposed at acceleration level, d^2 g/dt^2 = 0.

>>> import sympy as sp
>>> from derive.scene import Body, Gravity, Scene
>>> m, g = sp.symbols("m g", positive=True)
>>> d = derive(Scene({"ball": Body("ball", "point", m, {})}, gravity=Gravity(g)))
>>> d.solution[sp.Symbol("yddot_ball", real=True)]
-g
"""
from __future__ import annotations

import sympy as sp

from derive.mechanics import joints
from derive.mechanics.derivation import Derivation, Step, solve_linear
from derive.mechanics.kinematics import Coordinates
from derive.scene import Scene


def energies(scene: Scene, coords: Coordinates) -> tuple[sp.Expr, sp.Expr]:
    """Kinetic and potential energy of the scene, in the coordinate symbols."""
    kinetic = sp.Integer(0)
    potential = sp.Integer(0)
    for body in scene.bodies.values():
        vx, vy = coords.of(body.name, "x").u, coords.of(body.name, "y").u
        kinetic += body.mass * (vx**2 + vy**2) / 2
        if body.rotates:
            kinetic += body.inertia * coords.angular_velocity(body.name) ** 2 / 2
        if scene.gravity is not None:
            potential += body.mass * scene.gravity.g * coords.of(body.name, "y").q
    return kinetic, potential


def generalized_forces(scene: Scene, coords: Coordinates) -> dict[sp.Symbol, sp.Expr]:
    """Q_j = sum F . dv_P/du_j over the non-conservative applied forces (virtual work)."""
    result = {c.q: sp.Integer(0) for c in coords.all}
    for pull in scene.pulls:
        velocity = coords.material_velocity(pull.body, pull.offset)
        for c in coords.all:
            result[c.q] += (pull.force * pull.direction).dot(velocity.diff(c.u))
    return result


def derive(scene: Scene, coords: Coordinates | None = None) -> Derivation:
    """Euler–Lagrange equations with multipliers, solved for accelerations and forces."""
    coords = coords or Coordinates(scene)
    kinetic, potential = energies(scene, coords)
    lagrangian = kinetic - potential
    pairs = [
        (gap, force)
        for c in scene.constraints
        for gap, force in zip(joints.gaps(c, coords), joints.forces(c).values())
    ]
    applied = generalized_forces(scene, coords)
    equations = []
    for c in coords.all:
        lhs = coords.ddt(sp.diff(lagrangian, c.u)) - sp.diff(lagrangian, c.q)
        rhs = applied[c.q] + sum((force * sp.diff(gap, c.q) for gap, force in pairs), sp.Integer(0))
        equations.append(sp.Eq(sp.expand(lhs), sp.expand(rhs)))
    constraint_accelerations = [sp.Eq(sp.expand(coords.ddt(coords.ddt(gap))), 0) for gap, _ in pairs]
    unknowns = coords.accelerations + [force for _, force in pairs]
    solution = solve_linear(equations + constraint_accelerations, unknowns)
    steps = [
        Step("Kinetic and potential energy", (sp.Eq(sp.Symbol("T"), kinetic), sp.Eq(sp.Symbol("V"), potential))),
        Step("The Lagrangian", (sp.Eq(sp.Symbol("L"), lagrangian),)),
    ]
    if pairs:
        steps.append(
            Step(
                "Constraints g = 0, each with a multiplier equal to the force it exerts",
                tuple(sp.Eq(gap, 0) for gap, _ in pairs),
            )
        )
    steps += [
        Step("Euler–Lagrange equations, d/dt(dL/dq') - dL/dq = Q + sum of multiplier times dg/dq", tuple(equations)),
        Step("Constraints at acceleration level", tuple(constraint_accelerations)),
    ]
    return Derivation("lagrange", equations, unknowns, solution, steps)
