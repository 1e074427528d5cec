"""Newton–Euler: force balance on every body, torque balance about each center of mass.

m a_cm = sum F and I_cm alpha = sum (r x F)_z, with the constraint forces as unknowns
(from `derive.mechanics.joints`) and the constraints' velocity conditions differentiated
once to relate the accelerations.

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


def simplest(expr: sp.Expr) -> sp.Expr:
    """Expanded, with sin^2 + cos^2 folded where the directions of surfaces put it."""
    expr = sp.expand(expr)
    return sp.expand(sp.trigsimp(expr)) if expr.has(sp.sin, sp.cos) else expr


def all_forces(scene: Scene, coords: Coordinates) -> list[joints.AppliedForce]:
    """Gravity at every center of mass, and every constraint force."""
    result = []
    if scene.gravity is not None:
        for body in scene.bodies.values():
            weight = sp.Matrix([0, -body.mass * scene.gravity.g])
            result.append(joints.AppliedForce(body.name, sp.zeros(2, 1), weight, "weight"))
    for c in scene.constraints:
        result += joints.applied_forces(c, coords)
    for pull in scene.pulls:
        result.append(joints.AppliedForce(pull.body, pull.offset, pull.force * pull.direction, f"pull of {pull.name}"))
    return result


def derive(scene: Scene, coords: Coordinates | None = None) -> Derivation:
    """Force and torque balances with the kinematic constraints, solved."""
    coords = coords or Coordinates(scene)
    loads = all_forces(scene, coords)
    steps = []
    equations = []
    for body in scene.bodies.values():
        on_body = [f for f in loads if f.body == body.name]
        total = sum((f.force for f in on_body), sp.zeros(2, 1))
        balances = [
            sp.Eq(body.mass * coords.of(body.name, "x").a, total[0]),
            sp.Eq(body.mass * coords.of(body.name, "y").a, total[1]),
        ]
        if body.rotates:
            torque = sum((f.offset[0] * f.force[1] - f.offset[1] * f.force[0] for f in on_body), sp.Integer(0))
            balances.append(sp.Eq(body.inertia * coords.of(body.name, "theta").a, torque))
        balances = [sp.Eq(e.lhs, simplest(e.rhs)) for e in balances]
        equations += balances
        steps.append(Step(f"Forces and torques on the {body.name} ({', '.join(sorted({f.label for f in on_body})) or 'none'})", tuple(balances)))
    conditions = [v for c in scene.constraints for v in joints.velocity_conditions(c, coords)]
    kinematic = [sp.Eq(simplest(coords.ddt(v)), 0) for v in conditions]
    equations += kinematic
    if conditions:
        steps.append(Step("Kinematic constraints (velocities, then accelerations)", tuple(sp.Eq(v, 0) for v in conditions) + tuple(kinematic)))
    unknowns = coords.accelerations + [f for c in scene.constraints for f in joints.forces(c).values()]
    solution = solve_linear(equations, unknowns)
    return Derivation("newton_euler", equations, unknowns, solution, steps)
