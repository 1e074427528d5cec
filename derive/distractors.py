"""Wrong answers for multiple choice, built from the mistakes students make.

Each distractor is derived by the engine from a perturbed problem, not drawn at random:
sliding instead of rolling, the moment of inertia of the wrong shape (I = M R^2 for a disk),
the parallel-axis term forgotten; plus a lost factor of 2. Only values that differ from the
right answer (and from each other) are kept.

>>> from derive.problem import load
>>> labels = [label for label, _ in perturbations(load("rolling_incline"))]
>>> "sliding instead of rolling (ball)" in labels
True
"""
from __future__ import annotations

import dataclasses

import sympy as sp

from derive import numeric
from derive.answers import Solution
from derive.errors import InputError
from derive.problem import Problem
from derive.parts.contact import Contact

#: Round shapes whose moments students mix up (same size name: radius).
ROUND = ("ring", "disk", "sphere", "spherical_shell", "cylinder", "cylindrical_shell")


def perturbations(problem: Problem) -> list[tuple[str, Problem]]:
    """(what went wrong, the problem as the mistaken student set it up)."""
    scene = problem.scene
    result = []
    for c in scene.constraints:
        if isinstance(c, Contact) and c.rolling:
            constraints = tuple(dataclasses.replace(x, rolling=False) if x is c else x for x in scene.constraints)
            result.append((f"sliding instead of rolling ({c.body})",
                           dataclasses.replace(problem, scene=dataclasses.replace(scene, constraints=constraints))))
    for name, body in scene.bodies.items():
        if body.shape in ROUND and body.density is None and set(body.sizes) == {"radius"}:
            for other in ROUND:
                if other != body.shape and set(_sizes(other)) == {"radius"}:
                    bodies = {**scene.bodies, name: dataclasses.replace(body, shape=other)}
                    result.append((f"the inertia of a {other.replace('_', ' ')} for the {body.shape.replace('_', ' ')}",
                                   dataclasses.replace(problem, scene=dataclasses.replace(scene, bodies=bodies))))
    if any(a.shift is not None for a in problem.asks.values()):
        asks = {n: dataclasses.replace(a, shift=None) for n, a in problem.asks.items()}
        result.append(("the parallel-axis term forgotten", dataclasses.replace(problem, asks=asks)))
    return result


def _sizes(shape: str) -> tuple[str, ...]:
    from derive.inertia import SHAPES

    return tuple(SHAPES[shape].sizes)


# Problems hold dicts and do not hash: derivations are cached by identity (with the problem
# kept alive, so that an id is never reused), once for every variant of a sheet.
_DERIVED: dict[int, tuple[Problem, list[tuple[str, Problem, Solution]], Solution]] = {}


def _derived(problem: Problem) -> tuple[list[tuple[str, Problem, Solution]], Solution]:
    if id(problem) not in _DERIVED:
        # The declared conditions belong to the right set-up (mu_s >= mu_min means nothing when sliding).
        mistakes = [(label, mistaken, Solution(dataclasses.replace(mistaken, conditions=())))
                    for label, mistaken in perturbations(problem)]
        _DERIVED[id(problem)] = (problem, mistakes, Solution(problem))
    _, mistakes, solution = _DERIVED[id(problem)]
    return mistakes, solution


def distractors(problem: Problem, name: str, values: dict, digits: int, limit: int = 4) -> list[dict[str, str]]:
    """Up to `limit` wrong values of the answer `name` at these (SI) values, with what went wrong."""
    from derive.report import answer_values

    mistakes, solution = _derived(problem)
    correct = answer_values(solution, values, digits, [name])[name]
    if correct is None:
        return []
    candidates = []
    for label, _, mistaken in mistakes:
        try:
            value = answer_values(mistaken, values, digits, [name])[name]
        except (InputError, ValueError, KeyError, ZeroDivisionError):
            continue  # the mistake has no such quantity (friction when sliding)
        candidates.append((label, value))
    half = numeric.evaluate(sp.Rational(1, 2) * sp.Float(correct, 30), {}, digits)
    candidates += [("a lost factor of 2", numeric.evaluate(2 * sp.Float(correct, 30), {}, digits)),
                   ("a factor of 2 too many", half)]
    seen, result = {correct}, []
    for label, value in candidates:
        if value is not None and value not in seen:
            seen.add(value)
            result.append({"value": value, "mistake": label})
    return result[:limit]
