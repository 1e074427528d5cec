"""First integrals of a motion from its kept momenta: a momentum no force from outside changes
(a rod on a smooth floor: no horizontal force acts on it, so M x' is kept), zero at the start and
with constant coefficients, is the rate of a fixed sum of the coordinates, sum_j c_j (q_j - q_j0) = 0
(the rod's center of mass falls straight down). Each such sum is a holonomic constraint the motion
keeps, so with the work-energy theorem it takes one degree of freedom off the motion
(derive.mechanics.states follows the rest along one coordinate).

A momentum is kept by both routes or by neither (derive.mechanics.moves): Lagrange's Noether
test (the Lagrangian and every gap unchanged by the rigid shift, the loads doing no work along
it) and Newton–Euler's (no force on the bodies has a component along it), and its two forms,
dT/du . xi and sum m v, must be the same expression.

>>> import sympy as sp
>>> from derive.model.kinematics import Coordinates
>>> from derive.mechanics.states import rest
>>> from derive.parts.gravity import Gravity
>>> from derive.model.scene import Body, Scene
>>> m, g = sp.symbols("m g", positive=True)
>>> scene = Scene({"stone": Body("stone", "point", m, {})}, gravity=Gravity(g))
>>> coords = Coordinates(scene)
>>> [i.gap for i in zero_momenta(scene, coords, rest(coords), lambda e: float(e.subs({m: 1, g: 10})))]
[m*x_stone]
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import sympy as sp

from derive.mechanics import moves
from derive.text.steps import Step
from derive.core.tidying import tidy
from derive.model.kinematics import Coordinates
from derive.model.scene import Scene


class RoutesDisagree(AssertionError):
    """The two routes find different kept momenta: an engine fault, never the file's."""


@dataclass(frozen=True)
class Integral:
    """A kept momentum zero at the start, with constant coefficients: `gap`, sum_j c_j (q_j -
    q_j0), stays zero along the motion; `step` says why, for a worked solution."""

    gap: sp.Expr
    step: Step


def zero_momenta(scene: Scene, coords: Coordinates, start: dict, sample) -> tuple[Integral, ...]:
    """The independent first integrals of the motion from `start` (every coordinate and rate):
    each momentum both routes keep that is zero there and whose coefficients are constant. A kept
    momentum that is not zero (a thrown body's) moves its sum of coordinates with time, and is no
    constraint on the configuration; it is left out. `sample` gives an expression's value at the
    middle of the parameter ranges.

    Raises RoutesDisagree where Lagrange and Newton–Euler keep different momenta."""
    by_lagrange = moves.symmetries_kept(scene, coords, start, "lagrange", sample, ())
    by_newton_euler = moves.symmetries_kept(scene, coords, start, "newton_euler", sample, ())
    if set(by_lagrange) != set(by_newton_euler):
        raise RoutesDisagree(f"Lagrange keeps {[s.describe(scene) for s in by_lagrange]}, Newton–Euler "
                             f"{[s.describe(scene) for s in by_newton_euler]}")
    result, rows = [], []
    for symmetry in by_lagrange:
        if symmetry.along is None:  # a turn: its angular momentum's coefficients hold the positions
            continue
        momentum = tidy(moves.momentum_of(scene, coords, symmetry, "lagrange"))
        if tidy(momentum - symmetry.momentum(coords)) != 0:
            raise RoutesDisagree(f"{symmetry.describe(scene)} is {momentum} by Lagrange and "
                                 f"{symmetry.momentum(coords)} by Newton–Euler")
        coefficients = [sp.diff(momentum, c.u) for c in coords.all]
        if any(k.has(*coords.state) for k in coefficients) or tidy(momentum.xreplace(start)) != 0:
            continue
        row = [sample(k) for k in coefficients]
        if np.linalg.matrix_rank(np.array(rows + [row]), tol=1e-9 * (1 + max(map(abs, row)))) == len(rows):
            continue  # the same integral as one already taken (a subset's shift of a free set)
        rows.append(row)
        gap = tidy(sum((k * (c.q - start[c.q]) for k, c in zip(coefficients, coords.all)), sp.Integer(0)))
        step = Step(f"No force from outside has a component along {symmetry.along} on "
                    f"{'the whole scene' if len(symmetry.moved) == len(scene.bodies) else ', '.join(symmetry.moved)} "
                    f"(by Newton–Euler; by Lagrange, the Lagrangian and the constraints do not change in that shift), "
                    f"so {symmetry.describe(scene)} is kept; it is zero at the start and its coefficients are "
                    "constant, so it is the rate of a sum of the coordinates that does not change",
                    (sp.Eq(symmetry.symbol, momentum), sp.Eq(gap, 0)))
        result.append(Integral(gap, step))
    return tuple(result)
