"""Newton–Euler: force balance on every body, torque balance about each center of mass.

m a_cm = sum F and I_cm alpha = sum (r x F)_z, with the constraint forces as unknowns
and the loads of every part (`derive.parts`), and the constraints' velocity conditions
differentiated once to relate the accelerations.

>>> import sympy as sp
>>> from derive.parts.gravity import Gravity
>>> from derive.model.scene import Body, Scene
>>> m, g = sp.symbols("m g", positive=True)
>>> d = derive(Scene({"ball": Body("ball", "point", m, {})}, gravity=Gravity(g)))
>>> d.solution[sp.Symbol("yddot_ball", real=True)]
-g
"""
from __future__ import annotations

import dataclasses

import sympy as sp

from derive.parts import AppliedForce, AppliedTorque
from derive.mechanics.derivation import (FIXED_LEFT_OUT, Derivation, at_state, part_sentences, rest_positions, worth_showing)
from derive.text.steps import Step
from derive.core.tidying import simplest
from derive.model.kinematics import Coordinates
from derive.model.scene import Scene


def all_forces(scene: Scene, coords: Coordinates) -> list[AppliedForce | AppliedTorque]:
    """Every force and couple of every part: weights, constraint forces, loads."""
    return [load for part in scene.parts for load in part.loads(coords)]


def derive(scene: Scene, coords: Coordinates | None = None) -> Derivation:
    """Force and torque balances with the kinematic constraints (general: the steps show them in
    the reference configuration, at rest)."""
    coords = coords or Coordinates(scene)
    loads = all_forces(scene, coords)
    equations, balanced = [], []  # balanced: (body, its balances, the labels of its forces)
    for body in scene.bodies.values():
        on_body = [f for f in loads if f.body == body.name]
        forces = [f for f in on_body if isinstance(f, AppliedForce)]
        total = sum((f.force for f in forces), sp.zeros(2, 1))
        balances = [
            sp.Eq(body.mass * coords.of(body.name, "x").a, total[0]),
            sp.Eq(body.mass * coords.of(body.name, "y").a, total[1]),
        ]
        if body.rotates:
            torque = sum((f.offset[0] * f.force[1] - f.offset[1] * f.force[0] for f in forces), sp.Integer(0))
            torque += sum((f.torque for f in on_body if isinstance(f, AppliedTorque)), sp.Integer(0))
            balances.append(sp.Eq(body.inertia * coords.of(body.name, "theta").a, torque))
        equations += balances
        balanced.append((body, balances, ", ".join(sorted({f.label for f in on_body})) or "none"))
    conditions = [v for c in scene.constraints for v in c.conditions(coords)]
    unknowns = coords.accelerations + [f for c in scene.constraints for f in c.unknowns().values()]

    def written(derivation: Derivation) -> list[Step]:
        rest = coords.at_rest_in_reference()
        sentences = part_sentences(scene, coords, "newton_euler")
        steps = [Step(f"Forces and torques on the {body.name} ({labels})",
                      tuple(sp.Eq(e.lhs, simplest(e.rhs.xreplace(rest))) for e in balances), role="equations",
                      body=body.name, sentences=tuple(s for s in sentences if s.body == body.name))
                 for body, balances, labels in balanced]
        velocities = worth_showing([sp.Eq(simplest(v.xreplace(rest_positions(coords))), 0) for v in conditions])
        kinematic = tuple(s for s in sentences if s.body is None)
        if velocities:
            steps += [Step("Kinematic constraints on the velocities (in the reference configuration" + FIXED_LEFT_OUT
                           + ")", velocities, sentences=kinematic),
                      Step("The same constraints on the accelerations (their rates of change)",
                           worth_showing([at_state(e, rest) for e in derivation.at_rest_equations[len(equations):]]),
                           role="equations")]
        elif kinematic and steps:  # every constraint only holds a coordinate fixed: said with the last balance
            steps[-1] = dataclasses.replace(steps[-1], sentences=steps[-1].sentences + kinematic)
        return steps

    return Derivation("newton_euler", equations, unknowns, written, conditions, coords)
