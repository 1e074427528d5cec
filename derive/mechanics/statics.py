"""Statics as a textbook does it: the forces on each body balance, horizontally and vertically, and
so do their torques about the point that removes the most unknown forces.

For a ladder against a smooth wall a solution manual writes three equations: f = P across, N = M g
up, and the torques about the foot, P L sin(theta) = M g (L/2) cos(theta), which the floor's forces
have no moment about; the Lagrange route with multipliers would write five. Each constraint force
points the way it acts (at the middle of the parameter ranges), so that its symbol is a magnitude.
The values it gives are checked against both routes' (derive.solution.crosschecks).

>>> from derive.language.problem import load
>>> from derive.solution.answers import Solution
>>> solution = Solution(load("ladder_statics"))
>>> route = statics(solution.dynamics_scene, solution.coordinates, solution.derivations["newton_euler"],
...                 solution._sample)
>>> print(route.steps[0].text)
The forces on the ladder balance, and so do their torques about the point where it touches the floor
"""
from __future__ import annotations

from collections.abc import Callable

import sympy as sp

from derive.core.tidying import leading_plus, tidy
from derive.mechanics.along_motion import AlongMotion, NotAlongALine, component, moment, oriented
from derive.mechanics.derivation import Derivation, Indeterminate, solve_linear
from derive.text.steps import Step
from derive.mechanics.newton_euler import all_forces
from derive.model.kinematics import Coordinates
from derive.model.scene import Scene
from derive.parts import AppliedForce
from derive.parts.contact import Contact
from derive.parts.pin import Pin

ACROSS, UP = sp.Matrix([1, 0]), sp.Matrix([0, 1])


def statics(scene: Scene, coords: Coordinates, newton: Derivation, sample: Callable[[sp.Expr], float],
            needed: set[sp.Symbol] = frozenset()) -> AlongMotion:
    """The balances of a scene that rests as placed: NotAlongALine where it does not (it moves)."""
    rest = coords.at_rest_in_reference()
    reference = newton.at(rest)
    if any(sample(reference[c.a]) != 0 for c in coords.all):
        raise NotAlongALine("the scene does not rest as placed")
    flipped = {u: -1 if sample(reference[u]) < 0 else 1 for c in scene.constraints for u in c.unknowns().values()}
    loads = all_forces(scene, coords)
    equations, steps = [], []
    for body in scene.bodies.values():
        on_body = [oriented(f, flipped, rest) for f in loads if f.body == body.name]
        forces = [f for f in on_body if isinstance(f, AppliedForce)]
        if not any(f.force.free_symbols & set(flipped) for f in forces):
            continue
        point = _pivot(forces, set(flipped))
        balances = [sp.Eq(0, component(on_body, ACROSS, sample)), sp.Eq(0, component(on_body, UP, sample))]
        if body.rotates:
            balances.append(sp.Eq(0, moment(on_body, point, sample)))
        balances = [b for b in balances if isinstance(b, sp.Eq)]
        where = _where(scene, coords, body.name, point)
        equations += balances
        text = f"The forces on the {body.name} balance" + (f", and so do their torques about {where}" if body.rotates else "")
        steps.append(Step(text, tuple(balances), role="equations", body=body.name))
    forces = sorted({u for e in equations for u in e.free_symbols if u in flipped}, key=str)
    try:
        solved = solve_linear(equations, forces, newton.placed)
    except (Indeterminate, ValueError) as error:
        raise NotAlongALine(str(error)) from None
    wanted = set(needed) & set(flipped)
    steps.append(Step("Solving", tuple(sp.Eq(u, leading_plus(solved[u])) for u in forces if u in wanted or not wanted),
                      role="solve"))
    values = {c.a: sp.Integer(0) for c in coords.all}
    values.update({u: tidy(flipped[u] * solved[u]) for u in forces})
    return AlongMotion(tuple(steps), values, {}, {}, flipped)


def _pivot(forces: list[AppliedForce], unknowns: set) -> sp.Matrix:
    """Where the most unknown forces act on the body (the first such point): torques about it leave
    them out."""
    counts = {}
    for f in forces:
        key = tuple(f.offset)
        counts[key] = counts.get(key, 0) + len(f.force.free_symbols & unknowns)
    best = max(counts.values())
    return sp.Matrix(next(key for key, n in counts.items() if n == best))


def _where(scene: Scene, coords: Coordinates, body: str, point: sp.Matrix) -> str:
    """The point of a body torques are taken about, in words: its center, where it touches a surface,
    or where it is pinned."""
    if point == sp.zeros(2, 1):
        return "its center"
    rest = coords.at_rest_in_reference()
    for part in scene.constraints:
        if isinstance(part, Contact) and part.body == body and part.offset(coords).xreplace(rest) == point:
            return f"the point where it touches the {part.surface}"
        if isinstance(part, Pin) and part.body == body and coords.rotated(body, part.offset).xreplace(rest) == point:
            return f"its pin, {'fixed' if part.to is None else 'to the ' + part.to}"
    return "the point where most of the unknown forces act on it"
